//! Prognostics (issue 12): calibrate the wear model to a gearbox's observations and
//! predict its wear and remaining useful life with uncertainty.
//!
//! Pieces, data flowing down: [`observations`] (the CSV of measurements) and [`prior`]
//! (the `[calibration]` table) -> [`forward`] (one true wear study, read at any cycle
//! count) -> [`surrogate`] (reference runs that stand for every wear coefficient, by the
//! k x N invariance of Archard wear) -> `likelihood` (the noise model) -> [`grid`]
//! (exact posterior of one or two parameters) or `mcmc` (ensemble sampler) ->
//! [`calibrate`] -> [`predict`] (Monte Carlo ensemble, fans, remaining life). Randomness
//! comes from [`crate::rng`]: one stream per sample index, so runs are reproducible and
//! independent of the thread count and of sharding. docs/PROGNOSTICS.md states the
//! method and its measured accuracy.

pub mod band;
pub mod calibrate;
pub mod check;
pub mod fit_check;
pub mod forward;
pub mod grid;
pub mod indicator;
pub(crate) mod likelihood;
pub mod limits;
pub(crate) mod mcmc;
pub mod observations;
pub mod posterior_error;
pub mod predict;
pub mod prior;
pub mod quantity;

pub mod samples;
pub(crate) mod stats;
pub mod surrogate;
mod surrogate_duty;
#[cfg(test)]
mod tests_calibration;
pub mod train_forward;

pub use forward::{Crossing, Trajectory};
pub use observations::Observations;
pub use prior::{Parameter, Prior, Theta};
pub use quantity::Quantity;
pub use surrogate::Surrogate;
