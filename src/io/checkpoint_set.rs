//! The checkpoint logs of a study's wear runs, one per mode, appended to after every
//! update while the runs go on in parallel (the wear commands and the Python binding
//! share it).

use super::checkpoint::{checkpoint_name, CheckpointLog, LoadedCheckpoint};
use super::{OutputDir, OutputError};
use crate::study::wear_loop::{WearMode, WearRun};
use std::sync::Mutex;

/// One append-only checkpoint log per wear mode, in an output set's state files.
pub struct CheckpointSet {
    logs: Vec<(WearMode, Mutex<CheckpointLog>)>,
}

impl CheckpointSet {
    /// Start the log of every run in `out` (a fresh run, or one resumed from the
    /// checkpoint it was loaded from).
    pub fn open(
        out: &mut OutputDir,
        runs: &[(&WearRun, Option<&LoadedCheckpoint>)],
        case_sha256: &str,
    ) -> Result<Self, OutputError> {
        let mut logs = Vec::new();
        for (run, loaded) in runs {
            let path = out.state_path(&checkpoint_name(run.mode))?;
            let log = match loaded {
                Some(l) => CheckpointLog::resume(&path, l)?,
                None => CheckpointLog::create(&path, case_sha256, run)?,
            };
            logs.push((run.mode, Mutex::new(log)));
        }
        Ok(Self { logs })
    }

    /// Append the new updates of `run`. A failed write is an `OutputError` inside the
    /// returned error, so callers can tell it from a solver error.
    pub fn record(&self, run: &WearRun) -> anyhow::Result<()> {
        if let Some((_, log)) = self.logs.iter().find(|(m, _)| *m == run.mode) {
            log.lock()
                .map_err(|_| anyhow::anyhow!("checkpoint writer poisoned"))?
                .append_new(run)?;
        }
        Ok(())
    }
}
