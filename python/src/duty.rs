//! Duty cycles from Python: the load spectrum of a measured history (as `gearwear
//! load-spectrum`), and a case given that spectrum.

use crate::case::Case;
use crate::convert::{outcome_to_py, path_or_columns};
use crate::errors::config_error;
use crate::worker::run_job;
use gearwear::app::LoadSpectrumJob;
use gearwear::config::case::TorqueShaft;
use gearwear::config::load::{case_with, load_case};
use gearwear::duty::ldd::{Interpolation, LddSettings, Level};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

fn interpolation_of(s: &str) -> PyResult<Interpolation> {
    match s {
        "linear" => Ok(Interpolation::Linear),
        "hold" => Ok(Interpolation::Hold),
        _ => Err(PyValueError::new_err(format!(
            "interpolation = {s:?}: expected \"linear\" or \"hold\""
        ))),
    }
}

fn level_of(s: &str) -> PyResult<Level> {
    match s {
        "mean" => Ok(Level::Mean),
        "upper" => Ok(Level::Upper),
        _ => Err(PyValueError::new_err(format!(
            "level = {s:?}: expected \"mean\" or \"upper\""
        ))),
    }
}

fn shaft_of(s: &str) -> PyResult<TorqueShaft> {
    match s {
        "pinion" => Ok(TorqueShaft::Pinion),
        "gear" => Ok(TorqueShaft::Gear),
        _ => Err(PyValueError::new_err(format!(
            "torque_shaft = {s:?}: expected \"pinion\" or \"gear\""
        ))),
    }
}

/// The load spectrum of a measured history (as `gearwear load-spectrum`).
#[pyfunction]
#[pyo3(signature = (history, *, torque_classes=10, speed_classes=5, interpolation="linear", level="mean", torque_shaft="pinion", gap_factor=10.0, merge_below_share=1e-3, out=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn load_spectrum<'py>(
    py: Python<'py>,
    history: Bound<'py, PyAny>,
    torque_classes: usize,
    speed_classes: usize,
    interpolation: &str,
    level: &str,
    torque_shaft: &str,
    gap_factor: f64,
    merge_below_share: f64,
    out: Option<PathBuf>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = LoadSpectrumJob {
        history: path_or_columns(&history)?,
        settings: LddSettings {
            torque_classes,
            speed_classes,
            interpolation: interpolation_of(interpolation)?,
            level: level_of(level)?,
        },
        torque_shaft: shaft_of(torque_shaft)?,
        gap_factor,
        merge_below_share,
        out,
        replace,
        budget: crate::jobs::budget_for(budget_scale, &figures, figure_size)?,
        figures: crate::jobs::figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
}

/// `case` with the `[load_spectrum]` section of `section` (TOML text) in place of its own.
#[pyfunction]
pub fn _case_with_spectrum(py: Python<'_>, case: &Case, section: &str) -> PyResult<Case> {
    let read = load_case(section, &[]).map_err(|e| config_error(py, &e.problems))?;
    let mut inner = case.inner.clone();
    inner.load_spectrum = read.load_spectrum;
    case_with(&inner, &[])
        .map(|inner| Case { inner })
        .map_err(|e| config_error(py, &e.problems))
}
