//! The wear job: the coupled dynamics-wear study and/or its quasi-static twin, with a
//! checkpoint after every update when it has an output folder (and resumable from it);
//! under a load spectrum it hands off to [`super::duty`], on a gear train to
//! [`super::wear_train`], on a train under a spectrum to [`super::duty_train`], on a
//! planetary set to [`super::wear_planetary`]. A helical pair runs on its planar model
//! with its slices' wear (`study::helical_wear`, docs/MODEL.md 11.3), under a spectrum too
//! ([`super::duty`], docs/MODEL.md 11.7). The runner it shares with the paper's study and
//! the spectrum's runs is [`super::wear_runs`].

use super::observer::Observer;
use super::wear_runs::{run_modes, stops};
use super::{budget, build_model, publish, Job, JobError, Outcome};
use crate::config::Case;
use crate::report::figure_output::FigureRequest;
use crate::report::wear::wear_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::{Budget, Job as Cost};
use crate::study::wear_loop::{run_wear_modes, WearMode, WearRun};
use std::path::PathBuf;

/// See the module docs.
#[derive(Debug, Clone)]
pub struct WearJob {
    /// The case whose wear is computed.
    pub case: Case,
    /// The modes to run, in order (the two run in parallel).
    pub modes: Vec<WearMode>,
    /// Output folder (checkpoints, then the results); `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Continue from the checkpoints in the output folder.
    pub resume: bool,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl Job for WearJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "wear"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        if self.case.planetary.is_some() && self.case.load_spectrum.is_some() {
            return super::duty_planetary::wear_of_planetary_under_spectrum(
                self, figures, observer,
            );
        }
        if self.case.planetary.is_some() {
            return super::wear_planetary::wear_of_planetary(self, figures, observer);
        }
        if self.case.load_spectrum.is_some() {
            // A train's wear under a spectrum has no per-tooth wear (docs/MODEL.md 9.10).
            let study = "`gearwear wear` under a [load_spectrum]";
            crate::study::train::refuse_fault(&self.case, study)?;
        }
        let cost = Cost::Wear {
            dynamic: self.modes.contains(&WearMode::Dynamic),
            quasi_static: self.modes.contains(&WearMode::QuasiStatic),
        };
        budget::check(&self.case, cost, self.budget.as_ref())?;
        if !self.case.stage.is_empty() && self.case.load_spectrum.is_some() {
            return super::duty_train::wear_of_train_under_spectrum(self, figures, observer);
        }
        if !self.case.stage.is_empty() {
            return super::wear_train::wear_of_train(self, figures, observer);
        }
        if self.case.load_spectrum.is_some() {
            let out = (self.out.as_deref(), self.resume, self.replace);
            return super::duty::wear_under_spectrum(
                self.name(),
                &self.case,
                &self.modes,
                out,
                figures,
                observer,
            );
        }
        let model = if self.case.gear.helix_angle_deg != 0.0 {
            crate::study::helical_teeth::refuse_for_wear(
                &self.case,
                crate::study::helical_teeth::WEAR_STUDY,
            )?;
            let m = super::build_dynamics_model(&self.case, observer)?;
            // On axial bearings: its axial shift with new teeth (docs/MODEL.md 11.6).
            if let Some(w) = crate::study::helical_dynamics::new_teeth_axial_shift_warning(&m) {
                observer.warning(&w);
            }
            m
        } else {
            build_model(&self.case, observer)?
        };
        let meta = RunMetadata::of_model(self.name(), &model);
        let runs = run_modes(
            self.name(),
            &model,
            &self.modes,
            &meta,
            (self.out.as_deref(), self.resume, self.replace),
            observer,
            |model, starts, on_update| run_wear_modes(model, starts, on_update),
        )?;
        let refs: Vec<&WearRun> = runs.runs.iter().collect();
        let mut outcome = publish::publish(
            runs.out,
            wear_artifacts(&model, &refs).with_figure_output(figures),
            Some(&meta),
            observer,
        )?;
        outcome.incomplete = stops(&refs, observer);
        Ok(outcome)
    }
}
