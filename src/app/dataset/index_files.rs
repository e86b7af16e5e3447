//! The index and metadata of a dataset folder, built from its finished records' sidecars
//! and state files (`folder`): `index.parquet`, `index.csv`, `metadata.json` and the
//! indicator trends, by the same code for an unsharded run and a merge, so the two are
//! byte for byte equal; and whether a record's labels are those of the design described.

use super::folder::{read_in, sidecars, trajectories, Sidecar, DATASET_REL};
use crate::io::columns_csv::columns_csv;
use crate::io::parquet::{parquet_bytes, Column};
use crate::io::{OutputDir, OutputError};
use crate::report::artifacts::{stage_figures, FigureFile};
use crate::report::dataset_trends::trend_figure;
use crate::report::figure_output::FigureOutput;
use crate::study::dataset::index::{column_meaning, index_columns};
use crate::study::dataset::records::signal_file;
use crate::study::dataset::trends::{trend_columns, trends};
use crate::study::dataset::RecordLabels;
use serde_json::{json, Value};
use std::path::Path;

/// Why the index and metadata could not be built.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// Writing a file of the index failed.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The description or a table could not be made (the message names the file).
    #[error("{0}")]
    Format(String),
}

/// Most missing record ids listed in `metadata.json` (`records_missing`; the count is
/// `records_missing_count`).
pub const MAX_MISSING_LISTED: usize = 1000;

/// Records missing from a dataset's index: how many, and the first ids.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Missing {
    /// How many records are missing.
    pub count: usize,
    /// The first [`MAX_MISSING_LISTED`] missing ids, ascending.
    pub listed: Vec<usize>,
}

/// The index of a dataset (`index.parquet`, `index.csv`) as a run or a merge writes it.
pub struct IndexTables {
    /// Records indexed, and those missing from `0..total`.
    pub present: usize,
    /// Records missing from `0..total`: the count and the first ids.
    pub missing: Missing,
    /// The index columns and each column's unit.
    pub columns: Vec<Column>,
    /// Each index column's name and unit.
    pub units: Vec<(String, String)>,
    /// The channels' unit (the description's `record.channel_unit`).
    pub channel_unit: String,
    /// `index.parquet`'s bytes (the units in its metadata, `gearwear.units`).
    pub parquet: Vec<u8>,
    /// `index.csv`'s bytes.
    pub csv: Vec<u8>,
}

/// The index of the sidecars `cars` under the description `body` (`state/dataset.json`,
/// whose path `described` names it in messages) of a dataset of `total` records. Only
/// records whose identity the description gives are indexed: an id in range, and the
/// condition, its labels, state, speed, load, realisation and noise seed that id has in
/// the design ([`matches_design`]); an edited or planted sidecar is counted missing.
/// Public for the fuzz targets `dataset_sidecar` and `dataset_shard` (docs/RELIABILITY.md).
pub fn index_tables(
    cars: Vec<Sidecar>,
    body: &Value,
    total: usize,
    described: &Path,
) -> Result<IndexTables, BuildError> {
    let key = body["dataset_key"].as_str().unwrap_or_default();
    let rows: Vec<RecordLabels> = cars
        .into_iter()
        .filter(|s| s.dataset_key == key && s.labels.record_id < total)
        .map(|s| s.labels)
        .filter(|l| matches_design(l, body))
        .collect();
    let present: std::collections::BTreeSet<usize> = rows.iter().map(|r| r.record_id).collect();
    // Listed up to MAX_MISSING_LISTED ids (the count is in the headline): the list
    // never grows with the record count alone.
    let listed: Vec<usize> = (0..total)
        .filter(|i| !present.contains(i))
        .take(MAX_MISSING_LISTED)
        .collect();
    let missing = Missing {
        count: total - present.range(..total).count(),
        listed,
    };
    let channel_unit = body["record"]["channel_unit"]
        .as_str()
        .unwrap_or("-")
        .to_owned();
    // One chain per dataset (`design::chain_problems`), so one sampling rate.
    let rate_hz = body["record"]["sampling_rate_hz"]
        .as_f64()
        .filter(|r| r.is_finite() && *r > 0.0)
        .ok_or_else(|| {
            BuildError::Format(format!(
                "{}: no valid record.sampling_rate_hz",
                described.display()
            ))
        })?;
    let (columns, units) = index_columns(&rows, &channel_unit, rate_hz);
    let units_json = units_json(&units);
    let meta = vec![("gearwear.units".to_string(), units_json.to_string())];
    let parquet = parquet_bytes(&columns, &meta)
        .map_err(|e| BuildError::Format(format!("index.parquet: {e}")))?;
    let csv = columns_csv(&columns).map_err(|e| BuildError::Format(format!("index.csv: {e}")))?;
    Ok(IndexTables {
        present: rows.len(),
        missing,
        columns,
        units,
        channel_unit,
        parquet,
        csv,
    })
}

/// Each index column's unit, as JSON (`metadata.json` `index_columns` and the index's
/// Parquet metadata).
fn units_json(units: &[(String, String)]) -> Value {
    Value::Object(units.iter().map(|(n, u)| (n.clone(), json!(u))).collect())
}

/// Stage `index.parquet`, `index.csv`, `metadata.json` and the indicator trends (table,
/// and figure as `figures` says) of the dataset in `root` (whose records and state files
/// are in place) into `out`. Returns the ids missing from `0..total`.
pub fn stage_index_and_metadata(
    out: &mut OutputDir,
    root: &Path,
    total: usize,
    figures: FigureOutput,
) -> Result<Missing, BuildError> {
    let described = root.join(DATASET_REL);
    let body: Value = read_in(root, DATASET_REL)
        .and_then(|b| serde_json::from_slice(&b).ok())
        .ok_or_else(|| {
            BuildError::Format(format!("{}: missing or unreadable", described.display()))
        })?;
    let key = body["dataset_key"].as_str().unwrap_or_default().to_owned();
    let t = index_tables(sidecars(root), &body, total, &described)?;
    out.stage("index.parquet", &t.parquet)?;
    out.stage("index.csv", &t.csv)?;
    stage_trends(out, &t.columns, &t.channel_unit, figures)?;
    let mut metadata = body;
    metadata["index_column_meanings"] = json!(t
        .units
        .iter()
        .map(|(n, _)| (n.clone(), json!(column_meaning(n))))
        .collect::<serde_json::Map<String, Value>>());
    metadata["index_columns"] = units_json(&t.units);
    metadata["trajectories"] = trajectories_json(root, &key);
    metadata["records_present"] = json!(t.present);
    metadata["records_missing"] = json!(t.missing.listed);
    metadata["records_missing_count"] = json!(t.missing.count);
    out.stage_json("metadata.json", &metadata)?;
    Ok(t.missing)
}

/// Stage the indicator trends of the index columns `cols` (`indicator_trends.csv`, and
/// its figure as `figures` says; `unit`: the channels' unit), when the index has any.
fn stage_trends(
    out: &mut OutputDir,
    cols: &[Column],
    unit: &str,
    figures: FigureOutput,
) -> Result<(), BuildError> {
    if let Some(t) = trends(cols) {
        let table = columns_csv(&trend_columns(&t))
            .map_err(|e| BuildError::Format(format!("indicator_trends.csv: {e}")))?;
        out.stage("indicator_trends.csv", &table)?;
        let fig = FigureFile {
            path: "indicator_trends.png".into(),
            figure: trend_figure(&t, unit),
            width_px: 900,
            height_px: 1500,
            data: Some("indicator_trends.csv".into()),
            rendered: None,
        };
        stage_figures(out, &[fig], figures).map_err(|e| BuildError::Format(e.to_string()))?;
    }
    Ok(())
}

/// Each trajectory of dataset `key` in `root`: its condition, failure and end cycles,
/// whether it stopped, and its updates' cycles and maximum pinion wear (µm).
fn trajectories_json(root: &Path, key: &str) -> Value {
    json!(trajectories(root)
        .iter()
        .filter(|t| t.dataset_key == key)
        .map(|t| {
            let mut v = json!({
                "condition": t.condition,
                "failure_cycles": t.trajectory.failure_cycles,
                "end_cycles": t.trajectory.end_cycles,
                "stopped": t.trajectory.stopped,
                "updates": t.trajectory.records.len(),
                "update_cycles": t.trajectory.records.iter().map(|r| r.wear.cycles).collect::<Vec<_>>(),
                "update_max_wear_pinion_um": t.trajectory.records.iter().map(|r| r.wear.max_pinion_m() * 1e6).collect::<Vec<_>>(),
            });
            if !t.trajectory.cycle_factors.is_empty() {
                v["update_wear_max_um_by_stage"] = stage_wear_json(&t.trajectory);
            }
            v
        })
        .collect::<Vec<_>>())
}

/// A train's trajectory: each stage's deepest wear (either flank, µm) at every update,
/// stage order (stage 1's `update_max_wear_pinion_um` is its pinion flank alone).
fn stage_wear_json(t: &crate::study::dataset::trajectory::Trajectory) -> Value {
    json!((0..t.mesh_count())
        .map(|m| {
            (0..t.records.len())
                .filter_map(|i| t.record(m, i))
                .map(|r| r.wear.max_pinion_m().max(r.wear.max_gear_m()) * 1e6)
                .collect::<Vec<_>>()
        })
        .collect::<Vec<_>>())
}

/// Whether record labels `l` are those the design described by `body` (the
/// description, `state/dataset.json`) gives its id: condition (name, fault, severity),
/// trajectory state, speed, load, realisation and noise seed, all recomputed from the id,
/// its indicators' channels the description's sensors, and a train's stages numbered as
/// the description's train has them (none for a single pair).
pub fn matches_design(l: &RecordLabels, body: &Value) -> bool {
    let a = &body["axes"];
    let len = |v: &Value| v.as_array().map_or(0, Vec::len);
    let states = a["states"]["evenly_spaced"]
        .as_u64()
        .map(|n| n as usize)
        .unwrap_or_else(|| len(&a["states"]["cycles"]));
    let (speeds, loads) = (&a["input_speed_hz"], &a["load_torque_nm"]);
    let plan = crate::study::dataset::plan::Plan {
        conditions: len(&a["conditions"]),
        states,
        speeds: len(speeds),
        loads: len(loads),
        realisations: a["noise_realisations"].as_u64().unwrap_or(0) as usize,
    };
    if plan.realisations == 0 || plan.loads == 0 || plan.speeds == 0 || plan.states == 0 {
        return false;
    }
    let p = l.record_id / plan.realisations;
    let ix = plan.state_index(p);
    let c = &a["conditions"][ix.condition];
    let seed = body["seed"].as_u64().unwrap_or(0);
    ix.condition < plan.conditions
        && c["name"].as_str() == Some(l.condition.as_str())
        && c["fault"].as_str() == Some(l.fault.as_str())
        && c["severity"].as_f64() == Some(l.severity)
        && l.trajectory_state == ix.state
        && speeds[ix.speed].as_f64() == Some(l.input_speed_hz)
        && loads[ix.load].as_f64() == Some(l.load_torque_nm)
        && l.realisation == l.record_id % plan.realisations
        && l.noise_seed == crate::study::dataset::plan::record_seed(seed, l.record_id)
        && l.file == signal_file(l.record_id)
        && channels_match(l, &body["record"]["sensors"])
        && l.stages.len() == len(&body["train"]["conditions"][ix.condition]["stages"])
        && l.stages.iter().enumerate().all(|(k, s)| s.stage == k + 1)
        // A single pair has no limiting stage; a train's is absent only for new teeth
        // (every kept record's labels are recomputed besides: `super::label_check`).
        && (l.limiting_stage.is_none() || !l.stages.is_empty())
        // A planetary set's members: the sun, its planets, the ring (none otherwise).
        && l.members.len() == body["planetary"]["planets"].as_u64().map_or(0, |n| n as usize + 2)
        && (l.limiting_member.is_none() || !l.members.is_empty())
}

/// Whether the record's indicator channels are the description's sensors, in order: a
/// sidecar with both channels renamed `x` was merged into an index of two `x_rms` columns.
fn channels_match(l: &RecordLabels, sensors: &Value) -> bool {
    sensors.as_array().is_some_and(|s| {
        s.len() == l.indicators.len()
            && s.iter()
                .zip(&l.indicators)
                .all(|(a, c)| a.as_str() == Some(c.channel.as_str()))
    })
}
