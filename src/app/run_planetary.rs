//! The run job on a planetary set (`[planetary]`): the set's stiffness study (meshes,
//! phases, kinematics, the lumped model's modes), its steady state with new teeth, what a
//! sensor on the fixed ring hears of it (when the ring is fixed and the record steady),
//! the wear studies of every member (dynamic and quasi-static, checkpointed after every
//! update of the whole set and resumable exactly as `gearwear wear` on it,
//! `app::wear_planetary`), and the report with its planetary section
//! (`report::run_planetary`). Each study's files are the bytes its own job writes, in its
//! own folder of the run's. Under a `[load_spectrum]` the stiffness, dynamics and signals
//! studies are the set's at the monitoring bin's operating point, the wear studies run
//! under the spectrum (`app::duty_planetary`), and the report adds its duty-cycle section.

use super::observer::Observer;
use super::signals_planetary::{ring_sensor_problem, ring_signals_artifacts};
use super::wear_planetary::{planetary_stops, run_planetary_modes};
use super::{publish, JobError, Outcome, RunJob};
use crate::duty::planetary::{combined_planetary_run, PlanetarySpectrum, PlanetarySpectrumRun};
use crate::io::OutputDir;
use crate::report::dynamics_planetary::planetary_dynamics_artifacts;
use crate::report::figure_output::FigureOutput;
use crate::report::run_planetary::{planetary_run_artifacts, PlanetaryRun};
use crate::report::stiffness_planetary::planetary_stiffness_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::planetary::{estimate_planetary_spectrum_wear, estimate_planetary_wear};
use crate::study::budget::Job as Cost;
use crate::study::planetary::PlanetaryStudy;
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use crate::study::wear_loop::WearMode;

/// The wear runs of a run job: the set's runs (under a spectrum, read as one run each at
/// the monitoring bin), the spectrum's own runs (none without one) and the folder.
struct WearRuns {
    runs: Vec<PlanetaryWearRun>,
    spectrum_runs: Vec<PlanetarySpectrumRun>,
    out: Option<OutputDir>,
}

/// The wear studies of the run in both modes, at the case's operating point (`single`)
/// or under its spectrum (`spectrum`), each checked against the budget first.
fn wear_runs(
    job: &RunJob,
    (single, spectrum): (Option<&PlanetaryWearModel>, Option<&PlanetarySpectrum>),
    meta: &RunMetadata,
    observer: &dyn Observer,
) -> Result<WearRuns, JobError> {
    let case = &job.case;
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    let out = (job.out.as_deref(), job.resume, job.replace);
    if let Some(ps) = spectrum {
        super::budget::check_estimate(
            &estimate_planetary_spectrum_wear(&ps.models, &ps.shares, &case.wear, &modes),
            job.budget.as_ref(),
        )?;
        let r = super::duty_planetary::run_modes("run", ps, &modes, meta, out, observer)?;
        let runs = r
            .runs
            .iter()
            .map(|x| combined_planetary_run(x, ps.monitoring))
            .collect();
        return Ok(WearRuns {
            runs,
            spectrum_runs: r.runs,
            out: r.out,
        });
    }
    let model = single.ok_or_else(|| JobError::Failed(anyhow::anyhow!("no wear model")))?;
    super::budget::check_estimate(
        &estimate_planetary_wear(model, &case.wear, &modes),
        job.budget.as_ref(),
    )?;
    let r = run_planetary_modes("run", model, &case.wear, &modes, meta, out, observer)?;
    Ok(WearRuns {
        runs: r.runs,
        spectrum_runs: Vec::new(),
        out: r.out,
    })
}

/// Run the whole study of the planetary set in `job.case` (see the module docs).
pub fn run_of_planetary(
    job: &RunJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let case = &job.case;
    let spectrum = match case.load_spectrum {
        Some(_) => Some(PlanetarySpectrum::from_case(case)?),
        None => None,
    };
    // The studies at one operating point: the case's, or the monitoring bin's.
    let point = spectrum
        .as_ref()
        .map_or_else(|| case.clone(), |ps| case.at_bin(ps.monitoring));
    // The studies run one after the other; each must fit the budget alone (the steady
    // state's estimate is `gearwear dynamics`', the wear's `gearwear wear`'s).
    super::budget::check(&point, Cost::Dynamics, job.budget.as_ref())?;
    let single = match spectrum {
        Some(_) => None,
        None => Some(PlanetaryWearModel::from_case(case)?),
    };
    let model = match (&single, &spectrum) {
        (Some(m), _) => m,
        (None, Some(ps)) => ps.reference(),
        (None, None) => unreachable!("a model or a spectrum"),
    };
    // Before any study: the run's quasi-static wear comes last.
    if let Some(p) = model.quasi_static_problem() {
        return Err(JobError::input(p));
    }
    for w in &model.dynamics.study.warnings {
        observer.warning(w);
    }
    let meta = RunMetadata::new("run", case);
    let wear = wear_runs(job, (single.as_ref(), spectrum.as_ref()), &meta, observer)?;
    let refs: Vec<&PlanetaryWearRun> = wear.runs.iter().collect();
    let srefs: Vec<&PlanetarySpectrumRun> = wear.spectrum_runs.iter().collect();
    observer.note("run: the set's stiffness study and its steady state with new teeth");
    let study = PlanetaryStudy::from_case(&point)?;
    let stiffness = planetary_stiffness_artifacts(&study);
    let mut d = PlanetaryDynamics::from_case(&point)?;
    let response = d
        .solve()
        .map_err(|e| JobError::Failed(anyhow::Error::new(e)))?;
    let dynamics = planetary_dynamics_artifacts(&d, &response);
    let signals = match ring_sensor_problem(&point) {
        Some(p) => {
            observer.note(&format!("run: no ring sensor record ({p})"));
            None
        }
        None => Some(ring_signals_artifacts(&point, &d, &response)?),
    };
    let run = PlanetaryRun {
        study: &study,
        dynamics: &d,
        stiffness,
        dynamics_artifacts: dynamics,
        signals,
        wear_model: model,
        runs: &refs,
        duty: spectrum.as_ref().map(|ps| (ps, srefs.as_slice())),
    };
    let artifacts =
        planetary_run_artifacts(run, &meta, figures).map_err(|e| JobError::Failed(e.into()))?;
    let mut outcome = publish::publish(wear.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = planetary_stops(&refs, observer);
    Ok(outcome)
}
