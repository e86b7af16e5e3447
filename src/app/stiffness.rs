//! The stiffness job: mesh stiffness over a mesh period, the ISO 6336 cross-check, load
//! sharing and the quasi-static transmission error (paper Figure 2); on a gear train,
//! each stage's.

use super::observer::Observer;
use super::{budget, build_model, publish, Job, JobError, Outcome};
use crate::config::Case;
use crate::report::artifacts::Artifacts;
use crate::report::face_load::add_face_load_artifacts;
use crate::report::figure_output::FigureOutput;
use crate::report::figure_output::FigureRequest;
use crate::report::stiffness::stiffness_artifacts;
use crate::report::stiffness_helical::helical_stiffness_artifacts;
use crate::report::stiffness_planetary::planetary_stiffness_artifacts;
use crate::report::stiffness_train::train_stiffness_artifacts_of;
use crate::store::RunMetadata;
use crate::study::budget::{Budget, Job as Cost};
use crate::study::face_load::{face_load, lead_keys, CaseFaceLoad};
use crate::study::helical::HelicalModel;
use crate::study::planetary::PlanetaryStudy;
use crate::study::train_stages::stage_stiffness_models;
use std::path::PathBuf;

/// See the module docs.
#[derive(Debug, Clone)]
pub struct StiffnessJob {
    /// The case whose mesh stiffness is computed.
    pub case: Case,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl Job for StiffnessJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "stiffness"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        budget::check(&self.case, Cost::Stiffness, self.budget.as_ref())?;
        if !self.case.stage.is_empty() {
            return self.run_train(figures, observer);
        }
        if self.case.planetary.is_some() {
            return self.run_planetary(observer);
        }
        if self.case.gear.helix_angle_deg != 0.0 {
            return self.run_helical(figures, observer);
        }
        if !lead_keys(&self.case).is_empty() {
            return self.run_spur_lead(figures, observer);
        }
        let model = build_model(&self.case, observer)?;
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let meta = RunMetadata::of_model(self.name(), &model);
        let artifacts = stiffness_artifacts(&model).with_figure_output(figures);
        publish::publish(out, artifacts, Some(&meta), observer)
    }
}

impl StiffnessJob {
    /// A gear train: each stage's single-pair stiffness study
    /// (`report::stiffness_train`).
    fn run_train(
        &self,
        figures: FigureOutput,
        observer: &dyn Observer,
    ) -> Result<Outcome, JobError> {
        // Its helical stages on their slice models (docs/MODEL.md 4.3).
        let model = super::build_dynamics_model(&self.case, observer)?;
        let stages = stage_stiffness_models(&model)?;
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let meta = RunMetadata::of_model(self.name(), &model);
        let artifacts = train_stiffness_artifacts_of(&model, &stages).with_figure_output(figures);
        publish::publish(out, artifacts, Some(&meta), observer)
    }

    /// A planetary case: the set's meshes, phases, frequencies and lumped modes
    /// (`study::planetary`), `summary.json` only.
    fn run_planetary(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let study = PlanetaryStudy::from_case(&self.case)?;
        for w in &study.warnings {
            observer.warning(w);
        }
        if let Some(f) = study.section.active_fault() {
            // The summary holds the healthy meshes (a planetary stiffness study has no
            // per-tooth output yet): say so rather than let the fault pass unseen.
            observer.warning(&format!(
                "`planetary.fault` on {}: `gearwear stiffness` of a planetary set gives its healthy meshes' stiffness, phases and frequencies; the fault's stiffness reduction enters `gearwear dynamics`, `gearwear signals` and the sweep of dynamics",
                f.who()
            ));
        }
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let meta = RunMetadata::new(self.name(), &self.case);
        publish::publish(
            out,
            planetary_stiffness_artifacts(&study),
            Some(&meta),
            observer,
        )
    }

    /// A helical case: the slice model (`study::helical`) instead of the planar model.
    fn run_helical(
        &self,
        figures: FigureOutput,
        observer: &dyn Observer,
    ) -> Result<Outcome, JobError> {
        let (artifacts, warnings) = helical_stiffness_study(&self.case)?;
        for w in &warnings {
            observer.warning(w);
        }
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let meta = RunMetadata::new(self.name(), &self.case);
        let artifacts = artifacts.with_figure_output(figures);
        publish::publish(out, artifacts, Some(&meta), observer)
    }

    /// Warn of the face load's warnings, open the folder and publish `artifacts` with the
    /// face load added.
    fn publish_with_face_load(
        &self,
        mut artifacts: Artifacts,
        load: &CaseFaceLoad,
        meta: &RunMetadata,
        figures: FigureOutput,
        observer: &dyn Observer,
    ) -> Result<Outcome, JobError> {
        for w in &load.warnings {
            observer.warning(w);
        }
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        add_face_load_artifacts(load, &mut artifacts);
        let artifacts = artifacts.with_figure_output(figures);
        publish::publish(out, artifacts, Some(meta), observer)
    }

    /// A spur case with lead modifications or a misalignment: the spur study of the case
    /// without them (the planar model has no gap across the face) and the face load
    /// distribution of the pair cut into `stiffness.slices` slices (docs/MODEL.md 11.2).
    fn run_spur_lead(
        &self,
        figures: FigureOutput,
        observer: &dyn Observer,
    ) -> Result<Outcome, JobError> {
        let mut planar = self.case.clone();
        planar.modification = planar.modification.without_lead_keys();
        planar.operating.misalignment_um = None;
        planar.operating.misalignment_plane = None;
        let mut model = build_model(&planar, observer)?;
        let load = face_load(&HelicalModel::from_case(&self.case)?)?;
        model.case = self.case.clone();
        let meta = RunMetadata::of_model(self.name(), &model);
        let artifacts = stiffness_artifacts(&model);
        self.publish_with_face_load(artifacts, &load, &meta, figures, observer)
    }
}

/// What `gearwear stiffness` writes for the helical pair of `case` (the slice model,
/// `study::helical`, with its face load, `report::face_load`), and its warnings in the
/// order the job gives them (the slice model's, then the face load's); `gearwear run` on a
/// helical pair nests the same artifacts.
pub(crate) fn helical_stiffness_study(case: &Case) -> Result<(Artifacts, Vec<String>), JobError> {
    let model = HelicalModel::from_case(case)?;
    let load = face_load(&model)?;
    let mut artifacts = helical_stiffness_artifacts(&model);
    add_face_load_artifacts(&load, &mut artifacts);
    let warnings = model
        .warnings
        .iter()
        .chain(&load.warnings)
        .cloned()
        .collect();
    Ok((artifacts, warnings))
}
