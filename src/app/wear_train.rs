//! The wear job on a gear train (`[[stage]]`): every mesh worn at its own cycle count
//! by one response of the whole train (`study::train_wear`), the modes in parallel, the
//! results of `report::wear_train`. With an output folder, every update of the whole train
//! is kept (a log per mode and mesh, `app::train_checkpoints`) and `--resume` continues
//! from them once they are replayed and recomputed. Under a load spectrum the job is
//! `app::duty_train`'s (`app::wear` hands it over).
//! The run job on a train (`app::run_train`) runs its wear studies here too.

use super::observer::{keep_going, Observer};
use super::train_checkpoints::{mesh_checkpoint_name, open_logs, starting_runs};
use super::wear_runs::{mode_tasks, report_update, stops_of, Runs};
use super::{build_train_wear_model, publish, JobError, Outcome};
use crate::remedy::Problem;
use crate::report::figure_output::FigureOutput;
use crate::report::wear_train::train_wear_artifacts;
use crate::store::RunMetadata;
use crate::study::parallel_runs::run_in_parallel;
use crate::study::train::TrainModel;
use crate::study::train_wear::{run_train_wear, TrainWearRun};
use crate::study::wear_loop::{WearMode, WearStop};
use crate::study::Model;
use std::path::Path;

/// The train of `model`, or an input error when the case has no `[[stage]]` tables.
pub fn train_of(model: &Model) -> Result<&TrainModel, JobError> {
    model
        .train
        .as_ref()
        .ok_or_else(|| JobError::input(Problem::new("this case has no [[stage]] tables")))
}

/// Run the wear study of the train in `job.case` (see the module docs).
pub fn wear_of_train(
    job: &super::WearJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "wear";
    let model = build_train_wear_model(&job.case, observer)?;
    let train = train_of(&model)?;
    let meta = RunMetadata::of_model(name, &model);
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_train_modes(name, &model, train, &job.modes, &meta, out, observer)?;
    let refs: Vec<&TrainWearRun> = runs.runs.iter().collect();
    let artifacts = train_wear_artifacts(&model, train, &refs).with_figure_output(figures);
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = train_stops(&refs, observer);
    Ok(outcome)
}

/// The wear runs of `train` in `modes` for the job `command`: the output folder opened
/// (locked, its state read through its handle), then the checkpoints in it, each replayed
/// and recomputed before anything runs (when resuming), then the runs in parallel with a
/// log per mode and mesh appended after every update, progress and cancellation.
pub fn run_train_modes(
    command: &str,
    model: &Model,
    train: &TrainModel,
    modes: &[WearMode],
    meta: &RunMetadata,
    (out, resume, replace): (Option<&Path>, bool, bool),
    observer: &dyn Observer,
) -> Result<Runs<Vec<TrainWearRun>>, JobError> {
    if let (Some(o), true) = (out, resume) {
        super::checkpoints::require_folder(o)?;
    }
    let mut dir = publish::open_if(out, None, command, replace)?;
    let resume_from = dir.as_ref().filter(|_| resume);
    let stages = train.stages.len();
    let starts = starting_runs(
        model,
        train,
        modes,
        resume_from,
        &meta.case_sha256,
        observer,
    )?;
    let logs = match dir.as_mut() {
        Some(d) => Some(open_logs(d, &starts, stages, &meta.case_sha256)?),
        None => None,
    };
    let root = dir.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(modes, model.case.wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    let on_update = |mode: WearMode, run: &TrainWearRun| -> anyhow::Result<()> {
        if let (Some(logs), Some(root)) = (&logs, &root) {
            logs.record(mode, run.updates.len(), &|m, j| &run.updates[j].meshes[m])?;
            observer.checkpoint(&root.join(mesh_checkpoint_name(mode, 0)));
        }
        if let Some(u) = run.updates.last() {
            report_update(
                observer,
                &tasks,
                mode,
                run.updates.len() - 1,
                &u.meshes[0].wear,
            );
        }
        keep_going(observer)
    };
    let result = run_in_parallel(
        starts,
        |r| r.mode,
        &|start, f| run_train_wear(model, train, start, f),
        &on_update,
    );
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    Ok(Runs {
        runs: result?,
        out: dir,
    })
}

/// Tell `observer` about the train's runs that stopped early; the failure to return if
/// one was the solver's (`wear_runs::stops_of`).
pub fn train_stops(runs: &[&TrainWearRun], observer: &dyn Observer) -> Option<String> {
    let modes: Vec<(WearMode, Option<&WearStop>)> =
        runs.iter().map(|r| (r.mode, r.stopped.as_ref())).collect();
    stops_of(&modes, observer)
}
