//! Checkpoint logs of wear runs kept as several single-point logs each: a run under a
//! load spectrum (one log per bin) and a train's run (one log per mesh). Each log is an
//! ordinary wear run's checkpoint (`checkpoint.rs`); after every update the parts are
//! appended one after another, so an interruption between two appends leaves some logs
//! one update longer (the readers cut them back to the updates every log holds).

use super::checkpoint::{load_checkpoint_named, CheckpointError, CheckpointLog};
use crate::io::{OutputDir, OutputError};
use crate::study::wear_loop::{UpdateRecord, WearMode, WearRun};
use std::sync::Mutex;

/// One log per mode and part, appended to after every update.
pub(crate) struct PartLogs {
    logs: Vec<(WearMode, Mutex<Vec<CheckpointLog>>)>,
}

/// A mode's parts as the logs start: each part's published name and the run it starts at
/// (no record for a fresh run; a resumed run's records, rewritten into a new file).
pub(crate) type PartStarts = (WearMode, Vec<(String, WearRun)>);

impl PartLogs {
    /// Start the logs of every mode's parts in `out`.
    pub fn open(
        out: &mut OutputDir,
        case_sha256: &str,
        starts: &[PartStarts],
    ) -> Result<Self, OutputError> {
        let mut logs = Vec::new();
        for (mode, parts) in starts {
            let mut per_part = Vec::new();
            for (name, run) in parts {
                per_part.push(CheckpointLog::create_named(out, name, case_sha256, run)?);
            }
            logs.push((*mode, Mutex::new(per_part)));
        }
        Ok(Self { logs })
    }

    /// Append the updates of `mode`'s run not yet in its logs: it holds `total` updates,
    /// of which part i's record j is `record(i, j)`.
    pub fn record<'a>(
        &self,
        mode: WearMode,
        total: usize,
        record: &dyn Fn(usize, usize) -> &'a UpdateRecord,
    ) -> anyhow::Result<()> {
        if let Some((_, logs)) = self.logs.iter().find(|(m, _)| *m == mode) {
            let mut logs = logs
                .lock()
                .map_err(|_| anyhow::anyhow!("checkpoint writer poisoned"))?;
            for (i, log) in logs.iter_mut().enumerate() {
                log.append_upto(total, &|j| record(i, j))?;
            }
        }
        Ok(())
    }
}

/// The logs of `mode` published as `names` in `out` (each the partial file of an
/// interrupted run if there is one, else the published one), in order; a part without
/// a log is None.
pub(crate) fn load_parts(
    out: &OutputDir,
    names: &[String],
    mode: WearMode,
    case_sha256: &str,
    max_bytes: u64,
) -> Result<Vec<Option<WearRun>>, CheckpointError> {
    names
        .iter()
        .map(|name| {
            load_checkpoint_named(out, name, mode, case_sha256, max_bytes).map(|l| l.map(|l| l.run))
        })
        .collect()
}
