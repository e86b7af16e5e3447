//! The simplified Newton iteration on one stage of the DIRK stepper (see the module
//! docs of `sdirk.rs` for the stopping rule and the Jacobian policy).

use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim};

use super::{Failure, Sdirk};
use crate::dynamics::integrator::{OdeSystem, StepStats, Vector};

impl<D: Dim> Sdirk<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// Solves the stage equation `Y = base + h gamma f(t_i, Y)` by simplified Newton
    /// from `*start` with the current iteration matrix. Returns `Y` and the largest
    /// contraction rate seen. On failure `*start` holds the last iterate reached while contracting (a
    /// better point for a new Jacobian). With `early_abort`, gives up as soon as the
    /// tolerance looks out of reach in the iterations left (a refresh is cheaper).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn solve_stage<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t_i: f64,
        hg: f64,
        inv_scale: &Vector<D>,
        base: &Vector<D>,
        start: &mut Vector<D>,
        early_abort: bool,
        st: &mut StepStats,
    ) -> Result<(Vector<D>, f64), Failure> {
        let max_iter = self.opts.max_newton_iters;
        let n = start.len() as f64;
        let mut y_stage = start.clone();
        // Before a rate is measured, assume the worst one the refresh policy tolerates
        // (or the last measured one if worse): a first correction is accepted alone
        // only if it is already within ~1/eta tolerances.
        let eta_floor = self.opts.refresh_rate / (1.0 - self.opts.refresh_rate);
        let mut eta = self.eta.max(eta_floor);
        let mut prev_norm = 0.0;
        let mut rate = f64::NAN;
        let mut max_rate: f64 = 0.0;
        for iters in 1..=max_iter {
            let f = sys.rhs(t_i, &y_stage);
            st.rhs_calls += 1;
            st.newton_iterations += 1;
            let delta = self.m_inv.apply(&((base + f * hg) - &y_stage));
            // Weighted RMS norm of the correction.
            let norm = (delta.component_mul(inv_scale).norm_squared() / n).sqrt();
            if !norm.is_finite() {
                return Err(Failure::NonFinite);
            }
            if iters > 1 {
                rate = norm / prev_norm;
                max_rate = max_rate.max(rate);
                st.max_rate = st.max_rate.max(rate);
                if rate.is_nan() || rate >= 0.99 {
                    return Err(Failure::Newton {
                        iterations: iters,
                        rate,
                    });
                }
                eta = rate / (1.0 - rate);
            }
            y_stage += delta;
            prev_norm = norm;
            if iters > 1 {
                start.clone_from(&y_stage);
            }
            if eta * norm <= 1.0 {
                if !y_stage.iter().all(|v| v.is_finite()) {
                    return Err(Failure::NonFinite);
                }
                self.eta = eta;
                return Ok((y_stage, max_rate));
            }
            // Predicted error after the remaining iterations (Hairer & Wanner II, IV.8).
            let left = (max_iter - iters) as i32;
            if early_abort && iters > 1 && eta * norm * rate.powi(left) > 1.0 {
                return Err(Failure::Newton {
                    iterations: iters,
                    rate,
                });
            }
        }
        Err(Failure::Newton {
            iterations: max_iter,
            rate,
        })
    }
}
