//! `gearwear sweep`: the cross product of `--vary` axes, run in parallel, one row per case
//! (resumable, shardable), or one axis followed along its solution branches
//! (`--continuation`); `gearwear sweep-merge` joins shard tables. The sweep itself is the
//! job `app::SweepJob` (output layout in its docs).

use super::args::{ContinuationArg, SweepArgs, SweepMergeArgs, SweepRunArg};
use super::error::flag;
use super::error::CliError;
use super::output::execute;
use crate::app::{SweepJob, SweepMergeJob};
use crate::study::budget::Budget;
use crate::study::sweep::{parse_vary, Continuation, Shard, SweepPlan, SweepRun};

pub(crate) fn run(a: &SweepArgs, budget: Option<Budget>) -> Result<(), CliError> {
    let base = a.case.load()?;
    let (axes, problems): (Vec<_>, Vec<_>) = a
        .vary
        .iter()
        .map(|v| parse_vary(v))
        .partition(Result::is_ok);
    if !problems.is_empty() {
        let p = problems.into_iter().filter_map(Result::err);
        return Err(CliError::Input(p.map(|p| p.render(flag)).collect()));
    }
    let plan = SweepPlan::new(axes.into_iter().filter_map(Result::ok).collect())
        .map_err(|p| CliError::input(p.render(flag)))?;
    let shard = match &a.shard {
        Some(s) => Shard::parse(s).map_err(|p| CliError::input(p.render(flag)))?,
        None => Shard::ALL,
    };
    execute(&SweepJob {
        base,
        plan,
        run: match a.run {
            SweepRunArg::Dynamics => SweepRun::Dynamics,
            SweepRunArg::Wear => SweepRun::Wear,
        },
        shard,
        continuation: a.continuation.map(|c| match c {
            ContinuationArg::Up => Continuation::Up,
            ContinuationArg::Down => Continuation::Down,
            ContinuationArg::Both => Continuation::Both,
        }),
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}

pub(crate) fn merge(a: &SweepMergeArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&SweepMergeJob {
        inputs: a.inputs.clone(),
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
