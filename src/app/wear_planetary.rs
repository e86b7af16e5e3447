//! The wear job on a planetary set (`[planetary]`): every sun-planet and ring-planet mesh
//! worn by one response of the whole set (`study::planetary_wear_loop`), the modes in
//! parallel, the results of `report::wear_planetary`. No checkpoints yet: `--resume` and a
//! load spectrum on a planetary set are refused, naming them.

use super::observer::{keep_going, Observer};
use super::wear_runs::{mode_tasks, stops_of};
use super::{publish, JobError, Outcome, WearJob};
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::FigureOutput;
use crate::report::wear_planetary::planetary_wear_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::planetary::estimate_planetary_wear;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use crate::study::wear_loop::{run_in_parallel, WearMode, WearStop};

/// Run the wear study of the planetary set in `job.case` (see the module docs).
pub fn wear_of_planetary(
    job: &WearJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    if job.case.load_spectrum.is_some() {
        return Err(JobError::input(Problem::new(
            "`[load_spectrum]` on a planetary set ([planetary]): the wear study under a load spectrum takes a single pair so far; remove one or the other",
        )));
    }
    if job.resume {
        return Err(JobError::input(Problem::of(
            Arg::Resume,
            "a planetary set's wear study keeps no checkpoints yet, so it cannot be resumed: run it again without resuming".to_string(),
        )));
    }
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
    let out = publish::open_if(job.out.as_deref(), None, "wear", job.replace)?;
    let starts: Vec<PlanetaryWearRun> = job
        .modes
        .iter()
        .map(|m| PlanetaryWearRun::new(*m))
        .collect();
    let wear = &job.case.wear;
    let tasks = mode_tasks(&job.modes, wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    // Progress in input cycles, with the deepest wear of any member so far.
    let on_update = |mode: WearMode, run: &PlanetaryWearRun| -> anyhow::Result<()> {
        let task = tasks.iter().find(|t| t.id == mode.name());
        if let (Some(t), Some(u)) = (task, run.updates.last()) {
            let deepest = u
                .flanks(&model)
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
        &|start, f| run_planetary_wear(&model, wear, start, f),
        &on_update,
    );
    for t in &tasks {
        observer.finish(t);
    }
    let runs = runs?;
    let refs: Vec<&PlanetaryWearRun> = runs.iter().collect();
    let meta = RunMetadata::new("wear", &job.case);
    let artifacts = planetary_wear_artifacts(&model, &refs).with_figure_output(figures);
    let mut outcome = publish::publish(out, artifacts, Some(&meta), observer)?;
    let modes: Vec<(WearMode, Option<&WearStop>)> =
        refs.iter().map(|r| (r.mode, r.stopped.as_ref())).collect();
    outcome.incomplete = stops_of(&modes, observer);
    Ok(outcome)
}
