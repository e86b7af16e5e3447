//! `gearwear dataset` and `gearwear dataset-merge`: parse, run the job, print.

use super::error::flag;
use super::error::CliError;
use super::output::execute;
use super::signals_args::{DatasetArgs, DatasetMergeArgs};
use crate::app::{DatasetJob, DatasetMergeJob, DesignSource};
use crate::study::budget::Budget;
use crate::study::dataset::Shard;

pub(crate) fn run(a: &DatasetArgs, budget: Option<Budget>) -> Result<(), CliError> {
    let shard = match &a.shard {
        Some(s) => Shard::parse(s).map_err(|p| CliError::input(p.render(flag)))?,
        None => Shard::ALL,
    };
    execute(&DatasetJob {
        design: DesignSource::file(&a.design)?,
        shard,
        out: a.out.clone(),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}

pub(crate) fn merge(a: &DatasetMergeArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&DatasetMergeJob {
        inputs: a.inputs.clone(),
        out: a.out.clone(),
        replace: super::output::replace(),
        figures: a.figures.request(),
        transfer_path: a.transfer_path.clone(),
        budget,
    })
}
