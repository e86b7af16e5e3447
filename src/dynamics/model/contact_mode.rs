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
//! & Fuehrer, *Numerical Methods in Multibody Dynamics*, Sect. 6.2). In a train each mesh
//! has its own mode and switches; a step holds them all.

use super::{GearSystem, MeshSprings, MAX_MESHES, MAX_PAIRS};

/// Which pairs of one mesh touch and whether the mesh pushes (the branches of its force
/// law).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ContactMode {
    /// Pair i of the contact set (in the order of `GearPair::pairs_in_contact`) touches.
    touching: [bool; MAX_PAIRS],
    /// The mesh force is its springs and damper (else 0).
    pub pushing: bool,
}

impl ContactMode {
    /// Whether pair `pair` of the contact set touches.
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

/// The contact mode of every mesh of a train (the first `n` entries are its meshes').
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ContactModes {
    modes: [ContactMode; MAX_MESHES],
    n: usize,
}

impl ContactModes {
    /// The modes of `n` meshes, from each mesh's.
    pub fn from_fn(n: usize, mut mode: impl FnMut(usize) -> ContactMode) -> Self {
        let mut modes = [ContactMode::default(); MAX_MESHES];
        for (m, slot) in modes.iter_mut().enumerate().take(n) {
            *slot = mode(m);
        }
        Self { modes, n }
    }

    /// Mesh `m`'s mode.
    pub fn mesh(&self, m: usize) -> ContactMode {
        self.modes[m]
    }

    /// Number of meshes.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether there are no meshes.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }
}

/// How one evaluation of the right-hand side decides the contact: the time at which the
/// sets of pairs in contact are decided, and the contact modes held fixed, if any. The
/// integrator's problem adaptor carries it for each trial step (decided at the step's
/// middle, so no stage of a step straddles a mesh event, and the step's modes frozen);
/// observers build their own. A value passed with each call, never state of the model.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactFrame {
    /// Time at which the pairs in contact are decided, s; None: the evaluation time.
    pub decision_time_s: Option<f64>,
    /// The contact modes held fixed; None: decided from the state at each evaluation,
    /// as the physics does.
    pub mode: Option<ContactModes>,
}

/// [`ContactFrame`] as one mesh sees it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MeshFrame {
    /// Time at which the pairs in contact are decided, s; None: the evaluation time.
    pub decision_time_s: Option<f64>,
    /// This mesh's contact mode held fixed; None: decided from the state.
    pub mode: Option<ContactMode>,
}

impl ContactFrame {
    /// Everything decided at the evaluation itself (time and state).
    pub const NATURAL: Self = Self {
        decision_time_s: None,
        mode: None,
    };

    /// The pairs in contact decided at `decide_s` (e.g. just after a mesh event), the
    /// modes from the state.
    pub fn decided_at(decide_s: f64) -> Self {
        Self {
            decision_time_s: Some(decide_s),
            mode: None,
        }
    }

    /// The pairs decided at `decide_s` and the contact modes held at `mode` (a step of
    /// the integrator).
    pub fn frozen(decide_s: f64, mode: ContactModes) -> Self {
        Self {
            decision_time_s: Some(decide_s),
            mode: Some(mode),
        }
    }

    /// What mesh `m` takes from the frame.
    #[inline]
    pub fn mesh(&self, m: usize) -> MeshFrame {
        MeshFrame {
            decision_time_s: self.decision_time_s,
            mode: self.mode.map(|modes| modes.mesh(m)),
        }
    }
}

/// Number of switching functions per mesh: one per pair (its compression) and the mesh
/// force.
pub const SWITCHES: usize = MAX_PAIRS + 1;

/// Index of the mesh-force switch among a mesh's switching functions.
pub const FORCE_SWITCH: usize = MAX_PAIRS;

/// The switching functions of the contact modes at one state: [`SWITCHES`] per mesh,
/// mesh m's switch j at index `m * SWITCHES + j`.
#[derive(Debug, Clone, Copy)]
pub struct ModeSwitch {
    /// Positive on the mode's own side: a pair's compression (m) with the sign that is
    /// positive while the pair stays as the mode says; the mesh force (N) likewise.
    margin: [f64; MAX_MESHES * SWITCHES],
    /// The function applies (an existing pair; the force only when a pair touches).
    active: [bool; MAX_MESHES * SWITCHES],
    /// Zero counts as crossed (the touching/pushing side is the open one, > 0).
    inclusive: [bool; MAX_MESHES * SWITCHES],
    /// Number of switching functions (`SWITCHES` per mesh).
    n: usize,
}

impl ModeSwitch {
    /// Switching function `j` (see the `margin` field's docs), units m for a pair, N for
    /// a mesh's [`FORCE_SWITCH`]; 0 for an inactive one.
    pub fn margin(&self, j: usize) -> f64 {
        self.margin[j]
    }

    /// Number of switching functions.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether there are no switching functions.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Whether the state has left the mode through switch `j`.
    pub fn crossed(&self, j: usize) -> bool {
        let m = self.margin[j];
        self.active[j] && (m < 0.0 || (self.inclusive[j] && m == 0.0))
    }

    /// Whether the state has left the mode through any switch.
    pub fn any_crossed(&self) -> bool {
        (0..self.n).any(|j| self.crossed(j))
    }
}

/// The sets of pairs in contact of every mesh as decided at some time
/// (`GearPair::decided_set_in`): evaluations whose sets and modes agree give the same
/// result bit for bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DecidedSets {
    sets: [(f64, usize); MAX_MESHES],
    n: usize,
}

impl DecidedSets {
    /// Equal bit for bit (the phases compared as bits).
    pub fn same_as(&self, other: &Self) -> bool {
        self.n == other.n
            && self.sets[..self.n]
                .iter()
                .zip(&other.sets[..self.n])
                .all(|(a, b)| a.0.to_bits() == b.0.to_bits() && a.1 == b.1)
    }
}

impl GearSystem<'_> {
    fn springs_of(&self, m: usize, frame: ContactFrame, t_s: f64, y: &[f64]) -> MeshSprings {
        let (q, v) = y.split_at(self.dofs());
        self.meshes[m].springs(frame.mesh(m), t_s, q, v)
    }

    /// What an evaluation in `frame` at time t takes from the frame's decision time (see
    /// [`crate::geometry::GearPair::decided_set_in`]), for every mesh.
    pub fn decided_sets(&self, frame: ContactFrame, t_s: f64) -> DecidedSets {
        let t = frame.decision_time_s.unwrap_or(t_s);
        let mut sets = [(0.0, 0); MAX_MESHES];
        for (m, mesh) in self.meshes.iter().enumerate() {
            let reach = mesh.parts.contact.reach();
            sets[m] = mesh.parts.pair.decided_set_in(reach, mesh.phase_at(t));
        }
        DecidedSets {
            sets,
            n: self.meshes.len(),
        }
    }

    /// The contact modes the state is in at time t, the pairs decided as `frame` says
    /// (its own modes, if it holds them, are ignored).
    pub fn natural_mode_in(&self, frame: ContactFrame, t_s: f64, y: &[f64]) -> ContactModes {
        let natural = ContactFrame {
            mode: None,
            ..frame
        };
        ContactModes::from_fn(self.meshes.len(), |m| {
            ContactMode::of(&self.springs_of(m, natural, t_s, y))
        })
    }

    /// The contact modes the state is in at time t.
    pub fn natural_mode(&self, t_s: f64, y: &[f64]) -> ContactModes {
        self.natural_mode_in(ContactFrame::NATURAL, t_s, y)
    }

    /// As [`GearSystem::natural_mode`] with the pairs in contact decided at `decide_s`
    /// (e.g. just after a mesh event).
    pub fn natural_mode_decided(&self, t_s: f64, decide_s: f64, y: &[f64]) -> ContactModes {
        self.natural_mode_in(ContactFrame::decided_at(decide_s), t_s, y)
    }

    /// The switching functions of `mode` at (t, y), the pairs in contact decided at
    /// `decide_s`.
    pub fn mode_switch(
        &self,
        mode: ContactModes,
        t_s: f64,
        decide_s: f64,
        y: &[f64],
    ) -> ModeSwitch {
        let frame = ContactFrame::frozen(decide_s, mode);
        let n = self.meshes.len() * SWITCHES;
        let mut s = ModeSwitch {
            margin: [0.0; MAX_MESHES * SWITCHES],
            active: [false; MAX_MESHES * SWITCHES],
            inclusive: [false; MAX_MESHES * SWITCHES],
            n,
        };
        for m in 0..self.meshes.len() {
            let sp = self.springs_of(m, frame, t_s, y);
            let mode = mode.mesh(m);
            let base = m * SWITCHES;
            for i in 0..sp.n_pairs {
                let c = sp.compression_m[i];
                s.active[base + i] = true;
                s.inclusive[base + i] = mode.touches(i);
                s.margin[base + i] = if mode.touches(i) { c } else { -c };
            }
            if mode.in_contact() {
                let f = sp.force_unclipped_n;
                let j = base + FORCE_SWITCH;
                s.active[j] = true;
                s.inclusive[j] = mode.pushing;
                s.margin[j] = if mode.pushing { f } else { -f };
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use crate::config::case::Case;
    use crate::dynamics::excitation::{ExternalError, PairGap};
    use crate::dynamics::model::{dof, NDOF};
    use crate::study::Model;

    #[test]
    fn switches_sit_where_compression_and_force_change_sign() {
        let m = Model::from_case(&Case::default()).unwrap();
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.2);
        let mut y = sys.static_equilibrium();
        let t = 0.3 * m.pair.mesh_angle_rad() / m.params.operating.pinion_speed_rad_s;
        // Loaded at rest: every pair in contact touches and the mesh pushes.
        let mode = sys.natural_mode(t, y.as_slice());
        assert!(mode.mesh(0).touches(0) && mode.mesh(0).pushing);
        assert!(!sys.mode_switch(mode, t, t, y.as_slice()).any_crossed());
        // Pull the gear away along the line of action (rigidly, so only the mesh
        // deflection changes) until the single pair opens: its switch is crossed,
        // and the natural mode is "no contact".
        let g = sys.mesh_gradient(0);
        let delta = g.dot(&y.rows(0, NDOF));
        y[dof::XG] += 2.0 * delta / g[dof::XP];
        let open = sys.mode_switch(mode, t, t, y.as_slice());
        assert!(open.crossed(0) && open.margin(0) < 0.0);
        let natural = sys.natural_mode(t, y.as_slice());
        assert!(!natural.mesh(0).in_contact() && !natural.mesh(0).pushing);
        assert!(!sys.mode_switch(natural, t, t, y.as_slice()).any_crossed());
    }
}
