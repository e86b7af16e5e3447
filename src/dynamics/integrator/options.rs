//! Settings of the simplified Newton iteration of the DIRK stepper.

use super::IntegratorError;

/// Settings of the Newton iteration of [`Sdirk`](super::Sdirk). These set how accurately the implicit
/// stage equations are solved, not the truncation error of the step: keep them well
/// below the accuracy you expect from the step size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SdirkOptions {
    /// Absolute Newton tolerance, units of `y`, > 0 (same for all components; use
    /// [`Sdirk::set_abs_tol`](super::Sdirk::set_abs_tol) for per-component values, e.g. m and m/s).
    pub abs_tol: f64,
    /// Relative Newton tolerance, dimensionless, >= 0.
    pub rel_tol: f64,
    /// Newton iterations allowed per stage, >= 1.
    pub max_newton_iters: usize,
    /// Contraction rate in (0, 1) above which the Jacobian and LU are refreshed before
    /// the next step. Default 0.1: on a 16-state system with a +-30 % switching mesh
    /// stiffness (`tests_cost.rs`) it needed 6.1 Newton iterations per step against 6.5
    /// for 0.3-0.9, with the same number of Jacobians.
    pub refresh_rate: f64,
    /// Factorised iteration matrices `(I - h gamma J)^{-1}` of earlier step lengths kept
    /// with the current Jacobian (dropped when it is re-evaluated), and reused when a
    /// step of one of those lengths comes again: error control that alternates between
    /// a whole node interval and its half then factorises once per length, not once per
    /// switch. The matrix of a length is the same whether kept or rebuilt (up to the
    /// round-off of the step lengths, 1e-9 relative). Default 0 (none kept).
    pub kept_matrices: usize,
}

impl Default for SdirkOptions {
    fn default() -> Self {
        Self {
            abs_tol: 1e-12,
            rel_tol: 1e-9,
            max_newton_iters: 10,
            refresh_rate: 0.1,
            kept_matrices: 0,
        }
    }
}

impl SdirkOptions {
    pub(super) fn validate(&self) -> Result<(), IntegratorError> {
        if !(self.abs_tol > 0.0 && self.abs_tol.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "abs_tol must be finite and > 0",
            ));
        }
        if !(self.rel_tol >= 0.0 && self.rel_tol.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "rel_tol must be finite and >= 0",
            ));
        }
        if self.max_newton_iters == 0 {
            return Err(IntegratorError::InvalidSetting(
                "max_newton_iters must be >= 1",
            ));
        }
        if !(self.refresh_rate > 0.0 && self.refresh_rate < 1.0) {
            return Err(IntegratorError::InvalidSetting(
                "refresh_rate must be in (0, 1)",
            ));
        }
        Ok(())
    }
}
