//! What every command does around its study: build the model (warnings to stderr), open
//! the output set, write and publish the artifacts, print the headline.
//!
//! Streams: results (the headline numbers) go to standard output, so `gearwear run >
//! out.txt` keeps them; progress bars, warnings and log lines go to standard error.
//! `--quiet` drops the headline.

use super::CliError;
use crate::config::Case;
use crate::io::{OutputDir, RunMetadata};
use crate::report::{publish_artifacts, Artifacts};
use crate::study::Model;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

static QUIET: AtomicBool = AtomicBool::new(false);

/// Set by `--quiet`.
pub fn set_quiet(q: bool) {
    QUIET.store(q, Ordering::Relaxed);
}

/// Print results to standard output unless `--quiet`.
pub fn say(text: &str) {
    if !QUIET.load(Ordering::Relaxed) && !text.is_empty() {
        println!("{text}");
    }
}

/// Build the model; geometry problems are input errors (exit 2); warnings go to stderr.
pub fn build_model(case: &Case) -> Result<Model, CliError> {
    let m = Model::from_case(case).map_err(|e| CliError::Input(e.0))?;
    for w in &m.warnings {
        eprintln!("warning: {w}");
    }
    Ok(m)
}

/// Open the output folder for `command` (one set per folder).
pub fn open_out(out: &Path, command: &str) -> Result<OutputDir, CliError> {
    Ok(OutputDir::open(out, None, command)?)
}

/// Stamp the metadata on the summary, stage everything, publish the set, print the
/// headline (stdout) and where the files went (stderr).
pub fn finish(out: OutputDir, mut a: Artifacts, meta: &RunMetadata) -> Result<(), CliError> {
    a.stamp_metadata(meta).map_err(anyhow::Error::from)?;
    let root = publish_artifacts(out, &a)?;
    say(&a.headline);
    eprintln!("{}: results -> {}", meta.command, root.display());
    Ok(())
}
