//! Lumped parameters of the 8-DOF model in SI units, built from the case
//! (paper Table 2, units corrected as docs/PAPER_NOTES.md says), and the operating point.

use crate::config::case::{Case, DynamicsSection, OperatingSection, SpeedBoundary, TorqueShaft};
use crate::geometry::GearPair;
use serde::Serialize;
use std::f64::consts::PI;

/// The nominal operating point of a pair: speed and torque on each shaft and the mesh
/// frequency, computed once from the case's `[operating]` section and the pair
/// ([`OperatingPoint::of`]) and used by the model, the checks of a case against its
/// geometry (`study::domain`), the run budget and the reports.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OperatingPoint {
    /// Nominal pinion speed Omega_p = 2 pi f_in, rad/s.
    pub pinion_speed_rad_s: f64,
    /// Nominal gear speed Omega_g = Omega_p z1 / z2, rad/s.
    pub gear_speed_rad_s: f64,
    /// Load torque at the brake (gear shaft), N m: T_brk of paper eq. (1).
    pub brake_torque_nm: f64,
    /// The same load referred to the motor (pinion shaft), N m: r_pb / r_gb T_brk.
    pub motor_torque_nm: f64,
    /// Mesh frequency f_m = z1 f_in, Hz.
    pub mesh_frequency_hz: f64,
    /// Mean mesh force without friction, N: the load torque over the base radius of its
    /// shaft (T_brk / r_gb = T_motor / r_pb; docs/MODEL.md, "Mean balance").
    pub static_mesh_force_n: f64,
}

impl OperatingPoint {
    /// The operating point of `op` on `pair`. The load torque on its shaft is moved to the
    /// other through the base radii (the friction-free torque ratio, r_gb / r_pb).
    pub fn of(op: &OperatingSection, pair: &GearPair) -> Self {
        let rpb = pair.pinion.base_radius_m;
        let rgb = pair.gear.base_radius_m;
        let (motor_t, brake_t) = match op.load_torque_shaft {
            TorqueShaft::Pinion => (op.load_torque_nm, op.load_torque_nm * rgb / rpb),
            TorqueShaft::Gear => (op.load_torque_nm * rpb / rgb, op.load_torque_nm),
        };
        let omega_p = 2.0 * PI * op.input_speed_hz;
        Self {
            pinion_speed_rad_s: omega_p,
            gear_speed_rad_s: omega_p * pair.pinion.teeth as f64 / pair.gear.teeth as f64,
            brake_torque_nm: brake_t,
            motor_torque_nm: motor_t,
            // From the input speed in Hz, not back from rad/s: 30 Hz x 19 is 570 exactly.
            mesh_frequency_hz: op.input_speed_hz * pair.pinion.teeth as f64,
            static_mesh_force_n: brake_t / rgb,
        }
    }
}

/// The operating point of one mesh of a train: its gears' speeds and torques, its mesh
/// frequency and its friction-free force.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MeshPoint {
    /// Nominal speeds of the mesh's pinion and gear, rad/s.
    pub pinion_speed_rad_s: f64,
    /// Nominal speed of the mesh's gear, rad/s.
    pub gear_speed_rad_s: f64,
    /// Mean torques on the pinion's and the gear's shafts, N m.
    pub pinion_torque_nm: f64,
    /// Mean torque on the gear's shaft, N m.
    pub gear_torque_nm: f64,
    /// Mesh frequency z_pinion f_pinion, Hz.
    pub mesh_frequency_hz: f64,
    /// Mean mesh force without friction, N: a shaft's torque over its base radius.
    pub static_mesh_force_n: f64,
}

/// The operating point of a train (`config::train`), computed once from `[operating]`
/// and the stages' pairs: every shaft's speed and torque and every mesh's frequency and
/// force. The input speed turns stage 1's pinion; each stage's gear turns at its
/// pinion's speed times z_pinion / z_gear and carries its pinion's torque times
/// r_gb / r_pb (friction-free, through the base radii), the next stage's pinion on the
/// same shaft; the load torque acts on the input shaft (`load_torque_shaft` =
/// "pinion") or the output shaft ("gear"). A one-stage train's numbers are the single
/// pair's [`OperatingPoint`]'s, computed the same way.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrainOperatingPoint {
    /// One per stage, in order.
    pub meshes: Vec<MeshPoint>,
}

impl TrainOperatingPoint {
    /// The operating point of `op` on a train of `pairs` (stage order).
    pub fn of(op: &OperatingSection, pairs: &[&GearPair]) -> Self {
        let omega_in = 2.0 * PI * op.input_speed_hz;
        let mut torque = match op.load_torque_shaft {
            TorqueShaft::Pinion => op.load_torque_nm,
            TorqueShaft::Gear => {
                // Back from the output, stage by stage, as the single pair does.
                let mut t = op.load_torque_nm;
                for p in pairs.iter().rev() {
                    t = t * p.pinion.base_radius_m / p.gear.base_radius_m;
                }
                t
            }
        };
        let mut speed = omega_in;
        let mut meshes = Vec::with_capacity(pairs.len());
        for (k, p) in pairs.iter().enumerate() {
            let (rpb, rgb) = (p.pinion.base_radius_m, p.gear.base_radius_m);
            let gear_torque = match (op.load_torque_shaft, k + 1 == pairs.len()) {
                // The output's torque as given, not moved there and back.
                (TorqueShaft::Gear, true) => op.load_torque_nm,
                _ => torque * rgb / rpb,
            };
            let gear_speed = speed * p.pinion.teeth as f64 / p.gear.teeth as f64;
            meshes.push(MeshPoint {
                pinion_speed_rad_s: speed,
                gear_speed_rad_s: gear_speed,
                pinion_torque_nm: torque,
                gear_torque_nm: gear_torque,
                mesh_frequency_hz: speed / (2.0 * PI) * p.pinion.teeth as f64,
                static_mesh_force_n: gear_torque / rgb,
            });
            torque = gear_torque;
            speed = gear_speed;
        }
        Self { meshes }
    }

    /// Nominal speed of every body of `assembly::Elements::train` (motor, each stage's
    /// pinion and gear, load), rad/s.
    pub fn body_speeds_rad_s(&self) -> Vec<f64> {
        let mut out = vec![self.meshes[0].pinion_speed_rad_s];
        for m in &self.meshes {
            out.push(m.pinion_speed_rad_s);
            out.push(m.gear_speed_rad_s);
        }
        out.push(self.meshes[self.meshes.len() - 1].gear_speed_rad_s);
        out
    }

    /// Mean torques on the input (motor) and output (load) shafts, N m.
    pub fn end_torques_nm(&self) -> (f64, f64) {
        (
            self.meshes[0].pinion_torque_nm,
            self.meshes[self.meshes.len() - 1].gear_torque_nm,
        )
    }
}

/// The axial degrees of freedom of a helical pair (docs/MODEL.md 11.6): how the bodies'
/// axial motion enters the mesh deflection and the axial bearings that hold them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxialSupport {
    /// d delta / d z_p of the mesh, m/m (the gear's is the opposite): -s tan(beta_b), s
    /// the sign of the axial mesh force on the pinion along its angular velocity
    /// (`study::helical::pinion_axial_sign`), delta the deflection along the transverse
    /// line of action.
    pub axial_gradient: f64,
    /// Axial bearing stiffness (N/m) and damping (N s/m) of pinion and gear; None: rigid
    /// (that body has no axial coordinate).
    pub bearings: [Option<(f64, f64)>; 2],
}

/// The tilting degrees of freedom of a helical pair (docs/MODEL.md 11.8): the mesh's
/// tilting levers and the tilting bearings that hold pinion and gear.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TiltSupport {
    /// How the bodies' tilts enter the mesh deflection (levers and the mesh's own tilting
    /// stiffness).
    pub mesh: crate::dynamics::assembly::elements::MeshTilt,
    /// Tilting bearing stiffness (N m/rad) and damping (N m s/rad) of pinion and gear,
    /// each about both axes normal to the shaft; None: rigid (no tilting coordinates).
    pub bearings: [Option<(f64, f64)>; 2],
    /// Diametral moments of inertia of pinion and gear, kg m^2 (each about an axis normal
    /// to its shaft through its centre).
    pub diametral_inertia_kg_m2: [f64; 2],
}

/// Parameters of paper eq. (1), SI: the lumped masses, inertias, bearing and coupling
/// stiffness and damping of the case (already SI, units in their names), and the
/// operating point derived from the case and the pair.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicParams {
    /// With every `"derived"` mass and inertia resolved from the pair's blanks.
    pub lumped: DynamicsSection<f64>,
    /// How the drivetrain's free rotation is held (`[operating]`).
    pub speed_boundary: SpeedBoundary,
    /// Slope c_slip of the motor torque-speed law of [`SpeedBoundary::MotorSlip`],
    /// N m s/rad.
    pub motor_slip_damping_nm_s_per_rad: f64,
    /// The nominal operating point: speeds, torques, mesh frequency, static mesh force.
    pub operating: OperatingPoint,
    /// The axial degrees of freedom of a helical pair whose case gives axial bearings
    /// (None: the planar model, and every spur pair).
    pub axial: Option<AxialSupport>,
    /// The tilting degrees of freedom of a helical pair whose case gives tilting bearings
    /// (None: no tilting coordinates, and every spur pair).
    pub tilt: Option<TiltSupport>,
}

impl DynamicParams {
    /// The parameters of `case` for `pair`: `"derived"` masses and inertias from the
    /// pair's blanks, the operating point from `[operating]`.
    pub fn from_case(case: &Case, pair: &GearPair) -> Self {
        let d = &case.dynamics;
        let o = &case.operating;
        Self {
            lumped: d.resolve(&pair.blank_estimates(d.blank_density_kg_per_m3)),
            speed_boundary: o.speed_boundary,
            motor_slip_damping_nm_s_per_rad: o.motor_slip_damping_nm_s_per_rad,
            operating: OperatingPoint::of(o, pair),
            axial: None,
            tilt: None,
        }
    }

    /// Number of axial coordinates (bodies on an axial bearing), 0 to 2.
    pub fn axial_coordinates(&self) -> usize {
        self.axial
            .map_or(0, |a| a.bearings.iter().filter(|b| b.is_some()).count())
    }

    /// Number of tilting coordinates (two per body on a tilting bearing), 0 to 4.
    pub fn tilt_coordinates(&self) -> usize {
        self.tilt
            .map_or(0, |t| 2 * t.bearings.iter().filter(|b| b.is_some()).count())
    }

    /// Equivalent mass of the mesh's torsional mode, kg (docs/PAPER_NOTES.md):
    /// m_e = J_p J_g / (J_p r_gb^2 + J_g r_pb^2).
    pub fn equivalent_mesh_mass_kg(&self, pair: &GearPair) -> f64 {
        equivalent_mesh_mass_kg(
            [
                self.lumped.inertia_pinion_kg_m2,
                self.lumped.inertia_gear_kg_m2,
            ],
            [pair.pinion.base_radius_m, pair.gear.base_radius_m],
        )
    }

    /// Mesh damping c_m = 2 zeta sqrt(k_mean m_e), N s/m (the paper gives none; docs/PAPER_NOTES.md).
    pub fn mesh_damping_n_s_per_m(&self, pair: &GearPair, mean_stiffness_n_per_m: f64) -> f64 {
        mesh_damping_n_s_per_m(
            self.lumped.mesh_damping_ratio,
            [
                self.lumped.inertia_pinion_kg_m2,
                self.lumped.inertia_gear_kg_m2,
            ],
            [pair.pinion.base_radius_m, pair.gear.base_radius_m],
            mean_stiffness_n_per_m,
        )
    }
}

/// Equivalent mass of a mesh's torsional mode, kg, from the polar inertias of its pinion
/// and gear (kg m^2) and their base radii (m): m_e = J_p J_g / (J_p r_gb^2 + J_g r_pb^2).
pub fn equivalent_mesh_mass_kg(inertia_kg_m2: [f64; 2], base_radius_m: [f64; 2]) -> f64 {
    let [jp, jg] = inertia_kg_m2;
    let [rp, rg] = base_radius_m;
    jp * jg / (jp * rg * rg + jg * rp * rp)
}

/// Mesh damping c_m = 2 zeta sqrt(k_mean m_e), N s/m, for the damping ratio zeta, the
/// inertias and base radii of the mesh's gears and its mean stiffness (N/m).
pub fn mesh_damping_n_s_per_m(
    damping_ratio: f64,
    inertia_kg_m2: [f64; 2],
    base_radius_m: [f64; 2],
    mean_stiffness_n_per_m: f64,
) -> f64 {
    2.0 * damping_ratio
        * (mean_stiffness_n_per_m * equivalent_mesh_mass_kg(inertia_kg_m2, base_radius_m)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_equivalent_mass_and_loads() {
        let case = Case::default();
        let pair = GearPair::from_case(&case.gear).unwrap();
        let p = DynamicParams::from_case(&case, &pair);
        // docs/PAPER_NOTES.md: m_e = 0.506 kg for the paper's inertias.
        assert!((p.equivalent_mesh_mass_kg(&pair) - 0.506).abs() < 5e-4);
        // 60 N m on the pinion: mesh force 60 / r_pb = 3361 N, both ways round.
        let f_from_brake = p.operating.brake_torque_nm / pair.gear.base_radius_m;
        let f_from_motor = p.operating.motor_torque_nm / pair.pinion.base_radius_m;
        assert!((f_from_brake - 3360.6).abs() < 0.5, "{f_from_brake}");
        assert!((f_from_brake - f_from_motor).abs() < 1e-9);
        // Mesh frequency 19 x 30 Hz.
        // Exactly: both factors and their product are whole numbers of f64.
        assert_eq!(p.operating.mesh_frequency_hz, 570.0);
        // The static mesh force is the same from either shaft's torque.
        assert!((p.operating.static_mesh_force_n - f_from_brake).abs() < 1e-9);
    }
}
