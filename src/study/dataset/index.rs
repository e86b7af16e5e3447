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

/// (column, unit, meaning) of the label columns, in order.
pub const LABEL_COLUMNS: [(&str, &str, &str); 18] = [
    ("record_id", "-", "the record's number in the design (its order: metadata `record_id`)"),
    ("file", "-", "the record's signal file, relative to the dataset folder"),
    ("condition", "-", "the design's condition the record belongs to"),
    ("fault", "-", "what the condition's case models (a label tied to the case's faults)"),
    ("severity", "-", "the design's grade of the fault (0 without one)"),
    ("trajectory_state", "-", "the state's number along the condition's run to failure (0: new teeth)"),
    ("cycles", "pinion cycles", "pinion load cycles run before the state"),
    ("max_wear_pinion_um", "um", "deepest wear of the pinion's profile at the state"),
    ("max_wear_gear_um", "um", "deepest wear of the gear's profile at the state"),
    ("wear_limit_um", "um", "the wear depth that defines failure"),
    ("remaining_cycles", "pinion cycles", "pinion cycles from the state to failure (to the trajectory's end when failure_censored = 1)"),
    ("failure_censored", "0/1", "1 when failure was not reached within the trajectory: remaining_cycles is then a lower bound"),
    ("input_speed_hz", "Hz", "pinion shaft speed of the record"),
    ("load_torque_nm", "N m", "load torque of the record (on the shaft the case names)"),
    ("mesh_hz", "Hz", "mesh frequency of the record (teeth of the pinion x its speed)"),
    ("sampling_rate_hz", "Hz", "sampling rate of the record's channels and tachometer"),
    ("realisation", "-", "the noise realisation's number at this state, speed and load"),
    ("noise_seed", "-", "seed of the record's measurement noise"),
];

/// (column prefix, unit, meaning) of a gear train's columns for each stage k, named
/// `<prefix>_stage<k>` (after the label columns; a train's records only).
pub const STAGE_COLUMNS: [(&str, &str, &str); 5] = [
    ("max_wear_pinion_um", "um", "deepest wear of the stage's pinion profile at the state"),
    ("max_wear_gear_um", "um", "deepest wear of the stage's gear profile at the state"),
    ("wear_max_um", "um", "deepest wear of the stage's mesh (either flank) at the state"),
    ("cycles", "stage pinion cycles", "load cycles of the stage's pinion at the state (input cycles x its revolutions per input revolution)"),
    ("mesh_hz", "Hz", "the stage's mesh frequency at the record's input speed"),
];

/// A gear train's column naming the stage whose mesh is the deepest worn.
pub const LIMITING_STAGE_COLUMN: (&str, &str, &str) = (
    "limiting_stage",
    "-",
    "the train's stage (1-based) whose mesh has the deepest wear at the state (either flank): the mesh that limits the train's life; 0 while no mesh has worn (new teeth)",
);

/// (column prefix, unit, meaning) of a planetary set's columns for each member, named
/// `<prefix>_<member>` with the member `sun`, `planet<n>` or `ring` (after the label
/// columns; a set's records only), as a train's are named per stage.
pub const MEMBER_COLUMNS: [(&str, &str, &str); 2] = [
    ("wear_max_um", "um", "deepest wear of the member (its deepest flank; the sun's and the ring's sum their meshes' wear) at the state"),
    ("tooth_contacts", "contacts", "load cycles of one of the member's teeth at the state (input cycles x its tooth contacts per input revolution; a planet's per flank)"),
];

/// A planetary set's column naming its deepest-worn member.
pub const LIMITING_MEMBER_COLUMN: (&str, &str, &str) = (
    "limiting_member",
    "-",
    "the set's member (sun, planet<n>, ring) with the deepest wear at the state: the member that limits the set's life; empty while nothing has worn (new teeth)",
);

/// (column, unit, meaning) of a planetary set's fault columns (a dataset with a condition
/// whose case has `[[planetary.fault]]`; after the member columns): the fault the record's
/// model applies (`config::planetary_fault::active`), read from its case's tables.
pub const PLANETARY_FAULT_COLUMNS: [(&str, &str, &str); 7] = [
    ("fault_member", "-", "the member whose tooth has the fault the record's set models (sun, planet, ring); empty without one"),
    ("fault_planet", "-", "the faulty planet (1-based) of a planet's fault; 0 otherwise"),
    ("fault_tooth", "-", "the faulty tooth, 0-based (docs/MODEL.md 9.5 for a pair, 12.13 for a planetary set's member); -1 without a fault"),
    ("fault_kind", "-", "the fault's kind (crack, spall, broken_tip); empty without one"),
    ("fault_crack_depth_mm", "mm", "a crack's depth from the root along its path; 0 for another kind or none"),
    ("fault_spall_depth_um", "um", "a spall's depth; 0 for another kind or none"),
    ("fault_removed_height_mm", "mm", "a broken tip's removed height; 0 for another kind or none"),
];

/// A planetary set's [`PLANETARY_FAULT_COLUMNS`], when any record's case has a fault.
fn planetary_fault_columns(
    rows: &[RecordLabels],
    cols: &mut Vec<Column>,
    units: &mut Vec<(String, String)>,
) {
    use crate::config::planetary_fault::{active, PlanetaryFault};
    if rows.iter().all(|l| active(&l.planetary_faults).is_none()) {
        return;
    }
    fn of(l: &RecordLabels) -> Option<&PlanetaryFault> {
        active(&l.planetary_faults)
    }
    // A size column holds its own kind's size only (a written key of another kind is
    // not the model's).
    let size = |f: &PlanetaryFault, key: &str| {
        let kind = match key {
            "crack_depth_mm" => "crack",
            "spall_depth_um" => "spall",
            _ => "broken_tip",
        };
        let v = f.written(key);
        if f.kind.name() == kind && v.is_finite() {
            v
        } else {
            0.0
        }
    };
    for (name, unit, _) in PLANETARY_FAULT_COLUMNS {
        let data = match name {
            "fault_member" => ColumnData::Text(
                rows.iter()
                    .map(|l| of(l).map_or(String::new(), |f| f.gear.name().into()))
                    .collect(),
            ),
            "fault_kind" => ColumnData::Text(
                rows.iter()
                    .map(|l| of(l).map_or(String::new(), |f| f.kind.name().into()))
                    .collect(),
            ),
            "fault_planet" => ColumnData::I64(
                rows.iter()
                    .map(|l| of(l).and_then(|f| f.planet).unwrap_or(0))
                    .collect(),
            ),
            "fault_tooth" => {
                ColumnData::I64(rows.iter().map(|l| of(l).map_or(-1, |f| f.tooth)).collect())
            }
            _ => {
                let key = name.trim_start_matches("fault_");
                ColumnData::F64(
                    rows.iter()
                        .map(|l| of(l).map_or(0.0, |f| size(f, key)))
                        .collect(),
                )
            }
        };
        units.push((name.to_string(), unit.to_string()));
        cols.push(Column::new(name, data));
    }
}

/// (column, unit, meaning) of a pair's or a train's fault columns (a dataset with a
/// condition whose case has `[[fault]]`; after the label columns): what the record's model
/// applies, read from its case's tables, so that the free-text `fault` and `severity`
/// labels are never the only statement of it. A record's sidecar holds every table
/// (`labels.faults`); the columns give the count and the first table.
pub const PAIR_FAULT_COLUMNS: [(&str, &str, &str); 8] = [
    ("fault_count", "-", "the number of `[[fault]]` tables of the record's case (0 without one); the columns after it describe the first, the sidecar's `labels.faults` all of them"),
    ("fault_gear", "-", "the gear whose tooth has the (first) fault: pinion or gear; empty without one"),
    ("fault_stage", "-", "the train stage (1-based) of the (first) fault; 0 for a single pair or without one"),
    ("fault_tooth", "-", "the faulty tooth, 0-based (docs/MODEL.md 9.5 for a pair, 12.13 for a planetary set's member); -1 without a fault"),
    ("fault_kind", "-", "the fault's kind (crack, spall, broken_tip); empty without one"),
    ("fault_crack_depth_mm", "mm", "a crack's depth from the root along its path; 0 for another kind or none"),
    ("fault_spall_depth_um", "um", "a spall's depth; 0 for another kind or none"),
    ("fault_removed_height_mm", "mm", "a broken tip's removed height; 0 for another kind or none"),
];

/// A pair's or train's [`PAIR_FAULT_COLUMNS`], when any record's case has a fault.
fn pair_fault_columns(
    rows: &[RecordLabels],
    cols: &mut Vec<Column>,
    units: &mut Vec<(String, String)>,
) {
    use crate::config::teeth::{FaultKind, FaultTable};
    if rows.iter().all(|l| l.faults.is_empty()) {
        return;
    }
    fn first(l: &RecordLabels) -> Option<&crate::config::teeth::FaultTable> {
        l.faults.first()
    }
    let text = |g: &dyn Fn(&FaultTable) -> String| {
        ColumnData::Text(
            rows.iter()
                .map(|l| first(l).map_or(String::new(), g))
                .collect(),
        )
    };
    // A size column holds its own kind's size only (a key of another kind is not read).
    let size = |kind: FaultKind, g: &dyn Fn(&FaultTable) -> Option<f64>| {
        let value = |f: &FaultTable| {
            if f.kind == kind {
                g(f).unwrap_or(0.0)
            } else {
                0.0
            }
        };
        ColumnData::F64(rows.iter().map(|l| first(l).map_or(0.0, value)).collect())
    };
    for (name, unit, _) in PAIR_FAULT_COLUMNS {
        let data = match name {
            "fault_count" => ColumnData::I64(rows.iter().map(|l| l.faults.len() as i64).collect()),
            "fault_gear" => text(&|f| f.gear.name().into()),
            "fault_stage" => ColumnData::I64(
                rows.iter()
                    .map(|l| first(l).and_then(|f| f.stage).unwrap_or(0))
                    .collect(),
            ),
            "fault_tooth" => ColumnData::I64(
                rows.iter()
                    .map(|l| first(l).map_or(-1, |f| f.tooth))
                    .collect(),
            ),
            "fault_kind" => text(&|f| f.kind.name().into()),
            "fault_crack_depth_mm" => size(FaultKind::Crack, &|f| f.crack_depth_mm),
            "fault_spall_depth_um" => size(FaultKind::Spall, &|f| f.spall_depth_um),
            _ => size(FaultKind::BrokenTip, &|f| f.removed_height_mm),
        };
        units.push((name.to_string(), unit.to_string()));
        cols.push(Column::new(name, data));
    }
}

/// The meaning of a member column `<prefix>_<member>`.
fn member_column_meaning(name: &str) -> Option<String> {
    MEMBER_COLUMNS.iter().find_map(|(prefix, _, m)| {
        let member = name.strip_prefix(prefix)?.strip_prefix('_')?;
        let known = member == "sun"
            || member == "ring"
            || member
                .strip_prefix("planet")
                .is_some_and(|k| k.parse::<usize>().is_ok());
        known.then(|| format!("{m} ({member})"))
    })
}

/// The stage `k` (1-based) and the meaning of a stage column `<prefix>_stage<k>`.
fn stage_column_meaning(name: &str) -> Option<String> {
    let (prefix, k) = name.rsplit_once("_stage")?;
    let k: usize = k.parse().ok()?;
    let (_, _, m) = STAGE_COLUMNS.iter().find(|(p, _, _)| *p == prefix)?;
    Some(format!("{m} (stage {k})"))
}

/// What an indicator column means, by its suffix (`<sensor>_<suffix>` or
/// `<sensor>_<shaft>_<suffix>`; docs/SIGNALS.md defines each).
const INDICATOR_MEANINGS: [(&str, &str); 13] = [
    ("rms", "root mean square of the channel's record"),
    ("crest_factor", "peak over RMS of the channel's record"),
    ("kurtosis", "normalised fourth moment of the channel's record"),
    ("tsa_rms", "RMS of the shaft's time-synchronous average (TSA)"),
    ("fm0", "peak-to-peak of the TSA over the sum of the amplitudes of its mesh harmonics 1..signals.mesh_harmonics (FM0)"),
    ("fm4", "kurtosis of the TSA's difference signal (FM4)"),
    ("m6a", "sixth moment of the difference signal over its variance cubed (M6A)"),
    ("m8a", "eighth moment of the difference signal over its variance to the fourth (M8A)"),
    ("na4", "fourth moment of the residual signal over the squared mean residual variance of the run so far (NA4)"),
    ("nb4", "NA4 of the envelope of the band-pass signal around the mesh frequency (NB4)"),
    ("energy_ratio", "RMS of the difference signal over RMS of the regular signal"),
    ("sideband_level_factor", "sum of the two first-order sidebands of the mesh fundamental over the TSA's RMS"),
    ("sideband_index", "mean amplitude of the two first-order sidebands of the mesh fundamental"),
];

/// The meaning of index column `name` (a label, or a channel's indicator: sensor name,
/// then the shaft of a TSA indicator), for the metadata.
pub fn column_meaning(name: &str) -> String {
    if let Some((_, _, m)) = LABEL_COLUMNS.iter().find(|(n, _, _)| *n == name) {
        return (*m).to_string();
    }
    if name == LIMITING_STAGE_COLUMN.0 {
        return LIMITING_STAGE_COLUMN.2.to_string();
    }
    if let Some(m) = stage_column_meaning(name) {
        return m;
    }
    if name == LIMITING_MEMBER_COLUMN.0 {
        return LIMITING_MEMBER_COLUMN.2.to_string();
    }
    if let Some(m) = member_column_meaning(name) {
        return m;
    }
    // The names both tables share (tooth, kind, sizes) mean the same in both.
    if let Some((_, _, m)) = PLANETARY_FAULT_COLUMNS
        .iter()
        .chain(&PAIR_FAULT_COLUMNS)
        .find(|(n, _, _)| *n == name)
    {
        return (*m).to_string();
    }
    for shaft in ["pinion", "gear"] {
        for (suffix, m) in &INDICATOR_MEANINGS[3..] {
            if name.ends_with(&format!("_{shaft}_{suffix}")) {
                return format!("{m}, {shaft} shaft, of the sensor the name begins with");
            }
        }
    }
    for (suffix, m) in &INDICATOR_MEANINGS[..3] {
        if name.ends_with(&format!("_{suffix}")) {
            return format!("{m}, of the sensor the name begins with");
        }
    }
    "-".into()
}

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
        .map(|(n, _, _)| (n.to_string(), "the labels".to_string()))
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

/// A gear train's columns (its records' `stages`, the first record's count; a design's
/// conditions share one count, `design_checks::train_problems`): each stage's
/// [`STAGE_COLUMNS`], then [`LIMITING_STAGE_COLUMN`]. None for a single pair.
fn stage_columns(rows: &[RecordLabels], cols: &mut Vec<Column>, units: &mut Vec<(String, String)>) {
    let n = rows.first().map_or(0, |l| l.stages.len());
    if n == 0 {
        return;
    }
    for k in 0..n {
        for (prefix, unit, _) in STAGE_COLUMNS {
            let values = rows
                .iter()
                .map(|l| {
                    l.stages.get(k).map_or(0.0, |s| match prefix {
                        "max_wear_pinion_um" => s.max_wear_pinion_um,
                        "max_wear_gear_um" => s.max_wear_gear_um,
                        "wear_max_um" => s.wear_max_um,
                        "cycles" => s.pinion_cycles,
                        _ => s.mesh_hz,
                    })
                })
                .collect();
            let name = format!("{prefix}_stage{}", k + 1);
            units.push((name.clone(), unit.to_string()));
            cols.push(Column::new(name, ColumnData::F64(values)));
        }
    }
    let (name, unit, _) = LIMITING_STAGE_COLUMN;
    let limiting = rows
        .iter()
        .map(|l| l.limiting_stage.unwrap_or(0) as i64)
        .collect();
    units.push((name.to_string(), unit.to_string()));
    cols.push(Column::new(name, ColumnData::I64(limiting)));
}

/// A planetary set's columns (its records' `members`, the first record's: a design's
/// conditions share one set size, `design_checks::planetary_problems`): each
/// [`MEMBER_COLUMNS`] for every member, then [`LIMITING_MEMBER_COLUMN`]. None otherwise.
fn member_columns(
    rows: &[RecordLabels],
    cols: &mut Vec<Column>,
    units: &mut Vec<(String, String)>,
) {
    let Some(first) = rows.first().filter(|l| !l.members.is_empty()) else {
        return;
    };
    for (prefix, unit, _) in MEMBER_COLUMNS {
        for (k, member) in first.members.iter().enumerate() {
            let values = rows
                .iter()
                .map(|l| {
                    l.members.get(k).map_or(0.0, |m| match prefix {
                        "wear_max_um" => m.wear_max_um,
                        _ => m.tooth_contacts,
                    })
                })
                .collect();
            let name = format!("{prefix}_{}", member.member);
            units.push((name.clone(), unit.to_string()));
            cols.push(Column::new(name, ColumnData::F64(values)));
        }
    }
    let (name, unit, _) = LIMITING_MEMBER_COLUMN;
    let limiting = rows
        .iter()
        .map(|l| l.limiting_member.clone().unwrap_or_default())
        .collect();
    units.push((name.to_string(), unit.to_string()));
    cols.push(Column::new(name, ColumnData::Text(limiting)));
}

/// The index columns of `rows` (sorted by record id) and each column's unit.
pub fn index_columns(
    rows: &[RecordLabels],
    channel_unit: &str,
    sampling_rate_hz: f64,
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
        f(&|_| sampling_rate_hz),
        i(&|l| l.realisation as i64),
        i(&|l| l.noise_seed as i64),
    ];
    let mut cols: Vec<Column> = LABEL_COLUMNS
        .iter()
        .zip(data)
        .map(|((n, _, _), d)| Column::new(*n, d))
        .collect();
    let mut units: Vec<(String, String)> = LABEL_COLUMNS
        .iter()
        .map(|(n, u, _)| (n.to_string(), u.to_string()))
        .collect();
    stage_columns(rows, &mut cols, &mut units);
    member_columns(rows, &mut cols, &mut units);
    if rows.iter().all(|l| l.members.is_empty()) {
        pair_fault_columns(rows, &mut cols, &mut units);
    }
    planetary_fault_columns(rows, &mut cols, &mut units);
    // A planetary set's records have no shaft TSA (`super::planetary_records`).
    let shafts: &[(&str, bool)] = match rows.first() {
        Some(l) if !l.members.is_empty() => &[],
        _ => &[("pinion", true), ("gear", false)],
    };
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
        for &(shaft, pinion) in shafts {
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
