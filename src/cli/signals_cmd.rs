//! `gearwear signals`: one record of the case as a sensor records it.

use super::error::CliError;
use super::output::execute;
use super::signals_args::SignalsArgs;
use crate::app::{SignalsJob, TransferPathSource};
use crate::study::budget::Budget;

pub(crate) fn run(a: &SignalsArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&SignalsJob {
        case: a.case.load()?,
        transfer_path: a.transfer_path.clone().map(TransferPathSource::File),
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
