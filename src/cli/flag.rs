//! How the command line spells a job's arguments in messages. Public so that
//! tests/no_flags.rs checks every message against the same table.

use crate::remedy::Arg;

/// How the command line spells a job's arguments in messages (`crate::remedy`).
pub fn flag(a: Arg) -> &'static str {
    match a {
        Arg::Override => "--set",
        Arg::CaseFile => "--config",
        Arg::Out => "--out",
        Arg::Resume => "--resume",
        Arg::Vary => "--vary",
        Arg::Shard => "--shard",
        Arg::Continuation => "--continuation",
        Arg::SweepRun => "--run",
        Arg::TransmissionError => "--transmission-error",
        Arg::Observations => "--observations",
        Arg::Posterior => "--posterior",
        Arg::Samples => "--samples",
        Arg::Walkers => "--walkers",
        Arg::Steps => "--steps",
        Arg::CheckRuns => "--check-runs",
        Arg::GridPoints => "--grid-points",
        Arg::LimitUm => "--limit-um",
        Arg::Cycles => "--cycles",
        Arg::BudgetScale => "--budget-scale",
        Arg::NoBudget => "--no-budget",
        Arg::Inputs => "input",
        Arg::Replace => "--replace",
        Arg::History => "--history",
        Arg::TorqueClasses => "--torque-classes",
        Arg::SpeedClasses => "--speed-classes",
        Arg::GapFactor => "--gap-factor",
        Arg::MergeBelowShare => "--merge-below-share",
        Arg::TransferPath => "--transfer-path",
        Arg::Design => "--design",
        Arg::FutureSpectrum => "--future-spectrum",
        Arg::FutureFromCycles => "--future-from-cycles",
        Arg::FigureFormats => "--figures",
        Arg::FigureSize => "--figure-size",
    }
}
