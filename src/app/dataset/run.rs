//! Running (a shard of) a checked dataset: the trajectories the shard needs (kept in
//! `state/`, reused when present), then its physical states in parallel, each writing its
//! records as soon as they are made; for an unsharded run, the index and metadata.

use super::claim::claim_folder;
use super::folder::{
    csv_rel, finished, is_file_in, make_folder, put, read_in, refused_names, sidecar_rel,
    trajectory_rel, TrajectoryFile, DATASET_REL,
};
use super::index_files::{stage_index_and_metadata, Missing};
use super::kept::Kept;
use super::label_check::kept_label_problems;
use super::plan::{dataset_key, description, Checked};
use super::request::{DatasetError, DatasetOutcome, DatasetRequest};
use super::state_files::{state_files, StateJob};
use super::verify::{kept_file_problem, os_seed, verify_states};
use crate::app::observer::{Observer, Task};
use crate::io::set_state::SetState;
use crate::io::OutputDir;
use crate::study::dataset::plan::{plan_of, Plan};
use crate::study::dataset::planetary::{run_case_trajectory, verify_case_trajectory};
use crate::study::dataset::records::signal_file;
use crate::study::dataset::trajectory::{run_trajectory, Trajectory};
use crate::study::dataset::verify::{
    states_to_recompute, verify_trajectory, MAX_RECOMPUTED_STATES,
};
use crate::study::dataset::DatasetDesign;
use crate::study::Model;
use rayon::prelude::*;
use serde_json::json;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Run (a shard of) a checked dataset into `root`. `out` is the folder's output set (the
/// shard's, or the whole dataset's).
pub(crate) fn run_dataset(
    req: &DatasetRequest,
    checked: Checked,
    root: &Path,
    mut out: OutputDir,
    obs: &dyn Observer,
) -> Result<DatasetOutcome, DatasetError> {
    let d = req.design;
    let Checked {
        setups,
        estimated_bytes: estimated,
        ..
    } = checked;
    for s in &setups {
        for w in &s.warnings {
            obs.warning(w);
        }
    }

    let key = dataset_key(d, &req.path_bytes);
    let plan = plan_of(d);
    let desc =
        serde_json::to_vec_pretty(&description(req, &setups, &key)).map_err(anyhow::Error::from)?;
    let prev = out.previous_state().clone();
    claim_folder(&out, root, (&key, req.replace), &desc, &prev)?;
    for dir in ["signals", "records", "state", "csv"] {
        if dir != "csv" || d.csv {
            // A sub-folder that cannot be made is the output folder's problem: input.
            make_folder(root, dir).map_err(|e| DatasetError::Input(vec![e.to_string()]))?;
        }
    }
    let (shard_first, shard_step) = (req.shard.index - 1, req.shard.count);
    let state_count = plan.shard_state_count(req.shard);
    let shard_records = state_count * plan.realisations;
    // Trajectories of the conditions this shard records.
    let needed = plan.shard_conditions(req.shard);
    let trajectories: BTreeMap<usize, Trajectory> = needed
        .par_iter()
        .map(|&c| trajectory(d, c, (root, &prev), &key).map(|t| (c, t)))
        .collect::<Result<_, DatasetError>>()?;
    let job = StateJob {
        req,
        plan: &plan,
        setups: &setups,
        trajectories: &trajectories,
        key: &key,
    };
    let problems = kept_records_problems(&job, root, (shard_first, shard_step), state_count);
    if !problems.is_empty() {
        return Err(DatasetError::Input(problems));
    }
    let done = AtomicUsize::new(0);
    let reused = AtomicUsize::new(0);
    let task = Task::items("records", "records", shard_records);
    obs.start(&task);
    // Only the failures are kept (a list of every state's result would grow with the shard).
    let failures: Vec<String> = (0..state_count)
        .into_par_iter()
        .map(|k| shard_first + k * shard_step)
        .filter_map(|p| {
            let r = one_state(&job, p, (root, &prev), &reused);
            let n = done.fetch_add(plan.realisations, Ordering::Relaxed) + plan.realisations;
            obs.advance(&task, n as f64, "");
            r.err().map(|e| format!("physical state {p}: {e:#}"))
        })
        .collect();
    obs.finish(&task);
    keep_files(&mut out, root, &plan, plan.shard_states(req.shard), &key, d);
    let missing = if req.shard.count == 1 {
        stage_index_and_metadata(&mut out, root, plan.records(), req.figures)
            .map_err(|e| DatasetError::Failed(anyhow::anyhow!("{e}")))?
    } else {
        out.stage_json(
            &format!("dataset_shard_{}_of_{}.json", req.shard.index, req.shard.count),
            &json!({"dataset_key": key, "shard": format!("{}/{}", req.shard.index, req.shard.count), "records": shard_records, "failures": failures}),
        )
        .map_err(|e| DatasetError::Failed(e.into()))?;
        Missing::default()
    };
    out.publish().map_err(|e| DatasetError::Failed(e.into()))?;
    let reused = reused.load(Ordering::Relaxed);
    Ok(DatasetOutcome {
        total_records: plan.records(),
        shard_records,
        computed: shard_records - reused - failures.len() * plan.realisations,
        reused,
        failures,
        missing,
        estimated_bytes: estimated,
    })
}

/// Finished records are reused only when a sample of them recomputes bit for bit and
/// every other one's labels are those the design and the verified trajectories give:
/// the problems of the shard's `count` states, `first` and every `step`-th after.
fn kept_records_problems(
    job: &StateJob,
    root: &Path,
    (first, step): (usize, usize),
    count: usize,
) -> Vec<String> {
    let sample: Vec<usize> = states_to_recompute(count, MAX_RECOMPUTED_STATES, os_seed())
        .into_iter()
        .map(|k| first + k * step)
        .collect();
    let mut problems = verify_states(job, root, &sample, Kept::WholeStates);
    problems.extend(kept_label_problems(
        job,
        root,
        (0..count)
            .map(|k| first + k * step)
            .filter(|p| !sample.contains(p)),
        Kept::WholeStates,
    ));
    problems
}

/// The trajectory of condition `c`: from `state/` when kept under the same key, else run.
fn trajectory(
    d: &DatasetDesign,
    c: usize,
    (root, prev): (&Path, &SetState),
    key: &str,
) -> Result<Trajectory, DatasetError> {
    let cond = &d.conditions[c];
    let rel = trajectory_rel(&cond.name);
    let input = |m: Vec<String>| {
        DatasetError::Input(
            m.iter()
                .map(|m| format!("condition `{}`: {m}", cond.name))
                .collect(),
        )
    };
    // A planetary set's model is its wear model (`study::dataset::planetary`).
    let model = match cond.case.planetary {
        Some(_) => None,
        None => Some(
            Model::wear_study_from_case(&cond.case, super::state_files::DATASET)
                .map_err(|e| input(e.0))?,
        ),
    };
    let (max, limit) = (d.max_cycles, d.wear_limit_um * 1e-6);
    if let Some(t) = read_in(root, &rel)
        .and_then(|b| serde_json::from_slice::<TrajectoryFile>(&b).ok())
        .filter(|t| t.dataset_key == key)
    {
        // Kept trajectories are used only when the wear law recomputes them.
        match &model {
            Some(m) => verify_trajectory(m, max, limit, &t.trajectory),
            None => verify_case_trajectory(&cond.case, max, limit, &t.trajectory),
        }
        .map_err(|e| kept_file_problem(root, &rel, &e.to_string()))?;
        return Ok(t.trajectory);
    }
    let t = match &model {
        Some(m) => run_trajectory(m, max, limit),
        None => run_case_trajectory(&cond.case, max, limit),
    }
    .map_err(|e| anyhow::anyhow!("trajectory of condition `{}`: {e:#}", cond.name))?;
    let file = TrajectoryFile {
        dataset_key: key.to_owned(),
        condition: cond.name.clone(),
        trajectory: t.clone(),
    };
    put(
        root,
        &rel,
        &serde_json::to_vec(&file).map_err(anyhow::Error::from)?,
        prev,
    )
    .map_err(|e| DatasetError::Failed(e.into()))?;
    Ok(t)
}

/// Refuse (exit code 2) the names the shard of `req` will write in `root` that hold what
/// gearwear must not replace, before the folder is opened (`prev`: its set's record).
pub fn refuse_planted_names(
    req: &DatasetRequest,
    root: &Path,
    prev: Option<&SetState>,
) -> Result<(), DatasetError> {
    let plan = plan_of(req.design);
    let refused = refused_names(root, shard_file_names(req.design, &plan, req), prev);
    if refused.is_empty() {
        Ok(())
    } else {
        Err(DatasetError::Input(refused))
    }
}

/// Every file name the shard of `req` writes: each record's signal, its CSV twin (when the
/// design asks for CSV) and its sidecar, and each recorded condition's trajectory.
fn shard_file_names<'a>(
    d: &'a DatasetDesign,
    plan: &'a Plan,
    req: &'a DatasetRequest,
) -> impl Iterator<Item = String> + 'a {
    let (first, step) = (req.shard.index - 1, req.shard.count);
    let records = (0..plan.shard_state_count(req.shard)).flat_map(move |k| {
        (0..plan.realisations).flat_map(move |r| {
            let id = plan.record_id(first + k * step, r);
            let csv = d.csv.then(|| csv_rel(id));
            [Some(signal_file(id)), csv, Some(sidecar_rel(id))]
                .into_iter()
                .flatten()
        })
    });
    let trajectories = plan
        .shard_conditions(req.shard)
        .into_iter()
        .map(|c| trajectory_rel(&d.conditions[c].name));
    records.chain(trajectories)
}

/// Compute and write the records of physical state `p` (unless all are finished).
fn one_state(
    job: &StateJob,
    p: usize,
    (root, prev): (&Path, &SetState),
    reused: &AtomicUsize,
) -> anyhow::Result<()> {
    let ids: Vec<usize> = (0..job.plan.realisations)
        .map(|r| job.plan.record_id(p, r))
        .collect();
    if ids.iter().all(|id| finished(root, *id, job.key).is_some()) {
        reused.fetch_add(ids.len(), Ordering::Relaxed);
        return Ok(());
    }
    state_files(job, p, &mut |f| {
        put(root, &f.signal_rel, &f.signal, prev)?;
        if let Some(csv) = &f.csv {
            put(root, &csv_rel(f.id), csv, prev)?;
        }
        put(root, &sidecar_rel(f.id), &f.sidecar, prev)?;
        Ok(())
    })
}

/// List the shard's finished records and the state files in its output set, so a later
/// run of the set that no longer makes them removes them.
fn keep_files(
    out: &mut OutputDir,
    root: &Path,
    plan: &Plan,
    states: impl Iterator<Item = usize>,
    key: &str,
    d: &DatasetDesign,
) {
    out.keep_state(DATASET_REL);
    for c in &d.conditions {
        if is_file_in(root, &trajectory_rel(&c.name)) {
            out.keep_state(&trajectory_rel(&c.name));
        }
    }
    for p in states {
        for r in 0..plan.realisations {
            let id = plan.record_id(p, r);
            if let Some(s) = finished(root, id, key) {
                out.keep_state(&s.labels.file);
                out.keep_state(&sidecar_rel(id));
                if d.csv {
                    out.keep_state(&csv_rel(id));
                }
            }
        }
    }
}
