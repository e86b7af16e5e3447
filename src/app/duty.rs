//! The wear and run jobs under a load spectrum (`[load_spectrum]` in the case): every bin
//! advances at every update (`duty::wear`), checkpointed per mode and bin
//! (`app::duty_runs`); `run` adds the life table and the report's duty-cycle section.
//! The jobs themselves (`WearJob`, `RunJob`) hand over here when the case has a spectrum.

use super::duty_runs::run_spectrum_job_modes;
use super::observer::Observer;
use super::wear_runs::stops;
use super::{publish, JobError, Outcome};
use crate::duty::contribution::combined_run;
use crate::duty::study::{run_duty_study, spectrum_life};
use crate::duty::wear::{run_spectrum_modes, SpectrumRun};
use crate::duty::SpectrumModel;
use crate::report::duty::{duty_run_artifacts, duty_wear_artifacts};
use crate::report::figure_output::FigureOutput;
use crate::store::RunMetadata;
use crate::study::wear_loop::{WearMode, WearRun};
use std::path::Path;

/// The models of every bin; their problems are input errors naming the bin, their
/// warnings (each once) go to `observer`.
pub fn build_spectrum_model(
    case: &crate::config::Case,
    observer: &dyn Observer,
) -> Result<SpectrumModel, JobError> {
    let sm = SpectrumModel::dynamics_from_case(case)?;
    for w in sm.warnings() {
        observer.warning(&w);
    }
    // A helical pair on axial bearings: its axial shift at every bin (docs/MODEL.md 11.6).
    for w in sm.axial_shift_warnings() {
        observer.warning(&w);
    }
    Ok(sm)
}

/// The metadata of a job under a spectrum: the whole case (its hash covers the bins) and
/// the values the monitoring bin's model resolved (every bin's operating point is in the
/// summary's `load_spectrum`).
pub(crate) fn spectrum_metadata(command: &str, sm: &SpectrumModel) -> RunMetadata {
    RunMetadata {
        resolved: Some(sm.bins[sm.monitoring].resolved()),
        ..RunMetadata::new(command, &sm.case)
    }
}

/// Tell `observer` about the runs that stopped early; the failure to return if one was the
/// solver's.
pub(crate) fn spectrum_stops(
    sm: &SpectrumModel,
    runs: &[&SpectrumRun],
    observer: &dyn Observer,
) -> Option<String> {
    let combined: Vec<WearRun> = runs
        .iter()
        .map(|r| combined_run(r, sm.monitoring))
        .collect();
    stops(&combined.iter().collect::<Vec<_>>(), observer)
}

/// The wear job under a spectrum.
pub fn wear_under_spectrum(
    command: &str,
    case: &crate::config::Case,
    modes: &[WearMode],
    (out, resume, replace): (Option<&Path>, bool, bool),
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let sm = build_spectrum_model(case, observer)?;
    let meta = spectrum_metadata(command, &sm);
    let runs = run_spectrum_job_modes(
        command,
        &sm,
        modes,
        &meta,
        (out, resume, replace),
        observer,
        |sm, starts, on_update| run_spectrum_modes(sm, starts, on_update),
    )?;
    let refs: Vec<&SpectrumRun> = runs.runs.iter().collect();
    // The same life table as `run`'s, in the dynamic mode when it ran.
    let life_mode = if modes.contains(&WearMode::Dynamic) {
        WearMode::Dynamic
    } else {
        WearMode::QuasiStatic
    };
    observer.note(&format!(
        "{command}: life to the wear limit under the spectrum and at each bin ({} runs)",
        sm.len() + 1
    ));
    let life = spectrum_life(&sm, life_mode).map_err(JobError::Failed)?;
    let mut outcome = publish::publish(
        runs.out,
        duty_wear_artifacts(&sm, &refs, Some(&life)).with_figure_output(figures),
        Some(&meta),
        observer,
    )?;
    outcome.incomplete = spectrum_stops(&sm, &refs, observer);
    Ok(outcome)
}

/// The run job under a spectrum.
pub fn run_under_spectrum(
    command: &str,
    case: &crate::config::Case,
    (out, resume, replace): (Option<&Path>, bool, bool),
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let sm = build_spectrum_model(case, observer)?;
    let meta = spectrum_metadata(command, &sm);
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    let study = run_spectrum_job_modes(
        command,
        &sm,
        &modes,
        &meta,
        (out, resume, replace),
        observer,
        run_duty_study,
    )?;
    let refs: Vec<&SpectrumRun> = study.runs.runs.iter().collect();
    let incomplete = spectrum_stops(&sm, &refs, observer);
    let artifacts = duty_run_artifacts(&sm, &study.runs, &meta, figures).ok_or_else(|| {
        JobError::Failed(anyhow::anyhow!("the duty-cycle study returned no runs"))
    })?;
    let mut outcome = publish::publish(study.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = incomplete;
    Ok(outcome)
}
