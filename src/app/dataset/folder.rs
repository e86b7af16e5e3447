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
//!   code for an unsharded run and a merge, so the two are byte for byte equal
//!   (`index_files`).

use crate::checksum::sha256_hex;
use crate::io::dir::Dir;
use crate::io::set_state::{check_replaceable, read_all, Ours, SetState};
use crate::io::OutputError;
use crate::study::dataset::records::signal_file;
use crate::study::dataset::trajectory::Trajectory;
use crate::study::dataset::RecordLabels;
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A finished record's sidecar (`records/<id>.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sidecar {
    /// Hash of everything the dataset was generated from (design, cases, transfer path,
    /// program version): a record is reused only under the same key.
    pub dataset_key: String,
    /// SHA-256 (hex) of the record's signal file: a record whose file no longer matches is
    /// computed again.
    pub signal_sha256: String,
    /// The record's labels (its row of the index).
    pub labels: RecordLabels,
}

/// A trajectory as kept in `state/`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct TrajectoryFile {
    pub dataset_key: String,
    pub condition: String,
    pub trajectory: Trajectory,
}

pub(crate) fn sidecar_rel(id: usize) -> String {
    format!("records/{id:07}.json")
}

pub(crate) fn csv_rel(id: usize) -> String {
    format!("csv/{id:07}.csv")
}

pub(crate) fn trajectory_rel(condition: &str) -> String {
    format!("state/trajectory_{condition}.json")
}

use crate::study::budget::KeptRecords;

pub(crate) const DATASET_REL: &str = "state/dataset.json";

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
/// regular single-link file of at most its cap (`cap_of`: a sidecar, the description,
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
    // Reading never creates: `Dir::open_root` makes a missing root, and a job's budget
    // counts what a folder holds before it may create it.
    if !root.is_dir() {
        return Vec::new();
    }
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

/// The sidecar of record `id` in `root` as it reads (at most [`MAX_SIDECAR_BYTES`]), if it
/// parses and names its own record.
pub fn sidecar_at(root: &Path, id: usize) -> Option<Sidecar> {
    let s = parse_sidecar(&read_in(root, &sidecar_rel(id))?)?;
    (s.labels.record_id == id).then_some(s)
}

/// Record ids of the sidecars `root` holds, from their names alone (`records/<id>.json`
/// as `sidecar_rel` names them): nothing is read, so a budget can count a folder
/// before any sidecar is parsed (issue 33). A bound of what a reading finds: a foreign,
/// unreadable or oversized sidecar is among them.
pub fn sidecar_ids(root: &Path) -> Vec<usize> {
    names_in(root, "records")
        .into_iter()
        .filter_map(|n| {
            let id: usize = n.strip_suffix(".json")?.parse().ok()?;
            (sidecar_rel(id) == format!("records/{n}")).then_some(id)
        })
        .collect()
}

/// The records and physical states of design `d` that `root` holds by the names of its
/// sidecars ([`sidecar_ids`]; ids beyond the design's records left out): at least what a
/// check of the folder reads back, counted before any of them is read.
pub fn kept_by_names(root: &Path, d: &crate::study::dataset::DatasetDesign) -> KeptRecords {
    let plan = crate::study::dataset::plan::plan_of(d);
    let r = plan.realisations.max(1);
    let ids: Vec<usize> = sidecar_ids(root)
        .into_iter()
        .filter(|id| *id < plan.records())
        .collect();
    let states: std::collections::BTreeSet<usize> = ids.iter().map(|id| id / r).collect();
    KeptRecords {
        records: ids.len() as f64,
        states: states.len() as f64,
    }
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
pub(crate) fn trajectories(root: &Path) -> Vec<TrajectoryFile> {
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
pub fn existing_key(root: &Path) -> Result<Option<String>, FolderError> {
    let Some(bytes) = read_in(root, DATASET_REL) else {
        return if is_file_in(root, DATASET_REL) || !absent_in(root, DATASET_REL) {
            Err(FolderError::Unreadable(root.join(DATASET_REL)))
        } else {
            Ok(None)
        };
    };
    described_key(&bytes, &root.join(DATASET_REL)).map(Some)
}

/// Why a dataset folder's description cannot be used, or why the folder belongs to
/// another design (each message names the file or folder).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FolderError {
    /// The description is there but cannot be read safely.
    #[error("{}: unreadable (a link, a hard link, too large, or not a file)", .0.display())]
    Unreadable(PathBuf),
    /// The description is not JSON.
    #[error("{}: not a dataset description", .0.display())]
    NotDescription(PathBuf),
    /// The description names no dataset key.
    #[error("{}: no dataset key", .0.display())]
    NoKey(PathBuf),
    /// The folder holds a dataset of another design.
    #[error("{}: the folder holds a dataset of another design (dataset key {}..., this design's {}...): a dataset folder belongs to the design that made it", .root.display(), key_shown(.existing), key_shown(.key))]
    AnotherDesign {
        /// The dataset folder.
        root: PathBuf,
        /// The key its description names (any text: read from the folder).
        existing: String,
        /// The key of the design that would write into it.
        key: String,
    },
}

/// The dataset key named by a description's bytes (`state/dataset.json`, at `described`
/// for the messages): `Err` when they are not a JSON object with a `dataset_key` string.
/// Public for the fuzz target `dataset_shard` (docs/RELIABILITY.md).
pub fn described_key(bytes: &[u8], described: &Path) -> Result<String, FolderError> {
    let body: Value = serde_json::from_slice(bytes)
        .map_err(|_| FolderError::NotDescription(described.to_owned()))?;
    body["dataset_key"]
        .as_str()
        .map(str::to_owned)
        .ok_or_else(|| FolderError::NoKey(described.to_owned()))
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
pub fn check_owner(root: &Path, key: &str, replace: bool) -> Result<(), FolderError> {
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
pub fn owner_problem(root: &Path, existing: &str, key: &str) -> Result<(), FolderError> {
    if existing == key {
        return Ok(());
    }
    Err(FolderError::AnotherDesign {
        root: root.to_owned(),
        existing: existing.to_owned(),
        key: key.to_owned(),
    })
}

/// Copy a dataset's record files (signals, CSVs, sidecars) and state files from `from`
/// into `to` (no-op for the same folder). Returns how many records were copied, and the
/// records left out (a signal file missing or not the one its sidecar names, or a file in
/// `records/` that does not read as a record's sidecar: over its cap, not JSON, under
/// another record's name; counted missing by the index, named here).
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
    let cars = sidecars(from);
    // A sidecar file that does not read as a record's (over its cap, not JSON, under
    // another record's name): its record is left out and named, not lost unnamed.
    let readable: std::collections::HashSet<String> = cars
        .iter()
        .map(|s| sidecar_rel(s.labels.record_id))
        .collect();
    let mut skipped: Vec<String> = names_in(from, "records")
        .into_iter()
        .filter(|n| n.ends_with(".json") && !readable.contains(&format!("records/{n}")))
        .map(|n| {
            format!(
                "records/{} of {}: not a readable sidecar (over {} MiB, not a record's labels, or under another record's name): its record is left out (counted missing)",
                crate::format::clip(&n, crate::format::SHOWN_CHARS),
                from.display(),
                MAX_SIDECAR_BYTES >> 20
            )
        })
        .collect();
    let mut n = 0;
    for s in cars.into_iter().filter(|s| s.dataset_key == key) {
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
