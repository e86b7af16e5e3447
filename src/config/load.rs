//! Reading a case: TOML text, `--set key=value` overrides, key and type checks, ranges.
//!
//! Every problem found becomes one line of [`ConfigError`]; nothing is computed from a
//! case that has any.

use super::case::Case;
use super::schema::{spec, Valid, KEYS};
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

/// The default case as a TOML tree (the reference for key names and types).
fn default_tree() -> Table {
    match Value::try_from(Case::default()) {
        Ok(Value::Table(t)) => t,
        _ => unreachable!("Case serialises to a table"),
    }
}

/// Parse `section.key=value`; the value is read as TOML, or as a bare string.
fn parse_override(text: &str) -> Result<(Vec<String>, Value), String> {
    let (key, raw) = text
        .split_once('=')
        .ok_or_else(|| format!("--set \"{text}\": expected section.key=value"))?;
    let key = key.trim();
    let raw = raw.trim();
    let path: Vec<String> = key.split('.').map(str::to_owned).collect();
    if path.len() != 2 || path.iter().any(String::is_empty) {
        return Err(format!("--set \"{text}\": the key must be section.key"));
    }
    let value = match toml::from_str::<Table>(&format!("v = {raw}")) {
        Ok(mut t) => t.remove("v").unwrap_or(Value::String(raw.into())),
        Err(_) => Value::String(raw.into()),
    };
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

/// Whether `got` can stand where the default has `want` (integers may stand for floats).
fn same_kind(want: &Value, got: &Value) -> bool {
    matches!(
        (want, got),
        (Value::Float(_), Value::Float(_) | Value::Integer(_))
            | (Value::Integer(_), Value::Integer(_))
            | (Value::String(_), Value::String(_))
            | (Value::Boolean(_), Value::Boolean(_))
            | (Value::Array(_), Value::Array(_))
            | (Value::Table(_), Value::Table(_))
    )
}

/// Check key names and value types against the default tree; widen integers to floats
/// where the default is a float so that serde accepts `input_speed_hz = 30`.
fn check_keys(user: &mut Table, problems: &mut Vec<String>) -> Vec<String> {
    let mut bad_paths = Vec::new();
    let reference = default_tree();
    for (section, value) in user.iter_mut() {
        let Some(ref_section) = reference.get(section) else {
            let valid: Vec<&str> = reference.keys().map(String::as_str).collect();
            problems.push(format!(
                "unknown section [{section}]; valid sections: {}",
                valid.join(", ")
            ));
            continue;
        };
        let (Value::Table(table), Value::Table(ref_table)) = (value, ref_section) else {
            problems.push(format!("[{section}] must be a table of keys"));
            continue;
        };
        for (key, v) in table.iter_mut() {
            let path = format!("{section}.{key}");
            let want = ref_table.get(key.as_str()).cloned().or_else(|| {
                // Optional keys are absent from the default tree.
                spec(&path).map(|_| Value::Float(0.0))
            });
            let Some(want) = want else {
                let valid: Vec<String> = KEYS
                    .iter()
                    .filter(|s| s.key.starts_with(&format!("{section}.")))
                    .map(|s| s.key.to_string())
                    .collect();
                problems.push(format!(
                    "unknown key `{path}`; valid keys in [{section}]: {}",
                    valid.join(", ")
                ));
                continue;
            };
            if !same_kind(&want, v) {
                bad_paths.push(path.clone());
                problems.push(format!(
                    "`{path}` = {v} is {}, expected {}",
                    type_name(v),
                    spec(&path)
                        .map(|s| s.valid.describe())
                        .unwrap_or_else(|| type_name(&want).into())
                ));
                continue;
            }
            if let (Value::Float(_), Value::Integer(i)) = (&want, &*v) {
                *v = Value::Float(*i as f64);
            }
            if let Value::Array(items) = v {
                for item in items.iter_mut() {
                    if let Value::Integer(i) = item {
                        *item = Value::Float(*i as f64);
                    }
                }
            }
        }
    }
    bad_paths
}

/// Check one value against its spec.
fn check_range(key: &str, v: &Value, valid: Valid) -> Option<String> {
    let num = v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
    let bad = |what: String| Some(format!("`{key}` = {v} is invalid: expected {what}"));
    match valid {
        Valid::Positive => match num {
            Some(x) if x.is_finite() && x > 0.0 => None,
            _ => bad(valid.describe()),
        },
        Valid::NonNegative => match num {
            Some(x) if x.is_finite() && x >= 0.0 => None,
            _ => bad(valid.describe()),
        },
        Valid::Closed(a, b) => match num {
            Some(x) if x >= a && x <= b => None,
            _ => bad(valid.describe()),
        },
        Valid::Open(a, b) => match num {
            Some(x) if x > a && x < b => None,
            _ => bad(valid.describe()),
        },
        Valid::IntAtLeast(n) => match v.as_integer() {
            Some(i) if i >= n => None,
            _ => bad(valid.describe()),
        },
        Valid::Choice(choices) => match v.as_str() {
            Some(s) if choices.contains(&s) => None,
            _ => bad(valid.describe()),
        },
        Valid::Bool => v.as_bool().map_or_else(|| bad(valid.describe()), |_| None),
        Valid::NonNegativeArray => match v.as_array() {
            Some(a)
                if !a.is_empty()
                    && a.iter()
                        .all(|x| x.as_float().is_some_and(|f| f.is_finite() && f >= 0.0)) =>
            {
                None
            }
            _ => bad(valid.describe()),
        },
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
            "`surface.roughness_table_wear_um` = {:?} must be strictly ascending",
            s.roughness_table_wear_um
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
}

/// Build a case from TOML text (empty for the default) and `--set` overrides.
///
/// Returns every problem at once; the case is only returned when there is none.
pub fn load_case(toml_text: &str, overrides: &[String]) -> Result<Case, ConfigError> {
    let mut problems = Vec::new();
    let mut user: Table = match toml::from_str(toml_text) {
        Ok(t) => t,
        Err(e) => {
            return Err(ConfigError::one(format!(
                "case file is not valid TOML: {e}"
            )))
        }
    };
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
                    _ => problems.push(format!("--set {o}: [{}] is not a table", path[0])),
                }
            }
            Err(e) => problems.push(e),
        }
    }
    let bad_types = check_keys(&mut user, &mut problems);
    // Range checks on every known key that was given with the right type (defaults are
    // valid, which a test checks).
    for (section, value) in &user {
        if let Value::Table(t) = value {
            for (key, v) in t {
                let path = format!("{section}.{key}");
                if let (Some(s), false) = (spec(&path), bad_types.contains(&path)) {
                    if let Some(p) = check_range(&path, v, s.valid) {
                        problems.push(p);
                    }
                }
            }
        }
    }
    if !problems.is_empty() {
        return Err(ConfigError { problems });
    }
    let case: Case = Value::Table(user)
        .try_into()
        .map_err(|e: toml::de::Error| ConfigError::one(format!("case file: {e}")))?;
    check_relations(&case, &mut problems);
    if problems.is_empty() {
        Ok(case)
    } else {
        Err(ConfigError { problems })
    }
}

/// Validate every key of an already built case against the schema (used on defaults).
pub fn check_all_ranges(case: &Case) -> Vec<String> {
    let tree = match Value::try_from(case) {
        Ok(Value::Table(t)) => t,
        _ => return vec!["case does not serialise".into()],
    };
    let mut problems = Vec::new();
    for s in KEYS {
        let (section, key) = s.key.split_once('.').unwrap_or(("", s.key));
        if let Some(v) = tree.get(section).and_then(|t| t.get(key)) {
            if let Some(p) = check_range(s.key, v, s.valid) {
                problems.push(p);
            }
        }
    }
    check_relations(case, &mut problems);
    problems
}

/// The default case as commented TOML: every key with its unit, meaning and range.
pub fn commented_template(case: &Case) -> String {
    let tree = match Value::try_from(case) {
        Ok(Value::Table(t)) => t,
        _ => Table::new(),
    };
    let mut out = String::from(
        "# gearwear case file. Defaults: the paper's case (Coatings 2022, 12, 1250).\n\
         # Every key is optional; an omitted key takes the value shown.\n",
    );
    let mut current = "";
    for s in KEYS {
        let (section, key) = s.key.split_once('.').unwrap_or(("", s.key));
        if section != current {
            out.push_str(&format!("\n[{section}]\n"));
            current = section;
        }
        out.push_str(&format!(
            "# {} [{}] Valid: {}.\n",
            s.doc,
            s.unit,
            s.valid.describe()
        ));
        match tree.get(section).and_then(|t| t.get(key)) {
            Some(v) => out.push_str(&format!("{key} = {v}\n")),
            None => out.push_str(&format!("# {key} = (unset)\n")),
        }
    }
    out
}

/// `docs/CONFIG.md` body: a table of every key.
pub fn markdown_reference(case: &Case) -> String {
    let tree = match Value::try_from(case) {
        Ok(Value::Table(t)) => t,
        _ => Table::new(),
    };
    let mut out = String::from(
        "# Case file reference\n\n\
         Generated from `src/config/schema.rs` by `gearwear config --markdown`; \
         a test keeps this file equal to that output.\n\n\
         | key | unit | default | valid | meaning |\n|---|---|---|---|---|\n",
    );
    for s in KEYS {
        let (section, key) = s.key.split_once('.').unwrap_or(("", s.key));
        let default = tree
            .get(section)
            .and_then(|t| t.get(key))
            .map(|v| v.to_string())
            .unwrap_or_else(|| "(derived)".into());
        out.push_str(&format!(
            "| `{}` | {} | `{}` | {} | {} |\n",
            s.key,
            s.unit,
            default,
            s.valid.describe(),
            s.doc.replace('|', "\\|")
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_cover_every_key() {
        assert!(check_all_ranges(&Case::default()).is_empty());
        // Every spec key is a real field (template prints a value or the optional marker).
        let t = commented_template(&Case::default());
        for s in KEYS {
            let key = s.key.split_once('.').unwrap().1;
            assert!(t.contains(&format!("{key} =")), "{key} missing in template");
        }
    }

    #[test]
    fn template_parses_back_to_the_default() {
        let t = commented_template(&Case::default());
        assert_eq!(load_case(&t, &[]).unwrap(), Case::default());
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
        assert_eq!(
            c.friction.model,
            crate::config::case::FrictionModel::Constant
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
    fn unknown_key_names_the_valid_ones() {
        let e = load_case("[operating]\nspeed_hz = 3\n", &[]).unwrap_err();
        assert!(e.problems[0].contains("operating.speed_hz"));
        assert!(e.problems[0].contains("operating.input_speed_hz"));
        let e = load_case("[gears]\n", &[]).unwrap_err();
        assert!(e.problems[0].contains("unknown section [gears]"));
    }

    #[test]
    fn wrong_type_and_bad_choice() {
        let e = load_case("[operating]\ninput_speed_hz = \"fast\"\n", &[]).unwrap_err();
        assert!(e.problems[0].contains("is a string"), "{e}");
        let e = load_case("", &["friction.model=coulomb".into()]).unwrap_err();
        assert!(e.problems[0].contains("\"xu2007\""), "{e}");
    }

    #[test]
    fn xu_needs_viscosity_above_one_cp() {
        let e = load_case("", &["lubricant.viscosity_cp=0.8".into()]).unwrap_err();
        assert!(e.problems[0].contains("lubricant.viscosity_cp"), "{e}");
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
}
