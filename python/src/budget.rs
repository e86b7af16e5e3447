//! The run budget of Python calls (`gearwear::study::budget`, as the command line's):
//! every study is estimated before it starts and refused over budget with a `CaseError`
//! naming what drives it. ``budget_scale=X`` multiplies the budget knowingly,
//! ``no_budget=True`` drops it.

use crate::errors::case_error;
use gearwear::config::{load_case, Case as LibCase};
use gearwear::study::budget::{estimate, estimate_sweep, Budget, Job};
use gearwear::study::sweep::{SweepPlan, SweepRun};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// The budget asked for: None without one.
pub fn budget_of(scale: Option<f64>, no_budget: bool) -> PyResult<Option<Budget>> {
    if no_budget {
        return Ok(None);
    }
    match scale {
        None => Ok(Some(Budget::DEFAULT)),
        Some(x) if x.is_normal() && x > 0.0 && x <= 1e9 => Ok(Some(Budget::scaled(x))),
        Some(x) => Err(PyValueError::new_err(format!(
            "budget_scale = {x}: expected a number in (0, 1e9]"
        ))),
    }
}

/// Phrase a budget refusal for Python (the library's message names the command line's
/// flags; here they are keyword arguments).
fn for_python(msg: &str) -> String {
    msg.replace("--budget-scale X", "budget_scale=X")
        .replace("--no-budget", "no_budget=True")
        .replace("--shard I/N", "several calls over parts of the values")
}

/// Refuse `job` on `case` over `budget`.
pub fn check(py: Python<'_>, case: &LibCase, job: Job, budget: Option<Budget>) -> PyResult<()> {
    let Some(b) = budget else { return Ok(()) };
    estimate(case, job)
        .check(&b)
        .map_err(|m| case_error(py, &[for_python(&m)]))
}

/// Refuse a sweep of `plan` on `base` over `budget`: its costliest case, and all its cases
/// together (in milliseconds, before any case is resolved).
pub fn check_sweep(
    py: Python<'_>,
    base: &LibCase,
    plan: &SweepPlan,
    run: SweepRun,
    budget: Option<Budget>,
) -> PyResult<()> {
    let Some(b) = budget else { return Ok(()) };
    let Ok(text) = toml::to_string(base) else {
        return Ok(());
    };
    let axes: Vec<(String, Vec<String>)> = plan
        .axes
        .iter()
        .map(|x| (x.key.clone(), x.values.clone()))
        .collect();
    let load = |sets: &[String]| load_case(&text, sets).ok();
    let threads = crate::pool::current().map_or(1, |p| p.current_num_threads());
    let Some(e) = estimate_sweep(&load, &axes, Job::SweepCase(run), plan.len(), threads) else {
        return Ok(());
    };
    e.worst_case.check(&b).map_err(|m| {
        case_error(
            py,
            &[format!(
                "the sweep's costliest case ({}): {}",
                e.worst_overrides.join(", "),
                for_python(&m)
            )],
        )
    })?;
    e.total.check(&b).map_err(|m| {
        case_error(
            py,
            &[format!(
                "the sweep of {} case(s): {}",
                plan.len(),
                for_python(&m)
            )],
        )
    })
}
