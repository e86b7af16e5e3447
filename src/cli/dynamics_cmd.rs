//! `gearwear dynamics`: one steady-state evaluation of the tribo-dynamic model.

use super::args::DynamicsArgs;
use super::error::CliError;
use super::output::execute;
use crate::app::{DynamicsJob, TransmissionErrorSource};
use crate::study::budget::Budget;

pub(crate) fn run(a: &DynamicsArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&DynamicsJob {
        case: a.case.load()?,
        transmission_error: a
            .transmission_error
            .clone()
            .map(TransmissionErrorSource::File),
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
