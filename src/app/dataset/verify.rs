//! A dataset folder verified by recomputation (docs/RELIABILITY.md, "Datasets"): the
//! finished records of a sample of physical states computed again from the design and
//! compared with the files byte for byte, the kept trajectories recomputed by the wear
//! law (`study::dataset::verify`), and every sidecar's identity checked against the
//! design. A resumed run checks its shard's sample before it reuses anything
//! (`verify_states`); [`verify_dataset`] checks a whole folder.

use super::folder::{
    csv_rel, existing_key, finished, read_in, sidecar_rel, sidecars, trajectory_rel, Sidecar,
    TrajectoryFile,
};
use super::index_files::matches_design;
use super::kept::{first_difference, Kept};
use super::label_check::kept_label_problems;
use super::plan::{check_dataset, dataset_key, description};
use super::request::{DatasetError, DatasetRequest};
use super::state_files::{state_files, RecordFiles, StateJob};
use crate::checksum::sha256_hex;
use crate::study::dataset::plan::plan_of;
use crate::study::dataset::planetary::verify_case_trajectory;
use crate::study::dataset::verify::states_to_recompute;
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A seed from the operating system's randomness (a forger cannot know which records a
/// resume will recompute).
pub fn os_seed() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u64(0x6765_6172_7765_6172);
    h.finish()
}

/// The refusal of a kept file that does not recompute: its path, what differs, and the
/// way out.
pub(super) fn kept_file_problem(root: &Path, rel: &str, what: &str) -> DatasetError {
    DatasetError::Input(vec![format!(
        "{}: {what}: the file was edited or is not this design's (delete it to recompute it)",
        root.join(rel).display()
    )])
}

/// Recompute the records of each physical state in `states` that `kept` selects in
/// `root` and compare them with the files byte for byte (signal, CSV when the design
/// writes it, sidecar with labels and indicators, its first differing field named). One
/// message per record that differs or fails to recompute.
pub(super) fn verify_states(
    job: &StateJob,
    root: &Path,
    states: &[usize],
    kept: Kept,
) -> Vec<String> {
    states
        .par_iter()
        .flat_map_iter(|&p| {
            let ids: Vec<usize> = (0..job.plan.realisations)
                .map(|r| job.plan.record_id(p, r))
                .filter(|id| finished(root, *id, job.key).is_some())
                .collect();
            if ids.is_empty() || (kept == Kept::WholeStates && ids.len() < job.plan.realisations) {
                return Vec::new();
            }
            let mut problems = Vec::new();
            let r = state_files(job, p, &mut |f| {
                if !ids.contains(&f.id) {
                    return Ok(());
                }
                if let Some((what, rel)) = record_difference(root, &f) {
                    let advice = match kept {
                        Kept::WholeStates | Kept::InFolder => format!(
                            "the record was edited or is not this design's (delete {} to recompute it)",
                            root.join(sidecar_rel(f.id)).display()
                        ),
                        Kept::Finished => {
                            "the record was edited or is not its design's: a damaged or edited shard, not merged".to_owned()
                        }
                    };
                    problems.push(format!(
                        "{}: record {} recomputed from the design has another {what}: {advice}",
                        root.join(&rel).display(),
                        f.id,
                    ));
                }
                Ok(())
            });
            if let Err(e) = r {
                problems.push(format!(
                    "{}: physical state {p}: its finished records cannot be recomputed ({e:#}): they are not this design's",
                    root.display()
                ));
            }
            problems
        })
        .collect()
}

/// What of the record `f` recomputed differs from its files in `root` (what, and the
/// file), `None` when every file is the same byte for byte.
fn record_difference(root: &Path, f: &RecordFiles) -> Option<(String, String)> {
    let kept = |rel: &str| read_in(root, rel);
    if kept(&f.signal_rel).as_deref() != Some(&f.signal[..]) {
        return Some(("signal".into(), f.signal_rel.clone()));
    }
    if let Some(c) = &f.csv {
        if kept(&csv_rel(f.id)).as_deref() != Some(&c[..]) {
            return Some(("CSV".into(), csv_rel(f.id)));
        }
    }
    let rel = sidecar_rel(f.id);
    let file = kept(&rel)?;
    if file == f.sidecar {
        return None;
    }
    let parse = |b: &[u8]| serde_json::from_slice::<serde_json::Value>(b).ok();
    let what = match (parse(&file), parse(&f.sidecar)) {
        (Some(a), Some(b)) => first_difference(&a, &b, "")
            .map(|(at, a, b)| format!("`{at}` ({a} in the file, {b} recomputed)")),
        _ => None,
    };
    Some((
        what.map_or_else(
            || "sidecar".to_owned(),
            |w| format!("label or indicator {w}"),
        ),
        rel,
    ))
}

/// What [`verify_dataset`] checked and found.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Verified {
    /// Sidecars in the folder (whatever their state).
    pub records_present: usize,
    /// Physical states whose records were recomputed and compared.
    pub states_recomputed: Vec<usize>,
    /// Conditions whose kept trajectory the wear law recomputed.
    pub trajectories_verified: usize,
    /// Everything that is not what the design gives, one message each (empty: verified).
    pub problems: Vec<String>,
}

/// Verify the dataset of `req` in `root` (module docs): every sidecar's identity, every
/// kept trajectory, and the finished records of the first and last physical state and
/// `sample - 2` others drawn by `seed` (`study::dataset::verify`), recomputed bit for
/// bit. Refused (exit 2) when the design is invalid or the folder holds another design.
pub fn verify_dataset(
    req: &DatasetRequest,
    root: &Path,
    sample: usize,
    seed: u64,
) -> Result<Verified, DatasetError> {
    let d = req.design;
    let checked = check_dataset(req)?;
    let key = dataset_key(d, &req.path_bytes);
    match existing_key(root).map_err(|e| DatasetError::Input(vec![e.to_string()]))? {
        Some(k) if k == key => {}
        _ => {
            return Err(DatasetError::Input(vec![format!(
                "{}: holds no dataset of this design",
                root.display()
            )]))
        }
    }
    let plan = plan_of(d);
    let body = description(req, &checked.setups, &key);
    let mut v = Verified::default();
    let mut trajectories = BTreeMap::new();
    for (c, cond) in d.conditions.iter().enumerate() {
        let rel = trajectory_rel(&cond.name);
        let Some(t) = read_in(root, &rel)
            .and_then(|b| serde_json::from_slice::<TrajectoryFile>(&b).ok())
            .filter(|t| t.dataset_key == key && t.condition == cond.name)
        else {
            v.problems.push(format!(
                "{}: missing or unreadable",
                root.join(&rel).display()
            ));
            continue;
        };
        match verify_case_trajectory(
            &cond.case,
            d.max_cycles,
            d.wear_limit_um * 1e-6,
            &t.trajectory,
        ) {
            Ok(()) => {
                v.trajectories_verified += 1;
                trajectories.insert(c, t.trajectory);
            }
            Err(e) => v
                .problems
                .push(format!("{}: {e}", root.join(&rel).display())),
        }
    }
    let cars = sidecars(root);
    v.records_present = cars.len();
    v.problems.extend(identity_problems(
        root,
        &cars,
        (&key, &body),
        plan.records(),
    ));
    let job = StateJob {
        req,
        plan: &plan,
        setups: &checked.setups,
        trajectories: &trajectories,
        key: &key,
    };
    v.states_recomputed = states_to_recompute(plan.physical_states(), sample, seed)
        .into_iter()
        .filter(|p| trajectories.contains_key(&plan.state_index(*p).condition))
        .collect();
    v.problems.extend(verify_states(
        &job,
        root,
        &v.states_recomputed,
        Kept::WholeStates,
    ));
    // Every finished record's labels (those of the recomputed states compared above).
    let recomputed: BTreeSet<usize> = v.states_recomputed.iter().copied().collect();
    let held: BTreeSet<usize> = cars
        .iter()
        .map(|s| s.labels.record_id)
        .filter(|id| *id < plan.records())
        .map(|id| id / plan.realisations)
        .filter(|p| !recomputed.contains(p))
        .filter(|p| trajectories.contains_key(&plan.state_index(*p).condition))
        .collect();
    v.problems.extend(kept_label_problems(
        &job,
        root,
        held.into_iter(),
        Kept::InFolder,
    ));
    Ok(v)
}

/// Every sidecar of `cars` in `root` whose identity is not the one the design (`key`,
/// its description `body`) gives its id among `records`, or whose signal is not the one
/// it names: one message each.
fn identity_problems(
    root: &Path,
    cars: &[Sidecar],
    (key, body): (&str, &serde_json::Value),
    records: usize,
) -> Vec<String> {
    cars.iter()
        .filter_map(|s| {
            let id = s.labels.record_id;
            let problem = if s.dataset_key != key {
                "another design's record"
            } else if id >= records {
                "its id is beyond the design's records"
            } else if !matches_design(&s.labels, body) {
                "its labels are not those the design gives its id"
            } else if read_in(root, &s.labels.file).map(|b| sha256_hex(&b))
                != Some(s.signal_sha256.clone())
            {
                "its signal file is missing or not the one it names"
            } else {
                return None;
            };
            Some(format!(
                "{}: {problem}",
                root.join(sidecar_rel(id)).display()
            ))
        })
        .collect()
}
