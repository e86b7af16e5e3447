//! The run job on a helical pair (`gear.helix_angle_deg` > 0, docs/MODEL.md 11.5): the
//! slice stiffness study with ISO 6336's values and the face load (as `gearwear
//! stiffness`), the steady state of the new teeth on the planar model (as `gearwear
//! dynamics`), the wear studies per face slice, dynamic and quasi-static, checkpointed after
//! every update and resumable exactly as `gearwear wear` on the case (`study::helical_wear`),
//! the dynamic response at the paper's wear states taken from the dynamic run as the spur
//! pair's run takes them (`study::paper`), and the report (`report::run_helical`). Each
//! study's files are the bytes its own job writes, in its own folder of the run's.
//!
//! What the planar model refuses (per-tooth inputs, profile modifications, faults, worn
//! geometry, Pedrero's law, too many contact lines) is refused with `gearwear wear`'s
//! messages, before any work. Under a `[load_spectrum]` (docs/MODEL.md 11.7) the wear runs
//! are `gearwear wear`'s under the spectrum (`duty::wear`, checkpointed per bin as
//! `app::duty_runs`) with the life table (`duty::study::run_duty_study`), and the
//! stiffness, the new teeth and the wear states are those of the monitoring bin. A pair
//! on axial bearings is warned when its gears shift axially by more than 5 % of the face
//! width with new teeth (`helical_dynamics::axial_shift_warning`, at every bin).

use super::duty::{build_spectrum_model, spectrum_metadata, spectrum_stops};
use super::duty_runs::run_spectrum_job_modes;
use super::dynamics::pair_dynamics_artifacts;
use super::observer::Observer;
use super::stiffness::helical_stiffness_study;
use super::wear_runs::{run_modes, stops};
use super::{budget, build_dynamics_model, publish, JobError, Outcome, RunJob};
use crate::duty::study::run_duty_study;
use crate::duty::wear::SpectrumRun;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::summary::ResponseSummary;
use crate::report::duty::duty_wear_artifacts;
use crate::report::figure_output::FigureOutput;
use crate::report::run_helical::{helical_run_artifacts, HelicalDuty, HelicalRun};
use crate::report::wear::wear_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::Job as Cost;
use crate::study::helical_dynamics::axial_shift_warning;
use crate::study::paper::{run_paper_study, WearStateResult};
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;
use crate::wear::WearState;

/// Run the whole study of the helical pair in `job.case` (see the module docs).
pub fn run_of_helical(
    job: &RunJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "run";
    // In `gearwear wear`'s order: the budget, then the model's refusals.
    budget::check(&job.case, Cost::Run, job.budget.as_ref())?;
    if job.case.load_spectrum.is_some() {
        return run_of_helical_under_spectrum(job, figures, observer);
    }
    crate::study::helical_teeth::refuse_for_wear(
        &job.case,
        crate::study::helical_teeth::RUN_STUDY,
    )?;
    let model = build_dynamics_model(&job.case, observer)?;
    let (stiffness, stiffness_warnings) = helical_stiffness_study(&job.case)?;
    // The planar model holds the slice model's and the face load's warnings already.
    for w in stiffness_warnings
        .iter()
        .filter(|w| !model.warnings.contains(w))
    {
        observer.warning(w);
    }
    let meta = RunMetadata::of_model(name, &model);
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    let out = (job.out.as_deref(), job.resume, job.replace);
    let study = run_modes(
        name,
        &model,
        &modes,
        &meta,
        out,
        observer,
        |model, starts, on_update| {
            let mut s = starts.into_iter();
            let d0 = s.next().unwrap_or(WearRun::new(WearMode::Dynamic));
            let q0 = s.next().unwrap_or(WearRun::new(WearMode::QuasiStatic));
            run_paper_study(model, d0, q0, on_update)
        },
    )?;
    let mut s = study.runs;
    observer.note("run: the helical pair's steady state with new teeth");
    let (new_teeth, dynamics) = new_teeth(&model, Some(observer))?;
    s.wear_states.insert(0, new_teeth);
    let wear = wear_artifacts(&model, &[&s.dynamic, &s.quasi_static]);
    let run = HelicalRun {
        model: &model,
        study: &s,
        stiffness,
        stiffness_meta: RunMetadata::new("stiffness", &job.case),
        dynamics,
        wear,
        duty: None,
    };
    let artifacts =
        helical_run_artifacts(run, &meta, figures).map_err(|e| JobError::Failed(e.into()))?;
    let incomplete = stops(&[&s.dynamic, &s.quasi_static], observer);
    let mut outcome = publish::publish(study.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = incomplete;
    Ok(outcome)
}

/// A helical pair's run under its case's `[load_spectrum]` (module docs): the bins'
/// models (every bin's axial shift warned), the stiffness study of the monitoring bin's
/// operating point, the spectrum's wear runs and life table, the new teeth at the
/// monitoring bin, and the helical run's artifacts with `gearwear wear`'s under the
/// spectrum in `wear/` and the duty-cycle section.
fn run_of_helical_under_spectrum(
    job: &RunJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "run";
    let sm = build_spectrum_model(&job.case, observer)?;
    let monitor = &sm.bins[sm.monitoring];
    let monitor_case = job.case.at_bin(sm.monitoring);
    let (stiffness, stiffness_warnings) = helical_stiffness_study(&monitor_case)?;
    for w in stiffness_warnings
        .iter()
        .filter(|w| !sm.warnings().contains(w))
    {
        observer.warning(w);
    }
    let meta = spectrum_metadata(name, &sm);
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    let out = (job.out.as_deref(), job.resume, job.replace);
    let study = run_spectrum_job_modes(name, &sm, &modes, &meta, out, observer, run_duty_study)?;
    let mut duty = study.runs;
    let refs: Vec<&SpectrumRun> = duty.runs.iter().collect();
    let incomplete = spectrum_stops(&sm, &refs, observer);
    let Some(mut s) = duty.paper.take() else {
        return Err(JobError::Failed(anyhow::anyhow!(
            "the duty-cycle study returned no runs"
        )));
    };
    observer.note("run: the helical pair's steady state with new teeth at the monitoring bin");
    // Its axial shift was warned with every bin's, named by the bin.
    let (new_teeth, dynamics) = new_teeth(monitor, None)?;
    s.wear_states.insert(0, new_teeth);
    let wear = duty_wear_artifacts(&sm, &refs, duty.life.as_ref());
    let run = HelicalRun {
        model: monitor,
        study: &s,
        stiffness,
        stiffness_meta: RunMetadata::new("stiffness", &monitor_case),
        dynamics,
        wear,
        duty: Some(HelicalDuty {
            sm: &sm,
            runs: &duty.runs,
            life: duty.life.as_ref(),
        }),
    };
    let artifacts =
        helical_run_artifacts(run, &meta, figures).map_err(|e| JobError::Failed(e.into()))?;
    let mut outcome = publish::publish(study.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = incomplete;
    Ok(outcome)
}

/// The steady state of the new teeth as `gearwear dynamics` solves it (no external
/// error, the unworn state of the grid) as the run's first wear state (0 µm), and what
/// `gearwear dynamics` writes of it; its axial shift warned to `warn` as `gearwear
/// dynamics` warns it (`helical_dynamics::axial_shift_warning`; `None`: warned already).
fn new_teeth(
    model: &Model,
    warn: Option<&dyn Observer>,
) -> Result<(WearStateResult, crate::report::artifacts::Artifacts), JobError> {
    let wear = WearState::new(model.grid.len());
    let none = ExternalError::none();
    let response = model
        .dynamic(&wear, &none)
        .map_err(|e| JobError::Failed(anyhow::anyhow!(e)))?;
    if let (Some(observer), Some(w)) = (warn, axial_shift_warning(model, &response)) {
        observer.warning(&w);
    }
    let artifacts = pair_dynamics_artifacts(model, &response, &none, "new teeth");
    let state = WearStateResult {
        max_wear_um: 0.0,
        roughness_um: model.roughness_for(&wear),
        summary: ResponseSummary::of(&response),
        wear,
        response,
    };
    Ok((state, artifacts))
}
