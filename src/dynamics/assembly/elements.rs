//! The elements a gear train is assembled from (docs/MODEL.md, section 4.1): rigid
//! bodies, the connections between them (bearings to ground, shafts and couplings,
//! meshes) and the drive at its ends.
//!
//! Sign conventions. Every body's rotation coordinate is its deviation from the nominal
//! rotation, positive in the body's own sense of rotation (the sense it turns in under the
//! drive; `Assembly::spin` gives that sense in the plane, +1 counter-clockwise). So a
//! shaft's torsional spring acts on the difference of its ends' coordinates (both ends
//! turn alike), and a mesh's deflection grows with the driving gear's coordinate and
//! shrinks with the driven one's, whatever the stage. Lateral coordinates x, y are
//! displacements of a body's centre in the fixed plane of the train, SI.

use crate::config::case::SpeedBoundary;

/// What a body is (for names, messages and which inputs it can take).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyKind {
    /// The driving machine's rotor (rotation only).
    Motor,
    /// A gear: lateral motion and rotation, a member of one or more meshes.
    Gear,
    /// The driven machine (the paper's brake; rotation only).
    Load,
}

/// A rigid body: its inertia and the degrees of freedom it carries.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Name in messages and outputs ("motor", "pinion", "stage 2 gear", ...).
    pub name: String,
    /// What the body is.
    pub kind: BodyKind,
    /// Mass, kg (used when the body moves laterally).
    pub mass_kg: f64,
    /// Polar moment of inertia about the body's axis, kg m^2.
    pub inertia_kg_m2: f64,
    /// The body moves laterally (x, y) as well as rotating.
    pub lateral: bool,
}

/// A bearing: a body's centre held to ground by a spring and a damper per direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bearing {
    /// Index of the body the bearing holds.
    pub body: usize,
    /// Stiffness in x and y, N/m.
    pub stiffness_n_per_m: [f64; 2],
    /// Damping in x and y, N s/m.
    pub damping_n_s_per_m: [f64; 2],
}

/// An axial (thrust) bearing: a body held to ground along its axis by a spring and a
/// damper (docs/MODEL.md 11.6). A body with one carries an axial coordinate z (m, along
/// its mesh's pinion's angular velocity: a pair's two bodies share the direction; in a
/// train each stage counts z along its own pinion's, docs/MODEL.md 4.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxialBearing {
    /// Index of the body the bearing holds.
    pub body: usize,
    /// Axial stiffness, N/m.
    pub stiffness_n_per_m: f64,
    /// Axial damping, N s/m.
    pub damping_n_s_per_m: f64,
}

impl AxialBearing {
    /// The bearings of a pair's two `bodies` (pinion, gear) from their (stiffness N/m,
    /// damping N s/m), each body its own bearing to ground; a body without one (None) is
    /// held rigidly, with no axial coordinate.
    pub(crate) fn of_pair(bodies: [usize; 2], bearings: [Option<(f64, f64)>; 2]) -> Vec<Self> {
        bodies
            .into_iter()
            .zip(bearings)
            .filter_map(|(body, kc)| {
                kc.map(|(k, c)| AxialBearing {
                    body,
                    stiffness_n_per_m: k,
                    damping_n_s_per_m: c,
                })
            })
            .collect()
    }
}

/// A tilting bearing: a body held to ground against rotation about the two axes normal
/// to its shaft (x and y of the train's plane) by a spring and a damper per axis
/// (docs/MODEL.md 11.8). A body with one carries two tilting coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TiltBearing {
    /// Index of the body the bearing holds.
    pub body: usize,
    /// Tilting stiffness about each axis, N m/rad.
    pub stiffness_nm_per_rad: f64,
    /// Tilting damping about each axis, N m s/rad.
    pub damping_nm_s_per_rad: f64,
    /// The body's diametral moment of inertia (about an axis normal to its shaft through
    /// its centre), kg m^2: the inertia of its tilting coordinates.
    pub diametral_inertia_kg_m2: f64,
}

impl TiltBearing {
    /// The tilting bearings of a pair's two `bodies` (pinion, gear) from their (stiffness
    /// N m/rad, damping N m s/rad) and diametral inertias (kg m^2); a body without one
    /// (None) has no tilting coordinates.
    pub(crate) fn of_pair(
        bodies: [usize; 2],
        bearings: [Option<(f64, f64)>; 2],
        inertia_kg_m2: [f64; 2],
    ) -> Vec<Self> {
        (0..2)
            .filter_map(|i| {
                bearings[i].map(|(k, c)| TiltBearing {
                    body: bodies[i],
                    stiffness_nm_per_rad: k,
                    damping_nm_s_per_rad: c,
                    diametral_inertia_kg_m2: inertia_kg_m2[i],
                })
            })
            .collect()
    }
}

/// How the tilts of a helical mesh's bodies enter its deflection (docs/MODEL.md 11.8).
/// With n = d x z the unit normal of the plane of action in the transverse plane (d the
/// transverse line of action, z the pinion's axis) and each body's small tilt a about n
/// and b about d (rad), the deflection along the transverse line of action gains
///   -mu a_p + (mu - s t L) a_g + s t (r_b1 b_p + r_b2 b_g)   (m),
/// s t the hand's sign s times t = tan(beta_b) (`signed_tan_base_helix`), L the length
/// N1N2 of the line of action between the base circles' tangency points, and the mesh
/// adds the tilting spring J (a_g - a_p)^2 / 2 of the spread of its slices about their
/// centre of stiffness and the constant moment of its lead gaps on a_g - a_p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshTilt {
    /// mu = s t rho_bar, m: the slices' mean lever (period mean of sum k_j mu_j over sum
    /// k_j, mu_j = y_j - b/2 + s t rho_j).
    pub centre_lever_m: f64,
    /// s t = s tan(beta_b), s = +1 for a right-hand pinion, -1 for a left-hand one (the
    /// sign of the axial force on the pinion, `study::helical::pinion_axial_sign`).
    pub signed_tan_base_helix: f64,
    /// The period-mean moment of the slices' lead gaps, (K / N) sum_j G_j (y_j - b/2),
    /// N m: a constant generalised force on the relative tilt (0 without lead gaps).
    pub gap_moment_nm: f64,
    /// L = N1N2, m.
    pub line_of_action_length_m: f64,
    /// J, N m/rad: the period mean of sum k_j (mu_j - mu)^2.
    pub tilting_stiffness_nm_per_rad: f64,
}

/// A shaft or coupling between two bodies that turn together: a torsional spring and
/// damper on the difference of their rotations and, where the shaft carries two gears, a
/// lateral spring and damper between their centres (0: none).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shaft {
    /// Indices of the two bodies the shaft joins.
    pub ends: [usize; 2],
    /// Torsional stiffness on the difference of the ends' rotations, N m/rad.
    pub torsional_stiffness_nm_per_rad: f64,
    /// Torsional damping on the difference of the ends' rotations, N m s/rad.
    pub torsional_damping_nm_s_per_rad: f64,
    /// Lateral stiffness between the two centres, N/m (0: none).
    pub lateral_stiffness_n_per_m: f64,
    /// Lateral damping between the two centres, N s/m (0: none).
    pub lateral_damping_n_s_per_m: f64,
}

/// The geometry of a mesh between two gear bodies as the assembly needs it: which body
/// drives, the teeth (for the speed ratio), the base radii (levers of the mesh force) and
/// the operating pressure angle and centre line (the line of action in the plane). The
/// pair's stiffness, teeth, friction and wear travel with the model's mesh
/// (`dynamics::model`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshLink {
    /// The driving gear (the stage's pinion) and the driven one.
    pub pinion: usize,
    /// Index of the driven gear body.
    pub gear: usize,
    /// Teeth of pinion and gear (the speed ratio).
    pub teeth: [usize; 2],
    /// Base radii of pinion and gear, m.
    pub base_radius_m: [f64; 2],
    /// Operating pressure angle, rad.
    pub pressure_angle_rad: f64,
    /// Direction of the line from the pinion's centre to the gear's in the plane, rad
    /// from +x (0: the gear on +x, the paper's layout).
    pub centre_line_rad: f64,
    /// d delta / d z_p, m/m: how the pinion's axial motion changes the mesh deflection
    /// along the transverse line of action (the gear's is the opposite); -s tan(beta_b)
    /// for a helical mesh (docs/MODEL.md 11.6), 0 for a spur one. It enters the gradient
    /// only for a body with an axial coordinate (an [`AxialBearing`]).
    pub axial_gradient: f64,
    /// How the bodies' tilts enter the deflection (a helical mesh whose bodies tilt; None:
    /// no tilting terms). They enter the gradient only for bodies with a
    /// [`TiltBearing`].
    pub tilt: Option<MeshTilt>,
}

/// Which bodies the power enters and leaves by, and how their speeds are held
/// (`operating.speed_boundary`): the paper's three boundaries on any pair of bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drive {
    /// The driving body (the motor) and the driven one (the load).
    pub input: usize,
    /// Index of the driven body (the load).
    pub output: usize,
    /// How the speeds are held (`operating.speed_boundary`).
    pub boundary: SpeedBoundary,
    /// Mean torques on input and output, N m (the input's drives, the output's resists).
    pub input_torque_nm: f64,
    /// Mean torque on the output, N m (resisting).
    pub output_torque_nm: f64,
    /// The motor's slip damping, N m s/rad (motor slip only).
    pub slip_damping_nm_s_per_rad: f64,
}

/// The elements of a train.
#[derive(Debug, Clone, PartialEq)]
pub struct Elements {
    /// The rigid bodies; elements refer to them by index.
    pub bodies: Vec<Body>,
    /// Bearings holding bodies to ground.
    pub bearings: Vec<Bearing>,
    /// Shafts and couplings between bodies.
    pub shafts: Vec<Shaft>,
    /// Meshes between gear bodies.
    pub meshes: Vec<MeshLink>,
    /// Axial bearings (a helical pair whose case gives them; none otherwise: every body
    /// then has no axial coordinate).
    pub axial_bearings: Vec<AxialBearing>,
    /// Tilting bearings (a helical pair whose case gives them; none otherwise).
    pub tilt_bearings: Vec<TiltBearing>,
    /// Where the power enters and leaves, and how the speeds are held.
    pub drive: Drive,
}
