//! A continuation sweep: the points of each branch run in order around the library's
//! ordered runner (`study::sweep::continuation`), with their records when the sweep has
//! an output folder.
//!
//! A point's record (`cases/<case_id>.json`) also holds its branch and the exact start and
//! end states, so a rerun skips a point only if it was computed from the very state the
//! resumed branch reaches it with: a resumed continuation follows the same path, bit for
//! bit, as an uninterrupted one.

use super::cases::Planned;
use super::records::{case_path, write_record};
use super::Ran;
use crate::config::Case;
use crate::io::output_dir::StateFolder;
use crate::study::sweep::continuation::{run_continuation, PointRun};
use crate::study::sweep::{Branch, CaseRecord, ContinuationLink, ContinuationPlan, SweepRow};
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// Run the branches of `c` (`planned` by case id), writing a record per computed point
/// into `dir` if given; points finished in an earlier run from the same start state are
/// skipped (a kept point only with the table's `columns`); each row with a helical
/// pair's columns when `helical` (the table has them).
/// `on_point` after every point, `keep_going` before each.
pub fn run_branches(
    (dir, helical, columns): (Option<(&Path, &StateFolder)>, bool, &[String]),
    c: &ContinuationPlan,
    planned: &[Planned],
    keys: &[String],
    on_point: &(dyn Fn() + Sync),
    keep_going: &(dyn Fn() -> bool + Sync),
) -> Ran {
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
    let rows = Mutex::new(BTreeMap::<usize, SweepRow>::new());
    let outcomes = Mutex::new(Vec::new());
    let keep = |id: usize, r: &CaseRecord| {
        if let (Some(row), Ok(mut m)) = (super::row_of(r), rows.lock()) {
            m.insert(id, row);
        }
    };
    let finished = |b: Branch, id: usize, start: Option<&[f64]>| {
        let (dir, _) = dir?;
        let p = by_id.get(&id)?;
        let r = CaseRecord::read(&case_path(dir, id)).ok()??;
        if !r.is_continuation_result_of(id, &p.hash, keys, &p.labels, b, start)
            || r.columns != columns
        {
            return None;
        }
        let end = r.continuation.as_ref()?.end_state()?;
        keep(id, &r);
        skipped.fetch_add(1, Ordering::Relaxed);
        Some(end)
    };
    let report = |b: Branch, id: usize, run: PointRun| {
        on_point();
        let Some(p) = by_id.get(&id) else { return };
        let outcome = match run {
            PointRun::Finished { .. } => return,
            PointRun::Failed { error, .. } => Err(error),
            PointRun::Computed {
                start,
                mut outcome,
                end_state,
            } => {
                outcome.results = outcome.results.with_helical_columns(helical);
                let link = ContinuationLink::new(b, start.as_deref(), &end_state);
                match dir {
                    Some((_, cases)) => write_record(cases, p, keys, &outcome.results, Some(link))
                        .map(|rec| keep(id, &rec)),
                    None => {
                        if let Ok(mut m) = rows.lock() {
                            m.insert(
                                id,
                                SweepRow {
                                    case_id: id,
                                    values: p.labels.clone(),
                                    results: outcome.results.clone(),
                                    branch: Some(b),
                                },
                            );
                        }
                        Ok(())
                    }
                }
                .map(|()| outcome.warnings)
            }
        };
        if let Ok(mut o) = outcomes.lock() {
            o.push((id, outcome));
        }
    };
    run_continuation(c, &cases, &finished, &report, keep_going);
    let mut outcomes = outcomes.into_inner().unwrap_or_default();
    outcomes.sort_by_key(|o| o.0);
    Ran {
        outcomes,
        rows: rows
            .into_inner()
            .unwrap_or_default()
            .into_values()
            .collect(),
        skipped: skipped.into_inner(),
    }
}
