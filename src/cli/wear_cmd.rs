//! `gearwear wear`: the coupled dynamics-wear study and its quasi-static twin, with a
//! checkpoint after every update.

use super::args::{WearArgs, WearModeArg};
use super::error::CliError;
use super::output::execute;
use crate::app::WearJob;
use crate::study::budget::Budget;
use crate::study::wear_loop::WearMode;

pub(crate) fn run(a: &WearArgs, budget: Option<Budget>) -> Result<(), CliError> {
    let modes = match a.mode {
        WearModeArg::Dynamic => vec![WearMode::Dynamic],
        WearModeArg::QuasiStatic => vec![WearMode::QuasiStatic],
        WearModeArg::Both => vec![WearMode::Dynamic, WearMode::QuasiStatic],
    };
    execute(&WearJob {
        case: a.case.load()?,
        modes,
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        resume: a.resume,
        budget,
        figures: a.figures.request(),
    })
}
