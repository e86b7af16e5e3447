//! A parallel-axis reducer of N stages as elements: the motor, each stage's pinion and
//! gear on their bearings, the shafts joining stage k's gear to stage k + 1's pinion, the
//! load; the motor and load coupled as in the single pair (`single_pair`), which is the
//! one-stage case with the same bodies, numbering and matrices.

use super::elements::AxialBearing;
use super::elements::{Bearing, Body, BodyKind, Drive, Elements, MeshLink, Shaft};
use crate::config::case::DynamicsSection;
use crate::dynamics::params::AxialSupport;

/// One stage as the assembly needs it.
#[derive(Debug, Clone, PartialEq)]
pub struct StageElements {
    /// The stage's pinion and gear masses, inertias and bearings (resolved), and the
    /// motor's and load's inertias and couplings (taken from the first and last stage).
    pub lumped: DynamicsSection<f64>,
    /// Teeth of the stage's pinion and gear.
    pub teeth: [usize; 2],
    /// Base radii of pinion and gear, m.
    pub base_radius_m: [f64; 2],
    /// Operating pressure angle, rad.
    pub pressure_angle_rad: f64,
    /// Direction of the gear's centre seen from the pinion's, rad.
    pub centre_line_rad: f64,
    /// Torsional stiffness (N m/rad) and damping (N m s/rad) of the shaft to the next
    /// stage's pinion (None on the last stage).
    pub shaft: Option<(f64, f64)>,
    /// A helical stage's axial bearings and its mesh's d delta / d z_p (docs/MODEL.md
    /// 11.6, 4.3): each body on an axial bearing carries its own axial coordinate; None:
    /// rigid axial bearings (a spur stage, or a helical one without axial bearing keys).
    pub axial: Option<AxialSupport>,
}

/// Body index of the motor; stage k's (0-based) pinion and gear are 1 + 2k and 2 + 2k;
/// the load is the last body.
pub fn pinion_body(stage: usize) -> usize {
    1 + 2 * stage
}

/// See [`pinion_body`].
pub fn gear_body(stage: usize) -> usize {
    2 + 2 * stage
}

impl Elements {
    /// The train of `stages` (at least one) driven as `drive` says (its bodies are
    /// replaced by the motor's and the load's).
    pub fn train(stages: &[StageElements], mut drive: Drive) -> Self {
        let n = stages.len();
        let name = |what: &str, k: usize| {
            if n == 1 {
                what.to_owned()
            } else {
                format!("{what} {}", k + 1)
            }
        };
        let (first, last) = (&stages[0].lumped, &stages[n - 1].lumped);
        let rotor = |name: &str, kind, inertia_kg_m2| Body {
            name: name.into(),
            kind,
            mass_kg: 0.0,
            inertia_kg_m2,
            lateral: false,
        };
        let gear = |name: String, mass_kg, inertia_kg_m2| Body {
            name,
            kind: BodyKind::Gear,
            mass_kg,
            inertia_kg_m2,
            lateral: true,
        };
        let mut bodies = vec![rotor("motor", BodyKind::Motor, first.inertia_motor_kg_m2)];
        let mut bearings = Vec::new();
        let mut shafts = Vec::new();
        let mut meshes = Vec::new();
        let mut axial_bearings = Vec::new();
        let torsion = |ends, k, c| Shaft {
            ends,
            torsional_stiffness_nm_per_rad: k,
            torsional_damping_nm_s_per_rad: c,
            lateral_stiffness_n_per_m: 0.0,
            lateral_damping_n_s_per_m: 0.0,
        };
        shafts.push(torsion(
            [0, 1],
            first.coupling_stiffness_motor_nm_per_rad,
            first.coupling_damping_motor_nm_s_per_rad,
        ));
        for (k, s) in stages.iter().enumerate() {
            let l = &s.lumped;
            let (p, g) = (pinion_body(k), gear_body(k));
            bodies.push(gear(
                name("pinion", k),
                l.mass_pinion_kg,
                l.inertia_pinion_kg_m2,
            ));
            bodies.push(gear(name("gear", k), l.mass_gear_kg, l.inertia_gear_kg_m2));
            bearings.extend(stage_bearings(l, [p, g]));
            meshes.push(MeshLink {
                pinion: p,
                gear: g,
                teeth: s.teeth,
                base_radius_m: s.base_radius_m,
                pressure_angle_rad: s.pressure_angle_rad,
                centre_line_rad: s.centre_line_rad,
                axial_gradient: s.axial.map_or(0.0, |a| a.axial_gradient),
                tilt: None,
            });
            axial_bearings.extend(stage_axial_bearings(s, [p, g]));
            if let Some((kt, ct)) = s.shaft.filter(|_| k + 1 < n) {
                shafts.push(torsion([g, pinion_body(k + 1)], kt, ct));
            }
        }
        let load = bodies.len();
        bodies.push(rotor("brake", BodyKind::Load, last.inertia_brake_kg_m2));
        shafts.push(torsion(
            [gear_body(n - 1), load],
            last.coupling_stiffness_brake_nm_per_rad,
            last.coupling_damping_brake_nm_s_per_rad,
        ));
        drive.input = 0;
        drive.output = load;
        Self {
            bodies,
            bearings,
            shafts,
            meshes,
            axial_bearings,
            tilt_bearings: Vec::new(),
            drive,
        }
    }
}

/// A stage's lateral bearings on its pinion and gear (`bodies`), the same stiffness and
/// damping in x and y (N/m, N s/m).
fn stage_bearings(l: &DynamicsSection<f64>, bodies: [usize; 2]) -> [Bearing; 2] {
    let bearing = |body, k, c| Bearing {
        body,
        stiffness_n_per_m: [k, k],
        damping_n_s_per_m: [c, c],
    };
    [
        bearing(
            bodies[0],
            l.bearing_stiffness_pinion_n_per_m,
            l.bearing_damping_pinion_n_s_per_m,
        ),
        bearing(
            bodies[1],
            l.bearing_stiffness_gear_n_per_m,
            l.bearing_damping_gear_n_s_per_m,
        ),
    ]
}

/// A stage's axial bearings on its pinion and gear (`bodies`): each body on its own
/// bearing to ground, two gears on one shaft not tied axially (docs/MODEL.md 4.3).
fn stage_axial_bearings(s: &StageElements, bodies: [usize; 2]) -> Vec<AxialBearing> {
    AxialBearing::of_pair(bodies, s.axial.map_or([None, None], |a| a.bearings))
}
