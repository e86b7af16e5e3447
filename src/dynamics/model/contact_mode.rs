//! The contact mode of the mesh and its switches: contact loss as an event.
//!
//! Which pairs touch (compression delta - g_i > 0) and whether the mesh pushes (spring
//! and damper force of the touching pairs > 0) follow from the state. Where either
//! changes, the right-hand side has a kink (a compression or the force crossing zero)
//! or a jump (a pair closing again at a closing speed dc/dt > 0 meets the damper force
//! c_m dc/dt at once). An implicit step across such a switch has no smooth stage
//! solution: Newton fails, or converges to a point of the wrong side. So the integrator
//! holds the mode fixed during a step (each law continues smoothly past its switch),
//! checks the switching functions at the step's end and, if one changed sign, cuts the
//! step at the first sign change and goes on in the new mode: event location for
//! discontinuous right-hand sides (Hairer, Norsett & Wanner I, Sect. II.6; Eich-Soellner
//! & Fuehrer, *Numerical Methods in Multibody Dynamics*, Sect. 6.2).

use super::{GearSystem, MeshSprings, State, MAX_PAIRS, NDOF};

/// Which pairs touch and whether the mesh pushes (the branches of the mesh force law).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ContactMode {
    /// Pair i of the contact set (in the order of `GearPair::pairs_in_contact`) touches.
    touching: [bool; MAX_PAIRS],
    /// The mesh force is its springs and damper (else 0).
    pub pushing: bool,
}

impl ContactMode {
    pub fn touches(&self, pair: usize) -> bool {
        self.touching[pair]
    }

    /// The mode the springs were evaluated in.
    pub fn of(sp: &MeshSprings) -> Self {
        Self {
            touching: sp.touching,
            pushing: sp.pushing,
        }
    }

    /// Whether any pair touches.
    pub fn in_contact(&self) -> bool {
        self.touching.iter().any(|t| *t)
    }
}

/// How one evaluation of the right-hand side decides the contact: the time at which the
/// set of pairs in contact is decided, and the contact mode held fixed, if any. The
/// integrator's problem adaptor carries it for each trial step (decided at the step's
/// middle, so no stage of a step straddles a mesh event, and the step's mode frozen);
/// observers build their own. A value passed with each call, never state of the model.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactFrame {
    /// Time at which the pairs in contact are decided, s; None: the evaluation time.
    pub decision_time_s: Option<f64>,
    /// The contact mode held fixed; None: decided from the state at each evaluation,
    /// as the physics does.
    pub mode: Option<ContactMode>,
}

impl ContactFrame {
    /// Everything decided at the evaluation itself (time and state).
    pub const NATURAL: Self = Self {
        decision_time_s: None,
        mode: None,
    };

    /// The pairs in contact decided at `decide_s` (e.g. just after a mesh event), the
    /// mode from the state.
    pub fn decided_at(decide_s: f64) -> Self {
        Self {
            decision_time_s: Some(decide_s),
            mode: None,
        }
    }

    /// The pairs decided at `decide_s` and the contact mode held at `mode` (a step of
    /// the integrator).
    pub fn frozen(decide_s: f64, mode: ContactMode) -> Self {
        Self {
            decision_time_s: Some(decide_s),
            mode: Some(mode),
        }
    }
}

/// Number of switching functions: one per pair (its compression) and the mesh force.
pub const SWITCHES: usize = MAX_PAIRS + 1;

/// Index of the mesh-force switch among the switching functions.
pub const FORCE_SWITCH: usize = MAX_PAIRS;

/// The switching functions of a contact mode at one state.
#[derive(Debug, Clone, Copy, Default)]
pub struct ModeSwitch {
    /// Positive on the mode's own side: a pair's compression (m) with the sign that is
    /// positive while the pair stays as the mode says; the mesh force (N) likewise.
    margin: [f64; SWITCHES],
    /// The function applies (an existing pair; the force only when a pair touches).
    active: [bool; SWITCHES],
    /// Zero counts as crossed (the touching/pushing side is the open one, > 0).
    inclusive: [bool; SWITCHES],
}

impl ModeSwitch {
    /// Switching function `j` (see [`ModeSwitch::margin`] docs of the field), units m
    /// for a pair, N for [`FORCE_SWITCH`]; 0 for an inactive one.
    pub fn margin(&self, j: usize) -> f64 {
        self.margin[j]
    }

    /// Whether the state has left the mode through switch `j`.
    pub fn crossed(&self, j: usize) -> bool {
        let m = self.margin[j];
        self.active[j] && (m < 0.0 || (self.inclusive[j] && m == 0.0))
    }

    /// Whether the state has left the mode through any switch.
    pub fn any_crossed(&self) -> bool {
        (0..SWITCHES).any(|j| self.crossed(j))
    }
}

impl GearSystem<'_> {
    fn springs_of(&self, frame: ContactFrame, t_s: f64, y: &State) -> MeshSprings {
        self.springs(frame, t_s, &y.as_slice()[..NDOF], &y.as_slice()[NDOF..])
    }

    /// What an evaluation in `frame` at time t takes from the frame's decision time (see
    /// [`crate::geometry::GearPair::decided_set`]): evaluations at the same time and
    /// state whose keys and contact modes agree give the same result bit for bit.
    pub fn decided_set(&self, frame: ContactFrame, t_s: f64) -> (f64, usize) {
        let decide = self.phase_at(frame.decision_time_s.unwrap_or(t_s));
        self.parts.pair.decided_set(decide)
    }

    /// The contact mode the state is in at time t, the pairs decided as `frame` says
    /// (its own mode, if it holds one, is ignored).
    pub fn natural_mode_in(&self, frame: ContactFrame, t_s: f64, y: &State) -> ContactMode {
        let natural = ContactFrame {
            mode: None,
            ..frame
        };
        ContactMode::of(&self.springs_of(natural, t_s, y))
    }

    /// The contact mode the state is in at time t.
    pub fn natural_mode(&self, t_s: f64, y: &State) -> ContactMode {
        ContactMode::of(&self.springs_of(ContactFrame::NATURAL, t_s, y))
    }

    /// As [`GearSystem::natural_mode`] with the pairs in contact decided at `decide_s`
    /// (e.g. just after a mesh event).
    pub fn natural_mode_decided(&self, t_s: f64, decide_s: f64, y: &State) -> ContactMode {
        ContactMode::of(&self.springs_of(ContactFrame::decided_at(decide_s), t_s, y))
    }

    /// The switching functions of `mode` at (t, y), the pairs in contact decided at
    /// `decide_s`.
    pub fn mode_switch(&self, mode: ContactMode, t_s: f64, decide_s: f64, y: &State) -> ModeSwitch {
        let sp = self.springs_of(ContactFrame::frozen(decide_s, mode), t_s, y);
        let mut s = ModeSwitch::default();
        for i in 0..sp.n_pairs {
            let c = sp.compression_m[i];
            s.active[i] = true;
            s.inclusive[i] = mode.touches(i);
            s.margin[i] = if mode.touches(i) { c } else { -c };
        }
        if mode.in_contact() {
            let f = sp.force_unclipped_n;
            s.active[FORCE_SWITCH] = true;
            s.inclusive[FORCE_SWITCH] = mode.pushing;
            s.margin[FORCE_SWITCH] = if mode.pushing { f } else { -f };
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::Case;
    use crate::dynamics::excitation::{ExternalError, PairGap};
    use crate::study::Model;

    #[test]
    fn switches_sit_where_compression_and_force_change_sign() {
        let m = Model::from_case(&Case::default()).unwrap();
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.2);
        let mut y = sys.static_equilibrium();
        let t = 0.3 * m.pair.mesh_angle_rad() / m.params.operating.pinion_speed_rad_s;
        // Loaded at rest: every pair in contact touches and the mesh pushes.
        let mode = sys.natural_mode(t, &y);
        assert!(mode.touches(0) && mode.pushing);
        assert!(!sys.mode_switch(mode, t, t, &y).any_crossed());
        // Pull the gear away along the line of action (rigidly, so only the mesh
        // deflection changes) until the single pair opens: its switch is crossed,
        // and the natural mode is "no contact".
        let delta = sys
            .mesh_gradient()
            .dot(&y.fixed_rows::<NDOF>(0).into_owned());
        y[super::super::dof::XG] += 2.0 * delta / sys.mesh_gradient()[super::super::dof::XP];
        let open = sys.mode_switch(mode, t, t, &y);
        assert!(open.crossed(0) && open.margin(0) < 0.0);
        let natural = sys.natural_mode(t, &y);
        assert!(!natural.in_contact() && !natural.pushing);
        assert!(!sys.mode_switch(natural, t, t, &y).any_crossed());
    }
}
