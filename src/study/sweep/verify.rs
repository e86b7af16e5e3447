//! Finished sweep cases verified by recomputation when a sweep is rerun: a record's own
//! checksum can be recomputed by whoever edits it, so a sample of the finished cases is
//! run again and must give the recorded results bit for bit. Each costs one case.

use super::case_record::CaseRecord;
use super::case_run::{CaseError, CaseOutcome, SweepRun};
use crate::config::Case;
use crate::study::wear_check::{random_sample, StoredRunError};

/// Most finished cases recomputed when a sweep is rerun.
pub const MAX_RECOMPUTED_CASES: usize = 4;

/// Which of `n` finished cases to recompute: a random sample of up to
/// [`MAX_RECOMPUTED_CASES`] (at least one when there is one), so that an edited record
/// among n is found with probability min(1, 4 / n) on each rerun.
pub fn cases_to_recompute(n: usize) -> Vec<usize> {
    random_sample(n, MAX_RECOMPUTED_CASES, &[])
}

/// How a sweep runs one case: `super::run_case`, or the job's (`duty::study::run_sweep_case`,
/// which runs a wear case under its `[load_spectrum]`).
pub type CaseRunner = dyn Fn(&Case, SweepRun) -> Result<CaseOutcome, CaseError> + Sync;

/// Run `case` again by `runner` (the sweep's own way of running a case) and require the
/// results `rec` holds, bit for bit (a failed case has no record, so a failure now is a
/// mismatch too).
pub fn verify_record(
    case: &Case,
    run: SweepRun,
    rec: &CaseRecord,
    runner: &CaseRunner,
) -> Result<(), StoredRunError> {
    let again = runner(case, run).map_err(|e| {
        StoredRunError::Mismatch(format!("recomputed, the case fails ({e}), but its record holds results: the record is not this case's"))
    })?;
    // A spur case of a table with a helical pair's columns holds them empty.
    let helical = SweepRun::layout_of(&rec.columns).is_some_and(|(_, _, h)| h);
    let now: Vec<Option<u64>> = again
        .results
        .with_helical_columns(helical)
        .values()
        .iter()
        .map(|x| x.is_finite().then_some(x.to_bits()))
        .collect();
    let stored: Vec<Option<u64>> = rec.results.iter().map(|x| x.map(f64::to_bits)).collect();
    if let Some(i) = (0..now.len().max(stored.len())).find(|i| now.get(*i) != stored.get(*i)) {
        let show = |v: Option<&Option<u64>>| {
            v.copied()
                .flatten()
                .map_or("none".into(), |b| format!("{:e}", f64::from_bits(b)))
        };
        return Err(StoredRunError::Mismatch(format!(
            "recomputed, column `{}` is {} but the record holds {}: the record was edited or is not this case's",
            rec.columns.get(i).map_or("?", String::as_str),
            show(now.get(i)),
            show(stored.get(i))
        )));
    }
    Ok(())
}
