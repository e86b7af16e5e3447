//! What the steady-state solvers record of a periodic solution: a sample at every point
//! of the solution (the grid nodes and every step between them), the path of contact,
//! and the time integrals of the mesh force and DTE step by step (a trapezoid on the
//! points would split the force's jumps at the mesh events).

use super::model::{ContactFrame, ContactMode, GearSystem, MeshState, State, NDOF};
use super::period::PeriodObserver;
use super::response::{sorted_by_rho1, PathSample, Signals};

/// Change of the displacements over one period of the periodic orbit: the drift of the
/// drivetrain's rigid rotation under the motor-slip boundary, ~0 otherwise.
fn drift(y_start: &State, y_end: &State) -> State {
    let mut d = y_end - y_start;
    for i in NDOF..2 * NDOF {
        d[i] = 0.0;
    }
    d
}

/// Records one period of the periodic solution (see the module docs). With a
/// tooth-resolved mesh the period spans `excitation_periods` mesh periods and each
/// contact is tagged with its engagement, its mesh cycle modulo that number.
#[derive(Default)]
pub struct Recorder {
    pub sig: Signals,
    pub path: Vec<PathSample>,
    pub force_int: f64,
    pub dte_int: f64,
    /// Mesh periods of the recorded period (0 or 1: one).
    pub excitation_periods: usize,
    /// The last step-end evaluation, offered to the next point and step (see
    /// [`Evaluation`]).
    last: Option<Evaluation>,
}

/// One right-hand-side evaluation kept for reuse. A step's end is the next point and the
/// next step's start: the same time and state, evaluated with the pairs and the contact
/// mode the step held. The result depends on the frame only through the pairs decided
/// ([`GearSystem::decided_set`]) and the mode (`GearSystem::springs`), so where both
/// agree the kept result is the one a new evaluation would give, bit for bit; elsewhere
/// (a mesh event, a contact switch) it is evaluated anew.
struct Evaluation {
    t: f64,
    y: State,
    set: (f64, usize),
    mode: ContactMode,
    dy: State,
    ms: MeshState,
}

impl Evaluation {
    fn is_at(&self, t: f64, y: &State, set: (f64, usize)) -> bool {
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        same(self.t, t)
            && same(self.set.0, set.0)
            && self.set.1 == set.1
            && self.y.iter().zip(y.iter()).all(|(a, b)| same(*a, *b))
    }
}

impl Recorder {
    pub fn new(excitation_periods: usize) -> Self {
        Self {
            excitation_periods,
            ..Self::default()
        }
    }
}

impl Recorder {
    /// The evaluated window of `periods` periods from the one period recorded (periodic
    /// to the steady-state tolerance, so every later period repeats it; the rigid
    /// rotation's drift is carried on), and the path of contact sorted by rho1.
    pub fn window(
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
        (sig, sorted_by_rho1(&self.path))
    }
}

impl PeriodObserver for Recorder {
    fn point(&mut self, sys: &GearSystem, t: f64, decide: f64, y: &State) {
        let frame = ContactFrame::decided_at(decide);
        let set = sys.decided_set(frame, t);
        let kept = self
            .last
            .as_ref()
            .filter(|e| e.is_at(t, y, set) && sys.natural_mode_in(frame, t, y) == e.mode);
        let (dy, ms) = match kept {
            Some(e) => (e.dy, e.ms),
            None => sys.derivative(frame, t, y),
        };
        record(
            &mut self.sig,
            t,
            sys.phase_at(t) % sys.parts.pair.mesh_angle_rad(),
            y,
            &dy,
            &ms,
        );
        let first = self.path.len();
        push_path(&mut self.path, sys, y, &ms);
        // The engagement within the excitation period (`PathSample::cycle`).
        let p = self.excitation_periods.max(1) as i64;
        for s in &mut self.path[first..] {
            s.cycle = s.cycle.rem_euclid(p);
        }
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
        let set = sys.decided_set(frame, t);
        let kept = self
            .last
            .as_ref()
            .filter(|e| e.mode == mode && e.is_at(t, y0, set));
        let (f0, ms0) = match kept {
            Some(e) => (e.dy, e.ms),
            None => sys.derivative(frame, t, y0),
        };
        let (f1, ms1) = sys.derivative(frame, t + h, y1);
        self.last = Some(Evaluation {
            t: t + h,
            y: *y1,
            set,
            mode,
            dy: f1,
            ms: ms1,
        });
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
    let omega_p =
        sys.parts.params.operating.pinion_speed_rad_s + y[NDOF + super::model::dof::PHI_P];
    let omega_g = sys.parts.params.operating.gear_speed_rad_s + y[NDOF + super::model::dof::PHI_G];
    PathSample::push_contacts(path, ms, sys.parts.pair.loa_length_m, omega_p, omega_g);
}
