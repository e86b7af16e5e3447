//! Steady-state evaluation: integrate mesh period by mesh period until the response
//! repeats itself, then record whole periods.
//!
//! Steady state is detected, not guessed: after each period the dynamic transmission
//! error and the mesh force at every grid node are compared with the previous period's;
//! when the largest change, relative to the signal's peak, falls below the case's
//! tolerance, the response is periodic in the mesh period to that accuracy.

use super::grid::period_nodes;
use super::integrator::{IntegratorError, OdeSystem, Sdirk, SdirkOptions};
use super::model::{GearSystem, MeshState, State, NDOF, NSTATE};
use super::response::{DynamicResponse, PathSample, Signals};
use nalgebra::SMatrix;

/// Numerical settings of a steady-state evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyStateSettings {
    pub steps_per_mesh_period: usize,
    pub max_mesh_periods: usize,
    pub tolerance: f64,
    pub evaluated_mesh_periods: usize,
}

impl SteadyStateSettings {
    pub fn from_case(n: &crate::config::case::NumericsSection) -> Self {
        Self {
            steps_per_mesh_period: n.steps_per_mesh_period.max(1) as usize,
            max_mesh_periods: n.max_mesh_periods.max(2) as usize,
            tolerance: n.steady_state_tolerance,
            evaluated_mesh_periods: n.evaluated_mesh_periods.max(1) as usize,
        }
    }
}

/// Why a dynamic evaluation failed.
#[derive(Debug, thiserror::Error)]
pub enum DynamicsError {
    #[error("the integrator failed at t = {time_s:.6e} s: {reason}")]
    Integrator { time_s: f64, reason: String },
    #[error("no steady state after {periods} mesh periods (last relative change {change:.2e} > tolerance {tolerance:.1e}); raise numerics.max_mesh_periods or check the damping")]
    NotPeriodic {
        periods: usize,
        change: f64,
        tolerance: f64,
    },
    #[error("the state became non-finite at t = {0:.6e} s")]
    NonFinite(f64),
}

/// The model seen by the integrator.
struct Ode<'s, 'a> {
    sys: &'s GearSystem<'a>,
}

impl OdeSystem<NSTATE> for Ode<'_, '_> {
    fn rhs(&mut self, t: f64, y: &State) -> State {
        self.sys.derivative(t, y).0
    }
    fn jacobian(&mut self, t: f64, y: &State) -> Option<SMatrix<f64, NSTATE, NSTATE>> {
        Some(self.sys.jacobian(t, y))
    }
}

/// Largest change between two periods' samples relative to the samples' peak.
fn relative_change(a: &[f64], b: &[f64]) -> f64 {
    let peak = b.iter().fold(0.0_f64, |m, x| m.max(x.abs())).max(1e-300);
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
        / peak
}

/// Newton tolerances per state component: 1e-12 m of mesh deflection, and the
/// velocities scaled by the fastest mesh-mode frequency; the truncation error of the
/// fixed step (~1e-9 m) stays far above them.
fn newton_abs_tol(sys: &GearSystem) -> State {
    let r = sys
        .pair
        .pinion
        .base_radius_m
        .min(sys.pair.gear.base_radius_m);
    let omega = 1e5; // rad/s, above the mesh mode
    let mut tol = State::zeros();
    for i in 0..NDOF {
        let q = if i < 4 { 1e-12 } else { 1e-12 / r };
        tol[i] = q;
        tol[NDOF + i] = q * omega;
    }
    tol
}

/// A fixed-step stepper over a grid whose step changes only between mesh events.
struct GridStepper {
    sdirk: Sdirk<NSTATE>,
    h: f64,
}

impl GridStepper {
    fn new(sys: &GearSystem, h0: f64) -> Result<Self, IntegratorError> {
        let mut sdirk = Sdirk::new(h0, SdirkOptions::default())?;
        sdirk.set_abs_tol(newton_abs_tol(sys))?;
        Ok(Self { sdirk, h: h0 })
    }

    fn step(
        &mut self,
        ode: &mut Ode,
        t: f64,
        h: f64,
        y: &mut State,
    ) -> Result<(), IntegratorError> {
        // Grid steps within a segment are equal to round-off; refactor only between segments.
        if (h - self.h).abs() > 1e-9 * self.h {
            self.sdirk.set_step_size(h)?;
            self.h = h;
        }
        ode.sys.set_contact_decision_time(Some(t + 0.5 * h));
        let r = self.sdirk.step(ode, t, y).map(|_| ());
        ode.sys.set_contact_decision_time(None);
        r
    }
}

/// Integrate `sys` to its mesh-periodic steady state and record the evaluated window,
/// starting from the static equilibrium.
pub fn solve_steady_state(
    sys: &GearSystem,
    settings: &SteadyStateSettings,
) -> Result<DynamicResponse, DynamicsError> {
    solve_steady_state_from(sys, settings, None)
}

/// As [`solve_steady_state`], starting at mesh phase 0 from `start` (a state at a
/// mesh-period boundary, e.g. [`DynamicResponse::end_state`] of a neighbouring case)
/// instead of the static equilibrium.
pub fn solve_steady_state_from(
    sys: &GearSystem,
    settings: &SteadyStateSettings,
    start: Option<&[f64; NSTATE]>,
) -> Result<DynamicResponse, DynamicsError> {
    let omega = sys.params.pinion_speed_rad_s;
    let nodes = period_nodes(sys.pair, omega, settings.steps_per_mesh_period);
    let period = *nodes.last().unwrap_or(&0.0);
    let mut ode = Ode { sys };
    let integ_err = |t: f64| {
        move |e: IntegratorError| DynamicsError::Integrator {
            time_s: t,
            reason: e.to_string(),
        }
    };
    let mut stepper = GridStepper::new(sys, nodes[1] - nodes[0]).map_err(integ_err(0.0))?;
    let mut y = match start {
        Some(s) => State::from_column_slice(s),
        None => sys.static_equilibrium(),
    };
    let n = nodes.len();

    let mut prev_dte = vec![f64::NAN; n];
    let mut prev_force = vec![f64::NAN; n];
    let mut dte = vec![0.0; n];
    let mut force = vec![0.0; n];
    let mut converged_after = None;
    let mut quiet = 0;
    // A quarter of the shortest step: far from any other event, far above round-off.
    let eps_t = 0.25
        * nodes
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min);
    let mut change = f64::INFINITY;
    let mut t0 = 0.0;
    let mut steps = 0usize;

    for p in 0..settings.max_mesh_periods {
        for (k, node) in nodes.iter().enumerate() {
            let t = t0 + node;
            if k > 0 {
                let h = t - (t0 + nodes[k - 1]);
                stepper
                    .step(&mut ode, t - h, h, &mut y)
                    .map_err(integ_err(t))?;
                steps += 1;
                if !y.iter().all(|v| v.is_finite()) {
                    return Err(DynamicsError::NonFinite(t));
                }
            }
            // A node can be a mesh event: sample its left limit, the same on every
            // period whatever the round-off in t (the right limit is recorded below).
            sys.set_contact_decision_time(Some(t - eps_t));
            let (_, ms) = sys.derivative(t, &y);
            sys.set_contact_decision_time(None);
            dte[k] = ms.deflection_m;
            force[k] = ms.force_n;
        }
        t0 += period;
        if p >= 1 {
            change = relative_change(&dte, &prev_dte).max(relative_change(&force, &prev_force));
            // Two consecutive periods under the tolerance: one quiet period can be chance.
            quiet = if change < settings.tolerance {
                quiet + 1
            } else {
                0
            };
            if quiet >= 2 {
                converged_after = Some(p + 1);
                break;
            }
        }
        std::mem::swap(&mut dte, &mut prev_dte);
        std::mem::swap(&mut force, &mut prev_force);
    }
    let Some(periods_to_converge) = converged_after else {
        return Err(DynamicsError::NotPeriodic {
            periods: settings.max_mesh_periods,
            change,
            tolerance: settings.tolerance,
        });
    };

    // Record the evaluated window: nodes 0..n-1 of each period (the last node is the
    // next period's first), then the path samples of the last period.
    let mut sig = Signals::default();
    let mut path = Vec::with_capacity(n * 2);
    let (mut force_int, mut dte_int) = (0.0, 0.0);
    for p in 0..settings.evaluated_mesh_periods {
        let last = p + 1 == settings.evaluated_mesh_periods;
        for (k, node) in nodes.iter().enumerate() {
            let t = t0 + node;
            if k > 0 {
                let h = t - (t0 + nodes[k - 1]);
                let y_prev = y;
                stepper
                    .step(&mut ode, t - h, h, &mut y)
                    .map_err(integ_err(t))?;
                steps += 1;
                let y_mid = (y_prev + y) * 0.5;
                let (_, ms_mid) = sys.derivative(t - 0.5 * h, &y_mid);
                force_int += ms_mid.force_n * h;
                dte_int += ms_mid.deflection_m * h;
            }
            if k + 1 == n {
                break;
            }
            sys.set_contact_decision_time(Some(t + eps_t));
            let (dy, ms) = sys.derivative(t, &y);
            sys.set_contact_decision_time(None);
            record(
                &mut sig,
                t,
                sys.phase_at(t) % sys.pair.mesh_angle_rad(),
                &y,
                &dy,
                &ms,
            );
            if last {
                push_path(&mut path, sys, &y, &ms);
            }
        }
        t0 += period;
    }
    path.sort_by(|a, b| a.rho1_m.total_cmp(&b.rho1_m));
    let stats = stepper.sdirk.stats();
    Ok(DynamicResponse {
        signals: sig,
        path,
        periods_to_converge,
        periodicity_error: change,
        mesh_period_s: period,
        mean_mesh_force_n: force_int / (period * settings.evaluated_mesh_periods as f64),
        mean_dte_m: dte_int / (period * settings.evaluated_mesh_periods as f64),
        end_state: std::array::from_fn(|i| y[i]),
        steps,
        rhs_evaluations: stats.rhs_calls as usize,
        factorizations: stats.lu_factorizations as usize,
    })
}

fn record(sig: &mut Signals, t: f64, phase: f64, y: &State, dy: &State, ms: &MeshState) {
    let mut q = [0.0; NDOF];
    let mut v = [0.0; NDOF];
    let mut a = [0.0; NDOF];
    for i in 0..NDOF {
        q[i] = y[i];
        v[i] = y[NDOF + i];
        a[i] = dy[NDOF + i];
    }
    sig.time_s.push(t);
    sig.phase_rad.push(phase);
    sig.dte_m.push(ms.deflection_m);
    sig.mesh_force_n.push(ms.force_n);
    sig.mesh_stiffness_n_per_m.push(ms.stiffness_total_n_per_m);
    sig.displacement.push(q);
    sig.velocity.push(v);
    sig.acceleration.push(a);
    sig.push_pairs(ms);
}

fn push_path(path: &mut Vec<PathSample>, sys: &GearSystem, y: &State, ms: &MeshState) {
    let omega_p = sys.params.pinion_speed_rad_s + y[NDOF + super::model::dof::PHI_P];
    let omega_g = sys.params.gear_speed_rad_s + y[NDOF + super::model::dof::PHI_G];
    PathSample::push_contacts(path, ms, sys.pair.loa_length_m, omega_p, omega_g);
}
