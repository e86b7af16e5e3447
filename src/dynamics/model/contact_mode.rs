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
    /// Hold the contact mode fixed for the following evaluations (`None`: decide it
    /// from the state at each evaluation, as the physics does).
    pub fn set_contact_mode(&self, mode: Option<ContactMode>) {
        self.contact_mode.set(mode);
    }

    fn springs_in(&self, mode: Option<ContactMode>, t_s: f64, y: &State) -> MeshSprings {
        let saved = self.contact_mode.replace(mode);
        let sp = self.springs(t_s, &y.as_slice()[..NDOF], &y.as_slice()[NDOF..]);
        self.contact_mode.set(saved);
        sp
    }

    /// The contact mode the state is in at time t.
    pub fn natural_mode(&self, t_s: f64, y: &State) -> ContactMode {
        ContactMode::of(&self.springs_in(None, t_s, y))
    }

    /// As [`GearSystem::natural_mode`] with the pairs in contact decided at `decide_s`
    /// (e.g. just after a mesh event).
    pub fn natural_mode_decided(&self, t_s: f64, decide_s: f64, y: &State) -> ContactMode {
        let saved = self.contact_decision_time_s.replace(Some(decide_s));
        let m = self.natural_mode(t_s, y);
        self.contact_decision_time_s.set(saved);
        m
    }

    /// The switching functions of `mode` at (t, y).
    pub fn mode_switch(&self, mode: ContactMode, t_s: f64, y: &State) -> ModeSwitch {
        let sp = self.springs_in(Some(mode), t_s, y);
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
        let t = 0.3 * m.pair.mesh_angle_rad() / m.params.pinion_speed_rad_s;
        // Loaded at rest: every pair in contact touches and the mesh pushes.
        let mode = sys.natural_mode(t, &y);
        assert!(mode.touches(0) && mode.pushing);
        assert!(!sys.mode_switch(mode, t, &y).any_crossed());
        // Pull the gear away along the line of action (rigidly, so only the mesh
        // deflection changes) until the single pair opens: its switch is crossed,
        // and the natural mode is "no contact".
        let delta = sys
            .mesh_gradient()
            .dot(&y.fixed_rows::<NDOF>(0).into_owned());
        y[super::super::dof::XG] += 2.0 * delta / sys.mesh_gradient()[super::super::dof::XP];
        let open = sys.mode_switch(mode, t, &y);
        assert!(open.crossed(0) && open.margin(0) < 0.0);
        let natural = sys.natural_mode(t, &y);
        assert!(!natural.in_contact() && !natural.pushing);
        assert!(!sys.mode_switch(natural, t, &y).any_crossed());
    }
}
