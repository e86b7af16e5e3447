//! The output folder of a command: results are staged, then published as one set with a
//! manifest, so a folder never mixes the files of two runs.
//!
//! - **One writer.** Opening takes the set's lock (`lock.rs`); a second writer of the same
//!   set is refused with the holder named.
//! - **Staging.** Outputs are written into a private staging folder inside `--out`, so a
//!   run that fails (a solver error, a full disk) leaves the previous complete set as it
//!   was.
//! - **Publishing.** The staged files are renamed into place, files that the previous
//!   run of this set listed but this one does not produce are removed, and the manifest
//!   (`manifest.json`, or `STEM.manifest.json` for a named set such as a sweep shard) is
//!   written last, listing every file with its SHA-256. While publishing, a file
//!   `INCOMPLETE` marks the folder; it is removed when the manifest is written, so a
//!   folder interrupted in the middle says so.
//! - **State files** (checkpoints, finished sweep cases) are written at once, atomically,
//!   outside the staging, because an interrupted run resumes from them; the manifest lists
//!   them by name so a later run that does not produce them removes them.
//! - **Orphans.** Staging folders and temporary files left by a killed run are removed
//!   when the set is next opened (under the lock, so they cannot be another writer's).
//! - Nothing is written outside `--out`: every write is an exclusive create or a rename
//!   inside it, and sub-folders that are symbolic links are refused (`atomic.rs`).

use super::atomic::{ensure_real_dir, write_atomic, TEMP_PREFIX};
use super::error::OutputError;
use super::lock::{LockError, OutputLock};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

const STAGING_PREFIX: &str = ".gearwear-staging-";
/// Name of the marker of a folder whose publishing was interrupted.
pub const INCOMPLETE_MARKER: &str = "INCOMPLETE";

/// One published file.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ManifestEntry {
    /// Path relative to the output folder, `/`-separated.
    pub path: String,
    pub sha256: String,
    pub bytes: u64,
}

/// What a published set holds.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Manifest {
    pub program: String,
    pub version: String,
    pub command: String,
    /// Outputs of the run, with their checksums.
    pub files: Vec<ManifestEntry>,
    /// State files the run keeps for resuming (checkpoints, sweep cases), by name.
    #[serde(default)]
    pub state_files: Vec<String>,
}

/// An open output set (see the module docs).
#[derive(Debug)]
pub struct OutputDir {
    root: PathBuf,
    manifest_name: String,
    command: String,
    staging: tempfile::TempDir,
    staged: BTreeSet<String>,
    state: BTreeSet<String>,
    _lock: OutputLock,
}

pub use crate::checksum::sha256_hex;

/// A relative output path must stay inside the folder: no absolute path, no `..`.
fn check_relative(rel: &str) -> Result<(), OutputError> {
    let p = Path::new(rel);
    let ok = !rel.is_empty()
        && p.components()
            .all(|c| matches!(c, std::path::Component::Normal(_)));
    if ok {
        Ok(())
    } else {
        Err(OutputError::new(
            "write",
            p,
            "not a plain path inside the output folder",
            None,
        ))
    }
}

/// Temporary files older than this are orphans even in a folder shared by several sets
/// (a live write finishes within seconds).
const ORPHAN_AGE: std::time::Duration = std::time::Duration::from_secs(600);

/// Remove what a killed run of this set left in `dir`: its staging folders (their names
/// carry the set, `staging_prefix`), and temporary files, all of them when the folder has
/// one set (`shared == false`, and we hold its lock) or only old ones when sets share it.
fn remove_orphans(dir: &Path, staging_prefix: &str, shared: bool) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Ok(ft) = e.file_type() else { continue };
        if name.starts_with(staging_prefix) && ft.is_dir() {
            let _ = std::fs::remove_dir_all(e.path());
        } else if name.starts_with(TEMP_PREFIX) && ft.is_file() {
            let old = e
                .metadata()
                .and_then(|m| m.modified())
                .ok()
                .and_then(|t| t.elapsed().ok())
                .is_some_and(|age| age > ORPHAN_AGE);
            if !shared || old {
                let _ = std::fs::remove_file(e.path());
            }
        } else if ft.is_dir() && name == "cases" {
            remove_orphans(&e.path(), staging_prefix, shared);
        }
    }
}

impl OutputDir {
    /// Open `root` for the output set `set` (`None`: the folder's one set, manifest
    /// `manifest.json`; `Some(stem)`: `STEM.manifest.json`, so that several sets, such as
    /// sweep shards, can share a folder) of `command`.
    pub fn open(root: &Path, set: Option<&str>, command: &str) -> Result<Self, LockError> {
        ensure_real_dir(root, root)?;
        let (lock_name, manifest_name) = match set {
            None => (".gearwear.lock".to_owned(), "manifest.json".to_owned()),
            Some(s) => (format!(".{s}.lock"), format!("{s}.manifest.json")),
        };
        let lock = OutputLock::acquire(&root.join(lock_name), command)?;
        let staging_prefix = format!("{STAGING_PREFIX}{}-", set.unwrap_or("set"));
        remove_orphans(root, &staging_prefix, set.is_some());
        let staging = tempfile::Builder::new()
            .prefix(&staging_prefix)
            .tempdir_in(root)
            .map_err(|e| OutputError::io("create a staging folder in", root, &e))?;
        Ok(Self {
            root: root.to_path_buf(),
            manifest_name,
            command: command.to_owned(),
            staging,
            staged: BTreeSet::new(),
            state: BTreeSet::new(),
            _lock: lock,
        })
    }

    /// The output folder.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// The command whose set this is.
    pub fn command(&self) -> &str {
        &self.command
    }

    /// Stage an output file `rel` (relative path, `/`-separated) with `bytes`.
    pub fn stage(&mut self, rel: &str, bytes: &[u8]) -> Result<(), OutputError> {
        check_relative(rel)?;
        let dst = self.staging.path().join(rel);
        if let Some(parent) = dst.parent() {
            std::fs::create_dir_all(parent)
                .map_err(|e| OutputError::io("create the folder", parent, &e))?;
        }
        std::fs::write(&dst, bytes).map_err(|e| OutputError::io("write", &dst, &e))?;
        self.staged.insert(rel.to_owned());
        Ok(())
    }

    /// Stage `value` as pretty JSON at `rel`.
    pub fn stage_json(&mut self, rel: &str, value: &serde_json::Value) -> Result<(), OutputError> {
        let text = serde_json::to_string_pretty(value)
            .map_err(|e| OutputError::new("write", Path::new(rel), e.to_string(), None))?;
        self.stage(rel, text.as_bytes())
    }

    /// Write a state file `rel` now, atomically, and list it in the manifest.
    pub fn write_state(&mut self, rel: &str, bytes: &[u8]) -> Result<(), OutputError> {
        check_relative(rel)?;
        let path = self.root.join(rel);
        if let Some(parent) = path.parent() {
            ensure_real_dir(&self.root, parent)?;
        }
        write_atomic(&path, bytes)?;
        self.state.insert(rel.to_owned());
        Ok(())
    }

    /// The path of state file `rel` inside the folder (its folders created, checked to be
    /// real folders), listed in the manifest; the caller writes it (e.g. an append-only
    /// checkpoint).
    pub fn state_path(&mut self, rel: &str) -> Result<PathBuf, OutputError> {
        check_relative(rel)?;
        let path = self.root.join(rel);
        if let Some(parent) = path.parent() {
            ensure_real_dir(&self.root, parent)?;
        }
        self.state.insert(rel.to_owned());
        Ok(path)
    }

    /// Declare a state file that exists already (e.g. a finished sweep case kept from an
    /// earlier run) as part of this set.
    pub fn keep_state(&mut self, rel: &str) {
        self.state.insert(rel.to_owned());
    }

    /// The manifest of the set as last published in this folder, if any.
    pub fn previous_manifest(&self) -> Option<Manifest> {
        let text = std::fs::read_to_string(self.root.join(&self.manifest_name)).ok()?;
        serde_json::from_str(&text).ok()
    }

    /// Publish the staged files as the folder's new set; returns its manifest.
    pub fn publish(self) -> Result<Manifest, OutputError> {
        let previous = self.previous_manifest();
        let marker = self.root.join(INCOMPLETE_MARKER);
        write_atomic(
            &marker,
            format!(
                "gearwear {} was interrupted while publishing its results into this folder: \
                 the files here may belong to different runs. Run the command again.\n",
                self.command
            )
            .as_bytes(),
        )?;
        let mut files = Vec::with_capacity(self.staged.len());
        for rel in &self.staged {
            let src = self.staging.path().join(rel);
            let dst = self.root.join(rel);
            let bytes = std::fs::read(&src).map_err(|e| OutputError::io("read", &src, &e))?;
            std::fs::File::open(&src)
                .and_then(|f| f.sync_all())
                .map_err(|e| OutputError::io("write", &src, &e))?;
            if let Some(parent) = dst.parent() {
                ensure_real_dir(&self.root, parent)?;
            }
            std::fs::rename(&src, &dst).map_err(|e| OutputError::io("write", &dst, &e))?;
            files.push(ManifestEntry {
                path: rel.clone(),
                sha256: sha256_hex(&bytes),
                bytes: bytes.len() as u64,
            });
        }
        if let Some(prev) = previous {
            let now: BTreeSet<&str> = self
                .staged
                .iter()
                .chain(self.state.iter())
                .map(String::as_str)
                .collect();
            let old = prev
                .files
                .iter()
                .map(|f| f.path.as_str())
                .chain(prev.state_files.iter().map(String::as_str));
            for rel in old.filter(|r| !now.contains(r) && check_relative(r).is_ok()) {
                let _ = std::fs::remove_file(self.root.join(rel));
            }
        }
        let manifest = Manifest {
            program: "gearwear".into(),
            version: env!("CARGO_PKG_VERSION").into(),
            command: self.command.clone(),
            files,
            state_files: self.state.iter().cloned().collect(),
        };
        let text = serde_json::to_string_pretty(&manifest).map_err(|e| {
            OutputError::new(
                "write",
                &self.root.join(&self.manifest_name),
                e.to_string(),
                None,
            )
        })?;
        write_atomic(&self.root.join(&self.manifest_name), text.as_bytes())?;
        std::fs::remove_file(&marker).map_err(|e| OutputError::io("remove", &marker, &e))?;
        Ok(manifest)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    fn names(dir: &Path) -> BTreeSet<String> {
        fs::read_dir(dir)
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| !n.starts_with(".gearwear"))
            .collect()
    }

    #[test]
    fn a_rerun_removes_what_it_no_longer_produces() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "wear").unwrap();
        o.stage("a.csv", b"1").unwrap();
        o.stage("b.csv", b"2").unwrap();
        o.write_state("checkpoint_b.json", b"{}").unwrap();
        o.publish().unwrap();
        fs::write(d.path().join("user_notes.txt"), b"mine").unwrap();
        let mut o = OutputDir::open(d.path(), None, "wear").unwrap();
        o.stage("a.csv", b"3").unwrap();
        let m = o.publish().unwrap();
        let expect: BTreeSet<String> = ["a.csv", "manifest.json", "user_notes.txt"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        assert_eq!(names(d.path()), expect);
        assert_eq!(fs::read(d.path().join("a.csv")).unwrap(), b"3");
        assert_eq!(m.files[0].sha256, sha256_hex(b"3"));
    }

    #[test]
    fn a_failed_run_leaves_the_previous_set() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "run").unwrap();
        o.stage("summary.json", b"30 Hz").unwrap();
        o.stage("report.html", b"30 Hz").unwrap();
        o.publish().unwrap();
        {
            let mut o = OutputDir::open(d.path(), None, "run").unwrap();
            o.stage("summary.json", b"40 Hz").unwrap();
            // ... the run fails here: the set is dropped unpublished.
        }
        assert_eq!(fs::read(d.path().join("summary.json")).unwrap(), b"30 Hz");
        let left: Vec<_> = fs::read_dir(d.path())
            .unwrap()
            .flatten()
            .filter(|e| e.file_name().to_string_lossy().starts_with(STAGING_PREFIX))
            .collect();
        assert!(left.is_empty(), "staging folder left behind");
    }

    #[test]
    fn orphans_of_a_killed_run_are_removed() {
        let d = tempfile::tempdir().unwrap();
        fs::create_dir(d.path().join(format!("{STAGING_PREFIX}set-x"))).unwrap();
        fs::write(d.path().join(format!("{TEMP_PREFIX}y")), b"half").unwrap();
        let o = OutputDir::open(d.path(), None, "x").unwrap();
        drop(o);
        assert!(names(d.path()).is_empty(), "{:?}", names(d.path()));
    }

    #[test]
    fn paths_that_leave_the_folder_are_refused() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "x").unwrap();
        assert!(o.stage("../escape.txt", b"x").is_err());
        assert!(o.stage("/etc/passwd", b"x").is_err());
        assert!(o.write_state("a/../../b", b"x").is_err());
    }

    #[test]
    fn named_sets_share_a_folder() {
        let d = tempfile::tempdir().unwrap();
        let mut a = OutputDir::open(d.path(), Some("sweep_shard_1_of_2"), "sweep").unwrap();
        let mut b = OutputDir::open(d.path(), Some("sweep_shard_2_of_2"), "sweep").unwrap();
        a.stage("sweep_shard_1_of_2.csv", b"a").unwrap();
        b.stage("sweep_shard_2_of_2.csv", b"b").unwrap();
        a.publish().unwrap();
        b.publish().unwrap();
        assert!(d.path().join("sweep_shard_1_of_2.manifest.json").exists());
        assert!(d.path().join("sweep_shard_2_of_2.csv").exists());
        assert!(OutputDir::open(d.path(), Some("sweep_shard_1_of_2"), "sweep").is_ok());
    }
}
