//! The paper's model as the smallest train: motor, pinion, gear and brake, the pinion and
//! gear on bearings, the motor and brake coupled to them, one mesh (paper eq. 1); a
//! helical pair's axial bearings where its case gives them (docs/MODEL.md 11.6).

use super::elements::{
    AxialBearing, Bearing, Body, BodyKind, Drive, Elements, MeshLink, Shaft, TiltBearing,
};
use crate::dynamics::params::DynamicParams;
use crate::geometry::GearPair;

/// Body index of the single pair's motor.
pub const MOTOR: usize = 0;
/// Body index of the single pair's pinion.
pub const PINION: usize = 1;
/// Body index of the single pair's gear.
pub const GEAR: usize = 2;
/// Body index of the single pair's brake.
pub const BRAKE: usize = 3;

impl Elements {
    /// The elements of paper eq. (1) for `pair` with the lumped parameters and operating
    /// point of `params`: the pinion's centre at the origin, the gear's on +x; with
    /// `params.axial`, the axial bearings and the mesh's axial gradient; with
    /// `params.tilt`, the tilting bearings and the mesh's tilting terms.
    pub fn single_pair(params: &DynamicParams, pair: &GearPair) -> Self {
        let l = &params.lumped;
        let axial_bearings = params.axial.map_or_else(Vec::new, |a| {
            AxialBearing::of_pair([PINION, GEAR], a.bearings)
        });
        let body = |name: &str, kind, mass_kg, inertia_kg_m2, lateral| Body {
            name: name.into(),
            kind,
            mass_kg,
            inertia_kg_m2,
            lateral,
        };
        let bearing = |body, k: f64, c: f64| Bearing {
            body,
            stiffness_n_per_m: [k, k],
            damping_n_s_per_m: [c, c],
        };
        let coupling = |ends, k, c| Shaft {
            ends,
            torsional_stiffness_nm_per_rad: k,
            torsional_damping_nm_s_per_rad: c,
            lateral_stiffness_n_per_m: 0.0,
            lateral_damping_n_s_per_m: 0.0,
        };
        Self {
            bodies: vec![
                body("motor", BodyKind::Motor, 0.0, l.inertia_motor_kg_m2, false),
                body(
                    "pinion",
                    BodyKind::Gear,
                    l.mass_pinion_kg,
                    l.inertia_pinion_kg_m2,
                    true,
                ),
                body(
                    "gear",
                    BodyKind::Gear,
                    l.mass_gear_kg,
                    l.inertia_gear_kg_m2,
                    true,
                ),
                body("brake", BodyKind::Load, 0.0, l.inertia_brake_kg_m2, false),
            ],
            bearings: vec![
                bearing(
                    PINION,
                    l.bearing_stiffness_pinion_n_per_m,
                    l.bearing_damping_pinion_n_s_per_m,
                ),
                bearing(
                    GEAR,
                    l.bearing_stiffness_gear_n_per_m,
                    l.bearing_damping_gear_n_s_per_m,
                ),
            ],
            shafts: vec![
                coupling(
                    [MOTOR, PINION],
                    l.coupling_stiffness_motor_nm_per_rad,
                    l.coupling_damping_motor_nm_s_per_rad,
                ),
                coupling(
                    [GEAR, BRAKE],
                    l.coupling_stiffness_brake_nm_per_rad,
                    l.coupling_damping_brake_nm_s_per_rad,
                ),
            ],
            meshes: vec![MeshLink {
                pinion: PINION,
                gear: GEAR,
                teeth: [pair.pinion.teeth, pair.gear.teeth],
                base_radius_m: [pair.pinion.base_radius_m, pair.gear.base_radius_m],
                pressure_angle_rad: pair.operating_pressure_angle_rad,
                centre_line_rad: 0.0,
                axial_gradient: params.axial.map_or(0.0, |a| a.axial_gradient),
                tilt: params.tilt.map(|t| t.mesh),
            }],
            axial_bearings,
            tilt_bearings: params.tilt.map_or_else(Vec::new, |t| {
                TiltBearing::of_pair([PINION, GEAR], t.bearings, t.diametral_inertia_kg_m2)
            }),
            drive: Drive {
                input: MOTOR,
                output: BRAKE,
                boundary: params.speed_boundary,
                input_torque_nm: params.operating.motor_torque_nm,
                output_torque_nm: params.operating.brake_torque_nm,
                slip_damping_nm_s_per_rad: params.motor_slip_damping_nm_s_per_rad,
            },
        }
    }
}
