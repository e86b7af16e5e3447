//! The run job: the paper's whole section 4 (mesh stiffness, the dynamic and quasi-static
//! wear studies with checkpoints, the dynamic response at three wear states) with its
//! report, figures and the CSV behind each. On a gear train, `app::run_train`; on a
//! planetary set, `app::run_planetary`; on a helical pair, `app::run_helical`.

use super::observer::{keep_going, Observer};
use super::wear_runs::{run_modes, stops};
use super::{budget, build_model, publish, Job, JobError, Outcome};
use crate::config::paper_case::{other_contact_path, runs_contact_twin};
use crate::config::Case;
use crate::report::figure_output::FigureRequest;
use crate::report::paper::run_artifacts;
use crate::store::RunMetadata;
use crate::study::budget::{Budget, Job as Cost};
use crate::study::paper::run_paper_study;
use crate::study::paper::PaperStudy;
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;
use std::path::PathBuf;

/// See the module docs.
#[derive(Debug, Clone)]
pub struct RunJob {
    /// The case whose full paper study runs.
    pub case: Case,
    /// Output folder (checkpoints, then the results); `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// Continue the wear studies from the checkpoints in the output folder.
    pub resume: bool,
    /// The run budget (`None`: no check).
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
        if !self.case.stage.is_empty() {
            if self.case.load_spectrum.is_some() {
                // Under a spectrum its wear has no per-tooth wear (docs/MODEL.md 9.10).
                let study = "`gearwear run` under a [load_spectrum]";
                crate::study::train::refuse_fault(&self.case, study)?;
            }
            return super::run_train::run_of_train(self, figures, observer);
        }
        if self.case.planetary.is_some() {
            return super::run_planetary::run_of_planetary(self, figures, observer);
        }
        if self.case.gear.helix_angle_deg != 0.0 {
            return super::run_helical::run_of_helical(self, figures, observer);
        }
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
        let twin = contact_twin(&self.case, observer);
        let twin = twin.as_ref().map(|(m, t)| (m, t));
        let artifacts = run_artifacts(&model, s, twin, &meta, figures);
        let incomplete = stops(&[&s.dynamic, &s.quasi_static], observer);
        let mut outcome = publish::publish(study.out, artifacts, Some(&meta), observer)?;
        outcome.incomplete = incomplete;
        Ok(outcome)
    }
}

/// The paper's case under the other contact model (`contact.path`, docs/MODEL.md section
/// 4.2), so that the report sets the nominal path (the paper's own model) and the
/// extended contact (the default) beside the paper's numbers (issue 32); run whole,
/// without checkpoints. `None` for any other case, where the other model does not take
/// the case (Pedrero's law given explicitly, which the extended contact refuses), or
/// where its study fails (a warning says so; the case's own results stand).
fn contact_twin(case: &Case, observer: &dyn Observer) -> Option<(Model, PaperStudy)> {
    if !runs_contact_twin(case) {
        return None;
    }
    let mut twin = case.clone();
    twin.contact.path = other_contact_path(case.contact.path);
    let name = serde_json::to_value(twin.contact.path).unwrap_or_default();
    observer.note(&format!(
        "the paper's case again with contact.path = {name}, for the comparison's other column"
    ));
    let (d, q) = (
        WearRun::new(WearMode::Dynamic),
        WearRun::new(WearMode::QuasiStatic),
    );
    let study = Model::from_case(&twin)
        .map_err(|e| anyhow::anyhow!(e.0.join("; ")))
        .and_then(|m| Ok((run_paper_study(&m, d, q, &|_, _| keep_going(observer))?, m)));
    match study {
        Ok((study, model)) => Some((model, study)),
        Err(e) => {
            observer.warning(&format!(
                "the paper's case with contact.path = {name} (the comparison's other column) gave no result: {e:#}"
            ));
            None
        }
    }
}
