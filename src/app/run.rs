//! The run job: the paper's whole section 4 (mesh stiffness, the dynamic and quasi-static
//! wear studies with checkpoints, the dynamic response at three wear states) with its
//! report, figures and the CSV behind each.

use super::observer::Observer;
use super::wear_runs::{run_modes, stops};
use super::{budget, build_model, publish, Job, JobError, Outcome};
use crate::config::Case;
use crate::report::figure_output::FigureRequest;
use crate::report::paper::run_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::{Budget, Job as Cost};
use crate::study::paper::run_paper_study;
use crate::study::wear_loop::{WearMode, WearRun};
use std::path::PathBuf;

/// See the module docs.
#[derive(Debug, Clone)]
pub struct RunJob {
    pub case: Case,
    /// Output folder (checkpoints, then the results); `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// Continue the wear studies from the checkpoints in the output folder.
    pub resume: bool,
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl Job for RunJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "run"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        super::refuse_train(&self.case)?;
        budget::check(&self.case, Cost::Run, self.budget.as_ref())?;
        if self.case.load_spectrum.is_some() {
            let out = (self.out.as_deref(), self.resume, self.replace);
            return super::duty::run_under_spectrum(
                self.name(),
                &self.case,
                out,
                figures,
                observer,
            );
        }
        let model = build_model(&self.case, observer)?;
        let meta = RunMetadata::of_model(self.name(), &model);
        let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
        let study = run_modes(
            self.name(),
            &model,
            &modes,
            &meta,
            (self.out.as_deref(), self.resume, self.replace),
            observer,
            |model, starts, on_update| {
                let mut s = starts.into_iter();
                let d0 = s.next().unwrap_or(WearRun::new(WearMode::Dynamic));
                let q0 = s.next().unwrap_or(WearRun::new(WearMode::QuasiStatic));
                run_paper_study(model, d0, q0, on_update)
            },
        )?;
        let s = &study.runs;
        let artifacts = run_artifacts(&model, s, &meta, figures);
        let incomplete = stops(&[&s.dynamic, &s.quasi_static], observer);
        let mut outcome = publish::publish(study.out, artifacts, Some(&meta), observer)?;
        outcome.incomplete = incomplete;
        Ok(outcome)
    }
}
