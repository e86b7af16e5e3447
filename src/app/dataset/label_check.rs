//! Every kept record's labels checked against what the design and the verified wear
//! trajectory give it (docs/RELIABILITY.md, "Datasets"). Recomputing a record's signal
//! and indicators takes a steady-state solve, so a resume or a merge recomputes only a
//! sample of states (`super::verify`); its labels (wear depths per flank, tooth and
//! stage, cycles, remaining cycles, limiting stage, speed, load, mesh frequency, fault
//! tables, noise seed) need no solve, and its indicators are a function of its signal
//! file as stored (`Record::round_to_stored`): so every kept record's labels are
//! recomputed here, the indicators from the record's own signal file (whose checksum the
//! sidecar holds). A label or indicator edited in a record no sample reaches is found all
//! the same; a signal edited together with its checksum only by the sample. A record's
//! CSV twin (when the design asks for one) is the signal file's samples written as text:
//! it is rendered again from the verified signal file and compared byte for byte, so an
//! edited, missing or swapped CSV is named as well.

use super::folder::{csv_rel, finished, read_in, sidecar_rel, Sidecar};
use super::kept::{first_difference, Kept};
use super::state_files::{
    planetary_inputs, planetary_state_model, state_inputs, state_model, StateJob,
};
use crate::checksum::sha256_hex;
use crate::signals::analysis::ChannelIndicators;
use crate::signals::files::record_table;
use crate::study::dataset::planetary_records::{
    planetary_expected_labels, planetary_record_csv, planetary_stored_indicators,
};
use crate::study::dataset::records::{expected_labels, stored_indicators, RecordLabels};
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
    let kept_of = |p: usize| -> Vec<(usize, Sidecar)> {
        let cars: Vec<_> = (0..job.plan.realisations)
            .filter_map(|r| finished(root, job.plan.record_id(p, r), job.key).map(|s| (r, s)))
            .collect();
        if kept == Kept::WholeStates && cars.len() < job.plan.realisations {
            return Vec::new();
        }
        cars
    };
    let held: Vec<(usize, Vec<(usize, Sidecar)>)> = states
        .iter()
        .map(|&p| (p, kept_of(p)))
        .filter(|(_, k)| !k.is_empty())
        .collect();
    let Some((first, _)) = held.first() else {
        return Vec::new();
    };
    if job.req.design.conditions[job.plan.state_index(*first).condition]
        .case
        .planetary
        .is_some()
    {
        return planetary_group_problems(job, root, held, kept);
    }
    let model = match state_model(job, job.plan.state_index(*first)) {
        Ok(m) => m,
        Err(e) => return vec![unrecomputable(root, *first, &e)],
    };
    // The states in parallel: each kept record's signal is read and analysed (the
    // check's main cost, about a record's analysis each).
    held.into_par_iter()
        .flat_map_iter(|(p, records)| {
            let ix = job.plan.state_index(p);
            let labelled = state_inputs(job, ix, &model).and_then(|inp| {
                let expected = expected_labels(&inp, job.plan, p, ix)?;
                Ok((inp, expected))
            });
            match labelled {
                Ok((inp, expected)) => records
                    .into_iter()
                    .filter_map(|(r, car)| {
                        let unit = inp.setup.chain.acquisition.unit;
                        let of = |b| {
                            let (rec, ind) = stored_indicators(&inp, b)?;
                            let csv = job.req.design.csv;
                            Ok((
                                ind,
                                csv.then(|| record_table(&rec, unit).to_csv()).transpose()?,
                            ))
                        };
                        record_problem(root, &of, car, &expected[r], kept)
                    })
                    .collect::<Vec<_>>(),
                Err(e) => vec![unrecomputable(root, p, &e)],
            }
        })
        .collect()
}

/// [`group_problems`] of a planetary condition's states `held` (each with its kept
/// records): the labels from the set's trajectory, the indicators from the stored files
/// (`study::dataset::planetary_records`).
fn planetary_group_problems(
    job: &StateJob,
    root: &Path,
    held: Vec<(usize, Vec<(usize, Sidecar)>)>,
    kept: Kept,
) -> Vec<String> {
    let first = held[0].0;
    let model = match planetary_state_model(job, job.plan.state_index(first)) {
        Ok(m) => m,
        Err(e) => return vec![unrecomputable(root, first, &e)],
    };
    held.into_par_iter()
        .flat_map_iter(|(p, records)| {
            let ix = job.plan.state_index(p);
            let labelled = planetary_inputs(job, ix, &model).and_then(|inp| {
                let expected = planetary_expected_labels(&inp, job.plan, p, ix)?;
                Ok((inp, expected))
            });
            match labelled {
                Ok((inp, expected)) => records
                    .into_iter()
                    .filter_map(|(r, car)| {
                        let of = |b| {
                            let (rec, ind) = planetary_stored_indicators(&inp, b)?;
                            let csv = job.req.design.csv;
                            Ok((ind, csv.then(|| planetary_record_csv(&rec)).transpose()?))
                        };
                        record_problem(root, &of, car, &expected[r], kept)
                    })
                    .collect::<Vec<_>>(),
                Err(e) => vec![unrecomputable(root, p, &e)],
            }
        })
        .collect()
}

/// What a kept record's check recomputes from its stored signal file: its indicators,
/// and its CSV twin's bytes when the design writes one.
type StoredCheck = (Vec<ChannelIndicators>, Option<Vec<u8>>);

/// The message of kept record `car` whose labels differ from `expected` (its indicators
/// recomputed here from its stored signal file by `stored`, e.g.
/// `records::stored_indicators`), or whose CSV twin is not the one its signal file
/// gives, if any.
fn record_problem(
    root: &Path,
    stored: &dyn Fn(Vec<u8>) -> anyhow::Result<StoredCheck>,
    car: Sidecar,
    expected: &RecordLabels,
    kept: Kept,
) -> Option<String> {
    let at = root.join(sidecar_rel(car.labels.record_id));
    let id = car.labels.record_id;
    // The signal file `finished` found whole; read again, and checked again against the
    // sidecar's checksum, since the folder may change in between.
    let signal = read_in(root, &car.labels.file)
        .filter(|b| sha256_hex(b) == car.signal_sha256)
        .ok_or_else(|| anyhow::anyhow!("it changed while it was checked"));
    let mut expected = expected.clone();
    match signal.and_then(stored) {
        Ok((indicators, csv)) => {
            expected.indicators = indicators;
            if let Some(what) = csv.and_then(|c| csv_difference(root, id, &c)) {
                return Some(format!("{}: {what}: {}", at.display(), advice(kept)));
            }
        }
        Err(e) => {
            return Some(format!(
                "{}: record {id}'s signal file cannot be read back ({e:#}): {}",
                at.display(),
                advice(kept)
            ))
        }
    }
    let what = label_difference(&car.labels, &expected)?;
    Some(format!(
        "{}: record {id}'s label {what}: {}",
        at.display(),
        advice(kept)
    ))
}

/// What is wrong with record `id`'s CSV twin in `root`, `None` when it is `expected` (the
/// bytes its verified signal file gives) byte for byte.
fn csv_difference(root: &Path, id: usize, expected: &[u8]) -> Option<String> {
    let rel = csv_rel(id);
    match read_in(root, &rel) {
        None => Some(format!("record {id}'s CSV twin {rel} is missing")),
        Some(kept) if kept == expected => None,
        Some(_) => Some(format!(
            "record {id}'s CSV twin {rel} does not hold the samples of its signal file"
        )),
    }
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
        "`{at}` is {a} in the file, {b} from the design, its verified wear trajectory and the record's signal file"
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
