//! The index table of a dataset: one row per record (sorted by record id), its labels
//! and indicators as columns, with units.
//!
//! NA4 and NB4 are trend indicators: their denominator averages the residual (envelope)
//! variances of the records of the same run so far (Zakrajsek 1993). In the index a run
//! is a condition's trajectory recorded at one speed, load and noise realisation, its
//! records in order of cycles; each record's NA4 uses the variances of that run's
//! records up to and including its own. The per-record files keep NA4 of the record alone.

use super::records::RecordLabels;
use crate::io::parquet::{Column, ColumnData};
use crate::signals::indicators::ShaftIndicators;
use std::collections::BTreeMap;

/// (column, unit) of the label columns, in order.
pub const LABEL_COLUMNS: [(&str, &str); 17] = [
    ("record_id", "-"),
    ("file", "-"),
    ("condition", "-"),
    ("fault", "-"),
    ("severity", "-"),
    ("trajectory_state", "-"),
    ("cycles", "pinion cycles"),
    ("max_wear_pinion_um", "um"),
    ("max_wear_gear_um", "um"),
    ("wear_limit_um", "um"),
    ("remaining_cycles", "pinion cycles"),
    ("failure_censored", "0/1"),
    ("input_speed_hz", "Hz"),
    ("load_torque_nm", "N m"),
    ("mesh_hz", "Hz"),
    ("realisation", "-"),
    ("noise_seed", "-"),
];

/// Shaft indicator columns and whether they carry the channel unit.
const SHAFT_COLUMNS: [(&str, bool); 10] = [
    ("tsa_rms", true),
    ("fm0", false),
    ("fm4", false),
    ("m6a", false),
    ("m8a", false),
    ("na4", false),
    ("nb4", false),
    ("energy_ratio", false),
    ("sideband_level_factor", false),
    ("sideband_index", true),
];

fn shaft_value(s: &ShaftIndicators, name: &str) -> f64 {
    match name {
        "tsa_rms" => s.tsa_rms,
        "fm0" => s.fm0,
        "fm4" => s.fm4,
        "m6a" => s.m6a,
        "m8a" => s.m8a,
        "na4" => s.na4,
        "nb4" => s.nb4,
        "energy_ratio" => s.energy_ratio,
        "sideband_level_factor" => s.sideband_level_factor,
        _ => s.sideband_index,
    }
}

/// A run of records for the NA4/NB4 trend (module docs).
fn run_key(l: &RecordLabels) -> (String, u64, u64, usize) {
    (
        l.condition.clone(),
        l.input_speed_hz.to_bits(),
        l.load_torque_nm.to_bits(),
        l.realisation,
    )
}

/// NA4 and NB4 of every record (by position in `rows`) for channel `c` and shaft
/// `pinion` (true) or gear, with the run's history.
fn trends(rows: &[RecordLabels], c: usize, pinion: bool) -> Vec<(f64, f64)> {
    let shaft = |l: &RecordLabels| -> Option<ShaftIndicators> {
        let ch = l.indicators.get(c)?;
        if pinion {
            ch.pinion
        } else {
            ch.gear
        }
    };
    let mut runs: BTreeMap<_, Vec<usize>> = BTreeMap::new();
    for (i, l) in rows.iter().enumerate() {
        runs.entry(run_key(l)).or_default().push(i);
    }
    let mut out = vec![(0.0, 0.0); rows.len()];
    for members in runs.values_mut() {
        members.sort_by(|a, b| {
            rows[*a]
                .cycles
                .total_cmp(&rows[*b].cycles)
                .then(rows[*a].record_id.cmp(&rows[*b].record_id))
        });
        let (mut sum_r, mut sum_e) = (0.0, 0.0);
        for (k, &i) in members.iter().enumerate() {
            let Some(s) = shaft(&rows[i]) else { continue };
            sum_r += s.residual_variance;
            sum_e += s.envelope_variance;
            let n = (k + 1) as f64;
            // NA4 alone is m4 / var^2: rescale to m4 / (mean variance)^2.
            let rescale = |alone: f64, var: f64, mean: f64| {
                if mean > 0.0 {
                    alone * (var / mean).powi(2)
                } else {
                    0.0
                }
            };
            out[i] = (
                rescale(s.na4, s.residual_variance, sum_r / n),
                rescale(s.nb4, s.envelope_variance, sum_e / n),
            );
        }
    }
    out
}

/// The index columns a channel named `name` gets, in order: `<name>_rms`,
/// `_crest_factor`, `_kurtosis`, then `<name>_<shaft>_<indicator>` for each shaft.
pub fn channel_column_names(name: &str) -> Vec<String> {
    let mut out: Vec<String> = ["rms", "crest_factor", "kurtosis"]
        .iter()
        .map(|c| format!("{name}_{c}"))
        .collect();
    for shaft in ["pinion", "gear"] {
        out.extend(
            SHAFT_COLUMNS
                .iter()
                .map(|(c, _)| format!("{name}_{shaft}_{c}")),
        );
    }
    out
}

/// Problems of sensor names as index columns: a name empty or used twice, or two
/// sensors whose generated columns collide with each other or with a label column
/// (sensors "x" and "x_pinion_tsa" both give `x_pinion_tsa_rms`).
pub fn sensor_column_problems(sensors: &[String]) -> Vec<String> {
    let mut p = Vec::new();
    let mut owner: BTreeMap<String, String> = LABEL_COLUMNS
        .iter()
        .map(|(n, _)| (n.to_string(), "the labels".to_string()))
        .collect();
    for (i, s) in sensors.iter().enumerate() {
        if s.trim().is_empty() {
            p.push(format!(
                "sensor {} has an empty name: name every sensor",
                i + 1
            ));
            continue;
        }
        if sensors[..i].contains(s) {
            p.push(format!(
                "sensor {:?} is named twice: sensor names must be unique",
                s
            ));
            continue;
        }
        for col in channel_column_names(s) {
            if let Some(o) = owner.get(&col) {
                p.push(format!(
                    "sensor {s:?} gives the index column `{col}`, which {} give too: rename one of them",
                    if o == "the labels" { o.clone() } else { format!("sensor {o:?}'s columns") }
                ));
                break;
            }
            owner.insert(col, s.clone());
        }
    }
    p
}

/// The index columns of `rows` (sorted by record id) and each column's unit.
pub fn index_columns(
    rows: &[RecordLabels],
    channel_unit: &str,
) -> (Vec<Column>, Vec<(String, String)>) {
    use ColumnData::*;
    let f = |g: &dyn Fn(&RecordLabels) -> f64| F64(rows.iter().map(g).collect());
    let i = |g: &dyn Fn(&RecordLabels) -> i64| I64(rows.iter().map(g).collect());
    let t = |g: &dyn Fn(&RecordLabels) -> String| Text(rows.iter().map(g).collect());
    let data = [
        i(&|l| l.record_id as i64),
        t(&|l| l.file.clone()),
        t(&|l| l.condition.clone()),
        t(&|l| l.fault.clone()),
        f(&|l| l.severity),
        i(&|l| l.trajectory_state as i64),
        f(&|l| l.cycles),
        f(&|l| l.max_wear_pinion_um),
        f(&|l| l.max_wear_gear_um),
        f(&|l| l.wear_limit_um),
        f(&|l| l.remaining_cycles),
        i(&|l| i64::from(l.failure_censored)),
        f(&|l| l.input_speed_hz),
        f(&|l| l.load_torque_nm),
        f(&|l| l.mesh_hz),
        i(&|l| l.realisation as i64),
        i(&|l| l.noise_seed as i64),
    ];
    let mut cols: Vec<Column> = LABEL_COLUMNS
        .iter()
        .zip(data)
        .map(|((n, _), d)| Column::new(*n, d))
        .collect();
    let mut units: Vec<(String, String)> = LABEL_COLUMNS
        .iter()
        .map(|(n, u)| (n.to_string(), u.to_string()))
        .collect();
    let channels: Vec<String> = rows.first().map_or(Vec::new(), |l| {
        l.indicators.iter().map(|c| c.channel.clone()).collect()
    });
    for (c, name) in channels.iter().enumerate() {
        let ch = |l: &RecordLabels| l.indicators.get(c).map(|x| x.signal).unwrap_or_default();
        for (col, unit, g) in [
            (
                "rms",
                channel_unit,
                &(|l: &RecordLabels| ch(l).rms) as &dyn Fn(&RecordLabels) -> f64,
            ),
            ("crest_factor", "-", &|l: &RecordLabels| ch(l).crest_factor),
            ("kurtosis", "-", &|l: &RecordLabels| ch(l).kurtosis),
        ] {
            cols.push(Column::new(format!("{name}_{col}"), f(g)));
            units.push((format!("{name}_{col}"), unit.to_string()));
        }
        for (shaft, pinion) in [("pinion", true), ("gear", false)] {
            let tr = trends(rows, c, pinion);
            for (col, with_unit) in SHAFT_COLUMNS {
                let values: Vec<f64> = rows
                    .iter()
                    .enumerate()
                    .map(|(k, l)| {
                        let s =
                            l.indicators
                                .get(c)
                                .and_then(|x| if pinion { x.pinion } else { x.gear });
                        match (col, s) {
                            ("na4", Some(_)) => tr[k].0,
                            ("nb4", Some(_)) => tr[k].1,
                            (_, Some(s)) => shaft_value(&s, col),
                            (_, None) => 0.0,
                        }
                    })
                    .collect();
                let name = format!("{name}_{shaft}_{col}");
                units.push((
                    name.clone(),
                    if with_unit {
                        channel_unit.to_string()
                    } else {
                        "-".to_string()
                    },
                ));
                cols.push(Column::new(name, F64(values)));
            }
        }
    }
    (cols, units)
}
