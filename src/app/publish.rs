//! Publishing a job's outputs to a folder: one call that every job ends with.
//!
//! The folder is opened (and locked) before the study starts, so a second writer is
//! refused before anything is computed and checkpoints can go into it while the study
//! runs (`app::checkpoints`); the artifacts are staged and published as one set at the
//! end (`io::OutputDir`): the folder then holds this run's files and none of an earlier
//! run's. Without a folder (the Python binding's default), nothing is written and the
//! artifacts are only handed back.

use super::observer::Observer;
use super::{JobError, Outcome};
use crate::io::{OtherSet, OutputDir};
use crate::report::{write_artifacts, Artifacts};
use crate::store::RunMetadata;
use std::path::Path;

/// Open `dir` for the output set of `command`: `set` names the set when several share
/// the folder (sweep and prediction shards), `None` is the folder's one set. A folder
/// holding another command's results is refused unless `replace` (`io::OtherSet`).
pub fn open(
    dir: &Path,
    set: Option<&str>,
    command: &str,
    replace: bool,
) -> Result<OutputDir, JobError> {
    let other = if replace {
        OtherSet::Replace
    } else {
        OtherSet::Refuse
    };
    Ok(OutputDir::open_with(dir, set, command, other)?)
}

/// Open `dir` if given (see [`open`]).
pub fn open_if(
    dir: Option<&Path>,
    set: Option<&str>,
    command: &str,
    replace: bool,
) -> Result<Option<OutputDir>, JobError> {
    dir.map(|d| open(d, set, command, replace)).transpose()
}

/// Finish a job: stamp `meta` on the summary (unless the summary carries its own), then,
/// with an output folder, stage every artifact and publish the set, telling `observer`
/// where it went. Returns the outcome with the artifacts.
pub fn publish(
    out: Option<OutputDir>,
    mut artifacts: Artifacts,
    meta: Option<&RunMetadata>,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    if let Some(m) = meta {
        artifacts
            .stamp_metadata(m)
            .map_err(|e| JobError::Failed(e.into()))?;
    }
    let published = match out {
        Some(mut o) => {
            write_artifacts(&mut o, &artifacts)?;
            let root = o.root().to_path_buf();
            let command = o.command().to_owned();
            o.publish()?;
            observer.note(&format!(
                "{command}: {} -> {}",
                artifacts.contents_words(),
                folder_words(&root)
            ));
            Some(root)
        }
        None => None,
    };
    Ok(Outcome {
        artifacts,
        published,
        incomplete: None,
    })
}

/// A folder as a person reads it: its path with a trailing separator.
fn folder_words(dir: &Path) -> String {
    let d = dir.display().to_string();
    if d.ends_with(std::path::MAIN_SEPARATOR) {
        d
    } else {
        format!("{d}{}", std::path::MAIN_SEPARATOR)
    }
}
