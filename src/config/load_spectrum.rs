//! `[load_spectrum]`: the duty cycle of a case as a table of operating bins (issue 20).
//!
//! Each bin is an operating point (a load torque on the named shaft and an input speed)
//! with its share of the load cycles (pinion revolutions). Written inline
//! (`bins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, ...]`) or in a CSV file
//! (`file = "spectrum.csv"`, header `torque_nm,input_speed_hz,share`). Alternatives, each
//! for every bin of a spectrum: `input_speed_rpm` for the speed (Hz = rpm / 60) and `hours`
//! for the share (time at the bin; the cycles of bin i are 3600 h_i f_i, so its share of
//! the cycles is h_i f_i / sum_j h_j f_j). The case keeps the converted values (Hz, shares
//! of the cycles), so a resolved case states what was used.
//!
//! Without the section the case's single operating point (`[operating]`) applies. With it,
//! the studies that accumulate wear (wear, run, calibrate, predict, sweeps of wear) use the
//! spectrum and ignore `operating.load_torque_nm` and `operating.input_speed_hz`; the
//! other operating keys (speed boundary, slip) hold for every bin.
//!
//! Every problem names the bin (1-based; with its file line for a CSV), the key and the
//! valid range, and nothing is computed from a case that has one.

use super::case::{Case, TorqueShaft};
use super::schema::{number, spec, Range, Valid};
use serde::{Deserialize, Serialize};
use std::path::Path;
use toml::Value;

/// One operating bin, as the model uses it: SI-style units of its names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpectrumBin {
    /// Load torque on the spectrum's shaft, N m (before `torque_scale`).
    pub torque_nm: f64,
    /// Input (pinion) speed, Hz (before `speed_scale`).
    pub input_speed_hz: f64,
    /// Share of the load cycles (pinion revolutions), in [0, 1]; the shares sum to 1.
    pub share: f64,
}

/// The `[load_spectrum]` section, resolved (file read, rpm and hours converted).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpectrumSection {
    pub bins: Vec<SpectrumBin>,
    /// Shaft the bins' torques are on; absent: `operating.load_torque_shaft`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub torque_shaft: Option<TorqueShaft>,
    /// Factor on every bin's torque (a sweep axis: "all torques x 1.2").
    #[serde(default = "one")]
    pub torque_scale: f64,
    /// Factor on every bin's speed.
    #[serde(default = "one")]
    pub speed_scale: f64,
    /// Bin (1-based) at which vibration is observed for calibration; absent: the bin with
    /// the largest share (the first of equals).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub monitoring_bin: Option<i64>,
    /// Maximum pinion wear depth that ends the flanks' life in the `run` report's life
    /// table (under the spectrum and at each bin alone), um.
    #[serde(default = "default_life_limit")]
    pub life_wear_limit_um: f64,
}

fn one() -> f64 {
    1.0
}

/// 10 um: a fifth of a 2 mm module's 0.05 m wear allowance, the limit of
/// docs/PROGNOSTICS.md's worked example.
fn default_life_limit() -> f64 {
    10.0
}

/// Largest number of bins: each is a dynamic evaluation per wear update (the run budget
/// checks the cost); 10 000 is far beyond any published load spectrum (ISO 6336-6 examples
/// and wind-turbine LDDs use tens to a few hundred bins).
pub const MAX_BINS: usize = 10_000;

/// How far the shares may be from summing to 1: six significant digits, the precision a
/// spectrum written by hand in decimals carries (0.333 + 0.333 + 0.334).
pub const SHARE_SUM_TOLERANCE: f64 = 1e-6;

impl LoadSpectrumSection {
    /// A spectrum of the given bins with no scale, on the operating shaft.
    pub fn of_bins(bins: Vec<SpectrumBin>) -> Self {
        Self {
            bins,
            torque_shaft: None,
            torque_scale: 1.0,
            speed_scale: 1.0,
            monitoring_bin: None,
            life_wear_limit_um: default_life_limit(),
        }
    }

    /// Torque of bin `i` as applied (scale included), N m.
    pub fn torque_nm(&self, i: usize) -> f64 {
        self.bins[i].torque_nm * self.torque_scale
    }

    /// Input speed of bin `i` as applied (scale included), Hz.
    pub fn input_speed_hz(&self, i: usize) -> f64 {
        self.bins[i].input_speed_hz * self.speed_scale
    }

    /// Shaft of the torques, given the case's operating section.
    pub fn shaft(&self, operating: TorqueShaft) -> TorqueShaft {
        self.torque_shaft.unwrap_or(operating)
    }

    /// Index (0-based) of the bin vibration is observed at.
    pub fn monitoring_index(&self) -> usize {
        match self.monitoring_bin {
            Some(b) if b >= 1 && (b as usize) <= self.bins.len() => b as usize - 1,
            _ => self.bins.iter().enumerate().fold(0, |best, (i, b)| {
                if b.share > self.bins[best].share {
                    i
                } else {
                    best
                }
            }),
        }
    }

    /// Mean time per pinion cycle, s: sum_i share_i / f_i (cycles of bin i take 1 / f_i
    /// each). Life in hours = cycles x this / 3600.
    pub fn seconds_per_cycle(&self) -> f64 {
        (0..self.bins.len())
            .map(|i| self.bins[i].share / self.input_speed_hz(i))
            .sum()
    }
}

impl Case {
    /// The case at bin `i` of its spectrum: the operating point set to the bin's torque
    /// (on the spectrum's shaft) and speed, without the spectrum. Everything else is the
    /// case's, so a bin equal to the operating point gives the case itself.
    pub fn at_bin(&self, i: usize) -> Case {
        let mut c = self.clone();
        if let Some(s) = self.load_spectrum.as_ref() {
            c.operating.load_torque_nm = s.torque_nm(i);
            c.operating.input_speed_hz = s.input_speed_hz(i);
            c.operating.load_torque_shaft = s.shaft(self.operating.load_torque_shaft);
        }
        c.load_spectrum = None;
        c
    }

    /// The case of every bin, or None without a spectrum.
    pub fn bin_cases(&self) -> Option<Vec<Case>> {
        let s = self.load_spectrum.as_ref()?;
        Some((0..s.bins.len()).map(|i| self.at_bin(i)).collect())
    }
}

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
    /// The speed key as written and its value (for messages).
    speed_key: &'static str,
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
pub fn spectrum_problems(case: &Case) -> Vec<String> {
    match &case.load_spectrum {
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

fn as_number(v: &Value) -> Option<f64> {
    v.as_float().or_else(|| v.as_integer().map(|i| i as f64))
}

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
    let one_of =
        |a: &'static str, b: &'static str, problems: &mut Vec<String>| match (get(a), get(b)) {
            (Some(Some(x)), None) => Some((a, x)),
            (None, Some(Some(x))) => Some((b, x)),
            (Some(_), Some(_)) => {
                problems.push(format!("{origin}: give `{a}` or `{b}`, not both"));
                None
            }
            (None, None) => {
                problems.push(format!("{origin}: missing `{a}` (or `{b}`)"));
                None
            }
            _ => None,
        };
    let torque = match get("torque_nm") {
        Some(Some(t)) => Some(t),
        None => {
            problems.push(format!("{origin}: missing `torque_nm`"));
            None
        }
        _ => None,
    };
    let speed = one_of("input_speed_hz", "input_speed_rpm", problems);
    let weight = one_of("share", "hours", problems);
    let (torque, (speed_key, speed_value), (wkey, w)) = (torque?, speed?, weight?);
    if !ok {
        return None;
    }
    let origin = if speed_key == "input_speed_rpm" {
        format!(
            "{origin} ({} rpm = {} Hz)",
            number(speed_value),
            number(speed_value / 60.0)
        )
    } else {
        origin
    };
    Some(RawBin {
        origin,
        torque_nm: torque,
        // 1 Hz = 60 rpm.
        speed_hz: if speed_key == "input_speed_rpm" {
            speed_value / 60.0
        } else {
            speed_value
        },
        speed_key,
        speed_value,
        weight: if wkey == "hours" {
            Weight::Hours(w)
        } else {
            Weight::Share(w)
        },
    })
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
    let speed_keys: Vec<&str> = raw.iter().map(|b| b.speed_key).collect();
    if speed_keys.windows(2).any(|w| w[0] != w[1]) {
        problems.push(
            "`load_spectrum`: give `input_speed_hz` at every bin or `input_speed_rpm` at every bin, not a mix".into(),
        );
        return None;
    }
    for b in raw {
        if b.speed_key == "input_speed_rpm" && !(b.speed_value.is_finite() && b.speed_value > 0.0) {
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
        if let Err(e) = super::load::normalise(&path, &mut value, s.valid) {
            problems.push(e);
            continue;
        }
        if let Some(e) = super::load::check_range(&path, &value, s.valid) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load::{check_all_ranges, load_case, load_case_in};

    fn err(text: &str) -> String {
        load_case(text, &[]).unwrap_err().to_string()
    }

    const TWO: &str = "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 80, input_speed_hz = 45, share = 0.3}]\n";

    #[test]
    fn inline_bins_load_and_a_case_without_the_section_is_unchanged() {
        let c = load_case(TWO, &[]).unwrap();
        let s = c.load_spectrum.as_ref().unwrap();
        assert_eq!(s.bins.len(), 2);
        assert_eq!(
            s.bins[1],
            SpectrumBin {
                torque_nm: 80.0,
                input_speed_hz: 45.0,
                share: 0.3
            }
        );
        // The largest share is observed by default.
        assert_eq!(s.monitoring_index(), 0);
        // No section: the default case, and its serialised form has no trace of it.
        assert_eq!(load_case("", &[]).unwrap(), Case::default());
        assert!(!toml::to_string(&Case::default())
            .unwrap()
            .contains("load_spectrum"));
        // An empty section (as the commented template prints it) is no spectrum.
        assert_eq!(
            load_case("[load_spectrum]\n", &[]).unwrap(),
            Case::default()
        );
        // A resolved case reloads to itself.
        let text = toml::to_string(&c).unwrap();
        assert_eq!(load_case(&text, &[]).unwrap(), c);
        assert!(check_all_ranges(&c).is_empty());
    }

    #[test]
    fn bin_cases_carry_the_operating_point() {
        let c = load_case(
            &format!("{TWO}torque_shaft = \"gear\"\ntorque_scale = 1.5\n"),
            &["load_spectrum.speed_scale=2".into()],
        )
        .unwrap();
        let b = c.at_bin(1);
        assert_eq!(b.operating.load_torque_nm, 120.0);
        assert_eq!(b.operating.input_speed_hz, 90.0);
        assert_eq!(b.operating.load_torque_shaft, TorqueShaft::Gear);
        assert!(b.load_spectrum.is_none());
        // Everything else is the case's.
        assert_eq!(b.wear, c.wear);
        // A bin at the operating point is the case without its spectrum.
        let one = load_case(
            "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 1}]\n",
            &[],
        )
        .unwrap();
        assert_eq!(one.at_bin(0), Case::default());
    }

    #[test]
    fn rpm_and_hours_convert_as_stated() {
        let c = load_case(
            "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_rpm = 1800, hours = 2}, {torque_nm = 80, input_speed_rpm = 900, hours = 1}]\n",
            &[],
        )
        .unwrap();
        let s = c.load_spectrum.unwrap();
        // 1800 rpm = 30 Hz; cycles 2 h x 30 Hz : 1 h x 15 Hz = 60 : 15 = 0.8 : 0.2.
        assert_eq!(s.bins[0].input_speed_hz, 30.0);
        assert_eq!(s.bins[1].input_speed_hz, 15.0);
        assert!((s.bins[0].share - 0.8).abs() < 1e-15 && (s.bins[1].share - 0.2).abs() < 1e-15);
        // Mean time per cycle: 0.8 / 30 + 0.2 / 15 s.
        assert!((s.seconds_per_cycle() - (0.8 / 30.0 + 0.2 / 15.0)).abs() < 1e-15);
    }

    #[test]
    fn a_csv_file_is_read_from_the_case_folder() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("s.csv"),
            "torque_nm,input_speed_hz,share\n60,30,0.25\n70,35,0.75\n",
        )
        .unwrap();
        let c = load_case_in("[load_spectrum]\nfile = \"s.csv\"\n", &[], dir.path()).unwrap();
        assert_eq!(c.load_spectrum.as_ref().unwrap().bins[1].share, 0.75);
        std::fs::write(
            dir.path().join("bad.csv"),
            "torque_nm,input_speed_hz,share\n60,30,0.25\n-70,35,0.75\n",
        )
        .unwrap();
        let e = load_case_in("[load_spectrum]\nfile = \"bad.csv\"\n", &[], dir.path())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("bin 2") && e.contains("line 3") && e.contains("torque_nm"),
            "{e}"
        );
        let e = load_case_in("[load_spectrum]\nfile = \"none.csv\"\n", &[], dir.path())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("load_spectrum.file") && e.contains("cannot read"),
            "{e}"
        );
    }

    #[test]
    fn bad_spectra_name_the_bin_the_key_and_the_range() {
        // Shares not summing to 1.
        let e = err("[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 80, input_speed_hz = 45, share = 0.2}]\n");
        assert!(e.contains("sum to 0.9") && e.contains("hours"), "{e}");
        // Hours totalling zero.
        let e = err("[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, hours = 0}]\n");
        assert!(e.contains("hours total 0"), "{e}");
        // Negative, non-finite, outside the range (with the scale that put it there).
        for (bin, want) in [
            (
                "{torque_nm = -60, input_speed_hz = 30, share = 1}",
                "`torque_nm` = -60",
            ),
            (
                "{torque_nm = 60, input_speed_hz = nan, share = 1}",
                "`input_speed_hz` = NaN",
            ),
            (
                "{torque_nm = inf, input_speed_hz = 30, share = 1}",
                "`torque_nm` = inf",
            ),
            (
                "{torque_nm = 60, input_speed_hz = 2000, share = 1}",
                "outside [1e-6, 1000]",
            ),
            (
                "{torque_nm = 60, input_speed_hz = 30, share = 1.5}",
                "`share` = 1.5",
            ),
            ("{torque_nm = 60, input_speed_hz = 30}", "missing `share`"),
            (
                "{torque_nm = 60, input_speed_hz = 30, input_speed_rpm = 1800, share = 1}",
                "not both",
            ),
            (
                "{torque_nm = 60, speed_hz = 30, share = 1}",
                "unknown key `speed_hz`",
            ),
        ] {
            let e = err(&format!("[load_spectrum]\nbins = [{bin}]\n"));
            assert!(
                e.contains("load_spectrum bin 1") && e.contains(want),
                "{bin}: {e}"
            );
        }
        // 45 Hz x 30 = 1350 Hz is out of range; 30 x 30 = 900 Hz is not.
        let e = err(&format!("{TWO}speed_scale = 30\n"));
        assert!(
            e.contains("bin 2")
                && !e.contains("bin 1")
                && e.contains("speed_scale")
                && e.contains("operating.input_speed_hz"),
            "{e}"
        );
        let e = err(&format!("{TWO}monitoring_bin = 3\n"));
        assert!(e.contains("monitoring_bin") && e.contains("[1, 2]"), "{e}");
        let e = err("[load_spectrum]\ntorque_scale = 2\n");
        assert!(e.contains("has no bins"), "{e}");
        let e = err(&format!("{TWO}file = \"x.csv\"\n"));
        assert!(e.contains("not both"), "{e}");
    }
}
