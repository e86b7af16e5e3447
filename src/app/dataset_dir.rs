//! The files of a dataset folder (docs/SIGNALS.md, "Dataset layout"):
//!
//! - `signals/<id>.parquet`: one record (accelerometers and tachometer, float32);
//! - `csv/<id>.csv`: the same record as PHM 2009-style CSV, when the design asks;
//! - `records/<id>.json`: the record's labels and indicators, the dataset key and the
//!   SHA-256 of its signal file (written last: a record is finished when this exists);
//! - `state/dataset.json`: the dataset's description (design, cases, chain, axes);
//! - `state/trajectory_<condition>.json`: the condition's run-to-failure trajectory;
//! - `indicator_trends.csv`, `indicator_trends.png`: the condition indicators along each
//!   trajectory (`study::dataset::trends`);
//! - `index.parquet`, `index.csv`: one row per record; `metadata.json`: everything
//!   needed to read and reproduce the dataset. Built from the files above, by the same
//!   code for an unsharded run and a merge, so the two are byte for byte equal.

use crate::checksum::sha256_hex;
use crate::io::atomic::{ensure_real_dir, write_atomic};
use crate::io::columns_csv::columns_csv;
use crate::io::parquet::parquet_bytes;
use crate::io::{OutputDir, OutputError};
use crate::report::dataset_trends::trend_figure;
use crate::report::plot::render_png;
use crate::study::dataset::index::index_columns;
use crate::study::dataset::trajectory::Trajectory;
use crate::study::dataset::trends::{trend_columns, trends};
use crate::study::dataset::RecordLabels;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// A finished record's sidecar (`records/<id>.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sidecar {
    /// Hash of everything the dataset was generated from (design, cases, transfer path,
    /// program version): a record is reused only under the same key.
    pub dataset_key: String,
    pub signal_sha256: String,
    pub labels: RecordLabels,
}

/// A trajectory as kept in `state/`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TrajectoryFile {
    pub dataset_key: String,
    pub condition: String,
    pub trajectory: Trajectory,
}

pub fn sidecar_rel(id: usize) -> String {
    format!("records/{id:07}.json")
}

pub fn csv_rel(id: usize) -> String {
    format!("csv/{id:07}.csv")
}

pub fn trajectory_rel(condition: &str) -> String {
    format!("state/trajectory_{condition}.json")
}

pub const DATASET_REL: &str = "state/dataset.json";

/// Write `bytes` at `rel` inside `root` atomically (folders created, checked real).
pub fn put(root: &Path, rel: &str, bytes: &[u8]) -> Result<(), OutputError> {
    let path = root.join(rel);
    if let Some(parent) = path.parent() {
        ensure_real_dir(root, parent)?;
    }
    write_atomic(&path, bytes)
}

/// The sidecar of record `id` in `root`, if it exists, reads, and its signal file is
/// present with the recorded checksum.
pub fn finished(root: &Path, id: usize, key: &str) -> Option<Sidecar> {
    let text = std::fs::read(root.join(sidecar_rel(id))).ok()?;
    let s: Sidecar = serde_json::from_slice(&text).ok()?;
    if s.dataset_key != key {
        return None;
    }
    let bytes = std::fs::read(root.join(&s.labels.file)).ok()?;
    (sha256_hex(&bytes) == s.signal_sha256).then_some(s)
}

/// Every readable sidecar of `root`, by record id.
pub fn sidecars(root: &Path) -> Vec<Sidecar> {
    let Ok(entries) = std::fs::read_dir(root.join("records")) else {
        return Vec::new();
    };
    let mut out: Vec<Sidecar> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".json"))
        .filter_map(|e| serde_json::from_slice(&std::fs::read(e.path()).ok()?).ok())
        .collect();
    out.sort_by_key(|s| s.labels.record_id);
    out
}

/// Trajectory files of `root`.
pub fn trajectories(root: &Path) -> Vec<TrajectoryFile> {
    let Ok(entries) = std::fs::read_dir(root.join("state")) else {
        return Vec::new();
    };
    let mut out: Vec<TrajectoryFile> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with("trajectory_"))
        .filter_map(|e| serde_json::from_slice(&std::fs::read(e.path()).ok()?).ok())
        .collect();
    out.sort_by(|a, b| a.condition.cmp(&b.condition));
    out
}

/// Why the index and metadata could not be built.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error("{0}")]
    Format(String),
}

/// Stage `index.parquet`, `index.csv` and `metadata.json` of the dataset in `root`
/// (whose records and state files are in place) into `out`. Returns the ids missing
/// from `0..total`.
pub fn stage_index_and_metadata(
    out: &mut OutputDir,
    root: &Path,
    total: usize,
) -> Result<Vec<usize>, BuildError> {
    let body: Value = std::fs::read(root.join(DATASET_REL))
        .ok()
        .and_then(|b| serde_json::from_slice(&b).ok())
        .ok_or_else(|| {
            BuildError::Format(format!(
                "{}: missing or unreadable",
                root.join(DATASET_REL).display()
            ))
        })?;
    let cars = sidecars(root);
    let key = body["dataset_key"].as_str().unwrap_or_default().to_owned();
    let rows: Vec<RecordLabels> = cars
        .into_iter()
        .filter(|s| s.dataset_key == key)
        .map(|s| s.labels)
        .collect();
    let present: std::collections::BTreeSet<usize> = rows.iter().map(|r| r.record_id).collect();
    let missing: Vec<usize> = (0..total).filter(|i| !present.contains(i)).collect();
    let unit = body["record"]["channel_unit"]
        .as_str()
        .unwrap_or("-")
        .to_owned();
    let (cols, units) = index_columns(&rows, &unit);
    let units_json: serde_json::Map<String, Value> =
        units.iter().map(|(n, u)| (n.clone(), json!(u))).collect();
    let meta = vec![(
        "gearwear.units".to_string(),
        Value::Object(units_json.clone()).to_string(),
    )];
    let pq = parquet_bytes(&cols, &meta)
        .map_err(|e| BuildError::Format(format!("index.parquet: {e}")))?;
    out.stage("index.parquet", &pq)?;
    let csv = columns_csv(&cols).map_err(|e| BuildError::Format(format!("index.csv: {e}")))?;
    out.stage("index.csv", &csv)?;
    if let Some(t) = trends(&cols) {
        let table = columns_csv(&trend_columns(&t))
            .map_err(|e| BuildError::Format(format!("indicator_trends.csv: {e}")))?;
        out.stage("indicator_trends.csv", &table)?;
        let fig = trend_figure(&t, &unit);
        let png = render_png(&fig, 900, 1500)
            .map_err(|e| BuildError::Format(format!("indicator_trends.png: {e}")))?;
        out.stage("indicator_trends.png", &png)?;
    }
    let mut metadata = body;
    metadata["index_columns"] = Value::Object(units_json);
    metadata["trajectories"] = json!(trajectories(root)
        .iter()
        .filter(|t| t.dataset_key == key)
        .map(|t| json!({
            "condition": t.condition,
            "failure_cycles": t.trajectory.failure_cycles,
            "end_cycles": t.trajectory.end_cycles,
            "stopped": t.trajectory.stopped,
            "updates": t.trajectory.records.len(),
            "update_cycles": t.trajectory.records.iter().map(|r| r.wear.cycles).collect::<Vec<_>>(),
            "update_max_wear_pinion_um": t.trajectory.records.iter().map(|r| r.wear.max_pinion_m() * 1e6).collect::<Vec<_>>(),
        }))
        .collect::<Vec<_>>());
    metadata["records_present"] = json!(rows.len());
    metadata["records_missing"] = json!(missing);
    out.stage_json("metadata.json", &metadata)?;
    Ok(missing)
}

/// Copy a dataset's record files (signals, CSVs, sidecars) and state files from `from`
/// into `to` (no-op for the same folder). Returns how many records were copied.
pub fn copy_dataset(from: &Path, to: &Path, key: &str) -> Result<usize, OutputError> {
    if same_dir(from, to) {
        return Ok(0);
    }
    let mut n = 0;
    for s in sidecars(from).into_iter().filter(|s| s.dataset_key == key) {
        let id = s.labels.record_id;
        let mut rels = vec![s.labels.file.clone(), sidecar_rel(id)];
        if from.join(csv_rel(id)).exists() {
            rels.insert(1, csv_rel(id));
        }
        for rel in rels {
            let bytes = std::fs::read(from.join(&rel))
                .map_err(|e| OutputError::io("read", &from.join(&rel), &e))?;
            put(to, &rel, &bytes)?;
        }
        n += 1;
    }
    for t in trajectories(from)
        .into_iter()
        .filter(|t| t.dataset_key == key)
    {
        let rel = trajectory_rel(&t.condition);
        let bytes = std::fs::read(from.join(&rel))
            .map_err(|e| OutputError::io("read", &from.join(&rel), &e))?;
        put(to, &rel, &bytes)?;
    }
    let bytes = std::fs::read(from.join(DATASET_REL))
        .map_err(|e| OutputError::io("read", &from.join(DATASET_REL), &e))?;
    put(to, DATASET_REL, &bytes)?;
    Ok(n)
}

fn same_dir(a: &Path, b: &Path) -> bool {
    let canon =
        |p: &Path| -> PathBuf { std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf()) };
    canon(a) == canon(b)
}
