//! The output folder of a command: results are staged, then published as one set, so a
//! folder never mixes the files of two runs, and gearwear never deletes, truncates or
//! follows anything it did not create itself in the folder.
//!
//! - **One writer.** Opening takes the set's lock (`lock.rs`); a second writer of the same
//!   set is refused with the holder named.
//! - **Its own record.** The set's state file (`set_state.rs`) lists what gearwear wrote
//!   here, with each file's identity. Only a file still exactly as recorded is replaced or
//!   removed; a name holding anything else (a user's file, a link, a hard link, a file
//!   edited since) is left alone and the run says so. A folder holding another command's
//!   set is refused unless replacing it is allowed.
//! - **Staging.** Outputs are written into a private staging folder inside the output
//!   folder, so a run that fails (a solver error, a full disk) leaves the previous
//!   complete set as it was.
//! - **Publishing.** Every target name is checked first; then the staged files are renamed
//!   into place, the files of the previous set that this one does not produce are removed
//!   (if still as recorded), and `manifest.json` (or `STEM.manifest.json`) and the state
//!   file are written. While publishing, a file `INCOMPLETE` marks the folder, so a folder
//!   interrupted in the middle says so. If a target name holds something gearwear may not
//!   replace, nothing is published and the staged results are kept in a visible folder.
//! - **State files** (checkpoints, finished sweep cases) are written at once (a new file
//!   renamed into place), because an interrupted run resumes from them.
//! - **Orphans.** The staging folder of a killed run is recorded in the state file and
//!   removed when the set is next opened (only if it is still the folder recorded).
//! - Every operation is relative to an open folder handle (`dir.rs`): no link is followed
//!   below the folder the user named, no file is truncated, no FIFO is opened blocking.

use super::dir::{remove_tree, Dir, Entry};
use super::error::OutputError;
use super::lock::{LockError, OutputLock};
use super::set_state::{
    check_replaceable, is_recorded_output, read_all, read_state, Ours, PlaceRecord, Recognise,
    SetState,
};
use std::collections::{BTreeMap, BTreeSet};
use std::fs::File;
use std::path::{Path, PathBuf};

mod publish;

pub use publish::{Manifest, ManifestEntry, INCOMPLETE_MARKER, UNPUBLISHED_PREFIX};

const STAGING_PREFIX: &str = ".gearwear-staging-";
/// The record of the folder's (unnamed) output set; `.SET.gearwear-state.json` for a named one.
const STATE_NAME: &str = ".gearwear-state.json";
/// Whether a folder holding another command's set may be replaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OtherSet {
    /// Refuse it (the default).
    #[default]
    Refuse,
    /// Replace it (the user asked to).
    Replace,
}

struct Staged {
    entry: Entry,
    sha256: String,
    bytes: u64,
}

/// An open output set (see the module docs).
pub struct OutputDir {
    root: Dir,
    manifest_name: String,
    state_name: String,
    command: String,
    staging: Dir,
    staging_name: String,
    staged: BTreeMap<String, Staged>,
    state: BTreeSet<String>,
    at_publish: Vec<(String, String, Recognise)>,
    previous: SetState,
    published: bool,
    _lock: OutputLock,
}

impl std::fmt::Debug for OutputDir {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "OutputDir({})", self.root.path().display())
    }
}

pub use crate::checksum::sha256_hex;

/// A relative output path must stay inside the folder: plain names separated by `/`.
fn check_relative(rel: &str) -> Result<(), OutputError> {
    let ok = !rel.is_empty()
        && rel
            .split('/')
            .all(|c| !c.is_empty() && c != "." && c != ".." && !c.contains('\\'));
    if ok {
        Ok(())
    } else {
        Err(OutputError::new(
            "write",
            Path::new(rel),
            "not a plain path inside the output folder",
            None,
        ))
    }
}

fn is_state_format(b: &[u8]) -> bool {
    String::from_utf8_lossy(b).contains("\"gearwear-output-state\"")
}

impl OutputDir {
    /// Open `root` for the output set `set` (`None`: the folder's one set, manifest
    /// `manifest.json`; `Some(stem)`: `STEM.manifest.json`, so that several sets, such as
    /// sweep shards, can share a folder) of `command`, refusing another command's set.
    pub fn open(root: &Path, set: Option<&str>, command: &str) -> Result<Self, LockError> {
        Self::open_with(root, set, command, OtherSet::Refuse)
    }

    /// The record of the output set `set` in `root_path` as the last run left it, read
    /// without taking the folder's lock or changing anything (None: no folder, no record,
    /// or one that is not this folder's: `open_with` refuses that one). For checks a job
    /// makes before it opens the folder.
    pub fn previous_state_of(root_path: &Path, set: Option<&str>) -> Option<SetState> {
        let root = Dir::open_root(root_path).ok()?;
        let name = match set {
            None => STATE_NAME.to_owned(),
            Some(s) => format!(".{s}{STATE_NAME}"),
        };
        read_state(&root, &name).ok().flatten()
    }

    /// As [`OutputDir::open`], with the choice for another command's set.
    pub fn open_with(
        root_path: &Path,
        set: Option<&str>,
        command: &str,
        other: OtherSet,
    ) -> Result<Self, LockError> {
        let root = Dir::open_root(root_path)?;
        let (lock_name, manifest_name, state_name) = match set {
            None => (
                ".gearwear.lock".to_owned(),
                "manifest.json".to_owned(),
                STATE_NAME.to_owned(),
            ),
            Some(s) => {
                check_relative(s)?;
                (
                    format!(".{s}.lock"),
                    format!("{s}.manifest.json"),
                    format!(".{s}{STATE_NAME}"),
                )
            }
        };
        let lock = OutputLock::acquire(&root, &lock_name, command)?;
        let folder = root.entry_self()?.inode;
        let previous =
            read_state(&root, &state_name)?.unwrap_or_else(|| SetState::new(folder, command));
        // A manifest gearwear has no record of writing: results of an earlier version,
        // another tool, or a copy. Refused now rather than after the run.
        if root.entry(&manifest_name)?.is_some() {
            let recorded = previous
                .output(&manifest_name)
                .map(|r| is_recorded_output(&root, &manifest_name, r))
                .transpose()?
                .unwrap_or(false);
            if !recorded {
                return Err(super::dir::not_ours(
                    &root.join(&manifest_name),
                    "it lists results that gearwear has no record of writing in this folder (an earlier gearwear, another tool, a copy, or an edit)",
                )
                .into());
            }
        }
        if previous.command != command && !previous.outputs.is_empty() && other == OtherSet::Refuse
        {
            return Err(LockError::OtherCommand {
                path: root_path.to_path_buf(),
                held: previous.command.clone(),
                files: previous.outputs.len(),
            });
        }
        // Staging folders of killed runs of this set, if still the ones recorded.
        for s in &previous.staging {
            if matches!(root.entry(&s.path)?, Some(e) if e.kind == super::dir::Kind::Folder && e.inode == s.inode)
            {
                let _ = remove_tree(&root, &s.path);
            }
        }
        let prefix = format!("{STAGING_PREFIX}{}-", set.unwrap_or("set"));
        let (staging, staging_name) = root.create_private_folder(&prefix)?;
        let out = Self {
            manifest_name,
            state_name,
            command: command.to_owned(),
            staging_name,
            staged: BTreeMap::new(),
            state: BTreeSet::new(),
            at_publish: Vec::new(),
            previous,
            published: false,
            _lock: lock,
            staging,
            root,
        };
        let staging_rec = PlaceRecord {
            path: out.staging_name.clone(),
            inode: out.staging.entry_self()?.inode,
        };
        let mut st = out.previous.clone();
        st.staging = vec![staging_rec];
        out.write_state_file(&st)?;
        Ok(out)
    }

    /// The output folder.
    pub fn root(&self) -> &Path {
        self.root.path()
    }

    /// The open output folder.
    pub fn dir(&self) -> &Dir {
        &self.root
    }

    /// What gearwear recorded in the folder before this run (its outputs and state files).
    pub fn previous_state(&self) -> &SetState {
        &self.previous
    }

    /// The command whose set the folder held before this run.
    pub fn previous_command(&self) -> &str {
        &self.previous.command
    }

    fn write_state_file(&self, st: &SetState) -> Result<(), OutputError> {
        check_replaceable(
            &self.root,
            &self.state_name,
            Ours::Format(None, is_state_format),
        )?;
        let text = serde_json::to_vec_pretty(st).map_err(|e| {
            OutputError::new(
                "write",
                &self.root.join(&self.state_name),
                e.to_string(),
                None,
            )
        })?;
        self.root
            .write_new(&self.staging, &self.state_name, &text)?;
        Ok(())
    }

    /// The command whose set this is.
    pub fn command(&self) -> &str {
        &self.command
    }

    /// Stage an output file `rel` (relative path, `/`-separated) with `bytes`.
    pub fn stage(&mut self, rel: &str, bytes: &[u8]) -> Result<(), OutputError> {
        check_relative(rel)?;
        let (dir, name) = self.staging.descend(rel, true)?;
        let entry = dir.write_new(&dir, &name, bytes)?;
        self.staged.insert(
            rel.to_owned(),
            Staged {
                entry,
                sha256: sha256_hex(bytes),
                bytes: bytes.len() as u64,
            },
        );
        Ok(())
    }

    /// Stage `value` as pretty JSON at `rel`.
    pub fn stage_json(&mut self, rel: &str, value: &serde_json::Value) -> Result<(), OutputError> {
        let text = serde_json::to_string_pretty(value)
            .map_err(|e| OutputError::new("write", Path::new(rel), e.to_string(), None))?;
        self.stage(rel, text.as_bytes())
    }

    /// A handle for writing state files into the sub-folder `folder` (created if
    /// missing), from several threads at once (finished sweep cases).
    pub fn state_folder(&self, folder: &str) -> Result<StateFolder, OutputError> {
        check_relative(folder)?;
        let (parent, name) = self.root.descend(folder, true)?;
        let dir = parent.sub(&name, true)?;
        Ok(StateFolder {
            dir,
            scratch: self.staging.try_clone()?,
            folder: folder.to_owned(),
        })
    }

    /// Write a state file `rel` now (a new file renamed into place) and keep it in the
    /// set. What `rel` held must be gearwear's: recorded, or recognised by `recognise`.
    pub fn write_state(
        &mut self,
        rel: &str,
        bytes: &[u8],
        recognise: Recognise,
    ) -> Result<(), OutputError> {
        check_relative(rel)?;
        let (dir, name) = self.root.descend(rel, true)?;
        check_replaceable(
            &dir,
            &name,
            Ours::Format(self.previous.state_file(rel), recognise),
        )?;
        dir.write_new(&self.staging, &name, bytes)?;
        self.state.insert(rel.to_owned());
        Ok(())
    }

    /// Start an append-only state file `rel` with `bytes` (a new file renamed into place,
    /// as [`OutputDir::write_state`]); returns it open for appending. It joins the set
    /// under `rel`, or under `final_rel` (renamed when the set is published) when given.
    pub fn create_log(
        &mut self,
        rel: &str,
        final_rel: Option<&str>,
        bytes: &[u8],
        recognise: Recognise,
    ) -> Result<File, OutputError> {
        use std::io::Write;
        check_relative(rel)?;
        let (dir, name) = self.root.descend(rel, true)?;
        check_replaceable(
            &dir,
            &name,
            Ours::Format(self.previous.state_file(rel), recognise),
        )?;
        let (mut f, tmp) = self.staging.create_new(super::dir::TEMP_PREFIX)?;
        f.write_all(bytes)
            .and_then(|_| f.sync_all())
            .map_err(|e| OutputError::io("write", &dir.join(&name), &e))?;
        self.staging.rename_to(&tmp, &dir, &name)?;
        match final_rel {
            Some(to) => {
                check_relative(to)?;
                self.at_publish
                    .push((rel.to_owned(), to.to_owned(), recognise));
            }
            None => {
                self.state.insert(rel.to_owned());
            }
        }
        Ok(f)
    }

    /// Read the file `rel` of the folder (a state file to resume from): None when there is
    /// none; refused when it is not a regular single-link file, or is larger than `max`.
    pub fn read_file(&self, rel: &str, max: u64) -> Result<Option<Vec<u8>>, OutputError> {
        check_relative(rel)?;
        let (dir, name) = match self.root.descend(rel, false) {
            Ok(x) => x,
            Err(e) => {
                return match self.root.entry(rel.split('/').next().unwrap_or(rel))? {
                    None => Ok(None),
                    Some(_) => Err(e),
                }
            }
        };
        let Some((f, e)) = dir.open_existing(&name, false)? else {
            return Ok(None);
        };
        let path = dir.join(&name);
        if e.bytes > max {
            return Err(OutputError::new(
                "read",
                &path,
                format!(
                    "it holds {} bytes, more than the {max} this run can have written",
                    e.bytes
                ),
                None,
            ));
        }
        read_all(f, max)
            .map(Some)
            .map_err(|x| OutputError::io("read", &path, &x))
    }

    /// Declare a state file that exists already (e.g. a finished sweep case kept from an
    /// earlier run) as part of this set.
    pub fn keep_state(&mut self, rel: &str) {
        self.state.insert(rel.to_owned());
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if !self.published {
            let _ = remove_tree(&self.root, &self.staging_name);
        }
    }
}

/// A sub-folder of an output set for state files written from several threads (see
/// [`OutputDir::state_folder`]).
pub struct StateFolder {
    dir: Dir,
    scratch: Dir,
    folder: String,
}

impl StateFolder {
    /// Write the state file `name` of this folder now; what it held must be free, or a
    /// file `recognise` accepts as gearwear's.
    pub fn write(&self, name: &str, bytes: &[u8], recognise: Recognise) -> Result<(), OutputError> {
        check_replaceable(&self.dir, name, Ours::Format(None, recognise))?;
        self.dir.write_new(&self.scratch, name, bytes)?;
        Ok(())
    }

    /// The folder's path relative to the output folder.
    pub fn folder(&self) -> &str {
        &self.folder
    }

    /// The open folder.
    pub fn dir(&self) -> &Dir {
        &self.dir
    }
}

/// Path of `rel` in `root` (for messages and reading).
pub fn path_in(root: &Path, rel: &str) -> PathBuf {
    root.join(rel)
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
            .filter(|n| !n.starts_with(".gearwear") && !n.starts_with('.'))
            .collect()
    }

    fn any(_: &[u8]) -> bool {
        true
    }
    const ANY: Recognise = any;

    #[test]
    fn a_rerun_removes_what_it_no_longer_produces_and_nothing_else() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "wear").unwrap();
        o.stage("a.csv", b"1").unwrap();
        o.stage("csv/b.csv", b"2").unwrap();
        o.write_state("checkpoint_b.json", b"{}", ANY).unwrap();
        o.publish().unwrap();
        fs::write(d.path().join("user_notes.txt"), b"mine").unwrap();
        let mut o = OutputDir::open(d.path(), None, "wear").unwrap();
        o.stage("a.csv", b"3").unwrap();
        let m = o.publish().unwrap();
        let expect: BTreeSet<String> = ["a.csv", "csv", "manifest.json", "user_notes.txt"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        assert_eq!(names(d.path()), expect);
        assert!(!d.path().join("csv/b.csv").exists());
        assert_eq!(fs::read(d.path().join("a.csv")).unwrap(), b"3");
        assert_eq!(fs::read(d.path().join("user_notes.txt")).unwrap(), b"mine");
        assert_eq!(m.files[0].sha256, sha256_hex(b"3"));
    }

    #[test]
    fn an_edited_output_is_left_alone_and_blocks_its_replacement() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "run").unwrap();
        o.stage("a.csv", b"1").unwrap();
        o.stage("b.csv", b"2").unwrap();
        o.publish().unwrap();
        fs::write(d.path().join("a.csv"), b"edited by hand").unwrap();
        fs::write(d.path().join("b.csv"), b"edited too").unwrap();
        // A rerun that no longer writes b.csv leaves it; one that writes a.csv is refused.
        let mut o = OutputDir::open(d.path(), None, "run").unwrap();
        o.stage("a.csv", b"3").unwrap();
        let e = o.publish().unwrap_err().to_string();
        assert!(e.contains("a.csv") && e.contains("kept in"), "{e}");
        assert_eq!(fs::read(d.path().join("a.csv")).unwrap(), b"edited by hand");
        assert_eq!(fs::read(d.path().join("b.csv")).unwrap(), b"edited too");
        let kept = fs::read_dir(d.path())
            .unwrap()
            .flatten()
            .find(|e| {
                e.file_name()
                    .to_string_lossy()
                    .starts_with(UNPUBLISHED_PREFIX)
            })
            .expect("the results are kept");
        assert_eq!(fs::read(kept.path().join("a.csv")).unwrap(), b"3");
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
    fn the_staging_folder_of_a_killed_run_is_removed_but_a_planted_one_is_not() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "x").unwrap();
        o.stage("a.csv", b"half").unwrap();
        let staging = o.staging_name.clone();
        o.published = true; // as if killed: the staging folder stays
        drop(o);
        assert!(d.path().join(&staging).exists());
        let planted = d.path().join(format!("{STAGING_PREFIX}set-planted"));
        fs::create_dir(&planted).unwrap();
        fs::write(planted.join("mine.txt"), b"mine").unwrap();
        drop(OutputDir::open(d.path(), None, "x").unwrap());
        assert!(!d.path().join(&staging).exists());
        assert_eq!(fs::read(planted.join("mine.txt")).unwrap(), b"mine");
    }

    #[test]
    fn paths_that_leave_the_folder_are_refused() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "x").unwrap();
        assert!(o.stage("../escape.txt", b"x").is_err());
        assert!(o.stage("/etc/passwd", b"x").is_err());
        assert!(o.write_state("a/../../b", b"x", ANY).is_err());
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

    #[test]
    fn another_commands_set_is_refused_unless_replacing_is_allowed() {
        let d = tempfile::tempdir().unwrap();
        let mut o = OutputDir::open(d.path(), None, "run").unwrap();
        o.stage("report.html", b"r").unwrap();
        o.publish().unwrap();
        let e = OutputDir::open(d.path(), None, "dynamics")
            .unwrap_err()
            .to_string();
        assert!(e.contains("gearwear run") && e.contains("2 files"), "{e}");
        let mut o = OutputDir::open_with(d.path(), None, "dynamics", OtherSet::Replace).unwrap();
        o.stage("summary.json", b"s").unwrap();
        o.publish().unwrap();
        assert!(!d.path().join("report.html").exists());
    }

    #[test]
    fn a_planted_manifest_is_refused_and_nothing_it_lists_is_touched() {
        let d = tempfile::tempdir().unwrap();
        fs::write(d.path().join("notes.txt"), b"mine").unwrap();
        let m = r#"{"program":"gearwear","version":"0","command":"run","files":[{"path":"notes.txt","sha256":"x","bytes":4}],"state_files":["notes.txt"]}"#;
        fs::write(d.path().join("manifest.json"), m).unwrap();
        let e = OutputDir::open(d.path(), None, "run")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("manifest.json") && e.contains("no record"),
            "{e}"
        );
        assert_eq!(fs::read(d.path().join("notes.txt")).unwrap(), b"mine");
    }
}
