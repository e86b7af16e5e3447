//! `gearwear run`: the paper's whole section 4 from one command, with a report.

use super::args::RunArgs;
use super::error::CliError;
use super::output::execute;
use crate::app::RunJob;
use crate::study::budget::Budget;

pub(crate) fn run(a: &RunArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&RunJob {
        case: a.case.load()?,
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        resume: a.resume,
        budget,
        figures: a.figures.request(),
    })
}
