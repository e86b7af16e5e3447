//! The wear job on a gear train (`[[stage]]`): every mesh worn at its own cycle count
//! by one response of the whole train (`study::train_wear`), the modes in parallel, the
//! results of `report::wear_train`. No checkpoints yet: a train's run is refused with
//! `--resume`, and so is a load spectrum.

use super::observer::{keep_going, Observer};
use super::wear_runs::{mode_tasks, report_update, stops_of};
use super::{build_train_model, publish, JobError, Outcome};
use crate::remedy::{Arg, Problem};
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
    if job.resume {
        return Err(JobError::input(Problem::of(
            Arg::Resume,
            "the wear study of a gear train ([[stage]] tables) writes no checkpoints yet, so it cannot resume: run it afresh",
        )));
    }
    let model = build_train_model(&job.case, observer)?;
    let Some(train) = model.train.as_ref() else {
        return Err(JobError::input(Problem::new(
            "this case has no [[stage]] tables",
        )));
    };
    let meta = RunMetadata::of_model(name, &model);
    let out = publish::open_if(job.out.as_deref(), None, name, job.replace)?;
    let tasks = mode_tasks(&job.modes, model.case.wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    let on_update = |mode: WearMode, run: &TrainWearRun| -> anyhow::Result<()> {
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
    let starts = job.modes.iter().map(|m| TrainWearRun::new(*m)).collect();
    let result = run_in_parallel(
        starts,
        |r| r.mode,
        &|start, f| run_train_wear(&model, train, start, f),
        &on_update,
    );
    for t in &tasks {
        observer.finish(t);
    }
    let runs = result?;
    let refs: Vec<&TrainWearRun> = runs.iter().collect();
    let artifacts = train_wear_artifacts(&model, train, &refs).with_figure_output(figures);
    let mut outcome = publish::publish(out, artifacts, Some(&meta), observer)?;
    let modes: Vec<(WearMode, Option<&WearStop>)> =
        runs.iter().map(|r| (r.mode, r.stopped.as_ref())).collect();
    outcome.incomplete = stops_of(&modes, observer);
    Ok(outcome)
}
