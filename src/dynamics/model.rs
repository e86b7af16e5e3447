//! The 8-DOF translational-rotational tribo-dynamic model, paper eq. (1)-(6), with the
//! corrections of `docs/MODEL.md`.
//!
//! Coordinates (generalised displacements q, SI):
//! `[x_p, y_p, x_g, y_g, phi_m, phi_p, phi_g, phi_b]`, where the angles are deviations
//! from the nominal rotation: theta_m = Omega_p t + phi_m, theta_p = Omega_p t + phi_p,
//! theta_g = Omega_g t + phi_g, theta_b = Omega_g t + phi_b, Omega_g = Omega_p z1/z2.
//! Working with deviations keeps the mesh deflection a difference of small numbers
//! (r_pb theta_p - r_gb theta_g loses ~10 digits after a few seconds otherwise).
//! State y = [q; dq/dt] (16 entries).
//!
//! Layout: pinion centre at the origin, gear centre on +x. The line of action points
//! along d = (sin phi, cos phi) (phi the operating pressure angle, as in eq. 1), the
//! pinion's surface velocity at the contact along -e with e = (cos phi, -sin phi).
//! Mesh deflection (eq. 2 bracket without e_t):
//!   delta = r_pb phi_p - r_gb phi_g + (x_p - x_g) sin phi + (y_p - y_g) cos phi.
//! Forces on the pinion: -F d (mesh), +sum f_i e (friction); on the gear the opposite.
//! Friction f_i = mu_i W_i tanh(u_s,i / v_s) (eq. 6) with u_s = u_p - u_g (eq. 5), so the
//! friction power -sum f_i u_s,i is never positive. Torques: pinion -r_pb F - sum rho1_i f_i,
//! gear +r_gb F + sum rho2_i f_i (eq. 3-4, radii of curvature as lever arms).

use super::assembly::elements::Elements;
use super::assembly::Assembly;
use super::drive::Drive;
use super::excitation::{ExternalError, PairGap};
use super::params::DynamicParams;
use super::tooth_mesh::ToothMesh;
use crate::config::case::{LoadSharingModel, SpeedBoundary};
use crate::contact::friction::{Friction, XuConstants};
use crate::contact::hertz::HertzContact;
use crate::contact::kinematics::SurfaceKinematics;
use crate::contact::load_sharing::pedrero_shares;
use crate::geometry::GearPair;
use crate::stiffness::mesh::MeshStiffness;
use nalgebra::{SMatrix, SVector};

mod contact_mode;
mod linear;
pub use contact_mode::{ContactFrame, ContactMode, ModeSwitch, FORCE_SWITCH, SWITCHES};

/// Number of generalised coordinates.
pub const NDOF: usize = 8;
/// Number of first-order states.
pub const NSTATE: usize = 16;
/// Largest number of pairs in contact handled (contact ratio < 4).
pub const MAX_PAIRS: usize = 4;

pub type State = SVector<f64, NSTATE>;
pub type Matrix8 = SMatrix<f64, NDOF, NDOF>;

/// Index of each coordinate in q.
pub mod dof {
    pub const XP: usize = 0;
    pub const YP: usize = 1;
    pub const XG: usize = 2;
    pub const YG: usize = 3;
    pub const PHI_M: usize = 4;
    pub const PHI_P: usize = 5;
    pub const PHI_G: usize = 6;
    pub const PHI_B: usize = 7;
}

/// Everything the mesh does at one instant (for the right-hand side and for signals).
#[derive(Debug, Clone, Copy, Default)]
pub struct MeshState {
    pub n_pairs: usize,
    /// Pair contact positions rho1, m.
    pub rho1_m: [f64; MAX_PAIRS],
    pub stiffness_n_per_m: [f64; MAX_PAIRS],
    /// Share of the mesh force, kappa_i (eq. 7 or by stiffness).
    pub share: [f64; MAX_PAIRS],
    pub load_n: [f64; MAX_PAIRS],
    pub pressure_pa: [f64; MAX_PAIRS],
    pub half_width_m: [f64; MAX_PAIRS],
    pub friction_coefficient: [f64; MAX_PAIRS],
    /// Signed friction force f_i, N (positive when the pinion surface is faster).
    pub friction_n: [f64; MAX_PAIRS],
    /// Sliding velocity u_p - u_g, m/s.
    pub sliding_m_per_s: [f64; MAX_PAIRS],
    /// Mesh force F, N (>= 0).
    pub force_n: f64,
    /// Relative displacement along the line of action (dynamic transmission error), m.
    pub deflection_m: f64,
    /// Sum of the stiffnesses of the pairs in contact, N/m.
    pub stiffness_total_n_per_m: f64,
    /// Sum of the stiffnesses of the pairs actually touching (gap closed), N/m.
    pub stiffness_touching_n_per_m: f64,
    /// Compression of each pair, delta - g_i (m; > 0: the gap is closed).
    pub compression_m: [f64; MAX_PAIRS],
    /// Spring and damper force of the touching pairs before the mesh-cannot-pull limit,
    /// N (0 when none touches): F = this when it is positive.
    pub force_unclipped_n: f64,
    /// Whether the mesh pushes (F given by its springs and damper) or not (F = 0).
    pub pushing: bool,
    /// Mesh cycle of each pair (tooth-resolved mesh only; 0 otherwise).
    pub cycle: [i64; MAX_PAIRS],
    /// Share of the face width missing from each pair's contact line (a spall).
    pub width_loss: [f64; MAX_PAIRS],
    /// Change of each pair's Hertz 1/R by its flanks' wear, 1/m (severe wear).
    pub curvature_change: [f64; MAX_PAIRS],
}

/// The elastic part of the mesh at one instant ([`GearSystem::springs`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct MeshSprings {
    pub n_pairs: usize,
    /// Pair contact positions rho1, m.
    pub rho1_m: [f64; MAX_PAIRS],
    pub stiffness_n_per_m: [f64; MAX_PAIRS],
    /// delta - g_i, m.
    pub compression_m: [f64; MAX_PAIRS],
    /// Pairs counted as touching (gap closed, or as the frozen contact mode says).
    pub touching: [bool; MAX_PAIRS],
    pub stiffness_touching_n_per_m: f64,
    /// sum of k_i (delta - g_i) over the touching pairs, N.
    pub elastic_n: f64,
    /// Spring and damper force of the touching pairs, N (0 when none touches).
    pub force_unclipped_n: f64,
    pub pushing: bool,
    /// delta and d delta / dt (m, m/s).
    pub deflection_m: f64,
    pub deflection_rate_m_per_s: f64,
    /// Mesh cycle of each pair and the share of its face width lost (tooth-resolved).
    pub cycle: [i64; MAX_PAIRS],
    pub width_loss: [f64; MAX_PAIRS],
    pub curvature_change: [f64; MAX_PAIRS],
}

/// The inputs a [`GearSystem`] is assembled from (borrowed model objects and the
/// values of one evaluation).
#[derive(Clone, Copy)]
pub struct GearSystemParts<'a> {
    pub pair: &'a GearPair,
    pub mesh: &'a MeshStiffness,
    pub params: &'a DynamicParams,
    pub friction: &'a Friction,
    /// Lubricant inlet viscosity for the friction law, cP.
    pub viscosity_cp: f64,
    pub gap: &'a PairGap,
    pub external: &'a ExternalError,
    pub load_sharing: LoadSharingModel,
    /// Composite RMS roughness for the friction law, um.
    pub roughness_um: f64,
    /// Effective modulus E* of the contact, Pa.
    pub effective_modulus_pa: f64,
    /// The tooth-resolved mesh, when the teeth differ or are modified (None: every tooth
    /// the paper's, with `gap`).
    pub teeth: Option<&'a ToothMesh>,
}

/// Effective radius (m) of a contact whose flanks' curvature changed by `dk` (1/m) from
/// the involutes' 1/rho1 + 1/rho2 (severe wear, `contact::worn_curvature`). A worn flank
/// that turns conformal has no Hertz line contact: 1/R is kept at least a tenth of the
/// involutes' (the radius at most ten times theirs; docs/MODEL.md, section 9).
fn worn_radius(rho1: f64, rho2: f64, dk: f64) -> f64 {
    let k0 = 1.0 / rho1 + 1.0 / rho2;
    1.0 / (k0 + dk).max(0.1 * k0)
}

/// The assembled model: immutable inputs for one dynamic evaluation. It holds no
/// evaluation state: how the contact is decided travels with each call as a
/// [`ContactFrame`], so one system may be shared between threads.
pub struct GearSystem<'a> {
    /// What the system was assembled from.
    pub parts: GearSystemParts<'a>,
    /// Mesh damping c_m, N s/m.
    pub mesh_damping_n_s_per_m: f64,
    inv_mass: [f64; NDOF],
    k_lin: Matrix8,
    c_lin: Matrix8,
    /// d delta / d q.
    grad: SVector<f64, NDOF>,
    /// Constant generalised forces (motor and brake torques).
    q_ext: SVector<f64, NDOF>,
    /// sin and cos of the operating pressure angle.
    sin_cos_phi: (f64, f64),
    /// The friction law's terms of the viscosity and roughness (constant here).
    xu: XuConstants,
    /// A time-varying nominal speed and load (transient simulations), or None for the
    /// constant operating point of `params`.
    drive: Option<&'a Drive>,
}

// The system is shared read-only (e.g. by parallel studies): it must stay Send + Sync.
const _: () = {
    const fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<GearSystem<'static>>();
};

impl<'a> GearSystem<'a> {
    pub fn new(mut parts: GearSystemParts<'a>) -> Self {
        // `Auto` becomes the law this mesh uses, once (config::case::LoadSharingModel).
        parts.load_sharing = parts
            .load_sharing
            .resolve(parts.teeth.is_some(), parts.pair.contact_ratio);
        let GearSystemParts {
            pair, mesh, params, ..
        } = parts;
        let asm = Assembly::new(Elements::single_pair(params, pair))
            .expect("the single pair is a connected train");
        let geometry = &asm.meshes()[0];
        let [sx, co] = geometry.line_of_action;
        let c_m = params.mesh_damping_n_s_per_m(pair, mesh.mean_stiffness_n_per_m());
        let xu = XuConstants::new(parts.viscosity_cp, parts.roughness_um);
        Self {
            parts,
            mesh_damping_n_s_per_m: c_m,
            inv_mass: std::array::from_fn(|i| asm.inverse_masses()[i]),
            k_lin: Matrix8::from_fn(|i, j| asm.stiffness()[(i, j)]),
            c_lin: Matrix8::from_fn(|i, j| asm.damping()[(i, j)]),
            grad: SVector::from_fn(|i, _| asm.mesh_gradient(0)[i]),
            q_ext: SVector::from_fn(|i, _| asm.external_forces()[i]),
            sin_cos_phi: (sx, co),
            xu,
            drive: None,
        }
    }

    /// The same system driven by `drive` (`dynamics::drive`): nominal speed ramp and load
    /// fluctuation. The steady-state solvers use systems without a drive.
    pub fn with_drive(mut self, drive: &'a Drive) -> Self {
        self.drive = Some(drive);
        self
    }

    /// Run-out of a tooth-resolved mesh at time t (`ToothMesh::runout_at`, which follows
    /// the constant operating speed): under a drive, at the time the constant speed
    /// reaches the drive's angle, its rate scaled by the drive's speed.
    fn runout_at(&self, tm: &ToothMesh, t_s: f64) -> (f64, f64) {
        match self.drive {
            None => tm.runout_at(t_s),
            Some(d) => {
                let w = self.parts.params.operating.pinion_speed_rad_s;
                let (e, de) = tm.runout_at(d.angle(t_s) / w);
                (e, de * d.speed(t_s) / w)
            }
        }
    }

    /// Nominal pinion and gear speeds at time t, rad/s.
    #[inline]
    pub fn nominal_speeds(&self, t_s: f64) -> (f64, f64) {
        let p = self.parts.params;
        match self.drive {
            Some(d) => {
                let w = d.speed(t_s);
                (
                    w,
                    w * p.operating.gear_speed_rad_s / p.operating.pinion_speed_rad_s,
                )
            }
            None => (p.operating.pinion_speed_rad_s, p.operating.gear_speed_rad_s),
        }
    }

    /// d delta / dq: the mesh direction in generalised coordinates.
    pub fn mesh_gradient(&self) -> &SVector<f64, NDOF> {
        &self.grad
    }

    /// Linear (bearing, coupling) stiffness and damping matrices and inverse masses.
    pub fn linear_parts(&self) -> (&Matrix8, &Matrix8, &[f64; NDOF]) {
        (&self.k_lin, &self.c_lin, &self.inv_mass)
    }

    /// Constant generalised forces (motor/brake torques).
    pub fn external_forces(&self) -> &SVector<f64, NDOF> {
        &self.q_ext
    }

    /// Mesh phase (rad of pinion rotation) at time t: the nominal rotation Omega_p t.
    ///
    /// The stiffness and contact positions follow the nominal angle; the vibratory part
    /// phi_p (~1e-5 rad against a 0.33 rad mesh period) is neglected there, the standard
    /// time-varying-stiffness approximation (docs/MODEL.md).
    #[inline]
    pub fn phase_at(&self, t_s: f64) -> f64 {
        match self.drive {
            Some(d) => d.angle(t_s),
            None => self.parts.params.operating.pinion_speed_rad_s * t_s,
        }
    }

    /// The pairs in contact at time t and the force of their springs and damper, for
    /// generalised displacements q and velocities v (paper eq. 2 with the wear gaps and
    /// the external error): what decides the contact mode and the mesh force. The pairs
    /// and the mode are decided as `frame` says.
    pub fn springs(&self, frame: ContactFrame, t_s: f64, q: &[f64], v: &[f64]) -> MeshSprings {
        let mut sp = MeshSprings::default();
        for i in 0..NDOF {
            sp.deflection_m += self.grad[i] * q[i];
            sp.deflection_rate_m_per_s += self.grad[i] * v[i];
        }
        if let Some(tm) = self.parts.teeth {
            return self.springs_resolved(tm, frame, t_s, sp);
        }
        let phase = self.phase_at(t_s);
        let omega_nom = self.nominal_speeds(t_s).0;
        let rb1 = self.parts.pair.pinion.base_radius_m;
        let (e_ext, de_ext) = self.parts.external.at(phase);
        let frozen = frame.mode;
        let decide = frame.decision_time_s.map_or(phase, |t| self.phase_at(t));
        let mut gap_rate_weighted = 0.0;
        for (_, rho1) in self.parts.pair.pairs_in_contact_decided(phase, decide) {
            let n = sp.n_pairs;
            if n == MAX_PAIRS {
                break;
            }
            let k = self.parts.mesh.pair_stiffness_n_per_m(rho1);
            let (g_wear, dg_drho) = self.parts.gap.at(rho1);
            // Effective gap of this pair: wear gap minus the external error (eq. 2 sign).
            let gap = g_wear - e_ext;
            let c = sp.deflection_m - gap;
            sp.rho1_m[n] = rho1;
            sp.stiffness_n_per_m[n] = k;
            sp.compression_m[n] = c;
            if frozen.map_or(c > 0.0, |m| m.touches(n)) {
                sp.touching[n] = true;
                sp.elastic_n += k * c;
                sp.stiffness_touching_n_per_m += k;
                gap_rate_weighted += k * (dg_drho * rb1 * omega_nom - de_ext * omega_nom);
            }
            sp.n_pairs += 1;
        }
        self.close_springs(sp, gap_rate_weighted, frozen)
    }

    /// The force of the touching pairs' springs and damper and whether the mesh pushes,
    /// given their stiffness-weighted gap rate (N/s).
    fn close_springs(
        &self,
        mut sp: MeshSprings,
        gap_rate_weighted: f64,
        frozen: Option<ContactMode>,
    ) -> MeshSprings {
        // Mesh damping acts on the closing rate of the touching pairs (eq. 2, c_m term
        // with de_t/dt); the mesh cannot pull: F >= 0 (contact loss). Within a step of
        // frozen mode the laws continue smoothly past their switches (F may go slightly
        // negative) until the step is cut at the switch (docs/MODEL.md, section 4).
        let k_touch = sp.stiffness_touching_n_per_m;
        if k_touch > 0.0 {
            let closing = sp.deflection_rate_m_per_s - gap_rate_weighted / k_touch;
            sp.force_unclipped_n = sp.elastic_n + self.mesh_damping_n_s_per_m * closing;
        }
        sp.pushing = k_touch > 0.0 && frozen.map_or(sp.force_unclipped_n > 0.0, |m| m.pushing);
        sp
    }

    /// [`GearSystem::springs`] of a tooth-resolved mesh: each pair's teeth from its mesh
    /// cycle (`dynamics::tooth_mesh`), the run-out common to all pairs.
    fn springs_resolved(
        &self,
        tm: &ToothMesh,
        frame: ContactFrame,
        t_s: f64,
        mut sp: MeshSprings,
    ) -> MeshSprings {
        let phase = self.phase_at(t_s);
        let omega_nom = self.nominal_speeds(t_s).0;
        let rb1 = self.parts.pair.pinion.base_radius_m;
        let (e_ext, de_ext) = self.parts.external.at(phase);
        let (e_run, de_run) = self.runout_at(tm, t_s);
        let frozen = frame.mode;
        let decide = frame.decision_time_s.map_or(phase, |t| self.phase_at(t));
        let cycle_now = self.parts.pair.mesh_cycle(decide);
        let mut gap_rate_weighted = 0.0;
        for (k, rho1) in self.parts.pair.pairs_in_contact_decided(phase, decide) {
            let n = sp.n_pairs;
            if n == MAX_PAIRS {
                break;
            }
            let cycle = cycle_now - k as i64;
            let pp = tm.pair(self.parts.mesh, cycle, rho1);
            let gap = pp.gap_m - e_ext - e_run;
            let c = sp.deflection_m - gap;
            sp.rho1_m[n] = rho1;
            sp.stiffness_n_per_m[n] = pp.stiffness_n_per_m;
            sp.compression_m[n] = c;
            sp.cycle[n] = cycle;
            sp.width_loss[n] = pp.width_loss;
            sp.curvature_change[n] = pp.curvature_change_per_m;
            if frozen.map_or(c > 0.0, |m| m.touches(n)) {
                let k = pp.stiffness_n_per_m;
                sp.touching[n] = true;
                sp.elastic_n += k * c;
                sp.stiffness_touching_n_per_m += k;
                gap_rate_weighted +=
                    k * (pp.gap_slope * rb1 * omega_nom - de_ext * omega_nom - de_run);
            }
            sp.n_pairs += 1;
        }
        self.close_springs(sp, gap_rate_weighted, frozen)
    }

    /// Mesh state at time t for generalised displacements q and velocities v, the
    /// contact decided as `frame` says.
    pub fn mesh_state(&self, frame: ContactFrame, t_s: f64, q: &[f64], v: &[f64]) -> MeshState {
        use dof::*;
        let sp = self.springs(frame, t_s, q, v);
        let n = sp.n_pairs;
        let mut ms = MeshState {
            n_pairs: n,
            rho1_m: sp.rho1_m,
            stiffness_n_per_m: sp.stiffness_n_per_m,
            deflection_m: sp.deflection_m,
            stiffness_total_n_per_m: sp.stiffness_n_per_m[..n].iter().sum(),
            stiffness_touching_n_per_m: sp.stiffness_touching_n_per_m,
            compression_m: sp.compression_m,
            force_unclipped_n: sp.force_unclipped_n,
            pushing: sp.pushing,
            force_n: if sp.pushing {
                sp.force_unclipped_n
            } else {
                0.0
            },
            cycle: sp.cycle,
            width_loss: sp.width_loss,
            curvature_change: sp.curvature_change,
            ..MeshState::default()
        };
        let (nominal_p, nominal_g) = self.nominal_speeds(t_s);
        let omega_p = nominal_p + v[PHI_P];
        let omega_g = nominal_g + v[PHI_G];
        let stiffness_shares = (sp.elastic_n > 0.0).then(|| {
            let mut sh = [0.0; MAX_PAIRS];
            for i in (0..n).filter(|i| sp.touching[*i]) {
                sh[i] = sp.stiffness_n_per_m[i] * sp.compression_m[i] / sp.elastic_n;
            }
            sh
        });
        self.fill_contacts(&mut ms, stiffness_shares, omega_p, omega_g);
        ms
    }

    /// Per-pair shares, loads, Hertz contact and friction for a mesh state whose pairs
    /// (`rho1_m`, `n_pairs`) and force are set. `stiffness_shares` are the shares by
    /// pair compression (used by `LoadSharingModel::Stiffness`); `omega_*` the actual
    /// pinion and gear speeds, rad/s (eq. 5).
    pub fn fill_contacts(
        &self,
        ms: &mut MeshState,
        stiffness_shares: Option<[f64; MAX_PAIRS]>,
        omega_p: f64,
        omega_g: f64,
    ) {
        let n = ms.n_pairs;
        match self.parts.load_sharing {
            // By the contact set decided (pairs ordered from the last to enter).
            LoadSharingModel::Pedrero => {
                pedrero_shares(self.parts.pair, &ms.rho1_m[..n], &mut ms.share[..n])
            }
            // `Auto` was resolved in `GearSystem::new` and never reaches here.
            LoadSharingModel::Stiffness | LoadSharingModel::Auto => {
                ms.share[..n].copy_from_slice(&stiffness_shares.unwrap_or_default()[..n])
            }
        }
        for i in 0..n {
            // A pair load below zero exists only inside a step whose frozen contact mode
            // is about to switch; the contact and friction see no load then.
            let w = (ms.share[i] * ms.force_n).max(0.0);
            ms.load_n[i] = w;
            let rho1 = ms.rho1_m[i];
            let rho2 = self.parts.pair.rho_gear(rho1);
            let width = self.parts.pair.face_width_m * (1.0 - ms.width_loss[i]);
            let e_star = self.parts.effective_modulus_pa;
            let hz = match ms.curvature_change[i] {
                0.0 => HertzContact::with_modulus(w, width, rho1, rho2, e_star),
                dk => HertzContact::with_radius(w, width, worn_radius(rho1, rho2, dk), e_star),
            };
            ms.pressure_pa[i] = hz.max_pressure_pa;
            ms.half_width_m[i] = hz.half_width_m;
            let kin = SurfaceKinematics::new(omega_p, omega_g, rho1, rho2);
            let u_s = kin.sliding_velocity_m_per_s();
            ms.sliding_m_per_s[i] = u_s;
            let mu = self.parts.friction.coefficient_with(&hz, &kin, &self.xu);
            ms.friction_coefficient[i] = mu;
            // Positive when the pinion surface is faster; acts on the pinion along +e.
            ms.friction_n[i] = mu * w * self.parts.friction.direction(u_s);
        }
    }

    /// Generalised forces of the mesh (normal force and friction) for a mesh state.
    #[inline]
    pub fn mesh_forces(&self, ms: &MeshState) -> SVector<f64, NDOF> {
        use dof::*;
        let mut qf = -ms.force_n * self.grad;
        let (s, c) = self.sin_cos_phi;
        let mut f_sum = 0.0;
        let mut m_p = 0.0;
        let mut m_g = 0.0;
        for i in 0..ms.n_pairs {
            let f = ms.friction_n[i];
            f_sum += f;
            m_p += ms.rho1_m[i] * f;
            m_g += self.parts.pair.rho_gear(ms.rho1_m[i]) * f;
        }
        // Friction along e = (cos phi, -sin phi) on the pinion, opposite on the gear.
        qf[XP] += f_sum * c;
        qf[YP] -= f_sum * s;
        qf[XG] -= f_sum * c;
        qf[YG] += f_sum * s;
        qf[PHI_P] -= m_p;
        qf[PHI_G] += m_g;
        qf
    }

    /// Right-hand side dy/dt and the mesh state it used, the contact decided as `frame`
    /// says.
    pub fn derivative(&self, frame: ContactFrame, t_s: f64, y: &State) -> (State, MeshState) {
        let q = y.fixed_rows::<NDOF>(0).into_owned();
        let v = y.fixed_rows::<NDOF>(NDOF).into_owned();
        let ms = self.mesh_state(frame, t_s, q.as_slice(), v.as_slice());
        let rhs = self.q_ext + self.mesh_forces(&ms) - self.k_lin * q - self.c_lin * v;
        let mut dy = State::zeros();
        for i in 0..NDOF {
            dy[i] = v[i];
            dy[NDOF + i] = rhs[i] * self.inv_mass[i];
        }
        if let Some(d) = self.drive {
            self.add_drive(d, t_s, &mut dy);
        }
        (dy, ms)
    }

    /// The drive's terms in dy/dt (`dynamics::drive`): the nominal acceleration
    /// -d^2 Theta/dt^2 on every free angle, and the load fluctuation on the shaft where
    /// the load acts.
    fn add_drive(&self, d: &Drive, t_s: f64, dy: &mut State) {
        use dof::*;
        let p = self.parts.params;
        let ratio = p.operating.gear_speed_rad_s / p.operating.pinion_speed_rad_s;
        let a = d.accel(t_s);
        for (i, r) in [(PHI_M, 1.0), (PHI_P, 1.0), (PHI_G, ratio), (PHI_B, ratio)] {
            if self.inv_mass[i] > 0.0 {
                dy[NDOF + i] -= a * r;
            }
        }
        let dt = d.torque_at(t_s);
        if dt != 0.0 {
            if p.speed_boundary == SpeedBoundary::BrakeSpeedImposed {
                dy[NDOF + PHI_M] += dt * self.inv_mass[PHI_M];
            } else {
                dy[NDOF + PHI_B] -= dt * self.inv_mass[PHI_B];
            }
        }
    }
}
