//! The wear job on a gear train (`[[stage]]`): every mesh worn at its own cycle count
//! by one response of the whole train (`study::train_wear`), the modes in parallel, the
//! results of `report::wear_train`. With an output folder, every update of the whole train
//! is kept (a log per mode and mesh, `app::train_checkpoints`) and `--resume` continues
//! from them once they are replayed and recomputed. A load spectrum on a train is refused.

use super::observer::{keep_going, Observer};
use super::train_checkpoints::{mesh_checkpoint_name, open_logs, starting_runs};
use super::wear_runs::{mode_tasks, report_update, stops_of};
use super::{build_train_model, publish, JobError, Outcome};
use crate::remedy::Problem;
use crate::report::figure_output::FigureOutput;
use crate::report::wear_train::train_wear_artifacts;
use crate::store::RunMetadata;
use crate::study::train_wear::{run_train_wear, TrainWearRun};
use crate::study::wear_loop::{run_in_parallel, WearMode, WearStop};

/// Run the wear study of the train in `job.case` (see the module docs).
pub fn wear_of_train(
    job: &super::WearJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "wear";
    if job.case.load_spectrum.is_some() {
        return Err(JobError::input(Problem::new(
            "`[load_spectrum]` on a gear train ([[stage]] tables): the wear study under a load spectrum takes a single pair so far; remove one or the other",
        )));
    }
    if let (Some(o), true) = (job.out.as_deref(), job.resume) {
        super::checkpoints::require_folder(o)?;
    }
    let model = build_train_model(&job.case, observer)?;
    let Some(train) = model.train.as_ref() else {
        return Err(JobError::input(Problem::new(
            "this case has no [[stage]] tables",
        )));
    };
    let meta = RunMetadata::of_model(name, &model);
    // The folder first (locked, its state read through its handle), then the checkpoints
    // in it, each replayed and recomputed before anything runs.
    let mut out = publish::open_if(job.out.as_deref(), None, name, job.replace)?;
    let resume_from = out.as_ref().filter(|_| job.resume);
    let stages = train.stages.len();
    let starts = starting_runs(
        &model,
        train,
        &job.modes,
        resume_from,
        &meta.case_sha256,
        observer,
    )?;
    let logs = match out.as_mut() {
        Some(d) => Some(open_logs(d, &starts, stages, &meta.case_sha256)?),
        None => None,
    };
    let root = out.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(&job.modes, model.case.wear.total_cycles);
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
        &|start, f| run_train_wear(&model, train, start, f),
        &on_update,
    );
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    let runs = result?;
    let refs: Vec<&TrainWearRun> = runs.iter().collect();
    let artifacts = train_wear_artifacts(&model, train, &refs).with_figure_output(figures);
    let mut outcome = publish::publish(out, artifacts, Some(&meta), observer)?;
    let modes: Vec<(WearMode, Option<&WearStop>)> =
        runs.iter().map(|r| (r.mode, r.stopped.as_ref())).collect();
    outcome.incomplete = stops_of(&modes, observer);
    Ok(outcome)
}
