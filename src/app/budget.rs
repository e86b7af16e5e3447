//! The run budget in every job (`study::budget` estimates the cost): a job over its
//! budget is refused before anything is computed, naming the keys that drive the cost
//! and how to raise the budget. A job takes the budget as `Option<Budget>`: `None` runs
//! without the check, a scaled [`Budget`] raises it knowingly.

use super::JobError;
use crate::config::Case;
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::budget::{estimate, Budget, Job};

/// The cost of a prognostics job (calibrate, predict): each of its forward runs is a
/// dynamic wear study of the case at its sampled parameters, and the number of runs is
/// the user's explicit choice.
pub const FORWARD_RUN: Job = Job::Wear {
    dynamic: true,
    quasi_static: false,
};

/// The budget a front end passes by default.
pub const DEFAULT: Option<Budget> = Some(Budget::DEFAULT);

/// The remedy of a run over budget.
pub fn over_budget(message: String) -> Problem {
    Problem::new(message).remedy(Remedy::new(
        Words::new()
            .text("lower those keys, or raise the budget knowingly with ")
            .arg(Arg::BudgetScale)
            .text(" X (or drop the check with ")
            .arg(Arg::NoBudget)
            .text(")"),
    ))
}

/// Refuse `job` on `case` if it is over `budget` (`None`: no check).
pub fn check(case: &Case, job: Job, budget: Option<&Budget>) -> Result<(), JobError> {
    match budget {
        Some(b) => estimate(case, job)
            .check(b)
            .map_err(|m| JobError::input(over_budget(m))),
        None => Ok(()),
    }
}
