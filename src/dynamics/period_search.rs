//! The search for the mesh-periodic orbit: quasi-Newton shooting on the one-period map
//! ([`super::shooting`]) from the static equilibrium or a warm start, each iteration one
//! base period (a mesh period; a train's common period) of the error-controlled integration of [`super::period`]; the settings
//! that bound it and the ways it can fail. Both the one-period steady state
//! ([`super::steady`]) and the one over a hunting period ([`super::hunting`]) start here.

use super::grid::train_nodes;
use super::modal::run_in_periods;
use super::model::{GearSystem, State};
use super::period::{period_stepper, PeriodIntegrator, PlanMode, StepFailure};
use super::recorder::{Recorder, SplitRecorder};
use super::response::{DynamicResponse, MeshResponse, PathSample};
use super::shooting::{scaled_max, Reduction, Shooting};
use super::state_scales::state_scales;
use nalgebra::DVector;

/// Numerical settings of a steady-state evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyStateSettings {
    /// Grid nodes per mesh period (the longest step).
    pub steps_per_mesh_period: usize,
    /// Local error tolerance of a step, relative to the state scales.
    pub integration_tolerance: f64,
    /// Give up on steady state after this many mesh periods.
    pub max_mesh_periods: usize,
    /// Steady state: the shooting's estimated distance from the periodic orbit, relative
    /// to the state's scales, below this.
    pub tolerance: f64,
    /// Mesh periods recorded once steady (signals, spectra).
    pub evaluated_mesh_periods: usize,
}

impl SteadyStateSettings {
    /// The settings of `[numerics]` (counts raised to their least meaningful value: at least
    /// one node, two periods searched and one recorded).
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
    /// A step of the period integration failed.
    #[error(transparent)]
    Integrator(#[from] StepFailure),
    /// The search did not reach the periodic orbit within its periods.
    #[error("no steady state after {periods} mesh periods (estimated distance from the periodic orbit {change:.2e} > tolerance {tolerance:.1e}); raise numerics.max_mesh_periods or check the damping; with a tooth fault, check that the faulty tooth can still carry the load (a nearly severed tooth leaves the model: docs/MODEL.md, section 9.9)")]
    NotPeriodic {
        /// Periods integrated.
        periods: usize,
        /// Estimated distance from the periodic orbit at the end, relative to the state's scales.
        change: f64,
        /// The steady-state tolerance it was held to.
        tolerance: f64,
    },
    /// An integrator setting out of its range (the message names it).
    #[error("invalid integrator setting: {0}")]
    Setting(String),
    /// The train's common excitation period overflows an integer count of base periods.
    #[error("the train's excitation period (the smallest common period of its meshes and their teeth) is too long to count in integers; a train of these teeth cannot be solved")]
    PeriodTooLong,
}

/// How many times a recorded period of `base_periods` base periods is repeated to cover
/// the case's evaluated mesh periods (of the first mesh), at least once.
pub fn window_repeats(
    sys: &GearSystem,
    settings: &SteadyStateSettings,
    base_periods: usize,
) -> usize {
    let per_base = super::grid::base_period(sys).map_or(1, |(_, c)| c[0].max(1));
    settings
        .evaluated_mesh_periods
        .div_ceil(base_periods * per_base)
        .max(1)
}

/// The search for the periodic orbit: quasi-Newton shooting on the one-period map
/// (module docs), each iteration one base period (a mesh period; a train's common
/// period) from t = 0 (so with a tooth-resolved mesh, the orbit of the teeth of mesh
/// cycle 0 meeting again and again).
pub struct MeshPeriodSearch<'s, 'a> {
    sys: &'s GearSystem<'a>,
    /// The period stepper (one base period per call).
    pub(crate) ps: Box<dyn PeriodIntegrator + 's>,
    /// The reduction of the state to the coordinates the shooting iterates on.
    pub(crate) red: Reduction,
    template: State,
    z: DVector<f64>,
    red_scales: DVector<f64>,
    /// Mesh periods integrated so far.
    pub periods: usize,
}

impl<'s, 'a> MeshPeriodSearch<'s, 'a> {
    /// A search on `sys` with `settings`, from the state `start` (length the system's states)
    /// or, without one, the static equilibrium.
    pub fn new(
        sys: &'s GearSystem<'a>,
        settings: &SteadyStateSettings,
        start: Option<&[f64]>,
    ) -> Result<Self, DynamicsError> {
        let nodes =
            train_nodes(sys, settings.steps_per_mesh_period).ok_or(DynamicsError::PeriodTooLong)?;
        let ps = period_stepper(sys, nodes, settings.integration_tolerance)
            .map_err(|e| DynamicsError::Setting(e.to_string()))?;
        let template = match start {
            Some(s) if s.len() == sys.states() => State::from_column_slice(s),
            _ => sys.static_equilibrium(),
        };
        let red = Reduction::new(sys);
        let red_scales = red.scales(&state_scales(sys));
        let z = red.reduce(template.as_slice());
        Ok(Self {
            sys,
            ps,
            z,
            template,
            red_scales,
            red,
            periods: 0,
        })
    }

    /// Runs the search to the case's tolerance. With `record`, the last period
    /// integrated is recorded when it is likely to be the last one needed (the first
    /// from a warm start, or once the search is close; a train's every period, see
    /// `splice_at`) and returned with its start and end states.
    pub fn run(
        &mut self,
        settings: &SteadyStateSettings,
        warm: bool,
        record: bool,
    ) -> Result<Option<(Recorder, State, State)>, DynamicsError> {
        let sys = self.sys;
        let period = self.ps.period();
        let mut shooting = Shooting::new(sys, &self.red, period, &state_scales(sys));
        let splice_at = if record {
            self.splice_at(settings)
        } else {
            None
        };
        let mut distance = f64::INFINITY;
        let mut recorded = None;
        // Every period starts at t = 0: the one-period map is the same function in every
        // iteration (the model depends on time through the mesh phase only).
        while distance >= settings.tolerance {
            // `>=`: a failed splice adds its partial pass to the count.
            if self.periods >= settings.max_mesh_periods {
                return Err(DynamicsError::NotPeriodic {
                    periods: self.periods,
                    change: distance,
                    tolerance: settings.tolerance,
                });
            }
            let y0 = self.start_state();
            let mut y = y0.clone();
            // Close to the orbit (or warm), fix the step sequence: build it once, then
            // replay.
            let first = self.periods == 0;
            let close = distance < 1e-2 || (first && warm);
            self.advance_plan(close);
            let speculative = record
                && (distance < 100.0 * settings.tolerance
                    || (first && warm)
                    || splice_at.is_some());
            let mut split = None;
            if let (true, Some(at)) = (speculative, splice_at) {
                let mut s = SplitRecorder {
                    at,
                    before: Recorder::new(sys, 1),
                    after: Recorder::new(sys, 1),
                    state_at: None,
                };
                self.ps.integrate(0.0, y.as_mut_slice(), &mut s)?;
                split = Some(s);
            } else if speculative {
                let mut rec = Recorder::new(sys, 1);
                self.ps.integrate(0.0, y.as_mut_slice(), &mut rec)?;
                recorded = Some((rec, y0.clone(), y.clone()));
            } else {
                self.ps.integrate(0.0, y.as_mut_slice(), &mut ())?;
                recorded = None;
            }
            self.periods += 1;
            let (next, d) = shooting.next(&self.z, &self.red.reduce(y.as_slice()));
            self.z = next;
            distance = d;
            if let Some(mut s) = split {
                if distance < settings.tolerance {
                    s.before.append(&s.after);
                    recorded = Some((s.before, y0, y));
                } else if let Some((rec, end)) = self.splice(settings, s, &y)? {
                    return Ok(Some((rec, self.start_state(), end)));
                } else {
                    recorded = None;
                }
            }
        }
        Ok(recorded)
    }

    /// Moves the step plan on: built once the search is `close`, then replayed.
    fn advance_plan(&mut self, close: bool) {
        match self.ps.plan_mode() {
            PlanMode::Free if close => self.ps.set_plan_mode(PlanMode::Build),
            PlanMode::Build => self.ps.set_plan_mode(PlanMode::Replay),
            _ => {}
        }
    }

    /// Where a train's recorded period may be spliced (s from its start), or None. A
    /// train's base period spans many periods of its first mesh (31 on the two-stage
    /// example), and the map over it contracts so strongly that one period from any
    /// start of the search ends on the orbit: what the start differs from the orbit by
    /// has decayed within the first W mesh periods, W = 1.2 ln(1 / tolerance) /
    /// (sigma T_1) ([`super::modal::run_in_periods`]: sigma the slowest decay rate of
    /// the averaged model, T_1 the first mesh's period). So the recording of a period
    /// from the search's start is right after those W mesh periods, and only its first
    /// W need recording again from the next start ([`Self::splice`]): 1 + W / c_1 base
    /// periods instead of two (c_1 the first mesh's periods in the base period). Only
    /// where W is at most half of c_1 (never the single pair, whose base period is one
    /// mesh period).
    fn splice_at(&self, settings: &SteadyStateSettings) -> Option<f64> {
        let c1 = *super::grid::base_period(self.sys)?.1.first()?;
        if c1 < 4 {
            return None;
        }
        let t1 = self.ps.period() / c1 as f64;
        let w = run_in_periods(self.sys, t1, settings.tolerance, c1);
        (2 * w <= c1).then(|| self.ps.node_at_or_after(w as f64 * t1))
    }

    /// The splice of a period recorded from the previous start (`s`, split at its node
    /// `s.at`, ending at `end`): the first part recorded again from the current start up
    /// to `s.at` and joined to the rest of `s`. None, and the search goes on, unless both
    /// ends of the joined record are on the orbit: the current start within the tolerance
    /// of `end` (the previous period's end, on the orbit where the map contracts as
    /// [`Self::splice_at`] requires: so the record is periodic, and its first part, from
    /// that start, is the orbit's; a quasi-Newton step that left the orbit would put its
    /// own transient there, which has decayed by `s.at` and the second check would miss),
    /// and the two parts within the tolerance at `s.at` (the previous start's difference
    /// had decayed there).
    fn splice(
        &mut self,
        settings: &SteadyStateSettings,
        mut s: SplitRecorder,
        end: &State,
    ) -> Result<Option<(Recorder, State)>, DynamicsError> {
        let Some(state_at) = s.state_at.take() else {
            return Ok(None);
        };
        // Agreement is `d < tol`: a NaN distance is none.
        let agree = |d: f64| d < settings.tolerance;
        if !agree(self.distance_between(&self.start_state(), end)) {
            return Ok(None);
        }
        // A plan built in the split period is replayed; a free search stays free (a
        // plan built on part of a period would leave the rest to one step per node).
        self.advance_plan(false);
        let mut y = self.start_state();
        let mut rec = Recorder::new(self.sys, 1);
        self.ps
            .integrate_part(0.0, y.as_mut_slice(), &mut rec, s.at)?;
        self.periods += 1;
        let joined = State::from_column_slice(&state_at);
        if !agree(self.distance_between(&joined, &y)) {
            return Ok(None);
        }
        // Under motor slip the two trajectories also differ by a rigid rotation, which
        // never decays (no force depends on it): the later part is carried on by it, so
        // that the angles run on without a jump at the split, to the end state.
        let mut end = end.clone();
        if let Some(shift) = self.red.rigid_offset(&state_at, y.as_slice()) {
            s.after.shift_displacements(&shift);
            for (e, d) in end.iter_mut().zip(&shift) {
                *e += d;
            }
        }
        rec.append(&s.after);
        Ok(Some((rec, end)))
    }

    /// Replay the step plan from now on (built by the search once it was close).
    pub fn replay(&mut self) {
        if self.ps.plan_mode() == PlanMode::Build {
            self.ps.set_plan_mode(PlanMode::Replay);
        }
    }

    /// The state the search has reached, at a mesh-period boundary.
    pub fn start_state(&self) -> State {
        self.red.embed(&self.z, self.template.as_slice())
    }

    /// Largest change between two states in the unknowns, relative to their scales.
    pub fn distance_between(&self, a: &State, b: &State) -> f64 {
        let (a, b) = (self.red.reduce(a.as_slice()), self.red.reduce(b.as_slice()));
        scaled_max(&(b - a), &self.red_scales)
    }

    /// The response from a recorded window.
    #[allow(clippy::too_many_arguments)]
    pub fn response(
        &self,
        signals: super::response::Signals,
        paths: Vec<Vec<PathSample>>,
        rec: &Recorder,
        recorded_s: f64,
        excitation_periods: usize,
        periodicity: f64,
        y_end: &State,
    ) -> DynamicResponse {
        let stats = self.ps.integrator_stats();
        let counts = self.ps.counts();
        let meshes = paths
            .into_iter()
            .enumerate()
            .map(|(m, path)| MeshResponse {
                path,
                mean_mesh_force_n: rec.force_int[m] / recorded_s,
                mean_dte_m: rec.dte_int[m] / recorded_s,
            })
            .collect();
        DynamicResponse {
            signals,
            meshes,
            periods_to_converge: self.periods,
            periodicity_error: periodicity,
            mesh_period_s: self.ps.period(),
            excitation_periods,
            end_state: y_end.as_slice().to_vec(),
            steps: counts.accepted,
            rhs_evaluations: stats.rhs_calls as usize,
            factorizations: stats.lu_factorizations as usize,
            step_counts: counts,
        }
    }
}
