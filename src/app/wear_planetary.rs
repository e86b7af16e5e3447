//! The wear job on a planetary set (`[planetary]`): every sun-planet and ring-planet mesh
//! worn by one response of the whole set (`study::planetary_wear_loop`), the modes in
//! parallel, the results of `report::wear_planetary`. With an output folder, every update
//! of the whole set is kept (a log per mode and mesh, `app::planetary_checkpoints`) and
//! `--resume` continues from them once they are replayed and recomputed. A set under a
//! load spectrum wears in `app::duty_planetary`. The run job on a planetary set
//! (`app::run_planetary`) runs its wear studies here too.

use super::observer::{keep_going, Observer};
use super::planetary_checkpoints::{open_logs, planetary_checkpoint_name, starting_runs};
use super::wear_runs::{mode_tasks, stops_of, Runs};
use super::{publish, JobError, Outcome, WearJob};
use crate::config::case::WearSection;
use crate::report::figure_output::FigureOutput;
use crate::report::wear_planetary::planetary_wear_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::planetary::estimate_planetary_wear;
use crate::study::parallel_runs::run_in_parallel;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use crate::study::wear_loop::{WearMode, WearStop};
use std::path::Path;

/// Run the wear study of the planetary set in `job.case` (see the module docs).
pub fn wear_of_planetary(
    job: &WearJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let model = PlanetaryWearModel::from_case(&job.case)?;
    // After the model (milliseconds: the budget counts the updates from the set's own
    // first wear rate), before the folder is opened.
    super::budget::check_estimate(
        &estimate_planetary_wear(&model, &job.case.wear, &job.modes),
        job.budget.as_ref(),
    )?;
    for w in &model.dynamics.study.warnings {
        observer.warning(w);
    }
    let meta = RunMetadata::new("wear", &job.case);
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_planetary_modes(
        "wear",
        &model,
        &job.case.wear,
        &job.modes,
        &meta,
        out,
        observer,
    )?;
    let refs: Vec<&PlanetaryWearRun> = runs.runs.iter().collect();
    let artifacts = planetary_wear_artifacts(&model, &refs).with_figure_output(figures);
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = planetary_stops(&refs, observer);
    Ok(outcome)
}

/// Tell `observer` about the set's runs that stopped early; the failure to return if one
/// was the solver's (`wear_runs::stops_of`).
pub(super) fn planetary_stops(
    runs: &[&PlanetaryWearRun],
    observer: &dyn Observer,
) -> Option<String> {
    let modes: Vec<(WearMode, Option<&WearStop>)> =
        runs.iter().map(|r| (r.mode, r.stopped.as_ref())).collect();
    stops_of(&modes, observer)
}

/// The wear runs of the set in `modes` for the job `command`: the output folder opened
/// (locked), then the checkpoints in it, each replayed and recomputed before anything
/// runs (when resuming), then the runs in parallel with a log per mode and mesh appended
/// after every update (`wear`: the case's `[wear]`), progress (input cycles, the deepest wear of any member) and
/// cancellation.
pub(super) fn run_planetary_modes(
    command: &str,
    model: &PlanetaryWearModel,
    wear: &WearSection,
    modes: &[WearMode],
    meta: &RunMetadata,
    (out, resume, replace): (Option<&Path>, bool, bool),
    observer: &dyn Observer,
) -> Result<Runs<Vec<PlanetaryWearRun>>, JobError> {
    if let (Some(o), true) = (out, resume) {
        super::checkpoints::require_folder(o)?;
    }
    if modes.contains(&WearMode::QuasiStatic) {
        if let Some(p) = model.quasi_static_problem() {
            return Err(JobError::input(p));
        }
    }
    let mut dir = publish::open_if(out, None, command, replace)?;
    let resume_from = dir.as_ref().filter(|_| resume);
    let starts = starting_runs(model, wear, modes, resume_from, &meta.case_sha256, observer)?;
    let logs = match dir.as_mut() {
        Some(d) => Some(open_logs(d, model, &starts, &meta.case_sha256)?),
        None => None,
    };
    let root = dir.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(modes, wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    // Progress in input cycles, with the deepest wear of any member so far.
    let on_update = |mode: WearMode, run: &PlanetaryWearRun| -> anyhow::Result<()> {
        if let (Some(logs), Some(root)) = (&logs, &root) {
            logs.record(mode, run.updates.len(), &|j, i| &run.updates[i].meshes[j])?;
            observer.checkpoint(&root.join(planetary_checkpoint_name(model, mode, 0)));
        }
        let task = tasks.iter().find(|t| t.id == mode.name());
        if let (Some(t), Some(u)) = (task, run.updates.last()) {
            let deepest = u
                .flanks(model)
                .iter()
                .flat_map(|f| f.depth_m.iter())
                .fold(0.0_f64, |a, b| a.max(*b));
            let status = format!(
                "{} updates, deepest wear {:.3} µm",
                run.updates.len() - 1,
                deepest * 1e6
            );
            observer.advance(t, u.input_cycles, &status);
        }
        keep_going(observer)
    };
    let runs = run_in_parallel(
        starts,
        |r| r.mode,
        &|start, f| run_planetary_wear(model, wear, start, f),
        &on_update,
    );
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    Ok(Runs {
        runs: runs?,
        out: dir,
    })
}
