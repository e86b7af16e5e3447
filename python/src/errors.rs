//! The exceptions of the package and the conversion of the library's errors to them.

use crate::convert::toml_to_py;
use gearwear::app::JobError;
use gearwear::config::Problem as LibProblem;
use gearwear::remedy::{Arg, Words};
use pyo3::create_exception;
use pyo3::exceptions::{PyKeyboardInterrupt, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

create_exception!(
    gearwear,
    CaseError,
    PyValueError,
    "The input is invalid (the case, an argument, an input table). `problems` lists every \
     problem (gearwear.Problem: key, value, valid, message), as the command line's exit-2 \
     messages do."
);
create_exception!(
    gearwear,
    StudyError,
    PyRuntimeError,
    "A study failed on a valid case (e.g. no periodic steady state was found within \
     numerics.max_mesh_periods); the command line exits 1 for these."
);

/// One problem of a case (see `gearwear.CaseError`).
#[pyclass(frozen, get_all, module = "gearwear")]
pub struct Problem {
    /// Dotted key (`section.key`), or None when the message names none.
    key: Option<String>,
    /// The value given (a Python value read from its TOML text), or None.
    value: Py<PyAny>,
    /// What would be valid (a range, the choices, the valid keys, a condition), or None.
    valid: Option<String>,
    /// The whole message, as the command line prints it.
    message: String,
}

#[pymethods]
impl Problem {
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let r = |o: Bound<'_, PyAny>| -> PyResult<String> { Ok(o.repr()?.to_string()) };
        Ok(format!(
            "Problem(key={}, value={}, valid={}, message={})",
            r(self.key.clone().into_pyobject(py)?)?,
            r(self.value.bind(py).clone())?,
            r(self.valid.clone().into_pyobject(py)?)?,
            r(self.message.clone().into_pyobject(py)?.into_any())?,
        ))
    }

    fn __str__(&self) -> String {
        self.message.clone()
    }

    /// The fields as a dict.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("key", &self.key)?;
        d.set_item("value", self.value.bind(py))?;
        d.set_item("valid", &self.valid)?;
        d.set_item("message", &self.message)?;
        Ok(d)
    }
}

/// A value's TOML text as a Python value (the text itself when it does not parse).
fn value_of(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
    let parsed = toml::from_str::<toml::Table>(&format!("v = {text}"))
        .ok()
        .and_then(|mut t| t.remove("v"));
    Ok(match parsed {
        Some(v) => toml_to_py(py, &v)?.unbind(),
        None => text.into_pyobject(py)?.into_any().unbind(),
    })
}

/// `CaseError` carrying every problem (message as the command line prints it).
pub fn case_error(py: Python<'_>, messages: &[String]) -> PyErr {
    let build = || -> PyResult<PyErr> {
        let mut problems = Vec::with_capacity(messages.len());
        for m in messages {
            let p = LibProblem::from_message(m);
            problems.push(Problem {
                value: match &p.value {
                    Some(t) => value_of(py, t)?,
                    None => py.None(),
                },
                key: p.key,
                valid: p.valid,
                message: p.message,
            });
        }
        let text = if messages.len() == 1 {
            messages[0].clone()
        } else {
            let lines: Vec<String> = messages.iter().map(|m| format!("  - {m}")).collect();
            format!(
                "invalid case ({} problems):\n{}",
                messages.len(),
                lines.join("\n")
            )
        };
        let err = CaseError::new_err(text);
        err.value(py).setattr("problems", problems)?;
        Ok(err)
    };
    build().unwrap_or_else(|e| e)
}

/// How Python spells a job's arguments in messages (`gearwear::remedy`): keyword
/// arguments of the study functions, in backticks.
pub fn spell(a: Arg) -> &'static str {
    match a {
        Arg::Override => "`Case.set`",
        Arg::CaseFile => "`Case.from_toml`",
        Arg::Out => "`out`",
        Arg::Resume => "`resume`",
        Arg::Vary => "`vary`",
        Arg::Shard => "`shard`",
        Arg::Continuation => "`continuation`",
        Arg::SweepRun => "`run`",
        Arg::TransmissionError => "`transmission_error`",
        Arg::Observations => "`observations`",
        Arg::Posterior => "`posterior`",
        Arg::Samples => "`samples`",
        Arg::Walkers => "`walkers`",
        Arg::Steps => "`steps`",
        Arg::CheckRuns => "`check_runs`",
        Arg::GridPoints => "`grid_points`",
        Arg::LimitUm => "`limit_um`",
        Arg::Cycles => "`cycles`",
        Arg::BudgetScale => "`budget_scale`",
        Arg::NoBudget => "`budget_scale=math.inf`",
        Arg::Inputs => "`inputs`",
        Arg::Replace => "`replace=True`",
        Arg::History => "`history`",
        Arg::TorqueClasses => "`torque_classes`",
        Arg::SpeedClasses => "`speed_classes`",
        Arg::GapFactor => "`gap_factor`",
        Arg::MergeBelowShare => "`merge_below_share`",
        Arg::TransferPath => "`transfer_path`",
        Arg::Design => "`design`",
        Arg::FutureSpectrum => "`future_spectrum`",
        Arg::FutureFromCycles => "`future_from_cycles`",
        Arg::FigureFormats => "`figures`",
        Arg::FigureSize => "`figure_size`",
    }
}

/// `CaseError` for the problems of a case (`ConfigError`), worded for Python.
pub fn config_error(py: Python<'_>, problems: &[Words]) -> PyErr {
    let m: Vec<String> = problems.iter().map(|w| w.render(spell)).collect();
    case_error(py, &m)
}

/// A job's error as the Python exception: input problems as `CaseError` (a `ValueError`,
/// every problem in `problems`), the output folder as `OSError`, a stop on request as
/// `KeyboardInterrupt`, a solver failure as `StudyError`.
pub fn job_error(py: Python<'_>, e: JobError) -> PyErr {
    match e {
        JobError::Input(_) => case_error(py, &e.messages(spell)),
        JobError::Output(p) => PyOSError::new_err(p.render(spell)),
        JobError::Cancelled => PyKeyboardInterrupt::new_err("study interrupted"),
        JobError::Failed(e) => StudyError::new_err(format!("{e:#}")),
    }
}
