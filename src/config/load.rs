//! Reading a case: TOML text, `--set key=value` overrides, key and type checks, ranges.
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
//! - A `--set` value is one line: a newline or another control character in it is an
//!   error (multi-line values belong in a `--config` file), never silently cut.
//! - Values echoed in messages are cut to [`SHOWN_CHARS`] characters with an ellipsis.

use super::case::Case;
use super::schema::{spec, Range, Valid, KEYS};
use std::fmt;
use toml::{Table, Value};

/// All problems found in a case, one message each.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigError {
    pub problems: Vec<String>,
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
            problems: vec![msg.into()],
        }
    }
}

/// Longest piece of user input echoed in a message, characters.
pub const SHOWN_CHARS: usize = 80;

/// `text` cut to `max` characters, with an ellipsis and the full length when cut.
pub fn clip(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        None => text.to_owned(),
        Some((at, _)) => format!("{}... ({} characters)", &text[..at], text.chars().count()),
    }
}

/// A TOML value as echoed in messages: numbers short (`1e-9`, not 0.000000001).
fn show(v: &Value) -> String {
    match v {
        Value::Float(x) => super::schema::number(*x),
        _ => clip(&v.to_string(), SHOWN_CHARS),
    }
}

/// Parse `section.key=value`; the value is read as TOML, or as a bare string.
fn parse_override(text: &str) -> Result<(Vec<String>, Value), String> {
    let shown = clip(text, SHOWN_CHARS);
    if text.chars().any(char::is_control) {
        return Err(format!(
            "--set \"{}\": the value holds a line break or another control character; a --set value is one line (put multi-line values in a --config file)",
            shown.escape_debug()
        ));
    }
    let (key, raw) = text
        .split_once('=')
        .ok_or_else(|| format!("--set \"{shown}\": expected section.key=value"))?;
    let key = key.trim();
    let raw = raw.trim();
    let path: Vec<String> = key.split('.').map(str::to_owned).collect();
    if path.len() != 2 || path.iter().any(String::is_empty) {
        return Err(format!("--set \"{shown}\": the key must be section.key"));
    }
    // One value: exactly the table {v = ...}; anything else is a bare string.
    let value = match toml::from_str::<Table>(&format!("v = {raw}")) {
        Ok(t) if t.len() == 1 => t.get("v").cloned(),
        _ => None,
    }
    .unwrap_or_else(|| Value::String(raw.into()));
    Ok((path, value))
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
fn normalise(path: &str, v: &mut Value, valid: Valid) -> Result<(), String> {
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
fn check_range(key: &str, v: &Value, valid: Valid) -> Option<String> {
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
            "`{key}` = {} is invalid: expected {}",
            show(v),
            valid.describe()
        )
    })
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
        let Value::Table(table) = value else {
            problems.push(format!(
                "[{name}] must be a table of keys (a [{name}] section or an inline table), not {}",
                type_name(value)
            ));
            continue;
        };
        for (key, v) in table.iter_mut() {
            let path = format!("{section}.{key}");
            let Some(s) = spec(&path) else {
                let valid: Vec<&str> = KEYS
                    .iter()
                    .filter(|s| s.key.starts_with(&format!("{section}.")))
                    .map(|s| s.key)
                    .collect();
                problems.push(format!(
                    "unknown key `{}`; valid keys in [{section}]: {}",
                    clip(&path, SHOWN_CHARS),
                    valid.join(", ")
                ));
                continue;
            };
            match normalise(&path, v, s.valid) {
                Ok(()) => problems.extend(check_range(&path, v, s.valid)),
                Err(p) => problems.push(p),
            }
        }
    }
}

/// Checks that involve more than one key of the case file itself.
fn check_relations(case: &Case, problems: &mut Vec<String>) {
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
}

/// Merge the `--set` overrides into the user's tree.
fn apply_overrides(user: &mut Table, overrides: &[String], problems: &mut Vec<String>) {
    for o in overrides {
        match parse_override(o) {
            Ok((path, value)) => {
                let section = user
                    .entry(path[0].clone())
                    .or_insert_with(|| Value::Table(Table::new()));
                match section {
                    Value::Table(t) => {
                        t.insert(path[1].clone(), value);
                    }
                    _ => problems.push(format!(
                        "--set {}: [{}] is not a table",
                        clip(o, SHOWN_CHARS),
                        clip(&path[0], SHOWN_CHARS)
                    )),
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

/// Build a case from TOML text (empty for the default) and `--set` overrides.
///
/// Returns every problem at once; the case is only returned when there is none.
pub fn load_case(toml_text: &str, overrides: &[String]) -> Result<Case, ConfigError> {
    let mut problems = Vec::new();
    let mut user: Table = toml::from_str(toml_text).map_err(|e| {
        ConfigError::one(format!(
            "case file is not valid TOML{}",
            toml_error(&e, toml_text)
        ))
    })?;
    apply_overrides(&mut user, overrides, &mut problems);
    check_keys(&mut user, &mut problems);
    speed_in_rpm(&mut user, &mut problems);
    if !problems.is_empty() {
        return Err(ConfigError { problems });
    }
    let case: Case = Value::Table(user)
        .try_into()
        .map_err(|e: toml::de::Error| {
            ConfigError::one(format!("case file{}", toml_error(&e, "")))
        })?;
    check_relations(&case, &mut problems);
    if problems.is_empty() {
        Ok(case)
    } else {
        Err(ConfigError { problems })
    }
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
    fn every_problem_is_reported_once_with_key_and_value() {
        let e = load_case(
            "[gear]\nmodule_mm = -2\nface_width_mm = 0\n[wear]\ncoefficient_m2_per_n = -1e-16\n",
            &[],
        )
        .unwrap_err();
        assert_eq!(e.problems.len(), 3, "{e}");
        assert!(e
            .problems
            .iter()
            .any(|p| p.contains("gear.module_mm") && p.contains("-2")));
        assert!(e
            .problems
            .iter()
            .any(|p| p.contains("wear.coefficient_m2_per_n")));
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
