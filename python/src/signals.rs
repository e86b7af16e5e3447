//! The signal studies: `signals`, `dataset` and `dataset_merge` as jobs of
//! `gearwear::app` (the command line's jobs), their results converted to dicts.

use crate::case::{is_toml_text, Case};
use crate::convert::{outcome_to_py, py_to_toml_design};
use crate::worker::run_job;
use gearwear::app::{DatasetJob, DatasetMergeJob, DesignSource, SignalsJob, TransferPathSource};
use gearwear::study::dataset::Shard;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyMapping, PyString};
use std::path::PathBuf;

/// One record of what a sensor sees (as `gearwear signals`).
#[pyfunction]
#[pyo3(signature = (case, *, transfer_path=None, out=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn signals<'py>(
    py: Python<'py>,
    case: &Case,
    transfer_path: Option<PathBuf>,
    out: Option<PathBuf>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let budget = crate::jobs::budget_for(budget_scale, &figures, figure_size)?;
    let job = SignalsJob {
        case: case.inner.clone(),
        transfer_path: transfer_path.map(TransferPathSource::File),
        out,
        replace,
        budget,
        figures: crate::jobs::figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
}

/// Where a design given from Python comes from: a path to a design file, TOML text, or a
/// mapping (whose `case` may be a `Case` object). Text and mappings resolve their relative
/// paths (a `case` file, a `transfer_path`) against the current folder.
fn design_source(py: Python<'_>, design: &Bound<'_, PyAny>) -> PyResult<DesignSource> {
    let job_error = |e| crate::errors::job_error(py, e);
    let here = PathBuf::from(".");
    if let Ok(s) = design.cast::<PyString>() {
        let s = s.to_cow()?;
        if is_toml_text(&s) {
            return DesignSource::inline(s.into_owned(), "design (text)", here, None)
                .map_err(job_error);
        }
    }
    if let Ok(m) = design.cast::<PyMapping>() {
        let mut case_text = None;
        let table = PyDict::new(py);
        for item in m.items()?.iter() {
            let (k, v): (String, Bound<'_, PyAny>) = item.extract()?;
            match v.cast::<Case>() {
                Ok(c) if k == "case" => {
                    case_text = Some(c.borrow().to_toml_text());
                    table.set_item(k, "(Case object)")?;
                }
                _ => table.set_item(k, v)?,
            }
        }
        let text = toml::to_string(&py_to_toml_design(table.as_any())?)
            .map_err(|e| PyValueError::new_err(format!("the design is not a TOML table: {e}")))?;
        return DesignSource::inline(text, "design (dict)", here, case_text).map_err(job_error);
    }
    let path: PathBuf = design.extract().map_err(|_| {
        PyTypeError::new_err(
            "design: give a path to a design file, TOML text or a dict of the design's keys",
        )
    })?;
    DesignSource::file(&path).map_err(job_error)
}

/// A labelled dataset from a study design (as `gearwear dataset`): a design file, TOML
/// text or a dict; `shard` is `(i, n)` for shard i of n.
#[pyfunction]
#[pyo3(signature = (design, out, *, shard=None, progress=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn dataset<'py>(
    py: Python<'py>,
    design: &Bound<'py, PyAny>,
    out: PathBuf,
    shard: Option<(usize, usize)>,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let budget = crate::jobs::budget_for(budget_scale, &figures, figure_size)?;
    let shard = match shard {
        None => Shard::ALL,
        Some((index, count)) if index >= 1 && index <= count => Shard { index, count },
        Some((i, n)) => {
            return Err(PyValueError::new_err(format!(
                "shard = ({i}, {n}): expected (i, n) with 1 <= i <= n"
            )))
        }
    };
    let design = design_source(py, design)?;
    let job = DatasetJob {
        design,
        shard,
        out,
        replace,
        budget,
        figures: crate::jobs::figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, progress)?;
    outcome_to_py(py, o, w)
}

/// The shards of a dataset joined (as `gearwear dataset-merge`); `transfer_path`: the
/// transfer-path file the shards' design names (`--transfer-path`).
#[pyfunction]
#[pyo3(signature = (inputs, out, *, replace=false, figures=None, figure_size=None, transfer_path=None, budget_scale=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn dataset_merge<'py>(
    py: Python<'py>,
    inputs: Vec<PathBuf>,
    out: PathBuf,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
    transfer_path: Option<PathBuf>,
    budget_scale: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let budget = crate::jobs::budget_for(budget_scale, &figures, figure_size)?;
    let job = DatasetMergeJob {
        budget,
        inputs,
        out,
        replace,
        figures: crate::jobs::figure_request(figures, figure_size),
        transfer_path,
    };
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
}
