//! `gearwear sweep --continuation`: the checks, and the record files of the points of
//! each branch around the library's ordered runner (`study::sweep::continuation`).
//!
//! A point's record (`cases/<case_id>.json`) also holds its branch and the exact start and
//! end states, so a rerun skips a point only if it was computed from the very state the
//! resumed branch reaches it with: a resumed continuation follows the same path, bit for
//! bit, as an uninterrupted one.

use super::args::{ContinuationArg, SweepArgs, SweepRunArg};
use super::sweep_records::{case_path, write_record, Outcomes, Planned};
use super::CliError;
use crate::config::Case;
use crate::dynamics::model::NSTATE;
use crate::io::output_dir::StateFolder;
use crate::study::sweep::continuation::{run_continuation, PointRun};
use crate::study::sweep::{
    Branch, CaseRecord, Continuation, ContinuationLink, ContinuationPlan, SweepPlan, SweepRun,
};
use indicatif::ProgressBar;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// The continuation checks: one axis, `--run dynamics`, no `--shard`.
pub fn continuation_of(
    a: &SweepArgs,
    plan: &SweepPlan,
) -> Result<Option<ContinuationPlan>, CliError> {
    let Some(c) = a.continuation else {
        return Ok(None);
    };
    if let Some(s) = &a.shard {
        return Err(CliError::input(format!(
            "--continuation with --shard {s}: a branch runs in order, point after point, so it cannot be split into shards"
        )));
    }
    if a.run != SweepRunArg::Dynamics {
        return Err(CliError::input(
            "--continuation needs --run dynamics (the wear study is not warm-started along a branch)",
        ));
    }
    let c = match c {
        ContinuationArg::Up => Continuation::Up,
        ContinuationArg::Down => Continuation::Down,
        ContinuationArg::Both => Continuation::Both,
    };
    ContinuationPlan::new(plan, c)
        .map(Some)
        .map_err(CliError::input)
}

/// Run the branches of a continuation sweep (`planned` by case id), writing a record per
/// computed point; points finished in an earlier run from the same start state are
/// skipped. Returns the outcome of each point run now, the records of the table, and the
/// number of points skipped.
pub fn run_branches(
    dir: &Path,
    cases_folder: &StateFolder,
    c: &ContinuationPlan,
    planned: &[Planned],
    keys: &[String],
    pb: &ProgressBar,
) -> (Outcomes, Vec<CaseRecord>, usize) {
    let by_id: BTreeMap<usize, &Planned> = planned.iter().map(|p| (p.id, p)).collect();
    // The resolved case of each value of the axis (the same on every branch).
    let mut cases: Vec<Case> = Vec::new();
    for (_, points) in &c.branches {
        for x in points {
            if let Some(p) = by_id.get(&x.case_id) {
                if cases.len() <= x.value_index {
                    cases.resize(x.value_index + 1, p.case.clone());
                }
                cases[x.value_index] = p.case.clone();
            }
        }
    }
    let skipped = AtomicUsize::new(0);
    let records = Mutex::new(BTreeMap::<usize, CaseRecord>::new());
    let outcomes = Mutex::new(Vec::new());
    let finished = |b: Branch, id: usize, start: Option<&[f64; NSTATE]>| {
        let p = by_id.get(&id)?;
        let r = CaseRecord::read(&case_path(dir, id)).ok()??;
        if !r.is_continuation_result_of(id, &p.hash, keys, &p.values, b, start) {
            return None;
        }
        let end = r.continuation.as_ref()?.end_state()?;
        records.lock().ok()?.insert(id, r);
        skipped.fetch_add(1, Ordering::Relaxed);
        Some(end)
    };
    let report = |b: Branch, id: usize, run: PointRun| {
        pb.inc(1);
        let Some(p) = by_id.get(&id) else { return };
        let outcome = match run {
            PointRun::Finished { .. } => return,
            PointRun::Failed { error, .. } => Err(error),
            PointRun::Computed {
                start,
                outcome,
                end_state,
            } => {
                let link = ContinuationLink::new(b, start.as_ref(), &end_state);
                write_record(
                    cases_folder,
                    p,
                    SweepRun::Dynamics,
                    keys,
                    &outcome.results,
                    Some(link),
                )
                .map(|rec| {
                    if let Ok(mut m) = records.lock() {
                        m.insert(id, rec);
                    }
                    outcome.warnings
                })
            }
        };
        if let Ok(mut o) = outcomes.lock() {
            o.push((id, outcome));
        }
    };
    run_continuation(c, &cases, &finished, &report);
    let records: Vec<CaseRecord> = records
        .into_inner()
        .unwrap_or_default()
        .into_values()
        .collect();
    let mut outcomes = outcomes.into_inner().unwrap_or_default();
    outcomes.sort_by_key(|o| o.0);
    (outcomes, records, skipped.into_inner())
}
