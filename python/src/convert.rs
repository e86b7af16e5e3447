//! Conversions between the library's values and Python objects: JSON summaries to dicts,
//! TOML values both ways, report tables to numpy arrays. Nothing else.

use gearwear::io::Table;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString};

/// A JSON value as the Python object `json.loads` would give for its text (the same
/// floats: serde_json writes the shortest round-trip form, so this is exact). Written by
/// hand: ten lines, where a crate would add a dependency tied to the PyO3 version.
pub fn json_to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u)) => u.into_pyobject(py)?.into_any(),
            _ => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| json_to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(m) => {
            let d = PyDict::new(py);
            for (k, x) in m {
                d.set_item(k, json_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// A TOML value as a Python object (tables as dicts; dates as their text).
pub fn toml_to_py<'py>(py: Python<'py>, v: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    use toml::Value;
    Ok(match v {
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        Value::Float(f) => f.into_pyobject(py)?.into_any(),
        Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Datetime(d) => PyString::new(py, &d.to_string()).into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| toml_to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Table(t) => {
            let d = PyDict::new(py);
            for (k, x) in t {
                d.set_item(k, toml_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// A Python value as a TOML value: bool, str, anything with `__index__` (int, numpy
/// integers) as an integer, anything `float()` takes as a float, iterables as arrays.
pub fn py_to_toml(obj: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    use toml::Value;
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Value::Boolean(b.is_true()));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Value::String(s.to_cow()?.into_owned()));
    }
    if obj.hasattr("__index__")? {
        return Ok(Value::Integer(obj.extract::<i64>()?));
    }
    if let Ok(f) = obj.extract::<f64>() {
        return Ok(Value::Float(f));
    }
    if let Ok(it) = obj.try_iter() {
        let items = it.map(|x| py_to_toml(&x?)).collect::<PyResult<Vec<_>>>()?;
        return Ok(Value::Array(items));
    }
    Err(PyTypeError::new_err(format!(
        "cannot use a {} as a case value: give a number, a string, a bool or a list of numbers",
        obj.get_type().name()?
    )))
}

/// The tables of a report as `{name: (columns, data, lengths)}`: `data` a float64 array
/// of shape (n_columns, n_rows) holding column i in row i (NaN past its length, as the
/// CSV leaves those cells empty), `lengths` each column's own length. One array per
/// table rather than one per column: fewer Python objects per call. Names lose their
/// folder and `.csv` (`csv/updates_dynamic.csv` -> `updates_dynamic`).
pub fn tables_to_py<'py>(
    py: Python<'py>,
    tables: Vec<(String, Table)>,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for (path, t) in tables {
        let name = path.rsplit('/').next().unwrap_or(&path);
        let name = name.strip_suffix(".csv").unwrap_or(name);
        let n_rows = t.rows();
        let lengths: Vec<usize> = t.columns.iter().map(Vec::len).collect();
        let mut flat = Vec::with_capacity(n_rows * t.columns.len());
        for c in &t.columns {
            flat.extend_from_slice(c);
            flat.resize(flat.len() + n_rows - c.len(), f64::NAN);
        }
        let data = PyArray1::from_vec(py, flat).reshape([t.columns.len(), n_rows])?;
        out.set_item(name, (t.names, data, lengths))?;
    }
    Ok(out)
}

/// Rows of equal length as a 2-D float64 array (rows x columns).
pub fn matrix_to_py<'py>(
    py: Python<'py>,
    rows: Vec<Vec<f64>>,
    n_cols: usize,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let n = rows.len();
    let flat: Vec<f64> = rows.into_iter().flatten().collect();
    PyArray1::from_vec(py, flat).reshape([n, n_cols])
}
