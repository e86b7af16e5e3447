//! Resuming under a load spectrum only from records this case computes (issues 21 and
//! 22, as `study::wear_check::verify_resumable` for one operating point): line checksums
//! cannot stop someone who recomputes them, recomputation can. The first record (when it
//! is new teeth) and the last are recomputed from the record before them, every bin's
//! response included, and must equal the stored ones bit for bit.

use super::model::SpectrumModel;
use super::wear::{advance, block_after, first_record, respond, SpectrumRecord, SpectrumRun};
use crate::study::wear_check::StoredRunError;
use crate::study::wear_loop::start_of;

/// The record after `last` as the run computes it (`wear::run_spectrum_wear`): the
/// block, the state it reaches and every bin's response on it, warm-started from `last`.
fn next_record(
    sm: &SpectrumModel,
    run: &SpectrumRun,
    last: &SpectrumRecord,
) -> Option<SpectrumRecord> {
    let n = block_after(sm, last, &run.shares)?;
    let mut next = advance(last, &run.shares, n);
    let starts: Vec<Option<Vec<f64>>> = last.bins.iter().map(start_of).collect();
    let bins = respond(sm, run.mode, &next.wear, &starts).ok()?;
    next.roughness_um = sm.bins[0].roughness_for(&next.wear);
    next.bins = bins;
    Some(next)
}

/// Ok when `run` (read back from its bin checkpoints) holds records of `sm`'s case: the
/// first, if it is new teeth, and the last, recomputed, equal the stored ones (their
/// wear state and every bin's record, compared as JSON, which carries every double
/// exactly). Else which update differs, for the message.
pub(crate) fn verify_spectrum_run(
    sm: &SpectrumModel,
    run: &SpectrumRun,
) -> Result<(), StoredRunError> {
    let n = run.records.len();
    let same = |a: &SpectrumRecord, b: &SpectrumRecord| {
        serde_json::to_string(&(&a.wear, &a.bins)).ok()
            == serde_json::to_string(&(&b.wear, &b.bins)).ok()
    };
    let fresh = sm.bins[0].new_wear_state();
    let mut checks = Vec::new();
    if n > 0 && run.records[0].wear == fresh {
        checks.push(0);
    }
    if n > 1 {
        checks.push(n - 1);
    }
    for j in checks {
        let again = if j == 0 {
            first_record(sm, run.mode, fresh.clone()).ok()
        } else {
            next_record(sm, run, &run.records[j - 1])
        };
        if !again.is_some_and(|a| same(&a, &run.records[j])) {
            let from = if j == 0 {
                "from new teeth"
            } else {
                "from the update before it"
            };
            return Err(StoredRunError::Mismatch(format!(
                "update {j} (line {} of each bin's checkpoint) is not what this case's model computes {from}, every bin recomputed: the records are not this case's, or were edited",
                j + 2
            )));
        }
    }
    Ok(())
}
