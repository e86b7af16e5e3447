//! Every kept record's labels checked against what the design and the verified wear
//! trajectory give it (docs/RELIABILITY.md, "Datasets"). Recomputing a record's signal
//! and indicators takes a steady-state solve, so a resume or a merge recomputes only a
//! sample of states (`super::verify`); its labels (wear depths per flank, tooth and
//! stage, cycles, remaining cycles, limiting stage, speed, load, mesh frequency, fault
//! tables, noise seed) need no solve, so every kept record's are recomputed here: a
//! label edited in a record no sample reaches is found all the same.

use super::folder::{finished, sidecar_rel};
use super::kept::{first_difference, Kept};
use super::state_files::{state_inputs, state_model, StateJob};
use crate::study::dataset::records::{expected_labels, RecordLabels};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;

/// The labels of every finished record of `states` in `root` (for [`Kept::WholeStates`],
/// of the states whose records are all finished: the others are recomputed whole)
/// compared with the labels the design and the job's trajectories give them, indicators
/// aside. One message per record whose labels differ (the first differing field named)
/// and per state whose labels cannot be recomputed.
pub(super) fn kept_label_problems(
    job: &StateJob,
    root: &Path,
    states: impl Iterator<Item = usize>,
    kept: Kept,
) -> Vec<String> {
    // Grouped by condition, speed and load: one model per group.
    let mut groups: BTreeMap<(usize, usize, usize), Vec<usize>> = BTreeMap::new();
    for p in states {
        let ix = job.plan.state_index(p);
        groups
            .entry((ix.condition, ix.speed, ix.load))
            .or_default()
            .push(p);
    }
    groups
        .into_par_iter()
        .flat_map_iter(|(_, states)| group_problems(job, root, &states, kept))
        .collect()
}

/// [`kept_label_problems`] of the states of one condition, speed and load.
fn group_problems(job: &StateJob, root: &Path, states: &[usize], kept: Kept) -> Vec<String> {
    let kept_of = |p: usize| -> Vec<(usize, RecordLabels)> {
        let cars: Vec<_> = (0..job.plan.realisations)
            .filter_map(|r| finished(root, job.plan.record_id(p, r), job.key).map(|s| (r, s)))
            .collect();
        if kept == Kept::WholeStates && cars.len() < job.plan.realisations {
            return Vec::new();
        }
        cars.into_iter().map(|(r, s)| (r, s.labels)).collect()
    };
    let held: Vec<(usize, Vec<(usize, RecordLabels)>)> = states
        .iter()
        .map(|&p| (p, kept_of(p)))
        .filter(|(_, k)| !k.is_empty())
        .collect();
    let Some((first, _)) = held.first() else {
        return Vec::new();
    };
    let model = match state_model(job, job.plan.state_index(*first)) {
        Ok(m) => m,
        Err(e) => return vec![unrecomputable(root, *first, &e)],
    };
    let mut problems = Vec::new();
    for (p, records) in held {
        let ix = job.plan.state_index(p);
        let expected =
            state_inputs(job, ix, &model).and_then(|inp| expected_labels(&inp, job.plan, p, ix));
        let expected = match expected {
            Ok(e) => e,
            Err(e) => {
                problems.push(unrecomputable(root, p, &e));
                continue;
            }
        };
        for (r, mut labels) in records {
            labels.indicators.clear();
            if let Some(what) = label_difference(&labels, &expected[r]) {
                problems.push(format!(
                    "{}: record {}'s label {what}: {}",
                    root.join(sidecar_rel(labels.record_id)).display(),
                    labels.record_id,
                    advice(kept)
                ));
            }
        }
    }
    problems
}

/// The first field in which `kept` and `expected` differ, with both values, `None` when
/// they are equal.
fn label_difference(kept: &RecordLabels, expected: &RecordLabels) -> Option<String> {
    if kept == expected {
        return None;
    }
    let json = |l: &RecordLabels| serde_json::to_value(l).unwrap_or_default();
    let (at, a, b) = first_difference(&json(kept), &json(expected), "")?;
    Some(format!(
        "`{at}` is {a} in the file, {b} from the design and its verified wear trajectory"
    ))
}

/// What the user can do about a record whose labels are false.
fn advice(kept: Kept) -> &'static str {
    match kept {
        Kept::WholeStates | Kept::InFolder => {
            "the record was edited or is not this design's (delete its sidecar to recompute it)"
        }
        Kept::Finished => {
            "the record was edited or is not its design's: a damaged or edited shard, not merged"
        }
    }
}

/// The message of physical state `p` whose labels cannot be recomputed.
fn unrecomputable(root: &Path, p: usize, e: &anyhow::Error) -> String {
    format!(
        "{}: physical state {p}: the labels of its finished records cannot be recomputed ({e:#}): they are not this design's",
        root.display()
    )
}
