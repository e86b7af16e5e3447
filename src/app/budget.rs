//! The run budget in every job: a job over its budget is refused before anything is
//! computed, naming the keys that drive the cost and how to raise the budget (the remedy,
//! worded with the front ends' arguments, is added here, at the application's edge). The
//! cost model itself, one module per job family, is `study::budget`. A job takes the
//! budget as `Option<Budget>`: `None` runs without the check, a scaled [`Budget`] raises
//! it knowingly.

use super::JobError;
use crate::config::Case;
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::budget::{estimate, Budget, Job};

/// The budget a front end passes by default.
pub const DEFAULT: Option<Budget> = Some(Budget::DEFAULT);

/// The remedy of a run over budget.
pub fn over_budget(message: impl std::fmt::Display) -> Problem {
    Problem::new(message.to_string()).remedy(Remedy::new(
        Words::new()
            .text("ease those keys (lower a length, count or rate; raise a speed), or raise the budget knowingly with ")
            .arg(Arg::BudgetScale)
            .text(" X (or drop the check with ")
            .arg(Arg::NoBudget)
            .text(")"),
    ))
}

/// Refuse `job` on `case` if it is over `budget` (`None`: no check).
/// Under a load spectrum, a bin the model refuses (a load beyond the flanks, a speed out
/// of range) is named rather than priced: the estimate of such a bin is meaningless (a
/// wear rate from a load the flanks cannot carry), so the wear and run jobs, which run
/// every bin, build the bins' models when their estimate is over the budget and return
/// the bins' problems when there are any (a spur or helical pair, a train; a planetary
/// set's bins are its own job's).
pub fn check(case: &Case, job: Job, budget: Option<&Budget>) -> Result<(), JobError> {
    let runs_bins = matches!(job, Job::Wear { .. } | Job::Run)
        && case.load_spectrum.is_some()
        && case.planetary.is_none();
    match budget {
        Some(b) => estimate(case, job).check(b).map_err(|m| {
            if runs_bins {
                if let Err(e) = crate::duty::SpectrumModel::dynamics_from_case(case) {
                    return JobError::from(e);
                }
            }
            JobError::input(over_budget(m))
        }),
        None => Ok(()),
    }
}

/// Refuse a job whose estimate, made once its inputs are read (observations, posterior,
/// shards, tables), is over `budget` (`None`: no check).
pub fn check_estimate(
    e: &crate::study::budget::Estimate,
    budget: Option<&Budget>,
) -> Result<(), JobError> {
    match budget {
        Some(b) => e.check(b).map_err(|m| JobError::input(over_budget(m))),
        None => Ok(()),
    }
}
