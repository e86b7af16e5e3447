//! The dynamics job: one steady-state evaluation of the tribo-dynamic model with new
//! teeth, optionally with an external transmission error.

use super::observer::Observer;
use super::{budget, build_dynamics_model, publish, Job, JobError, Outcome};
use crate::config::Case;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::response::DynamicResponse;
use crate::remedy::Arg;
use crate::report::artifacts::Artifacts;
use crate::report::dynamics::dynamics_artifacts;
use crate::report::dynamics_planetary::planetary_dynamics_artifacts;
use crate::report::face_load::add_dynamic_face_load_artifacts;
use crate::report::figure_output::FigureRequest;
use crate::store::transmission_error::{read_transmission_error, transmission_error_from_deg_um};
use crate::store::RunMetadata;
use crate::study::budget::{Budget, Job as Cost};
use crate::study::face_load_dynamic::DynamicFaceLoad;
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::Model;
use crate::wear::WearState;
use std::path::PathBuf;

/// An external transmission error over one mesh period (positive adds to the mesh
/// compression, paper eq. 2).
#[derive(Debug, Clone)]
pub enum TransmissionErrorSource {
    /// A CSV file `pinion_angle_deg,error_um`.
    File(PathBuf),
    /// Samples (pinion angle deg, error um).
    Samples(Vec<(f64, f64)>),
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct DynamicsJob {
    /// The case whose steady state is computed.
    pub case: Case,
    /// A measured static transmission error replacing the model's (`None`: the model's).
    pub transmission_error: Option<TransmissionErrorSource>,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl Job for DynamicsJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "dynamics"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        budget::check(&self.case, Cost::Dynamics, self.budget.as_ref())?;
        if self.case.planetary.is_some() {
            return self.run_planetary(observer);
        }
        let model = build_dynamics_model(&self.case, observer)?;
        let period = model.pair.mesh_angle_rad();
        let external = match &self.transmission_error {
            Some(TransmissionErrorSource::File(p)) => read_transmission_error(p, period)?,
            Some(TransmissionErrorSource::Samples(s)) => transmission_error_from_deg_um(
                s,
                period,
                Arg::TransmissionError.plain(),
            )
            .map_err(|e| {
                JobError::input(crate::remedy::Problem::of(Arg::TransmissionError, e.reason))
            })?,
            None => ExternalError::none(),
        };
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let r = model
            .dynamic(&WearState::new(model.grid.len()), &external)
            .map_err(|e| JobError::Failed(anyhow::anyhow!(e)))?;
        if let Some(w) = crate::study::helical_dynamics::axial_shift_warning(&model, &r) {
            observer.warning(&w);
        }
        let label = if self.transmission_error.is_some() {
            "new teeth, external transmission error"
        } else {
            "new teeth"
        };
        let meta = RunMetadata::of_model(self.name(), &model);
        let artifacts = pair_dynamics_artifacts(&model, &r, &external, label);
        publish::publish(
            out,
            artifacts.with_figure_output(figures),
            Some(&meta),
            observer,
        )
    }
}

/// What `gearwear dynamics` writes for the response `r` of a single pair's `model` to
/// `external` (`label` names the state in figure titles): `report::dynamics`' artifacts,
/// with a helical pair's dynamic face load when it has lead gaps (`report::face_load`).
/// `gearwear run` on a helical pair nests the same artifacts.
pub(crate) fn pair_dynamics_artifacts(
    model: &Model,
    r: &DynamicResponse,
    external: &ExternalError,
    label: &str,
) -> Artifacts {
    let mut artifacts = dynamics_artifacts(model, r, label);
    if let Some(d) = DynamicFaceLoad::of(model, r, external) {
        let lead = model.helical.as_ref().and_then(|h| h.lead.as_ref());
        if let Some(l) = lead {
            add_dynamic_face_load_artifacts(&d, &l.static_load, &mut artifacts);
        }
    }
    artifacts
}

impl DynamicsJob {
    /// A planetary case: the set's dynamic model (`study::planetary_dynamics`), its steady
    /// state, `summary.json` and the mesh-force and motion tables.
    fn run_planetary(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        if self.transmission_error.is_some() {
            return Err(JobError::input(crate::remedy::Problem::of(
                Arg::TransmissionError,
                "a planetary set takes no external transmission error (its meshes' excitation is their stiffness and phasing)".to_string(),
            )));
        }
        let mut d = PlanetaryDynamics::from_case(&self.case)?;
        for w in &d.study.warnings {
            observer.warning(w);
        }
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let r = d
            .solve()
            .map_err(|e| JobError::Failed(anyhow::Error::new(e)))?;
        let meta = RunMetadata::new(self.name(), &self.case);
        publish::publish(
            out,
            planetary_dynamics_artifacts(&d, &r),
            Some(&meta),
            observer,
        )
    }
}
