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

use super::case::{Case, FaultTable, LoadSpectrumSection, ToothFault};
use super::operating::SpeedUnit;
use super::overrides::apply_overrides;
use super::parse::{as_number, check_range, normalise, sections, type_name, unknown_key};
use super::schema::{spec, KeySpec, TABLE_ARRAYS};
use crate::format::{clip, SHOWN_CHARS};
use crate::remedy::Words;
use std::fmt;
use toml::{Table, Value};

pub use super::parse::override_value;

/// All problems found in a case, one message each. A message about an override names
/// the override argument through [`Words`], which each front end spells its own way.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigError {
    /// The problems, one message each, in the order they were found.
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
    /// An error of the one problem `msg`.
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
        // Stages count from 1, as every other stage message does; faults from 0, as
        // their other messages (and the teeth) do.
        let shown = if section == "stage" { i + 1 } else { i };
        check_table(section, table, &format!(" ({section} {shown})"), problems);
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

/// The array-of-tables section of tooth faults, resolved apart once checked.
const FAULT: &str = "fault";
/// The planetary set's section (read by `planetary_section`, not by the schema).
const PLANETARY: &str = "planetary";

/// Checks that involve more than one key of the case file itself.
/// `faults`: the case's `[[fault]]` tables as written, checked here before they are
/// resolved.
fn check_relations(case: &Case, faults: &[FaultTable], problems: &mut Vec<String>) {
    problems.extend(super::teeth_checks::teeth_problems(
        &case.teeth,
        &case.modification,
        faults,
        case.gear.teeth_pinion,
        case.gear.teeth_gear,
        &case
            .stage
            .iter()
            .map(|s| {
                let g = s.gear_section(&case.gear);
                [g.teeth_pinion, g.teeth_gear]
            })
            .collect::<Vec<_>>(),
    ));
    problems.extend(super::teeth_checks::face_span_problems(faults, &case.gear));
    problems.extend(super::train::helical_stage_fault_problems(
        &case.stage,
        &case.gear,
        faults,
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
/// take yet), as written. A `[[fault]]` table names its stage on a train
/// (`fault.stage`) and is checked with the faults.
fn single_pair_inputs(case: &Case) -> Vec<&'static str> {
    let mut out = Vec::new();
    if case.teeth != Default::default() {
        out.push("[teeth]");
    }
    if case.modification != Default::default() {
        out.push("[modification]");
    }
    out
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
    let (hz, rpm) = (
        SpeedUnit::Hz.input_speed_key(),
        SpeedUnit::Rpm.input_speed_key(),
    );
    match SpeedUnit::given(op.contains_key(hz), op.contains_key(rpm), "operating.") {
        Err(both) => {
            op.remove(rpm);
            problems.push(both.to_string());
        }
        Ok(Some(SpeedUnit::Rpm)) => {
            if let Some(x) = op.remove(rpm).as_ref().and_then(as_number) {
                op.insert(hz.into(), Value::Float(SpeedUnit::Rpm.to_hz(x)));
            }
        }
        Ok(_) => {}
    }
}

/// The built-in case with `--set`-style overrides (`"section.key=value"`), for unit tests
/// of the layers above; panics on an override the case refuses.
#[cfg(test)]
pub(crate) fn default_with(overrides: &[&str]) -> Case {
    let sets: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
    load_case("", &sets).expect("a test's overrides are valid")
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
        planetary_section(&mut user, &mut more);
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
pub(crate) fn load_spectrum_section(
    toml_text: &str,
    dir: &std::path::Path,
) -> Result<LoadSpectrumSection, ConfigError> {
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
        if *key == "operating.input_speed_rpm" {
            // The base case's speed is in Hz: the varied speed in rpm replaces it.
            if let Some(Value::Table(op)) = user.get_mut("operating") {
                op.remove("input_speed_hz");
            }
        }
        let path: Vec<String> = match key.split('.').count() {
            3 => key.split('.').map(str::to_owned).collect(),
            _ => {
                let (section, k) = key.split_once('.').unwrap_or((key, ""));
                vec![section.to_owned(), k.to_owned()]
            }
        };
        super::overrides::set_path(&mut user, &path, value.clone()).map_err(ConfigError::one)?;
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
) -> Option<LoadSpectrumSection> {
    user.remove(LOAD_SPECTRUM)
        .and_then(|v| super::load_spectrum::parse_section(v, dir, problems))
}

/// The `[planetary]` section taken out of `user` and read: each of its keys (and
/// `[planetary.lumped]`'s) that the schema lists is normalised and range-checked against
/// it first; then the section is read by serde (`config::planetary`, unknown keys refused
/// there) and its checks across keys run (`PlanetarySection::range_problems`).
fn planetary_section(
    user: &mut Table,
    problems: &mut Vec<String>,
) -> Option<super::planetary::PlanetarySection> {
    let mut value = user.remove(PLANETARY)?;
    let before = problems.len();
    if let Value::Table(t) = &mut value {
        check_nested_keys(PLANETARY, t, problems);
        if let Some(faults) = t.get_mut("fault") {
            check_planetary_faults(faults, problems);
        }
    }
    if problems.len() > before {
        return None;
    }
    match value.try_into::<super::planetary::PlanetarySection>() {
        Ok(section) => {
            problems.extend(section.range_problems());
            Some(section)
        }
        Err(e) => {
            problems.push(format!("[planetary]{}", toml_error(&e, "")));
            None
        }
    }
}

/// The `[[planetary.fault]]` tables (a single `[planetary.fault]` taken as an array of
/// one) normalised and range-checked in place: `kind`, `gear`, `planet` and `tooth` by
/// their own schema entries, the sizes by the pair's `fault.*` entries (the same keys,
/// units and ranges).
fn check_planetary_faults(value: &mut Value, problems: &mut Vec<String>) {
    if let Value::Table(t) = value {
        *value = Value::Array(vec![Value::Table(std::mem::take(t))]);
    }
    let Value::Array(items) = value else {
        problems.push(format!(
            "[[planetary.fault]] must be tables of keys, not {}",
            type_name(value)
        ));
        return;
    };
    for (i, item) in items.iter_mut().enumerate() {
        let Value::Table(table) = item else {
            problems.push(format!(
                "[[planetary.fault]] entry {i} must be a table of keys, not {}",
                type_name(item)
            ));
            continue;
        };
        for (key, v) in table.iter_mut() {
            let path = match key.as_str() {
                "kind" | "gear" | "planet" | "tooth" => format!("planetary.fault.{key}"),
                _ => format!("fault.{key}"),
            };
            let Some(s) = spec(&path) else { continue };
            // A size is checked as the pair's `fault.*` key, named as the user wrote it.
            let named = |p: String| {
                let p = p.replacen(&format!("`{path}`"), &format!("`planetary.fault.{key}`"), 1);
                format!("{p} (planetary fault {})", i + 1)
            };
            match normalise(&path, v, s.valid) {
                Ok(()) => problems.extend(check_range(&path, v, s.valid).map(named)),
                Err(p) => problems.push(named(p)),
            }
        }
    }
}

/// The schema's keys in `table` (at dotted path `prefix`, sub-tables descended) normalised
/// and range-checked in place; keys the schema does not list are left to the reader.
fn check_nested_keys(prefix: &str, table: &mut Table, problems: &mut Vec<String>) {
    for (key, v) in table.iter_mut() {
        let path = format!("{prefix}.{key}");
        if let Value::Table(sub) = v {
            check_nested_keys(&path, sub, problems);
            continue;
        }
        let Some(s) = spec(&path) else { continue };
        match normalise(&path, v, s.valid) {
            Ok(()) => problems.extend(check_range(&path, v, s.valid)),
            Err(p) => problems.push(p),
        }
    }
}

/// Key, type and range checks of a tree, then the case and the checks across keys.
fn validate(mut user: Table, dir: &std::path::Path) -> Result<Case, ConfigError> {
    let mut problems = Vec::new();
    let spectrum = spectrum_section(&mut user, dir, &mut problems);
    let planetary = planetary_section(&mut user, &mut problems);
    check_keys(&mut user, &mut problems);
    speed_in_rpm(&mut user, &mut problems);
    if !problems.is_empty() {
        return Err(ConfigError::of(problems));
    }
    // The `[[fault]]` tables are resolved into the case's faults once they are checked.
    let fault_tables = user.remove(FAULT).map(Value::try_into::<Vec<FaultTable>>);
    let mut case: Case = Value::Table(user)
        .try_into()
        .map_err(|e: toml::de::Error| {
            ConfigError::one(format!("case file{}", toml_error(&e, "")))
        })?;
    let faults = fault_tables
        .transpose()
        .map_err(|e| ConfigError::one(format!("case file{}", toml_error(&e, ""))))?
        .unwrap_or_default();
    case.load_spectrum = spectrum;
    case.planetary = planetary;
    check_relations(&case, &faults, &mut problems);
    if !problems.is_empty() {
        return Err(ConfigError::of(problems));
    }
    case.fault = faults
        .into_iter()
        .map(ToothFault::try_from)
        .collect::<Result<_, _>>()
        .map_err(ConfigError::one)?;
    Ok(case)
}

/// Whether `key` is a key of the case file: its entry in the schema, or the problem as
/// [`load_case`] words it (unknown section or key, with the valid ones).
pub(crate) fn known_key(key: &str) -> Result<&'static KeySpec, String> {
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

/// Validate every key of an already built case against the schema (used on defaults and
/// templates).
#[cfg(test)]
pub(crate) fn check_all_ranges(case: &Case) -> Vec<String> {
    let tree = match Value::try_from(case) {
        Ok(Value::Table(t)) => t,
        _ => return vec!["case does not serialise".into()],
    };
    let mut problems = Vec::new();
    for s in super::schema::KEYS {
        let (section, key) = s.key.split_once('.').unwrap_or(("", s.key));
        if let Some(v) = tree.get(section).and_then(|t| t.get(key)) {
            let mut v = v.clone();
            match normalise(s.key, &mut v, s.valid) {
                Ok(()) => problems.extend(check_range(s.key, &v, s.valid)),
                Err(p) => problems.push(p),
            }
        }
    }
    let faults: Vec<FaultTable> = case.fault.iter().map(|f| f.table().clone()).collect();
    check_relations(case, &faults, &mut problems);
    problems.extend(super::load_spectrum::spectrum_problems(
        case.load_spectrum.as_ref(),
    ));
    problems
}
