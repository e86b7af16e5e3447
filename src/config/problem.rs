//! One problem of a case taken apart into fields: the key it concerns, the value given,
//! what would be valid, and the whole message.
//!
//! The checks (`load_case`, the gear pair, the model) report problems as one message each,
//! written to a fixed pattern: the key in backticks, "`section.key` = VALUE is invalid:
//! expected RANGE" or "`section.key` = VALUE is a string, expected RANGE", "unknown key
//! `section.key`; valid keys in \[section\]: ...". [`Problem::from_message`] reads those
//! fields back, for callers that want them one by one (the Python binding's
//! `CaseError.problems`); a test below keeps it in step with the messages.

use super::schema::spec;

/// The fields of one problem; `None` where the message does not have one (e.g. a
/// geometry problem that involves several keys).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// Dotted key, `section.key` (or the unknown section's name).
    pub key: Option<String>,
    /// The value given, as TOML text (`45`, `"fast"`, `[0.1, 0.5]`).
    pub value: Option<String>,
    /// What would be valid: a range, a list of choices or of valid keys, a condition.
    pub valid: Option<String>,
    /// The whole message, as the command line prints it.
    pub message: String,
}

/// The texts between pairs of backticks.
fn backticked(message: &str) -> Vec<&str> {
    message.split('`').skip(1).step_by(2).collect()
}

/// `section.key` with two non-empty identifier parts, the first starting with a letter.
fn looks_like_key(t: &str) -> bool {
    let ident = |s: &str| {
        s.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
            && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    };
    matches!(t.split_once('.'), Some((a, b)) if ident(a) && ident(b))
}

/// The text after the first `marker`.
fn after<'a>(message: &'a str, marker: &str) -> Option<&'a str> {
    message.find(marker).map(|i| &message[i + marker.len()..])
}

impl Problem {
    /// Read the fields of a problem message (see the module docs).
    pub fn from_message(message: &str) -> Self {
        let ticked = backticked(message);
        let key = ticked
            .iter()
            .find(|t| spec(t).is_some())
            .or_else(|| ticked.iter().find(|t| looks_like_key(t)))
            .map(|t| t.to_string())
            .or_else(|| {
                after(message, "unknown section [")
                    .and_then(|r| r.split_once(']'))
                    .map(|(s, _)| s.to_owned())
            });
        let value = key.as_deref().and_then(|k| {
            let rest = after(message, &format!("`{k}` = "))?;
            // A quoted value ends at its closing quote; others at " is ".
            let end = if let Some(quoted) = rest.strip_prefix('"') {
                quoted.find('"').map(|i| i + 2)
            } else {
                rest.find(" is ")
            }?;
            Some(rest[..end].trim().to_owned())
        });
        let valid = after(message, "expected ")
            .or_else(|| after(message, "; valid keys in ").and_then(|r| after(r, "]: ")))
            .or_else(|| after(message, "; valid sections: "))
            .or_else(|| {
                after(message, " is invalid").and_then(|r| r.split_once(": ").map(|(_, v)| v))
            })
            .or_else(|| after(message, ": they "))
            .map(|v| v.trim().to_owned());
        Self {
            key,
            value,
            valid,
            message: message.to_owned(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load_case;

    /// The single problem `load_case` reports for a case.
    fn one(toml: &str, sets: &[&str]) -> Problem {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        let e = load_case(toml, &sets).unwrap_err();
        assert_eq!(e.problems.len(), 1, "{e}");
        Problem::from_message(&e.problems[0].to_string())
    }

    #[test]
    fn out_of_range_gives_key_value_and_range() {
        let p = one("[gear]\nmodule_mm = -2\n", &[]);
        assert_eq!(p.key.as_deref(), Some("gear.module_mm"));
        assert_eq!(p.value.as_deref(), Some("-2"));
        // The range as the schema states it (`valid` is what the message carried).
        let module = crate::config::schema::spec("gear.module_mm").unwrap();
        assert_eq!(p.valid, Some(module.valid.describe()));
        let p = one("", &["gear.pressure_angle_deg=40"]);
        assert_eq!(p.valid.as_deref(), Some("a number in [10, 35]"));
    }

    #[test]
    fn wrong_type_and_bad_choice() {
        let p = one("[operating]\ninput_speed_hz = \"fast\"\n", &[]);
        assert_eq!(p.key.as_deref(), Some("operating.input_speed_hz"));
        assert_eq!(p.value.as_deref(), Some("\"fast\""));
        let speed = crate::config::schema::spec("operating.input_speed_hz").unwrap();
        assert_eq!(p.valid, Some(speed.valid.describe()));
        let p = one("", &["friction.model=coulomb"]);
        assert_eq!(p.key.as_deref(), Some("friction.model"));
        assert_eq!(p.value.as_deref(), Some("\"coulomb\""));
        assert!(p.valid.unwrap().contains("\"xu2007\""));
    }

    #[test]
    fn unknown_key_and_section_list_the_valid_ones() {
        let p = one("[operating]\nspeed_hz = 3\n", &[]);
        assert_eq!(p.key.as_deref(), Some("operating.speed_hz"));
        assert!(p.valid.unwrap().contains("operating.input_speed_hz"));
        let p = one("[gears]\n", &[]);
        assert_eq!(p.key.as_deref(), Some("gears"));
        assert!(p.valid.unwrap().contains("gear"));
    }

    #[test]
    fn relations_name_the_key() {
        let p = one("", &["lubricant.viscosity_cp=0.8"]);
        assert_eq!(p.key.as_deref(), Some("lubricant.viscosity_cp"));
        assert_eq!(p.value.as_deref(), Some("0.8"));
        assert!(p.valid.unwrap().contains("> 1"));
        let p = one("", &["surface.roughness_table_rms_um=[0.2, 0.1]"]);
        assert_eq!(p.key.as_deref(), Some("surface.roughness_table_wear_um"));
        assert!(p.valid.unwrap().contains("same length"));
    }

    #[test]
    fn a_message_without_fields_keeps_its_text() {
        let p = Problem::from_message("contact ratio 0.9 is below 1");
        assert_eq!((p.key, p.value, p.valid), (None, None, None));
        assert_eq!(p.message, "contact ratio 0.9 is below 1");
    }
}
