//! `gearwear.Case`: a validated case, immutable. Every way of making one goes through the
//! library's `load_case` (TOML text plus `section.key=value` overrides), as the command
//! line's `--config` and `--set` do, so a case is valid exactly when the CLI accepts it.

use crate::convert::{py_to_toml, toml_to_py};
use crate::errors::case_error;
use crate::errors::config_error;
use gearwear::config::schema::{spec, KEYS};
use gearwear::config::{commented_template, load_case, Case as LibCase};
use gearwear::io::input::MAX_CASE_BYTES;
use gearwear::io::read_input_text;
use gearwear::store::RunMetadata;
use pyo3::exceptions::{PyKeyError, PyOSError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyMapping, PyString, PyTuple};
use std::path::PathBuf;

/// A gear-pair case: every input of the model, validated.
///
/// Build one with ``Case.paper()`` (the paper's case, the defaults), ``Case.from_toml``
/// (a case file or its text, as ``gearwear --config``) and ``case.set(key, value)`` (as
/// ``--set key=value``; returns a new case). Read a key with ``case["gear.module_mm"]``.
/// Every key, with its unit, default and valid range: ``gearwear.keys()`` or
/// docs/CONFIG.md. Invalid input raises ``gearwear.CaseError`` listing every problem.
/// Geometry that cannot mesh is found when a study builds the model (as in the CLI).
#[pyclass(frozen, eq, module = "gearwear", name = "Case")]
#[derive(Clone, PartialEq)]
pub struct Case {
    pub inner: LibCase,
}

/// The case as a TOML tree (every key present except unset optional ones).
fn tree(c: &LibCase) -> toml::Table {
    match toml::Value::try_from(c) {
        Ok(toml::Value::Table(t)) => t,
        _ => toml::Table::new(),
    }
}

/// The sections of `mine` that differ from `paper` beyond what the flat `KEYS` reach
/// (`section.key`): arrays of tables (`[[stage]]`, `[[fault]]`) and nested tables, each
/// named as it is spelt in a case file (`[[stage]] x 2`, `[planetary]`), so that
/// `Case.__repr__` never shows a case as another one.
fn beyond_flat_keys(mine: &toml::Table, paper: &toml::Table) -> Vec<String> {
    let rest = |t: &toml::Table, sec: &str| -> Option<toml::Value> {
        match t.get(sec)?.clone() {
            toml::Value::Table(mut tab) => {
                for s in KEYS {
                    if let Some((a, k)) = s.key.split_once('.') {
                        if a == sec {
                            tab.remove(k);
                        }
                    }
                }
                (!tab.is_empty()).then_some(toml::Value::Table(tab))
            }
            other => Some(other),
        }
    };
    let sections: std::collections::BTreeSet<&String> = mine.keys().chain(paper.keys()).collect();
    sections
        .into_iter()
        .filter(|sec| rest(mine, sec) != rest(paper, sec))
        .map(|sec| match mine.get(sec.as_str()) {
            Some(toml::Value::Array(a)) => format!("[[{sec}]] x {}", a.len()),
            _ => format!("[{sec}]"),
        })
        .collect()
}

/// Load through the library; problems become `CaseError`.
fn load(py: Python<'_>, text: &str, sets: &[String]) -> PyResult<Case> {
    load_case(text, sets)
        .map(|inner| Case { inner })
        .map_err(|e| config_error(py, &e.problems))
}

/// Whether a string is TOML text rather than a file name: it has a line break, a `=` or
/// a `[`, or is blank (the empty case).
pub(crate) fn is_toml_text(s: &str) -> bool {
    s.trim().is_empty() || s.contains(['\n', '=', '['])
}

impl Case {
    /// The case as the TOML text `to_toml` gives Python (read back to the same case).
    pub(crate) fn to_toml_text(&self) -> String {
        commented_template(&self.inner)
    }

    /// The value of `key` as a Python object.
    pub fn get<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        let (s, k) = key.split_once('.').unwrap_or((key, ""));
        match tree(&self.inner).get(s).and_then(|t| t.get(k)) {
            Some(v) => toml_to_py(py, v),
            None if spec(key).is_some() => Ok(py.None().into_bound(py)),
            None => Err(PyKeyError::new_err(format!(
                "unknown key `{key}`; gearwear.keys() lists the valid ones"
            ))),
        }
    }
}

#[pymethods]
impl Case {
    /// The paper's case (the defaults), as ``Case.paper()``.
    #[new]
    fn new() -> Self {
        Self::paper()
    }

    /// The paper's case: Coatings 2022, 12, 1250, Tables 1-2 and section 4, with the
    /// readings and added parameters docs/MODEL.md gives.
    #[staticmethod]
    fn paper() -> Self {
        Case {
            inner: LibCase::default(),
        }
    }

    /// A case from a TOML case file (a ``pathlib.Path``, or a ``str`` file name) or from
    /// TOML text (a ``str`` with a line break, ``=`` or ``[``). Omitted keys take the
    /// paper's values.
    #[staticmethod]
    fn from_toml(py: Python<'_>, source: &Bound<'_, PyAny>) -> PyResult<Self> {
        let given: Option<String> = match source.cast::<PyString>() {
            Ok(s) => Some(s.to_cow()?.into_owned()),
            Err(_) => None,
        };
        let text = match given {
            Some(s) if is_toml_text(&s) => s,
            _ => {
                let path: PathBuf = source.extract().map_err(|_| {
                    PyTypeError::new_err("from_toml takes TOML text or a path to a case file")
                })?;
                // A regular file of bounded size only (a FIFO or /dev/zero is refused at
                // once); a file that is not TOML is named, never quoted.
                read_input_text(&path, "case file", MAX_CASE_BYTES)
                    .map_err(|e| PyOSError::new_err(format!("case file {e}")))?
            }
        };
        load(py, &text, &[])
    }

    /// A new case with keys changed, as ``--set key=value``: ``case.set(key, value)`` or
    /// ``case.set({key: value, ...})`` (several keys at once, checked together, e.g. the
    /// two roughness tables). None unsets an optional key (one with no value in the
    /// paper's case, e.g. ``gear.centre_distance_mm``: then the one the profile shifts
    /// give); for any other key it is refused. Values are converted before anything is
    /// built: NaN, infinities, nesting deeper than 4 levels and arrays of more than 1e5
    /// items are refused.
    #[pyo3(signature = (*args))]
    fn set(&self, py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Self> {
        let pairs: Vec<(String, Bound<'_, PyAny>)> = match args.len() {
            2 => vec![(args.get_item(0)?.extract()?, args.get_item(1)?)],
            1 => {
                let m = args.get_item(0)?;
                let m = m.cast::<PyMapping>().map_err(|_| {
                    PyTypeError::new_err("set(key, value) or set({key: value, ...})")
                })?;
                let mut v = Vec::new();
                for item in m.items()?.iter() {
                    let (k, x): (String, Bound<'_, PyAny>) = item.extract()?;
                    v.push((k, x));
                }
                v
            }
            _ => {
                return Err(PyTypeError::new_err(
                    "set(key, value) or set({key: value, ...})",
                ))
            }
        };
        let mut t = tree(&self.inner);
        let mut sets = Vec::new();
        let paper = tree(&LibCase::default());
        let mut problems = Vec::new();
        for (key, value) in pairs {
            let (s, k) = key.split_once('.').unwrap_or((&key, ""));
            if value.is_none() {
                let optional =
                    spec(&key).is_some() && paper.get(s).and_then(|x| x.get(k)).is_none();
                if !optional {
                    problems.push(format!(
                        "`{key}` = None: only an optional key (one the paper's case leaves unset) can be unset; give a value"
                    ));
                    continue;
                }
                if let Some(toml::Value::Table(sec)) = t.get_mut(s) {
                    sec.remove(k);
                }
                continue;
            }
            match py_to_toml(&value) {
                Ok(v) => sets.push(format!("{key}={v}")),
                Err(e) => problems.push(format!("`{key}`: {}", e.value(py))),
            }
        }
        if !problems.is_empty() {
            return Err(case_error(py, &problems));
        }
        let text = toml::to_string(&t).map_err(|e| PyTypeError::new_err(e.to_string()))?;
        load(py, &text, &sets)
    }

    /// The case as commented TOML (every key with its unit, meaning and valid range), as
    /// ``gearwear config`` prints it; ``Case.from_toml`` reads it back.
    fn to_toml(&self) -> String {
        commented_template(&self.inner)
    }

    /// The value of a key, e.g. ``case["gear.module_mm"]`` (None for an unset optional
    /// key).
    fn __getitem__<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        self.get(py, key)
    }

    fn __contains__(&self, key: &str) -> bool {
        spec(key).is_some()
    }

    /// Every key of the case, in the order of the case file.
    fn keys(&self) -> Vec<&'static str> {
        KEYS.iter().map(|s| s.key).collect()
    }

    /// The case as a flat dict ``{key: value}`` (None for unset optional keys).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for s in KEYS {
            d.set_item(s.key, self.get(py, s.key)?)?;
        }
        Ok(d)
    }

    /// SHA-256 of the resolved case, as ``metadata.case_sha256`` in every summary.
    #[getter]
    fn sha256(&self) -> String {
        RunMetadata::new("", &self.inner).case_sha256
    }

    /// ``Case.paper().set({...})`` with the keys that differ from the paper's case, when
    /// those keys rebuild it; a case the flat keys cannot spell (a gear train's
    /// ``[[stage]]`` tables, tooth faults, a planetary set's nested tables) gets a
    /// ``<gearwear.Case: ...>`` that names what else differs (``to_toml()`` spells all).
    fn __repr__(&self) -> String {
        let (mine, paper) = (tree(&self.inner), tree(&LibCase::default()));
        let mut diff = Vec::new();
        for s in KEYS {
            let (sec, k) = s.key.split_once('.').unwrap_or((s.key, ""));
            let a = mine.get(sec).and_then(|t| t.get(k));
            let b = paper.get(sec).and_then(|t| t.get(k));
            if a != b {
                let v = a.map_or("None".to_owned(), |v| match v {
                    toml::Value::Boolean(true) => "True".into(),
                    toml::Value::Boolean(false) => "False".into(),
                    other => other.to_string(),
                });
                diff.push(format!("{:?}: {v}", s.key));
            }
        }
        let beyond = beyond_flat_keys(&mine, &paper);
        match (diff.is_empty(), beyond.is_empty()) {
            (true, true) => "gearwear.Case.paper()".into(),
            (false, true) => format!("gearwear.Case.paper().set({{{}}})", diff.join(", ")),
            (true, false) => format!(
                "<gearwear.Case: the paper's case with {}; to_toml() spells every key>",
                beyond.join(", ")
            ),
            (false, false) => format!(
                "<gearwear.Case: the paper's case with {} and the keys {{{}}}; to_toml() \
                 spells every key>",
                beyond.join(", "),
                diff.join(", ")
            ),
        }
    }

    /// Pickling (e.g. for multiprocessing): the case travels as its TOML text.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        let text =
            toml::to_string(&slf.get().inner).map_err(|e| PyTypeError::new_err(e.to_string()))?;
        Ok((slf.get_type().getattr("from_toml")?, (text,)))
    }
}
