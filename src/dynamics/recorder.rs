//! What the steady-state solvers record of a periodic solution: a sample at every point
//! of the solution (the grid nodes and every step between them), the path of contact,
//! and the time integrals of the mesh force and DTE step by step (a trapezoid on the
//! points would split the force's jumps at the mesh events).

use super::model::{ContactFrame, ContactModes, DecidedSets, GearSystem, MeshState};
use super::observer::PeriodObserver;
use super::response::{sorted_by_rho1, PathSample, Signals};

/// Change of the displacements over one period of the periodic orbit: the drift of the
/// drivetrain's rigid rotation under the motor-slip boundary, ~0 otherwise (the
/// displacements' share of two states).
fn drift(y_start: &[f64], y_end: &[f64]) -> Vec<f64> {
    let n = y_start.len() / 2;
    (0..n).map(|i| y_end[i] - y_start[i]).collect()
}

/// Records one period of the periodic solution (see the module docs). With a
/// tooth-resolved mesh the period spans `excitation_periods` base periods and each
/// contact is tagged with its engagement, its mesh cycle modulo that number of its mesh
/// periods.
#[derive(Default)]
pub struct Recorder {
    pub(crate) sig: Signals,
    /// Each mesh's path of contact.
    pub paths: Vec<Vec<PathSample>>,
    /// Each mesh's time integrals of the force (N s) and DTE (m s).
    pub force_int: Vec<f64>,
    pub(crate) dte_int: Vec<f64>,
    /// Base periods of the recorded period (0 or 1: one).
    pub excitation_periods: usize,
    /// Mesh periods of each mesh in the recorded period (for tagging engagements).
    engagements: Vec<i64>,
    /// The last step-end evaluation, offered to the next point and step (see
    /// [`Evaluation`]).
    last: Option<Evaluation>,
    /// Room for the evaluations of a step: the midpoint's state and evaluation, and an
    /// evaluation's buffers to reuse (no allocation per sample once the first step ran).
    work: Work,
    y_mid: Vec<f64>,
    spare: Option<Evaluation>,
}

/// Buffers of one right-hand-side evaluation.
#[derive(Default)]
struct Work {
    dy: Vec<f64>,
    meshes: Vec<MeshState>,
}

/// One right-hand-side evaluation kept for reuse. A step's end is the next point and the
/// next step's start: the same time and state, evaluated with the pairs and the contact
/// mode the step held. The result depends on the frame only through the pairs decided
/// ([`GearSystem::decided_sets`]) and the modes (`TrainMesh::springs`), so where both
/// agree the kept result is the one a new evaluation would give, bit for bit; elsewhere
/// (a mesh event, a contact switch) it is evaluated anew.
struct Evaluation {
    t: f64,
    y: Vec<f64>,
    sets: DecidedSets,
    mode: ContactModes,
    dy: Vec<f64>,
    meshes: Vec<MeshState>,
}

impl Evaluation {
    fn is_at(&self, t: f64, y: &[f64], sets: &DecidedSets) -> bool {
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        same(self.t, t)
            && self.sets.same_as(sets)
            && self.y.iter().zip(y.iter()).all(|(a, b)| same(*a, *b))
    }
}

impl Recorder {
    /// A recorder of `sys` over `excitation_periods` base periods.
    pub fn new(sys: &GearSystem, excitation_periods: usize) -> Self {
        let n_meshes = sys.meshes.len();
        let base = super::grid::base_period(sys).map_or(vec![1; n_meshes], |(_, c)| c);
        Self {
            sig: Signals::new(sys.dofs(), n_meshes),
            paths: vec![Vec::new(); n_meshes],
            force_int: vec![0.0; n_meshes],
            dte_int: vec![0.0; n_meshes],
            excitation_periods,
            engagements: base
                .iter()
                .map(|c| (c * excitation_periods.max(1)) as i64)
                .collect(),
            last: None,
            work: Work {
                dy: vec![0.0; sys.states()],
                meshes: vec![MeshState::default(); n_meshes],
            },
            y_mid: vec![0.0; sys.states()],
            spare: None,
        }
    }

    /// The evaluated window of `periods` periods from the one period recorded (periodic
    /// to the steady-state tolerance, so every later period repeats it; the rigid
    /// rotation's drift is carried on), and each mesh's path of contact sorted by rho1.
    pub fn window(
        &self,
        period: f64,
        periods: usize,
        y_start: &[f64],
        y_end: &[f64],
    ) -> (Signals, Vec<Vec<PathSample>>) {
        let sig = self.sig.repeated(period, periods, &drift(y_start, y_end));
        (sig, self.paths.iter().map(|p| sorted_by_rho1(p)).collect())
    }

    /// Appends `later`, the recording of the stretch of the solution that follows this
    /// one's (same system and excitation periods): its samples, paths and integrals.
    pub(crate) fn append(&mut self, later: &Recorder) {
        self.sig.append(&later.sig);
        for (p, more) in self.paths.iter_mut().zip(&later.paths) {
            p.extend_from_slice(more);
        }
        for (a, b) in self.force_int.iter_mut().zip(&later.force_int) {
            *a += b;
        }
        for (a, b) in self.dte_int.iter_mut().zip(&later.dte_int) {
            *a += b;
        }
    }

    /// Moves every recorded displacement by `shift` (a rigid rotation: nothing else
    /// recorded depends on it).
    pub(crate) fn shift_displacements(&mut self, shift: &[f64]) {
        self.sig.displacement.shift_each(shift);
    }

    /// Evaluates the right-hand side into the work buffers.
    fn evaluate(&mut self, sys: &GearSystem, frame: ContactFrame, t: f64, y: &[f64]) {
        let w = &mut self.work;
        sys.derivative_into(frame, t, y, &mut w.dy, &mut w.meshes);
    }

    /// An evaluation of `sys` at `(t, y)` in `frame` (kept as decided in `sets` and
    /// `mode`), in the spare buffers when there are some.
    #[allow(clippy::too_many_arguments)]
    fn evaluation(
        &mut self,
        sys: &GearSystem,
        frame: ContactFrame,
        t: f64,
        y: &[f64],
        sets: DecidedSets,
        mode: ContactModes,
    ) -> Evaluation {
        let mut e = self.spare.take().unwrap_or_else(|| Evaluation {
            t,
            y: vec![0.0; y.len()],
            sets,
            mode,
            dy: vec![0.0; sys.states()],
            meshes: vec![MeshState::default(); sys.meshes.len()],
        });
        sys.derivative_into(frame, t, y, &mut e.dy, &mut e.meshes);
        e.t = t;
        e.y.copy_from_slice(y);
        e.sets = sets;
        e.mode = mode;
        e
    }
}

impl PeriodObserver for Recorder {
    fn point(&mut self, sys: &GearSystem, t: f64, decide: f64, y: &[f64]) {
        let frame = ContactFrame::decided_at(decide);
        let sets = sys.decided_sets(frame, t);
        let reuse = self
            .last
            .as_ref()
            .is_some_and(|e| e.is_at(t, y, &sets) && sys.natural_mode_in(frame, t, y) == e.mode);
        if !reuse {
            self.evaluate(sys, frame, t, y);
        }
        let (dy, meshes) = match (&self.last, reuse) {
            (Some(e), true) => (&e.dy, &e.meshes),
            _ => (&self.work.dy, &self.work.meshes),
        };
        record(&mut self.sig, sys, t, y, dy, meshes);
        let n = sys.dofs();
        for (m, ms) in meshes.iter().enumerate() {
            // The DTE's rate: its gradient times the velocities (the DTE is linear in q).
            let rate = sys.mesh(m).geometry.gradient.iter();
            self.sig.meshes[m]
                .dte_rate_m_per_s
                .push(rate.map(|(i, g)| g * y[n + i]).sum());
            let path = &mut self.paths[m];
            let first = path.len();
            push_path(path, sys, m, y, ms);
            // The engagement within the excitation period (`PathSample::cycle`).
            let p = self.engagements[m].max(1);
            for s in &mut path[first..] {
                s.cycle = s.cycle.rem_euclid(p);
            }
        }
    }

    fn step(
        &mut self,
        sys: &GearSystem,
        t: f64,
        h: f64,
        y0: &[f64],
        y1: &[f64],
        mode: ContactModes,
    ) {
        // Simpson's rule on the step, with the midpoint state from the cubic Hermite
        // interpolant of the step's ends (fourth order; the force is smooth inside a
        // step, which never crosses a mesh event or a contact switch).
        let frame = ContactFrame::frozen(t + 0.5 * h, mode);
        let sets = sys.decided_sets(frame, t);
        let e0 = match self.last.take() {
            Some(e) if e.mode == mode && e.is_at(t, y0, &sets) => e,
            other => {
                if other.is_some() {
                    self.spare = other;
                }
                self.evaluation(sys, frame, t, y0, sets, mode)
            }
        };
        let e1 = self.evaluation(sys, frame, t + h, y1, sets, mode);
        let (f0, f1) = (&e0.dy, &e1.dy);
        for (i, m) in self.y_mid.iter_mut().enumerate() {
            *m = (y0[i] + y1[i]) * 0.5 + (f0[i] - f1[i]) * (h / 8.0);
        }
        let w = &mut self.work;
        sys.derivative_into(frame, t + 0.5 * h, &self.y_mid, &mut w.dy, &mut w.meshes);
        let simpson = |a: f64, m: f64, b: f64| h / 6.0 * (a + 4.0 * m + b);
        let (ms0, ms1) = (&e0.meshes, &e1.meshes);
        for m in 0..ms1.len() {
            let mid = &w.meshes[m];
            self.force_int[m] += simpson(ms0[m].force_n, mid.force_n, ms1[m].force_n);
            self.dte_int[m] += simpson(ms0[m].deflection_m, mid.deflection_m, ms1[m].deflection_m);
        }
        // The step's own accelerations at both ends (the solution's slope data; points
        // and steps alternate, so entry j belongs to the step leaving sample j).
        let n = sys.dofs();
        let [start, end] = &mut self.sig.step_acceleration;
        start.push(&f0[n..]);
        end.push(&f1[n..]);
        self.last = Some(e1);
        self.spare = Some(e0);
    }
}

fn record(
    sig: &mut Signals,
    sys: &GearSystem,
    t: f64,
    y: &[f64],
    dy: &[f64],
    meshes: &[MeshState],
) {
    let n = sys.dofs();
    sig.time_s.push(t);
    sig.displacement.push(&y[..n]);
    sig.velocity.push(&y[n..]);
    sig.acceleration.push(&dy[n..]);
    for (m, ms) in meshes.iter().enumerate() {
        let mesh = sys.mesh(m);
        let phase = mesh.phase_at(t) % mesh.parts.pair.mesh_angle_rad();
        sig.meshes[m].push(phase, ms);
    }
}

fn push_path(path: &mut Vec<PathSample>, sys: &GearSystem, m: usize, y: &[f64], ms: &MeshState) {
    let n = sys.dofs();
    let mesh = sys.mesh(m);
    let [rp, rg] = mesh.geometry.rotation;
    let [wp, wg] = mesh.operating.speeds_rad_s;
    let omega_p = wp + y[n + rp];
    let omega_g = wg + y[n + rg];
    PathSample::push_contacts(path, ms, mesh.parts.pair.loa_length_m, omega_p, omega_g);
}

/// A period recorded in two parts split at the node time `at` (s): the points and steps
/// before it go to `before`, the rest to `after` (no step crosses a node), and the state
/// of the point at `at` is kept. The splice of the steady-state search
/// ([`super::period_search`]) replaces `before` by a recording from a better start.
pub(crate) struct SplitRecorder {
    /// Where the parts meet, s.
    pub at: f64,
    /// The part before `at`.
    pub before: Recorder,
    /// The part from `at` on.
    pub after: Recorder,
    /// The state at `at`.
    pub state_at: Option<Vec<f64>>,
}

impl PeriodObserver for SplitRecorder {
    fn point(&mut self, sys: &GearSystem, t: f64, decide: f64, y: &[f64]) {
        if t < self.at {
            return self.before.point(sys, t, decide, y);
        }
        if self.state_at.is_none() {
            self.state_at = Some(y.to_vec());
        }
        self.after.point(sys, t, decide, y);
    }

    fn step(
        &mut self,
        sys: &GearSystem,
        t: f64,
        h: f64,
        y0: &[f64],
        y1: &[f64],
        mode: ContactModes,
    ) {
        let part = if t < self.at {
            &mut self.before
        } else {
            &mut self.after
        };
        part.step(sys, t, h, y0, y1, mode);
    }
}
