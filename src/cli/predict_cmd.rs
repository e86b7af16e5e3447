//! `gearwear predict`: Monte Carlo prediction of wear, vibration indicators and remaining
//! life over posterior (or prior) samples; `gearwear predict-merge`: joins its shards.

use super::args::{ForwardArg, PredictArgs, PredictMergeArgs};
use super::error::flag;
use super::error::CliError;
use super::output::execute;
use crate::app::{
    ForwardModel, FutureInput, PredictJob, PredictMergeJob, PredictOptions, SpectrumSource,
    TableSource,
};
use crate::study::budget::Budget;
use crate::study::sweep::Shard;

pub(crate) fn run(a: &PredictArgs, budget: Option<Budget>) -> Result<(), CliError> {
    let shard = match &a.shard {
        Some(s) => Shard::parse(s).map_err(|p| CliError::input(p.render(flag)))?,
        None => Shard::ALL,
    };
    execute(&PredictJob {
        case: a.case.load()?,
        posterior: a.posterior.clone().map(TableSource::File),
        options: PredictOptions {
            limit_um: a.limit_um,
            cycles: a.cycles,
            seed: a.seed,
            samples: a.samples,
            grid_points: a.grid_points,
            forward: match a.forward {
                ForwardArg::Surrogate => ForwardModel::Surrogate,
                ForwardArg::Exact => ForwardModel::Exact,
            },
            check_runs: a.check_runs,
        },
        future: FutureInput {
            spectrum: a.future_spectrum.clone().map(SpectrumSource::File),
            from_cycles: a.future_from_cycles,
        },
        shard,
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}

pub(crate) fn merge(a: &PredictMergeArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&PredictMergeJob {
        inputs: a.inputs.clone(),
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
