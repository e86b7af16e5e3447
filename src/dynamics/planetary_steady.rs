//! The mesh-periodic steady state of a planetary set's dynamic model
//! (`planetary_dynamic`, docs/MODEL.md 12.5), integrated with the project's ESDIRK3(2)
//! stepper (`integrator::Sdirk`, the gear model's method; on stack vectors for 3 to 5
//! planets, `integrator::with_state_size`) under the same
//! local error control as `period` (step factor 0.9 err^(-1/3), clamped to [0.2, 5]).
//!
//! In the carrier frame every mesh's stiffness repeats with the mesh period T_m (the
//! phases only shift it), so the steady state is T_m-periodic. It is the fixed point of
//! the one-period map, found from the static equilibrium at the mean stiffness by the
//! quasi-Newton shooting of `shooting.rs` on every state (the members are grounded: no
//! rigid rotation to remove), its Jacobian started from the monodromy of the
//! time-invariant model ([`PlanetaryDynamic::mean_state_matrix`]), until the estimated
//! distance to the fixed point is below the case's `numerics.steady_state_tolerance`
//! relative to the state's scales (the largest static deflection for displacements,
//! times 2 pi f_m for velocities). One more period is then recorded at
//! `numerics.steps_per_mesh_period` equally spaced times (each reached by
//! error-controlled steps).
//!
//! Step grid (as the gear pair's `grid::period_nodes`): every mesh's stiffness jumps
//! where a tooth pair enters or leaves contact, at fixed times in the period
//! (`PlanetaryMeshes::jump_cycles`). Those times join the sample times as nodes that no
//! step crosses, each step deciding the pairs in contact at its middle
//! (`PlanetaryDynamic::decide_contact_at`), and the Jacobian is refreshed after each
//! jump; the error control then meets only the smooth response between jumps instead
//! of locating every jump by rejected steps.

use super::integrator::tableau::ESDIRK32;
use super::integrator::{with_state_size, Sdirk, SdirkOptions, Vector};
use super::planetary_dynamic::PlanetaryDynamic;
use super::planetary_grid::{period_grid, Node};
use super::shooting::{state_matrix_exp, Shooting};
use nalgebra::allocator::Allocator;
use nalgebra::{DVector, DefaultAllocator, Dim, U1};

/// Integration and steady-state settings (from `[numerics]`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanetarySettings {
    /// Recorded samples per mesh period (also the longest step, T_m / samples).
    pub samples_per_period: usize,
    /// Local error per step relative to the state's scales.
    pub integration_tolerance: f64,
    /// Mesh periods integrated at most before giving up.
    pub max_periods: usize,
    /// Largest change of the state over a period, relative to its scales, at steady state.
    pub steady_state_tolerance: f64,
}

/// One recorded mesh period of the steady state.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetaryResponse {
    /// Sample times from the period's start, s.
    pub times_s: Vec<f64>,
    /// Mesh forces per sample (sun meshes 1..N, then ring meshes 1..N), N.
    pub mesh_forces_n: Vec<Vec<f64>>,
    /// Each mesh's mean force over the period (same order), N, integrated between the
    /// samples (`mean_forces`).
    pub mean_forces_n: Vec<f64>,
    /// The coordinates q per sample, m.
    pub displacements_m: Vec<Vec<f64>>,
    /// The static deflection at mean stiffness the search started from, m.
    pub static_m: Vec<f64>,
    /// Mesh periods integrated before the recorded one.
    pub periods_to_steady: usize,
    /// Change of the state over the recorded period, relative to its scales.
    pub periodicity: f64,
    /// Accepted steps over the whole run.
    pub steps: u64,
    /// Mesh periods recorded: 1, or a tooth fault's period (`PlanetaryMeshes::periods`).
    pub mesh_periods: usize,
}

impl PlanetaryResponse {
    /// Each mesh's largest force over the recorded samples (sun meshes 1..N, then ring
    /// meshes 1..N), N; empty without samples.
    pub fn max_forces_n(&self) -> Vec<f64> {
        let n = self.mesh_forces_n.first().map_or(0, Vec::len);
        (0..n)
            .map(|j| {
                self.mesh_forces_n
                    .iter()
                    .map(|r| r[j])
                    .fold(f64::NEG_INFINITY, f64::max)
            })
            .collect()
    }
}

/// Why the steady state could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanetaryDynamicsError {
    /// The stiffness at mean mesh stiffness is singular.
    #[error("the planetary set has a member with no path to ground (a free rotation or translation): give its bearing or torsional support a stiffness")]
    Singular,
    /// The integrator failed.
    #[error("integration failed at t = {t_s:.6e} s: {reason}")]
    Integration {
        /// Time of the failure, s.
        t_s: f64,
        /// The integrator's message.
        reason: String,
    },
    /// The state did not become periodic.
    #[error("no steady state after {periods} mesh periods (change over the last period {change:.3e} of the state's scale; raise `numerics.max_mesh_periods` or the damping)")]
    NotSteady {
        /// Periods integrated.
        periods: usize,
        /// The last period's change, relative.
        change: f64,
    },
}

/// The one-period search's outcome: the stepper with its plan, the state on the orbit at
/// t = 0, the periods integrated, the state's scales and the static deflection.
struct Searched<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    run: Run<D>,
    z: DVector<f64>,
    periods: usize,
    scale: DVector<f64>,
    q0: DVector<f64>,
}

/// Integrate `sys` to its steady state and record it: one mesh period with every tooth
/// alike, the fault's period (`PlanetaryMeshes::periods`) with a tooth fault
/// (`solve_fault_period`).
pub fn solve_planetary_steady_state(
    sys: &mut PlanetaryDynamic,
    s: &PlanetarySettings,
) -> Result<PlanetaryResponse, PlanetaryDynamicsError> {
    // 3, 4 and 5 planets: 3 (N + 3) coordinates, twice as many states.
    with_state_size!(2 * sys.dofs(), [36, 42, 48], dim => solve_sized(sys, s, dim))
}

/// [`solve_planetary_steady_state`] with states of dimension `dim`.
fn solve_sized<D: Dim>(
    sys: &mut PlanetaryDynamic,
    s: &PlanetarySettings,
    dim: D,
) -> Result<PlanetaryResponse, PlanetaryDynamicsError>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    if sys.source.periods() > 1 {
        return solve_fault_period(sys, s, dim);
    }
    let Searched {
        mut run,
        z,
        periods,
        scale,
        q0,
    } = search(sys, s, dim)?;
    let mut y = z;
    let (samples, periodicity) = run.recorded_pass(sys, s, 1, &mut y, &scale)?;
    Ok(response(
        sys,
        s,
        &samples,
        q0,
        periods,
        periodicity,
        &run,
        1,
    ))
}

/// The mesh-periodic orbit's state at t = 0 by the quasi-Newton shooting of the module
/// docs, from the static equilibrium at mean stiffness.
fn search<D: Dim>(
    sys: &mut PlanetaryDynamic,
    s: &PlanetarySettings,
    dim: D,
) -> Result<Searched<D>, PlanetaryDynamicsError>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let n = sys.dofs();
    let q0 = sys
        .static_deflection()
        .ok_or(PlanetaryDynamicsError::Singular)?;
    let x_scale = q0.amax().max(f64::MIN_POSITIVE);
    let period = 1.0 / sys.mesh_frequency_hz;
    let v_scale = x_scale * 2.0 * std::f64::consts::PI * sys.mesh_frequency_hz;
    let scale = DVector::from_fn(2 * n, |i, _| if i < n { x_scale } else { v_scale });
    let mut stepper =
        Sdirk::with_dimension(dim, &ESDIRK32, period, newton(&scale)).map_err(|e| fail(0.0, e))?;
    let of = |v: &DVector<f64>| Vector::<D>::from_column_slice_generic(dim, U1, v.as_slice());
    stepper
        .set_error_tolerance(
            of(&scale.map(|v| v * s.integration_tolerance)),
            of(&DVector::zeros(2 * n)),
        )
        .map_err(|e| fail(0.0, e))?;
    let h_max = period / s.samples_per_period as f64;
    let mut run = Run {
        dim,
        stepper,
        h_prop: h_max,
        h_max,
        grid: period_grid(&sys.source.jump_cycles(), period, s.samples_per_period),
        plan: Vec::new(),
        mode: PlanMode::Free,
        next_plan: 0,
    };
    let mut z = DVector::zeros(2 * n);
    z.rows_mut(0, n).copy_from(&q0);
    let mut shooting = Shooting::from_monodromy(
        &state_matrix_exp(&sys.mean_state_matrix(), period),
        scale.clone(),
    );
    let mut periods = 0;
    // Every period starts at t = 0: the model depends on time through the mesh phase only,
    // so the one-period map is the same function in every iteration (quasi-Newton on it,
    // `shooting`, from the monodromy of the time-invariant model).
    let mut distance = f64::INFINITY;
    loop {
        // Close to the orbit, fix the step sequence: build it over one period, then
        // replay it (refined where the error test fails), as the gear pair's search.
        run.mode = match run.mode {
            PlanMode::Free if distance < PLAN_DISTANCE => PlanMode::Build,
            PlanMode::Build => PlanMode::Replay,
            m => m,
        };
        let mut y = z.clone();
        run.period(sys, 0.0, &mut y, None)?;
        periods += 1;
        let next;
        (next, distance) = shooting.next(&z, &y);
        z = next;
        if distance < s.steady_state_tolerance {
            break;
        }
        if periods >= s.max_periods {
            return Err(PlanetaryDynamicsError::NotSteady {
                periods,
                change: distance,
            });
        }
    }
    if run.mode == PlanMode::Build {
        run.mode = PlanMode::Replay;
    }
    Ok(Searched {
        run,
        z,
        periods,
        scale,
        q0,
    })
}

/// The response of the recorded `samples` (states at each sample's start over `recorded`
/// mesh periods, then the end state).
#[allow(clippy::too_many_arguments)]
fn response<D: Dim>(
    sys: &PlanetaryDynamic,
    s: &PlanetarySettings,
    samples: &[Vec<f64>],
    q0: DVector<f64>,
    periods: usize,
    periodicity: f64,
    run: &Run<D>,
    recorded: usize,
) -> PlanetaryResponse
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let n = sys.dofs();
    let count = s.samples_per_period * recorded;
    let dt = 1.0 / sys.mesh_frequency_hz / s.samples_per_period as f64;
    PlanetaryResponse {
        times_s: (0..count).map(|k| k as f64 * dt).collect(),
        mesh_forces_n: (0..count)
            .map(|k| sys.mesh_forces(k as f64 * dt, &samples[k]))
            .collect(),
        mean_forces_n: mean_forces(sys, 0.0, dt, samples),
        displacements_m: samples[..count].iter().map(|y| y[..n].to_vec()).collect(),
        static_m: q0.iter().copied().collect(),
        periods_to_steady: periods,
        periodicity,
        steps: run.stepper.stats().steps,
        mesh_periods: recorded,
    }
}

/// Mesh periods of run-in before a fault's period is recorded: W = 1.2 ln(1 / tolerance)
/// / (sigma T_m), sigma the slowest decay rate of the time-invariant model (the smallest
/// -Re(lambda) of [`PlanetaryDynamic::mean_state_matrix`]), so that the one-period orbit
/// the run-in starts from (the healthy set's, up to the state's scales away from the
/// faulty orbit) has decayed to the tolerance; 20 % margin for the uneven decay under
/// time-varying stiffness, as the pair's `hunting::run_in_periods`. At least 2, at most
/// `periods` (a pass that is not yet periodic is followed by another).
fn run_in_periods(sys: &PlanetaryDynamic, tolerance: f64, periods: usize) -> usize {
    let eig = sys.mean_state_matrix().complex_eigenvalues();
    let scale = eig.iter().fold(0.0_f64, |m, l| m.max(l.norm()));
    let sigma = eig
        .iter()
        .map(|l| -l.re)
        .filter(|d| *d > 1e-9 * scale)
        .fold(f64::INFINITY, f64::min);
    if !(sigma.is_finite() && sigma > 0.0) {
        return periods;
    }
    let w = 1.2 * (1.0 / tolerance).ln() * sys.mesh_frequency_hz / sigma;
    (w.ceil() as usize).max(2).min(periods)
}

/// The steady state of a set with a tooth fault over the fault's period P mesh periods
/// (docs/MODEL.md 12.13), as the pair's `hunting::solve_hunting`: (1) the one-period orbit
/// of the healthy set ([`search`], the fault left out), (2) a run-in with the fault over
/// the last W mesh periods of the period ([`run_in_periods`]), ending at its start, (3)
/// passes of P periods from t = 0, recorded, until one changes the state by less than the
/// steady-state tolerance relative to its scales (the P-period map contracts by
/// e^(-sigma P T_m): one pass from a settled state is periodic). Every period of a pass
/// is integrated from its own start time c T_m, so each pair meets its own teeth.
fn solve_fault_period<D: Dim>(
    sys: &mut PlanetaryDynamic,
    s: &PlanetarySettings,
    dim: D,
) -> Result<PlanetaryResponse, PlanetaryDynamicsError>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let p = sys.source.periods();
    let faulty = sys.source.clone();
    sys.source = faulty.without_fault();
    let searched = search(sys, s, dim);
    sys.source = faulty;
    let Searched {
        mut run,
        z,
        mut periods,
        scale,
        q0,
    } = searched?;
    let t_m = 1.0 / sys.mesh_frequency_hz;
    let mut y = z;
    let w = run_in_periods(sys, s.steady_state_tolerance, p);
    for c in p - w..p {
        run.period(sys, c as f64 * t_m, &mut y, None)?;
    }
    periods += w;
    // At least two passes after the search and the run-in, whatever
    // `numerics.max_mesh_periods` allows (a fault's period may be longer than it).
    let budget = s.max_periods.max(periods + 2 * p);
    loop {
        let (samples, periodicity) = run.recorded_pass(sys, s, p, &mut y, &scale)?;
        if periodicity < s.steady_state_tolerance {
            return Ok(response(
                sys,
                s,
                &samples,
                q0,
                periods,
                periodicity,
                &run,
                p,
            ));
        }
        periods += p;
        if periods + p > budget {
            return Err(PlanetaryDynamicsError::NotSteady {
                periods,
                change: periodicity,
            });
        }
    }
}

/// Sub-intervals per sample interval of the mean forces' midpoint rule: a mesh force
/// jumps with its stiffness (by up to ~half its value when a pair enters or leaves), and
/// the midpoint rule errs by at most a jump times half a sub-interval, 0.5 / (2 x 64 x
/// samples per period) of the mean, 2e-5 at 200 samples.
const MEAN_SUBDIVISIONS: usize = 64;

/// Each mesh's mean force over the recorded period, N: the midpoint rule on
/// [`MEAN_SUBDIVISIONS`] points per sample interval, the state between samples by cubic
/// Hermite interpolation of q with q' (its error O(dt^4)), the stiffness at the point.
fn mean_forces(sys: &PlanetaryDynamic, t0: f64, dt: f64, samples: &[Vec<f64>]) -> Vec<f64> {
    let n = sys.dofs();
    let mut sum = vec![0.0; 2 * sys.params.planet_angles_rad.len()];
    let mut y = vec![0.0; 2 * n];
    let intervals = samples.len() - 1;
    for k in 0..intervals {
        let (a, b) = (&samples[k], &samples[k + 1]);
        for j in 0..MEAN_SUBDIVISIONS {
            let s = (j as f64 + 0.5) / MEAN_SUBDIVISIONS as f64;
            hermite(a, b, n, dt, s, &mut y);
            let f = sys.mesh_forces(t0 + (k as f64 + s) * dt, &y);
            for (acc, v) in sum.iter_mut().zip(f) {
                *acc += v;
            }
        }
    }
    let count = (intervals * MEAN_SUBDIVISIONS) as f64;
    sum.iter().map(|v| v / count).collect()
}

/// The cubic Hermite interpolant of [q, q'] between states `a` and `b` (dt apart) at the
/// fraction `s`: q from both ends' q and q', q' its derivative.
fn hermite(a: &[f64], b: &[f64], n: usize, dt: f64, s: f64, y: &mut [f64]) {
    let (s2, s3) = (s * s, s * s * s);
    let (h00, h10, h01, h11) = (
        2.0 * s3 - 3.0 * s2 + 1.0,
        s3 - 2.0 * s2 + s,
        -2.0 * s3 + 3.0 * s2,
        s3 - s2,
    );
    let (d00, d10, d01, d11) = (
        6.0 * s2 - 6.0 * s,
        3.0 * s2 - 4.0 * s + 1.0,
        -6.0 * s2 + 6.0 * s,
        3.0 * s2 - 2.0 * s,
    );
    for i in 0..n {
        let (qa, va, qb, vb) = (a[i], a[n + i], b[i], b[n + i]);
        y[i] = h00 * qa + h10 * dt * va + h01 * qb + h11 * dt * vb;
        y[n + i] = (d00 * qa + d01 * qb) / dt + d10 * va + d11 * vb;
    }
}

/// Newton tolerances a thousandth of the error tolerance's scale (the stage equations
/// solved well below the truncation error).
fn newton(scale: &DVector<f64>) -> SdirkOptions {
    SdirkOptions {
        abs_tol: scale.min() * 1e-9,
        ..SdirkOptions::default()
    }
}

fn fail(t_s: f64, e: impl std::fmt::Display) -> PlanetaryDynamicsError {
    PlanetaryDynamicsError::Integration {
        t_s,
        reason: e.to_string(),
    }
}

/// max_i |b_i - a_i| / scale_i.
fn relative_change(a: &DVector<f64>, b: &DVector<f64>, scale: &DVector<f64>) -> f64 {
    (b - a)
        .iter()
        .zip(scale.iter())
        .map(|(d, s)| d.abs() / s)
        .fold(0.0, f64::max)
}

/// How a period chooses its steps (as the gear pair's `period::PlanMode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PlanMode {
    /// Each step from the error control alone.
    Free,
    /// As `Free`, keeping the step ends that are not grid nodes as the plan.
    Build,
    /// Along the plan; a step the error test cuts adds its finer end to the plan (never
    /// coarsened).
    Replay,
}

/// Distance from the fixed point (relative to the state's scales) below which the search
/// fixes its step sequence (the gear pair's `period_search` threshold): the error
/// control's accept/reject decisions change with the state and make the one-period map
/// jump by the size of the local errors, above the steady-state tolerance; along one
/// fixed sequence the map is a continuous function of the state.
const PLAN_DISTANCE: f64 = 1e-2;

/// The stepper, its step proposal, the period's step grid and the step plan.
struct Run<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    dim: D,
    stepper: Sdirk<D>,
    h_prop: f64,
    h_max: f64,
    grid: Vec<Node>,
    /// Step ends (s from the period's start) that are not grid nodes, in order.
    plan: Vec<f64>,
    mode: PlanMode,
    /// The first plan point not yet passed (replay) in the current period.
    next_plan: usize,
}

impl<D: Dim> Run<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// One recorded pass of `p` mesh periods from t = 0 and the state `y` (each period
    /// integrated from its own start c T_m, so each pair meets its own teeth): its samples,
    /// the last the state at the pass's end, and its change of state relative to `scale`
    /// (the periodicity, dimensionless).
    fn recorded_pass(
        &mut self,
        sys: &mut PlanetaryDynamic,
        s: &PlanetarySettings,
        p: usize,
        y: &mut DVector<f64>,
        scale: &DVector<f64>,
    ) -> Result<(Vec<Vec<f64>>, f64), PlanetaryDynamicsError> {
        let t_m = 1.0 / sys.mesh_frequency_hz;
        let y_start = y.clone();
        let mut samples = Vec::with_capacity(p * s.samples_per_period + 1);
        for c in 0..p {
            self.period(sys, c as f64 * t_m, y, Some(&mut samples))?;
        }
        samples.push(y.as_slice().to_vec());
        Ok((samples, relative_change(&y_start, y, scale)))
    }

    /// One mesh period from `t0` over the step grid, from a fresh step proposal and
    /// Jacobian so that the period map depends on the state only (its fixed point is
    /// then the steady state to the integration's round-off), the Jacobian refreshed
    /// after each stiffness jump; the state at each sample's start pushed onto `rec`
    /// when given.
    fn period(
        &mut self,
        sys: &mut PlanetaryDynamic,
        t0: f64,
        y_out: &mut DVector<f64>,
        mut rec: Option<&mut Vec<Vec<f64>>>,
    ) -> Result<(), PlanetaryDynamicsError> {
        let mut y = Vector::<D>::from_column_slice_generic(self.dim, U1, y_out.as_slice());
        let y = &mut y;
        self.h_prop = self.h_max;
        self.stepper.invalidate_jacobian();
        self.next_plan = 0;
        if self.mode == PlanMode::Build {
            self.plan.clear();
        }
        let mut t = t0;
        for k in 1..self.grid.len() {
            if let (true, Some(r)) = (self.grid[k - 1].sample, rec.as_deref_mut()) {
                r.push(y.as_slice().to_vec());
            }
            let result = self.advance(sys, t0, &mut t, y, t0 + self.grid[k].t_s);
            if result.is_err() {
                sys.decide_contact_at(None);
            }
            result?;
            if self.grid[k].jump {
                self.stepper.invalidate_jacobian();
            }
        }
        sys.decide_contact_at(None);
        y_out.copy_from_slice(y.as_slice());
        Ok(())
    }

    /// The end of the next step from `t` towards the node `t_end` on the plan (replay:
    /// its next point before `t_end`, else `t_end`), s; None when not replaying.
    fn planned(&mut self, t0: f64, t: f64, t_end: f64) -> Option<f64> {
        if self.mode != PlanMode::Replay {
            return None;
        }
        while self.next_plan < self.plan.len() && t0 + self.plan[self.next_plan] <= t {
            self.next_plan += 1;
        }
        Some(match self.plan.get(self.next_plan) {
            Some(p) if t0 + p < t_end => t0 + p,
            _ => t_end,
        })
    }

    /// Error-controlled steps from `*t` to `t_end` (the last one cut to land on it), or
    /// along the plan when replaying (`t0` the period's start).
    fn advance(
        &mut self,
        sys: &mut PlanetaryDynamic,
        t0: f64,
        t: &mut f64,
        y: &mut Vector<D>,
        t_end: f64,
    ) -> Result<(), PlanetaryDynamicsError> {
        let h_min = self.h_max * 1e-9;
        while t_end - *t > h_min {
            let h_free = self.h_prop.min(self.h_max);
            let target = self.planned(t0, *t, t_end);
            let mut h = target.map_or(h_free.min(t_end - *t), |e| e - *t);
            let h_planned = h;
            loop {
                // The step crosses no node: one contact set, decided at its middle.
                sys.decide_contact_at(Some(*t + 0.5 * h));
                match self.stepper.try_step(sys, *t, y, h) {
                    Err(e) => {
                        h *= 0.5;
                        if h < h_min {
                            return Err(fail(*t, e));
                        }
                    }
                    Ok(tr) if tr.error > 1.0 => {
                        h *= (0.9 * tr.error.powf(-1.0 / 3.0)).clamp(0.2, 0.9);
                        if h < h_min {
                            return Err(fail(*t, "local error above tolerance"));
                        }
                    }
                    Ok(tr) => {
                        self.stepper.accept(&tr);
                        let grow = (0.9 * tr.error.max(1e-10).powf(-1.0 / 3.0)).clamp(0.2, 5.0);
                        // A step cut short to land on a node keeps the longer proposal
                        // unless its own error asks for a shorter one.
                        self.h_prop = if h < h_free && grow >= 1.0 {
                            h_free
                        } else {
                            h * grow
                        };
                        let t_new = match target {
                            Some(e) if h == h_planned => e,
                            _ if h == t_end - *t => t_end,
                            _ => *t + h,
                        };
                        match self.mode {
                            // A step the error test cut: the plan keeps the finer point.
                            PlanMode::Replay if h < h_planned => {
                                self.plan.insert(self.next_plan, t_new - t0)
                            }
                            PlanMode::Build if t_new < t_end => self.plan.push(t_new - t0),
                            _ => {}
                        }
                        *t = t_new;
                        *y = tr.y;
                        break;
                    }
                }
            }
        }
        *t = t_end;
        Ok(())
    }
}
