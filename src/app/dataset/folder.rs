//! The files of a dataset folder (docs/SIGNALS.md, "Dataset layout"):
//!
//! - `signals/<id>.parquet`: one record (accelerometers and tachometer, float32);
//! - `csv/<id>.csv`: the same record as PHM 2009-style CSV, when the design asks;
//! - `records/<id>.json`: the record's labels and indicators, the dataset key and the
//!   SHA-256 of its signal file (written last: a record is finished when this exists);
//! - `state/dataset.json`: the dataset's description (design, cases, chain, axes);
//! - `state/trajectory_<condition>.json`: the condition's run-to-failure trajectory;
//! - `indicator_trends.csv`, `indicator_trends.png` (and/or `.svg`, as the job asks): the
//!   condition indicators along each trajectory (`study::dataset::trends`);
//! - `index.parquet`, `index.csv`: one row per record; `metadata.json`: everything
//!   needed to read and reproduce the dataset. Built from the files above, by the same
//!   code for an unsharded run and a merge, so the two are byte for byte equal.

use crate::checksum::sha256_hex;
use crate::io::columns_csv::columns_csv;
use crate::io::dir::Dir;
use crate::io::parquet::{parquet_bytes, Column};
use crate::io::set_state::{check_replaceable, read_all, Ours, SetState};
use crate::io::{OutputDir, OutputError};
use crate::report::artifacts::{stage_figures, FigureFile};
use crate::report::dataset_trends::trend_figure;
use crate::report::figure_output::FigureOutput;
use crate::study::dataset::index::{column_meaning, index_columns};
use crate::study::dataset::records::signal_file;
use crate::study::dataset::trajectory::Trajectory;
use crate::study::dataset::trends::{trend_columns, trends};
use crate::study::dataset::RecordLabels;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::collections::BTreeMap;
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

/// Largest file of a dataset folder read back (a record's signal file, a trajectory):
/// far above a record of the longest valid length.
pub const MAX_DATASET_FILE_BYTES: u64 = 1 << 30;

/// Largest sidecar (`records/<id>.json`) read back: its labels (two lists of per-tooth
/// wear, 25 bytes a tooth) and each channel's indicators (about 1.5 kB of pretty JSON a
/// channel): 32 MiB holds 20,000 channels. Parsing a sidecar takes a few times its size
/// (a 650 MB one took 2.9 GB), so a cap near the signal files' aborted a resume.
pub const MAX_SIDECAR_BYTES: u64 = 32 << 20;

/// Largest description (`state/dataset.json`) read back: the design (at most 16 MiB, as
/// read) and each condition's case.
pub const MAX_DESCRIPTION_BYTES: u64 = 64 << 20;

/// The read cap of the dataset file at `rel` (one of the caps above).
fn cap_of(rel: &str) -> u64 {
    if rel.starts_with("records/") {
        MAX_SIDECAR_BYTES
    } else if rel == DATASET_REL {
        MAX_DESCRIPTION_BYTES
    } else {
        MAX_DATASET_FILE_BYTES
    }
}

/// Whether the first bytes of a file are one of a dataset's own files (a Parquet record,
/// a record's CSV, a sidecar, trajectory or description), so `put` may replace it: a
/// file of a killed run is rewritten, anything else at that name is left alone.
fn is_dataset_file(b: &[u8]) -> bool {
    let json = || {
        let t = String::from_utf8_lossy(b);
        t.starts_with('{') && (t.contains("\"dataset_key\"") || t.contains("\"axes\""))
    };
    b.starts_with(b"PAR1") || b.starts_with(b"time_s,") || json()
}

/// Write `bytes` at `rel` inside `root`: a new file renamed into place, every folder on the
/// way opened relative to `root` without following a link (`io::dir`). What `rel` held
/// must be a dataset file: one the folder's set recorded (`prev`, even if damaged since),
/// or one in a dataset file's format; a user's file, a link or a hard link there is
/// refused.
pub fn put(root: &Path, rel: &str, bytes: &[u8], prev: &SetState) -> Result<(), OutputError> {
    let top = Dir::open_root(root)?;
    let (dir, name) = top.descend(rel, true)?;
    check_replaceable(
        &dir,
        &name,
        Ours::Format(prev.state_file(rel), is_dataset_file),
    )?;
    dir.write_new(&dir, &name, bytes)?;
    Ok(())
}

/// What `put` would refuse among the names `rels` of `root` (a link, a FIFO, a hard link,
/// a user's file at a dataset file's name, or a link at its sub-folder), checked without
/// writing anything (`prev`: the set's record, read without opening the folder), so that a
/// run refuses them before it opens the folder or does any work (exit code 2): at most
/// ten messages, then how many more.
pub fn refused_names(
    root: &Path,
    rels: impl IntoIterator<Item = String>,
    prev: Option<&SetState>,
) -> Vec<String> {
    const SHOWN: usize = 10;
    let Ok(top) = Dir::open_root(root) else {
        return Vec::new(); // no folder yet: nothing in it to refuse
    };
    let mut dirs: BTreeMap<String, Option<Dir>> = BTreeMap::new();
    let (mut out, mut more) = (Vec::new(), 0usize);
    let mut refuse = |m: String, out: &mut Vec<String>| {
        if out.len() < SHOWN {
            out.push(m);
        } else {
            more += 1;
        }
    };
    for rel in rels {
        let (folder, name) = rel.rsplit_once('/').unwrap_or(("", rel.as_str()));
        let dir = dirs.entry(folder.to_owned()).or_insert_with(|| {
            let d = if folder.is_empty() {
                top.try_clone()
            } else {
                top.sub(folder, false)
            };
            match d {
                Ok(d) => Some(d),
                // A sub-folder not made yet holds nothing to refuse.
                Err(_) if absent_in(root, folder) => None,
                Err(e) => {
                    refuse(e.to_string(), &mut out);
                    None
                }
            }
        });
        if let Some(dir) = dir {
            let ours = Ours::Format(prev.and_then(|p| p.state_file(&rel)), is_dataset_file);
            if let Err(e) = check_replaceable(dir, name, ours) {
                refuse(e.to_string(), &mut out);
            }
        }
    }
    if more > 0 {
        out.push(format!("and {more} more names like these"));
    }
    out
}

/// Create the sub-folder `folder` of `root` (never through a link).
pub fn make_folder(root: &Path, folder: &str) -> Result<(), OutputError> {
    Dir::open_root(root)?.sub(folder, true).map(|_| ())
}

/// The bytes of `rel` in `root`, read without following a link or blocking, only from a
/// regular single-link file of at most its cap ([`cap_of`]: a sidecar, the description,
/// any other file); None otherwise (a missing, foreign, oversized or unreadable file
/// counts as absent: the record is recomputed).
pub fn read_in(root: &Path, rel: &str) -> Option<Vec<u8>> {
    let cap = cap_of(rel);
    let top = Dir::open_root(root).ok()?;
    let (dir, name) = top.descend(rel, false).ok()?;
    let (f, e) = dir.open_existing(&name, false).ok()??;
    if e.bytes > cap {
        return None;
    }
    read_all(f, cap).ok()
}

/// Whether `rel` in `root` is a regular single-link file (no link followed).
pub fn is_file_in(root: &Path, rel: &str) -> bool {
    use crate::io::dir::Kind;
    let entry = Dir::open_root(root)
        .and_then(|top| top.descend(rel, false))
        .and_then(|(dir, name)| dir.entry(&name));
    matches!(entry, Ok(Some(e)) if e.kind == Kind::File && e.links == 1)
}

/// Names in the sub-folder `folder` of `root` (not through a link).
fn names_in(root: &Path, folder: &str) -> Vec<String> {
    Dir::open_root(root)
        .and_then(|d| d.sub(folder, false))
        .and_then(|d| d.names())
        .unwrap_or_default()
}

/// A sidecar is only trusted for the files of its own record id: a sidecar naming another
/// file (edited or planted) is ignored.
fn own_files(s: &Sidecar) -> bool {
    s.labels.file == signal_file(s.labels.record_id)
}

/// A sidecar's bytes as a resume ([`finished`]) and a merge or index ([`sidecars`]) read
/// them: a [`Sidecar`] in JSON that names its own record's signal file; `None` for
/// anything else (not JSON, another shape, a file of another record). Public for the fuzz
/// target `fuzz/fuzz_targets/dataset_sidecar.rs` (docs/RELIABILITY.md).
pub fn parse_sidecar(bytes: &[u8]) -> Option<Sidecar> {
    serde_json::from_slice(bytes).ok().filter(own_files)
}

/// The sidecar of record `id` in `root`, if it exists, reads, and its signal file is
/// present with the recorded checksum.
pub fn finished(root: &Path, id: usize, key: &str) -> Option<Sidecar> {
    let s = parse_sidecar(&read_in(root, &sidecar_rel(id))?)?;
    if s.dataset_key != key || s.labels.record_id != id {
        return None;
    }
    let bytes = read_in(root, &s.labels.file)?;
    (sha256_hex(&bytes) == s.signal_sha256).then_some(s)
}

/// Every readable sidecar of `root`, by record id.
pub fn sidecars(root: &Path) -> Vec<Sidecar> {
    let mut out: Vec<Sidecar> = names_in(root, "records")
        .into_iter()
        .filter(|n| n.ends_with(".json"))
        .filter_map(|n| {
            let s = parse_sidecar(&read_in(root, &format!("records/{n}"))?)?;
            // Only under its own name (and naming its own signal file: `parse_sidecar`).
            (sidecar_rel(s.labels.record_id) == format!("records/{n}")).then_some(s)
        })
        .collect();
    out.sort_by_key(|s| s.labels.record_id);
    out
}

/// Trajectory files of `root`.
pub fn trajectories(root: &Path) -> Vec<TrajectoryFile> {
    let mut out: Vec<TrajectoryFile> = names_in(root, "state")
        .into_iter()
        .filter(|n| n.starts_with("trajectory_"))
        .filter_map(|n| serde_json::from_slice(&read_in(root, &format!("state/{n}"))?).ok())
        .filter(|t: &TrajectoryFile| check_name_only(&t.condition))
        .collect();
    out.sort_by(|a, b| a.condition.cmp(&b.condition));
    out
}

/// A condition name that makes a plain file name (`trajectory_<condition>.json`).
fn check_name_only(condition: &str) -> bool {
    !condition.is_empty() && !condition.contains(['/', '\\']) && condition != ".."
}

/// The dataset key of the dataset already in `root` (its `state/dataset.json`):
/// `Ok(None)` when the folder holds none, `Err` when the description is there but
/// unreadable (damaged, foreign, too large): a folder belongs to the design that made it.
pub fn existing_key(root: &Path) -> Result<Option<String>, String> {
    let Some(bytes) = read_in(root, DATASET_REL) else {
        return if is_file_in(root, DATASET_REL) || !absent_in(root, DATASET_REL) {
            Err(format!(
                "{}: unreadable (a link, a hard link, too large, or not a file)",
                root.join(DATASET_REL).display()
            ))
        } else {
            Ok(None)
        };
    };
    described_key(&bytes, &root.join(DATASET_REL)).map(Some)
}

/// The dataset key named by a description's bytes (`state/dataset.json`, at `described`
/// for the messages): `Err` when they are not a JSON object with a `dataset_key` string.
/// Public for the fuzz target `dataset_shard` (docs/RELIABILITY.md).
pub fn described_key(bytes: &[u8], described: &Path) -> Result<String, String> {
    let body: Value = serde_json::from_slice(bytes)
        .map_err(|_| format!("{}: not a dataset description", described.display()))?;
    body["dataset_key"]
        .as_str()
        .map(str::to_owned)
        .ok_or_else(|| format!("{}: no dataset key", described.display()))
}

/// The first 12 characters of a dataset key, as messages show it (a key read from a
/// damaged or foreign description may hold any characters: cut at a character, never
/// inside one).
pub(crate) fn key_shown(key: &str) -> String {
    key.chars().take(12).collect()
}

/// Whether nothing (no file, folder or link) is at `rel` in `root` (no link followed).
fn absent_in(root: &Path, rel: &str) -> bool {
    match Dir::open_root(root).and_then(|top| top.descend(rel, false)) {
        Ok((dir, name)) => matches!(dir.entry(&name), Ok(None)),
        Err(_) => !root.join(rel).exists() && root.join(rel).symlink_metadata().is_err(),
    }
}

/// Refuse to put a dataset of key `key` into `root` when `root` already holds another
/// design's (unless `replace`): the message names the folder and both keys. Checked
/// before the folder is opened, so nothing in it changes.
pub fn check_owner(root: &Path, key: &str, replace: bool) -> Result<(), String> {
    if replace {
        return Ok(());
    }
    match existing_key(root)? {
        Some(k) => owner_problem(root, &k, key),
        None => Ok(()),
    }
}

/// The refusal of a dataset of key `key` in the folder `root` whose description names
/// the key `existing` (any text: read from the folder), when the two differ. Public for
/// the fuzz target `dataset_shard`.
pub fn owner_problem(root: &Path, existing: &str, key: &str) -> Result<(), String> {
    if existing == key {
        return Ok(());
    }
    Err(format!(
        "{}: the folder holds a dataset of another design (dataset key {}..., this design's {}...): a dataset folder belongs to the design that made it",
        root.display(),
        key_shown(existing),
        key_shown(key)
    ))
}

/// Why the index and metadata could not be built.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error("{0}")]
    Format(String),
}

/// Most missing record ids listed in `metadata.json` (`records_missing`; the count is
/// `records_missing_count`).
pub const MAX_MISSING_LISTED: usize = 1000;

/// Records missing from a dataset's index: how many, and the first ids.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Missing {
    pub count: usize,
    /// The first [`MAX_MISSING_LISTED`] missing ids, ascending.
    pub listed: Vec<usize>,
}

/// The index of a dataset (`index.parquet`, `index.csv`) as a run or a merge writes it.
pub struct IndexTables {
    /// Records indexed, and those missing from `0..total`.
    pub present: usize,
    pub missing: Missing,
    /// The index columns and each column's unit.
    pub columns: Vec<Column>,
    pub units: Vec<(String, String)>,
    /// The channels' unit (the description's `record.channel_unit`).
    pub channel_unit: String,
    pub parquet: Vec<u8>,
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
        .map(|t| json!({
            "condition": t.condition,
            "failure_cycles": t.trajectory.failure_cycles,
            "end_cycles": t.trajectory.end_cycles,
            "stopped": t.trajectory.stopped,
            "updates": t.trajectory.records.len(),
            "update_cycles": t.trajectory.records.iter().map(|r| r.wear.cycles).collect::<Vec<_>>(),
            "update_max_wear_pinion_um": t.trajectory.records.iter().map(|r| r.wear.max_pinion_m() * 1e6).collect::<Vec<_>>(),
        }))
        .collect::<Vec<_>>())
}

/// Whether record labels `l` are those the design described by `body` (the
/// description, `state/dataset.json`) gives its id: condition (name, fault, severity),
/// trajectory state, speed, load, realisation and noise seed, all recomputed from the id,
/// and its indicators' channels the description's sensors.
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

/// Copy a dataset's record files (signals, CSVs, sidecars) and state files from `from`
/// into `to` (no-op for the same folder). Returns how many records were copied, and the
/// records left out (a signal file missing or not the one its sidecar names: counted
/// missing by the index, named here).
pub fn copy_dataset(
    from: &Path,
    to: &Path,
    key: &str,
    prev: &SetState,
) -> Result<(usize, Vec<String>), OutputError> {
    if same_dir(from, to) {
        return Ok((0, Vec::new()));
    }
    // Read as the folder's own files are: no link followed, regular files of bounded size.
    let read = |rel: &str| {
        read_in(from, rel).ok_or_else(|| {
            OutputError::new(
                "read",
                &from.join(rel),
                "missing, not a regular single-link file, or too large",
                None,
            )
        })
    };
    let (mut n, mut skipped) = (0, Vec::new());
    for s in sidecars(from).into_iter().filter(|s| s.dataset_key == key) {
        let id = s.labels.record_id;
        let signal = read_in(from, &s.labels.file).filter(|b| sha256_hex(b) == s.signal_sha256);
        let car = read_in(from, &sidecar_rel(id));
        let (Some(signal), Some(car)) = (signal, car) else {
            skipped.push(format!(
                "record {id} of {}: its signal file is missing or not the one its sidecar names: left out (counted missing)",
                from.display()
            ));
            continue;
        };
        put(to, &s.labels.file, &signal, prev)?;
        if let Some(csv) = read_in(from, &csv_rel(id)) {
            put(to, &csv_rel(id), &csv, prev)?;
        }
        put(to, &sidecar_rel(id), &car, prev)?;
        n += 1;
    }
    for t in trajectories(from)
        .into_iter()
        .filter(|t| t.dataset_key == key)
    {
        let rel = trajectory_rel(&t.condition);
        put(to, &rel, &read(&rel)?, prev)?;
    }
    put(to, DATASET_REL, &read(DATASET_REL)?, prev)?;
    Ok((n, skipped))
}

/// The names [`copy_dataset`] would write from `from` into another folder (`key`: the
/// dataset's): each record's signal, CSV twin (where `from` has one) and sidecar, each
/// trajectory and the description; none when `from` is the target `to` itself. For
/// [`refused_names`] before a merge opens its folder.
pub fn copied_names(from: &Path, to: &Path, key: &str) -> Vec<String> {
    if same_dir(from, to) {
        return Vec::new();
    }
    let mut names = Vec::new();
    for s in sidecars(from).into_iter().filter(|s| s.dataset_key == key) {
        let id = s.labels.record_id;
        names.push(s.labels.file.clone());
        if is_file_in(from, &csv_rel(id)) {
            names.push(csv_rel(id));
        }
        names.push(sidecar_rel(id));
    }
    let own = trajectories(from)
        .into_iter()
        .filter(|t| t.dataset_key == key);
    names.extend(own.map(|t| trajectory_rel(&t.condition)));
    names.push(DATASET_REL.to_owned());
    names
}

fn same_dir(a: &Path, b: &Path) -> bool {
    let canon =
        |p: &Path| -> PathBuf { std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf()) };
    canon(a) == canon(b)
}
