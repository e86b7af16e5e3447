//! What `calibrate` and `predict` check of a gear train (`[[stage]]`) before any work:
//! its prognostics follow one operating point (no load spectrum, no change of duty) and
//! observe wear and the response per stage (no condition indicator of the housing's
//! record yet). The forward model is the train's wear loop
//! (`prognostics::train_forward`); observations name the mesh by a `stage` column
//! (`prognostics::observations`).

use super::JobError;
use crate::config::Case;
use crate::prognostics::train_forward::{TRAIN_DUTY, TRAIN_INDICATORS};
use crate::prognostics::Quantity;

/// Number of meshes of `case`: its stages, 1 for a single pair.
pub(crate) fn stages_of(case: &Case) -> usize {
    case.stage.len().max(1)
}

/// Refuse what a train's prognostics do not take: a load spectrum or a change of duty
/// (`future`), and observed condition indicators (`observed`). Nothing for a single pair.
pub(crate) fn check_train_prognostics(
    case: &Case,
    observed: &[Quantity],
    future: bool,
) -> Result<(), JobError> {
    if case.stage.is_empty() {
        return Ok(());
    }
    crate::study::train::refuse_fault(case, "`gearwear calibrate` and `gearwear predict`")?;
    if future || case.load_spectrum.is_some() {
        return Err(JobError::input(TRAIN_DUTY));
    }
    if observed.iter().any(|q| matches!(q, Quantity::Indicator(_))) {
        return Err(JobError::input(TRAIN_INDICATORS));
    }
    Ok(())
}
