//! `gearwear calibrate`: the posterior of the uncertain parameters given observations.

use super::args::CalibrateArgs;
use super::error::CliError;
use super::output::execute;
use crate::app::{CalibrateJob, CalibrationOptions, TableSource};
use crate::study::budget::Budget;

pub(crate) fn run(a: &CalibrateArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&CalibrateJob {
        case: a.case.load()?,
        observations: TableSource::File(a.observations.clone()),
        options: CalibrationOptions {
            seed: a.seed,
            samples: a.samples,
            walkers: a.walkers,
            steps: a.steps,
            check_runs: a.check_runs,
        },
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
