//! Where each wear run of a command starts (afresh, or with `--resume` from its
//! checkpoint, checked and recomputed before anything else is computed), and the
//! checkpoint logs appended to after every update. The logic is the library's
//! (`io::checkpoint_set`).

use super::CliError;
use crate::io::checkpoint_set::CheckpointSet;
use crate::io::OutputDir;
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;

/// With `resume`, the output folder must exist (checked before it would be created).
pub fn require_folder(out: &std::path::Path, resume: bool) -> Result<(), CliError> {
    if resume && !out.is_dir() {
        return Err(CliError::input(format!(
            "--resume: no checkpoint to resume from in {}: the folder does not exist; run without --resume to start afresh",
            out.display()
        )));
    }
    Ok(())
}

/// The starting runs of `modes` (see `io::checkpoint_set::starting_runs`).
pub fn starting_runs(
    out: &OutputDir,
    modes: &[WearMode],
    resume: bool,
    case_sha256: &str,
    model: &Model,
) -> Result<Vec<WearRun>, CliError> {
    let (runs, notes) =
        crate::io::checkpoint_set::starting_runs(out, modes, resume, case_sha256, model)
            .map_err(|e| CliError::input(e.replace("resuming:", "--resume:")))?;
    for n in notes {
        eprintln!("note: {n}");
    }
    Ok(runs)
}

/// The checkpoint logs of the runs that start at `runs`, in `out`.
pub fn open_checkpoints(
    out: &mut OutputDir,
    runs: &[WearRun],
    case_sha256: &str,
) -> Result<CheckpointSet, CliError> {
    let refs: Vec<&WearRun> = runs.iter().collect();
    Ok(CheckpointSet::open(out, &refs, case_sha256)?)
}
