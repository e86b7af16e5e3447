//! Checkpoints of wear runs: the case they belong to and every update so far, so an
//! interrupted study resumes where it stopped and reaches the same numbers.

use super::OutputDir;
use crate::study::wear_loop::{WearMode, WearRun};
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::sync::Mutex;

/// What a checkpoint file holds.
#[derive(Serialize, Deserialize)]
pub struct Checkpoint {
    pub case_sha256: String,
    pub run: WearRun,
}

/// File name of a mode's checkpoint, relative to the output folder.
pub fn checkpoint_name(mode: WearMode) -> String {
    format!("checkpoint_{}.json", mode.name())
}

/// Why a checkpoint cannot be used (an input problem: the message names the file).
#[derive(Debug, thiserror::Error)]
#[error("--resume: {path}: {reason}")]
pub struct CheckpointError {
    pub path: String,
    pub reason: String,
}

/// The bytes of a checkpoint.
pub fn checkpoint_bytes(case_sha256: &str, run: &WearRun) -> Vec<u8> {
    let c = Checkpoint {
        case_sha256: case_sha256.to_owned(),
        run: run.clone(),
    };
    serde_json::to_vec(&c).unwrap_or_default()
}

/// Writes each wear run's checkpoint into an output set after every update, for runs going
/// on in parallel (the wear commands and the Python binding share it).
pub struct CheckpointWriter {
    out: Mutex<OutputDir>,
    case_sha256: String,
}

impl CheckpointWriter {
    pub fn new(out: OutputDir, case_sha256: &str) -> Self {
        Self {
            out: Mutex::new(out),
            case_sha256: case_sha256.to_owned(),
        }
    }

    /// Write the checkpoint of `run` (a state file of the set). A failed write is an
    /// `OutputError` inside the returned error, so callers can tell it from a solver error.
    pub fn write(&self, mode: WearMode, run: &WearRun) -> anyhow::Result<()> {
        let bytes = checkpoint_bytes(&self.case_sha256, run);
        self.out
            .lock()
            .map_err(|_| anyhow::anyhow!("checkpoint writer poisoned"))?
            .write_state(&checkpoint_name(mode), &bytes)?;
        Ok(())
    }

    /// The output set back, to publish the results into.
    pub fn into_inner(self) -> anyhow::Result<OutputDir> {
        self.out
            .into_inner()
            .map_err(|_| anyhow::anyhow!("checkpoint writer poisoned"))
    }
}

fn short(s: &str) -> String {
    s.chars().take(12).collect()
}

/// Load the checkpoint of `mode` in `dir` for the case with hash `case_sha256`:
/// `Ok(None)` when there is none, an error when it is unreadable or belongs to another
/// case or mode.
pub fn load_checkpoint(
    dir: &Path,
    mode: WearMode,
    case_sha256: &str,
) -> Result<Option<WearRun>, CheckpointError> {
    let p = dir.join(checkpoint_name(mode));
    let err = |reason: String| CheckpointError {
        path: p.display().to_string(),
        reason,
    };
    let bytes = match std::fs::read(&p) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(err(format!("cannot read: {e}"))),
    };
    let c: Checkpoint = serde_json::from_slice(&bytes)
        .map_err(|e| err(format!("not a gearwear checkpoint: {e}")))?;
    if c.case_sha256 != case_sha256 {
        return Err(err(format!(
            "belongs to another case (hash {} != {}); rerun without --resume or with the same case",
            short(&c.case_sha256),
            short(case_sha256)
        )));
    }
    if c.run.mode != mode {
        return Err(err(format!(
            "holds a {} run, not a {} one",
            c.run.mode.label(),
            mode.label()
        )));
    }
    Ok(Some(c.run))
}
