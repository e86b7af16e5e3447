//! The tribo-dynamic model of a gear train: the assembled linear parts
//! (`dynamics::assembly`) and, per mesh, the time-varying, nonlinear mesh force of paper
//! eq. (1)-(6) with the corrections of `docs/MODEL.md`. The paper's 8-DOF pair is the
//! smallest train (`GearSystem::new`).
//!
//! Coordinates (generalised displacements q, SI) are numbered by the assembly; for the
//! single pair `[x_p, y_p, x_g, y_g, phi_m, phi_p, phi_g, phi_b]` ([`dof`]). The angles are
//! deviations from the nominal rotation: theta_b = Omega_b t + phi_b for every body b,
//! Omega_b its nominal speed (the operating point). Working with deviations keeps the
//! mesh deflection a difference of small numbers (r_pb theta_p - r_gb theta_g loses ~10
//! digits after a few seconds otherwise). State y = [q; dq/dt].
//!
//! Per mesh (single pair: pinion centre at the origin, gear centre on +x), the line of
//! action points along d = (sin phi, cos phi) (phi the operating pressure angle, as in
//! eq. 1), the pinion's surface velocity at the contact along -e with e = (cos phi,
//! -sin phi) (`assembly::MeshGeometry` for any layout and sense of rotation). Mesh
//! deflection (eq. 2 bracket without e_t):
//!   delta = r_pb phi_p - r_gb phi_g + (x_p - x_g) sin phi + (y_p - y_g) cos phi.
//! Forces on the pinion: -F d (mesh), +sum f_i e (friction); on the gear the opposite.
//! Friction f_i = mu_i W_i tanh(u_s,i / v_s) (eq. 6) with u_s = u_p - u_g (eq. 5), so the
//! friction power -sum f_i u_s,i is never positive. Torques: pinion -r_pb F - sum rho1_i f_i,
//! gear +r_gb F + sum rho2_i f_i (eq. 3-4, radii of curvature as lever arms).

use super::assembly::elements::Elements;
use super::assembly::Assembly;
use super::contact_path::ContactPath;
use super::drive::Drive;
use super::excitation::{ExternalError, PairGap};
use super::params::{mesh_damping_n_s_per_m, DynamicParams};
use super::tooth_mesh::ToothMesh;
use crate::config::case::LoadSharingModel;
use crate::contact::friction::{Friction, XuConstants};
use crate::geometry::GearPair;
use crate::stiffness::mesh::MeshStiffness;
use nalgebra::DVector;
use std::borrow::Cow;

mod contact_mode;
mod linear;
mod mesh;
mod rhs;
pub use contact_mode::{
    ContactFrame, ContactMode, ContactModes, DecidedSets, MeshFrame, ModeSwitch, FORCE_SWITCH,
    SWITCHES,
};
pub use mesh::TrainMesh;

/// Number of generalised coordinates of the single pair (the one-stage train).
pub const NDOF: usize = 8;
/// Number of first-order states of the single pair.
pub const NSTATE: usize = 16;
/// Largest number of pairs in contact handled per mesh (contact ratio < 4).
pub const MAX_PAIRS: usize = 4;
/// Largest number of meshes in one train (the case-file validation refuses more).
pub const MAX_MESHES: usize = 16;

/// A state y = [q; dq/dt] of an assembled train (SI).
pub type State = DVector<f64>;

/// Index of each coordinate of the single pair (`dynamics::assembly` numbers them:
/// laterals of pinion and gear, then the rotations of motor, pinion, gear and brake).
pub mod dof {
    /// Lateral displacement x of the pinion centre, m.
    pub const XP: usize = 0;
    /// Lateral displacement y of the pinion centre, m.
    pub const YP: usize = 1;
    /// Lateral displacement x of the gear centre, m.
    pub const XG: usize = 2;
    /// Lateral displacement y of the gear centre, m.
    pub const YG: usize = 3;
    /// Rotation deviation phi_m of the motor, rad.
    pub const PHI_M: usize = 4;
    /// Rotation deviation phi_p of the pinion, rad.
    pub const PHI_P: usize = 5;
    /// Rotation deviation phi_g of the gear, rad.
    pub const PHI_G: usize = 6;
    /// Rotation deviation phi_b of the brake, rad.
    pub const PHI_B: usize = 7;
}

/// Everything a mesh does at one instant (for the right-hand side and for signals).
#[derive(Debug, Clone, Copy, Default)]
pub struct MeshState {
    /// Number of pairs in contact (entries of the arrays past it are zero).
    pub n_pairs: usize,
    /// Pair contact positions rho1, m.
    pub rho1_m: [f64; MAX_PAIRS],
    /// Stiffness k_i of each pair at its contact position, N/m.
    pub stiffness_n_per_m: [f64; MAX_PAIRS],
    /// Share of the mesh force, kappa_i (eq. 7 or by stiffness).
    pub share: [f64; MAX_PAIRS],
    /// Load W_i = kappa_i F carried by each pair, N (never negative).
    pub load_n: [f64; MAX_PAIRS],
    /// Maximum Hertz contact pressure p_0 of each pair, Pa.
    pub pressure_pa: [f64; MAX_PAIRS],
    /// Hertz contact half-width a of each pair, m.
    pub half_width_m: [f64; MAX_PAIRS],
    /// Friction coefficient mu_i of each pair (the case's law: Xu et al., paper eq. 8, by
    /// default).
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
    /// Pairs touching (or standing off) by a tip corner beyond the path of contact
    /// (`dynamics::contact_path`); their `rho1_m` is the path's end they continue.
    pub corner: [bool; MAX_PAIRS],
}

/// The elastic part of a mesh at one instant ([`TrainMesh::springs`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct MeshSprings {
    /// Number of pairs in contact (entries of the arrays past it are unused).
    pub n_pairs: usize,
    /// Pair contact positions rho1, m.
    pub rho1_m: [f64; MAX_PAIRS],
    /// Stiffness k_i of each pair at its contact position, N/m.
    pub stiffness_n_per_m: [f64; MAX_PAIRS],
    /// delta - g_i, m.
    pub compression_m: [f64; MAX_PAIRS],
    /// Pairs counted as touching (gap closed, or as the frozen contact mode says).
    pub touching: [bool; MAX_PAIRS],
    /// Sum of the stiffnesses of the touching pairs, N/m.
    pub stiffness_touching_n_per_m: f64,
    /// sum of k_i (delta - g_i) over the touching pairs, N.
    pub elastic_n: f64,
    /// Spring and damper force of the touching pairs, N (0 when none touches).
    pub force_unclipped_n: f64,
    /// Whether the mesh pushes (F = `force_unclipped_n`) or not (F = 0).
    pub pushing: bool,
    /// delta and d delta / dt (m, m/s).
    pub deflection_m: f64,
    /// d delta / dt, m/s.
    pub deflection_rate_m_per_s: f64,
    /// Mesh cycle of each pair and the share of its face width lost (tooth-resolved).
    pub cycle: [i64; MAX_PAIRS],
    /// Share of the face width missing from each pair's contact line (a spall).
    pub width_loss: [f64; MAX_PAIRS],
    /// Change of each pair's Hertz 1/R by its flanks' wear, 1/m (severe wear).
    pub curvature_change: [f64; MAX_PAIRS],
    /// Pairs at a tip corner beyond the path of contact.
    pub corner: [bool; MAX_PAIRS],
}

/// What one mesh is made of: the pair, its stiffness, friction and contact, its wear
/// gaps, its external error and its teeth (borrowed model objects and the values of one
/// evaluation).
#[derive(Clone, Copy)]
pub struct MeshParts<'a> {
    /// The pair's geometry.
    pub pair: &'a GearPair,
    /// The pair's mesh stiffness along the path of contact.
    pub mesh: &'a MeshStiffness,
    /// The case's friction law (coefficient: Xu et al., paper eq. 8, by default; force
    /// mu W signed by the sliding, eq. 6).
    pub friction: &'a Friction,
    /// Lubricant inlet viscosity for the friction law, cP.
    pub viscosity_cp: f64,
    /// The gap each tooth pair closes before it carries load (wear), m along the line of
    /// action.
    pub gap: &'a PairGap,
    /// The external transmission error e(theta) (paper eq. 2).
    pub external: &'a ExternalError,
    /// How the mesh force is shared between the pairs in contact.
    pub load_sharing: LoadSharingModel,
    /// Composite RMS roughness for the friction law, um.
    pub roughness_um: f64,
    /// Effective modulus E* of the contact, Pa.
    pub effective_modulus_pa: f64,
    /// The tooth-resolved mesh, when the teeth differ or are modified (None: every tooth
    /// the paper's, with `gap`).
    pub teeth: Option<&'a ToothMesh>,
    /// Where the pairs touch: the path of contact, or beyond it by their tip corners.
    pub contact: &'a ContactPath,
}

/// The inputs a single pair's [`GearSystem`] is assembled from: its mesh's parts and the
/// lumped parameters and operating point of paper eq. (1).
#[derive(Clone, Copy)]
pub struct GearSystemParts<'a> {
    /// The pair's geometry.
    pub pair: &'a GearPair,
    /// The pair's mesh stiffness along the path of contact.
    pub mesh: &'a MeshStiffness,
    /// Lumped parameters and operating point (paper eq. 1).
    pub params: &'a DynamicParams,
    /// The case's friction law (coefficient: Xu et al., paper eq. 8, by default; force
    /// mu W signed by the sliding, eq. 6).
    pub friction: &'a Friction,
    /// Lubricant inlet viscosity for the friction law, cP.
    pub viscosity_cp: f64,
    /// The gap each tooth pair closes before it carries load (wear), m along the line of
    /// action.
    pub gap: &'a PairGap,
    /// The external transmission error e(theta) (paper eq. 2).
    pub external: &'a ExternalError,
    /// How the mesh force is shared between the pairs in contact.
    pub load_sharing: LoadSharingModel,
    /// Composite RMS roughness for the friction law, um.
    pub roughness_um: f64,
    /// Effective modulus E* of the contact, Pa.
    pub effective_modulus_pa: f64,
    /// The tooth-resolved mesh, when the teeth differ or are modified (None: every tooth
    /// the paper's, with `gap`).
    pub teeth: Option<&'a ToothMesh>,
    /// Where the pairs touch (`dynamics::contact_path`).
    pub contact: &'a ContactPath,
}

impl<'a> GearSystemParts<'a> {
    /// The mesh's share of the parts.
    pub fn mesh_parts(&self) -> MeshParts<'a> {
        MeshParts {
            pair: self.pair,
            mesh: self.mesh,
            friction: self.friction,
            viscosity_cp: self.viscosity_cp,
            gap: self.gap,
            external: self.external,
            load_sharing: self.load_sharing,
            roughness_um: self.roughness_um,
            effective_modulus_pa: self.effective_modulus_pa,
            teeth: self.teeth,
            contact: self.contact,
        }
    }
}

/// The operating point of one mesh as the model uses it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOperating {
    /// Nominal speeds of pinion and gear, rad/s.
    pub speeds_rad_s: [f64; 2],
    /// Mean torques on the pinion's and the gear's shafts, N m.
    pub torques_nm: [f64; 2],
    /// Mean mesh force without friction, N.
    pub static_force_n: f64,
    /// Mesh damping ratio zeta (c_m = 2 zeta sqrt(k_mean m_e)).
    pub damping_ratio: f64,
}

/// The assembled model: immutable inputs for one dynamic evaluation. It holds no
/// evaluation state: how the contact is decided travels with each call as a
/// [`ContactFrame`], so one system may be shared between threads.
pub struct GearSystem<'a> {
    asm: Cow<'a, Assembly>,
    /// The meshes, in the order of the assembly's.
    pub meshes: Vec<TrainMesh<'a>>,
    /// Nominal speed of every body, rad/s, in body order.
    body_speeds_rad_s: Vec<f64>,
    /// The assembly's stiffness and damping, as the right-hand side multiplies them.
    linear: rhs::LinearParts,
    /// A time-varying nominal speed and load (transient simulations), or None for the
    /// constant operating point.
    drive: Option<&'a Drive>,
}

// The system is shared read-only (e.g. by parallel studies): it must stay Send + Sync.
const _: () = {
    const fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<GearSystem<'static>>();
};

impl<'a> GearSystem<'a> {
    /// The single pair of paper eq. (1) (the one-stage train).
    pub fn new(parts: GearSystemParts<'a>) -> Self {
        let p = parts.params;
        let asm = Assembly::new(Elements::single_pair(p, parts.pair))
            .expect("the single pair is a connected train");
        let o = &p.operating;
        let (ws, wg) = (o.pinion_speed_rad_s, o.gear_speed_rad_s);
        let operating = MeshOperating {
            speeds_rad_s: [ws, wg],
            torques_nm: [o.motor_torque_nm, o.brake_torque_nm],
            static_force_n: o.static_mesh_force_n,
            damping_ratio: p.lumped.mesh_damping_ratio,
        };
        Self::assembled(
            Cow::Owned(asm),
            vec![(parts.mesh_parts(), operating)],
            vec![ws, ws, wg, wg],
        )
    }

    /// A train: the assembly, each mesh's parts and operating point (in the assembly's
    /// mesh order) and every body's nominal speed, rad/s.
    pub fn assembled(
        asm: Cow<'a, Assembly>,
        meshes: Vec<(MeshParts<'a>, MeshOperating)>,
        body_speeds_rad_s: Vec<f64>,
    ) -> Self {
        let input_speed = body_speeds_rad_s[asm.elements.drive.input];
        let meshes = meshes
            .into_iter()
            .enumerate()
            .map(|(m, (mut parts, op))| {
                // `Auto` becomes the law this mesh uses, once (LoadSharingModel::resolve).
                // Pedrero's law is for perfect involutes on the nominal path only.
                let shared_by_compression = parts.teeth.is_some() || parts.contact.is_extended();
                parts.load_sharing = parts
                    .load_sharing
                    .resolve(shared_by_compression, parts.pair.contact_ratio);
                let link = &asm.elements.meshes[m];
                let inertia = |b: usize| asm.elements.bodies[b].inertia_kg_m2;
                let c_m = mesh_damping_n_s_per_m(
                    op.damping_ratio,
                    [inertia(link.pinion), inertia(link.gear)],
                    link.base_radius_m,
                    parts.mesh.mean_stiffness_n_per_m(),
                );
                TrainMesh {
                    parts,
                    mesh_damping_n_s_per_m: c_m,
                    geometry: asm.meshes()[m].clone(),
                    operating: op,
                    input_speed_rad_s: input_speed,
                    xu: XuConstants::new(parts.viscosity_cp, parts.roughness_um),
                    drive: None,
                }
            })
            .collect();
        let linear = rhs::LinearParts::of(&asm);
        Self {
            asm,
            meshes,
            body_speeds_rad_s,
            linear,
            drive: None,
        }
    }

    /// The same system driven by `drive` (`dynamics::drive`): nominal speed ramp and load
    /// fluctuation on the input's speed. The steady-state solvers use systems without a
    /// drive.
    pub fn with_drive(mut self, drive: &'a Drive) -> Self {
        self.drive = Some(drive);
        for m in &mut self.meshes {
            m.drive = Some(drive);
        }
        self
    }

    /// The assembled train.
    pub fn assembly(&self) -> &Assembly {
        &self.asm
    }

    /// Number of coordinates (the state has twice as many entries).
    pub fn dofs(&self) -> usize {
        self.asm.len()
    }

    /// Number of states, 2 [`GearSystem::dofs`].
    pub fn states(&self) -> usize {
        2 * self.asm.len()
    }

    /// Mesh `m`.
    pub fn mesh(&self, m: usize) -> &TrainMesh<'a> {
        &self.meshes[m]
    }

    /// Nominal speed of each body, rad/s.
    pub fn body_speeds_rad_s(&self) -> &[f64] {
        &self.body_speeds_rad_s
    }

    /// d delta / dq of mesh `m` in the assembled coordinates.
    pub fn mesh_gradient(&self, m: usize) -> DVector<f64> {
        self.asm.mesh_gradient(m)
    }

    /// Linear (bearing, shaft, coupling) stiffness and damping matrices and inverse
    /// masses.
    pub fn linear_parts(&self) -> (&nalgebra::DMatrix<f64>, &nalgebra::DMatrix<f64>, &[f64]) {
        (
            self.asm.stiffness(),
            self.asm.damping(),
            self.asm.inverse_masses(),
        )
    }

    /// Constant generalised forces (the drive's torques).
    pub fn external_forces(&self) -> &DVector<f64> {
        self.asm.external_forces()
    }

    /// Mesh phase of mesh `m` at time t (its pinion's nominal rotation, rad).
    #[inline]
    pub fn phase_at(&self, m: usize, t_s: f64) -> f64 {
        self.meshes[m].phase_at(t_s)
    }
}
