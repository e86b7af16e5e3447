//! What every command does around its study: build the model (warnings to stderr), open
//! the output set, write and publish the artifacts, print the headline.
//!
//! Streams: results (the headline numbers) go to standard output, so `gearwear run >
//! out.txt` keeps them; progress bars, warnings and log lines go to standard error.
//! `--quiet` drops the headline.

use super::CliError;
use crate::config::Case;
use crate::io::{OtherSet, OutputDir, RunMetadata};
use crate::report::{publish_artifacts, Artifacts};
use crate::study::Model;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

static QUIET: AtomicBool = AtomicBool::new(false);
static REPLACE: AtomicBool = AtomicBool::new(false);
static BUDGET: std::sync::Mutex<Option<crate::study::budget::Budget>> = std::sync::Mutex::new(None);

/// The run budget the flags ask for (None: `--no-budget`).
pub fn set_budget(b: Option<crate::study::budget::Budget>) {
    if let Ok(mut g) = BUDGET.lock() {
        *g = b;
    }
}

/// Refuse, before it computes, a job whose estimate (made once its inputs are read:
/// observations, posterior, shards) is over the run budget.
pub fn check_budget(e: &crate::study::budget::Estimate) -> Result<(), CliError> {
    let b = BUDGET.lock().ok().and_then(|g| *g);
    match b {
        Some(b) => e.check(&b).map_err(CliError::input),
        None => Ok(()),
    }
}

/// Set by `--replace`: an output folder holding another command's results may be
/// replaced.
pub fn set_replace(r: bool) {
    REPLACE.store(r, Ordering::Relaxed);
}

/// Set by `--quiet`.
pub fn set_quiet(q: bool) {
    QUIET.store(q, Ordering::Relaxed);
}

/// Print results to standard output unless `--quiet` (never a panic: `io::console`).
pub fn say(text: &str) {
    if !QUIET.load(Ordering::Relaxed) && !text.is_empty() {
        crate::io::console::out_line(text);
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
    open_set(out, None, command)
}

/// Open the output set `set` of `out` for `command`, replacing another command's set
/// only with `--replace`.
pub fn open_set(out: &Path, set: Option<&str>, command: &str) -> Result<OutputDir, CliError> {
    let other = if REPLACE.load(Ordering::Relaxed) {
        OtherSet::Replace
    } else {
        OtherSet::Refuse
    };
    Ok(OutputDir::open_with(out, set, command, other)?)
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
