//! The state file of an output set: gearwear's own record of what it wrote into the
//! folder, the only list it trusts when it replaces or removes a file.
//!
//! `.gearwear-state.json` (`.STEM.gearwear-state.json` for a named set) holds the folder's
//! identity (device and inode: a state file copied from another folder does not count),
//! the command, every published output with its identity (device, inode, size, SHA-256),
//! the state files kept for resuming (checkpoints, finished sweep cases) with their
//! device and inode, and the staging folders in use. A file is gearwear's to replace or
//! remove only while it is still exactly what this record says: the same inode, one link,
//! the same size and checksum. `manifest.json` is written for people and scripts to read;
//! gearwear never acts on it.

use super::dir::{check_plain, Dir, Entry, Inode, Kind};
use super::error::OutputError;
use serde::{Deserialize, Serialize};

const FORMAT: &str = "gearwear-output-state";
const VERSION: u32 = 1;
/// Largest state file read back: a sweep of 1e6 finished cases lists ~100 MB.
pub const MAX_STATE_BYTES: u64 = 256 << 20;

/// A published output as written.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct OutputRecord {
    /// Path relative to the output folder, `/`-separated.
    pub path: String,
    /// Device and inode of the file as written.
    #[serde(flatten)]
    pub inode: Inode,
    /// Size, bytes.
    pub bytes: u64,
    /// SHA-256 of the content, lowercase hex.
    pub sha256: String,
}

/// A state file (appended to, or written once per case) or a staging folder.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct PlaceRecord {
    /// Path relative to the output folder.
    pub path: String,
    /// Device and inode of the file or folder.
    #[serde(flatten)]
    pub inode: Inode,
}

/// The content of a state file (see the module docs).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SetState {
    /// Format name of the file, "gearwear-output-state".
    pub format: String,
    /// Format version.
    pub version: u32,
    /// Device and inode of the output folder the record belongs to.
    pub folder: Inode,
    /// The command that wrote the set.
    pub command: String,
    /// Every published output.
    pub outputs: Vec<OutputRecord>,
    /// State files kept for resuming (checkpoints, finished sweep cases).
    pub state_files: Vec<PlaceRecord>,
    /// Staging folders in use.
    pub staging: Vec<PlaceRecord>,
}

impl SetState {
    /// An empty record for `folder`.
    pub fn new(folder: Inode, command: &str) -> Self {
        Self {
            format: FORMAT.into(),
            version: VERSION,
            folder,
            command: command.into(),
            outputs: Vec::new(),
            state_files: Vec::new(),
            staging: Vec::new(),
        }
    }

    /// The published output at `path`, if recorded.
    pub fn output(&self, path: &str) -> Option<&OutputRecord> {
        self.outputs.iter().find(|o| o.path == path)
    }

    /// The state file at `path`, if recorded.
    pub fn state_file(&self, path: &str) -> Option<&PlaceRecord> {
        self.state_files.iter().find(|o| o.path == path)
    }
}

/// Read the state file `name` of `root`: None when there is none; an error when the name
/// holds something that is not gearwear's record of this very folder.
pub fn read_state(root: &Dir, name: &str) -> Result<Option<SetState>, OutputError> {
    let Some((file, e)) = root.open_existing(name, false)? else {
        return Ok(None);
    };
    let path = root.join(name);
    let foreign = |why: &str| {
        super::dir::not_ours(
            &path,
            &format!("{why}: it is not gearwear's record of this folder"),
        )
    };
    if e.bytes > MAX_STATE_BYTES {
        return Err(foreign(&format!("it holds {} bytes", e.bytes)));
    }
    let bytes = read_all(file, MAX_STATE_BYTES).map_err(|e| OutputError::io("read", &path, &e))?;
    let s: SetState = serde_json::from_slice(&bytes).map_err(|_| foreign("it does not parse"))?;
    if s.format != FORMAT || s.version != VERSION {
        return Err(foreign("its format is not gearwear's"));
    }
    if s.folder != root.entry_self()?.inode {
        return Err(foreign(
            "it was written for another folder (copied from elsewhere?)",
        ));
    }
    Ok(Some(s))
}

/// Read at most `max` bytes of `f`.
pub fn read_all(f: std::fs::File, max: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let mut v = Vec::new();
    f.take(max).read_to_end(&mut v)?;
    Ok(v)
}

/// Whether the entry `name` of `dir` is still exactly the output recorded (`rec`): one
/// link, the same inode, size and SHA-256.
pub fn is_recorded_output(dir: &Dir, name: &str, rec: &OutputRecord) -> Result<bool, OutputError> {
    match dir.entry(name)? {
        Some(e)
            if e.kind == Kind::File
                && e.links == 1
                && e.inode == rec.inode
                && e.bytes == rec.bytes => {}
        _ => return Ok(false),
    }
    let Some((f, e)) = dir.open_existing(name, false)? else {
        return Ok(false);
    };
    if e.inode != rec.inode {
        return Ok(false);
    }
    let bytes = read_all(f, rec.bytes.saturating_add(1))
        .map_err(|x| OutputError::io("read", &dir.join(name), &x))?;
    Ok(crate::checksum::sha256_hex(&bytes) == rec.sha256)
}

/// Whether the entry `name` of `dir` is still the state file recorded (one link, the same
/// inode).
pub fn is_recorded_place(dir: &Dir, name: &str, rec: &PlaceRecord) -> Result<bool, OutputError> {
    Ok(
        matches!(dir.entry(name)?, Some(Entry { kind: Kind::File, links: 1, inode, .. }) if inode == rec.inode),
    )
}

/// Whether the first bytes of a file are in one of gearwear's own formats.
pub type Recognise = fn(&[u8]) -> bool;

/// How a name that gearwear is about to replace may be recognised as its own.
pub enum Ours<'a> {
    /// Only an output recorded in the state file, unchanged.
    Recorded(Option<&'a OutputRecord>),
    /// A state file: recorded (same inode), or a regular single-link file whose first
    /// bytes `recognise` accepts as gearwear's own format (a checkpoint, a case record,
    /// an interrupted run's marker).
    Format(Option<&'a PlaceRecord>, Recognise),
}

/// Bytes read to recognise a file's format.
const RECOGNISE_BYTES: u64 = 4096;

/// Ok when `name` in `dir` is free or gearwear's own by `ours`; else the error says what
/// it holds and why it is left alone.
pub fn check_replaceable(dir: &Dir, name: &str, ours: Ours<'_>) -> Result<(), OutputError> {
    let Some(e) = dir.entry(name)? else {
        return Ok(());
    };
    let path = dir.join(name);
    check_plain(&path, &e)?;
    let ok = match ours {
        Ours::Recorded(Some(rec)) => is_recorded_output(dir, name, rec)?,
        Ours::Recorded(None) => false,
        Ours::Format(rec, recognise) => {
            rec.is_some_and(|r| r.inode == e.inode)
                || match dir.open_existing(name, false)? {
                    Some((f, _)) => recognise(
                        &read_all(f, RECOGNISE_BYTES)
                            .map_err(|x| OutputError::io("read", &path, &x))?,
                    ),
                    None => true,
                }
        }
    };
    if ok {
        Ok(())
    } else {
        Err(super::dir::not_ours(
            &path,
            "it was not written by gearwear, or was changed after gearwear wrote it",
        ))
    }
}
