//! A dataset folder claimed by one design: under a folder-wide lock that every dataset
//! run takes (whatever its own set's lock: a shard and an unsharded run lock different
//! sets), the folder's owner is checked and, when it has none, this design's
//! description written; the folder is marked `INCOMPLETE` until the run publishes. Two
//! runs of different designs started at once into an empty folder: the second to claim
//! it is refused (issue 33: both exited 0 and mixed their records).

use super::folder::{check_owner, put, DATASET_REL};
use super::request::DatasetError;
use crate::io::lock::{LockError, OutputLock};
use crate::io::set_state::SetState;
use crate::io::OutputDir;
use std::path::Path;
use std::time::{Duration, Instant};

/// The folder-wide lock of a dataset folder's claim (held for a moment by each run).
pub const CLAIM_LOCK: &str = ".gearwear-dataset.lock";

/// How long a run waits for another run's claim (a read and a write of the description).
const CLAIM_WAIT: Duration = Duration::from_secs(30);

/// Claim `out`'s folder `root` for the dataset of key `key` (module docs): refused when
/// another design owns it (unless `replace`); else its description `desc` written and
/// the folder marked incomplete.
pub(super) fn claim_folder(
    out: &OutputDir,
    root: &Path,
    (key, replace): (&str, bool),
    desc: &[u8],
    prev: &SetState,
) -> Result<(), DatasetError> {
    let failed = |e: crate::io::OutputError| DatasetError::Failed(e.into());
    let started = Instant::now();
    let _lock = loop {
        match OutputLock::acquire(out.dir(), CLAIM_LOCK, "dataset (claiming the folder)") {
            Ok(l) => break l,
            Err(LockError::Held { .. }) if started.elapsed() < CLAIM_WAIT => {
                std::thread::sleep(Duration::from_millis(20));
            }
            Err(e) => return Err(DatasetError::Input(vec![e.to_string()])),
        }
    };
    check_owner(root, key, replace).map_err(|m| DatasetError::Input(vec![m.to_string()]))?;
    out.mark_incomplete().map_err(failed)?;
    put(root, DATASET_REL, desc, prev).map_err(failed)
}
