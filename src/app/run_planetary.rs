//! The run job on a planetary set (`[planetary]`): the set's stiffness study (meshes,
//! phases, kinematics, the lumped model's modes), its steady state with new teeth, what a
//! sensor on the fixed ring hears of it (when the ring is fixed and the record steady),
//! the wear studies of every member (dynamic and quasi-static, checkpointed after every
//! update of the whole set and resumable exactly as `gearwear wear` on it,
//! `app::wear_planetary`), and the report with its planetary section
//! (`report::run_planetary`). Each study's files are the bytes its own job writes, in its
//! own folder of the run's.

use super::observer::Observer;
use super::signals_planetary::{ring_sensor_problem, ring_signals_artifacts};
use super::wear_planetary::{planetary_stops, refuse_spectrum, run_planetary_modes};
use super::{publish, JobError, Outcome, RunJob};
use crate::report::dynamics_planetary::planetary_dynamics_artifacts;
use crate::report::figure_output::FigureOutput;
use crate::report::run_planetary::{planetary_run_artifacts, PlanetaryRun};
use crate::report::stiffness_planetary::planetary_stiffness_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::planetary::estimate_planetary_wear;
use crate::study::budget::Job as Cost;
use crate::study::planetary::PlanetaryStudy;
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use crate::study::wear_loop::WearMode;

/// Run the whole study of the planetary set in `job.case` (see the module docs).
pub fn run_of_planetary(
    job: &RunJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let case = &job.case;
    refuse_spectrum(case)?;
    // The studies run one after the other; each must fit the budget alone (the steady
    // state's estimate is `gearwear dynamics`', the wear's `gearwear wear`'s).
    super::budget::check(case, Cost::Dynamics, job.budget.as_ref())?;
    let model = PlanetaryWearModel::from_case(case)?;
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    super::budget::check_estimate(
        &estimate_planetary_wear(&model, &case.wear, &modes),
        job.budget.as_ref(),
    )?;
    for w in &model.dynamics.study.warnings {
        observer.warning(w);
    }
    let meta = RunMetadata::new("run", case);
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_planetary_modes("run", &model, &case.wear, &modes, &meta, out, observer)?;
    let refs: Vec<&PlanetaryWearRun> = runs.runs.iter().collect();
    observer.note("run: the set's stiffness study and its steady state with new teeth");
    let study = PlanetaryStudy::from_case(case)?;
    let stiffness = planetary_stiffness_artifacts(&study);
    let mut d = PlanetaryDynamics::from_case(case)?;
    let response = d
        .solve()
        .map_err(|e| JobError::Failed(anyhow::Error::new(e)))?;
    let dynamics = planetary_dynamics_artifacts(&d, &response);
    let signals = match ring_sensor_problem(case) {
        Some(p) => {
            observer.note(&format!("run: no ring sensor record ({p})"));
            None
        }
        None => Some(ring_signals_artifacts(case, &d, &response)?),
    };
    let run = PlanetaryRun {
        study: &study,
        dynamics: &d,
        stiffness,
        dynamics_artifacts: dynamics,
        signals,
        wear_model: &model,
        runs: &refs,
    };
    let artifacts =
        planetary_run_artifacts(run, &meta, figures).map_err(|e| JobError::Failed(e.into()))?;
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = planetary_stops(&refs, observer);
    Ok(outcome)
}
