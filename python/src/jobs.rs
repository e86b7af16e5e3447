//! The study functions: each converts its Python arguments into a job of the library's
//! application layer (`gearwear::app`, the same jobs as the command line), runs it
//! (`worker::run_job`) and converts what it returns (`convert`) into a dict of named
//! fields, which the package wraps in a result object. Nothing here orders the steps of
//! a study.

use crate::case::{is_toml_text, Case};
use crate::convert::{outcome_to_py, path_or_columns, sweep_to_py};
use crate::errors::spell;
use crate::worker::run_job;
use gearwear::app::{
    CalibrateJob, CalibrationOptions, DynamicsJob, ForwardModel, FutureInput, PredictJob,
    PredictMergeJob, PredictOptions, RunJob, SpectrumSource, StiffnessJob, SweepJob, SweepMergeJob,
    TransmissionErrorSource, WearJob,
};
use gearwear::config::load::override_value;
use gearwear::format::format_number;
use gearwear::report::figure_output::FigureRequest;
use gearwear::study::budget::Budget;
use gearwear::study::sweep::{
    parse_axis, Axis, AxisValue, Continuation, Shard, SweepPlan, SweepRun,
};
use gearwear::study::wear_loop::WearMode;
use numpy::PyReadonlyArray2;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::path::PathBuf;
use std::time::Instant;

/// The budget of `budget_scale`: the default times the scale; infinity drops the check.
pub(crate) fn budget_of(scale: f64) -> PyResult<Option<Budget>> {
    if scale == f64::INFINITY {
        return Ok(None);
    }
    if !(scale.is_normal() && scale > 0.0) {
        return Err(PyValueError::new_err(format!(
            "budget_scale = {scale}: expected a number > 0 (math.inf: no budget check)"
        )));
    }
    Ok(Some(Budget::scaled(scale)))
}

/// Mesh stiffness, ISO 6336 check, load sharing, quasi-static TE (as `gearwear stiffness`).
#[pyfunction]
#[pyo3(signature = (case, *, out=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
pub fn stiffness<'py>(
    py: Python<'py>,
    case: &Case,
    out: Option<PathBuf>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = StiffnessJob {
        case: case.inner.clone(),
        out,
        replace,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
}

/// The figure options of a job: `figures` ("png", "svg" or "png,svg") and
/// `figure_size` (width, height) px, checked when the job starts.
/// [`budget_of`] with the job's PNG figures counted at the size asked for
/// (`gearwear::app::budget::with_figures`).
pub(crate) fn budget_for(
    scale: f64,
    figures: &Option<String>,
    size: Option<(i64, i64)>,
) -> PyResult<Option<Budget>> {
    Ok(gearwear::app::budget::with_figures(
        budget_of(scale)?,
        &figure_request(figures.clone(), size),
    ))
}

pub(crate) fn figure_request(figures: Option<String>, size: Option<(i64, i64)>) -> FigureRequest {
    FigureRequest {
        formats: figures,
        size: size.map(|(w, h)| format!("{w}x{h}")),
    }
}

/// The samples (pinion angle deg, error um) of an (n, 2) array.
fn samples_of(te: Option<PyReadonlyArray2<'_, f64>>) -> PyResult<Option<Vec<(f64, f64)>>> {
    let Some(te) = te else { return Ok(None) };
    let a = te.as_array();
    if a.ncols() != 2 {
        return Err(PyValueError::new_err(format!(
            "transmission_error: expected an array of shape (n, 2) (pinion angle deg, error µm), got {:?}",
            a.shape()
        )));
    }
    Ok(Some(a.rows().into_iter().map(|r| (r[0], r[1])).collect()))
}

/// The job of `dynamics(...)`.
pub fn dynamics_job(
    case: &Case,
    te: Option<Vec<(f64, f64)>>,
    out: Option<PathBuf>,
    replace: bool,
    budget: Option<Budget>,
    figures: FigureRequest,
) -> DynamicsJob {
    DynamicsJob {
        case: case.inner.clone(),
        transmission_error: te.map(TransmissionErrorSource::Samples),
        out,
        replace,
        budget,
        figures,
    }
}

/// One steady-state evaluation of new teeth (as `gearwear dynamics`).
#[pyfunction]
#[pyo3(signature = (case, transmission_error=None, *, out=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn dynamics<'py>(
    py: Python<'py>,
    case: &Case,
    transmission_error: Option<PyReadonlyArray2<'py, f64>>,
    out: Option<PathBuf>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = dynamics_job(
        case,
        samples_of(transmission_error)?,
        out,
        replace,
        budget_for(budget_scale, &figures, figure_size)?,
        figure_request(figures, figure_size),
    );
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
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

/// The wear study (as `gearwear wear`).
#[pyfunction]
#[pyo3(signature = (case, mode="both", progress=None, *, out=None, resume=false, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn wear<'py>(
    py: Python<'py>,
    case: &Case,
    mode: &str,
    progress: Option<Bound<'py, PyAny>>,
    out: Option<PathBuf>,
    resume: bool,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = WearJob {
        case: case.inner.clone(),
        modes: modes_of(mode)?,
        out,
        replace,
        resume,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, progress)?;
    outcome_to_py(py, o, w)
}

/// The paper's whole section 4 (as `gearwear run`).
#[pyfunction]
#[pyo3(signature = (case, out=None, progress=None, *, resume=false, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn run<'py>(
    py: Python<'py>,
    case: &Case,
    out: Option<PathBuf>,
    progress: Option<Bound<'py, PyAny>>,
    resume: bool,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = RunJob {
        case: case.inner.clone(),
        out,
        replace,
        resume,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, progress)?;
    outcome_to_py(py, o, w)
}

/// The label of a value given as a Python object (`format_number` for floats).
fn label_of(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(x) => format_number(*x),
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// An axis from a key and a Python value: range or list text (`"20:40:5"`, `"a,b"`), or
/// a sequence of values (numbers, strings, arrays of numbers).
fn axis_of(key: &str, spec: &Bound<'_, PyAny>) -> PyResult<Result<Axis, String>> {
    if let Ok(s) = spec.cast::<PyString>() {
        return Ok(parse_axis(key, &s.to_cow()?).map_err(|p| p.render(spell)));
    }
    let mut values = Vec::new();
    for item in spec.try_iter()? {
        let item = item?;
        let value = match item.cast::<PyString>() {
            Ok(s) => override_value(&s.to_cow()?),
            Err(_) => crate::convert::py_to_toml(&item)?,
        };
        values.push(AxisValue {
            label: label_of(&value),
            value,
        });
    }
    Ok(Axis::new(key, values).map_err(|p| p.render(spell)))
}

/// `"up"`, `"down"` or `"both"`.
fn continuation_of(c: Option<&str>) -> PyResult<Option<Continuation>> {
    Ok(match c {
        None => None,
        Some("up") => Some(Continuation::Up),
        Some("down") => Some(Continuation::Down),
        Some("both") => Some(Continuation::Both),
        Some(o) => {
            return Err(PyValueError::new_err(format!(
                "continuation = {o:?}: expected \"up\", \"down\" or \"both\""
            )))
        }
    })
}

/// A seed given as an int or a whole float in [0, 2^53] (`gearwear::rng`: the message
/// names `seed`, the value and the range); a bool is not a seed; None (absent) is 1.
fn seed_of(py: Python<'_>, seed: Option<&Bound<'_, PyAny>>) -> PyResult<u64> {
    // Absent: 1, the command line's default.
    let Some(seed) = seed else { return Ok(1) };
    let checked = if seed.is_instance_of::<pyo3::types::PyBool>() {
        Err(format!(
            "`seed` = {seed} is a bool, expected a whole number in [0, {}]",
            gearwear::rng::MAX_SEED
        ))
    } else if let Ok(i) = seed.extract::<i128>() {
        gearwear::rng::seed_from_i128("seed", i).map_err(|e| e.to_string())
    } else if let Ok(x) = seed.extract::<f64>() {
        gearwear::rng::seed_from_f64("seed", x).map_err(|e| e.to_string())
    } else {
        return Err(PyTypeError::new_err(format!(
            "seed takes a whole number in [0, {}]",
            gearwear::rng::MAX_SEED
        )));
    };
    checked.map_err(|m| crate::errors::case_error(py, &[m]))
}

/// A shard given as `"I/N"` or `(I, N)`.
fn shard_of(shard: Option<&Bound<'_, PyAny>>) -> PyResult<Result<Shard, String>> {
    let Some(s) = shard else {
        return Ok(Ok(Shard::ALL));
    };
    let text = match s.extract::<(usize, usize)>() {
        Ok((i, n)) => format!("{i}/{n}"),
        Err(_) => s.extract::<String>()?,
    };
    Ok(Shard::parse(&text).map_err(|p| p.render(spell)))
}

/// The cross product of `vary` on `case` (as `gearwear sweep`): in memory, or with `out`
/// resumable and shardable; or one axis followed along its branches.
#[pyfunction]
#[pyo3(signature = (case, vary, run="dynamics", progress=None, *, out=None, shard=None, continuation=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep<'py>(
    py: Python<'py>,
    case: &Case,
    vary: Vec<(String, Bound<'py, PyAny>)>,
    run: &str,
    progress: Option<Bound<'py, PyAny>>,
    out: Option<PathBuf>,
    shard: Option<Bound<'py, PyAny>>,
    continuation: Option<String>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = match run {
        "dynamics" => SweepRun::Dynamics,
        "wear" => SweepRun::Wear,
        _ => {
            return Err(PyValueError::new_err(format!(
                "run = {run:?}: expected \"dynamics\" or \"wear\""
            )))
        }
    };
    let mut axes = Vec::new();
    let mut problems = Vec::new();
    for (k, v) in &vary {
        match axis_of(k, v)? {
            Ok(a) => axes.push(a),
            Err(e) => problems.push(e),
        }
    }
    let shard = shard_of(shard.as_ref())?;
    problems.extend(shard.as_ref().err().cloned());
    if !problems.is_empty() {
        return Err(crate::errors::case_error(py, &problems));
    }
    let plan =
        SweepPlan::new(axes).map_err(|p| crate::errors::case_error(py, &[p.render(spell)]))?;
    let job = SweepJob {
        base: case.inner.clone(),
        plan,
        run: kind,
        shard: shard.unwrap_or(Shard::ALL),
        continuation: continuation_of(continuation.as_deref())?,
        out,
        replace,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, progress)?;
    sweep_to_py(py, o, w)
}

/// The tables of sweep shards joined (as `gearwear sweep-merge`).
#[pyfunction]
#[pyo3(signature = (inputs, out=None, *, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
pub fn sweep_merge<'py>(
    py: Python<'py>,
    inputs: Vec<PathBuf>,
    out: Option<PathBuf>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = SweepMergeJob {
        inputs,
        out,
        replace,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, None)?;
    sweep_to_py(py, o, w)
}

/// The posterior of the wear coefficient given observations (as `gearwear calibrate`).
/// `observations`: a CSV path, or `(columns, arrays)`.
#[pyfunction]
#[pyo3(signature = (case, observations, *, seed=None, samples=2000, walkers=32, steps=2000, check_runs=3, out=None, progress=None, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn calibrate<'py>(
    py: Python<'py>,
    case: &Case,
    observations: Bound<'py, PyAny>,
    seed: Option<Bound<'py, PyAny>>,
    samples: usize,
    walkers: usize,
    steps: usize,
    check_runs: usize,
    out: Option<PathBuf>,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = CalibrateJob {
        case: case.inner.clone(),
        observations: path_or_columns(&observations)?,
        options: CalibrationOptions {
            seed: seed_of(py, seed.as_ref())?,
            samples,
            walkers,
            steps,
            check_runs,
        },
        out,
        replace,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, progress)?;
    outcome_to_py(py, o, w)
}

/// A `[load_spectrum]` section given as TOML text or a path to a file (told apart as
/// `Case.from_toml` tells them).
fn spectrum_source(s: &Bound<'_, PyAny>) -> PyResult<SpectrumSource> {
    if let Ok(t) = s.cast::<PyString>() {
        let t = t.to_cow()?.into_owned();
        if is_toml_text(&t) {
            return Ok(SpectrumSource::Text(t));
        }
    }
    s.extract::<PathBuf>()
        .map(SpectrumSource::File)
        .map_err(|_| {
            PyTypeError::new_err("future_spectrum takes TOML text or a path to a TOML file")
        })
}

/// Monte Carlo prediction of wear, vibration and remaining life (as `gearwear predict`).
/// `posterior`: None (the case's prior), a CSV path, or `(columns, arrays)`.
#[pyfunction]
#[pyo3(signature = (case, posterior=None, *, limit_um, cycles, seed=None, samples=None, grid_points=101, forward="surrogate", shard=None, check_runs=3, out=None, progress=None, budget_scale=1.0, replace=false, future_spectrum=None, future_from_cycles=None, figures=None, figure_size=None))]
#[allow(clippy::too_many_arguments)]
pub fn predict<'py>(
    py: Python<'py>,
    case: &Case,
    posterior: Option<Bound<'py, PyAny>>,
    limit_um: f64,
    cycles: f64,
    seed: Option<Bound<'py, PyAny>>,
    samples: Option<usize>,
    grid_points: usize,
    forward: &str,
    shard: Option<Bound<'py, PyAny>>,
    check_runs: usize,
    out: Option<PathBuf>,
    progress: Option<Bound<'py, PyAny>>,
    budget_scale: f64,
    replace: bool,
    future_spectrum: Option<Bound<'py, PyAny>>,
    future_from_cycles: Option<f64>,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let forward = match forward {
        "surrogate" => ForwardModel::Surrogate,
        "exact" => ForwardModel::Exact,
        _ => {
            return Err(PyValueError::new_err(format!(
                "forward = {forward:?}: expected \"surrogate\" or \"exact\""
            )))
        }
    };
    let shard = shard_of(shard.as_ref())?.map_err(|m| crate::errors::case_error(py, &[m]))?;
    let job = PredictJob {
        case: case.inner.clone(),
        posterior: posterior.as_ref().map(path_or_columns).transpose()?,
        options: PredictOptions {
            limit_um,
            cycles,
            seed: seed_of(py, seed.as_ref())?,
            samples,
            grid_points,
            forward,
            check_runs,
        },
        future: FutureInput {
            spectrum: future_spectrum.as_ref().map(spectrum_source).transpose()?,
            from_cycles: future_from_cycles,
        },
        shard,
        out,
        replace,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, progress)?;
    outcome_to_py(py, o, w)
}

/// The shards of a prediction joined (as `gearwear predict-merge`).
#[pyfunction]
#[pyo3(signature = (inputs, out=None, *, budget_scale=1.0, replace=false, figures=None, figure_size=None))]
pub fn predict_merge<'py>(
    py: Python<'py>,
    inputs: Vec<PathBuf>,
    out: Option<PathBuf>,
    budget_scale: f64,
    replace: bool,
    figures: Option<String>,
    figure_size: Option<(i64, i64)>,
) -> PyResult<Bound<'py, PyDict>> {
    let job = PredictMergeJob {
        inputs,
        out,
        replace,
        budget: budget_for(budget_scale, &figures, figure_size)?,
        figures: figure_request(figures, figure_size),
    };
    let (o, w) = run_job(py, job, None)?;
    outcome_to_py(py, o, w)
}

/// Benchmark helper: seconds taken by each of `repeats` Rust-only runs of the job
/// `dynamics(case)` runs (model, evaluation, report builder, metadata), GIL released.
#[pyfunction]
pub fn _time_rust_dynamics(py: Python<'_>, case: &Case, repeats: usize) -> PyResult<Vec<f64>> {
    use gearwear::app::Job;
    let job = dynamics_job(case, None, None, false, None, FigureRequest::default());
    Ok(py.detach(move || {
        (0..repeats)
            .map(|_| {
                let t0 = Instant::now();
                drop(job.run(&()));
                t0.elapsed().as_secs_f64()
            })
            .collect()
    }))
}
