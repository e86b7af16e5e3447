//! Conversions between the library's values and Python objects: JSON summaries to dicts,
//! TOML values both ways, report tables to numpy arrays, a job's outcome to a dict of
//! named fields, input tables from numpy columns. Nothing else.

use gearwear::app::{Outcome, SweepOutput, TableSource};
use gearwear::io::Table;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict, PyList, PyMapping, PyString};
use std::path::PathBuf;

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

/// Deepest nesting of a case value: a number in an array of a table in an array of
/// tables is depth 3; anything deeper (a self-referential list) is refused before it
/// recurses.
pub const MAX_DEPTH: usize = 4;
/// Most items of an array (or entries of a table) in a case value: the longest array a
/// case takes is far shorter; a longer one (or an endless iterator) is refused before it
/// is read whole.
pub const MAX_ITEMS: usize = 100_000;
/// Longest string in a case value (a model name, a file name).
pub const MAX_STRING: usize = 4096;

/// Whether `obj` is numpy's boolean scalar (`np.bool_`), which has `__index__` and would
/// otherwise pass for the integer 1 where `True` is refused.
fn is_numpy_bool(obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    let t = obj.get_type();
    let module: String = t.module()?.extract().unwrap_or_default();
    let name = t.name()?.to_string();
    Ok(module == "numpy" && (name == "bool_" || name == "bool"))
}

/// A Python value as a TOML value: bool (numpy's too), str, anything with `__index__`
/// (int, numpy integers) as an integer, anything `float()` takes as a finite float,
/// mappings as tables and iterables as arrays, within [`MAX_DEPTH`], [`MAX_ITEMS`] and
/// [`MAX_STRING`]. None, NaN and infinities are refused here, before anything is built.
pub fn py_to_toml(obj: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    to_toml(obj, 0, MAX_DEPTH)
}

/// Deepest nesting of a study design given as a dict: a value of a per-tooth list in the
/// `teeth` table of a condition's case (`condition` list -> table -> `case` -> `teeth`
/// -> list -> number) is depth 6.
pub const MAX_DESIGN_DEPTH: usize = 8;

/// A study design given as a mapping, as a TOML table, within [`MAX_DESIGN_DEPTH`] and
/// the item and string limits of [`py_to_toml`].
pub fn py_to_toml_design(obj: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    to_toml(obj, 0, MAX_DESIGN_DEPTH)
}

fn to_toml(obj: &Bound<'_, PyAny>, depth: usize, max_depth: usize) -> PyResult<toml::Value> {
    use toml::Value;
    if depth > max_depth {
        return Err(PyValueError::new_err(format!(
            "a value nested more than {max_depth} levels deep (a list that contains itself?)"
        )));
    }
    if obj.is_none() {
        return Err(PyTypeError::new_err("None is not a case value"));
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Value::Boolean(b.is_true()));
    }
    if is_numpy_bool(obj)? {
        return Ok(Value::Boolean(obj.is_truthy()?));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        let s = s.to_cow()?;
        if s.chars().count() > MAX_STRING {
            return Err(PyValueError::new_err(format!(
                "a string of more than {MAX_STRING} characters is not a case value"
            )));
        }
        return Ok(Value::String(s.into_owned()));
    }
    if obj.hasattr("__index__")? {
        return obj
            .extract::<i64>()
            .map(Value::Integer)
            .map_err(|_| PyValueError::new_err("an integer beyond 64 bits is not a case value"));
    }
    if let Ok(f) = obj.extract::<f64>() {
        if !f.is_finite() {
            return Err(PyValueError::new_err(format!(
                "{f} is not a finite number: a case value must be"
            )));
        }
        return Ok(Value::Float(f));
    }
    let too_many = || {
        PyValueError::new_err(format!(
            "more than {MAX_ITEMS} items: no case value is that long (an endless iterator?)"
        ))
    };
    if let Ok(m) = obj.cast::<PyMapping>() {
        if m.len()? > MAX_ITEMS {
            return Err(too_many());
        }
        let mut t = toml::Table::new();
        for item in m.items()?.iter() {
            let (k, v): (String, Bound<'_, PyAny>) = item.extract()?;
            t.insert(k, to_toml(&v, depth + 1, max_depth)?);
        }
        return Ok(Value::Table(t));
    }
    if obj.len().is_ok_and(|n| n > MAX_ITEMS) {
        return Err(too_many());
    }
    if let Ok(it) = obj.try_iter() {
        let mut items = Vec::new();
        for x in it {
            if items.len() == MAX_ITEMS {
                return Err(too_many());
            }
            items.push(to_toml(&x?, depth + 1, max_depth)?);
        }
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
        let name = name
            .strip_suffix(".csv")
            .or_else(|| name.strip_suffix(".parquet"))
            .unwrap_or(name);
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

/// A job's outcome as a dict: `summary`, `tables`, `headline`, `documents` (file name ->
/// bytes: the report, the figures' PNG/SVG files when rendered for it), `warnings`, `out` (the folder
/// written, or None) and `incomplete` (why the result is incomplete, or None).
pub fn outcome_to_py<'py>(
    py: Python<'py>,
    o: Outcome,
    warnings: Vec<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let a = o.artifacts;
    let d = PyDict::new(py);
    d.set_item("summary", json_to_py(py, &a.summary)?)?;
    let docs = PyDict::new(py);
    for (name, bytes) in &a.documents {
        docs.set_item(name, PyBytes::new(py, bytes))?;
    }
    // A figure rendered for a report has its files: the same bytes the folder gets.
    for f in &a.figures {
        let Some(r) = &f.rendered else { continue };
        if let Some(png) = &r.png {
            docs.set_item(&f.path, PyBytes::new(py, png))?;
        }
        if let Some(svg) = &r.svg {
            let name = gearwear::report::artifacts::svg_path(&f.path);
            docs.set_item(name, PyBytes::new(py, svg.as_bytes()))?;
        }
    }
    d.set_item("tables", tables_to_py(py, a.tables)?)?;
    d.set_item("headline", a.headline)?;
    d.set_item("documents", docs)?;
    d.set_item("warnings", warnings)?;
    d.set_item("out", o.published)?;
    d.set_item("incomplete", o.incomplete)?;
    Ok(d)
}

/// A sweep's output as a dict: the outcome's fields (`summary` is sweep.json's content)
/// and the table: `keys`, `columns`, `case_ids`, `values` (the labels of the varied
/// values, a list per row), `branches` (per row, or None), `results` (rows x columns).
pub fn sweep_to_py<'py>(
    py: Python<'py>,
    s: SweepOutput,
    warnings: Vec<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let t = s.table;
    let d = outcome_to_py(py, s.outcome, warnings)?;
    let columns = t.columns();
    let n_cols = columns.len();
    let ids: Vec<f64> = t.rows.iter().map(|r| r.case_id as f64).collect();
    let values: Vec<Vec<String>> = t.rows.iter().map(|r| r.values.clone()).collect();
    let branches: Vec<Option<&str>> = t.rows.iter().map(|r| r.branch.map(|b| b.name())).collect();
    let results = matrix_to_py(
        py,
        t.rows.iter().map(|r| r.results.values()).collect(),
        n_cols,
    )?;
    d.set_item("keys", t.keys)?;
    d.set_item("columns", columns)?;
    d.set_item("case_ids", PyArray1::from_vec(py, ids))?;
    d.set_item("values", values)?;
    d.set_item("branches", branches)?;
    d.set_item("results", results)?;
    Ok(d)
}

/// An input table: a path (`str` or `os.PathLike`) to a CSV file, or `(names, columns)`
/// with one 1-D float64 array per name (NaN: not measured).
pub fn path_or_columns(obj: &Bound<'_, PyAny>) -> PyResult<TableSource> {
    if let Ok((names, columns)) = obj.extract::<(Vec<String>, Vec<PyReadonlyArray1<'_, f64>>)>() {
        let mut t = Table::new();
        for (n, c) in names.iter().zip(columns) {
            t = t.col(n, c.as_array().to_vec());
        }
        return Ok(TableSource::Columns(t));
    }
    match obj.extract::<PathBuf>() {
        Ok(p) => Ok(TableSource::File(p)),
        Err(_) => Err(PyTypeError::new_err(format!(
            "expected a path to a CSV file or (column names, arrays), got {}",
            obj.get_type().name()?
        ))),
    }
}
