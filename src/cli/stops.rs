//! What the CLI says about wear runs that stopped before their total cycles.

use super::CliError;
use crate::study::wear_loop::{StopKind, WearRun};

/// Warns about every wear run that stopped early (its outputs are written up to the
/// stop). A stop because the worn teeth left the model's domain is a result (exit code
/// 0, `stopped` in summary.json); one for want of a steady state is a failure of the
/// solver the user should act on (exit code 1, after all outputs are written).
pub fn report_stops(runs: &[&WearRun]) -> Result<(), CliError> {
    let mut failed = None;
    for run in runs {
        if let Some(stop) = &run.stopped {
            let message = format!(
                "the {} wear run stopped early: {}",
                run.mode.name(),
                stop.reason
            );
            eprintln!("warning: {message}");
            if stop.kind == StopKind::Numerical {
                failed = Some(message);
            }
        }
    }
    match failed {
        Some(m) => Err(CliError::Failed(anyhow::anyhow!(m))),
        None => Ok(()),
    }
}
