//! `gearwear dynamics`: one steady-state evaluation of the tribo-dynamic model.

use super::args::DynamicsArgs;
use super::output::{build_model, finish, open_out};
use super::CliError;
use crate::dynamics::excitation::ExternalError;
use crate::io::transmission_error::read_transmission_error;
use crate::io::RunMetadata;
use crate::report::dynamics::dynamics_artifacts;
use crate::wear::WearState;

pub fn run(a: &DynamicsArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let external = match &a.transmission_error {
        Some(p) => read_transmission_error(p, model.pair.mesh_angle_rad())?,
        None => ExternalError::none(),
    };
    let out = open_out(&a.out, "dynamics")?;
    let r = model
        .dynamic(&WearState::new(model.grid.len()), &external)
        .map_err(|e| CliError::Failed(e.into()))?;
    let label = if a.transmission_error.is_some() {
        "new teeth, external transmission error"
    } else {
        "new teeth"
    };
    finish(
        out,
        dynamics_artifacts(&model, &r, label),
        &RunMetadata::new("dynamics", &case),
    )
}
