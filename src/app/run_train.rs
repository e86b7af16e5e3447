//! The run job on a gear train (`[[stage]]`): each stage's mesh stiffness, the train's
//! steady state with new teeth, the wear studies (dynamic and quasi-static: every mesh
//! worn at its own cycle count, checkpointed after every update of the whole train and
//! resumable exactly as `gearwear wear` on a train, `app::wear_train`), and the report
//! with a section per stage (`report::run_train`). Each study's files are the bytes its
//! own job writes, in its own folder of the run's.

use super::observer::Observer;
use super::wear_train::{run_train_modes, train_of, train_stops};
use super::{build_train_wear_model, publish, JobError, Outcome, RunJob};
use crate::dynamics::excitation::ExternalError;
use crate::report::figure_output::FigureOutput;
use crate::report::run_train::{train_run_artifacts, TrainRun};
use crate::store::RunMetadata;
use crate::study::budget::{estimate, Budget, Estimate, Job as Cost, Term};
use crate::study::train_stages::stage_models;
use crate::study::train_wear::TrainWearRun;
use crate::study::wear_loop::WearMode;
use crate::wear::WearState;

/// Run the whole study of the train in `job.case` (see the module docs).
pub fn run_of_train(
    job: &RunJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "run";
    check_budget(&job.case, job.budget.as_ref())?;
    if job.case.load_spectrum.is_some() {
        return super::duty_train::run_of_train_under_spectrum(job, figures, observer);
    }
    let model = build_train_wear_model(&job.case, observer)?;
    let train = train_of(&model)?;
    let stages = stage_models(&model)?;
    let meta = RunMetadata::of_model(name, &model);
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_train_modes(name, &model, train, &modes, &meta, out, observer)?;
    let refs: Vec<&TrainWearRun> = runs.runs.iter().collect();
    observer.note("run: the train's steady state with new teeth");
    let response = model
        .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
        .map_err(|e| JobError::Failed(anyhow::anyhow!(e)))?;
    let run = TrainRun {
        model: &model,
        train,
        stages: &stages,
        response: &response,
        runs: &refs,
    };
    let artifacts =
        train_run_artifacts(&run, &meta, figures).map_err(|e| JobError::Failed(e.into()))?;
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = train_stops(&refs, observer);
    Ok(outcome)
}

/// Refuse the run of the train in `case` over `budget` (`None`: no check). Its studies
/// run one after the other: the wear studies of both modes (their own estimate, that of
/// `gearwear wear`), then one dynamic evaluation (that of `gearwear dynamics`); each must
/// fit alone (memory, the give-up time of a failing evaluation), and their times add up.
/// Their memory does not: a study's recorded signals are dropped before the next starts
/// (what stays, the wear records, is in the wear study's own estimate).
fn check_budget(case: &crate::config::Case, budget: Option<&Budget>) -> Result<(), JobError> {
    let wear = estimate(
        case,
        Cost::Wear {
            dynamic: true,
            quasi_static: true,
        },
    );
    let dynamics = estimate(case, Cost::Dynamics);
    super::budget::check_estimate(&wear, budget)?;
    super::budget::check_estimate(&dynamics, budget)?;
    let time_only = dynamics.terms.iter().map(|t| Term {
        bytes: 0.0,
        ..t.clone()
    });
    let together = Estimate {
        terms: wear.terms.iter().cloned().chain(time_only).collect(),
        ..wear.clone()
    };
    super::budget::check_estimate(&together, budget)
}
