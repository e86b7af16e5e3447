//! The signal studies: `signals`, `dataset` and `dataset_merge` as jobs of
//! `gearwear::app` (the command line's jobs), their results converted to dicts.

use crate::case::Case;
use crate::convert::outcome_to_py;
use crate::worker::run_job;
use gearwear::app::{DatasetJob, DatasetMergeJob, DesignSource, SignalsJob, TransferPathSource};
use gearwear::study::dataset::Shard;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
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
    let budget = crate::jobs::budget_of(budget_scale)?;
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

/// A labelled dataset from a study design file (as `gearwear dataset`); `shard` is
/// `(i, n)` for shard i of n.
#[pyfunction]
#[pyo3(signature = (design, out, *, shard=None, progress=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn dataset<'py>(
    py: Python<'py>,
    design: PathBuf,
    out: PathBuf,
    shard: Option<(usize, usize)>,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let budget = crate::jobs::budget_of(budget_scale)?;
    let shard = match shard {
        None => Shard::ALL,
        Some((index, count)) if index >= 1 && index <= count => Shard { index, count },
        Some((i, n)) => {
            return Err(PyValueError::new_err(format!(
                "shard = ({i}, {n}): expected (i, n) with 1 <= i <= n"
            )))
        }
    };
    let design = DesignSource::file(&design).map_err(|e| crate::errors::job_error(py, e))?;
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

/// The shards of a dataset joined (as `gearwear dataset-merge`).
#[pyfunction]
#[pyo3(signature = (inputs, out, *, replace=false, figures=None, figure_size=None))]
pub fn dataset_merge<'py>(
    py: Python<'py>,
    inputs: Vec<PathBuf>,
    out: PathBuf,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = DatasetMergeJob {
        inputs,
        out,
        replace,
        figures: crate::jobs::figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
}
