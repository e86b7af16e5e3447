//! Integration of the gear model over one period (a mesh period; a train's common period): error-controlled steps between
//! the grid nodes, contact-mode events located inside steps, and what is recorded.
//!
//! Steps. The grid nodes of [`super::grid::period_nodes`] (the mesh events, where a pair
//! enters or leaves contact or passes the pitch point, and `steps_per_mesh_period` nodes
//! in all) bound the steps: no step crosses a node, so the stiffness jumps never fall
//! inside a step, and the node spacing is the largest step. Inside each node interval
//! the ESDIRK3(2) pair ([`super::integrator::tableau::ESDIRK32`]) chooses the step from
//! its embedded error estimate (Hairer, Norsett & Wanner I, Sect. II.4; the standard
//! controller h_new = h min(5, max(0.2, 0.9 err^(-1/3))), exponent 1/(embedded order + 1)).
//! After a stiffness jump the bearing velocities settle within a few microseconds; at
//! low input speed a node interval is hundreds of microseconds, so the controller takes
//! small steps there and long ones on the quasi-static stretches.
//!
//! Contact mode. Each step holds the contact mode fixed ([`super::model::ContactMode`]);
//! a step that ends across a switch is cut back to the switch by the Illinois variant of
//! regula falsi on the step length (each trial is a step from the same start, so the
//! located point is a point of the discrete solution), and the next step starts in the
//! new mode. A Newton failure rejects the step and halves it, down to a floor.

use super::integrator::tableau::ESDIRK32;
use super::integrator::{
    with_state_size, IntegratorError, Matrix, OdeSystem, Sdirk, SdirkOptions, StepStats, Trial,
    Vector,
};
use super::model::{ContactFrame, ContactModes, GearSystem, MeshState, ModeSwitch};
pub use super::observer::PeriodObserver;
use super::state_scales::state_scales;
pub use super::step_failure::StepFailure;
use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim, U1};

/// Factorised iteration matrices a train's stepper keeps for recurring step lengths
/// ([`SdirkOptions::kept_matrices`]): between two events the error control alternates
/// between a whole node interval and parts of it, and each new factorisation of the
/// train's larger matrix costs several steps' work. The single pair keeps none (its
/// results stay those of before the option existed).
const TRAIN_KEPT_MATRICES: usize = 3;

/// Work counters of the period integrations.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StepCounts {
    /// Steps accepted.
    pub accepted: usize,
    /// Steps rejected by the error test.
    pub rejected: usize,
    /// Steps rejected because Newton failed.
    pub newton_failures: usize,
    /// Contact-mode switches located, and the trial steps that located them.
    pub events: usize,
    /// Trial steps taken to locate the contact-mode switches.
    pub event_trials: usize,
}

/// The model seen by the integrator during one trial step: the system and the contact
/// frame of that step (pairs decided at its middle, its contact modes frozen), and room
/// for the meshes' states.
struct Ode<'s, 'a, 'w> {
    sys: &'s GearSystem<'a>,
    frame: ContactFrame,
    meshes: &'w mut [MeshState],
}

impl<D: Dim> OdeSystem<D> for Ode<'_, '_, '_>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    fn rhs(&mut self, t: f64, y: &Vector<D>) -> Vector<D> {
        let (dim, _) = y.shape_generic();
        let mut dy = Vector::<D>::zeros_generic(dim, U1);
        self.sys
            .derivative_into(self.frame, t, y.as_slice(), dy.as_mut_slice(), self.meshes);
        dy
    }
    fn jacobian(&mut self, t: f64, y: &Vector<D>) -> Option<Matrix<D>> {
        let (dim, _) = y.shape_generic();
        let mut j = Matrix::<D>::zeros_generic(dim, dim);
        self.sys
            .jacobian_into(self.frame, t, y.as_slice(), j.as_mut_slice());
        Some(j)
    }
}

/// What the solvers ask of a period stepper, whatever its state's dimension type
/// ([`period_stepper`]).
pub trait PeriodIntegrator {
    /// Integrates `y` over the period starting at `t0` (a period boundary), showing the
    /// solution to `obs`.
    fn integrate(
        &mut self,
        t0: f64,
        y: &mut [f64],
        obs: &mut dyn PeriodObserver,
    ) -> Result<(), StepFailure>;
    /// As [`PeriodIntegrator::integrate`], but only from `t0` to `t0 + until_s`, which
    /// must be a node of the period ([`PeriodIntegrator::node_at_or_after`]); the point
    /// at the end is not shown (it opens the rest of the period).
    fn integrate_part(
        &mut self,
        t0: f64,
        y: &mut [f64],
        obs: &mut dyn PeriodObserver,
        until_s: f64,
    ) -> Result<(), StepFailure>;
    /// The first node of the period at or after `s` (s from the period start; the
    /// period itself when `s` is past the last node).
    fn node_at_or_after(&self, s: f64) -> f64;
    /// The period, s.
    fn period(&self) -> f64;
    /// How the following periods choose their steps.
    fn set_plan_mode(&mut self, mode: PlanMode);
    /// How the following periods choose their steps.
    fn plan_mode(&self) -> PlanMode;
    /// Work counters of the underlying stepper (rhs calls, LU factorisations).
    fn integrator_stats(&self) -> StepStats;
    /// Work counters of the period integrations ([`StepCounts`]).
    fn counts(&self) -> StepCounts;
}

/// The period stepper of `sys` over `nodes` with the relative local error `tolerance`:
/// on stack vectors sized at compile time for the state sizes users meet, on heap
/// vectors of the system's size otherwise (`integrator::with_state_size`). The
/// sizes: the single spur pair (16 states, the paper's), a helical pair with its axial
/// coordinates (20), a two-stage spur train or a helical pair that also tilts (28), a
/// two-stage train with axial coordinates on its helical stages (36), a three-stage
/// spur train (40).
pub fn period_stepper<'s, 'a>(
    sys: &'s GearSystem<'a>,
    nodes: Vec<f64>,
    tolerance: f64,
) -> Result<Box<dyn PeriodIntegrator + 's>, IntegratorError> {
    with_state_size!(sys.states(), [16, 20, 28, 36, 40], dim => {
        Ok(Box::new(PeriodStepper::new(sys, dim, nodes, tolerance)?))
    })
}

/// The smallest step the error control may take, s, at most: 1e-7 of the shortest node
/// interval, and never above 1e-12 s. At a very low speed the node intervals are long
/// while the velocity tolerance (`state_scales`: delta x the mesh frequency) shrinks with
/// the speed, so a small jump of the acceleration (a contact switching exactly at a node)
/// needs a step far below 1e-7 of an interval to meet it; the floor lets it take one and
/// grow again (a few dozen steps), where 1e-7 of the interval failed below about 0.02 Hz
/// input on the built-in case. At the paper's speed 1e-7 of an interval is already lower.
const H_MIN_FLOOR_S: f64 = 1e-12;

/// Most steps the error control may take within one node interval before the evaluation
/// stops with its advice: the built-in case takes about one, a slow or coarse grid tens.
/// With the floor [`H_MIN_FLOOR_S`] far below a long interval, a tolerance the state's
/// round-off cannot meet (1e-8 at 1e-6 Hz input on 20 nodes) would otherwise step on at
/// the floor for days instead of failing.
const MAX_STEPS_PER_INTERVAL: usize = 20_000;
/// Steps the gear model over whole periods (see module docs), states of dimension `D`.
pub struct PeriodStepper<'s, 'a, D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    sys: &'s GearSystem<'a>,
    dim: D,
    stepper: Sdirk<D>,
    /// Room for the meshes' states in the right-hand side.
    meshes: Vec<MeshState>,
    /// Node times within a period, s, from 0 to the period.
    nodes: Vec<f64>,
    /// Node k changes the set of pairs in contact (a pair enters or leaves).
    set_change: Vec<bool>,
    /// A time offset far inside any node interval, s (for deciding right limits).
    eps_t: f64,
    h_min: f64,
    /// Local error tolerance (relative to the state scales), for the failure advice.
    tolerance: f64,
    /// Step ends (times within the period, s) recorded by a [`PlanMode::Build`] period.
    plan: Vec<f64>,
    plan_mode: PlanMode,
    /// Work counters of the periods integrated so far.
    pub counts: StepCounts,
    /// A train's steps divide what is left of a node interval into equal parts
    /// ([`PeriodStepper::next_step`]); the single pair keeps its own rule.
    equal_steps: bool,
}

/// How the steps of a period are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanMode {
    /// By the error control alone.
    Free,
    /// By the error control, and the step ends are kept as the plan.
    Build,
    /// Along the plan (refined where the error test fails, never coarsened), so that
    /// the one-period map is the same smooth function of the start state in every
    /// period: with steps chosen afresh, the accept/reject decisions would change with
    /// the state and make the map jump by the size of the local errors, which a
    /// fixed-point iteration cannot converge through.
    Replay,
    /// Along the plan, refined where the error test fails but without keeping the
    /// refinements: the periods of a tooth-resolved mesh differ from the one the plan was
    /// built on, and each period's own refinements would only add steps to the others.
    ReplayFixed,
}

impl<'s, 'a, D: Dim> PeriodStepper<'s, 'a, D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// A stepper of states of dimension `dim` (the system's [`GearSystem::states`]) over
    /// `nodes` (times within a period, 0 and the period included) with the relative local
    /// error `tolerance` (dimensionless, of the state scales).
    pub fn new(
        sys: &'s GearSystem<'a>,
        dim: D,
        nodes: Vec<f64>,
        tolerance: f64,
    ) -> Result<Self, IntegratorError> {
        let min_gap = nodes
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min);
        let eps_t = 0.25 * min_gap;
        let last = *nodes.last().unwrap_or(&0.0);
        let set_change = nodes
            .iter()
            .map(|t| {
                // The period boundary is pair entry: the set changes there too.
                *t == 0.0
                    || *t == last
                    || sys.meshes.iter().any(|m| {
                        let (a, b) = (m.phase_at(t - eps_t), m.phase_at(t + eps_t));
                        let reach = m.parts.contact.reach();
                        let count = |d: f64| m.parts.pair.decided_set_in(reach, d).1;
                        count(a) != count(b)
                    })
            })
            .collect();
        let scales = state_scales(sys);
        let scales = Vector::<D>::from_column_slice_generic(dim, U1, scales.as_slice());
        let n = sys.dofs();
        let rel = Vector::<D>::from_fn_generic(dim, U1, |i, _| if i < n { 0.0 } else { tolerance });
        let opts = SdirkOptions {
            kept_matrices: if sys.meshes.len() > 1 {
                TRAIN_KEPT_MATRICES
            } else {
                0
            },
            ..SdirkOptions::default()
        };
        let mut stepper = Sdirk::with_dimension(dim, &ESDIRK32, min_gap, opts)?;
        stepper.set_error_tolerance(&scales * tolerance, rel)?;
        // Newton solves the stages two decades below the local error tolerance
        // (Hairer & Wanner II, Sect. IV.8: kappa ~ 1e-2).
        stepper.set_abs_tol(&scales * (1e-2 * tolerance))?;
        Ok(Self {
            sys,
            dim,
            stepper,
            meshes: vec![MeshState::default(); sys.meshes.len()],
            h_min: (1e-7 * min_gap).min(H_MIN_FLOOR_S),
            tolerance,
            plan: Vec::new(),
            plan_mode: PlanMode::Free,
            nodes,
            set_change,
            eps_t,
            counts: StepCounts::default(),
            equal_steps: sys.meshes.len() > 1,
        })
    }

    /// The step to try from `t` towards the node `tb` (and the point it aims at): along
    /// the plan when replaying, else the proposed step, landing on the node without
    /// leaving a sliver for the next step. A train ([`PeriodStepper::equal_steps`]) cuts
    /// what is left of the interval into ceil(rest / proposed) equal steps, the next of
    /// them being the step: while the proposal holds, every step of the interval, and
    /// of the equal intervals that follow in a gap between mesh events
    /// ([`super::grid::train_nodes`]), has one length, so the factorised iteration matrix
    /// of that length serves them all (the two-stage example: 6 479 LU factorisations
    /// in a cold steady state instead of 12 757, for 2 % more steps). The single pair's
    /// rule (the proposal, or half the rest when less than two proposals are left) stays,
    /// so its steps and results are those of before.
    fn next_step(
        &self,
        t0: f64,
        t: f64,
        tb: f64,
        h_prop: f64,
        next_plan: &mut usize,
    ) -> (f64, f64) {
        let rest = tb - t;
        let mut target = tb;
        if matches!(self.plan_mode, PlanMode::Replay | PlanMode::ReplayFixed) {
            while *next_plan < self.plan.len() && t0 + self.plan[*next_plan] <= t {
                *next_plan += 1;
            }
            if *next_plan < self.plan.len() && t0 + self.plan[*next_plan] < tb {
                target = t0 + self.plan[*next_plan];
            }
            return (target - t, target);
        }
        let h = if rest <= 1.05 * h_prop {
            rest
        } else if self.equal_steps {
            rest / (rest / h_prop).ceil()
        } else if rest < 2.0 * h_prop {
            0.5 * rest
        } else {
            h_prop
        };
        (h, target)
    }

    /// [`Self::integrate_vector`] on a slice.
    fn integrate_slice(
        &mut self,
        t0: f64,
        y: &mut [f64],
        obs: &mut dyn PeriodObserver,
        last: usize,
    ) -> Result<(), StepFailure> {
        let mut v = Vector::<D>::from_column_slice_generic(self.dim, U1, y);
        let result = self.integrate_vector(t0, &mut v, obs, last);
        y.copy_from_slice(v.as_slice());
        result
    }

    /// Integrates `y` from `t0` (a period boundary) to node `last` (the period's last
    /// node: the whole period), showing the solution to `obs`.
    fn integrate_vector(
        &mut self,
        t0: f64,
        y: &mut Vector<D>,
        obs: &mut dyn PeriodObserver,
        last: usize,
    ) -> Result<(), StepFailure> {
        let sys = self.sys;
        let n = self.nodes.len();
        // Every period starts alike (a pair enters): the step sequence depends on the
        // state only, so a periodic solution is stepped the same way in every period.
        let mut h_prop = self.nodes[1] - self.nodes[0];
        let mut decide = t0 + self.eps_t;
        let mut mode = sys.natural_mode_decided(t0, decide, y.as_slice());
        self.stepper.invalidate_jacobian();
        obs.point(sys, t0, decide, y.as_slice());
        let max_events = 100 * n;
        let events_before = self.counts.events;
        if self.plan_mode == PlanMode::Build {
            self.plan.clear();
        }
        // Next point of the plan not yet passed (replay).
        let mut next_plan = 0;
        for k in 1..=last {
            let tb = t0 + self.nodes[k];
            let mut t = t0 + self.nodes[k - 1];
            let mut steps_here = 0_usize;
            while t < tb {
                steps_here += 1;
                if steps_here > MAX_STEPS_PER_INTERVAL {
                    return Err(self.failure(
                        t,
                        y,
                        format!(
                            "the error control took more than {MAX_STEPS_PER_INTERVAL} steps in one node interval (the last {h_prop:.2e} s of {:.2e} s)",
                            self.nodes[k] - self.nodes[k - 1]
                        ),
                    ));
                }
                let (h, target) = self.next_step(t0, t, tb, h_prop, &mut next_plan);
                let (trial, event) = self.step(t, y, h, mode, &mut h_prop)?;
                let t_new = if trial.h == h && h == target - t {
                    target
                } else {
                    t + trial.h
                };
                match self.plan_mode {
                    // A step the error test cut: the plan keeps the finer point.
                    PlanMode::Replay if !event && trial.h < h => {
                        self.plan.insert(next_plan, t_new - t0)
                    }
                    PlanMode::Build if !event && t_new < tb => self.plan.push(t_new - t0),
                    _ => {}
                }
                let y0 = std::mem::replace(y, trial.y);
                obs.step(sys, t, t_new - t, y0.as_slice(), y.as_slice(), mode);
                decide = if t_new == tb { tb + self.eps_t } else { t_new };
                if event {
                    mode = sys.natural_mode_decided(t_new, decide, y.as_slice());
                    self.stepper.invalidate_jacobian();
                    if self.counts.events - events_before > max_events {
                        return Err(self.failure(
                            t_new,
                            y,
                            "the contact opens and closes without end (chatter)".into(),
                        ));
                    }
                }
                t = t_new;
                if t < tb {
                    obs.point(sys, t, decide, y.as_slice());
                }
            }
            if self.set_change[k] && k < last {
                mode = sys.natural_mode_decided(tb, decide, y.as_slice());
                self.stepper.invalidate_jacobian();
            }
            if k < last {
                obs.point(sys, tb, decide, y.as_slice());
            }
        }
        Ok(())
    }

    /// One accepted step from `(t, y)` of size `h` or less (error test, Newton
    /// failure, contact event). Returns the step and whether it ended on a located
    /// mode switch; updates the proposed next step `h_prop`.
    fn step(
        &mut self,
        t: f64,
        y: &Vector<D>,
        mut h: f64,
        mode: ContactModes,
        h_prop: &mut f64,
    ) -> Result<(Trial<D>, bool), StepFailure> {
        loop {
            match self.trial(t, y, h, mode) {
                Err(e) => {
                    self.counts.newton_failures += 1;
                    h *= 0.5;
                    if h < self.h_min {
                        return Err(self.failure(
                            t,
                            y,
                            format!("{e} (step halved to {:.2e} s)", h),
                        ));
                    }
                }
                Ok(tr) if tr.error > 1.0 => {
                    self.counts.rejected += 1;
                    h *= (0.9 * tr.error.powf(-1.0 / 3.0)).clamp(0.2, 0.9);
                    if h < self.h_min {
                        return Err(self.failure(
                            t,
                            y,
                            format!(
                                "local error {:.2e} of tolerance at step {:.2e} s",
                                tr.error, h
                            ),
                        ));
                    }
                }
                Ok(tr) => {
                    *h_prop = h * (0.9 * tr.error.max(1e-10).powf(-1.0 / 3.0)).clamp(0.2, 5.0);
                    let sw = self.switches(mode, t + h, &tr.y, t + 0.5 * h);
                    if !sw.any_crossed() {
                        self.stepper.accept(&tr);
                        self.counts.accepted += 1;
                        return Ok((tr, false));
                    }
                    let located = self.locate(t, y, mode, tr, sw)?;
                    self.stepper.accept(&located);
                    self.counts.accepted += 1;
                    self.counts.events += 1;
                    return Ok((located, true));
                }
            }
        }
    }

    /// A trial step in frozen contact modes, the contact sets decided at its middle.
    fn trial(
        &mut self,
        t: f64,
        y: &Vector<D>,
        h: f64,
        mode: ContactModes,
    ) -> Result<Trial<D>, IntegratorError> {
        let mut ode = Ode {
            sys: self.sys,
            frame: ContactFrame::frozen(t + 0.5 * h, mode),
            meshes: &mut self.meshes,
        };
        self.stepper.try_step(&mut ode, t, y, h)
    }

    fn switches(&self, mode: ContactModes, t: f64, y: &Vector<D>, decide: f64) -> ModeSwitch {
        self.sys.mode_switch(mode, t, decide, y.as_slice())
    }

    /// Cuts the step `full` from `(t, y)` back to the first switch of `mode` it
    /// crossed (`sw_full` at its end): Illinois regula falsi on the step length, on the
    /// switch whose linear root estimate comes first. Returns the step ending just past
    /// the switch (on the new side), within 1e-6 of the step length.
    fn locate(
        &mut self,
        t: f64,
        y: &Vector<D>,
        mode: ContactModes,
        full: Trial<D>,
        sw_full: ModeSwitch,
    ) -> Result<Trial<D>, StepFailure> {
        let h = full.h;
        let (mut lo, mut m_lo) = (0.0, self.switches(mode, t, y, t + 0.5 * h));
        let (mut hi, mut m_hi, mut best) = (h, sw_full, full);
        let tol = (1e-6 * h).max(4.0 * f64::EPSILON * t.abs());
        // Illinois weights: the end kept twice in a row has its value halved.
        let (mut w_lo, mut w_hi, mut last_kept_lo) = (1.0, 1.0, None);
        for _ in 0..60 {
            if hi - lo <= tol {
                break;
            }
            let mut tau = hi;
            for j in (0..m_hi.len()).filter(|j| m_hi.crossed(*j)) {
                let (a, b) = (
                    m_lo.margin(j).max(0.0) * w_lo,
                    m_hi.margin(j).min(0.0) * w_hi,
                );
                if a - b > 0.0 {
                    tau = tau.min(lo + (hi - lo) * a / (a - b));
                }
            }
            let span = hi - lo;
            tau = tau.clamp(lo + 1e-3 * span, hi - 1e-3 * span);
            self.counts.event_trials += 1;
            let tr = match self.trial(t, y, tau, mode) {
                Ok(tr) => tr,
                Err(_) => {
                    tau = lo + 0.5 * span;
                    self.trial(t, y, tau, mode).map_err(|e| {
                        self.failure(t, y, format!("{e} while locating a contact switch"))
                    })?
                }
            };
            let sw = self.switches(mode, t + tau, &tr.y, t + 0.5 * tau);
            if sw.any_crossed() {
                (hi, m_hi, best) = (tau, sw, tr);
                w_hi = 1.0;
                w_lo = if last_kept_lo == Some(true) {
                    0.5 * w_lo
                } else {
                    1.0
                };
                last_kept_lo = Some(true);
            } else {
                (lo, m_lo) = (tau, sw);
                w_lo = 1.0;
                w_hi = if last_kept_lo == Some(false) {
                    0.5 * w_hi
                } else {
                    1.0
                };
                last_kept_lo = Some(false);
            }
        }
        Ok(best)
    }

    /// The failure at (t, y), with the first mesh's phase, DTE and force.
    fn failure(&self, t: f64, y: &Vector<D>, reason: String) -> StepFailure {
        let (_, ms) = self.sys.derivative(ContactFrame::NATURAL, t, y.as_slice());
        let mesh = self.sys.mesh(0);
        let period_rad = mesh.parts.pair.mesh_angle_rad();
        let phase = mesh.phase_at(t) % period_rad;
        StepFailure {
            time_s: t,
            phase_deg: phase / period_rad * 360.0,
            dte_um: ms[0].deflection_m * 1e6,
            force_n: ms[0].force_n,
            reason,
            intervals: self.nodes.len().saturating_sub(1),
            tolerance: self.tolerance,
        }
    }
}

impl<D: Dim> PeriodIntegrator for PeriodStepper<'_, '_, D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    fn integrate(
        &mut self,
        t0: f64,
        y: &mut [f64],
        obs: &mut dyn PeriodObserver,
    ) -> Result<(), StepFailure> {
        self.integrate_slice(t0, y, obs, self.nodes.len() - 1)
    }

    fn integrate_part(
        &mut self,
        t0: f64,
        y: &mut [f64],
        obs: &mut dyn PeriodObserver,
        until_s: f64,
    ) -> Result<(), StepFailure> {
        let last = self.nodes.partition_point(|t| *t < until_s);
        self.integrate_slice(t0, y, obs, last.clamp(1, self.nodes.len() - 1))
    }

    fn node_at_or_after(&self, s: f64) -> f64 {
        let k = self.nodes.partition_point(|t| *t < s);
        self.nodes[k.min(self.nodes.len() - 1)]
    }

    fn period(&self) -> f64 {
        *self.nodes.last().unwrap_or(&0.0)
    }

    fn set_plan_mode(&mut self, mode: PlanMode) {
        self.plan_mode = mode;
    }

    fn plan_mode(&self) -> PlanMode {
        self.plan_mode
    }

    fn integrator_stats(&self) -> StepStats {
        self.stepper.stats()
    }

    fn counts(&self) -> StepCounts {
        self.counts
    }
}
