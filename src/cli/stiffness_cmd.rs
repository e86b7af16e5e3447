//! `gearwear stiffness`: mesh stiffness over a mesh period, ISO 6336 cross-check, load
//! sharing and the quasi-static transmission error (paper Figure 2).

use super::args::StiffnessArgs;
use super::error::CliError;
use super::output::execute;
use crate::app::StiffnessJob;
use crate::study::budget::Budget;

pub(crate) fn run(a: &StiffnessArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&StiffnessJob {
        case: a.case.load()?,
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
