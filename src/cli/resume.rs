//! Where each wear run of a command starts: afresh, or with `--resume` from its checkpoint.

use super::CliError;
use crate::io::checkpoint::{checkpoint_name, load_checkpoint};
use crate::study::wear_loop::{WearMode, WearRun};
use std::path::Path;

/// The starting runs of `modes`. With `resume`, each mode continues from its checkpoint in
/// `dir`; a mode without one starts afresh (it was interrupted before its first update),
/// but finding no checkpoint at all is an error: the user asked to resume something that
/// is not there.
pub fn starting_runs(
    dir: &Path,
    modes: &[WearMode],
    resume: bool,
    case_sha256: &str,
) -> Result<Vec<WearRun>, CliError> {
    if !resume {
        return Ok(modes.iter().map(|m| WearRun::new(*m)).collect());
    }
    let mut found = Vec::new();
    for m in modes {
        found.push(load_checkpoint(dir, *m, case_sha256)?);
    }
    if found.iter().all(Option::is_none) {
        let names: Vec<String> = modes.iter().map(|m| checkpoint_name(*m)).collect();
        return Err(CliError::input(format!(
            "--resume: no checkpoint to resume from in {} (looked for {}); run without --resume to start afresh",
            dir.display(),
            names.join(", ")
        )));
    }
    Ok(modes
        .iter()
        .zip(found)
        .map(|(m, f)| {
            f.unwrap_or_else(|| {
                eprintln!("note: no {} checkpoint: that run starts afresh", m.label());
                WearRun::new(*m)
            })
        })
        .collect())
}
