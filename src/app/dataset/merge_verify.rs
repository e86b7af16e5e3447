//! A merge's inputs verified by recomputation before the target is opened
//! (docs/RELIABILITY.md, "Datasets"), as a resume verifies the records it reuses: each
//! shard's design rebuilt from its description (its design text, its conditions' cases,
//! the transfer-path file the merge is given, checked against the hash the description
//! keeps), the description recomputed from it and compared, then the first, the last
//! and a seeded random sample of the physical states the shard holds records of
//! (`study::dataset::verify::states_to_recompute`, the resume's rule) recomputed and
//! compared with the shard's files bit for bit (signal, CSV, labels and indicators).

use super::folder::{read_in, sidecars, trajectories, DATASET_REL};
use super::index_files::matches_design;
use super::kept::Kept;
use super::label_check::kept_label_problems;
use super::plan::{check_dataset, dataset_key, description};
use super::request::{DatasetError, DatasetRequest};
use super::state_files::StateJob;
use super::verify::{os_seed, verify_states};
use crate::checksum::sha256_hex;
use crate::signals::transfer::TransferPath;
use crate::study::budget::{estimate_dataset_check, Estimate};
use crate::study::dataset::plan::{plan_of, Shard};
use crate::study::dataset::verify::{states_to_recompute, MAX_RECOMPUTED_STATES};
use crate::study::dataset::{design_of_cases, DatasetDesign, Defaults};
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The transfer-path file a merge was given: where it is, its parsed path and its bytes.
pub(crate) type GivenPath<'a> = Option<(&'a Path, &'a TransferPath, &'a [u8])>;

/// Verify every shard in `inputs` (of the dataset `key`) by recomputation (module docs);
/// `given`: the transfer-path file given to the merge. One message per problem, each
/// naming the input folder (and the record and what differs).
pub(super) fn verify_inputs(
    inputs: &[&Path],
    key: &str,
    given: GivenPath,
) -> Result<(), DatasetError> {
    let seed = os_seed();
    let mut problems = Vec::new();
    for dir in inputs {
        if let Err(p) = verify_input(dir, key, given, seed) {
            problems.extend(p);
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(DatasetError::Input(problems))
    }
}

/// The cost of [`verify_inputs`] (`study::budget::estimate_dataset_check`), summed over
/// the shards in `inputs` before any is verified: each shard's design rebuilt from its
/// description, its record size checked, the records and states it holds counted by
/// their sidecars' names (nothing read: a foreign sidecar is counted too); the shards are verified one after another, so the memory is the largest
/// shard's. A shard whose design cannot be rebuilt adds nothing: its verification
/// refuses it before any work.
pub(super) fn verify_estimate(inputs: &[&Path], given: GivenPath, threads: usize) -> Estimate {
    let mut sum: Option<Estimate> = None;
    for dir in inputs {
        let Some(e) = shard_estimate(dir, given, threads) else {
            continue;
        };
        match &mut sum {
            None => sum = Some(e),
            Some(s) => {
                for (a, b) in s.terms.iter_mut().zip(&e.terms) {
                    a.seconds += b.seconds;
                    a.bytes = a.bytes.max(b.bytes);
                }
            }
        }
    }
    sum.unwrap_or_else(|| Estimate::of_terms(Vec::new()))
}

/// [`verify_estimate`] of one shard, `None` when its design cannot be rebuilt.
fn shard_estimate(dir: &Path, given: GivenPath, threads: usize) -> Option<Estimate> {
    let body = read_in(dir, DATASET_REL).and_then(|b| serde_json::from_slice::<Value>(&b).ok())?;
    let d = design_of(dir, &body).ok()?;
    let (path, path_bytes) = path_of(dir, &d, &body, given).ok()?;
    let req = whole_request(&d, path, path_bytes);
    let checked = check_dataset(&req).ok()?;
    // Counted from the sidecars' names, before any is read (issue 33).
    let kept = super::folder::kept_by_names(dir, &d);
    Some(estimate_dataset_check(&d, kept, threads, checked.record))
}

/// The request that recomputes a shard of design `d` (through `path`, whose file's bytes
/// are `path_bytes`): the whole design, as one shard.
fn whole_request<'a>(
    d: &'a DatasetDesign,
    path: Option<TransferPath>,
    path_bytes: &[u8],
) -> DatasetRequest<'a> {
    DatasetRequest {
        design: d,
        path,
        path_bytes: path_bytes.to_vec(),
        shard: Shard { index: 1, count: 1 },
        figures: Default::default(),
        replace: false,
    }
}

/// The design a shard's description `body` gives (module docs), named after `dir`.
fn design_of(dir: &Path, body: &Value) -> Result<DatasetDesign, Vec<String>> {
    let name = dir.join(DATASET_REL).display().to_string();
    let cases: Option<Vec<String>> = body["cases"].as_array().and_then(|cs| {
        cs.iter()
            .map(|c| c["case_toml"].as_str().map(str::to_owned))
            .collect()
    });
    let first = |v: &Value| v.as_array().and_then(|a| a.first()).and_then(Value::as_f64);
    let defaults = (|| {
        Some(Defaults {
            max_cycles: body["run_to_failure"]["max_cycles"].as_f64()?,
            speed_hz: first(&body["axes"]["input_speed_hz"])?,
            torque_nm: first(&body["axes"]["load_torque_nm"])?,
        })
    })();
    let (Some(text), Some(cases), Some(defaults)) = (body["design"].as_str(), cases, defaults)
    else {
        return Err(vec![format!(
            "{name}: no design, cases or axes to recompute the records from: a damaged or edited shard"
        )]);
    };
    design_of_cases(text, &name, &cases, defaults)
}

/// The transfer path the shard's design `d` needs, from the file given to the merge,
/// checked against the hash its description `body` keeps.
fn path_of<'a>(
    dir: &Path,
    d: &DatasetDesign,
    body: &Value,
    given: GivenPath<'a>,
) -> Result<(Option<TransferPath>, &'a [u8]), String> {
    let kept = body["transfer_path_sha256"].as_str().unwrap_or_default();
    match (&d.transfer_path, given) {
        (None, None) => Ok((None, &[])),
        (None, Some((file, _, _))) => Err(format!(
            "{}: its design uses no transfer-path file (the generic housing), yet the merge was given the transfer path {}: leave it out",
            dir.display(),
            file.display()
        )),
        (Some(named), None) => Err(format!(
            "{}: its design's records are made through the transfer-path file `{}` (SHA-256 {}...): give the merge that file as its transfer path to recompute them",
            dir.display(),
            named.display(),
            kept.chars().take(12).collect::<String>()
        )),
        (Some(_), Some((_, path, bytes))) if sha256_hex(bytes) == kept => {
            Ok((Some(path.clone()), bytes))
        }
        (Some(named), Some((file, _, bytes))) => Err(format!(
            "{}: the merge's transfer path {} (SHA-256 {}...) is not the file `{}` its design was made with (SHA-256 {}...)",
            dir.display(),
            file.display(),
            &sha256_hex(bytes)[..12],
            named.display(),
            kept.chars().take(12).collect::<String>()
        )),
    }
}

/// Verify one shard `dir` (module docs), its sample drawn by `seed`.
fn verify_input(dir: &Path, key: &str, given: GivenPath, seed: u64) -> Result<(), Vec<String>> {
    let Some(body) =
        read_in(dir, DATASET_REL).and_then(|b| serde_json::from_slice::<Value>(&b).ok())
    else {
        return Err(vec![format!("{}: no {DATASET_REL}", dir.display())]);
    };
    let d = design_of(dir, &body)?;
    let (path, path_bytes) = path_of(dir, &d, &body, given).map_err(|e| vec![e])?;
    let req = whole_request(&d, path, path_bytes);
    let in_dir = |m: String| format!("{}: {m}", dir.display());
    let checked = check_dataset(&req).map_err(|e| vec![in_dir(e.to_string())])?;
    let own_key = dataset_key(&d, &req.path_bytes);
    if own_key != key || description(&req, &checked.setups, key) != body {
        return Err(vec![format!(
            "{}: {DATASET_REL} is not the description its own design gives (recomputed): a damaged or edited shard",
            dir.display()
        )]);
    }
    let plan = plan_of(&d);
    // Trajectories: already recomputed by the wear law (`merge::check_trajectories`).
    let kept: BTreeMap<String, _> = trajectories(dir)
        .into_iter()
        .filter(|t| t.dataset_key == key)
        .map(|t| (t.condition, t.trajectory))
        .collect();
    let trajectories: BTreeMap<usize, _> = d
        .conditions
        .iter()
        .enumerate()
        .filter_map(|(c, cond)| kept.get(&cond.name).map(|t| (c, t.clone())))
        .collect();
    // The physical states the shard holds records of that the merge indexes: under the
    // key, their identity the one the design gives their id, their signal the one they
    // name (any other is counted missing and named by the merge).
    let held: Vec<usize> = sidecars(dir)
        .into_iter()
        .filter(|s| {
            s.dataset_key == key
                && s.labels.record_id < plan.records()
                && matches_design(&s.labels, &body)
                && read_in(dir, &s.labels.file).map(|b| sha256_hex(&b))
                    == Some(s.signal_sha256.clone())
        })
        .map(|s| s.labels.record_id / plan.realisations)
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    let drawn: Vec<usize> = states_to_recompute(held.len(), MAX_RECOMPUTED_STATES, seed)
        .into_iter()
        .map(|i| held[i])
        .collect();
    let mut problems = Vec::new();
    let sample: Vec<usize> = drawn
        .iter()
        .copied()
        .filter(|p| {
            let c = plan.state_index(*p).condition;
            let has = trajectories.contains_key(&c);
            if !has {
                problems.push(format!(
                    "{}: physical state {p} has records but condition `{}` no trajectory in state/: they cannot be recomputed (a damaged or edited shard)",
                    dir.display(),
                    d.conditions[c].name
                ));
            }
            has
        })
        .collect();
    let job = StateJob {
        req: &req,
        plan: &plan,
        setups: &checked.setups,
        trajectories: &trajectories,
        key,
    };
    problems.extend(verify_states(&job, dir, &sample, Kept::Finished));
    // Every other held record's labels, recomputed from the verified trajectories (a
    // state of a condition without one is named above when sampled, and here otherwise).
    problems.extend(kept_label_problems(
        &job,
        dir,
        held.iter().copied().filter(|p| !drawn.contains(p)),
        Kept::Finished,
    ));
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems)
    }
}
