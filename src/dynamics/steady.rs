//! Steady-state evaluation: find the mesh-periodic solution, then record whole periods.
//!
//! Steady state is found, not assumed: quasi-Newton shooting on the one-period map
//! ([`super::shooting`]) from the static equilibrium or from a given periodic state
//! (warm start), each iteration one mesh period of the error-controlled integration of
//! [`super::period`]. It stops when the estimated distance of the start state from the
//! periodic orbit, relative to the state's scales, is below the case's tolerance. One
//! period of the orbit is recorded (the last search period when it started close enough,
//! else one more) and repeated over the evaluated window; its periodicity (the change of
//! the state over that period) is reported.

use super::grid::period_nodes;
use super::model::{ContactFrame, ContactMode, GearSystem, MeshState, State, NDOF};
use super::period::{
    state_scales, PeriodObserver, PeriodStepper, PlanMode, StepCounts, StepFailure,
};
use super::response::{DynamicResponse, PathSample, Signals};
use super::shooting::{scaled_max, Reduction, Shooting};

/// Numerical settings of a steady-state evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyStateSettings {
    /// Grid nodes per mesh period (the longest step).
    pub steps_per_mesh_period: usize,
    /// Local error tolerance of a step, relative to the state scales.
    pub integration_tolerance: f64,
    pub max_mesh_periods: usize,
    pub tolerance: f64,
    pub evaluated_mesh_periods: usize,
}

impl SteadyStateSettings {
    pub fn from_case(n: &crate::config::case::NumericsSection) -> Self {
        Self {
            steps_per_mesh_period: n.steps_per_mesh_period.max(1) as usize,
            integration_tolerance: n.integration_tolerance,
            max_mesh_periods: n.max_mesh_periods.max(2) as usize,
            tolerance: n.steady_state_tolerance,
            evaluated_mesh_periods: n.evaluated_mesh_periods.max(1) as usize,
        }
    }
}

/// Why a dynamic evaluation failed.
#[derive(Debug, thiserror::Error)]
pub enum DynamicsError {
    #[error(transparent)]
    Integrator(#[from] StepFailure),
    #[error("no steady state after {periods} mesh periods (estimated distance from the periodic orbit {change:.2e} > tolerance {tolerance:.1e}); raise numerics.max_mesh_periods or check the damping")]
    NotPeriodic {
        periods: usize,
        change: f64,
        tolerance: f64,
    },
    #[error("invalid integrator setting: {0}")]
    Setting(String),
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
    start: Option<&[f64; 16]>,
) -> Result<DynamicResponse, DynamicsError> {
    let nodes = period_nodes(
        sys.parts.pair,
        sys.parts.params.pinion_speed_rad_s,
        settings.steps_per_mesh_period,
    );
    let mut ps = PeriodStepper::new(sys, nodes, settings.integration_tolerance)
        .map_err(|e| DynamicsError::Setting(e.to_string()))?;
    let period = ps.period();
    let template = match start {
        Some(s) => State::from_column_slice(s),
        None => sys.static_equilibrium(),
    };
    let red = Reduction::new(sys);
    let scales = state_scales(sys);
    let red_scales = red.scales(&scales);
    let mut shooting = Shooting::new(sys, &red, period, &scales);
    let mut z = red.reduce(&template);
    let mut distance = f64::INFINITY;
    let mut periods = 0;
    // The last period integrated, recorded when it was likely to be the last one
    // needed: the first from a warm start, or once the search is close.
    let mut recorded: Option<(Recorder, State, State)> = None;
    // Every period starts at t = 0: the one-period map is the same function in every
    // iteration (the model depends on time through the mesh phase only).
    while distance >= settings.tolerance {
        if periods == settings.max_mesh_periods {
            return Err(DynamicsError::NotPeriodic {
                periods,
                change: distance,
                tolerance: settings.tolerance,
            });
        }
        let y0 = red.embed(&z, &template);
        let mut y = y0;
        // Close to the orbit (or warm), fix the step sequence: build it once, then replay.
        let close = distance < 1e-2 || (periods == 0 && start.is_some());
        match ps.plan_mode() {
            PlanMode::Free if close => ps.set_plan_mode(PlanMode::Build),
            PlanMode::Build => ps.set_plan_mode(PlanMode::Replay),
            _ => {}
        }
        let speculative =
            distance < 100.0 * settings.tolerance || (periods == 0 && start.is_some());
        if speculative {
            let mut rec = Recorder::default();
            ps.integrate(0.0, &mut y, &mut rec)?;
            recorded = Some((rec, y0, y));
        } else {
            ps.integrate(0.0, &mut y, &mut ())?;
            recorded = None;
        }
        periods += 1;
        let (next, d) = shooting.next(&z, &red.reduce(&y));
        z = next;
        distance = d;
    }
    let (rec, y_start, y_end) = match recorded {
        Some(r) => r,
        None => {
            if ps.plan_mode() == PlanMode::Build {
                ps.set_plan_mode(PlanMode::Replay);
            }
            let y0 = red.embed(&z, &template);
            let mut y = y0;
            let mut rec = Recorder::default();
            ps.integrate(0.0, &mut y, &mut rec)?;
            (rec, y0, y)
        }
    };
    let periodicity = scaled_max(&(red.reduce(&y_end) - red.reduce(&y_start)), &red_scales);
    let n_eval = settings.evaluated_mesh_periods;
    let (signals, path) = rec.window(period, n_eval, &y_start, &y_end);
    let stats = ps.integrator_stats();
    let StepCounts { accepted, .. } = ps.counts;
    Ok(DynamicResponse {
        signals,
        path,
        periods_to_converge: periods,
        periodicity_error: periodicity,
        mesh_period_s: period,
        mean_mesh_force_n: rec.force_int / period,
        mean_dte_m: rec.dte_int / period,
        end_state: std::array::from_fn(|i| y_end[i]),
        steps: accepted,
        rhs_evaluations: stats.rhs_calls as usize,
        factorizations: stats.lu_factorizations as usize,
        step_counts: ps.counts,
    })
}

/// Change of the displacements over one period of the periodic orbit: the drift of the
/// drivetrain's rigid rotation under the motor-slip boundary, ~0 otherwise.
fn drift(y_start: &State, y_end: &State) -> State {
    let mut d = y_end - y_start;
    for i in NDOF..2 * NDOF {
        d[i] = 0.0;
    }
    d
}

/// Records one period of the periodic solution: a sample at every point of the solution
/// (the grid nodes and every step between them), the path of contact, and the time
/// integrals of the mesh force and DTE step by step (a trapezoid on the points would
/// split the force's jumps at the mesh events).
#[derive(Default)]
struct Recorder {
    sig: Signals,
    path: Vec<PathSample>,
    force_int: f64,
    dte_int: f64,
}

impl Recorder {
    /// The evaluated window of `periods` periods from the one period recorded (periodic
    /// to the steady-state tolerance, so every later period repeats it; the rigid
    /// rotation's drift is carried on), and the path of contact sorted by rho1.
    fn window(
        &self,
        period: f64,
        periods: usize,
        y_start: &State,
        y_end: &State,
    ) -> (Signals, Vec<PathSample>) {
        // Destructured in full: a new signal must be repeated here too.
        let Signals {
            time_s,
            phase_rad,
            dte_m,
            mesh_force_n,
            mesh_stiffness_n_per_m,
            displacement,
            velocity,
            acceleration,
            friction_coefficient,
            friction_n,
            pair_load_n,
        } = &self.sig;
        let mut sig = self.sig.clone();
        let d = drift(y_start, y_end);
        for p in 1..periods {
            let shift = p as f64 * period;
            sig.time_s.extend(time_s.iter().map(|t| t + shift));
            sig.displacement.extend(
                displacement
                    .iter()
                    .map(|q| -> [f64; NDOF] { std::array::from_fn(|i| q[i] + p as f64 * d[i]) }),
            );
            sig.phase_rad.extend_from_slice(phase_rad);
            sig.dte_m.extend_from_slice(dte_m);
            sig.mesh_force_n.extend_from_slice(mesh_force_n);
            sig.mesh_stiffness_n_per_m
                .extend_from_slice(mesh_stiffness_n_per_m);
            sig.velocity.extend_from_slice(velocity);
            sig.acceleration.extend_from_slice(acceleration);
            for j in 0..2 {
                sig.friction_coefficient[j].extend_from_slice(&friction_coefficient[j]);
                sig.friction_n[j].extend_from_slice(&friction_n[j]);
                sig.pair_load_n[j].extend_from_slice(&pair_load_n[j]);
            }
        }
        let mut path = self.path.clone();
        path.sort_by(|a, b| a.rho1_m.total_cmp(&b.rho1_m));
        (sig, path)
    }
}

impl PeriodObserver for Recorder {
    fn point(&mut self, sys: &GearSystem, t: f64, decide: f64, y: &State) {
        let (dy, ms) = sys.derivative(ContactFrame::decided_at(decide), t, y);
        record(
            &mut self.sig,
            t,
            sys.phase_at(t) % sys.parts.pair.mesh_angle_rad(),
            y,
            &dy,
            &ms,
        );
        push_path(&mut self.path, sys, y, &ms);
    }

    fn step(
        &mut self,
        sys: &GearSystem,
        t: f64,
        h: f64,
        y0: &State,
        y1: &State,
        mode: ContactMode,
    ) {
        // Simpson's rule on the step, with the midpoint state from the cubic Hermite
        // interpolant of the step's ends (fourth order; the force is smooth inside a
        // step, which never crosses a mesh event or a contact switch).
        let frame = ContactFrame::frozen(t + 0.5 * h, mode);
        let (f0, ms0) = sys.derivative(frame, t, y0);
        let (f1, ms1) = sys.derivative(frame, t + h, y1);
        let y_mid = (y0 + y1) * 0.5 + (f0 - f1) * (h / 8.0);
        let (_, ms) = sys.derivative(frame, t + 0.5 * h, &y_mid);
        let simpson = |a: f64, m: f64, b: f64| h / 6.0 * (a + 4.0 * m + b);
        self.force_int += simpson(ms0.force_n, ms.force_n, ms1.force_n);
        self.dte_int += simpson(ms0.deflection_m, ms.deflection_m, ms1.deflection_m);
    }
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
    let omega_p = sys.parts.params.pinion_speed_rad_s + y[NDOF + super::model::dof::PHI_P];
    let omega_g = sys.parts.params.gear_speed_rad_s + y[NDOF + super::model::dof::PHI_G];
    PathSample::push_contacts(path, ms, sys.parts.pair.loa_length_m, omega_p, omega_g);
}
