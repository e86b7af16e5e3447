//! The case files of a sweep with an output folder: `cases/<case_id>.json`, one per
//! finished case or continuation point, written first (a new file renamed into place,
//! through the set's state folder: `io::output_dir::StateFolder`), read back before
//! anything is computed, so a rerun skips what is finished; a sample of the finished
//! cases is recomputed first (`study::sweep::verify`), so an edited record is refused.

use super::super::JobError;
use super::cases::Planned;
use crate::io::output_dir::StateFolder;
use crate::remedy::{Problem, Remedy};
use crate::study::sweep::{CaseError, CaseRecord, CaseResults, ContinuationLink, SweepRun};
use std::path::{Path, PathBuf};

/// Where the record of case `id` lives.
pub fn case_path(dir: &Path, id: usize) -> PathBuf {
    dir.join("cases").join(format!("{id}.json"))
}

/// Whether the first bytes of a file are a sweep case record's (so a new record may
/// replace it).
pub fn is_case_record(b: &[u8]) -> bool {
    let t = String::from_utf8_lossy(b);
    t.trim_start().starts_with('{') && t.contains("\"case_id\"") && t.contains("\"case_sha256\"")
}

/// Write the record of a finished case (or continuation point) into `cases` (the set's
/// `cases` folder); the record is the first and only file a case writes.
pub fn write_record(
    cases: &StateFolder,
    p: &Planned,
    keys: &[String],
    results: &CaseResults,
    continuation: Option<ContinuationLink>,
) -> Result<CaseRecord, CaseError> {
    let rec = CaseRecord::of(p.id, &p.hash, keys, &p.labels, results, continuation);
    let text = serde_json::to_string_pretty(&rec).map_err(|e| CaseError::Solve(e.into()))?;
    cases
        .write(&format!("{}.json", p.id), text.as_bytes(), is_case_record)
        .map_err(|e| CaseError::Solve(e.into()))?;
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
            Problem::new(e.to_string())
                .remedy(Remedy::new("delete it to recompute that case").path(case_path(dir, id)))
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(JobError::Input(problems))
    }
}

/// Recompute a random sample of the finished cases `done` (`study::sweep::verify`): a
/// record edited with a recomputed checksum is refused, naming it.
pub fn verify_finished(
    dir: &Path,
    done: &[(&Planned, &CaseRecord)],
    run: SweepRun,
) -> Result<(), JobError> {
    use crate::study::sweep::verify::{cases_to_recompute, verify_record};
    use rayon::prelude::*;
    let problems: Vec<Problem> = cases_to_recompute(done.len())
        .into_par_iter()
        .filter_map(|i| {
            let (p, rec) = done[i];
            // Recomputed as the sweep ran it (a wear case under its spectrum too).
            verify_record(&p.case, run, rec, &crate::duty::study::run_sweep_case)
                .err()
                .map(|e| {
                    Problem::new(format!("{}: {e}", case_path(dir, p.id).display())).remedy(
                        Remedy::new("delete it to recompute that case").path(case_path(dir, p.id)),
                    )
                })
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(JobError::Input(problems))
    }
}
