//! Diagonally implicit Runge-Kutta stepper with a simplified Newton iteration, for the
//! tableaux of [`super::tableau`]: Alexander's SDIRK3 (fixed steps, the default of
//! [`Sdirk::new`]) and the ESDIRK3(2) pair of Kennedy & Carpenter, whose embedded
//! solution gives a local error estimate for step size control ([`Sdirk::try_step`]).
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
//! Both methods are stiffly accurate, so `y_{n+1}` is the last stage value. An explicit
//! first stage (ESDIRK) is `Y_1 = y_n`, `k_1 = f(t_n, y_n)`: the last stage derivative of
//! the step that ended at `(t_n, y_n)` (first same as last), unless the caller declared
//! the system changed ([`Sdirk::invalidate_jacobian`]).
//!
//! Error estimate (embedded pair only): `err = (I - h gamma J)^{-1} h sum_i (b_i - b_hat_i)
//! k_i`, the difference of the two solutions filtered by the iteration matrix, as Hairer
//! & Wanner II (Sect. IV.8, eq. 8.19-8.20) advise for stiff problems: without the filter
//! the estimate of a stiff component is `|h lambda|` times too large and the step would be
//! cut for modes that the L-stable method damps correctly. Its size is the weighted RMS
//! norm with the weights of [`Sdirk::set_error_tolerance`].
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

use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim, DimName, U1};

use super::lu::IterationInverse;
pub use super::options::SdirkOptions;

mod newton;
use super::tableau::{Tableau, ALEXANDER3, MAX_STAGES};
use super::{
    finite_difference_jacobian, IntegratorError, Matrix, OdeSystem, StepStats, Stepper, Vector,
};

/// Jacobian re-evaluations allowed per stage after Newton failures, before giving up.
const MAX_STAGE_REFRESHES: usize = 2;

/// End of the previous accepted step, used to predict (SDIRK) or supply (ESDIRK, first
/// same as last) the first stage of the next one.
#[derive(Debug, Clone)]
struct LastStep<D: Dim>
where
    DefaultAllocator: Allocator<D>,
{
    t_end: f64,
    y_end: Vector<D>,
    /// Last stage derivative `k_s`, which approximates `f(t_end, y_end)`.
    k_end: Vector<D>,
}

impl<D: Dim> LastStep<D>
where
    DefaultAllocator: Allocator<D>,
{
    /// Whether a step starting at `(t, y)` continues this one.
    fn continues(&self, t: f64, y: &Vector<D>, h: f64) -> bool {
        (t - self.t_end).abs() <= 1e-6 * h && *y == self.y_end
    }
}

/// Why one attempt at a stage failed (mapped to [`IntegratorError`] if it is final).
enum Failure {
    NonFinite,
    Newton { iterations: usize, rate: f64 },
}

/// A computed but not yet accepted step (see [`Sdirk::try_step`]).
#[derive(Debug, Clone)]
pub struct Trial<D: Dim>
where
    DefaultAllocator: Allocator<D>,
{
    /// Start time and size of the step.
    pub t: f64,
    /// Size of the step, s.
    pub h: f64,
    /// Solution at `t + h`.
    pub y: Vector<D>,
    /// Weighted RMS norm of the local error estimate (<= 1: within tolerance); 0 for a
    /// tableau without an embedded solution.
    pub error: f64,
    /// Work spent on this attempt.
    pub stats: StepStats,
    k_end: Vector<D>,
}

/// L-stable DIRK stepper for stiff systems (see module docs). Holds the factorised
/// iteration matrix between steps; use one per independent trajectory.
#[derive(Debug, Clone)]
pub struct Sdirk<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    tab: &'static Tableau,
    h: f64,
    opts: SdirkOptions,
    dim: D,
    abs_tol: Vector<D>,
    /// Error weights `err_abs_i + err_rel_i max(|y_n,i|, |y_n+1,i|)`.
    err_abs: Vector<D>,
    err_rel: Vector<D>,
    /// The last Jacobian evaluated, if still valid.
    jac: Option<Matrix<D>>,
    /// `(I - h gamma J)^{-1}` for `m_inv_h`: an explicit inverse, or a second-order
    /// system's Schur blocks from 9 coordinates on (see [`super::lu`] for why an inverse
    /// rather than triangular solves).
    m_inv: IterationInverse<D>,
    m_inv_h: f64,
    /// Earlier `(m_inv_h, m_inv)` of the current Jacobian, newest last (at most
    /// `opts.kept_matrices`).
    kept: Vec<(f64, IterationInverse<D>)>,
    /// A new Jacobian must be evaluated before the next step.
    refresh: bool,
    /// Hairer's `eta = theta / (1 - theta)` carried between stages and steps.
    eta: f64,
    last: Option<LastStep<D>>,
    /// `f(t, y)` of the last explicit first stage computed, for repeated attempts from
    /// the same point (rejected steps, event location).
    first_stage: Option<(f64, Vector<D>, Vector<D>)>,
    stats: StepStats,
}

impl<D: DimName> Sdirk<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// Alexander's SDIRK3 with step `h` (time units, finite and > 0) and Newton
    /// settings `opts`, for a dimension known at compile time.
    pub fn new(h: f64, opts: SdirkOptions) -> Result<Self, IntegratorError> {
        Self::with_tableau(&ALEXANDER3, h, opts)
    }

    /// The stepper of tableau `tab` (see [`super::tableau`]), for a dimension known at
    /// compile time.
    pub fn with_tableau(
        tab: &'static Tableau,
        h: f64,
        opts: SdirkOptions,
    ) -> Result<Self, IntegratorError> {
        Self::with_dimension(D::name(), tab, h, opts)
    }
}

impl<D: Dim> Sdirk<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// The stepper of tableau `tab` for states of dimension `dim` (`Dyn(n)` for a size
    /// known when the system is built).
    pub fn with_dimension(
        dim: D,
        tab: &'static Tableau,
        h: f64,
        opts: SdirkOptions,
    ) -> Result<Self, IntegratorError> {
        opts.validate()?;
        check_step(h)?;
        let repeat = |v: f64| Vector::<D>::from_element_generic(dim, U1, v);
        Ok(Self {
            tab,
            h,
            opts,
            dim,
            abs_tol: repeat(opts.abs_tol),
            err_abs: repeat(opts.abs_tol),
            err_rel: repeat(opts.rel_tol),
            jac: None,
            m_inv: IterationInverse::identity(dim),
            m_inv_h: f64::NAN,
            kept: Vec::new(),
            refresh: true,
            eta: 1.0,
            last: None,
            first_stage: None,
            stats: StepStats::default(),
        })
    }

    /// The tableau in use.
    pub fn tableau(&self) -> &'static Tableau {
        self.tab
    }

    /// Per-component absolute Newton tolerances (units of each `y_i`, all finite and > 0).
    pub fn set_abs_tol(&mut self, abs_tol: Vector<D>) -> Result<(), IntegratorError> {
        if !abs_tol.iter().all(|a| *a > 0.0 && a.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "abs_tol must be finite and > 0",
            ));
        }
        self.abs_tol = abs_tol;
        Ok(())
    }

    /// Weights of the local error norm: component `i` may err by
    /// `abs_i + rel_i max(|y_n,i|, |y_n+1,i|)` (units of `y_i`; `abs_i > 0`, `rel_i >= 0`).
    pub fn set_error_tolerance(
        &mut self,
        abs: Vector<D>,
        rel: Vector<D>,
    ) -> Result<(), IntegratorError> {
        if !abs.iter().all(|a| *a > 0.0 && a.is_finite())
            || !rel.iter().all(|r| *r >= 0.0 && r.is_finite())
        {
            return Err(IntegratorError::InvalidSetting(
                "error tolerances must be finite, abs > 0 and rel >= 0",
            ));
        }
        self.err_abs = abs;
        self.err_rel = rel;
        Ok(())
    }

    /// Changes the default step size of [`Sdirk::step`].
    pub fn set_step_size(&mut self, h: f64) -> Result<(), IntegratorError> {
        check_step(h)?;
        self.h = h;
        Ok(())
    }

    /// Forces a Jacobian evaluation and LU at the next step and forgets the previous
    /// step, e.g. after the caller changed the system (a known discontinuity such as a
    /// change of the set of teeth in contact).
    pub fn invalidate_jacobian(&mut self) {
        self.refresh = true;
        self.last = None;
        self.first_stage = None;
    }

    /// The Newton settings.
    pub fn options(&self) -> &SdirkOptions {
        &self.opts
    }

    /// Counters accumulated since creation or the last [`Sdirk::reset_stats`], including
    /// the work of failed and rejected steps (which do not count in `steps`).
    pub fn stats(&self) -> StepStats {
        self.stats
    }

    /// Zeroes the accumulated counters.
    pub fn reset_stats(&mut self) {
        self.stats = StepStats::default();
    }

    /// One step `y(t) -> y(t + h)` of the default size. On error `y` is unchanged
    /// (never NaN).
    pub fn step<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut Vector<D>,
    ) -> Result<StepStats, IntegratorError> {
        let trial = self.try_step(sys, t, y, self.h)?;
        self.accept(&trial);
        *y = trial.y;
        let mut st = trial.stats;
        st.steps = 1;
        Ok(st)
    }

    /// Computes a step of size `h` from `(t, y)` with its error estimate, without
    /// committing it: pass it to [`Sdirk::accept`] to continue from it, or try again
    /// (e.g. with a smaller `h`) from the same point.
    pub fn try_step<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &Vector<D>,
        h: f64,
    ) -> Result<Trial<D>, IntegratorError> {
        check_step(h)?;
        let mut st = StepStats::default();
        let result = self.try_step_inner(sys, t, y, h, &mut st);
        self.stats.accumulate(&st);
        result.map(|(y_new, k_end, error)| Trial {
            t,
            h,
            y: y_new,
            error,
            stats: st,
            k_end,
        })
    }

    /// Makes `trial` the last step: the next one starting at its end continues it.
    pub fn accept(&mut self, trial: &Trial<D>) {
        self.last = Some(LastStep {
            t_end: trial.t + trial.h,
            y_end: trial.y.clone(),
            k_end: trial.k_end.clone(),
        });
        self.stats.steps += 1;
    }

    /// The step's work: the matrix brought up to date, the stages solved, the error
    /// estimated. Returns the solution, the last stage derivative and the error norm.
    fn try_step_inner<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &Vector<D>,
        h: f64,
        st: &mut StepStats,
    ) -> Result<(Vector<D>, Vector<D>, f64), IntegratorError> {
        if !t.is_finite() || !y.iter().all(|v| v.is_finite()) {
            return Err(IntegratorError::NonFinite { t });
        }
        if self.refresh || self.jac.is_none() {
            self.refresh_matrix(sys, t, y, h, st)?;
        } else if !same_step(h, self.m_inv_h) && !self.take_kept(h) {
            self.factor(t, h, st)?;
        }
        let tab = self.tab;
        let zero = || Vector::<D>::zeros_generic(self.dim, U1);
        let mut k: [Vector<D>; MAX_STAGES] = std::array::from_fn(|_| zero());
        let explicit = tab.explicit_first_stage();
        // Predictor: stage derivative k_i ~ k_(i-1); for the first implicit stage the last
        // stage of the previous step if this step continues it (else the explicit stage
        // derivative, else k = 0, i.e. Y = y_n).
        let continues = self.last.as_ref().filter(|l| l.continues(t, y, h));
        let mut k_guess = continues.map_or_else(zero, |l| l.k_end.clone());
        if explicit {
            k[0] = self.first_stage_derivative(sys, t, y, h, st)?;
            k_guess = k[0].clone();
        }
        // Inverse weights of the Newton norm (see module docs).
        let inv_scale = Vector::<D>::from_fn_generic(self.dim, U1, |i, _| {
            1.0 / (self.abs_tol[i] + self.opts.rel_tol * y[i].abs())
        });
        let mut y_stage = y.clone();
        let mut max_rate: f64 = 0.0;
        for i in usize::from(explicit)..tab.stages {
            let mut base = y.clone();
            for (j, kj) in k.iter().enumerate().take(i) {
                base += kj * (h * tab.a[i][j]);
            }
            let (y_i, rate) = self.stage(sys, t, h, i, &inv_scale, &base, &k_guess, st)?;
            max_rate = max_rate.max(rate);
            y_stage = y_i;
            k[i] = (&y_stage - &base) / (h * tab.gamma);
            k_guess = k[i].clone();
        }
        // Slow contraction in this step: refresh the Jacobian before the next one.
        self.refresh = max_rate > self.opts.refresh_rate;
        let error = self.error_norm(&k, y, &y_stage, h);
        if !error.is_finite() {
            return Err(IntegratorError::NonFinite { t });
        }
        let k_end = k[tab.stages - 1].clone();
        Ok((y_stage, k_end, error))
    }

    /// `f(t, y)` for an explicit first stage: the last stage derivative of the step that
    /// ended at `(t, y)` (first same as last), or the one already computed for another
    /// attempt from the same point, or a new evaluation.
    fn first_stage_derivative<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &Vector<D>,
        h: f64,
        st: &mut StepStats,
    ) -> Result<Vector<D>, IntegratorError> {
        if let Some(l) = self.last.as_ref().filter(|l| l.continues(t, y, h)) {
            return Ok(l.k_end.clone());
        }
        if let Some((t0, y0, f0)) = &self.first_stage {
            if *t0 == t && y0 == y {
                return Ok(f0.clone());
            }
        }
        let f0 = sys.rhs(t, y);
        st.rhs_calls += 1;
        if !f0.iter().all(|v| v.is_finite()) {
            return Err(IntegratorError::NonFinite { t });
        }
        self.first_stage = Some((t, y.clone(), f0.clone()));
        Ok(f0)
    }

    /// Solves implicit stage `i` from `base` (y_n plus the earlier stages' share), with
    /// up to [`MAX_STAGE_REFRESHES`] Jacobian refreshes at the stage's own time. Returns
    /// the stage value and its largest contraction rate.
    #[allow(clippy::too_many_arguments)]
    fn stage<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        h: f64,
        i: usize,
        inv_scale: &Vector<D>,
        base: &Vector<D>,
        k_guess: &Vector<D>,
        st: &mut StepStats,
    ) -> Result<(Vector<D>, f64), IntegratorError> {
        let hg = h * self.tab.gamma;
        let t_i = t + self.tab.c[i] * h;
        // Newton start; on failure, moved to the last contracting iterate.
        let mut start = base + k_guess * hg;
        let mut refreshes = 0;
        loop {
            let can_refresh = refreshes < MAX_STAGE_REFRESHES;
            match self.solve_stage(sys, t_i, hg, inv_scale, base, &mut start, can_refresh, st) {
                Ok(done) => return Ok(done),
                // The converged earlier stages stay valid (the Jacobian only steers
                // Newton), so only this stage is redone, with J at its own time.
                Err(_) if can_refresh => {
                    refreshes += 1;
                    st.retries += 1;
                    self.refresh_matrix(sys, t_i, &start, h, st)?;
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
        }
    }

    /// Weighted RMS norm of the embedded error estimate (module docs); 0 without an
    /// embedded solution.
    fn error_norm(
        &self,
        k: &[Vector<D>; MAX_STAGES],
        y: &Vector<D>,
        y_new: &Vector<D>,
        h: f64,
    ) -> f64 {
        let Some(bh) = self.tab.b_hat else {
            return 0.0;
        };
        let mut e = Vector::<D>::zeros_generic(self.dim, U1);
        for (i, ki) in k.iter().enumerate().take(self.tab.stages) {
            e += ki * (h * (self.tab.b[i] - bh[i]));
        }
        let e = self.m_inv.apply(&e);
        let n = y.len();
        let sum: f64 = (0..n)
            .map(|i| {
                let sc = self.err_abs[i] + self.err_rel[i] * y[i].abs().max(y_new[i].abs());
                (e[i] / sc).powi(2)
            })
            .sum();
        (sum / n as f64).sqrt()
    }

    /// Evaluates `J` at `(t, y)` and factorises `I - h gamma J`.
    fn refresh_matrix<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &Vector<D>,
        h: f64,
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
                let floor = &self.abs_tol / self.opts.rel_tol.max(f64::EPSILON.sqrt());
                st.rhs_calls += y.len() as u64;
                finite_difference_jacobian(sys, t, y, &f_y, &floor)
            }
        };
        st.jacobian_evals += 1;
        if !jac.iter().all(|v| v.is_finite()) {
            return Err(IntegratorError::NonFinite { t });
        }
        self.jac = Some(jac);
        self.refresh = false;
        // The kept matrices belong to the old Jacobian.
        self.kept.clear();
        self.m_inv_h = f64::NAN;
        self.factor(t, h, st)
    }

    /// Makes the kept matrix of step `h` ([`SdirkOptions::kept_matrices`]) the current
    /// one, keeping the current one in its place; false if none is kept for `h`.
    fn take_kept(&mut self, h: f64) -> bool {
        let Some(i) = self.kept.iter().position(|(hk, _)| same_step(h, *hk)) else {
            return false;
        };
        let (hk, m) = self.kept.remove(i);
        let old = std::mem::replace(&mut self.m_inv, m);
        self.kept.push((self.m_inv_h, old));
        self.m_inv_h = hk;
        self.eta = 1.0; // another matrix: measure the contraction again
        true
    }

    /// Factorises `I - h gamma J` with the stored Jacobian (`t` only names the error).
    fn factor(&mut self, t: f64, h: f64, st: &mut StepStats) -> Result<(), IntegratorError> {
        let jac = self
            .jac
            .as_ref()
            .ok_or(IntegratorError::SingularMatrix { t })?;
        let c = h * self.tab.gamma;
        st.lu_factorizations += 1;
        // A nearly singular matrix can pass the pivot test and still overflow: refused
        // as singular too.
        let m_inv = IterationInverse::of(jac, c).ok_or(IntegratorError::SingularMatrix { t })?;
        let old = std::mem::replace(&mut self.m_inv, m_inv);
        if self.opts.kept_matrices > 0 && self.m_inv_h.is_finite() {
            if self.kept.len() == self.opts.kept_matrices {
                self.kept.remove(0);
            }
            self.kept.push((self.m_inv_h, old));
        }
        self.m_inv_h = h;
        self.eta = 1.0; // new matrix: measure the contraction again before trusting it
        Ok(())
    }
}

impl<D: Dim> Stepper<D> for Sdirk<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    fn step_size(&self) -> f64 {
        self.h
    }

    fn step<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut Vector<D>,
    ) -> Result<StepStats, IntegratorError> {
        Sdirk::step(self, sys, t, y)
    }
}

/// Steps `h` and `h_matrix` are one length: they differ by round-off only (node
/// intervals computed as differences of times), so the matrix of one serves the other
/// (it only steers Newton).
fn same_step(h: f64, h_matrix: f64) -> bool {
    (h - h_matrix).abs() <= 1e-9 * h
}

fn check_step(h: f64) -> Result<(), IntegratorError> {
    if h > 0.0 && h.is_finite() {
        Ok(())
    } else {
        Err(IntegratorError::InvalidSetting(
            "step size must be finite and > 0",
        ))
    }
}
