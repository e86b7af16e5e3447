//! Mesh stiffness of an internal pair (a planet in a ring) by the potential energy method:
//! the planet's tooth as the external teeth (`potential_energy::ToothBeam`), the ring's
//! tooth as a cantilever of its own profile, thicker towards its root (outer) circle, and
//! the linearised Hertz stiffness of paper eq. 11.
//!
//! Sources: the energy method of Yang & Sun (1985) and Tian (2004) as in
//! `potential_energy`; its adaptation to the ring's tooth by Chen & Shao, Mech. Mach.
//! Theory 62 (2013) 63 ("Mesh stiffness of an internal spur gear pair with ring gear rim
//! deformation") and Liang, Zuo & Pandey, Mech. Mach. Theory 76 (2014) 20 (planetary gear
//! set mesh stiffness), written here from the ring's involute (geometry::internal).
//!
//! Assumptions (docs/MODEL.md section 12.2): the ring's rim is rigid (no foundation or rim
//! term for its teeth: Chen & Shao's rim deformation is left out, so a thin-rimmed ring is
//! stiffer here than in reality); the ring's tooth is clamped at its root circle and its
//! involute flank is followed down to that circle (the root fillet is not modelled, as for
//! external teeth whose root lies above the base circle); the planet's fillet foundation
//! (Sainsot et al. 2004) is optional, as in the external pair.
//!
//! Ring tooth frame: Y along the tooth's centreline, radially outwards from the ring's
//! centre; at radius r the tooth's half angle is theta(r) (`InternalGear::half_tooth_angle_rad`),
//! its half-thickness h = r sin(theta), its height Y = r cos(theta), and, since r dtheta/dr =
//! tan(alpha_r) on an involute, dY/dr = cos(theta + alpha_r) / cos(alpha_r). A contact at
//! radius r_c loads the tooth along the line of action, which makes the angle
//! beta = alpha_rc + theta_c with the perpendicular to the centreline (alpha_rc the
//! pressure angle at r_c); its radial component points outwards, towards the root, and
//! compresses the tooth (derivation in docs/MODEL.md 12.2). With d = Y - Y_c the distance
//! from the contact towards the root, per unit force:
//!   M = cos(beta) d - sin(beta) h_c,
//!   1/k_b = int M^2 / (E I) dY,  1/k_s = int 1.2 cos^2(beta) / (G A) dY,
//!   1/k_a = int sin^2(beta) / (E A) dY,  from Y_c to the root circle's Y_f,
//! I = (2h)^3 b / 12, A = 2 h b: the external tooth's integrals with alpha_1 -> beta.

use super::fillet::FilletFoundation;
use super::potential_energy::{
    hertz_stiffness_n_per_m, ElasticPair, GaussLegendre, ToothBeam, ToothCompliance,
};
use crate::geometry::internal::{InternalGear, InternalPair};

/// Timoshenko shear correction factor of a rectangular section (Yang & Sun 1985).
const SHEAR_FACTOR: f64 = 1.2;

/// A ring tooth as a cantilever clamped at the ring's root circle.
#[derive(Debug, Clone, PartialEq)]
pub struct RingToothBeam {
    ring: InternalGear,
    /// Face width b, m.
    pub face_width_m: f64,
    /// Young's modulus E, Pa.
    pub youngs_modulus_pa: f64,
    /// Shear modulus G = E / (2 (1 + nu)), Pa.
    pub shear_modulus_pa: f64,
}

impl RingToothBeam {
    /// The tooth of `ring`, face width b (m), Young's modulus E (Pa), Poisson ratio nu.
    pub fn new(ring: &InternalGear, face_width_m: f64, e_pa: f64, nu: f64) -> Self {
        Self {
            ring: ring.clone(),
            face_width_m,
            youngs_modulus_pa: e_pa,
            shear_modulus_pa: e_pa / (2.0 * (1.0 + nu)),
        }
    }

    /// (h, Y) of the flank point at radius r, m: (r sin theta, r cos theta).
    pub fn flank_point(&self, r_m: f64) -> (f64, f64) {
        let (s, c) = self.ring.half_tooth_angle_rad(r_m).sin_cos();
        (r_m * s, r_m * c)
    }

    /// beta = alpha_rc + theta_c: the angle of the line of action to the perpendicular of
    /// the centreline at the contact of radius of curvature rho2 (m) on the ring's flank.
    pub fn load_angle_rad(&self, rho2_m: f64) -> f64 {
        let rb = self.ring.base_radius_m;
        let r_c = rb.hypot(rho2_m);
        (rho2_m / rb).atan() + self.ring.half_tooth_angle_rad(r_c)
    }

    /// Bending, shear and axial compliances for a contact at the ring's radius of
    /// curvature rho2 (m), with the shared 20-point Gauss rule.
    pub fn compliance(&self, rho2_m: f64) -> ToothCompliance {
        self.compliance_with_rule(rho2_m, GaussLegendre::default_rule())
    }

    /// As [`Self::compliance`] with a given rule, integrated in r from the contact to the
    /// root circle (the module's equations).
    pub(crate) fn compliance_with_rule(
        &self,
        rho2_m: f64,
        rule: &GaussLegendre,
    ) -> ToothCompliance {
        let b = self.face_width_m;
        self.compliance_with_section_split(rho2_m, rule, &[], |h, _| {
            (2.0 * h * b, 2.0 * h * h * h * b / 3.0)
        })
    }

    /// Half-thickness h and height Y (m) of the section at the root circle, where the
    /// tooth is clamped (its thickest section, and where a root crack starts).
    pub fn root_section(&self) -> (f64, f64) {
        self.flank_point(self.ring.root_radius_m)
    }

    /// Half-thickness h and height Y (m) of the flank's tip corner (the tip circle).
    pub fn tip_section(&self) -> (f64, f64) {
        self.flank_point(self.ring.tip_radius_m)
    }

    /// The flank's radius (m) at its own radius of curvature rho2 (m): sqrt(r_b^2 + rho2^2).
    pub fn radius_at_m(&self, rho2_m: f64) -> f64 {
        self.ring.base_radius_m.hypot(rho2_m)
    }

    /// As [`Self::compliance_with_rule`] with the cross-section at each height given by
    /// `section(h, Y) -> (area m^2, second moment m^4)` (h the flank's half-thickness, Y
    /// the height, m) instead of the full 2h x b rectangle: a cracked or pitted ring tooth
    /// (`stiffness::ring_tooth_faults`); the moment arm stays measured from the
    /// centreline, as for the external tooth (`ToothBeam::compliance_with_section_split`).
    /// The integral from the contact to the root circle is split at the radii
    /// `breaks_m` (ascending) where the section jumps, so that each piece is smooth.
    pub(crate) fn compliance_with_section_split(
        &self,
        rho2_m: f64,
        rule: &GaussLegendre,
        breaks_m: &[f64],
        section: impl Fn(f64, f64) -> (f64, f64),
    ) -> ToothCompliance {
        let rb = self.ring.base_radius_m;
        let r_c = rb.hypot(rho2_m);
        let beta = self.load_angle_rad(rho2_m);
        let (sb, cb) = beta.sin_cos();
        let (h_c, y_c) = self.flank_point(r_c);
        let (e, g) = (self.youngs_modulus_pa, self.shear_modulus_pa);
        let per_dr = |r: f64| {
            let alpha_r = (rb / r).acos();
            let theta = self.ring.half_tooth_angle_rad(r);
            let (h, y) = (r * theta.sin(), r * theta.cos());
            let dy_dr = (theta + alpha_r).cos() / alpha_r.cos();
            let m = cb * (y - y_c) - sb * h_c;
            let (area, inertia) = section(h, y);
            [
                m * m / (e * inertia) * dy_dr,
                SHEAR_FACTOR * cb * cb / (g * area) * dy_dr,
                sb * sb / (e * area) * dy_dr,
            ]
        };
        let root = self.ring.root_radius_m;
        debug_assert!(breaks_m.windows(2).all(|w| w[0] <= w[1]));
        let ends = breaks_m
            .iter()
            .copied()
            .filter(|r| *r > r_c && *r < root)
            .chain(std::iter::once(root));
        let (mut sum, mut from) = ([0.0; 3], r_c);
        for to in ends {
            // (0 + x is x bit for bit: one piece is the healthy tooth's integral as before.)
            let piece = rule.integrate3(from, to, per_dr);
            for k in 0..3 {
                sum[k] += piece[k];
            }
            from = to;
        }
        ToothCompliance {
            bending_m_per_n: sum[0],
            shear_m_per_n: sum[1],
            axial_m_per_n: sum[2],
        }
    }
}

/// Mesh stiffness of a planet-ring pair, evaluated directly (no table: the lumped model
/// needs the mean, and a contact costs two 20-point integrals).
#[derive(Debug, Clone)]
pub struct InternalMeshStiffness {
    pair: InternalPair,
    planet: ToothBeam,
    ring: RingToothBeam,
    planet_fillet: Option<FilletFoundation>,
    hertz_m_per_n: f64,
}

impl InternalMeshStiffness {
    /// The pair's stiffness model; `elastic`'s pinion is the planet, its gear the ring;
    /// `planet_foundation` adds the planet's fillet foundation (Sainsot et al. 2004, at the
    /// fillet-junction root angle, extrapolated outside its fit like the external pair's
    /// default).
    pub fn new(pair: &InternalPair, elastic: &ElasticPair, planet_foundation: bool) -> Self {
        let b = pair.face_width_m;
        let planet = ToothBeam::new(&pair.planet, b, elastic.e_pinion_pa, elastic.nu_pinion);
        let planet_fillet = planet_foundation.then(|| {
            FilletFoundation::new(
                "planet",
                pair.planet.root_radius_m,
                pair.planet.bore_radius_m,
                pair.planet.fillet_junction_half_angle_rad,
                elastic.e_pinion_pa,
                b,
            )
        });
        Self {
            pair: pair.clone(),
            planet,
            ring: RingToothBeam::new(&pair.ring, b, elastic.e_gear_pa, elastic.nu_gear),
            planet_fillet,
            hertz_m_per_n: 1.0 / hertz_stiffness_n_per_m(b, elastic),
        }
    }

    /// The ring's tooth beam.
    pub fn ring_beam(&self) -> &RingToothBeam {
        &self.ring
    }

    /// The planet's tooth beam.
    pub fn planet_beam(&self) -> &ToothBeam {
        &self.planet
    }

    /// The pair's Hertz compliance 1/k_h over the full face width, m/N (paper eq. 11).
    pub fn hertz_compliance_m_per_n(&self) -> f64 {
        self.hertz_m_per_n
    }

    /// The pair's geometry.
    pub fn pair(&self) -> &InternalPair {
        &self.pair
    }

    /// Single-pair compliance at the planet's radius of curvature rho1 (m):
    /// 1/k_pair = 1/k_h + (planet 1/k_b + 1/k_s + 1/k_a [+ 1/k_f]) + ring's, m/N.
    pub fn pair_compliance_m_per_n(&self, rho1_m: f64) -> f64 {
        let rho2 = self.pair.rho_ring(rho1_m);
        let foundation = self.planet_fillet.as_ref().map_or(0.0, |f| {
            let u_f = self.planet.force_centreline_crossing_m(rho1_m) - self.planet.root_radius_m;
            f.compliance_m_per_n(u_f, self.planet.contact_angle_rad(rho1_m))
        });
        self.hertz_m_per_n
            + self.planet.compliance(rho1_m).total_m_per_n()
            + self.ring.compliance(rho2).total_m_per_n()
            + foundation
    }

    /// Single-pair stiffness k_pair(rho1), N/m.
    pub fn pair_stiffness_n_per_m(&self, rho1_m: f64) -> f64 {
        1.0 / self.pair_compliance_m_per_n(rho1_m)
    }

    /// Total stiffness at mesh phase `phase_rad` (planet rotation relative to the carrier
    /// since a pair entered contact): the pairs in contact in parallel, N/m.
    pub fn total_stiffness_n_per_m(&self, phase_rad: f64) -> f64 {
        self.pair
            .pairs_in_contact(phase_rad)
            .map(|rho| self.pair_stiffness_n_per_m(rho))
            .sum()
    }

    /// Mean of the total stiffness over a mesh period, N/m: (1/p_b) int k_pair d rho1 over
    /// the path of contact (each pair sweeps one base pitch per period), by a 40-point
    /// Gauss rule on the path (k_pair is smooth on it).
    pub fn mean_stiffness_n_per_m(&self) -> f64 {
        let rule = GaussLegendre::new(40);
        let v = rule.integrate3(self.pair.rho_start_m, self.pair.rho_end_m, |rho| {
            [self.pair_stiffness_n_per_m(rho), 0.0, 0.0]
        });
        v[0] / self.pair.base_pitch_m
    }
}
