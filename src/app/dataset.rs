//! The dataset jobs: a study design to a folder of labelled records (`app::dataset_dir`
//! for the layout), sharded, resumable, streamed to disk ([`DatasetJob`]); and the merge
//! of shards ([`DatasetMergeJob`]).
//!
//! Steps: check the design against the signal chain and the disk budget (before any
//! work); run the trajectories the shard needs (kept in `state/`, reused when present);
//! compute the shard's physical states in parallel, each writing its records as soon as
//! they are made (never all records in memory); then, for an unsharded run, build the
//! index and metadata from the files. A finished record (its sidecar present, under the
//! same dataset key, with its signal file intact) is not computed again.

use super::dataset_dir::{
    csv_rel, finished, is_file_in, make_folder, put, read_in, sidecar_rel,
    stage_index_and_metadata, trajectory_rel, Missing, Sidecar, TrajectoryFile, DATASET_REL,
};
use super::observer::{Observer, Task};
use super::{budget, publish, Job, JobError, Outcome};
use crate::checksum::sha256_hex;
use crate::io::input::{
    read_input, read_input_text, MAX_CASE_BYTES, MAX_DESIGN_BYTES, MAX_TRANSFER_PATH_BYTES,
};
use crate::io::set_state::SetState;
use crate::io::OutputDir;
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::{FigureOutput, FigureRequest};
use crate::report::signals::chain_json;
use crate::report::Artifacts;
use crate::signals::files::{record_parquet, record_table, units};
use crate::signals::path_file::parse_transfer_path;
use crate::signals::setup::{chain_of, ChainSetup};
use crate::signals::transfer::TransferPath;
use crate::study::budget::{estimate, Budget, Estimate, Job as Cost, Term};
use crate::study::dataset::parse_design;
use crate::study::dataset::plan::{Plan, Shard};
use crate::study::dataset::records::{state_records, StateInputs};
use crate::study::dataset::trajectory::{run_trajectory, Trajectory};
use crate::study::dataset::{DatasetDesign, StateChoice};
use crate::study::Model;
use rayon::prelude::*;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::path::Path;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Why a dataset step failed: bad input (the design, its files, the budget) or a run
/// that could not finish.
#[derive(Debug, thiserror::Error)]
pub enum DatasetError {
    #[error("{}", .0.join("\n"))]
    Input(Vec<String>),
    #[error(transparent)]
    Failed(#[from] anyhow::Error),
}

impl From<DatasetError> for JobError {
    fn from(e: DatasetError) -> Self {
        match e {
            DatasetError::Input(m) => JobError::Input(m.into_iter().map(Problem::new).collect()),
            DatasetError::Failed(e) => JobError::Failed(e),
        }
    }
}

/// What a dataset job did.
#[derive(Debug, Clone, PartialEq)]
pub struct DatasetOutcome {
    pub total_records: usize,
    pub shard_records: usize,
    pub computed: usize,
    pub reused: usize,
    /// Physical states that failed (the solver gave up), with the reason.
    pub failures: Vec<String>,
    /// Records missing from the index (an unsharded run or a merge): the count and
    /// the first ids.
    pub missing: Missing,
    pub estimated_bytes: f64,
}

/// A design, its transfer path (read by the caller) and where it goes.
pub struct DatasetRequest<'a> {
    pub design: &'a DatasetDesign,
    pub path: Option<TransferPath>,
    /// Bytes of the transfer-path file (part of the dataset key).
    pub path_bytes: Vec<u8>,
    pub shard: Shard,
    /// The formats and size of the dataset's figure.
    pub figures: FigureOutput,
}

/// Bytes of the metadata and labels of one record besides its signals (sidecar JSON with
/// the indicators and per-tooth wear, index row), a generous bound from measured files.
const LABEL_BYTES_PER_RECORD: f64 = 16_384.0;

/// The plan's axis sizes.
pub fn plan_of(d: &DatasetDesign) -> Plan {
    Plan {
        conditions: d.conditions.len(),
        states: match &d.states {
            StateChoice::Count(n) => *n,
            StateChoice::Cycles(c) => c.len(),
        },
        speeds: d.speeds_hz.len(),
        loads: d.torques_nm.len(),
        realisations: d.noise_realisations,
    }
}

/// The chain setup of each condition, checked at the design's fastest speed.
fn setups(req: &DatasetRequest) -> Result<Vec<ChainSetup>, Vec<String>> {
    let d = req.design;
    let fastest = d.speeds_hz.iter().fold(0.0_f64, |a, b| a.max(*b));
    let mut problems = Vec::new();
    let mut out = Vec::new();
    for c in &d.conditions {
        let mut case = c.case.clone();
        case.set_load_point(crate::config::case::LoadPoint {
            input_speed_hz: fastest,
            ..case.load_point()
        });
        match chain_of(
            &case,
            req.path.clone(),
            case.signals.max_input_speed_hz(&case),
        ) {
            Ok(s) => out.push(s),
            Err(e) => problems.extend(
                e.into_iter()
                    .map(|m| format!("condition `{}`: {m}", c.name)),
            ),
        }
    }
    if problems.is_empty() {
        Ok(out)
    } else {
        Err(problems)
    }
}

/// Estimated bytes of the whole dataset (module docs of `jobs::dataset_dir`).
pub fn estimate_bytes(d: &DatasetDesign, setups: &[ChainSetup]) -> f64 {
    let plan = plan_of(d);
    let slowest = d.speeds_hz.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    let per_state: f64 = setups
        .iter()
        .map(|s| {
            let g = &d.conditions[0].case.gear;
            let shaft_hz = match s.chain.tachometer.shaft {
                crate::signals::chain::Shaft::Pinion => slowest,
                crate::signals::chain::Shaft::Gear => {
                    slowest * g.teeth_pinion as f64 / g.teeth_gear as f64
                }
            };
            let n = s.chain.samples(shaft_hz) as f64;
            let columns = (s.chain.path.sensors.len() + 1) as f64;
            let csv = if d.csv {
                n * (columns + 1.0) * 16.0
            } else {
                0.0
            };
            n * columns * 4.0 + csv + LABEL_BYTES_PER_RECORD
        })
        .fold(0.0, f64::max);
    per_state * plan.records() as f64
}

/// Hash of everything the dataset is generated from.
pub fn dataset_key(d: &DatasetDesign, path_bytes: &[u8]) -> String {
    let mut text = d.text.clone();
    for c in &d.conditions {
        text.push_str(&toml::to_string(&c.case).unwrap_or_default());
    }
    text.push_str(&sha256_hex(path_bytes));
    text.push_str(env!("CARGO_PKG_VERSION"));
    sha256_hex(text.as_bytes())
}

/// The dataset's description (`state/dataset.json`, the body of metadata.json).
fn description(req: &DatasetRequest, setups: &[ChainSetup], key: &str) -> Value {
    let d = req.design;
    let plan = plan_of(d);
    let first = &setups[0].chain;
    let probe = crate::signals::record::Record {
        sampling_rate_hz: first.acquisition.sampling_rate_hz,
        channels: first
            .path
            .sensors
            .iter()
            .map(|s| (s.clone(), Vec::new()))
            .collect(),
        tachometer_v: Vec::new(),
    };
    json!({
        "program": "gearwear",
        "version": env!("CARGO_PKG_VERSION"),
        "dataset_key": key,
        "design": d.text,
        "seed": d.seed,
        "records": plan.records(),
        "physical_states": plan.physical_states(),
        "axes": {
            "conditions": d.conditions.iter().map(|c| json!({"name": c.name, "fault": c.fault, "severity": c.severity})).collect::<Vec<_>>(),
            "states": match &d.states { StateChoice::Count(n) => json!({"evenly_spaced": n}), StateChoice::Cycles(c) => json!({"cycles": c}) },
            "input_speed_hz": d.speeds_hz,
            "load_torque_nm": d.torques_nm,
            "noise_realisations": d.noise_realisations,
        },
        "record_id": "((((condition x states + state) x speeds + speed) x loads + load) x realisations + realisation)",
        "run_to_failure": {"max_cycles": d.max_cycles, "wear_limit_um": d.wear_limit_um, "failure": "the deepest wear, pinion or gear profile, reaches wear_limit_um"},
        "record": chain_json(first, first.samples(d.speeds_hz[0])),
        "signal_columns": units(&probe, first.acquisition.unit),
        "cases": d.conditions.iter().map(|c| json!({"condition": c.name, "case_toml": toml::to_string(&c.case).unwrap_or_default()})).collect::<Vec<_>>(),
        "layout": {
            "signals/<record_id>.parquet": "one record: a float32 column per accelerometer and the tachometer; sampling rate and units in the file's key-value metadata",
            "csv/<record_id>.csv": "the same record as CSV with time_s (when the design asks)",
            "records/<record_id>.json": "labels and indicators of one record",
            "index.parquet": "one row per record: labels and indicators (index.csv: the same as CSV)",
            "indicator_trends.csv": "the first channel's indicators along each trajectory (condition x speed x load), mean over the noise realisations of each state",
            "indicator_trends.png": "the same as a figure, against the pinion load cycles (indicator_trends.svg beside or instead of it when the job asks for SVG)",
            "state/": "the dataset's description and run-to-failure trajectories (used by resumes and merges)",
        },
    })
}

/// A request checked before anything is written: the chain of every condition and the
/// estimated size against the disk budget.
pub struct Checked {
    setups: Vec<ChainSetup>,
    estimated_bytes: f64,
}

/// Check `req` (module docs, first step).
pub fn check_dataset(req: &DatasetRequest) -> Result<Checked, DatasetError> {
    let d = req.design;
    let setups = setups(req).map_err(DatasetError::Input)?;
    let estimated = estimate_bytes(d, &setups);
    let budget = d.disk_budget_gib * 1024f64.powi(3);
    if estimated > budget {
        return Err(DatasetError::Input(vec![format!(
            "the dataset would take about {:.2} GiB ({} records), more than `records.disk_budget_gib` = {}: raise the budget, or make fewer or shorter records",
            estimated / 1024f64.powi(3),
            plan_of(d).records(),
            d.disk_budget_gib
        )]));
    }
    Ok(Checked {
        setups,
        estimated_bytes: estimated,
    })
}

/// The cost of (a shard of) a dataset against the run budget, before anything is
/// computed (the disk has its own budget): each condition's run-to-failure trajectory
/// costs at most a dynamic wear study to `max_cycles` (it stops earlier at the wear
/// limit), each physical state of the shard one dynamic evaluation at its speed and load
/// (the costliest of the lowest and highest speed and load of its condition). Memory: the
/// costliest single study on each of `threads` threads.
pub fn estimate_dataset(d: &DatasetDesign, shard: Shard, threads: usize) -> Estimate {
    let states = plan_of(d).shard_states(shard).len() as f64;
    let ends = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        [lo, hi]
    };
    let (mut trajectories_s, mut state_s, mut bytes) = (0.0, 0.0f64, 0.0f64);
    for c in &d.conditions {
        let mut case = c.case.clone();
        case.wear.total_cycles = d.max_cycles;
        let w = estimate(
            &case,
            Cost::Wear {
                dynamic: true,
                quasi_static: false,
            },
        );
        trajectories_s += w.seconds();
        bytes = bytes.max(w.memory_bytes());
        for speed in ends(&d.speeds_hz) {
            for torque in ends(&d.torques_nm) {
                let mut case = c.case.clone();
                case.set_load_point(crate::config::case::LoadPoint {
                    input_speed_hz: speed,
                    load_torque_nm: torque,
                    ..case.load_point()
                });
                let e = estimate(&case, Cost::Dynamics);
                state_s = state_s.max(e.seconds());
                bytes = bytes.max(e.memory_bytes());
            }
        }
    }
    Estimate {
        steps_per_evaluation: 0.0,
        steps_to_give_up: 0.0,
        recorded_samples: 0.0,
        wear_per_cycle_m: None,
        wear_updates_dynamic: 0.0,
        wear_updates_quasi_static: 0.0,
        terms: vec![
            Term {
                what: "the conditions' run-to-failure trajectories",
                seconds: trajectories_s,
                bytes: 0.0,
                keys: &["run_to_failure.max_cycles", "the conditions' wear keys"],
            },
            Term {
                what: "the physical states' dynamic evaluations",
                seconds: states * state_s,
                bytes: threads.max(1) as f64 * (bytes - 64e6),
                keys: &[
                    "the number of conditions, states, speeds and loads",
                    "the conditions' numerics keys",
                ],
            },
        ],
    }
}

/// Run (a shard of) a checked dataset into `root`. `out` is the folder's output set (the
/// shard's, or the whole dataset's).
pub fn run_dataset(
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
    } = checked;
    for s in &setups {
        for w in &s.warnings {
            obs.warning(w);
        }
    }

    let key = dataset_key(d, &req.path_bytes);
    let plan = plan_of(d);
    for dir in ["signals", "records", "state", "csv"] {
        if dir != "csv" || d.csv {
            make_folder(root, dir).map_err(|e| DatasetError::Failed(e.into()))?;
        }
    }
    let desc =
        serde_json::to_vec_pretty(&description(req, &setups, &key)).map_err(anyhow::Error::from)?;
    let prev = out.previous_state().clone();
    put(root, DATASET_REL, &desc, &prev).map_err(|e| DatasetError::Failed(e.into()))?;
    let states = plan.shard_states(req.shard);
    let shard_records = states.len() * plan.realisations;
    // Trajectories of the conditions this shard records.
    let mut needed: Vec<usize> = states
        .iter()
        .map(|p| plan.state_index(*p).condition)
        .collect();
    needed.dedup();
    needed.sort_unstable();
    needed.dedup();
    let trajectories: BTreeMap<usize, Trajectory> = needed
        .par_iter()
        .map(|&c| trajectory(d, c, (root, &prev), &key).map(|t| (c, t)))
        .collect::<Result<_, DatasetError>>()?;
    let done = AtomicUsize::new(0);
    let reused = AtomicUsize::new(0);
    let task = Task::items("records", "records", shard_records);
    obs.start(&task);
    let results: Vec<Result<(), String>> = states
        .par_iter()
        .map(|&p| {
            let r = one_state(
                req,
                &plan,
                p,
                &setups,
                &trajectories,
                (root, &prev),
                &key,
                &reused,
            );
            let n = done.fetch_add(plan.realisations, Ordering::Relaxed) + plan.realisations;
            obs.advance(&task, n as f64, "");
            r.map_err(|e| format!("physical state {p}: {e:#}"))
        })
        .collect();
    obs.finish(&task);
    let failures: Vec<String> = results.into_iter().filter_map(Result::err).collect();
    keep_files(&mut out, root, &plan, &states, &key, d);
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

/// The trajectory of condition `c`: from `state/` when kept under the same key, else run.
fn trajectory(
    d: &DatasetDesign,
    c: usize,
    (root, prev): (&Path, &SetState),
    key: &str,
) -> Result<Trajectory, DatasetError> {
    let cond = &d.conditions[c];
    let rel = trajectory_rel(&cond.name);
    if let Some(t) = read_in(root, &rel)
        .and_then(|b| serde_json::from_slice::<TrajectoryFile>(&b).ok())
        .filter(|t| t.dataset_key == key)
    {
        return Ok(t.trajectory);
    }
    let model = Model::from_case(&cond.case).map_err(|e| {
        DatasetError::Input(
            e.0.iter()
                .map(|m| format!("condition `{}`: {m}", cond.name))
                .collect(),
        )
    })?;
    let t = run_trajectory(&model, d.max_cycles, d.wear_limit_um * 1e-6)
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

/// Compute and write the records of physical state `p` (unless all are finished).
#[allow(clippy::too_many_arguments)]
fn one_state(
    req: &DatasetRequest,
    plan: &Plan,
    p: usize,
    setups: &[ChainSetup],
    trajectories: &BTreeMap<usize, Trajectory>,
    (root, prev): (&Path, &SetState),
    key: &str,
    reused: &AtomicUsize,
) -> anyhow::Result<()> {
    let d = req.design;
    let ids: Vec<usize> = (0..plan.realisations)
        .map(|r| plan.record_id(p, r))
        .collect();
    if ids.iter().all(|id| finished(root, *id, key).is_some()) {
        reused.fetch_add(ids.len(), Ordering::Relaxed);
        return Ok(());
    }
    let ix = plan.state_index(p);
    let cond = &d.conditions[ix.condition];
    let traj = &trajectories[&ix.condition];
    let cycles = match &d.states {
        StateChoice::Count(n) => traj.even_states(*n)[ix.state],
        StateChoice::Cycles(c) => c[ix.state],
    };
    let mut case = cond.case.clone();
    case.set_load_point(crate::config::case::LoadPoint {
        input_speed_hz: d.speeds_hz[ix.speed],
        load_torque_nm: d.torques_nm[ix.load],
        ..case.load_point()
    });
    let model = Model::from_case(&case).map_err(|e| anyhow::anyhow!("{e}"))?;
    let setup = &setups[ix.condition];
    let unit = setup.chain.acquisition.unit;
    let inputs = StateInputs {
        model: &model,
        setup,
        condition: cond,
        trajectory: traj,
        cycles,
        wear_limit_um: d.wear_limit_um,
        design_seed: d.seed,
    };
    state_records(&inputs, plan, p, ix, &mut |labels, rec| {
        let id = labels.record_id;
        let pq = record_parquet(&rec, unit, Some(&serde_json::to_value(&labels)?))?;
        put(root, &labels.file, &pq, prev)?;
        if d.csv {
            put(
                root,
                &csv_rel(id),
                &record_table(&rec, unit).to_csv()?,
                prev,
            )?;
        }
        let car = Sidecar {
            dataset_key: key.to_owned(),
            signal_sha256: sha256_hex(&pq),
            labels,
        };
        put(
            root,
            &sidecar_rel(id),
            &serde_json::to_vec_pretty(&car)?,
            prev,
        )?;
        Ok(())
    })
}

/// List the shard's finished records and the state files in its output set, so a later
/// run of the set that no longer makes them removes them.
fn keep_files(
    out: &mut OutputDir,
    root: &Path,
    plan: &Plan,
    states: &[usize],
    key: &str,
    d: &DatasetDesign,
) {
    out.keep_state(DATASET_REL);
    for c in &d.conditions {
        if is_file_in(root, &trajectory_rel(&c.name)) {
            out.keep_state(&trajectory_rel(&c.name));
        }
    }
    for &p in states {
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

/// Merge the dataset folders `inputs` (shards of one design) into `root`: their records
/// and state files copied over, then the index and metadata built as an unsharded run
/// builds them.
/// The dataset key and record count the shards in `inputs` share, read and checked
/// before any output folder is opened: every input a dataset folder of one design, its
/// record count the one its axes give.
fn shared_key(inputs: &[&Path]) -> Result<(String, usize), DatasetError> {
    let mut key: Option<(String, usize)> = None;
    let mut problems = Vec::new();
    for dir in inputs {
        let body: Option<Value> =
            read_in(dir, DATASET_REL).and_then(|b| serde_json::from_slice(&b).ok());
        let Some(body) = body else {
            problems.push(format!(
                "{}: no {DATASET_REL}: not a dataset folder (or not started)",
                dir.display()
            ));
            continue;
        };
        let k = body["dataset_key"].as_str().unwrap_or_default().to_owned();
        let total = body["records"].as_u64().unwrap_or(0) as usize;
        // The record count is trusted only when the axes beside it give it: a shard
        // edited to claim 2e9 records would otherwise size the index's missing list.
        if axes_records(&body) != Some(total) {
            problems.push(format!(
                "{}: {DATASET_REL} claims {total} records, which its axes do not give (conditions x states x speeds x loads x noise realisations): a damaged or edited shard",
                dir.display()
            ));
            continue;
        }
        match &key {
            None => key = Some((k, total)),
            Some((k0, _)) if *k0 != k => problems.push(format!(
                "{}: a shard of another dataset (dataset key {}..., the first input has {}...): merge shards of one design only",
                dir.display(),
                &k[..k.len().min(12)],
                &k0[..k0.len().min(12)]
            )),
            _ => {}
        }
    }
    key.filter(|_| problems.is_empty())
        .ok_or(DatasetError::Input(problems))
}

/// Joins the shards in `inputs` (checked by [`shared_key`], which gave `key` and
/// `total`) into `root`, its figure written as `figures` says.
fn merge_datasets(
    inputs: &[&Path],
    root: &Path,
    mut out: OutputDir,
    (key, total): (String, usize),
    figures: FigureOutput,
) -> Result<DatasetOutcome, DatasetError> {
    let mut copied = 0;
    for dir in inputs {
        copied += super::dataset_dir::copy_dataset(dir, root, &key, out.previous_state())
            .map_err(|e| DatasetError::Failed(e.into()))?;
    }
    let missing = stage_index_and_metadata(&mut out, root, total, figures)
        .map_err(|e| DatasetError::Failed(anyhow::anyhow!("{e}")))?;
    out.keep_state(DATASET_REL);
    for s in super::dataset_dir::sidecars(root)
        .into_iter()
        .filter(|s| s.dataset_key == key)
    {
        out.keep_state(&s.labels.file);
        out.keep_state(&sidecar_rel(s.labels.record_id));
        if is_file_in(root, &csv_rel(s.labels.record_id)) {
            out.keep_state(&csv_rel(s.labels.record_id));
        }
    }
    for t in super::dataset_dir::trajectories(root) {
        out.keep_state(&trajectory_rel(&t.condition));
    }
    out.publish().map_err(|e| DatasetError::Failed(e.into()))?;
    Ok(DatasetOutcome {
        total_records: total,
        shard_records: total,
        computed: 0,
        reused: copied,
        failures: Vec::new(),
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

/// A study design and where it was read from (its folder resolves the design's relative
/// paths: the case file and the transfer-path file).
#[derive(Debug, Clone)]
pub struct DesignSource {
    pub text: String,
    /// The design's name in messages (its file name).
    pub name: String,
    pub folder: PathBuf,
}

impl DesignSource {
    /// The design in `path`.
    pub fn file(path: &Path) -> Result<Self, JobError> {
        let name = path.display().to_string();
        let text = read_input_text(path, "study design", MAX_DESIGN_BYTES)
            .map_err(|e| JobError::input(Problem::given(Arg::Design, &name, e.reason)))?;
        Ok(Self {
            text,
            name,
            folder: path
                .parent()
                .map_or_else(|| PathBuf::from("."), Path::to_path_buf),
        })
    }
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct DatasetJob {
    pub design: DesignSource,
    pub shard: Shard,
    pub out: PathBuf,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the dataset's figure (`indicator_trends`), checked when the
    /// job starts; the records are the same whatever it is.
    pub figures: FigureRequest,
}

fn outcome(o: &DatasetOutcome, root: &Path, what: &str) -> Outcome {
    let mut artifacts = Artifacts {
        summary: serde_json::json!({
            "records": o.total_records,
            "records_of_this_run": o.shard_records,
            "computed": o.computed,
            "reused": o.reused,
            "failures": o.failures,
            "missing": o.missing.listed,
            "missing_count": o.missing.count,
            "estimated_bytes": o.estimated_bytes,
        }),
        ..Default::default()
    };
    artifacts.headline = format!(
        "{what}: {} of {} records ({} computed, {} reused){}",
        o.shard_records,
        o.total_records,
        o.computed,
        o.reused,
        if o.missing.count == 0 {
            String::new()
        } else {
            format!("; {} records missing from the index", o.missing.count)
        }
    );
    Outcome {
        artifacts,
        published: Some(root.to_path_buf()),
        incomplete: (!o.failures.is_empty()).then(|| {
            format!(
                "{} physical states failed:\n  {}",
                o.failures.len(),
                o.failures.join("\n  ")
            )
        }),
    }
}

impl Job for DatasetJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "dataset"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        let d = &self.design;
        let read = |rel: &str| {
            read_input_text(&d.folder.join(rel), "case file", MAX_CASE_BYTES).map_err(|e| e.reason)
        };
        let design = parse_design(&d.text, &d.name, &read).map_err(|m| {
            JobError::Input(m.into_iter().map(|m| Problem::of(Arg::Design, m)).collect())
        })?;
        let (path, path_bytes) = match &design.transfer_path {
            Some(rel) => {
                let p = d.folder.join(rel);
                let shown = p.display().to_string();
                let bytes =
                    read_input(&p, "transfer-path file", MAX_TRANSFER_PATH_BYTES).map_err(|e| {
                        JobError::input(Problem::given(Arg::TransferPath, &shown, e.reason))
                    })?;
                let path =
                    parse_transfer_path(&String::from_utf8_lossy(&bytes), &shown).map_err(|m| {
                        JobError::Input(
                            m.into_iter()
                                .map(|m| Problem::of(Arg::TransferPath, m))
                                .collect(),
                        )
                    })?;
                (Some(path), bytes)
            }
            None => (None, Vec::new()),
        };
        let req = DatasetRequest {
            design: &design,
            path,
            path_bytes,
            shard: self.shard,
            figures,
        };
        let checked = check_dataset(&req)?;
        let threads = rayon::current_num_threads();
        budget::check_estimate(
            &estimate_dataset(&design, self.shard, threads),
            self.budget.as_ref(),
        )?;
        let set = (self.shard.count > 1)
            .then(|| format!("dataset_shard_{}_of_{}", self.shard.index, self.shard.count));
        let out = publish::open(&self.out, set.as_deref(), self.name(), self.replace)?;
        let o = run_dataset(&req, checked, &self.out, out, observer)?;
        observer.note(&format!("dataset: results -> {}", self.out.display()));
        Ok(outcome(&o, &self.out, "dataset"))
    }
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct DatasetMergeJob {
    pub inputs: Vec<PathBuf>,
    pub out: PathBuf,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The formats and size of the merged dataset's figure, checked when the job starts.
    pub figures: FigureRequest,
}

impl Job for DatasetMergeJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "dataset-merge"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        if self.inputs.is_empty() {
            return Err(JobError::input(Problem::of(
                Arg::Inputs,
                "no dataset folders given",
            )));
        }
        let inputs: Vec<&Path> = self.inputs.iter().map(PathBuf::as_path).collect();
        let shared = shared_key(&inputs)?;
        let out = publish::open(&self.out, None, self.name(), self.replace)?;
        let o = merge_datasets(&inputs, &self.out, out, shared, figures)?;
        observer.note(&format!("dataset-merge: results -> {}", self.out.display()));
        Ok(outcome(&o, &self.out, "dataset-merge"))
    }
}
