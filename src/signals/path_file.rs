//! A transfer-path file: a measured FRF table (CSV, `super::frf_table`) or a modal
//! description (TOML):
//!
//! ```toml
//! sensors = ["input", "output"]
//! [[mode]]
//! frequency_hz = 2100.0
//! damping_ratio = 0.02
//! # modal constant G_rsj per sensor (rows, in `sensors` order) and bearing-force input
//! # (columns: pinion_x, pinion_y, gear_x, gear_y), 1/kg = m/s^2 per N above the mode
//! gains_per_kg = [[0.0075, 0.025, 0.005, 0.02], [0.006, 0.02, 0.004, 0.016]]
//! ```

use super::frf_table::parse_frf_table;
use super::transfer::{PathModel, StructuralMode, TransferPath};
use crate::format::format_number;
use serde::Deserialize;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ModalFile {
    sensors: Vec<String>,
    #[serde(rename = "mode")]
    modes: Vec<ModeEntry>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ModeEntry {
    frequency_hz: f64,
    damping_ratio: f64,
    gains_per_kg: Vec<Vec<f64>>,
}

/// Lowest natural frequency of a mode of a modal path, Hz: no structure a sensor is
/// mounted on has a mode slower than this, and its square stays far from underflow.
const MIN_MODE_HZ: f64 = 0.01;
/// Lowest modal damping ratio of a modal path (structures: 1e-4 to 0.1): keeps the
/// resonant accelerance g / (2 zeta) finite.
const MIN_DAMPING_RATIO: f64 = 1e-6;

/// Parse a transfer path from the text of `name` (`.csv`: FRF table, otherwise modal
/// TOML). Every problem names the file and the entry.
pub(crate) fn parse_transfer_path(text: &str, name: &str) -> Result<TransferPath, Vec<String>> {
    if name.to_ascii_lowercase().ends_with(".csv") {
        let t = parse_frf_table(text, name)?;
        let p = sensor_name_problems(&t.sensors, name);
        if !p.is_empty() {
            return Err(p);
        }
        return Ok(TransferPath {
            sensors: t.sensors.clone(),
            model: PathModel::Table(t),
            description: format!("FRF table {name}"),
            placement: format!("as the FRF table {name} defines them: each sensor's accelerance to the bearing forces (pinion x, y; gear x, y)"),
        });
    }
    let f: ModalFile =
        toml::from_str(text).map_err(|e| vec![format!("{name}: {}", e.message())])?;
    let mut problems = Vec::new();
    if f.sensors.is_empty() {
        problems.push(format!(
            "{name}: `sensors` is empty: name at least one sensor"
        ));
    }
    problems.extend(sensor_name_problems(&f.sensors, name));
    if f.modes.is_empty() {
        problems.push(format!("{name}: no [[mode]]: give at least one mode"));
    }
    let mut modes = Vec::new();
    for (r, m) in f.modes.iter().enumerate() {
        let at = format!("{name}, mode {}", r + 1);
        // Issue 33: a mode at 5e-324 Hz squared to 0 and gave 0/0 at the record's zero
        // frequency (empty channels, null indicators); bounded where every accelerance
        // is finite (`modal_accelerance`: |H| <= g / (2 zeta) at resonance, at most 5e11
        // m/s^2/N with the gains' 1e6).
        if !(m.frequency_hz.is_finite() && (MIN_MODE_HZ..=1e7).contains(&m.frequency_hz)) {
            problems.push(format!(
                "{at}: `frequency_hz` = {} is invalid: expected a number in [{MIN_MODE_HZ}, 1e7] Hz",
                format_number(m.frequency_hz)
            ));
        }
        if !(m.damping_ratio.is_finite()
            && m.damping_ratio >= MIN_DAMPING_RATIO
            && m.damping_ratio < 1.0)
        {
            problems.push(format!(
                "{at}: `damping_ratio` = {} is invalid: expected a number in [{MIN_DAMPING_RATIO:e}, 1)",
                format_number(m.damping_ratio)
            ));
        }
        if m.gains_per_kg.len() != f.sensors.len() {
            problems.push(format!(
                "{at}: `gains_per_kg` has {} rows for {} sensors: expected one row per sensor",
                m.gains_per_kg.len(),
                f.sensors.len()
            ));
            continue;
        }
        let mut rows = Vec::new();
        for (s, row) in m.gains_per_kg.iter().enumerate() {
            if row.len() != 4 || row.iter().any(|g| !g.is_finite() || g.abs() > 1e6) {
                problems.push(format!(
                    "{at}: `gains_per_kg` row {} ({}) is invalid: expected 4 finite numbers within +-1e6 1/kg (pinion_x, pinion_y, gear_x, gear_y)",
                    s + 1,
                    f.sensors[s]
                ));
                continue;
            }
            rows.push([row[0], row[1], row[2], row[3]]);
        }
        modes.push(StructuralMode {
            frequency_hz: m.frequency_hz,
            damping_ratio: m.damping_ratio,
            gains_per_kg: rows,
        });
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    Ok(TransferPath {
        sensors: f.sensors,
        model: PathModel::Modal(modes),
        description: format!("modal path {name}"),
        placement: format!("as the modal path {name} defines them: each sensor's modal constants to the bearing forces (pinion x, y; gear x, y)"),
    })
}

/// Problems of a path's sensor names: each names a column of every record, so each must
/// be non-empty (not blank) and unique.
pub fn sensor_name_problems(sensors: &[String], name: &str) -> Vec<String> {
    let mut p = Vec::new();
    for (i, s) in sensors.iter().enumerate() {
        if s.trim().is_empty() {
            p.push(format!(
                "{name}: sensor {} has an empty name: name every sensor (its column's name)",
                i + 1
            ));
        } else if sensors[..i].contains(s) {
            p.push(format!(
                "{name}: sensor {s:?} is named twice: sensor names must be unique (each names a column)"
            ));
        }
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modal_file_reads_and_bad_entries_are_named() {
        let ok = "sensors = [\"top\"]\n[[mode]]\nfrequency_hz = 3000\ndamping_ratio = 0.03\ngains_per_kg = [[0, 0.1, 0, 0.05]]\n";
        let p = parse_transfer_path(ok, "path.toml").unwrap();
        assert_eq!(p.sensors, vec!["top".to_string()]);
        let bad = "sensors = [\"top\"]\n[[mode]]\nfrequency_hz = -3\ndamping_ratio = 1.5\ngains_per_kg = [[0, 0.1]]\n";
        let e = parse_transfer_path(bad, "path.toml").unwrap_err();
        assert_eq!(e.len(), 3, "{e:?}");
        assert!(e[0].contains("mode 1") && e[0].contains("`frequency_hz` = -3"));
    }

    #[test]
    fn modes_are_bounded_where_every_accelerance_is_finite() {
        // Issue 33: 5e-324 Hz gave 0/0 at the zero frequency (empty channels).
        let mode = |f: &str, z: &str| {
            format!("sensors = [\"top\"]\n[[mode]]\nfrequency_hz = {f}\ndamping_ratio = {z}\ngains_per_kg = [[1e6, -1e6, 1e6, 1e6]]\n")
        };
        let e = parse_transfer_path(&mode("5e-324", "0.03"), "p.toml").unwrap_err();
        assert!(
            e[0].contains("`frequency_hz` = 5e-324") && e[0].contains("[0.01, 1e7]"),
            "{e:?}"
        );
        let e = parse_transfer_path(&mode("3000", "1e-300"), "p.toml").unwrap_err();
        assert!(
            e[0].contains("`damping_ratio`") && e[0].contains("[1e-6, 1)"),
            "{e:?}"
        );
        // At the accepted edges, the accelerance is finite at zero frequency, at the
        // resonance (the largest, g / (2 zeta)) and far above it.
        for (f, z) in [("0.01", "1e-6"), ("1e7", "1e-6"), ("0.01", "0.999")] {
            let p = parse_transfer_path(&mode(f, z), "p.toml").unwrap();
            let fr: f64 = f.parse().unwrap();
            for at in [0.0, fr, 1e-3 * fr, 1e3 * fr, 1e7] {
                for j in 0..4 {
                    let h = p.accelerance(0, j, at);
                    assert!(h.re.is_finite() && h.im.is_finite(), "{f} {z} at {at}: {h}");
                }
            }
        }
    }

    #[test]
    fn sensor_names_must_be_unique_and_non_empty() {
        // Issue 33: sensors ["a", "a"] gave duplicated columns; [""] was accepted.
        let modal = |sensors: &str, rows: usize| {
            format!(
                "sensors = {sensors}\n[[mode]]\nfrequency_hz = 3000\ndamping_ratio = 0.03\ngains_per_kg = [{}]\n",
                vec!["[0, 0.1, 0, 0.05]"; rows].join(", ")
            )
        };
        let e = parse_transfer_path(&modal("[\"a\", \"a\"]", 2), "p.toml").unwrap_err();
        assert!(
            e.iter()
                .any(|m| m.contains("p.toml") && m.contains("\"a\" is named twice")),
            "{e:?}"
        );
        let e = parse_transfer_path(&modal("[\"\"]", 1), "p.toml").unwrap_err();
        assert!(
            e.iter().any(|m| m.contains("sensor 1 has an empty name")),
            "{e:?}"
        );
        let csv = "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n0,,pinion_x,1,0\n5000,,pinion_x,1,0\n";
        if let Err(e) = parse_transfer_path(csv, "f.csv") {
            assert!(e.iter().any(|m| m.contains("f.csv")), "{e:?}");
        } else {
            panic!("an FRF table with an empty sensor name was accepted");
        }
    }
}
