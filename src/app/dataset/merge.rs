//! Joining the shards of a dataset: checked to be shards of one design before any output
//! folder is opened, their records and state files copied, then the index and metadata
//! built as an unsharded run builds them.

use super::folder::{
    copy_dataset, csv_rel, is_file_in, key_shown, read_in, sidecar_rel, sidecars, trajectories,
    trajectory_rel, DATASET_REL,
};
use super::index_files::stage_index_and_metadata;
use super::plan::key_of_description;
use super::request::{DatasetError, DatasetOutcome};
use crate::io::OutputDir;
use crate::report::figure_output::FigureOutput;
use serde_json::Value;
use std::path::Path;

/// The dataset key and record count the shards in `inputs` share, read and checked
/// before any output folder is opened: every input a dataset folder of one design, its
/// record count the one its axes give.
pub(super) fn shared_key(inputs: &[&Path]) -> Result<(String, usize), DatasetError> {
    let mut key: Option<(String, usize)> = None;
    let mut first_bytes: Option<Vec<u8>> = None;
    let mut problems = Vec::new();
    for dir in inputs {
        let bytes = read_in(dir, DATASET_REL);
        let (k, total) = match check_description(dir, bytes.as_deref()) {
            Ok(kt) => kt,
            Err(p) => {
                problems.push(p.to_string());
                continue;
            }
        };
        match &first_bytes {
            None => first_bytes = bytes,
            Some(b)
                if Some(b) != bytes.as_ref() && key.as_ref().is_some_and(|(k0, _)| *k0 == k) =>
            {
                problems.push(format!(
                    "{}: {DATASET_REL} differs from the first input's under the same dataset key: a damaged or edited shard",
                    dir.display()
                ));
                continue;
            }
            Some(_) => {}
        }
        match &key {
            None => key = Some((k, total)),
            Some((k0, _)) if *k0 != k => problems.push(format!(
                "{}: a shard of another dataset (dataset key {}..., the first input has {}...): merge shards of one design only",
                dir.display(),
                key_shown(&k),
                key_shown(k0)
            )),
            _ => {}
        }
    }
    key.filter(|_| problems.is_empty())
        .ok_or(DatasetError::Input(problems))
}

/// A shard's description (`state/dataset.json` of the folder `dir`, its bytes as read,
/// `None` when unreadable) checked as a merge checks it before any output folder is
/// opened: a JSON object with a dataset key; its record count the one its axes give
/// (conditions x states x speeds x loads x noise realisations, in checked arithmetic) and
/// at most `MAX_RECORDS`; its key the one its own design, cases, transfer-path hash and
/// version give. Returns the key and the record count, or the problem naming `dir`.
/// Public for the fuzz target `fuzz/fuzz_targets/dataset_shard.rs` (docs/RELIABILITY.md).
pub fn check_description(dir: &Path, bytes: Option<&[u8]>) -> Result<(String, usize), ShardError> {
    let body: Option<Value> = bytes.and_then(|b| serde_json::from_slice(b).ok());
    let Some(body) = body else {
        return Err(ShardError::NotDataset(dir.to_owned()));
    };
    let k = body["dataset_key"].as_str().unwrap_or_default().to_owned();
    let total = body["records"].as_u64().unwrap_or(0) as usize;
    // The record count is trusted only when the axes beside it give it: a shard
    // edited to claim 2e9 records would otherwise size the index's missing list.
    if axes_records(&body) != Some(total)
        || total as u64 > crate::study::dataset::design::MAX_RECORDS
    {
        return Err(ShardError::RecordCount {
            dir: dir.to_owned(),
            total,
        });
    }
    // The metadata is written from the description: it must be the one its design
    // gives (its key recomputed from its own design, cases and transfer path), and
    // the same in every shard ([`shared_key`]).
    if key_of_description(&body).as_deref() != Some(k.as_str()) {
        return Err(ShardError::EditedKey(dir.to_owned()));
    }
    Ok((k, total))
}

/// Why a merge input's description is refused (each message names its folder).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ShardError {
    /// No readable description: not a dataset folder, or a run not yet started.
    #[error("{}: no {DATASET_REL}: not a dataset folder (or not started)", .0.display())]
    NotDataset(std::path::PathBuf),
    /// The record count differs from the one its axes give, or is over the limit.
    #[error("{}: {DATASET_REL} claims {total} records, which its axes do not give (conditions x states x speeds x loads x noise realisations): a damaged or edited shard", .dir.display())]
    RecordCount {
        /// The input folder.
        dir: std::path::PathBuf,
        /// The record count it claims.
        total: usize,
    },
    /// The key is not the one its own design, cases and transfer path give.
    #[error("{}: {DATASET_REL} does not give its own dataset key (its design, cases or transfer path were edited): a damaged or edited shard", .0.display())]
    EditedKey(std::path::PathBuf),
}

/// Joins the shards in `inputs` (checked by [`shared_key`], which gave `key` and
/// `total`) into `root`, its figure written as `figures` says.
pub(super) fn merge_datasets(
    inputs: &[&Path],
    root: &Path,
    mut out: OutputDir,
    (key, total): (String, usize),
    figures: FigureOutput,
) -> Result<DatasetOutcome, DatasetError> {
    // Marked until published: a merge that fails half-way leaves the folder marked.
    out.mark_incomplete()
        .map_err(|e| DatasetError::Failed(e.into()))?;
    let (mut copied, mut skipped) = (0, Vec::new());
    for dir in inputs {
        let (n, bad) = copy_dataset(dir, root, &key, out.previous_state())
            .map_err(|e| DatasetError::Failed(e.into()))?;
        copied += n;
        skipped.extend(bad);
    }
    let missing = stage_index_and_metadata(&mut out, root, total, figures)
        .map_err(|e| DatasetError::Failed(anyhow::anyhow!("{e}")))?;
    out.keep_state(DATASET_REL);
    for s in sidecars(root).into_iter().filter(|s| s.dataset_key == key) {
        out.keep_state(&s.labels.file);
        out.keep_state(&sidecar_rel(s.labels.record_id));
        if is_file_in(root, &csv_rel(s.labels.record_id)) {
            out.keep_state(&csv_rel(s.labels.record_id));
        }
    }
    for t in trajectories(root) {
        out.keep_state(&trajectory_rel(&t.condition));
    }
    out.publish().map_err(|e| DatasetError::Failed(e.into()))?;
    Ok(DatasetOutcome {
        total_records: total,
        shard_records: total,
        computed: 0,
        reused: copied,
        failures: skipped,
        missing,
        estimated_bytes: 0.0,
    })
}

/// Records the axes of a dataset's description give: conditions x states x speeds x
/// loads x noise realisations (each a whole, positive count); `None` when an axis is
/// missing, empty or the product overflows.
fn axes_records(body: &Value) -> Option<usize> {
    let a = &body["axes"];
    let len = |v: &Value| v.as_array().map(Vec::len).filter(|n| *n > 0);
    let states = match (&a["states"]["evenly_spaced"], &a["states"]["cycles"]) {
        (n, _) if n.is_u64() => n.as_u64().map(|n| n as usize).filter(|n| *n > 0),
        (_, c) => len(c),
    }?;
    let realisations = a["noise_realisations"]
        .as_u64()
        .map(|n| n as usize)
        .filter(|n| *n > 0)?;
    [
        len(&a["conditions"])?,
        states,
        len(&a["input_speed_hz"])?,
        len(&a["load_torque_nm"])?,
        realisations,
    ]
    .iter()
    .try_fold(1_usize, |acc, n| acc.checked_mul(*n))
}

/// Every kept trajectory of the shards in `inputs` (of the dataset `key`) recomputed by
/// the wear law of its condition's case, as the description gives it
/// (`study::dataset::verify::verify_trajectory`): checked before the target is opened,
/// so a forged trajectory (wear scaled, cut short, failure moved) is refused, naming
/// its file, and the target is untouched.
pub(super) fn check_trajectories(inputs: &[&Path], key: &str) -> Result<(), DatasetError> {
    use crate::study::dataset::planetary::verify_case_trajectory;
    use rayon::prelude::*;
    let mut jobs = Vec::new();
    for dir in inputs {
        let Some(body) =
            read_in(dir, DATASET_REL).and_then(|b| serde_json::from_slice::<Value>(&b).ok())
        else {
            continue;
        };
        let limits = (
            body["run_to_failure"]["max_cycles"].as_f64(),
            body["run_to_failure"]["wear_limit_um"].as_f64(),
        );
        for t in trajectories(dir)
            .into_iter()
            .filter(|t| t.dataset_key == key)
        {
            let case = body["cases"]
                .as_array()
                .and_then(|cs| {
                    cs.iter()
                        .find(|c| c["condition"].as_str() == Some(&t.condition))
                })
                .and_then(|c| c["case_toml"].as_str())
                .map(str::to_owned);
            jobs.push((dir.join(trajectory_rel(&t.condition)), t, case, limits));
        }
    }
    let problems: Vec<String> = jobs
        .par_iter()
        .filter_map(|(path, t, case, limits)| {
            let checked = (|| {
                let case = case.as_deref().ok_or("no condition of that name in the description")?;
                let case = crate::config::load_case(case, &[]).map_err(|e| e.to_string())?;
                let (Some(max), Some(limit)) = *limits else {
                    return Err("the description gives no run-to-failure limits".to_owned());
                };
                verify_case_trajectory(&case, max, limit * 1e-6, &t.trajectory)
                    .map_err(|e| e.to_string())
            })();
            checked.err().map(|e| {
                format!(
                    "{}: {e}: the trajectory was edited or is not this design's (a damaged or edited shard)",
                    path.display()
                )
            })
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(DatasetError::Input(problems))
    }
}
