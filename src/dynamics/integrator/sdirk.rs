//! Fixed-step SDIRK3 stepper (Alexander 1977, tableau in [`super::tableau`]) with a
//! simplified Newton iteration.
//!
//! Stage `i` solves `Y_i = y_n + h sum_{j<i} a_ij k_j + h gamma f(t_n + c_i h, Y_i)` with
//! the simplified Newton iteration (Hairer & Wanner II, Sect. IV.8, for one stage)
//! `(I - h gamma J) dY = y_n + h sum_{j<i} a_ij k_j + h gamma f(Y) - Y`, `Y += dY`,
//! where `J ~ df/dy` is evaluated at some earlier point. Because `h` is fixed, one LU
//! factorisation of `I - h gamma J` (applied as the inverse it yields: one
//! matrix-vector product per iteration) serves all stages *and* all later steps until
//! convergence slows.
//! The stage derivative is recovered as `k_i = (Y_i - y_n - h sum_{j<i} a_ij k_j) / (h gamma)`
//! rather than `f(Y_i)`: this avoids an extra `rhs` call and does not amplify the Newton
//! residual by the stiff Jacobian (Hairer & Wanner II, Sect. IV.8).
//! The method is stiffly accurate, so `y_{n+1} = Y_3`.
//!
//! Newton stopping rule (Hairer & Wanner II, Sect. IV.8): with the
//! contraction rate `theta_k = |dY_k| / |dY_(k-1)|` and `eta_k = theta_k / (1 - theta_k)`,
//! stop when `eta_k |dY_k| <= 1`, where `|.|` is the RMS norm weighted by
//! `abs_tol_i + rel_tol * |y_n,i|` (fixed over the step, as in Hairer's RADAU5). Before a
//! rate is measured (first iteration), `eta = max(eta_last, r / (1 - r))` with
//! `r = refresh_rate`, the worst rate the refresh policy tolerates. This deviates from Hairer's `eta_last^0.8`: without step
//! size control nothing would catch a first correction wrongly accepted after a sudden
//! change of the Jacobian (a stiffness jump), so one correction alone is accepted only
//! when it is already within ~`(1 - r) / r` tolerances. The iteration fails when
//! `theta >= 0.99`, on a non-finite value, after `max_newton_iters`, or (while a Jacobian
//! refresh is still allowed) when the predicted error after the remaining iterations,
//! `eta |dY| theta^(k_max - k)`, still exceeds 1.
//!
//! Jacobian policy: `J` and the LU are kept across stages and steps. When a stage's
//! iteration fails, `J` is re-evaluated at that stage's time `t_n + c_i h` and at the last
//! contracting iterate (else the predictor), the LU is rebuilt and only that stage is
//! continued from there: the converged earlier stages stay valid, since `J` only steers
//! Newton, and evaluating at the stage time catches jumps inside the step (e.g. a
//! mesh-stiffness switch). After `MAX_STAGE_REFRESHES` (2) refreshes for one stage a
//! further failure returns [`IntegratorError::NewtonFailed`]. A step whose largest
//! converged `theta` exceeded `refresh_rate` schedules a refresh at `(t_{n+1}, y_{n+1})`
//! before the next step.

use nalgebra::{SMatrix, SVector};

use super::lu::StaticLu;
use super::tableau::{A, C, GAMMA, STAGES};
use super::{finite_difference_jacobian, IntegratorError, OdeSystem, StepStats, Stepper};

/// Settings of the Newton iteration of [`Sdirk`]. These set how accurately the implicit
/// stage equations are solved, not the (uncontrolled) truncation error of the fixed step:
/// keep them well below the accuracy you expect from the step size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SdirkOptions {
    /// Absolute Newton tolerance, units of `y`, > 0 (same for all components; use
    /// [`Sdirk::set_abs_tol`] for per-component values, e.g. m and m/s).
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
}

impl Default for SdirkOptions {
    fn default() -> Self {
        Self {
            abs_tol: 1e-12,
            rel_tol: 1e-9,
            max_newton_iters: 10,
            refresh_rate: 0.1,
        }
    }
}

impl SdirkOptions {
    fn validate(&self) -> Result<(), IntegratorError> {
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

/// Jacobian re-evaluations allowed per stage after Newton failures, before giving up.
const MAX_STAGE_REFRESHES: usize = 2;

/// End of the previous successful step, used to predict the first stage of the next one.
#[derive(Debug, Clone, Copy)]
struct LastStep<const N: usize> {
    t_end: f64,
    y_end: SVector<f64, N>,
    /// Last stage derivative `k_3`, which approximates `f(t_end, y_end)`.
    k_end: SVector<f64, N>,
}

/// Why one attempt at a step failed (mapped to [`IntegratorError`] if it is final).
enum Failure {
    NonFinite,
    Newton { iterations: usize, rate: f64 },
}

/// Fixed-step, L-stable SDIRK3 stepper for stiff systems (see module docs). Holds the
/// factorised iteration matrix between steps; use one per independent trajectory.
#[derive(Debug, Clone)]
pub struct Sdirk<const N: usize> {
    h: f64,
    opts: SdirkOptions,
    abs_tol: SVector<f64, N>,
    /// `(I - h gamma J)^{-1}`, built from an LU factorisation (see [`super::lu`] for why
    /// the inverse rather than triangular solves).
    m_inv: SMatrix<f64, N, N>,
    /// `m_inv` must be (re)computed before the next step.
    refresh: bool,
    /// Hairer's `eta = theta / (1 - theta)` carried between stages and steps.
    eta: f64,
    last: Option<LastStep<N>>,
    stats: StepStats,
}

impl<const N: usize> Sdirk<N> {
    /// A stepper with step `h` (time units, finite and > 0) and Newton settings `opts`.
    pub fn new(h: f64, opts: SdirkOptions) -> Result<Self, IntegratorError> {
        opts.validate()?;
        if !(h > 0.0 && h.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "step size must be finite and > 0",
            ));
        }
        Ok(Self {
            h,
            opts,
            abs_tol: SVector::repeat(opts.abs_tol),
            m_inv: SMatrix::identity(),
            refresh: true,
            eta: 1.0,
            last: None,
            stats: StepStats::default(),
        })
    }

    /// Per-component absolute Newton tolerances (units of each `y_i`, all finite and > 0).
    pub fn set_abs_tol(&mut self, abs_tol: SVector<f64, N>) -> Result<(), IntegratorError> {
        if !abs_tol.iter().all(|a| *a > 0.0 && a.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "abs_tol must be finite and > 0",
            ));
        }
        self.abs_tol = abs_tol;
        Ok(())
    }

    /// Changes the step size; the iteration matrix is rebuilt at the next step.
    pub fn set_step_size(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !(h > 0.0 && h.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "step size must be finite and > 0",
            ));
        }
        self.h = h;
        self.invalidate_jacobian();
        Ok(())
    }

    /// Forces a Jacobian evaluation and LU at the next step, e.g. after the caller changed
    /// the system (a known discontinuity such as loss of gear contact).
    pub fn invalidate_jacobian(&mut self) {
        self.refresh = true;
        self.last = None;
    }

    /// The Newton settings.
    pub fn options(&self) -> &SdirkOptions {
        &self.opts
    }

    /// Counters accumulated since creation or the last [`Sdirk::reset_stats`], including
    /// the work of failed steps (which do not count in `steps`).
    pub fn stats(&self) -> StepStats {
        self.stats
    }

    /// Zeroes the accumulated counters.
    pub fn reset_stats(&mut self) {
        self.stats = StepStats::default();
    }

    /// One step `y(t) -> y(t + h)`. On error `y` is unchanged (never NaN).
    pub fn step<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut SVector<f64, N>,
    ) -> Result<StepStats, IntegratorError> {
        let mut st = StepStats::default();
        let result = self.step_inner(sys, t, y, &mut st);
        self.stats.accumulate(&st);
        result.map(|()| st)
    }

    fn step_inner<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut SVector<f64, N>,
        st: &mut StepStats,
    ) -> Result<(), IntegratorError> {
        if !t.is_finite() || !y.iter().all(|v| v.is_finite()) {
            return Err(IntegratorError::NonFinite { t });
        }
        if self.refresh {
            self.refresh_matrix(sys, t, y, st)?;
        }
        let h = self.h;
        let hg = h * GAMMA;
        // Predictor: stage derivative k_i ~ k_(i-1); for stage 1 the last stage of the
        // previous step if this step continues it, else k = 0 (Y = y_n).
        let mut k_guess = match &self.last {
            Some(l) if (t - l.t_end).abs() <= 1e-6 * h && *y == l.y_end => l.k_end,
            _ => SVector::zeros(),
        };
        self.last = None;
        // Inverse weights of the Newton norm (see module docs).
        let inv_scale = SVector::<f64, N>::from_fn(|i, _| {
            1.0 / (self.abs_tol[i] + self.opts.rel_tol * y[i].abs())
        });
        let mut k = [SVector::<f64, N>::zeros(); STAGES];
        let mut y_stage = *y;
        let mut max_rate: f64 = 0.0;
        for i in 0..STAGES {
            let mut base = *y;
            for (j, kj) in k.iter().enumerate().take(i) {
                base += (h * A[i][j]) * kj;
            }
            let t_i = t + C[i] * h;
            // Newton start; on failure, moved to the last contracting iterate.
            let mut start = base + hg * k_guess;
            let mut refreshes = 0;
            y_stage = loop {
                let can_refresh = refreshes < MAX_STAGE_REFRESHES;
                match self.solve_stage(sys, t_i, &inv_scale, &base, &mut start, can_refresh, st) {
                    Ok((y_i, rate)) => {
                        max_rate = max_rate.max(rate);
                        break y_i;
                    }
                    // The converged earlier stages stay valid (the Jacobian only steers
                    // Newton), so only this stage is redone, with J at its own time.
                    Err(_) if can_refresh => {
                        refreshes += 1;
                        st.retries += 1;
                        self.refresh_matrix(sys, t_i, &start, st)?;
                    }
                    Err(Failure::NonFinite) => return Err(IntegratorError::NonFinite { t }),
                    Err(Failure::Newton { iterations, rate }) => {
                        return Err(IntegratorError::NewtonFailed {
                            t,
                            stage: i,
                            iterations,
                            rate,
                        })
                    }
                }
            };
            k[i] = (y_stage - base) / hg;
            k_guess = k[i];
        }
        *y = y_stage;
        st.steps = 1;
        // Slow contraction in this step: refresh the Jacobian before the next one.
        self.refresh = max_rate > self.opts.refresh_rate;
        self.last = Some(LastStep {
            t_end: t + h,
            y_end: y_stage,
            k_end: k[STAGES - 1],
        });
        Ok(())
    }

    /// Evaluates `J` at `(t, y)` and factorises `I - h gamma J`.
    fn refresh_matrix<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &SVector<f64, N>,
        st: &mut StepStats,
    ) -> Result<(), IntegratorError> {
        let jac = match sys.jacobian(t, y) {
            Some(jac) => jac,
            None => {
                let f_y = sys.rhs(t, y);
                st.rhs_calls += 1;
                if !f_y.iter().all(|v| v.is_finite()) {
                    return Err(IntegratorError::NonFinite { t });
                }
                // Below atol/rtol a component is "zero" for the Newton test, so it is
                // also the natural scale for its finite-difference increment.
                let floor = self.abs_tol / self.opts.rel_tol.max(f64::EPSILON.sqrt());
                st.rhs_calls += N as u64;
                finite_difference_jacobian(sys, t, y, &f_y, &floor)
            }
        };
        st.jacobian_evals += 1;
        if !jac.iter().all(|v| v.is_finite()) {
            return Err(IntegratorError::NonFinite { t });
        }
        let m = SMatrix::<f64, N, N>::identity() - (self.h * GAMMA) * jac;
        let lu = StaticLu::factor(&m).ok_or(IntegratorError::SingularMatrix { t })?;
        st.lu_factorizations += 1;
        let m_inv = lu.inverse();
        // A nearly singular matrix can pass the pivot test and still overflow here.
        if !m_inv.iter().all(|v| v.is_finite()) {
            return Err(IntegratorError::SingularMatrix { t });
        }
        self.m_inv = m_inv;
        self.refresh = false;
        self.eta = 1.0; // new matrix: measure the contraction again before trusting it
        Ok(())
    }

    /// Solves the stage equation `Y = base + h gamma f(t_i, Y)` by simplified Newton
    /// from `*start` with the current iteration matrix. Returns `Y` and the largest
    /// contraction rate seen. On failure `*start` holds the last iterate reached while contracting (a
    /// better point for a new Jacobian). With `early_abort`, gives up as soon as the
    /// tolerance looks out of reach in the iterations left (a refresh is cheaper).
    #[allow(clippy::too_many_arguments)]
    fn solve_stage<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t_i: f64,
        inv_scale: &SVector<f64, N>,
        base: &SVector<f64, N>,
        start: &mut SVector<f64, N>,
        early_abort: bool,
        st: &mut StepStats,
    ) -> Result<(SVector<f64, N>, f64), Failure> {
        let hg = self.h * GAMMA;
        let max_iter = self.opts.max_newton_iters;
        let mut y_stage = *start;
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
            let delta = self.m_inv * (base + hg * f - y_stage);
            // Weighted RMS norm of the correction.
            let norm = (delta.component_mul(inv_scale).norm_squared() / N as f64).sqrt();
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
                *start = y_stage;
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

impl<const N: usize> Stepper<N> for Sdirk<N> {
    fn step_size(&self) -> f64 {
        self.h
    }

    fn step<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut SVector<f64, N>,
    ) -> Result<StepStats, IntegratorError> {
        Sdirk::step(self, sys, t, y)
    }
}
