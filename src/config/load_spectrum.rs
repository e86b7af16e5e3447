//! Reading `[load_spectrum]` (the duty cycle of a case, `config::operating`) from a case
//! file: bins written inline
//! (`bins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, ...]`) or in a CSV file
//! (`file = "spectrum.csv"`, header `torque_nm,input_speed_hz,share`). Alternatives, each
//! for every bin of a spectrum: `input_speed_rpm` for the speed (Hz = rpm / 60) and `hours`
//! for the share (time at the bin; the cycles of bin i are 3600 h_i f_i, so its share of
//! the cycles is h_i f_i / sum_j h_j f_j). The section is resolved here: the case keeps
//! the converted values (Hz, shares of the cycles).
//!
//! Every problem names the bin (1-based; with its file line for a CSV), the key and the
//! valid range, and nothing is computed from a case that has one.

use super::operating::{
    LoadSpectrumSection, SpectrumBin, SpeedUnit, TorqueShaft, MAX_BINS, SHARE_SUM_TOLERANCE,
};
use super::parse::{as_number, check_range, normalise};
use super::schema::{number, spec, Range, Valid};
use std::path::Path;
use toml::Value;

/// What a bin's weight was given as.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Weight {
    Share(f64),
    Hours(f64),
}

/// One bin as written, with where it came from (for messages).
#[derive(Debug, Clone)]
struct RawBin {
    origin: String,
    torque_nm: f64,
    speed_hz: f64,
    /// The speed's unit as written and its value in it (for messages).
    speed_unit: SpeedUnit,
    speed_value: f64,
    weight: Weight,
}

const TORQUE_KEY: &str = "operating.load_torque_nm";
const SPEED_KEY: &str = "operating.input_speed_hz";

fn range_of(key: &str) -> Range {
    match spec(key).map(|s| s.valid) {
        Some(Valid::Num(r)) => r,
        _ => Range::closed(0.0, f64::MAX),
    }
}

/// Problems of a resolved section against its case's ranges; `label(i)` names bin i.
fn problems_of(s: &LoadSpectrumSection, label: &dyn Fn(usize) -> String) -> Vec<String> {
    let mut p = Vec::new();
    if s.bins.is_empty() {
        p.push("`load_spectrum` has no bins: give `bins` or a `file` with at least one row".into());
        return p;
    }
    if s.bins.len() > MAX_BINS {
        p.push(format!(
            "`load_spectrum` has {} bins, more than {MAX_BINS}: merge neighbouring bins",
            s.bins.len()
        ));
    }
    let (tr, sr) = (range_of(TORQUE_KEY), range_of(SPEED_KEY));
    for (i, b) in s.bins.iter().enumerate() {
        for (key, given, scale_key, scale, r, model_key) in [
            (
                "torque_nm",
                b.torque_nm,
                "torque_scale",
                s.torque_scale,
                tr,
                TORQUE_KEY,
            ),
            (
                "input_speed_hz",
                b.input_speed_hz,
                "speed_scale",
                s.speed_scale,
                sr,
                SPEED_KEY,
            ),
        ] {
            let used = given * scale;
            if !given.is_finite() || given <= 0.0 {
                p.push(format!(
                    "{}: `{key}` = {} is invalid: expected a positive finite number in {} (the range of `{model_key}`)",
                    label(i),
                    number(given),
                    r.describe()
                ));
            } else if !r.contains(used) {
                let how = if scale == 1.0 {
                    format!("`{key}` = {}", number(given))
                } else {
                    format!(
                        "`{key}` x `load_spectrum.{scale_key}` = {} x {} = {}",
                        number(given),
                        number(scale),
                        number(used)
                    )
                };
                p.push(format!(
                    "{}: {how} is outside {}, the valid range of `{model_key}`",
                    label(i),
                    r.describe()
                ));
            }
        }
        if !(b.share.is_finite() && (0.0..=1.0).contains(&b.share)) {
            p.push(format!(
                "{}: `share` = {} is invalid: expected a number in [0, 1] (a share of the load cycles)",
                label(i),
                number(b.share)
            ));
        }
    }
    let sum: f64 = s.bins.iter().map(|b| b.share).sum();
    if p.is_empty() && (sum - 1.0).abs() > SHARE_SUM_TOLERANCE {
        p.push(format!(
            "`load_spectrum` shares sum to {}, not 1 (within {SHARE_SUM_TOLERANCE:e}): bin 1 has {}; make them sum to 1, or give `hours` at each bin instead (any total)",
            (sum * 1e9).round() / 1e9,
            number(s.bins[0].share)
        ));
    }
    if let Some(m) = s.monitoring_bin {
        if m < 1 || m as usize > s.bins.len() {
            p.push(format!(
                "`load_spectrum.monitoring_bin` = {m} is invalid: expected a bin number in [1, {}]",
                s.bins.len()
            ));
        }
    }
    p
}

/// Problems of a case's spectrum (already resolved), bins named by number.
#[cfg(test)]
pub(crate) fn spectrum_problems(spectrum: Option<&LoadSpectrumSection>) -> Vec<String> {
    match spectrum {
        None => Vec::new(),
        Some(s) => problems_of(s, &|i| format!("load_spectrum bin {}", i + 1)),
    }
}

/// The keys of the section as written, besides the scalar schema keys.
const TABLE_KEYS: [&str; 2] = ["bins", "file"];
const SCALAR_KEYS: [&str; 5] = [
    "torque_shaft",
    "torque_scale",
    "speed_scale",
    "monitoring_bin",
    "life_wear_limit_um",
];

/// A bin from its (key, value) cells; `origin` names it in messages.
fn raw_bin(
    origin: String,
    cells: &[(String, Option<f64>)],
    problems: &mut Vec<String>,
) -> Option<RawBin> {
    let get = |k: &str| cells.iter().find(|(n, _)| n == k).map(|(_, v)| *v);
    let mut ok = true;
    for (name, v) in cells {
        let known = [
            "torque_nm",
            "input_speed_hz",
            "input_speed_rpm",
            "share",
            "hours",
        ];
        if !known.contains(&name.as_str()) {
            problems.push(format!(
                "{origin}: unknown key `{}`; a bin has `torque_nm`, `input_speed_hz` or `input_speed_rpm`, and `share` or `hours`",
                crate::format::clip(name, crate::format::SHOWN_CHARS)
            ));
            ok = false;
        } else if v.is_none() {
            problems.push(format!("{origin}: `{name}` is not a number"));
            ok = false;
        }
    }
    let torque = match get("torque_nm") {
        Some(Some(t)) => Some(t),
        None => {
            problems.push(format!("{origin}: missing `torque_nm`"));
            None
        }
        _ => None,
    };
    let speed = bin_speed(&origin, &get, problems);
    let weight = match (get("share"), get("hours")) {
        (Some(Some(x)), None) => Some(Weight::Share(x)),
        (None, Some(Some(x))) => Some(Weight::Hours(x)),
        (Some(_), Some(_)) => {
            problems.push(format!("{origin}: give `share` or `hours`, not both"));
            None
        }
        (None, None) => {
            problems.push(format!("{origin}: missing `share` (or `hours`)"));
            None
        }
        _ => None,
    };
    let (torque, (speed_unit, speed_value), weight) = (torque?, speed?, weight?);
    if !ok {
        return None;
    }
    let speed_hz = speed_unit.to_hz(speed_value);
    let origin = if speed_unit == SpeedUnit::Rpm {
        format!(
            "{origin} ({} rpm = {} Hz)",
            number(speed_value),
            number(speed_hz)
        )
    } else {
        origin
    };
    Some(RawBin {
        origin,
        torque_nm: torque,
        speed_hz,
        speed_unit,
        speed_value,
        weight,
    })
}

/// A bin's speed: its unit and value as written (`get(key)`: absent, not a number, or
/// the number); the problem pushed when it has none or both.
fn bin_speed(
    origin: &str,
    get: &dyn Fn(&str) -> Option<Option<f64>>,
    problems: &mut Vec<String>,
) -> Option<(SpeedUnit, f64)> {
    let given = |u: SpeedUnit| get(u.input_speed_key()).is_some();
    match SpeedUnit::given(given(SpeedUnit::Hz), given(SpeedUnit::Rpm), "") {
        Err(both) => {
            problems.push(format!("{origin}: {both}"));
            None
        }
        Ok(None) => {
            problems.push(format!("{origin}: missing {}", SpeedUnit::either_key("")));
            None
        }
        Ok(Some(u)) => get(u.input_speed_key()).flatten().map(|x| (u, x)),
    }
}

/// Bins written inline: an array of tables.
fn inline_bins(v: &Value, problems: &mut Vec<String>) -> Vec<RawBin> {
    let Some(items) = v.as_array() else {
        problems.push(
            "`load_spectrum.bins` must be an array of tables, e.g. bins = [{torque_nm = 60, input_speed_hz = 30, share = 1}]".into(),
        );
        return Vec::new();
    };
    items
        .iter()
        .enumerate()
        .filter_map(|(i, item)| {
            let origin = format!("load_spectrum bin {} (`load_spectrum.bins`)", i + 1);
            let Some(t) = item.as_table() else {
                problems.push(format!(
                    "{origin}: must be a table of torque_nm, input_speed_hz and share"
                ));
                return None;
            };
            let cells: Vec<(String, Option<f64>)> =
                t.iter().map(|(k, v)| (k.clone(), as_number(v))).collect();
            raw_bin(origin, &cells, problems)
        })
        .collect()
}

/// Bins from a CSV file (header: the bin keys).
fn file_bins(path: &Path, shown: &str, problems: &mut Vec<String>) -> Vec<RawBin> {
    // Only a regular file of bounded size (a FIFO or device would block or stream).
    let text = match crate::io::input::read_input_text(
        path,
        "load spectrum file",
        crate::io::input::MAX_LOAD_SPECTRUM_BYTES,
    ) {
        Ok(t) => t,
        Err(e) => {
            problems.push(format!(
                "`load_spectrum.file` = \"{shown}\": cannot read: {}",
                e.reason
            ));
            return Vec::new();
        }
    };
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header: Vec<String> = match rdr.headers() {
        Ok(h) => h.iter().map(str::to_owned).collect(),
        Err(e) => {
            problems.push(format!(
                "`load_spectrum.file` = \"{shown}\": no CSV header: {e}"
            ));
            return Vec::new();
        }
    };
    if let Some(name) = crate::io::table::repeated_column(header.iter().map(String::as_str)) {
        problems.push(format!(
            "`load_spectrum.file` = \"{shown}\": the header names the column `{}` twice: keep one",
            crate::format::clip(name, crate::format::SHOWN_CHARS)
        ));
        return Vec::new();
    }
    let mut bins = Vec::new();
    for (i, row) in rdr.records().enumerate() {
        let line = i + 2;
        let origin = format!(
            "load_spectrum bin {} (`load_spectrum.file` {shown}, line {line})",
            i + 1
        );
        match row {
            Ok(r) => {
                let cells: Vec<(String, Option<f64>)> = header
                    .iter()
                    .zip(r.iter())
                    .map(|(k, v)| (k.clone(), v.parse::<f64>().ok()))
                    .collect();
                bins.extend(raw_bin(origin, &cells, problems));
            }
            Err(e) => problems.push(format!("{origin}: {e}")),
        }
        if problems.len() > 50 {
            problems.push("(further rows not checked)".into());
            break;
        }
    }
    if bins.is_empty() && problems.is_empty() {
        problems.push(format!(
            "`load_spectrum.file` = \"{shown}\" has no bins (rows)"
        ));
    }
    bins
}

/// Convert the raw bins: one unit and one weight for all; hours to shares of cycles.
fn convert(raw: &[RawBin], problems: &mut Vec<String>) -> Option<Vec<SpectrumBin>> {
    let hours = raw
        .iter()
        .filter(|b| matches!(b.weight, Weight::Hours(_)))
        .count();
    if hours != 0 && hours != raw.len() {
        problems.push(
            "`load_spectrum`: give `share` at every bin or `hours` at every bin, not a mix".into(),
        );
        return None;
    }
    if raw.windows(2).any(|w| w[0].speed_unit != w[1].speed_unit) {
        problems.push(
            "`load_spectrum`: give `input_speed_hz` at every bin or `input_speed_rpm` at every bin, not a mix".into(),
        );
        return None;
    }
    for b in raw {
        if b.speed_unit == SpeedUnit::Rpm && !(b.speed_value.is_finite() && b.speed_value > 0.0) {
            problems.push(format!(
                "{}: `input_speed_rpm` = {} is invalid: expected a positive finite number (rpm = 60 x Hz, Hz in {})",
                b.origin,
                number(b.speed_value),
                range_of(SPEED_KEY).describe()
            ));
        }
        if let Weight::Hours(h) = b.weight {
            if !(h.is_finite() && h >= 0.0) {
                problems.push(format!(
                    "{}: `hours` = {} is invalid: expected a finite number >= 0 (time at the bin)",
                    b.origin,
                    number(h)
                ));
            }
        }
    }
    if !problems.is_empty() {
        return None;
    }
    let shares: Vec<f64> = if hours > 0 {
        // Cycles of bin i: 3600 h_i f_i; the common 3600 cancels in the shares.
        let cycles: Vec<f64> = raw
            .iter()
            .map(|b| match b.weight {
                Weight::Hours(h) => h * b.speed_hz,
                Weight::Share(s) => s,
            })
            .collect();
        let total: f64 = cycles.iter().sum();
        if !(total > 0.0 && total.is_finite()) {
            problems.push(format!(
                "`load_spectrum`: the hours total {} (cycles {}): at least one bin needs time > 0 at a speed > 0",
                number(raw.iter().map(|b| if let Weight::Hours(h) = b.weight { h } else { 0.0 }).sum()),
                number(total * 3600.0)
            ));
            return None;
        }
        cycles.iter().map(|c| c / total).collect()
    } else {
        raw.iter()
            .map(|b| match b.weight {
                Weight::Share(s) => s,
                Weight::Hours(h) => h,
            })
            .collect()
    };
    Some(
        raw.iter()
            .zip(shares)
            .map(|(b, share)| SpectrumBin {
                torque_nm: b.torque_nm,
                input_speed_hz: b.speed_hz,
                share,
            })
            .collect(),
    )
}

/// Parse and check the `[load_spectrum]` table of a case file (after `--set` overrides),
/// a relative `file` read from `dir`. `Ok(None)`: no section (or an empty one). Every
/// problem is pushed to `problems`.
pub(super) fn parse_section(
    v: Value,
    dir: &Path,
    problems: &mut Vec<String>,
) -> Option<LoadSpectrumSection> {
    let Value::Table(mut t) = v else {
        problems.push("[load_spectrum] must be a table (bins = [...] or file = \"...\")".into());
        return None;
    };
    if t.is_empty() {
        return None;
    }
    let before = problems.len();
    let bins_v = t.remove("bins");
    let file_v = t.remove("file");
    let mut section = LoadSpectrumSection::of_bins(Vec::new());
    for (key, mut value) in t {
        let path = format!("load_spectrum.{key}");
        let Some(s) = spec(&path).filter(|_| SCALAR_KEYS.contains(&key.as_str())) else {
            problems.push(format!(
                "unknown key `{}`; valid keys in [load_spectrum]: {}, {}",
                crate::format::clip(&path, crate::format::SHOWN_CHARS),
                TABLE_KEYS.join(", "),
                SCALAR_KEYS.join(", ")
            ));
            continue;
        };
        if let Err(e) = normalise(&path, &mut value, s.valid) {
            problems.push(e);
            continue;
        }
        if let Some(e) = check_range(&path, &value, s.valid) {
            problems.push(e);
            continue;
        }
        match key.as_str() {
            "torque_scale" => section.torque_scale = as_number(&value).unwrap_or(1.0),
            "speed_scale" => section.speed_scale = as_number(&value).unwrap_or(1.0),
            "monitoring_bin" => section.monitoring_bin = value.as_integer(),
            "life_wear_limit_um" => section.life_wear_limit_um = as_number(&value).unwrap_or(10.0),
            _ => {
                section.torque_shaft = Some(match value.as_str() {
                    Some("gear") => TorqueShaft::Gear,
                    _ => TorqueShaft::Pinion,
                })
            }
        }
    }
    let raw = match (bins_v, file_v) {
        (Some(_), Some(_)) => {
            problems.push("[load_spectrum]: give `bins` or `file`, not both".into());
            return None;
        }
        (None, None) => {
            problems.push("[load_spectrum] has no bins: give `bins = [{torque_nm = ..., input_speed_hz = ..., share = ...}, ...]` or `file = \"spectrum.csv\"`".into());
            return None;
        }
        (Some(b), None) => inline_bins(&b, problems),
        (None, Some(f)) => match f.as_str() {
            Some(name) => {
                let shown = crate::format::clip(name, crate::format::SHOWN_CHARS);
                file_bins(&dir.join(name), &shown, problems)
            }
            None => {
                problems.push("`load_spectrum.file` must be a string (a CSV path)".into());
                return None;
            }
        },
    };
    if problems.len() > before {
        return None;
    }
    section.bins = convert(&raw, problems)?;
    let origins: Vec<String> = raw.iter().map(|b| b.origin.clone()).collect();
    let found = problems_of(&section, &|i| origins[i].clone());
    if found.is_empty() {
        Some(section)
    } else {
        problems.extend(found);
        None
    }
}
