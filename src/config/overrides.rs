//! The command line's overrides (`--set section.key=value`, `section.N.key=value` for the
//! N-th table of an array-of-tables section) merged into the case file's tree before it is
//! checked.

use super::parse::override_value;
use super::schema::TABLE_ARRAYS;
use crate::format::{clip, SHOWN_CHARS};
use crate::remedy::{Arg, Words};
use toml::{Table, Value};

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
    if !(2..=3).contains(&path.len()) || path.iter().any(String::is_empty) {
        return Err(problem(
            shown,
            "the key must be section.key (section.N.key for the N-th [[stage]] or [[fault]] table, section.table.key for a sub-table such as planetary.lumped)",
        ));
    }
    Ok((path, override_value(raw)))
}

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

/// Set `section.sub.key` in the sub-table `[section.sub]` (`planetary.lumped.mass_sun_kg`),
/// making either table when absent; the schema checks the key afterwards.
fn set_sub_table_value(
    user: &mut Table,
    section: &str,
    sub: &str,
    key: &str,
    value: Value,
) -> Result<(), String> {
    let not_table = |what: String| format!("{what} is not a table");
    let outer = user
        .entry(section.to_owned())
        .or_insert_with(|| Value::Table(Table::new()));
    let Value::Table(outer) = outer else {
        return Err(not_table(format!("[{}]", clip(section, SHOWN_CHARS))));
    };
    let inner = outer
        .entry(sub.to_owned())
        .or_insert_with(|| Value::Table(Table::new()));
    let Value::Table(inner) = inner else {
        return Err(not_table(format!(
            "`{}.{}`",
            clip(section, SHOWN_CHARS),
            clip(sub, SHOWN_CHARS)
        )));
    };
    inner.insert(key.to_owned(), value);
    Ok(())
}

/// Set `section.N.key` (N from 1) in the N-th table of an array-of-tables section
/// (`stage.2.teeth_pinion=23`): the table must exist, since its other keys come from the
/// case file.
fn set_numbered_value(
    user: &mut Table,
    section: &str,
    index: &str,
    key: &str,
    value: Value,
) -> Result<(), String> {
    let shown = clip(section, SHOWN_CHARS);
    if !TABLE_ARRAYS.contains(&section) {
        return Err(format!(
            "[{shown}] is not a numbered section: only {} tables take section.N.key",
            TABLE_ARRAYS
                .iter()
                .map(|t| format!("[[{t}]]"))
                .collect::<Vec<_>>()
                .join(" and ")
        ));
    }
    let count = match user.get(section) {
        Some(Value::Array(items)) => items.len(),
        Some(Value::Table(_)) => 1,
        _ => 0,
    };
    let n = index
        .parse::<usize>()
        .ok()
        .filter(|n| (1..=count).contains(n));
    let Some(n) = n else {
        return Err(format!(
            "`{shown}.{}.{}` names [[{shown}]] table {} but the case has {count} (valid: 1 to {count}; add the table in the case file)",
            clip(index, 12),
            clip(key, SHOWN_CHARS),
            clip(index, 12)
        ));
    };
    match user.get_mut(section) {
        Some(Value::Array(items)) => match &mut items[n - 1] {
            Value::Table(t) => {
                t.insert(key.to_owned(), value);
                Ok(())
            }
            _ => Err(format!("[[{shown}]] table {n} is not a table")),
        },
        Some(Value::Table(t)) => {
            t.insert(key.to_owned(), value);
            Ok(())
        }
        _ => Err(format!("[[{shown}]] is not an array of tables")),
    }
}

/// Set the key of `path` (`[section, key]`, `[section, N, key]` of the N-th table of a
/// numbered section, `[section, table, key]` of a sub-table) in the tree.
pub(super) fn set_path(user: &mut Table, path: &[String], value: Value) -> Result<(), String> {
    match path {
        [section, index, key] if index.bytes().all(|b| b.is_ascii_digit()) => {
            set_numbered_value(user, section, index, key, value)
        }
        [section, sub, key] => set_sub_table_value(user, section, sub, key, value),
        [section, key] => set_value(user, section, key, value),
        _ => Err(format!(
            "the key `{}` must be section.key",
            clip(&path.join("."), SHOWN_CHARS)
        )),
    }
}

/// Merge the overrides (`section.key=value` texts) into the user's tree.
pub(super) fn apply_overrides(user: &mut Table, overrides: &[String], problems: &mut Vec<Words>) {
    for o in overrides {
        match parse_override(o) {
            Ok((path, value)) => {
                if let Err(e) = set_path(user, &path, value) {
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

/// Set `section.key` in the tree (the only table of an array-of-tables section); the
/// problem when the section is not a table.
pub(super) fn set_value(
    user: &mut Table,
    section: &str,
    key: &str,
    value: Value,
) -> Result<(), String> {
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
