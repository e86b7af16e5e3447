//! Settings of the prognostics jobs out of their ranges (`prognostics::limits`), each
//! turned into a problem of the argument it is given as.

use super::JobError;
use crate::remedy::{Arg, Problem};

/// The argument a prognostics setting is given as (`prognostics::limits`).
fn arg_of(setting: &str) -> Option<Arg> {
    Some(match setting {
        "samples" => Arg::Samples,
        "walkers" => Arg::Walkers,
        "steps" => Arg::Steps,
        "check_runs" => Arg::CheckRuns,
        "grid_points" => Arg::GridPoints,
        "limit_um" => Arg::LimitUm,
        "cycles" => Arg::Cycles,
        _ => return None,
    })
}

/// Settings out of their ranges (`prognostics::limits`), each as a problem of its
/// argument; every one at once.
pub fn check_settings(problems: Vec<crate::prognostics::limits::Problem>) -> Result<(), JobError> {
    if problems.is_empty() {
        return Ok(());
    }
    Err(JobError::Input(
        problems
            .into_iter()
            .map(|p| match arg_of(p.setting) {
                Some(a) => Problem::of(a, p.message),
                None => Problem::new(p.message),
            })
            .collect(),
    ))
}
