//! The case files of a sweep with an output folder: `cases/<case_id>.json`, one per
//! finished case or continuation point, written first and atomically, read back before
//! anything is computed, so a rerun skips what is finished.

use super::super::JobError;
use super::cases::Planned;
use crate::io::write_atomic;
use crate::remedy::{Problem, Remedy};
use crate::study::sweep::{CaseError, CaseRecord, CaseResults, ContinuationLink, SweepRun};
use std::path::{Path, PathBuf};

/// Where the record of case `id` lives.
pub fn case_path(dir: &Path, id: usize) -> PathBuf {
    dir.join("cases").join(format!("{id}.json"))
}

/// Write the record of a finished case (or continuation point); the record is the first
/// and only file a case writes.
pub fn write_record(
    dir: &Path,
    p: &Planned,
    keys: &[String],
    results: &CaseResults,
    continuation: Option<ContinuationLink>,
) -> Result<CaseRecord, CaseError> {
    let rec = CaseRecord::of(p.id, &p.hash, keys, &p.labels, results, continuation);
    let text = serde_json::to_string_pretty(&rec).map_err(|e| CaseError::Solve(e.into()))?;
    write_atomic(&case_path(dir, p.id), text.as_bytes()).map_err(|e| CaseError::Solve(e.into()))?;
    Ok(rec)
}

/// The record of a finished case, if `cases/<id>.json` holds this very case's result.
pub fn finished(dir: &Path, p: &Planned, run: SweepRun, keys: &[String]) -> Option<CaseRecord> {
    let r = CaseRecord::read(&case_path(dir, p.id)).ok()??;
    r.is_result_of(p.id, &p.hash, run, keys, &p.labels)
        .then_some(r)
}

/// Every case file of the plan that exists must read back whole and unedited
/// (`CaseRecord::verify`); a record of another case (changed base case or values) is
/// fine: it is recomputed and replaced.
pub fn check_case_files(dir: &Path, planned: &[Planned]) -> Result<(), JobError> {
    let problems: Vec<Problem> = planned
        .iter()
        .filter_map(|p| {
            CaseRecord::read(&case_path(dir, p.id))
                .err()
                .map(|e| (p.id, e))
        })
        .map(|(id, e)| {
            Problem::new(e)
                .remedy(Remedy::new("delete it to recompute that case").path(case_path(dir, id)))
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(JobError::Input(problems))
    }
}
