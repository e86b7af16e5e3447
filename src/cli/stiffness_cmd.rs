//! `gearwear stiffness`: mesh stiffness over a mesh period, ISO 6336 cross-check, load
//! sharing and the quasi-static transmission error (paper Figure 2).

use super::args::StiffnessArgs;
use super::output::{build_model, finish, open_out};
use super::CliError;
use crate::io::RunMetadata;
use crate::report::stiffness::stiffness_artifacts;

pub fn run(a: &StiffnessArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let out = open_out(&a.out, "stiffness")?;
    finish(
        out,
        stiffness_artifacts(&model),
        &RunMetadata::new("stiffness", &case),
    )
}
