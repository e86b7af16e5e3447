//! One-step integrators for first-order ODE systems `y' = f(t, y)` with `y` an
//! `nalgebra::OVector<f64, D>`: `D = Const<16>` (a stack vector, sized at compile time)
//! for the paper's 8-DOF pair (8 displacements and 8 velocities), `D = Dyn` (a heap
//! vector sized when the train is assembled) for any other train.
//!
//! * [`Sdirk`]: L-stable, stiffly accurate diagonally implicit Runge-Kutta methods with
//!   simplified Newton iterations, for the tableaux of [`tableau`]: Alexander's 3-stage
//!   order-3 SDIRK (fixed steps, [`Sdirk::new`]) and the ESDIRK3(2) pair of Kennedy &
//!   Carpenter, whose embedded solution estimates the local error for step size control
//!   ([`Sdirk::try_step`], [`Sdirk::accept`]; the gear model's solver,
//!   `dynamics::period`). Meant for the stiff gear model whose eigenvalues reach about
//!   -1.4e8 1/s while steps are ~1e-6-1e-4 s, i.e. `h*lambda ~ -1e2 to -1e4`: explicit
//!   methods are unstable there and A-stable but not L-stable methods (trapezoidal rule)
//!   leave the stiff modes ringing with `|R| -> 1`.
//! * [`Rk4`]: the classical explicit fourth-order Runge-Kutta method, for non-stiff
//!   problems and as a second method in tests.
//!
//! Both implement [`Stepper`]. With a size known at compile time a step allocates nothing
//! on the heap: the vectors and matrices are on the stack and the LU factorisation is a
//! hand-written one (`lu.rs`); with `Dyn` the vectors of a step are allocated per step (a
//! few per Newton iteration), which is small beside the right-hand side of a train.
//! Work counters ([`StepStats`]) are returned per step and accumulated.
//!
//! Measured cost (`tests_cost.rs`, release build, one test thread, on a shared 2-core
//! machine under load, so noisy): on a 16-state stiff linear chain with h = 1e-5 s,
//! 0.9-1.7 us per SDIRK step (6 `rhs` calls and 6 matrix-vector products, no Jacobian
//! after the first) against 0.26-0.5 us per RK4 step (4 `rhs` calls), which on the stiff
//! system would need steps of ~1e-8 s.
//!
//! Units: `t` and `h` are in the system's time unit (seconds in gearwear); `y` in whatever
//! units the system uses; the absolute Newton tolerance is in the units of `y`.
//!
//! ```
//! use gearwear::dynamics::integrator::{Sdirk, SdirkOptions, Stepper};
//! use nalgebra::{Const, SVector};
//! // y' = -1e6 (y - cos t): stiff, relaxes onto cos t.
//! let mut sys = |t: f64, y: &SVector<f64, 1>| SVector::<f64, 1>::new(-1e6 * (y[0] - t.cos()));
//! let mut stepper = Sdirk::<Const<1>>::new(0.01, SdirkOptions::default()).unwrap();
//! let (mut t, mut y) = (0.0, SVector::<f64, 1>::new(1.0));
//! stepper.advance(&mut sys, &mut t, &mut y, 100).unwrap();
//! assert!((y[0] - 1.0_f64.cos()).abs() < 1e-6);
//! ```

use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim, OMatrix, OVector};
use thiserror::Error;

mod lu;
mod options;
mod rk4;
mod sdirk;
pub mod tableau;

#[cfg(test)]
mod tests_cost;
#[cfg(test)]
mod tests_esdirk;
#[cfg(test)]
mod tests_linear;
#[cfg(test)]
mod tests_nonlinear;

pub use rk4::Rk4;
pub use sdirk::{Sdirk, SdirkOptions, Trial};

/// Runs `$make` with `$dim` bound to the state dimension of size `$n`: `Const<N>` (stack
/// vectors and matrices, loops of known length) when `$n` is one of the listed sizes,
/// `Dyn($n)` (heap) otherwise. Each listed size compiles the generic code once more, so
/// the lists hold the sizes users meet (`dynamics::period`, `dynamics::planetary_steady`);
/// the results are bit for bit those of `Dyn` because every product the stepper forms on
/// its `D`-sized vectors is a matrix-vector or vector operation, whose loops nalgebra runs
/// in the same order whatever the dimension type (tests/stepper_sizes.rs). Not so for
/// matrix-matrix products: nalgebra hands a `Dyn` f64 product larger than 5 x 5 to
/// `matrixmultiply`'s blocked kernel and a `Const` one to its own loops, so the one such
/// product (the Schur complement in `lu.rs`) is kept on `DMatrix` on both paths.
macro_rules! with_state_size {
    ($n:expr, [$($size:literal),*], $dim:ident => $make:expr) => {
        match $n {
            $($size => {
                let $dim = nalgebra::Const::<$size>;
                $make
            })*
            n => {
                let $dim = nalgebra::Dyn(n);
                $make
            }
        }
    };
}
pub(crate) use with_state_size;

/// A state vector of dimension `D`.
pub type Vector<D> = OVector<f64, D>;
/// A square matrix of dimension `D`.
pub type Matrix<D> = OMatrix<f64, D, D>;

/// A first-order ODE system `y' = f(t, y)` of dimension `D` (`Const<N>` or `Dyn`).
///
/// `&mut self` lets implementations keep caches or counters. Any closure
/// `FnMut(f64, &OVector<f64, D>) -> OVector<f64, D>` is an `OdeSystem<D>` (with a
/// finite-difference Jacobian).
pub trait OdeSystem<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// The right-hand side `f(t, y)` (units of `y` per unit time).
    fn rhs(&mut self, t: f64, y: &Vector<D>) -> Vector<D>;

    /// The Jacobian `df/dy` at `(t, y)` (units 1/time for a homogeneous system), if the
    /// system can provide one. The default `None` makes the implicit stepper use forward
    /// finite differences ([`finite_difference_jacobian`]), costing `N + 1` calls of `rhs`
    /// that are counted in [`StepStats::rhs_calls`]. The Jacobian only steers the Newton
    /// iteration: an approximate one slows convergence but does not change the solution.
    fn jacobian(&mut self, _t: f64, _y: &Vector<D>) -> Option<Matrix<D>> {
        None
    }
}

impl<D: Dim, F> OdeSystem<D> for F
where
    F: FnMut(f64, &Vector<D>) -> Vector<D>,
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    fn rhs(&mut self, t: f64, y: &Vector<D>) -> Vector<D> {
        self(t, y)
    }
}

/// Why a step could not be taken. On any error the state passed to `step` is unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum IntegratorError {
    /// A setting is out of range (step size, tolerances, iteration limits).
    #[error("invalid integrator setting: {0}")]
    InvalidSetting(&'static str),
    /// The state, a right-hand side or a Jacobian value was NaN or infinite.
    #[error("non-finite state, derivative or Jacobian at t = {t}")]
    NonFinite {
        /// Start time of the failed step.
        t: f64,
    },
    /// The Newton iteration matrix `I - h*gamma*J` is singular.
    #[error("iteration matrix I - h*gamma*J is singular at t = {t}")]
    SingularMatrix {
        /// Time at which the Jacobian was evaluated.
        t: f64,
    },
    /// Newton's method did not converge on a stage even with a Jacobian re-evaluated for
    /// that stage.
    #[error(
        "Newton iteration failed at t = {t} (stage {stage}, {iterations} iterations, \
         contraction rate {rate:.3}) with a re-evaluated Jacobian; use a smaller step"
    )]
    NewtonFailed {
        /// Start time of the failed step.
        t: f64,
        /// Stage (0-based) that failed.
        stage: usize,
        /// Newton iterations spent on that stage.
        iterations: usize,
        /// Last observed contraction rate `theta = |dy_k| / |dy_(k-1)|` (NaN if none).
        rate: f64,
    },
}

/// Work counters, per step (returned by `step`, `steps == 1`) or accumulated
/// (`stats()` of a stepper, or returned by [`Stepper::advance`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StepStats {
    /// Completed steps.
    pub steps: u64,
    /// Calls of `OdeSystem::rhs`, including those made for finite-difference Jacobians.
    pub rhs_calls: u64,
    /// Jacobian evaluations (analytic or finite-difference).
    pub jacobian_evals: u64,
    /// LU factorisations of `I - h*gamma*J`.
    pub lu_factorizations: u64,
    /// Newton iterations (each costs one `rhs` call and one LU solve).
    pub newton_iterations: u64,
    /// Stage solves repeated with a re-evaluated Jacobian after a Newton failure.
    pub retries: u64,
    /// Largest Newton contraction rate `theta` observed (0 if never measured).
    pub max_rate: f64,
}

impl StepStats {
    /// Adds the counters of `other` to `self` (and keeps the larger `max_rate`).
    pub fn accumulate(&mut self, other: &StepStats) {
        self.steps += other.steps;
        self.rhs_calls += other.rhs_calls;
        self.jacobian_evals += other.jacobian_evals;
        self.lu_factorizations += other.lu_factorizations;
        self.newton_iterations += other.newton_iterations;
        self.retries += other.retries;
        self.max_rate = self.max_rate.max(other.max_rate);
    }
}

/// A fixed-step one-step method.
pub trait Stepper<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// The fixed step size `h` (time units).
    fn step_size(&self) -> f64;

    /// Advances `y` from `t` to `t + h` in place. On error `y` is left unchanged.
    fn step<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut Vector<D>,
    ) -> Result<StepStats, IntegratorError>;

    /// Takes `n_steps` steps from `*t`, updating `*t` and `*y`; returns the summed
    /// counters. Times are computed as `t0 + k*h` so that they do not drift. On error,
    /// `*t` and `*y` hold the last successfully reached state.
    fn advance<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: &mut f64,
        y: &mut Vector<D>,
        n_steps: usize,
    ) -> Result<StepStats, IntegratorError> {
        let t0 = *t;
        let h = self.step_size();
        let mut total = StepStats::default();
        for k in 1..=n_steps {
            total.accumulate(&self.step(sys, *t, y)?);
            *t = t0 + k as f64 * h;
        }
        Ok(total)
    }
}

/// Forward-difference Jacobian `J[:, j] = (f(t, y + d_j e_j) - f(t, y)) / d_j`
/// (Hairer & Wanner II, Sect. IV.8; Dennis & Schnabel, Sect. 5.4) with
/// `d_j = sqrt(eps) * max(|y_j|, floor_j)`: the relative increment balances truncation
/// (~d) and cancellation (~eps/d) errors; `floor_j` (units of `y_j`) is the magnitude
/// below which component `j` counts as zero (must be > 0). `f_y` must be `f(t, y)`. Makes `N` calls of
/// `rhs` (`N` the dimension).
pub fn finite_difference_jacobian<S: OdeSystem<D>, D: Dim>(
    sys: &mut S,
    t: f64,
    y: &Vector<D>,
    f_y: &Vector<D>,
    floor: &Vector<D>,
) -> Matrix<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let sqrt_eps = f64::EPSILON.sqrt();
    let (dim, _) = y.shape_generic();
    let mut jac = Matrix::<D>::zeros_generic(dim, dim);
    let mut y_pert = y.clone();
    for j in 0..y.len() {
        let yj = y[j];
        let step = sqrt_eps * yj.abs().max(floor[j]);
        // A zero or non-finite floor would give a zero step: fall back to sqrt(eps).
        y_pert[j] = yj
            + if step > 0.0 && step.is_finite() {
                step
            } else {
                sqrt_eps
            };
        // Use the increment actually represented in floating point.
        let d = y_pert[j] - yj;
        let col = (sys.rhs(t, &y_pert) - f_y) / d;
        jac.set_column(j, &col);
        y_pert[j] = yj;
    }
    jac
}
