//! A gear train assembled from elements (`elements`): the degrees of freedom numbered,
//! the constant mass, stiffness and damping built once, and each mesh's geometry (the
//! gradient of its deflection and the direction of its friction) for the time-varying,
//! nonlinear mesh forces the model adds in the right-hand side (`dynamics::model`).
//! docs/MODEL.md, section 4.1, states the assembled equations of motion.
//!
//! Numbering. The coordinates come in blocks of one kind, each block in body order:
//! first the lateral displacements (x, y of every body that moves laterally), then the
//! rotations (every body). The paper's pair (bodies motor, pinion, gear, brake) is
//! numbered `[x_p, y_p, x_g, y_g, phi_m, phi_p, phi_g, phi_b]`, its eq. (1) order
//! (`dynamics::model::dof`). The axial coordinates (z of every body on an axial
//! bearing: a helical pair whose case gives them, docs/MODEL.md 11.6) come as a third
//! block after these, so the blocks before them keep their numbers (the single pair with
//! both axial bearings: `[.., phi_b, z_p, z_g]`). The tilting coordinates (rotations
//! about the plane's x and y axes of every body on a tilting bearing, docs/MODEL.md 11.8)
//! come as a fourth block after them (`[.., z_g, tilt_x_p, tilt_y_p, tilt_x_g,
//! tilt_y_g]`); a carrier's rotating frame (planetary sets) would add a block after them.
//!
//! Equations (SI): M q'' + C q' + K q = f_ext + sum over meshes f_mesh(t, q, q'), with M
//! diagonal (masses on the lateral coordinates, inertias on the rotations), K and C the
//! bearings' (to ground), the shafts' and couplings' (torsional and lateral) springs and
//! dampers and the motor's slip damper, f_ext the drive's mean torques. A coordinate whose
//! speed is imposed has an infinite mass: `inverse_masses` holds 0 there.

pub mod elements;
mod kinematics;
pub mod single_pair;
#[cfg(test)]
mod tests_assembly;
#[cfg(test)]
mod tests_axial;
#[cfg(test)]
mod tests_tilt;
mod tilt;
pub mod train;

use self::elements::Elements;
use crate::config::case::SpeedBoundary;
use nalgebra::{DMatrix, DVector};

/// A kind of coordinate of a body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dof {
    /// Lateral displacement x of the body's centre, m.
    X,
    /// Lateral displacement y of the body's centre, m.
    Y,
    /// Rotation deviation from the nominal rotation, rad.
    Rotation,
    /// Axial displacement z of the body along its axis, m (+ along the pinion's angular
    /// velocity).
    Axial,
    /// Tilt of the body about the plane's x axis, rad (small angle).
    TiltX,
    /// Tilt of the body about the plane's y axis, rad (small angle).
    TiltY,
}

/// What is wrong with a set of elements (the case-file validation names the keys).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AssemblyError {
    /// A body joined by nothing to the drive.
    #[error("{body} is connected to nothing that leads to the drive (no shaft, coupling or mesh joins it to the train)")]
    Disconnected {
        /// The body's name.
        body: String,
    },
    /// A body whose speed two paths through the train give differently.
    #[error("{body} would turn at {first} and at {second} times the input speed by two paths through the train: the speeds are inconsistent")]
    InconsistentSpeeds {
        /// The body's name.
        body: String,
        /// Its speed by the first path, times the input speed.
        first: f64,
        /// Its speed by the second path, times the input speed.
        second: f64,
    },
    /// A mesh between two bodies that turn the same way.
    #[error("a mesh joins {first} and {second}, which turn the same way: a pair of external gears turns its members in opposite senses")]
    MeshSameSense {
        /// Name of the mesh's first body.
        first: String,
        /// Name of the mesh's second body.
        second: String,
    },
    /// An element names a body the train does not have.
    #[error("element refers to body {index}, but the train has {bodies} bodies")]
    NoSuchBody {
        /// The body index the element gives.
        index: usize,
        /// Number of bodies of the train.
        bodies: usize,
    },
}

/// Where a mesh acts in the assembled coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshGeometry {
    /// d delta / d q as (coordinate, value) pairs in ascending coordinate order (m/m on
    /// lateral coordinates, m/rad on rotations: the base radii).
    pub gradient: Vec<(usize, f64)>,
    /// The line of action's direction d in the plane: the force on the pinion is -F d.
    pub line_of_action: [f64; 2],
    /// The common tangent e (perpendicular to d): the pinion's surface slides along -e
    /// when it is the faster, and friction f acts on the pinion along +f e.
    pub tangent: [f64; 2],
    /// x coordinate of pinion and gear (y follows it), when they move laterally.
    pub lateral: [Option<usize>; 2],
    /// Rotation coordinate of pinion and gear.
    pub rotation: [usize; 2],
    /// Axial coordinate of pinion and gear, when they have one.
    pub axial: [Option<usize>; 2],
    /// First tilting coordinate (about x; about y follows it) of pinion and gear, when
    /// they tilt.
    pub tilt: [Option<usize>; 2],
}

/// The assembled train (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Assembly {
    /// The elements the train was assembled from.
    pub elements: Elements,
    /// First lateral coordinate (x) of each body that moves laterally.
    lateral: Vec<Option<usize>>,
    /// Rotation coordinate of each body.
    rotation: Vec<usize>,
    /// Axial coordinate of each body on an axial bearing.
    axial: Vec<Option<usize>>,
    /// First tilting coordinate (about x; y follows) of each body on a tilting bearing.
    tilt: Vec<Option<usize>>,
    n: usize,
    inverse_masses: Vec<f64>,
    stiffness: DMatrix<f64>,
    damping: DMatrix<f64>,
    forces: DVector<f64>,
    /// The coordinate whose speed is imposed, if one is.
    held: Option<usize>,
    /// Sense of rotation of each body in the plane (+1 counter-clockwise, the input's).
    spin: Vec<f64>,
    /// Nominal speed of each body over the input's, from the teeth.
    speed_ratio: Vec<f64>,
    meshes: Vec<MeshGeometry>,
}

impl Assembly {
    /// Numbers the coordinates and builds the constant matrices (module docs).
    pub fn new(elements: Elements) -> Result<Self, AssemblyError> {
        kinematics::check_indices(&elements)?;
        let (spin, speed_ratio) = kinematics::kinematics(&elements)?;
        let mut next = 0;
        let lateral: Vec<Option<usize>> = elements
            .bodies
            .iter()
            .map(|b| {
                b.lateral.then(|| {
                    next += 2;
                    next - 2
                })
            })
            .collect();
        let rotation: Vec<usize> = (0..elements.bodies.len()).map(|i| next + i).collect();
        next += elements.bodies.len();
        let axial: Vec<Option<usize>> = (0..elements.bodies.len())
            .map(|b| {
                elements
                    .axial_bearings
                    .iter()
                    .any(|a| a.body == b)
                    .then(|| {
                        next += 1;
                        next - 1
                    })
            })
            .collect();
        let tilt: Vec<Option<usize>> = (0..elements.bodies.len())
            .map(|b| {
                elements.tilt_bearings.iter().any(|t| t.body == b).then(|| {
                    next += 2;
                    next - 2
                })
            })
            .collect();
        let n = next;
        let mut asm = Self {
            lateral,
            rotation,
            axial,
            tilt,
            n,
            inverse_masses: vec![0.0; n],
            stiffness: DMatrix::zeros(n, n),
            damping: DMatrix::zeros(n, n),
            forces: DVector::zeros(n),
            held: None,
            spin,
            speed_ratio,
            meshes: Vec::new(),
            elements,
        };
        asm.fill_masses();
        asm.fill_drive();
        asm.fill_springs();
        asm.meshes = (0..asm.elements.meshes.len())
            .map(|m| asm.mesh_geometry(m))
            .collect();
        asm.fill_mesh_tilting_springs();
        Ok(asm)
    }

    /// Each tilting helical mesh's own tilting spring J on the relative tilt
    /// tau = a_g - a_p about the plane of action's normal (`MeshTilt`): J h h^T in the
    /// constant stiffness, h = d tau / d q, and its lead gaps' mean moment G on tau: G h in
    /// the constant forces (docs/MODEL.md 11.8).
    fn fill_mesh_tilting_springs(&mut self) {
        for (link, geo) in self.elements.meshes.iter().zip(&self.meshes) {
            let Some(t) = link.tilt else { continue };
            let h =
                tilt::relative_tilt_gradient(geo.line_of_action, self.spin[link.pinion], geo.tilt);
            for (i, hi) in &h {
                for (j, hj) in &h {
                    self.stiffness[(*i, *j)] += t.tilting_stiffness_nm_per_rad * hi * hj;
                }
                self.forces[*i] += t.gap_moment_nm * hi;
            }
        }
    }

    /// Number of coordinates (the state has twice as many entries).
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether the train has no coordinates.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The coordinate of `body` in direction `dof`, if the body has it.
    pub fn index(&self, body: usize, dof: Dof) -> Option<usize> {
        match dof {
            Dof::X => self.lateral[body],
            Dof::Y => self.lateral[body].map(|x| x + 1),
            Dof::Rotation => Some(self.rotation[body]),
            Dof::Axial => self.axial[body],
            Dof::TiltX => self.tilt[body],
            Dof::TiltY => self.tilt[body].map(|x| x + 1),
        }
    }

    /// 1 / M per coordinate (0 where the speed is imposed), 1/kg and 1/(kg m^2).
    pub fn inverse_masses(&self) -> &[f64] {
        &self.inverse_masses
    }

    /// Constant stiffness (bearings, shafts, couplings, and a tilting helical mesh's own
    /// tilting spring, docs/MODEL.md 11.8), N/m, N m/rad.
    pub fn stiffness(&self) -> &DMatrix<f64> {
        &self.stiffness
    }

    /// Constant damping (bearings, shafts, couplings, motor slip), N s/m, N m s/rad.
    pub fn damping(&self) -> &DMatrix<f64> {
        &self.damping
    }

    /// The drive's constant generalised forces (mean torques), N m.
    pub fn external_forces(&self) -> &DVector<f64> {
        &self.forces
    }

    /// The coordinate whose speed is imposed, if one is.
    pub fn held(&self) -> Option<usize> {
        self.held
    }

    /// Sense of rotation of each body in the plane (+1: the input's).
    pub fn spin(&self) -> &[f64] {
        &self.spin
    }

    /// Nominal speed of each body over the input's (the product of the teeth ratios on
    /// the way; for the operating point's speeds see `dynamics::params`).
    pub fn speed_ratio(&self) -> &[f64] {
        &self.speed_ratio
    }

    /// Each mesh's geometry, in the order of `Elements::meshes`.
    pub fn meshes(&self) -> &[MeshGeometry] {
        &self.meshes
    }

    /// The rigid rotation of the drivetrain in the coordinates: every rotation turned so
    /// that no shaft twists and no mesh deflects (the input's by 1 rad, a mesh's gear by
    /// the pinion's times the ratio of base radii), laterals still. With no speed imposed
    /// it is a free motion (motor slip).
    pub fn rigid_rotation(&self) -> DVector<f64> {
        let mut r = DVector::zeros(self.n);
        let mut done = vec![false; self.elements.bodies.len()];
        let input = self.elements.drive.input;
        r[self.rotation[input]] = 1.0;
        done[input] = true;
        // Breadth first from the input through shafts (same angle) and meshes (angle
        // times the ratio of base radii); the kinematics checked the train is connected.
        let mut queue = std::collections::VecDeque::from([input]);
        while let Some(b) = queue.pop_front() {
            for (other, factor) in self.neighbours_by_base_radii(b) {
                if !done[other] {
                    done[other] = true;
                    r[self.rotation[other]] = r[self.rotation[b]] * factor;
                    queue.push_back(other);
                }
            }
        }
        r
    }

    /// Bodies joined to `b` and the factor of their rigid rotation over `b`'s.
    fn neighbours_by_base_radii(&self, b: usize) -> Vec<(usize, f64)> {
        let e = &self.elements;
        let shafts = e.shafts.iter().filter_map(|s| match s.ends {
            [x, y] if x == b => Some((y, 1.0)),
            [x, y] if y == b => Some((x, 1.0)),
            _ => None,
        });
        let meshes = e.meshes.iter().filter_map(|m| {
            let [rp, rg] = m.base_radius_m;
            if m.pinion == b {
                Some((m.gear, rp / rg))
            } else if m.gear == b {
                Some((m.pinion, rg / rp))
            } else {
                None
            }
        });
        shafts.chain(meshes).collect()
    }

    fn fill_masses(&mut self) {
        for (i, body) in self.elements.bodies.iter().enumerate() {
            if let Some(x) = self.lateral[i] {
                self.inverse_masses[x] = 1.0 / body.mass_kg;
                self.inverse_masses[x + 1] = 1.0 / body.mass_kg;
            }
            self.inverse_masses[self.rotation[i]] = 1.0 / body.inertia_kg_m2;
            if let Some(z) = self.axial[i] {
                self.inverse_masses[z] = 1.0 / body.mass_kg;
            }
        }
        for t in &self.elements.tilt_bearings {
            let x = self.tilt[t.body].expect("a tilting bearing's body tilts");
            self.inverse_masses[x] = 1.0 / t.diametral_inertia_kg_m2;
            self.inverse_masses[x + 1] = 1.0 / t.diametral_inertia_kg_m2;
        }
    }

    /// The drive's boundary: an imposed angle is a coordinate of infinite inertia (zero
    /// acceleration); the other end carries its mean torque (both ends under motor slip).
    fn fill_drive(&mut self) {
        let d = self.elements.drive;
        let (input, output) = (self.rotation[d.input], self.rotation[d.output]);
        match d.boundary {
            SpeedBoundary::MotorSpeedImposed => {
                self.held = Some(input);
                self.forces[output] = -d.output_torque_nm;
            }
            SpeedBoundary::BrakeSpeedImposed => {
                self.held = Some(output);
                self.forces[input] = d.input_torque_nm;
            }
            SpeedBoundary::MotorSlip => {
                self.forces[input] = d.input_torque_nm;
                self.forces[output] = -d.output_torque_nm;
            }
        }
        if let Some(h) = self.held {
            self.inverse_masses[h] = 0.0;
        }
    }

    /// Bearings (diagonal: radial on x and y, axial on z), shafts and couplings (a spring
    /// between two coordinates), and the motor's slip damper:
    /// T_0 + c_slip (Omega - dtheta/dt) = T_0 - c_slip dphi/dt.
    fn fill_springs(&mut self) {
        let e = &self.elements;
        for a in &e.axial_bearings {
            let z = self.axial[a.body].expect("an axial bearing's body has an axial coordinate");
            self.stiffness[(z, z)] += a.stiffness_n_per_m;
            self.damping[(z, z)] += a.damping_n_s_per_m;
        }
        for t in &e.tilt_bearings {
            let x = self.tilt[t.body].expect("a tilting bearing's body tilts");
            for i in [x, x + 1] {
                self.stiffness[(i, i)] += t.stiffness_nm_per_rad;
                self.damping[(i, i)] += t.damping_nm_s_per_rad;
            }
        }
        for b in &e.bearings {
            let x = self.lateral[b.body].expect("a bearing's body moves laterally");
            for (axis, i) in [x, x + 1].into_iter().enumerate() {
                self.stiffness[(i, i)] += b.stiffness_n_per_m[axis];
                self.damping[(i, i)] += b.damping_n_s_per_m[axis];
            }
        }
        for s in &e.shafts {
            let [a, b] = s.ends;
            let mut links = vec![(
                self.rotation[a],
                self.rotation[b],
                s.torsional_stiffness_nm_per_rad,
                s.torsional_damping_nm_s_per_rad,
            )];
            if let (Some(xa), Some(xb)) = (self.lateral[a], self.lateral[b]) {
                if s.lateral_stiffness_n_per_m > 0.0 || s.lateral_damping_n_s_per_m > 0.0 {
                    for k in 0..2 {
                        links.push((
                            xa + k,
                            xb + k,
                            s.lateral_stiffness_n_per_m,
                            s.lateral_damping_n_s_per_m,
                        ));
                    }
                }
            }
            for (i, j, kc, cc) in links {
                for (m, val) in [(&mut self.stiffness, kc), (&mut self.damping, cc)] {
                    m[(i, i)] += val;
                    m[(j, j)] += val;
                    m[(i, j)] -= val;
                    m[(j, i)] -= val;
                }
            }
        }
        if e.drive.boundary == SpeedBoundary::MotorSlip {
            let i = self.rotation[e.drive.input];
            self.damping[(i, i)] += e.drive.slip_damping_nm_s_per_rad;
        }
    }

    /// Mesh deflection (paper eq. 2 without e_t, in the mesh's own frame):
    /// delta = r_pb phi_p - r_gb phi_g + d . (u_p - u_g), with the line of action
    /// d = sin(phi) e1 + s cos(phi) e2 and the tangent e = cos(phi) e1 - s sin(phi) e2,
    /// e1 the centre line (pinion to gear), e2 it turned by +90 deg, s the pinion's sense
    /// of rotation (+1 counter-clockwise). For the paper's layout (e1 = +x, s = +1):
    /// d = (sin phi, cos phi), e = (cos phi, -sin phi), as in eq. (1). A helical mesh
    /// whose bodies move axially adds a (z_p - z_g), a = `MeshLink::axial_gradient`
    /// (docs/MODEL.md 11.6); one whose bodies tilt its tilting terms (`tilt`,
    /// docs/MODEL.md 11.8).
    fn mesh_geometry(&self, m: usize) -> MeshGeometry {
        let link = &self.elements.meshes[m];
        let s = self.spin[link.pinion];
        let (sin_phi, cos_phi) = link.pressure_angle_rad.sin_cos();
        let (sin_psi, cos_psi) = link.centre_line_rad.sin_cos();
        let (e1, e2) = ([cos_psi, sin_psi], [-sin_psi, cos_psi]);
        let d = [
            sin_phi * e1[0] + s * cos_phi * e2[0],
            sin_phi * e1[1] + s * cos_phi * e2[1],
        ];
        let e = [
            cos_phi * e1[0] - s * sin_phi * e2[0],
            cos_phi * e1[1] - s * sin_phi * e2[1],
        ];
        let lateral = [self.lateral[link.pinion], self.lateral[link.gear]];
        let rotation = [self.rotation[link.pinion], self.rotation[link.gear]];
        let mut gradient = Vec::with_capacity(6);
        for (x, sign) in [(lateral[0], 1.0), (lateral[1], -1.0)] {
            if let Some(x) = x {
                gradient.push((x, sign * d[0]));
                gradient.push((x + 1, sign * d[1]));
            }
        }
        gradient.push((rotation[0], link.base_radius_m[0]));
        gradient.push((rotation[1], -link.base_radius_m[1]));
        let axial = [self.axial[link.pinion], self.axial[link.gear]];
        if link.axial_gradient != 0.0 {
            for (z, sign) in [(axial[0], 1.0), (axial[1], -1.0)] {
                if let Some(z) = z {
                    gradient.push((z, sign * link.axial_gradient));
                }
            }
        }
        let tilts = [self.tilt[link.pinion], self.tilt[link.gear]];
        gradient.extend(tilt::tilt_gradient(link, d, s, tilts));
        gradient.sort_by_key(|(i, _)| *i);
        MeshGeometry {
            gradient,
            line_of_action: d,
            tangent: e,
            lateral,
            rotation,
            axial,
            tilt: tilts,
        }
    }

    /// d tau / d q of mesh `m` ((coordinate, rad/rad) pairs): tau = a_g - a_p, the
    /// relative tilt of its gear and pinion about the plane of action's normal n = d x z
    /// (docs/MODEL.md 11.8); empty where neither body tilts.
    pub fn relative_tilt_gradient(&self, m: usize) -> Vec<(usize, f64)> {
        let (link, geo) = (&self.elements.meshes[m], &self.meshes[m]);
        tilt::relative_tilt_gradient(geo.line_of_action, self.spin[link.pinion], geo.tilt)
    }

    /// d delta / d q of mesh `m` as a dense vector.
    pub fn mesh_gradient(&self, m: usize) -> DVector<f64> {
        let mut g = DVector::zeros(self.n);
        for (i, v) in &self.meshes[m].gradient {
            g[*i] = *v;
        }
        g
    }

    /// K + sum_m k_m g_m g_m^T: the constant stiffness with mesh `m`'s spring k_m (N/m)
    /// along its line of action (a linearisation, e.g. at the mean mesh stiffness).
    pub fn stiffness_with_meshes(&self, k_mesh: &[f64]) -> DMatrix<f64> {
        self.with_meshes(&self.stiffness, k_mesh)
    }

    /// C + sum_m c_m g_m g_m^T with mesh `m`'s damper c_m (N s/m).
    pub fn damping_with_meshes(&self, c_mesh: &[f64]) -> DMatrix<f64> {
        self.with_meshes(&self.damping, c_mesh)
    }

    fn with_meshes(&self, base: &DMatrix<f64>, per_mesh: &[f64]) -> DMatrix<f64> {
        let mut out = base.clone();
        for (m, value) in per_mesh.iter().enumerate() {
            let g = &self.meshes[m].gradient;
            for (i, gi) in g {
                for (j, gj) in g {
                    out[(*i, *j)] += gi * gj * value;
                }
            }
        }
        out
    }

    /// Each coordinate's name and unit, for tables: `x_<body>`, `y_<body>` (m),
    /// `phi_<body>` (rad), the body's name without spaces (the single pair:
    /// `x_pinion`, ..., `phi_brake`).
    pub fn coordinate_names(&self) -> Vec<(String, &'static str)> {
        (0..self.n)
            .map(|i| {
                let (body, dof) = self.describe(i);
                let b = body.replace(' ', "");
                match dof {
                    Dof::X => (format!("x_{b}"), "m"),
                    Dof::Y => (format!("y_{b}"), "m"),
                    Dof::Rotation => (format!("phi_{b}"), "rad"),
                    Dof::Axial => (format!("z_{b}"), "m"),
                    Dof::TiltX => (format!("tilt_x_{b}"), "rad"),
                    Dof::TiltY => (format!("tilt_y_{b}"), "rad"),
                }
            })
            .collect()
    }

    /// Name of the body a coordinate belongs to and the coordinate's kind.
    pub fn describe(&self, coordinate: usize) -> (&str, Dof) {
        for (b, body) in self.elements.bodies.iter().enumerate() {
            if self.rotation[b] == coordinate {
                return (&body.name, Dof::Rotation);
            }
            if self.axial[b] == Some(coordinate) {
                return (&body.name, Dof::Axial);
            }
            if let Some(x) = self.tilt[b] {
                if coordinate == x || coordinate == x + 1 {
                    let dof = if coordinate == x {
                        Dof::TiltX
                    } else {
                        Dof::TiltY
                    };
                    return (&body.name, dof);
                }
            }
            if let Some(x) = self.lateral[b] {
                if coordinate == x || coordinate == x + 1 {
                    let dof = if coordinate == x { Dof::X } else { Dof::Y };
                    return (&body.name, dof);
                }
            }
        }
        ("", Dof::Rotation)
    }
}
