//! The parser's helpers for values of a case file: a TOML value brought to the type its
//! key wants, checked against its range, echoed in messages; an override's value read;
//! the sections and keys the schema knows, named in messages. Shared by the reader of a
//! case (`config::load`) and of its load spectrum (`config::load_spectrum`).
//!
//! Values echoed in messages are cut to [`SHOWN_CHARS`] characters with an ellipsis.

use super::schema::{Range, Valid, KEYS};
use crate::format::{clip, SHOWN_CHARS};
use toml::{Table, Value};

/// A TOML value as echoed in messages: numbers short (`1e-9`, not 0.000000001).
pub(super) fn show(v: &Value) -> String {
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

pub(super) fn type_name(v: &Value) -> &'static str {
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
pub(super) fn as_number(v: &Value) -> Option<f64> {
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
            "`{key}` = {} is invalid{}: expected {}{}",
            show(v),
            first_bad_element(key, v, valid),
            valid.describe(),
            rpm_hint(key, v, valid)
        )
    })
}

/// For a speed in Hz out of range whose value read as rpm (v / 60 Hz) would be in range,
/// and that has an rpm twin key: the likely mix-up of units, named. Empty otherwise.
fn rpm_hint(key: &str, v: &Value, valid: Valid) -> String {
    let (Valid::Num(r), Some(x)) = (valid, as_number(v)) else {
        return String::new();
    };
    let Some(stem) = key.strip_suffix("_hz") else {
        return String::new();
    };
    let twin = format!("{stem}_rpm");
    if !r.contains(x / 60.0) || !KEYS.iter().any(|k| k.key == twin) {
        return String::new();
    }
    format!(
        "; if the speed was meant in rpm ({} rpm = {} Hz), give it as `{twin}`",
        show(v),
        crate::format::shown(x / 60.0)
    )
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
pub(super) fn sections() -> Vec<&'static str> {
    let mut s: Vec<&str> = KEYS
        .iter()
        .map(|k| k.key.split('.').next().unwrap_or(""))
        .collect();
    s.dedup();
    s
}

/// "unknown key `section.key`; valid keys in [section]: ...".
pub(super) fn unknown_key(section: &str, path: &str) -> String {
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
