//! Running a job from the command line: the terminal observer attached, the headline
//! printed, an incomplete result turned into exit code 1.
//!
//! Streams: results (the headline numbers) go to standard output, so `gearwear run >
//! out.txt` keeps them; progress bars, warnings and log lines go to standard error.
//! `--quiet` drops the headline.

use super::error::CliError;
use super::progress::Terminal;
use crate::app::{Job, Outcome};
use std::sync::atomic::{AtomicBool, Ordering};

static QUIET: AtomicBool = AtomicBool::new(false);
static REPLACE: AtomicBool = AtomicBool::new(false);

/// Set by `--replace`: an output folder holding another command's results may be
/// replaced.
pub(crate) fn set_replace(r: bool) {
    REPLACE.store(r, Ordering::Relaxed);
}

/// Whether `--replace` was given.
pub(crate) fn replace() -> bool {
    REPLACE.load(Ordering::Relaxed)
}

/// Set by `--quiet`.
pub(crate) fn set_quiet(q: bool) {
    QUIET.store(q, Ordering::Relaxed);
}

/// Print results to standard output unless `--quiet`.
pub(crate) fn say(text: &str) {
    if !QUIET.load(Ordering::Relaxed) && !text.is_empty() {
        println!("{text}");
    }
}

/// Run `job` with progress bars, print its headline; a result that is incomplete (a wear
/// run the solver gave up on, failed sweep cases) is an error after its outputs are
/// written.
pub(crate) fn execute<J: Job>(job: &J) -> Result<(), CliError>
where
    J::Output: AsRef<Outcome>,
{
    let output = job.run(&Terminal::new())?;
    let o = output.as_ref();
    say(&o.artifacts.headline);
    match &o.incomplete {
        Some(m) => Err(CliError::Failed(anyhow::anyhow!("{m}"))),
        None => Ok(()),
    }
}
