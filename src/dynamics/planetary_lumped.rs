//! The time-invariant lumped model of a planetary set (Lin & Parker, J. Vib. Acoust. 121
//! (1999) 316, "Analytical characterization of the unique properties of planetary gear
//! free vibration"): its mass and stiffness matrices, its natural frequencies and mode
//! shapes, each mode classified as Lin & Parker prove for equally spaced identical
//! planets, and its static response to a torque.
//!
//! Coordinates (docs/MODEL.md section 12.3), in the carrier's frame, all in metres: for
//! the carrier, ring and sun (in that order) x, y and u = r theta (r the base radius of
//! ring and sun, the carrier radius for the carrier); for each planet n the radial and
//! tangential displacements zeta_n, eta_n of its centre and u_n = r_bp theta_n. The
//! carrier turns at a constant speed in the mean; the centripetal and gyroscopic terms
//! of the rotating frame are neglected, as in Lin & Parker's modal analysis (valid while
//! the carrier's speed is small beside the lowest natural frequency), so M and K are
//! symmetric and constant.
//!
//! Deflections (Lin & Parker 1999, eqs. 1-3; psi_n the planet's angle, alpha_s = alpha_r
//! = alpha the operating pressure angles, psi_sn = psi_n - alpha_s, psi_rn = psi_n + alpha_r):
//!   sun mesh      d_sn = y_s cos psi_sn - x_s sin psi_sn - zeta_n sin alpha_s - eta_n cos alpha_s + u_s + u_n,
//!   ring mesh     d_rn = y_r cos psi_rn - x_r sin psi_rn + zeta_n sin alpha_r - eta_n cos alpha_r + u_r - u_n,
//!   planet pin    d_pn,zeta = x_c cos psi_n + y_c sin psi_n - zeta_n,
//!                 d_pn,eta  = -x_c sin psi_n + y_c cos psi_n + u_c - eta_n,
//! and the supports of carrier, ring and sun (k_j on x and y, k_ju = k_torsional / r_j^2 on
//! u). The strain energy is V = 1/2 sum k d^2, so K = sum k g g^T with g = grad d, m.
//! Mass: diag(m_j, m_j, I_j / r_j^2) per member and planet.

use crate::config::planetary::LumpedPlanetarySection;
use crate::remedy::Problems;
use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// Metres per millimetre.
const MM: f64 = 1e-3;

/// Indices of a member's three coordinates: carrier 0, ring 3, sun 6, planet n 9 + 3n.
const CARRIER: usize = 0;
const RING: usize = 3;
const SUN: usize = 6;
const PLANETS: usize = 9;

/// A mode's class (Lin & Parker 1999, for equally spaced identical planets).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModeClass {
    /// Central members only rotate; every planet moves alike. Multiplicity 1.
    Rotational,
    /// Central members only translate. Multiplicity 2.
    Translational,
    /// Central members at rest; only the planets move. Multiplicity N - 3.
    Planet,
    /// None of the three (unequal spacing, N < 3, or an accidental coincidence).
    Mixed,
}

impl ModeClass {
    /// The class's word in outputs.
    pub fn name(self) -> &'static str {
        match self {
            ModeClass::Rotational => "rotational",
            ModeClass::Translational => "translational",
            ModeClass::Planet => "planet",
            ModeClass::Mixed => "mixed",
        }
    }
}

/// A natural frequency with its shape and class.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetaryMode {
    /// Natural frequency, Hz.
    pub frequency_hz: f64,
    /// Mass-normalised shape (phi^T M phi = 1), in the module's coordinates.
    pub shape: Vec<f64>,
    /// Number of modes sharing this frequency (within [`DEGENERACY_REL_TOL`]).
    pub multiplicity: usize,
    /// Its class.
    pub class: ModeClass,
}

/// Two eigenvalues closer than this (relative) are one degenerate frequency: far above
/// the eigensolver's ~1e-13 and below any splitting a real difference between planets
/// makes (a 1e-6 relative change of a planet's stiffness splits them by ~1e-7).
pub const DEGENERACY_REL_TOL: f64 = 1e-8;

/// The lumped planetary model's parameters, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetaryLumped {
    /// Planet angles psi_n, rad.
    pub planet_angles_rad: Vec<f64>,
    /// Masses of carrier, ring, sun, planet, kg.
    pub mass_kg: [f64; 4],
    /// I / r^2 of carrier, ring, sun, planet, kg.
    pub inertia_over_r2_kg: [f64; 4],
    /// Base radii of ring, sun and planet and the carrier radius, m: [carrier, ring, sun, planet].
    pub radius_m: [f64; 4],
    /// Mean mesh stiffnesses sun-planet and ring-planet, N/m.
    pub mesh_stiffness_n_per_m: [f64; 2],
    /// Lateral support stiffness of carrier, ring, sun and the planet bearing, N/m.
    pub bearing_n_per_m: [f64; 4],
    /// Torsional support stiffness of carrier, ring, sun in u: k_t / r^2, N/m.
    pub torsional_n_per_m: [f64; 3],
    /// Operating pressure angle of both meshes, rad.
    pub pressure_angle_rad: f64,
}

/// The problems found while reading `[planetary.lumped]`, one message per key.
#[derive(Default)]
struct Checked {
    errs: Vec<String>,
}

impl Checked {
    /// `v` of `planetary.lumped.key`, a problem noted unless it is positive and finite
    /// (or zero when `zero_ok`: a free member).
    fn pos(&mut self, key: &str, v: f64, zero_ok: bool) -> f64 {
        if !(v.is_finite() && (v > 0.0 || (zero_ok && v == 0.0))) {
            let need = if zero_ok {
                "zero or positive"
            } else {
                "positive"
            };
            self.errs.push(format!(
                "`planetary.lumped.{key}` = {v} is invalid: it must be {need} and finite"
            ));
        }
        v
    }
}

/// The stiffnesses of `[planetary.lumped]` as written: the sun-planet and ring-planet
/// mesh stiffnesses (N/m), the bearings of carrier, ring, sun, planet (N/m) and the
/// torsional supports of carrier, ring, sun (N m/rad), problems noted in `c`.
fn stiffnesses(l: &LumpedPlanetarySection, c: &mut Checked) -> ([f64; 2], [f64; 4], [f64; 3]) {
    let mesh = [
        c.pos(
            "mesh_stiffness_sun_planet_n_per_m",
            l.mesh_stiffness_sun_planet_n_per_m,
            false,
        ),
        c.pos(
            "mesh_stiffness_ring_planet_n_per_m",
            l.mesh_stiffness_ring_planet_n_per_m,
            false,
        ),
    ];
    let bearing_n_per_m = [
        c.pos(
            "bearing_stiffness_carrier_n_per_m",
            l.bearing_stiffness_carrier_n_per_m,
            true,
        ),
        c.pos(
            "bearing_stiffness_ring_n_per_m",
            l.bearing_stiffness_ring_n_per_m,
            true,
        ),
        c.pos(
            "bearing_stiffness_sun_n_per_m",
            l.bearing_stiffness_sun_n_per_m,
            true,
        ),
        c.pos(
            "bearing_stiffness_planet_n_per_m",
            l.bearing_stiffness_planet_n_per_m,
            false,
        ),
    ];
    let torsional_nm = [
        c.pos(
            "torsional_stiffness_carrier_nm_per_rad",
            l.torsional_stiffness_carrier_nm_per_rad,
            true,
        ),
        c.pos(
            "torsional_stiffness_ring_nm_per_rad",
            l.torsional_stiffness_ring_nm_per_rad,
            true,
        ),
        c.pos(
            "torsional_stiffness_sun_nm_per_rad",
            l.torsional_stiffness_sun_nm_per_rad,
            true,
        ),
    ];
    (mesh, bearing_n_per_m, torsional_nm)
}

impl PlanetaryLumped {
    /// From `[planetary.lumped]` and the planet angles (rad); every key that is not a
    /// positive finite number (torsional supports may be 0: a free member), named.
    pub fn from_section(l: &LumpedPlanetarySection, angles: Vec<f64>) -> Result<Self, Problems> {
        let mut c = Checked::default();
        let mut pos = |key: &str, v: f64, zero_ok: bool| c.pos(key, v, zero_ok);
        let radius_m = [
            pos("carrier_radius_mm", l.carrier_radius_mm, false) * MM,
            pos("base_radius_ring_mm", l.base_radius_ring_mm, false) * MM,
            pos("base_radius_sun_mm", l.base_radius_sun_mm, false) * MM,
            pos("base_radius_planet_mm", l.base_radius_planet_mm, false) * MM,
        ];
        let mass_kg = [
            pos("mass_carrier_kg", l.mass_carrier_kg, false),
            pos("mass_ring_kg", l.mass_ring_kg, false),
            pos("mass_sun_kg", l.mass_sun_kg, false),
            pos("mass_planet_kg", l.mass_planet_kg, false),
        ];
        let inertia = [
            pos("inertia_carrier_kg_m2", l.inertia_carrier_kg_m2, false),
            pos("inertia_ring_kg_m2", l.inertia_ring_kg_m2, false),
            pos("inertia_sun_kg_m2", l.inertia_sun_kg_m2, false),
            pos("inertia_planet_kg_m2", l.inertia_planet_kg_m2, false),
        ];
        let (mesh, bearing_n_per_m, torsional_nm) = stiffnesses(l, &mut c);
        let alpha = l.pressure_angle_deg;
        if !(alpha.is_finite() && alpha > 0.0 && alpha < 45.0) {
            c.errs.push(format!("`planetary.lumped.pressure_angle_deg` = {alpha} is invalid: it must lie in (0, 45)"));
        }
        if !c.errs.is_empty() {
            return Err(c.errs.into());
        }
        Ok(Self {
            planet_angles_rad: angles,
            mass_kg,
            inertia_over_r2_kg: std::array::from_fn(|i| inertia[i] / radius_m[i].powi(2)),
            radius_m,
            mesh_stiffness_n_per_m: mesh,
            bearing_n_per_m,
            torsional_n_per_m: std::array::from_fn(|i| torsional_nm[i] / radius_m[i].powi(2)),
            pressure_angle_rad: alpha.to_radians(),
        })
    }

    /// Number of degrees of freedom, 3 (N + 3).
    pub fn dofs(&self) -> usize {
        PLANETS + 3 * self.planet_angles_rad.len()
    }

    /// The diagonal of M: (m, m, I / r^2) per member and planet, kg.
    pub fn mass_diagonal(&self) -> Vec<f64> {
        let mut m = Vec::with_capacity(self.dofs());
        for j in 0..3 {
            m.extend([self.mass_kg[j], self.mass_kg[j], self.inertia_over_r2_kg[j]]);
        }
        for _ in &self.planet_angles_rad {
            m.extend([self.mass_kg[3], self.mass_kg[3], self.inertia_over_r2_kg[3]]);
        }
        m
    }

    /// The gradients g of every deflection with its stiffness, (k N/m, g): the module's
    /// deflections, planet by planet, then the supports.
    pub fn springs(&self) -> Vec<(f64, DVector<f64>)> {
        let n = self.dofs();
        let a = self.pressure_angle_rad;
        let (sa, ca) = a.sin_cos();
        let mut out = Vec::new();
        let unit = |entries: &[(usize, f64)]| {
            let mut g = DVector::zeros(n);
            for (i, v) in entries {
                g[*i] += v;
            }
            g
        };
        for (p, psi) in self.planet_angles_rad.iter().enumerate() {
            let q = PLANETS + 3 * p;
            let (ss, cs) = (psi - a).sin_cos();
            let (sr, cr) = (psi + a).sin_cos();
            let (sp, cp) = psi.sin_cos();
            let [k_sun, k_ring] = self.mesh_stiffness_n_per_m;
            let k_pin = self.bearing_n_per_m[3];
            out.push((
                k_sun,
                unit(&[
                    (SUN, -ss),
                    (SUN + 1, cs),
                    (q, -sa),
                    (q + 1, -ca),
                    (SUN + 2, 1.0),
                    (q + 2, 1.0),
                ]),
            ));
            out.push((
                k_ring,
                unit(&[
                    (RING, -sr),
                    (RING + 1, cr),
                    (q, sa),
                    (q + 1, -ca),
                    (RING + 2, 1.0),
                    (q + 2, -1.0),
                ]),
            ));
            out.push((k_pin, unit(&[(CARRIER, cp), (CARRIER + 1, sp), (q, -1.0)])));
            out.push((
                k_pin,
                unit(&[
                    (CARRIER, -sp),
                    (CARRIER + 1, cp),
                    (CARRIER + 2, 1.0),
                    (q + 1, -1.0),
                ]),
            ));
        }
        for (j, base) in [CARRIER, RING, SUN].into_iter().enumerate() {
            out.push((self.bearing_n_per_m[j], unit(&[(base, 1.0)])));
            out.push((self.bearing_n_per_m[j], unit(&[(base + 1, 1.0)])));
            out.push((self.torsional_n_per_m[j], unit(&[(base + 2, 1.0)])));
        }
        out
    }

    /// The stiffness matrix K = sum k g g^T, N/m.
    pub fn stiffness(&self) -> DMatrix<f64> {
        let n = self.dofs();
        let mut k = DMatrix::zeros(n, n);
        for (kv, g) in self.springs() {
            k.ger(kv, &g, &g, 1.0);
        }
        k
    }

    /// Static displacements under generalised forces `f` (N, on the module's
    /// coordinates: a torque T on member j is T / r_j on its u), m; `None` when K is
    /// singular (a member with no path to ground).
    pub fn static_response(&self, f: &DVector<f64>) -> Option<DVector<f64>> {
        self.stiffness().cholesky().map(|c| c.solve(f))
    }

    /// The load of each sun-planet and ring-planet mesh in the displacement `q`, N:
    /// k d for every planet, ([sun meshes], [ring meshes]).
    pub fn mesh_loads(&self, q: &DVector<f64>) -> (Vec<f64>, Vec<f64>) {
        let springs = self.springs();
        let per = |offset: usize| {
            (0..self.planet_angles_rad.len())
                .map(|p| {
                    let (k, g) = &springs[4 * p + offset];
                    k * g.dot(q)
                })
                .collect()
        };
        (per(0), per(1))
    }

    /// Natural frequencies (ascending), mass-normalised shapes and classes: K phi =
    /// omega^2 M phi solved as the symmetric M^-1/2 K M^-1/2 (M diagonal).
    pub fn modes(&self) -> Vec<PlanetaryMode> {
        let m = self.mass_diagonal();
        let s: Vec<f64> = m.iter().map(|x| 1.0 / x.sqrt()).collect();
        let k = self.stiffness();
        let n = m.len();
        let a = DMatrix::from_fn(n, n, |i, j| s[i] * k[(i, j)] * s[j]);
        let eig = SymmetricEigen::new(a);
        let mut idx: Vec<usize> = (0..n).collect();
        idx.sort_by(|x, y| eig.eigenvalues[*x].total_cmp(&eig.eigenvalues[*y]));
        let lam: Vec<f64> = idx.iter().map(|i| eig.eigenvalues[*i].max(0.0)).collect();
        let shapes: Vec<Vec<f64>> = idx
            .iter()
            .map(|i| (0..n).map(|r| eig.eigenvectors[(r, *i)] * s[r]).collect())
            .collect();
        let mut out = Vec::with_capacity(n);
        let mut start = 0;
        while start < n {
            let scale = lam[n - 1].max(f64::MIN_POSITIVE);
            let mut end = start + 1;
            while end < n
                && (lam[end] - lam[start]) <= DEGENERACY_REL_TOL * lam[end].max(1e-6 * scale)
            {
                end += 1;
            }
            let class = classify(&shapes[start..end], &m);
            for i in start..end {
                out.push(PlanetaryMode {
                    frequency_hz: lam[i].sqrt() / (2.0 * std::f64::consts::PI),
                    shape: shapes[i].clone(),
                    multiplicity: end - start,
                    class,
                });
            }
            start = end;
        }
        out
    }
}

/// A central member's motion below this share of a mode's kinetic energy counts as none:
/// the eigenvectors' rounding (~1e-13) is far below it, a real participation far above.
const AT_REST_SHARE: f64 = 1e-9;

/// Lin & Parker's class of a (possibly degenerate) mode: from the kinetic-energy shares of
/// the central members' translations and rotations in every shape of the eigenspace.
fn classify(shapes: &[Vec<f64>], m: &[f64]) -> ModeClass {
    let share = |shape: &[f64], idx: &[usize]| -> f64 {
        let total: f64 = shape.iter().zip(m).map(|(v, mi)| mi * v * v).sum();
        idx.iter()
            .map(|i| m[*i] * shape[*i] * shape[*i])
            .sum::<f64>()
            / total
    };
    let translation = [CARRIER, CARRIER + 1, RING, RING + 1, SUN, SUN + 1];
    let rotation = [CARRIER + 2, RING + 2, SUN + 2];
    let none = |idx: &[usize]| shapes.iter().all(|s| share(s, idx) < AT_REST_SHARE);
    match (none(&translation), none(&rotation)) {
        (true, true) => ModeClass::Planet,
        (true, false) => ModeClass::Rotational,
        (false, true) => ModeClass::Translational,
        (false, false) => ModeClass::Mixed,
    }
}
