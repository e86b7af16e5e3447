//! The study functions: each builds the model of a case, calls the library's study and its
//! report builder (`gearwear::report::*`, the same as the command line), stamps the run's
//! metadata, and hands the summary and tables to Python.
//!
//! Each returns `(summary, tables, headline)` (plus the rendered documents for `run`);
//! the Python package wraps them in result objects.

use crate::budget::{budget_of, check, check_sweep};
use crate::case::Case;
use crate::convert::{json_to_py, matrix_to_py, tables_to_py};
use crate::errors::Failure;
use crate::worker::run_study;
use gearwear::config::Case as LibCase;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::io::checkpoint_set::CheckpointSet;
use gearwear::io::transmission_error::transmission_error_from_deg_um;
use gearwear::io::{OutputDir, RunMetadata};
use gearwear::report::dynamics::dynamics_artifacts;
use gearwear::report::paper::run_artifacts;
use gearwear::report::stiffness::stiffness_artifacts;
use gearwear::report::wear::wear_artifacts;
use gearwear::report::{publish_artifacts, Artifacts};
use gearwear::study::budget::Job;
use gearwear::study::paper::run_paper_study;
use gearwear::study::sweep::{
    parse_vary, resolve_cases, run_cases, SweepOutcome, SweepPlan, SweepRun,
};
use gearwear::study::wear_loop::{run_wear_modes, WearMode, WearRun};
use gearwear::study::Model;
use gearwear::wear::WearState;
use numpy::PyReadonlyArray2;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyTuple};
use serde_json::json;
use std::path::PathBuf;
use std::time::Instant;

fn model_of(case: &LibCase) -> Result<Model, Failure> {
    Model::from_case(case).map_err(|e| Failure::Case(e.0))
}

fn stamped(mut a: Artifacts, command: &str, case: &LibCase) -> Result<Artifacts, Failure> {
    a.stamp_metadata(&RunMetadata::new(command, case))
        .map_err(|e| Failure::Failed(e.into()))?;
    Ok(a)
}

/// `(summary, tables, headline)` as Python objects.
fn to_py<'py>(py: Python<'py>, a: Artifacts) -> PyResult<Bound<'py, PyTuple>> {
    let summary = json_to_py(py, &a.summary)?;
    let tables = tables_to_py(py, a.tables)?;
    PyTuple::new(
        py,
        [
            summary,
            tables.into_any(),
            a.headline.into_pyobject(py)?.into_any(),
        ],
    )
}

/// Mesh stiffness over a mesh period, ISO 6336 check, load sharing, quasi-static TE
/// (as `gearwear stiffness`).
#[pyfunction]
#[pyo3(signature = (case, budget_scale=None, no_budget=false))]
pub fn stiffness<'py>(
    py: Python<'py>,
    case: &Case,
    budget_scale: Option<f64>,
    no_budget: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let b = budget_of(budget_scale, no_budget)?;
    check(py, &case.inner, Job::Stiffness, b)?;
    let c = case.inner.clone();
    let a = run_study(py, None, move |_| {
        stamped(stiffness_artifacts(&model_of(&c)?), "stiffness", &c)
    })?;
    to_py(py, a)
}

/// One steady-state evaluation of new teeth, with an optional external transmission error
/// (samples: pinion angle deg, error um); what `gearwear dynamics` writes.
pub fn dynamics_of(case: &LibCase, te: Option<&[(f64, f64)]>) -> Result<Artifacts, Failure> {
    let model = model_of(case)?;
    let external = match te {
        Some(s) => {
            transmission_error_from_deg_um(s, model.pair.mesh_angle_rad(), "transmission_error")
                .map_err(|e| Failure::Input(e.to_string()))?
        }
        None => ExternalError::none(),
    };
    let r = model
        .dynamic(&WearState::new(model.grid.len()), &external)
        .map_err(|e| Failure::Failed(e.into()))?;
    let label = if te.is_some() {
        "new teeth, external transmission error"
    } else {
        "new teeth"
    };
    stamped(dynamics_artifacts(&model, &r, label), "dynamics", case)
}

fn samples_of(te: Option<PyReadonlyArray2<'_, f64>>) -> PyResult<Option<Vec<(f64, f64)>>> {
    let Some(te) = te else { return Ok(None) };
    let a = te.as_array();
    if a.ncols() != 2 {
        return Err(PyValueError::new_err(format!(
            "transmission_error: expected an array of shape (n, 2) (pinion angle deg, error um), got {:?}",
            a.shape()
        )));
    }
    Ok(Some(a.rows().into_iter().map(|r| (r[0], r[1])).collect()))
}

#[pyfunction]
#[pyo3(signature = (case, transmission_error=None, budget_scale=None, no_budget=false))]
pub fn dynamics<'py>(
    py: Python<'py>,
    case: &Case,
    transmission_error: Option<PyReadonlyArray2<'py, f64>>,
    budget_scale: Option<f64>,
    no_budget: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let b = budget_of(budget_scale, no_budget)?;
    check(py, &case.inner, Job::Dynamics, b)?;
    let c = case.inner.clone();
    let te = samples_of(transmission_error)?;
    let a = run_study(py, None, move |_| dynamics_of(&c, te.as_deref()))?;
    to_py(py, a)
}

/// The wear modes named by `mode`.
fn modes_of(mode: &str) -> PyResult<Vec<WearMode>> {
    match mode {
        "both" => Ok(vec![WearMode::Dynamic, WearMode::QuasiStatic]),
        "dynamic" => Ok(vec![WearMode::Dynamic]),
        "quasi_static" | "quasi-static" => Ok(vec![WearMode::QuasiStatic]),
        _ => Err(PyValueError::new_err(format!(
            "mode = {mode:?}: expected \"both\", \"dynamic\" or \"quasi_static\""
        ))),
    }
}

/// Progress of a wear run: the cycles its last update reached.
fn cycles_of(run: &WearRun) -> f64 {
    run.last().map_or(0.0, |r| r.wear.cycles)
}

#[pyfunction]
#[pyo3(signature = (case, mode="both", progress=None, budget_scale=None, no_budget=false))]
pub fn wear<'py>(
    py: Python<'py>,
    case: &Case,
    mode: &str,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: Option<f64>,
    no_budget: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let c = case.inner.clone();
    let modes = modes_of(mode)?;
    let job = Job::Wear {
        dynamic: modes.contains(&WearMode::Dynamic),
        quasi_static: modes.contains(&WearMode::QuasiStatic),
    };
    check(py, &c, job, budget_of(budget_scale, no_budget)?)?;
    let a = run_study(py, progress, move |ctx| {
        let model = model_of(&c)?;
        let total = c.wear.total_cycles;
        let starts = modes.iter().map(|m| WearRun::new(*m)).collect();
        let runs = run_wear_modes(&model, starts, &|m, run| {
            ctx.update(m.name(), cycles_of(run), total)
        })?;
        let refs: Vec<&WearRun> = runs.iter().collect();
        stamped(wear_artifacts(&model, &refs), "wear", &c)
    })?;
    to_py(py, a)
}

/// The paper's whole section 4 (as `gearwear run`); with `out`, the same output set with
/// checkpoints, figures and report.
#[pyfunction]
#[pyo3(signature = (case, out=None, progress=None, budget_scale=None, no_budget=false))]
pub fn run<'py>(
    py: Python<'py>,
    case: &Case,
    out: Option<PathBuf>,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: Option<f64>,
    no_budget: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    check(
        py,
        &case.inner,
        Job::Run,
        budget_of(budget_scale, no_budget)?,
    )?;
    let c = case.inner.clone();
    let a = run_study(py, progress, move |ctx| {
        let model = model_of(&c)?;
        let meta = RunMetadata::new("run", &c);
        let (d0, q0) = (
            WearRun::new(WearMode::Dynamic),
            WearRun::new(WearMode::QuasiStatic),
        );
        let mut writer = match &out {
            Some(dir) => {
                let mut set = OutputDir::open(dir, None, "run")
                    .map_err(|e| Failure::Output(e.to_string()))?;
                let logs = CheckpointSet::open(&mut set, &[&d0, &q0], &meta.case_sha256)
                    .map_err(|e| Failure::Output(e.to_string()))?;
                Some((set, logs))
            }
            None => None,
        };
        let total = c.wear.total_cycles;
        let study = run_paper_study(&model, d0.clone(), q0.clone(), &|m, run| {
            if let Some((_, logs)) = &writer {
                logs.record(run)?;
            }
            ctx.update(m.name(), cycles_of(run), total)
        })?;
        let a = stamped(run_artifacts(&model, &study, &meta), "run", &c)?;
        if let Some((set, logs)) = writer.take() {
            drop(logs);
            publish_artifacts(set, &a).map_err(|e| match e {
                gearwear::report::artifacts::WriteError::Output(o) => {
                    Failure::Output(o.to_string())
                }
                e => Failure::Failed(e.into()),
            })?;
        }
        Ok(a)
    })?;
    let docs = PyDict::new(py);
    for (name, bytes) in &a.documents {
        docs.set_item(name, PyBytes::new(py, bytes))?;
    }
    // The run's figures are rendered once, for its report: the same PNG bytes.
    for f in &a.figures {
        if let Some(png) = &f.png {
            docs.set_item(&f.path, PyBytes::new(py, png))?;
        }
    }
    let t = to_py(py, a)?;
    let mut items: Vec<Bound<'py, PyAny>> = t.iter().collect();
    items.push(docs.into_any());
    PyTuple::new(py, items)
}

fn sweep_run_of(run: &str) -> PyResult<SweepRun> {
    match run {
        "dynamics" => Ok(SweepRun::Dynamics),
        "wear" => Ok(SweepRun::Wear),
        _ => Err(PyValueError::new_err(format!(
            "run = {run:?}: expected \"dynamics\" or \"wear\""
        ))),
    }
}

/// The cross product of `vary` (pairs of key and `--vary` value text: `START:STOP:STEP`
/// or `v1,v2,...`) on `case`, run in parallel (as `gearwear sweep`, without files).
/// Returns `(summary, keys, columns, case_ids, values, results)`.
#[pyfunction]
#[pyo3(signature = (case, vary, run="dynamics", progress=None, budget_scale=None, no_budget=false))]
pub fn sweep<'py>(
    py: Python<'py>,
    case: &Case,
    vary: Vec<(String, String)>,
    run: &str,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: Option<f64>,
    no_budget: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let budget = budget_of(budget_scale, no_budget)?;
    let kind = sweep_run_of(run)?;
    let mut axes = Vec::new();
    let mut problems = Vec::new();
    for (k, v) in &vary {
        match parse_vary(&format!("{k}={v}")) {
            Ok(a) => axes.push(a),
            Err(e) => problems.push(e),
        }
    }
    if !problems.is_empty() {
        return Err(crate::errors::case_error(py, &problems));
    }
    let plan = SweepPlan::new(axes).map_err(|e| crate::errors::case_error(py, &[e]))?;
    check_sweep(py, &case.inner, &plan, kind, budget)?;
    let base = case.inner.clone();
    let plan2 = plan.clone();
    let (outcome, wall_s): (SweepOutcome, f64) = run_study(py, progress, move |ctx| {
        let started = Instant::now();
        let cases = resolve_cases(&base, &plan2).map_err(Failure::Case)?;
        let total = cases.len() as f64;
        let done = std::sync::atomic::AtomicUsize::new(0);
        let out = run_cases(&cases, plan2.keys(), kind, &|| !ctx.stopped(), &|| {
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            let _ = ctx.update("sweep", n as f64, total);
        });
        if ctx.stopped() {
            return Err(Failure::Interrupted);
        }
        Ok((out, started.elapsed().as_secs_f64()))
    })?;
    let t = &outcome.table;
    let summary = json!({
        "command": "sweep",
        "run": kind,
        "vary": plan.axes.iter().map(|x| json!({"key": x.key, "values": x.values})).collect::<Vec<_>>(),
        "total_cases": plan.len(),
        "computed": t.rows.len(),
        "failed": outcome.failed.iter().map(|(id, values, e)| json!({"case_id": id, "values": values, "error": e})).collect::<Vec<_>>(),
        "rows": t.rows.len(),
        "warnings": outcome.warnings,
        "wall_time_s": wall_s,
        "threads": rayon::current_num_threads(),
        "base": RunMetadata::new("sweep", &case.inner),
    });
    let ids: Vec<f64> = t.rows.iter().map(|r| r.case_id as f64).collect();
    let values: Vec<Vec<String>> = t.rows.iter().map(|r| r.values.clone()).collect();
    let n_cols = t.columns.len();
    let results = matrix_to_py(
        py,
        t.rows.iter().map(|r| r.results.clone()).collect(),
        n_cols,
    )?;
    PyTuple::new(
        py,
        [
            json_to_py(py, &summary)?,
            t.keys.clone().into_pyobject(py)?.into_any(),
            t.columns.clone().into_pyobject(py)?.into_any(),
            numpy::PyArray1::from_vec(py, ids).into_any(),
            values.into_pyobject(py)?.into_any(),
            results.into_any(),
        ],
    )
}

/// Benchmark helper: seconds taken by each of `repeats` Rust-only calls of what
/// `dynamics(case)` runs (model, evaluation, report builder, metadata), GIL released.
#[pyfunction]
pub fn _time_rust_dynamics(py: Python<'_>, case: &Case, repeats: usize) -> PyResult<Vec<f64>> {
    let c = case.inner.clone();
    Ok(py.detach(move || {
        (0..repeats)
            .map(|_| {
                let t0 = Instant::now();
                drop(dynamics_of(&c, None));
                t0.elapsed().as_secs_f64()
            })
            .collect()
    }))
}
