//! Reading a case: TOML text, `section.key=value` overrides, key and type checks, ranges.
//!
//! Every problem found becomes one line of [`ConfigError`]; nothing is computed from a
//! case that has any.
//!
//! Deliberate choices about the input's form (docs/CONFIG.md, "Form of a case"):
//! - A section may be written as a `[section]` table, an inline table
//!   (`gear = { module_mm = 3 }`) or dotted keys (`gear.module_mm = 3`): TOML defines
//!   them as the same table, so they are the same case. Anything else where a section
//!   belongs (a number, an array of tables `[[gear]]`) is an error.
//! - A whole-number key accepts `25` and `25.0`; a number key accepts `30` and `30.0`.
//! - An override is one line: a newline or another control character in it is an error
//!   (multi-line values belong in the case file), never silently cut.
//! - Values echoed in messages are cut to [`SHOWN_CHARS`] characters with an ellipsis.

use super::case::Case;
use super::schema::{spec, KeySpec, Range, Valid, KEYS, TABLE_ARRAYS};
use crate::format::{clip, SHOWN_CHARS};
use crate::remedy::{Arg, Words};
use std::fmt;
use toml::{Table, Value};

/// All problems found in a case, one message each. A message about an override names
/// the override argument through [`Words`], which each front end spells its own way.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigError {
    pub problems: Vec<Words>,
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "invalid case ({} problem(s)):", self.problems.len())?;
        for p in &self.problems {
            writeln!(f, "  - {p}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ConfigError {}

impl ConfigError {
    pub fn one(msg: impl Into<String>) -> Self {
        Self {
            problems: vec![Words::from(msg.into())],
        }
    }

    fn of(problems: Vec<String>) -> Self {
        Self {
            problems: problems.into_iter().map(Words::from).collect(),
        }
    }

    /// The messages in plain words.
    pub fn messages(&self) -> Vec<String> {
        self.problems.iter().map(Words::to_string).collect()
    }
}

/// A TOML value as echoed in messages: numbers short (`1e-9`, not 0.000000001).
fn show(v: &Value) -> String {
    match v {
        Value::Float(x) => super::schema::number(*x),
        _ => clip(&v.to_string(), SHOWN_CHARS),
    }
}

/// A value as an override reads it: one TOML value, or else the text as a bare string
/// (`friction.model=none`).
pub fn override_value(raw: &str) -> Value {
    let raw = raw.trim();
    // One value: exactly the table {v = ...}; anything else is a bare string.
    match toml::from_str::<Table>(&format!("v = {raw}")) {
        Ok(t) if t.len() == 1 => t.get("v").cloned(),
        _ => None,
    }
    .unwrap_or_else(|| Value::String(raw.into()))
}

/// Parse `section.key=value`; the value is read as TOML, or as a bare string.
fn parse_override(text: &str) -> Result<(Vec<String>, Value), Words> {
    let shown = clip(text, SHOWN_CHARS);
    let problem = |quoted: String, what: &str| {
        Words::new()
            .arg(Arg::Override)
            .text(format!(" \"{quoted}\": {what}"))
    };
    if text.chars().any(char::is_control) {
        return Err(problem(
            shown.escape_debug().to_string(),
            "the value holds a line break or another control character; each ",
        )
        .arg(Arg::Override)
        .text(" is one line (put multi-line values in ")
        .arg(Arg::CaseFile)
        .text(")"));
    }
    let (key, raw) = text
        .split_once('=')
        .ok_or_else(|| problem(shown.clone(), "expected section.key=value"))?;
    let key = key.trim();
    let path: Vec<String> = key.split('.').map(str::to_owned).collect();
    if path.len() != 2 || path.iter().any(String::is_empty) {
        return Err(problem(shown, "the key must be section.key"));
    }
    Ok((path, override_value(raw)))
}

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::String(_) => "a string",
        Value::Integer(_) => "an integer",
        Value::Float(_) => "a number",
        Value::Boolean(_) => "a boolean",
        Value::Datetime(_) => "a date",
        Value::Array(_) => "an array",
        Value::Table(_) => "a table",
    }
}

/// The value as a float, if it is a number.
fn as_number(v: &Value) -> Option<f64> {
    v.as_float().or_else(|| v.as_integer().map(|i| i as f64))
}

/// Bring `v` to the type `valid` wants (integers to floats for number keys, whole floats to
/// integers for count keys), or say why it cannot be: Err(problem).
pub(super) fn normalise(path: &str, v: &mut Value, valid: Valid) -> Result<(), String> {
    let wrong = |v: &Value| {
        format!(
            "`{path}` = {} is {}, expected {}",
            show(v),
            type_name(v),
            valid.describe()
        )
    };
    match valid {
        Valid::Num(_) | Valid::NumOrDerived(_) => match v {
            Value::Integer(i) => *v = Value::Float(*i as f64),
            Value::Float(_) => {}
            Value::String(s) if s == "derived" && matches!(valid, Valid::NumOrDerived(_)) => {}
            _ => return Err(wrong(v)),
        },
        Valid::Int(..) => match v {
            Value::Integer(_) => {}
            // 25.0 is the whole number 25; 2^53 bounds the floats that are exact integers.
            Value::Float(x) if x.fract() == 0.0 && x.abs() < 9.0e15 => {
                *v = Value::Integer(*x as i64)
            }
            Value::Float(_) => {}
            _ => return Err(wrong(v)),
        },
        Valid::NumArray(_) => match v {
            Value::Array(items) if items.iter().all(|x| as_number(x).is_some()) => {
                for x in items.iter_mut() {
                    if let Value::Integer(i) = x {
                        *x = Value::Float(*i as f64);
                    }
                }
            }
            _ => return Err(wrong(v)),
        },
        Valid::Choice(_) if !v.is_str() => return Err(wrong(v)),
        Valid::Bool if !v.is_bool() => return Err(wrong(v)),
        Valid::Choice(_) | Valid::Bool => {}
    }
    Ok(())
}

/// Check one (normalised) value against its spec.
pub(super) fn check_range(key: &str, v: &Value, valid: Valid) -> Option<String> {
    let in_range = |r: Range| as_number(v).is_some_and(|x| r.contains(x));
    let ok = match valid {
        Valid::Num(r) => in_range(r),
        Valid::NumOrDerived(r) => v.as_str() == Some("derived") || in_range(r),
        Valid::Int(lo, hi) => v.as_integer().is_some_and(|i| (lo..=hi).contains(&i)),
        Valid::Choice(choices) => v.as_str().is_some_and(|s| choices.contains(&s)),
        Valid::Bool => v.is_bool(),
        Valid::NumArray(r) => v.as_array().is_some_and(|a| {
            !a.is_empty()
                && a.iter()
                    .all(|x| as_number(x).is_some_and(|f| r.contains(f)))
        }),
    };
    (!ok).then(|| {
        format!(
            "`{key}` = {} is invalid{}: expected {}",
            show(v),
            first_bad_element(key, v, valid),
            valid.describe()
        )
    })
}

/// For an array key, which value is out of range (0-based, and the tooth it belongs to
/// for the per-tooth arrays of `[teeth]`): a long array's shown text is clipped, so the
/// message must say where the bad value is. Empty for other keys.
fn first_bad_element(key: &str, v: &Value, valid: Valid) -> String {
    let (Valid::NumArray(r), Some(items)) = (valid, v.as_array()) else {
        return String::new();
    };
    if items.is_empty() {
        return " (the array is empty)".into();
    }
    let bad = items
        .iter()
        .enumerate()
        .find(|(_, x)| !as_number(x).is_some_and(|f| r.contains(f)));
    match bad {
        Some((i, x)) => {
            // One value of a `[teeth]` array holds for every tooth.
            let tooth = if key.starts_with("teeth.") && items.len() > 1 {
                format!(", tooth {i}")
            } else {
                String::new()
            };
            format!(
                " (value {i} of 0 to {}{tooth}, is {})",
                items.len() - 1,
                show(x)
            )
        }
        None => String::new(),
    }
}

/// The sections of the case file, in schema order.
fn sections() -> Vec<&'static str> {
    let mut s: Vec<&str> = KEYS
        .iter()
        .map(|k| k.key.split('.').next().unwrap_or(""))
        .collect();
    s.dedup();
    s
}

/// Check section and key names, normalise value types and check ranges, in place.
fn check_keys(user: &mut Table, problems: &mut Vec<String>) {
    let valid_sections = sections();
    for (section, value) in user.iter_mut() {
        let name = clip(section, SHOWN_CHARS);
        if !valid_sections.contains(&section.as_str()) {
            problems.push(format!(
                "unknown section [{name}]; valid sections: {}",
                valid_sections.join(", ")
            ));
            continue;
        }
        if TABLE_ARRAYS.contains(&section.as_str()) {
            check_table_array(section, value, problems);
            continue;
        }
        let Value::Table(table) = value else {
            problems.push(format!(
                "[{name}] must be a table of keys (a [{name}] section or an inline table), not {}",
                type_name(value)
            ));
            continue;
        };
        check_table(section, table, "", problems);
    }
}

/// Check the keys of one table of `section`, normalising and range-checking in place;
/// `which` is appended to range problems (the entry of an array of tables).
fn check_table(section: &str, table: &mut Table, which: &str, problems: &mut Vec<String>) {
    for (key, v) in table.iter_mut() {
        let path = format!("{section}.{key}");
        let Some(s) = spec(&path) else {
            problems.push(unknown_key(section, &path));
            continue;
        };
        match normalise(&path, v, s.valid) {
            Ok(()) => problems.extend(check_range(&path, v, s.valid).map(|p| p + which)),
            Err(p) => problems.push(p),
        }
    }
}

/// Check an array-of-tables section (`[[fault]]`): every element a table whose keys are
/// the section's schema keys, normalised and range-checked in place. A single table
/// (`[fault]`) is taken as an array of one.
fn check_table_array(section: &str, value: &mut Value, problems: &mut Vec<String>) {
    if let Value::Table(t) = value {
        *value = Value::Array(vec![Value::Table(std::mem::take(t))]);
    }
    let Value::Array(items) = value else {
        problems.push(format!(
            "[[{section}]] must be tables of keys (`[[{section}]]` sections), not {}",
            type_name(value)
        ));
        return;
    };
    for (i, item) in items.iter_mut().enumerate() {
        let Value::Table(table) = item else {
            problems.push(format!(
                "[[{section}]] entry {i} must be a table of keys, not {}",
                type_name(item)
            ));
            continue;
        };
        check_table(section, table, &format!(" ({section} {i})"), problems);
        let required: &[&str] = match section {
            "fault" => &["kind", "gear", "tooth"],
            _ => &[],
        };
        for required in required {
            if !table.contains_key(*required) {
                problems.push(format!(
                    "`{section}.{required}` is required in every [[{section}]] table ({section} {i} has none)"
                ));
            }
        }
    }
}

/// The section read apart by [`super::load_spectrum`].
const LOAD_SPECTRUM: &str = "load_spectrum";

/// An override of a key of an array-of-tables section (`fault.crack_depth_mm=1`): it sets
/// the key of the section's only table, made when there is none. With several tables
/// the override cannot say which one it means.
fn set_table_array_value(
    user: &mut Table,
    section: &str,
    key: &str,
    value: Value,
) -> Result<(), String> {
    let entry = user
        .entry(section.to_owned())
        .or_insert_with(|| Value::Array(Vec::new()));
    if let Value::Table(t) = entry {
        *entry = Value::Array(vec![Value::Table(std::mem::take(t))]);
    }
    let Value::Array(items) = entry else {
        return Err(format!("[[{section}]] is not an array of tables"));
    };
    if items.is_empty() {
        items.push(Value::Table(Table::new()));
    }
    match items.as_mut_slice() {
        [Value::Table(t)] => {
            t.insert(key.to_owned(), value);
            Ok(())
        }
        _ => Err(format!(
            "the case has {} [[{section}]] tables: an override of `{section}.{key}` applies to a case with at most one (write the tables in the case file)",
            items.len()
        )),
    }
}

/// Checks that involve more than one key of the case file itself.
fn check_relations(case: &Case, problems: &mut Vec<String>) {
    problems.extend(super::teeth::teeth_problems(
        &case.teeth,
        &case.modification,
        &case.fault,
        case.gear.teeth_pinion,
        case.gear.teeth_gear,
    ));
    let s = &case.surface;
    if s.roughness_table_wear_um.len() != s.roughness_table_rms_um.len() {
        problems.push(format!(
            "`surface.roughness_table_wear_um` has {} entries but `surface.roughness_table_rms_um` has {}: they must have the same length",
            s.roughness_table_wear_um.len(),
            s.roughness_table_rms_um.len()
        ));
    }
    if s.roughness_table_wear_um.windows(2).any(|w| w[1] <= w[0]) {
        problems.push(format!(
            "`surface.roughness_table_wear_um` = {} must be strictly ascending",
            clip(&format!("{:?}", s.roughness_table_wear_um), SHOWN_CHARS)
        ));
    }
    if case.friction.model == super::case::FrictionModel::Xu2007
        && case.lubricant.viscosity_cp <= 1.0
    {
        problems.push(format!(
            "`lubricant.viscosity_cp` = {} is invalid with friction.model = \"xu2007\": Xu's regression uses log10 of the viscosity in cP and needs a value > 1",
            case.lubricant.viscosity_cp
        ));
    }
    let g = &case.gear;
    let ratio = g.face_width_mm / g.module_mm;
    if !(1.0..=100.0).contains(&ratio) {
        problems.push(format!(
            "`gear.face_width_mm` = {} is {ratio:.3} times `gear.module_mm` = {}: the face width must lie between 1 and 100 modules (a narrower tooth is a plate, a wider one cannot carry its load evenly)",
            g.face_width_mm, g.module_mm
        ));
    }
    problems.extend(super::signals::relation_problems(case));
    problems.extend(super::train::stage_problems(
        &case.stage,
        &single_pair_inputs(case),
    ));
    for (i, stage) in case.stage.iter().enumerate() {
        let g = stage.gear_section(&case.gear);
        let ratio = g.face_width_mm / g.module_mm;
        if !(1.0..=100.0).contains(&ratio) {
            problems.push(format!(
                "stage {}: the face width {} mm is {ratio:.3} times the module {} mm (`stage.face_width_mm`, `stage.module_mm`, or their [gear] defaults): it must lie between 1 and 100 modules",
                i + 1,
                g.face_width_mm,
                g.module_mm
            ));
        }
    }
}

/// The sections of a case that describe a single pair's teeth (which a train does not
/// take yet), as written.
fn single_pair_inputs(case: &Case) -> Vec<&'static str> {
    let mut out = Vec::new();
    if case.teeth != Default::default() {
        out.push("[teeth]");
    }
    if case.modification != Default::default() {
        out.push("[modification]");
    }
    if !case.fault.is_empty() {
        out.push("[[fault]]");
    }
    if case.load_spectrum.is_some() {
        out.push("[load_spectrum]");
    }
    out
}

/// Merge the overrides (`section.key=value` texts) into the user's tree.
fn apply_overrides(user: &mut Table, overrides: &[String], problems: &mut Vec<Words>) {
    for o in overrides {
        match parse_override(o) {
            Ok((path, value)) => {
                if let Err(e) = set_value(user, &path[0], &path[1], value) {
                    problems.push(
                        Words::new()
                            .arg(Arg::Override)
                            .text(format!(" {}: {e}", clip(o, SHOWN_CHARS))),
                    )
                }
            }
            Err(e) => problems.push(e),
        }
    }
}

/// A TOML parse error by its place (line, column) and the parser's words, never quoting
/// the text: a file that is not a case file at all (`/etc/passwd`) must not have its
/// content echoed into a message or a log.
fn toml_error(e: &toml::de::Error, text: &str) -> String {
    let place = e
        .span()
        .filter(|_| !text.is_empty())
        .map_or(String::new(), |s| {
            let before = &text.as_bytes()[..s.start.min(text.len())];
            let line = before.iter().filter(|b| **b == b'\n').count() + 1;
            let col = before.iter().rev().take_while(|b| **b != b'\n').count() + 1;
            format!(" at line {line}, column {col}")
        });
    format!("{place}: {}", clip(e.message().trim(), 2 * SHOWN_CHARS))
}

/// `operating.input_speed_rpm` (checked against its range already): the input speed in
/// revolutions per minute, the unit engineers think in, as an alternative to
/// `operating.input_speed_hz`. Replaced by `input_speed_hz` = rpm / 60 here, so a case
/// given in rpm is the very case (and hash) given in Hz; both at once is an error.
fn speed_in_rpm(user: &mut Table, problems: &mut Vec<String>) {
    let Some(Value::Table(op)) = user.get_mut("operating") else {
        return;
    };
    let Some(rpm) = op.remove("input_speed_rpm") else {
        return;
    };
    if op.contains_key("input_speed_hz") {
        problems.push(
            "`operating.input_speed_rpm` and `operating.input_speed_hz` are both given: give the input speed once, in rpm or in Hz".into(),
        );
        return;
    }
    if let Some(x) = rpm
        .as_float()
        .or_else(|| rpm.as_integer().map(|i| i as f64))
    {
        op.insert("input_speed_hz".into(), Value::Float(x / 60.0));
    }
}

/// Set `section.key` in the tree (the only table of an array-of-tables section); the
/// problem when the section is not a table.
fn set_value(user: &mut Table, section: &str, key: &str, value: Value) -> Result<(), String> {
    if TABLE_ARRAYS.contains(&section) {
        return set_table_array_value(user, section, key, value);
    }
    let entry = user
        .entry(section.to_owned())
        .or_insert_with(|| Value::Table(Table::new()));
    match entry {
        Value::Table(t) => {
            t.insert(key.to_owned(), value);
            Ok(())
        }
        _ => Err(format!("[{}] is not a table", clip(section, SHOWN_CHARS))),
    }
}

/// Build a case from TOML text (empty for the default) and overrides (`section.key=value`
/// texts: the command line's `--set`).
///
/// Returns every problem at once; the case is only returned when there is none. A
/// relative `load_spectrum.file` is read from the current folder ([`load_case_in`] names
/// another).
pub fn load_case(toml_text: &str, overrides: &[String]) -> Result<Case, ConfigError> {
    load_case_in(toml_text, overrides, std::path::Path::new("."))
}

/// As [`load_case`], with the folder a relative `load_spectrum.file` is read from (the
/// case file's own folder).
pub fn load_case_in(
    toml_text: &str,
    overrides: &[String],
    dir: &std::path::Path,
) -> Result<Case, ConfigError> {
    let mut user: Table = toml::from_str(toml_text).map_err(|e| {
        ConfigError::one(format!(
            "case file is not valid TOML{}",
            toml_error(&e, toml_text)
        ))
    })?;
    let mut problems = Vec::new();
    apply_overrides(&mut user, overrides, &mut problems);
    if !problems.is_empty() {
        // Check the keys too, so every problem is reported at once.
        let mut more = Vec::new();
        spectrum_section(&mut user, dir, &mut more);
        check_keys(&mut user, &mut more);
        problems.extend(more.into_iter().map(Words::from));
        return Err(ConfigError { problems });
    }
    validate(user, dir)
}

/// A `[load_spectrum]` section on its own: TOML text holding only that table, spelled as in
/// a case file (inline `bins` or a CSV `file`, read from `dir` when relative), parsed and
/// checked by the same code as a case's, so it gives the same problems. A future duty of a
/// prediction is given so.
pub fn load_spectrum_section(
    toml_text: &str,
    dir: &std::path::Path,
) -> Result<super::load_spectrum::LoadSpectrumSection, ConfigError> {
    let mut user: Table = toml::from_str(toml_text)
        .map_err(|e| ConfigError::one(format!("not valid TOML{}", toml_error(&e, toml_text))))?;
    let mut problems = Vec::new();
    let section = spectrum_section(&mut user, dir, &mut problems);
    if let Some(k) = user.keys().next() {
        problems.push(format!(
            "`{}`: only a [load_spectrum] section is read here",
            clip(k, SHOWN_CHARS)
        ));
    }
    match section {
        Some(s) if problems.is_empty() => Ok(s),
        _ => {
            if problems.is_empty() {
                problems.push("no [load_spectrum] section (or an empty one)".into());
            }
            Err(ConfigError::of(problems))
        }
    }
}

/// The case `base` with the typed `values` set (key, value as an override reads it),
/// validated as [`load_case`] validates. A sweep builds its cases so: each value is typed
/// once, when the sweep is planned, not read from text again for every case.
pub fn case_with(base: &Case, values: &[(&str, Value)]) -> Result<Case, ConfigError> {
    let mut user = match Value::try_from(base) {
        Ok(Value::Table(t)) => t,
        _ => return Err(ConfigError::one("the base case does not serialise")),
    };
    for (key, value) in values {
        let (section, k) = key.split_once('.').unwrap_or((key, ""));
        if *key == "operating.input_speed_rpm" {
            // The base case's speed is in Hz: the varied speed in rpm replaces it.
            if let Some(Value::Table(op)) = user.get_mut("operating") {
                op.remove("input_speed_hz");
            }
        }
        set_value(&mut user, section, k, value.clone()).map_err(ConfigError::one)?;
    }
    // A resolved case holds its spectrum's bins inline: no file to read.
    validate(user, std::path::Path::new("."))
}

/// The `[load_spectrum]` section taken out of `user` and read: its bins are tables or a
/// file, not schema keys.
fn spectrum_section(
    user: &mut Table,
    dir: &std::path::Path,
    problems: &mut Vec<String>,
) -> Option<super::load_spectrum::LoadSpectrumSection> {
    user.remove(LOAD_SPECTRUM)
        .and_then(|v| super::load_spectrum::parse_section(v, dir, problems))
}

/// Key, type and range checks of a tree, then the case and the checks across keys.
fn validate(mut user: Table, dir: &std::path::Path) -> Result<Case, ConfigError> {
    let mut problems = Vec::new();
    let spectrum = spectrum_section(&mut user, dir, &mut problems);
    check_keys(&mut user, &mut problems);
    speed_in_rpm(&mut user, &mut problems);
    if !problems.is_empty() {
        return Err(ConfigError::of(problems));
    }
    let mut case: Case = Value::Table(user)
        .try_into()
        .map_err(|e: toml::de::Error| {
            ConfigError::one(format!("case file{}", toml_error(&e, "")))
        })?;
    case.load_spectrum = spectrum;
    check_relations(&case, &mut problems);
    if problems.is_empty() {
        Ok(case)
    } else {
        Err(ConfigError::of(problems))
    }
}

/// Whether `key` is a key of the case file: its entry in the schema, or the problem as
/// [`load_case`] words it (unknown section or key, with the valid ones).
pub fn known_key(key: &str) -> Result<&'static KeySpec, String> {
    if let Some(s) = spec(key) {
        return Ok(s);
    }
    let (section, _) = key.split_once('.').unwrap_or((key, ""));
    let valid_sections = sections();
    if !valid_sections.contains(&section) {
        return Err(format!(
            "unknown section [{}]; valid sections: {}",
            clip(section, SHOWN_CHARS),
            valid_sections.join(", ")
        ));
    }
    Err(unknown_key(section, key))
}

/// "unknown key `section.key`; valid keys in [section]: ...".
fn unknown_key(section: &str, path: &str) -> String {
    let valid: Vec<&str> = KEYS
        .iter()
        .filter(|s| s.key.starts_with(&format!("{section}.")))
        .map(|s| s.key)
        .collect();
    format!(
        "unknown key `{}`; valid keys in [{section}]: {}",
        clip(path, SHOWN_CHARS),
        valid.join(", ")
    )
}

/// Validate every key of an already built case against the schema (used on defaults and
/// templates).
pub fn check_all_ranges(case: &Case) -> Vec<String> {
    let tree = match Value::try_from(case) {
        Ok(Value::Table(t)) => t,
        _ => return vec!["case does not serialise".into()],
    };
    let mut problems = Vec::new();
    for s in KEYS {
        let (section, key) = s.key.split_once('.').unwrap_or(("", s.key));
        if let Some(v) = tree.get(section).and_then(|t| t.get(key)) {
            let mut v = v.clone();
            match normalise(s.key, &mut v, s.valid) {
                Ok(()) => problems.extend(check_range(s.key, &v, s.valid)),
                Err(p) => problems.push(p),
            }
        }
    }
    check_relations(case, &mut problems);
    problems.extend(super::load_spectrum::spectrum_problems(case));
    problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::{Derivable, FrictionModel};

    fn err(text: &str, sets: &[&str]) -> String {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        load_case(text, &sets).unwrap_err().to_string()
    }

    #[test]
    fn defaults_and_new_pair_template_are_valid() {
        assert!(check_all_ranges(&Case::default()).is_empty());
        assert!(check_all_ranges(&Case::new_pair_template()).is_empty());
    }

    #[test]
    fn overrides_apply_and_integers_widen() {
        let c = load_case(
            "",
            &[
                "operating.input_speed_hz=45".into(),
                "friction.model=constant".into(),
            ],
        )
        .unwrap();
        assert_eq!(c.operating.input_speed_hz, 45.0);
        assert_eq!(c.friction.model, FrictionModel::Constant);
    }

    #[test]
    fn whole_numbers_written_with_a_decimal_point_are_accepted() {
        let c = load_case("", &["gear.teeth_pinion=25.0".into()]).unwrap();
        assert_eq!(c.gear.teeth_pinion, 25);
        let e = err("", &["gear.teeth_pinion=25.5"]);
        assert!(
            e.contains("gear.teeth_pinion") && e.contains("whole number"),
            "{e}"
        );
    }

    #[test]
    fn derived_is_accepted_only_where_the_geometry_can_give_the_value() {
        let c = load_case(
            "[dynamics]\nmass_pinion_kg = \"derived\"\n",
            &["gear.hub_bore_radius_gear_mm=derived".into()],
        )
        .unwrap();
        assert_eq!(c.dynamics.mass_pinion_kg, Derivable::Derived);
        assert_eq!(c.gear.hub_bore_radius_gear_mm, Derivable::Derived);
        let e = err("", &["dynamics.inertia_motor_kg_m2=derived"]);
        assert!(e.contains("dynamics.inertia_motor_kg_m2"), "{e}");
        let e = err("", &["dynamics.mass_gear_kg=derive"]);
        assert!(
            e.contains("dynamics.mass_gear_kg") && e.contains("\"derived\""),
            "{e}"
        );
    }

    #[test]
    fn a_bad_value_in_a_long_per_tooth_array_is_named_by_its_tooth() {
        // 31 values: the shown array is clipped before value 15, so only the index says
        // which tooth is wrong. NaN and inf are not numbers in any range.
        let mut gear = vec!["0"; 31];
        gear[15] = "5000";
        let e = err(
            "",
            &[&format!("teeth.pitch_error_gear_um=[{}]", gear.join(","))],
        );
        assert!(
            e.contains("`teeth.pitch_error_gear_um`")
                && e.contains("(value 15 of 0 to 30, tooth 15, is 5000)")
                && e.contains("[-1000, 1000]"),
            "{e}"
        );
        let e = err("[teeth]\nprofile_slope_pinion_um = [nan]\n", &[]);
        assert!(e.contains("(value 0 of 0 to 0, is NaN)"), "{e}");
        let e = err("[surface]\nroughness_table_wear_um = [0.1, inf, 1]\n", &[]);
        assert!(e.contains("(value 1 of 0 to 2, is inf)"), "{e}");
    }

    #[test]
    fn every_problem_is_reported_once_with_key_and_value() {
        let e = load_case(
            "[gear]\nmodule_mm = -2\nface_width_mm = 0\n[wear]\ncoefficient_m2_per_n = -1e-16\n",
            &[],
        )
        .unwrap_err();
        assert_eq!(e.problems.len(), 3, "{e}");
        let m = e.messages();
        assert!(m
            .iter()
            .any(|p| p.contains("gear.module_mm") && p.contains("-2")));
        assert!(m.iter().any(|p| p.contains("wear.coefficient_m2_per_n")));
    }

    #[test]
    fn non_finite_and_subnormal_values_are_rejected_everywhere() {
        for v in ["nan", "inf", "-inf", "5e-324", "1e-310"] {
            for key in [
                "gear.module_mm",
                "wear.block_cycles",
                "dynamics.bearing_damping_gear_n_s_per_m",
            ] {
                let e = err("", &[&format!("{key}={v}")]);
                assert!(e.contains(key), "{key}={v}: {e}");
            }
            let e = err(
                &format!("[surface]\nroughness_table_rms_um = [0.2, {v}, 0.1]\n"),
                &[],
            );
            assert!(e.contains("surface.roughness_table_rms_um"), "{v}: {e}");
        }
    }

    #[test]
    fn unknown_key_names_the_valid_ones() {
        let e = err("[operating]\nspeed_hz = 3\n", &[]);
        assert!(e.contains("operating.speed_hz"));
        assert!(e.contains("operating.input_speed_hz"));
        let e = err("[gears]\n", &[]);
        assert!(e.contains("unknown section [gears]"));
    }

    #[test]
    fn wrong_type_and_bad_choice() {
        let e = err("[operating]\ninput_speed_hz = \"fast\"\n", &[]);
        assert!(e.contains("is a string"), "{e}");
        let e = err("", &["friction.model=coulomb"]);
        assert!(e.contains("\"xu2007\""), "{e}");
    }

    #[test]
    fn xu_needs_viscosity_above_one_cp() {
        let e = err("", &["lubricant.viscosity_cp=0.8"]);
        assert!(e.contains("lubricant.viscosity_cp"), "{e}");
        // Fine without the Xu model.
        load_case(
            "",
            &[
                "lubricant.viscosity_cp=0.8".into(),
                "friction.model=none".into(),
            ],
        )
        .unwrap();
    }

    #[test]
    fn toml_forms_of_a_section_give_the_same_case_and_others_are_errors() {
        let section = load_case("[gear]\nmodule_mm = 3\n", &[]).unwrap();
        for text in ["gear = { module_mm = 3 }\n", "gear.module_mm = 3\n"] {
            assert_eq!(load_case(text, &[]).unwrap(), section, "{text}");
        }
        for text in ["gear = 3\n", "[[gear]]\nmodule_mm = 3\n"] {
            assert!(err(text, &[]).contains("[gear] must be a table"), "{text}");
        }
    }

    #[test]
    fn set_values_are_one_line_and_never_cut_silently() {
        for bad in [
            "gear.module_mm=3\n[gear]\nmodule_mm = 5",
            "gear.module_mm=3\r\nx",
            "friction.model=constant\tx",
        ] {
            let e = err("", &[bad]);
            assert!(e.contains("line break or another control character"), "{e}");
        }
    }

    #[test]
    fn long_values_are_echoed_cut() {
        let huge = "x".repeat(10_000_000);
        let e = err("", &[&format!("friction.model={huge}")]);
        assert!(e.len() < 2000, "{} bytes", e.len());
        assert!(
            e.contains("friction.model") && e.contains("characters)"),
            "{e}"
        );
        let e = err(&format!("[gear]\nmodule_mm = \"{huge}\"\n"), &[]);
        assert!(e.len() < 2000 && e.contains("gear.module_mm"));
        let e = err(&format!("[gear]\nmodule_mm = {huge}\n"), &[]);
        assert!(e.len() < 2000, "{} bytes", e.len());
    }

    #[test]
    fn face_width_must_suit_the_module() {
        let e = err("", &["gear.face_width_mm=0.5"]);
        assert!(
            e.contains("gear.face_width_mm") && e.contains("gear.module_mm"),
            "{e}"
        );
    }
}
