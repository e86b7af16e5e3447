//! Python binding of gearwear (`import gearwear`): converts types, computes nothing.
//!
//! The native module `gearwear._gearwear`; the package `gearwear` (python/gearwear/)
//! wraps its dicts in result objects. Layout: [`case`] (the `Case` class), [`jobs`]
//! (the study functions: arguments to a job of `gearwear::app`, the command line's
//! jobs), [`worker`] (a job on its own thread: GIL released, progress, Ctrl-C),
//! [`errors`] (exceptions, and how messages spell the arguments), [`convert`] (JSON,
//! TOML, tables and outcomes to Python, input tables from Python).

use pyo3::prelude::*;

mod case;
mod convert;
mod duty;
mod errors;
mod jobs;
mod pool;
mod signals;
mod worker;

/// Every key of a case file: `[{key, unit, valid, doc, default}]` (docs/CONFIG.md).
#[pyfunction]
fn keys(py: Python<'_>) -> PyResult<Vec<Bound<'_, pyo3::types::PyDict>>> {
    let paper = case::Case {
        inner: gearwear::config::Case::default(),
    };
    gearwear::config::schema::KEYS
        .iter()
        .map(|s| {
            let d = pyo3::types::PyDict::new(py);
            d.set_item("key", s.key)?;
            d.set_item("unit", s.unit)?;
            d.set_item("valid", s.valid.describe())?;
            d.set_item("doc", s.doc)?;
            d.set_item("default", paper.get(py, s.key)?)?;
            Ok(d)
        })
        .collect()
}

/// The `gearwear` command line on `argv` (`sys.argv`: the program's name first), run as the
/// binary runs it (same arguments, outputs, messages and exit codes: `gearwear::cli`); its
/// exit code. The GIL is released while it runs. The console script `gearwear` of the
/// wheel calls it (`gearwear/_cli.py`).
#[pyfunction]
fn _cli_main(py: Python<'_>, argv: Vec<String>) -> u8 {
    py.detach(move || gearwear::cli::main_from(argv))
}

#[pymodule]
fn _gearwear(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    use gearwear::report::dynamics::{COORDINATE_NAMES, COORDINATE_UNITS};
    m.add("COORDINATES", COORDINATE_NAMES)?;
    m.add("COORDINATE_UNITS", COORDINATE_UNITS)?;
    m.add_class::<case::Case>()?;
    m.add_class::<errors::Problem>()?;
    m.add("CaseError", py.get_type::<errors::CaseError>())?;
    m.add("StudyError", py.get_type::<errors::StudyError>())?;
    m.add_function(wrap_pyfunction!(keys, m)?)?;
    m.add_function(wrap_pyfunction!(_cli_main, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::stiffness, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::dynamics, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::wear, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::run, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::sweep_merge, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::calibrate, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::predict, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::predict_merge, m)?)?;
    m.add_function(wrap_pyfunction!(duty::load_spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(duty::_case_with_spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(signals::signals, m)?)?;
    m.add_function(wrap_pyfunction!(signals::dataset, m)?)?;
    m.add_function(wrap_pyfunction!(signals::dataset_merge, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::_time_rust_dynamics, m)?)?;
    m.add_function(wrap_pyfunction!(worker::_running_jobs, m)?)?;
    Ok(())
}
