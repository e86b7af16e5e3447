//! The internal (ring) gear and the internal pair of a planet in a ring: the ring's
//! involute and tooth form, the pair's operating pressure angle, path of contact and
//! contact ratio.
//!
//! Sources: ISO 21771 (cylindrical gears, internal gears with a negative number of teeth;
//! here counted positive with the signs written out); Litvin & Fuentes, *Gear Geometry and
//! Applied Theory* (2004), ch. 10 (internal involute gearing).
//!
//! The ring's tooth space is the tooth of an external gear of z_r teeth (its "space gear"):
//! the ring's flanks are that gear's involutes, concave seen from the planet, and the
//! ring's tooth is thicker at its root (outer) circle than at its tip (inner) circle.
//! Profile shift x_r keeps ISO 21771's sign: positive x_r thickens the ring's tooth at the
//! reference circle, s = m (pi/2 + 2 x_r tan alpha), and moves its tip circle inwards (the
//! space gear's shift is -x_r). (Catalogues such as KHK's count the internal gear's shift
//! with the other sign.)
//!
//! Positions on the line of action are measured as the planet's radius of curvature rho1,
//! from the planet's tangency point N1. Both tangency points lie on the same side of the
//! contact, the ring's N2 beyond N1: the ring's radius of curvature is rho2 = rho1 + N1N2,
//! N1N2 = a_w sin(alpha_w) = (r_b2 - r_b1) tan(alpha_w).

use super::involute::{inv, inv_inverse};
use super::pair::{Gear, GeometryError};
use std::f64::consts::PI;

/// A ring gear (internal, spur) as a pinion-type cutter with the basic rack's dimensions
/// generates it (SI units; radii from the ring's centre).
#[derive(Debug, Clone, PartialEq)]
pub struct InternalGear {
    /// Number of teeth z_r (positive).
    pub teeth: usize,
    /// Profile shift coefficient x_r (ISO 21771 sign, see the module's doc).
    pub profile_shift: f64,
    /// Reference radius r = m z / 2, m.
    pub pitch_radius_m: f64,
    /// Base radius r_b = r cos(alpha), m.
    pub base_radius_m: f64,
    /// Tip radius (inner circle) r_a = r - m (h_a* + x_r), m (ISO 21771 with z < 0).
    pub tip_radius_m: f64,
    /// Root radius (outer circle) r_f = r + m (h_f* - x_r), m.
    pub root_radius_m: f64,
    /// Half the angular width of a tooth space at the base circle, rad: the space gear's
    /// psi_b = pi/(2z) - 2 x_r tan(alpha)/z + inv(alpha).
    pub half_space_base_angle_rad: f64,
}

impl InternalGear {
    /// The ring of `z` teeth, shift `x` (ISO sign), module `m` (m), pressure angle
    /// `alpha` (rad), addendum and dedendum coefficients h_a*, h_f*.
    pub fn generated(z: usize, x: f64, m: f64, alpha: f64, h_a: f64, h_f: f64) -> Self {
        let zf = z as f64;
        let r = m * zf / 2.0;
        Self {
            teeth: z,
            profile_shift: x,
            pitch_radius_m: r,
            base_radius_m: r * alpha.cos(),
            tip_radius_m: r - m * (h_a + x),
            root_radius_m: r + m * (h_f - x),
            half_space_base_angle_rad: PI / (2.0 * zf) - 2.0 * x * alpha.tan() / zf + inv(alpha),
        }
    }

    /// Half the angular thickness of a ring tooth at radius r >= r_b, rad:
    /// theta(r) = pi/z - psi_b + inv(alpha_r), cos(alpha_r) = r_b / r (half a pitch
    /// minus half the space, ISO 21771). Grows with r: the tooth thickens towards its root.
    pub fn half_tooth_angle_rad(&self, r_m: f64) -> f64 {
        let a = (self.base_radius_m / r_m).clamp(-1.0, 1.0).acos();
        PI / self.teeth as f64 - self.half_space_base_angle_rad + inv(a)
    }

    /// Tooth thickness (arc) at radius r, m: s(r) = 2 r theta(r).
    pub fn thickness_at_radius_m(&self, r_m: f64) -> f64 {
        2.0 * r_m * self.half_tooth_angle_rad(r_m)
    }

    /// Radius of curvature of the ring's flank at its tip circle, m (the smallest on the
    /// flank that meshes): sqrt(r_a^2 - r_b^2).
    pub fn tip_rho_m(&self) -> f64 {
        (self.tip_radius_m.powi(2) - self.base_radius_m.powi(2))
            .max(0.0)
            .sqrt()
    }
}

/// A planet meshing inside a ring.
#[derive(Debug, Clone, PartialEq)]
pub struct InternalPair {
    /// Module m, m.
    pub module_m: f64,
    /// Reference pressure angle alpha, rad.
    pub pressure_angle_rad: f64,
    /// Face width b, m.
    pub face_width_m: f64,
    /// The planet (external gear 1).
    pub planet: Gear,
    /// The ring (internal gear 2).
    pub ring: InternalGear,
    /// Operating centre distance a_w (ring centre to planet centre), m.
    pub centre_distance_m: f64,
    /// Operating pressure angle alpha_w, rad: cos(alpha_w) = (r_b2 - r_b1) / a_w.
    pub operating_pressure_angle_rad: f64,
    /// N1N2 = a_w sin(alpha_w), m.
    pub loa_length_m: f64,
    /// Lower end of the path of contact in rho1 (the ring's tip meets the planet's flank), m.
    pub rho_start_m: f64,
    /// Upper end of the path in rho1 (the planet's tip), m.
    pub rho_end_m: f64,
    /// rho1 at the pitch point, r_b1 tan(alpha_w), m.
    pub rho_pitch_m: f64,
    /// Base pitch p_b = 2 pi r_b1 / z1, m.
    pub base_pitch_m: f64,
    /// Transverse contact ratio (rho_end - rho_start) / p_b; ISO 21771 for internal pairs:
    /// [sqrt(r_a1^2 - r_b1^2) - sqrt(r_a2^2 - r_b2^2) + a_w sin(alpha_w)] / p_b.
    pub contact_ratio: f64,
}

/// Zero-backlash operating pressure angle of an internal pair, rad (ISO 21771 with z_2,
/// x_2 of the internal gear negative, here written with both counted positive):
/// inv(alpha_w) = inv(alpha) - 2 tan(alpha) (x_r + x_p) / (z_r - z_p).
pub fn internal_operating_angle_rad(alpha: f64, z_p: f64, x_p: f64, z_r: f64, x_r: f64) -> f64 {
    inv_inverse(inv(alpha) - 2.0 * alpha.tan() * (x_r + x_p) / (z_r - z_p))
}

/// Metres per millimetre.
const MM: f64 = 1e-3;

impl InternalPair {
    /// The pair of `planet` in `ring` at centre distance `centre_distance_m` (the carrier's
    /// radius), with module `module_m` (m), pressure angle `alpha` (rad), face width (m).
    /// Every reason it cannot mesh, at once, as messages.
    pub fn new(
        planet: &Gear,
        ring: InternalGear,
        module_m: f64,
        alpha: f64,
        face_width_m: f64,
        centre_distance_m: f64,
    ) -> Result<Self, GeometryError> {
        let mut errors = Vec::new();
        let (rb1, rb2) = (planet.base_radius_m, ring.base_radius_m);
        if rb2 - rb1 <= 0.0 || centre_distance_m <= rb2 - rb1 {
            errors.push(format!(
                "the ring (base radius {:.4} mm) cannot hold the planet (base radius {:.4} mm) at the centre distance {:.4} mm",
                rb2 / MM,
                rb1 / MM,
                centre_distance_m / MM
            ));
            return Err(GeometryError(errors));
        }
        let alpha_w = ((rb2 - rb1) / centre_distance_m).acos();
        let loa = centre_distance_m * alpha_w.sin();
        let base_pitch = 2.0 * PI * rb1 / planet.teeth as f64;
        let rho_end = planet.tip_rho_m();
        let rho_start = ring.tip_rho_m() - loa;
        let eps = (rho_end - rho_start) / base_pitch;
        if ring.tip_radius_m <= rb2 {
            errors.push(format!(
                "the ring's tip circle (radius {:.4} mm) lies inside its base circle ({:.4} mm): its flanks are not involutes down to the tip (raise `planetary.teeth_ring`, about 2 / (1 - cos alpha) teeth or more, or lower its addendum)",
                ring.tip_radius_m / MM,
                rb2 / MM
            ));
        }
        if rho_start < planet.form_rho_m.max(0.0) {
            errors.push(format!(
                "tip interference: the ring's tip meets the planet at rho1 = {:.3} mm, below the planet's lowest involute point {:.3} mm (check `planetary.profile_shift_ring` and the addendum)",
                rho_start / MM,
                planet.form_rho_m.max(0.0) / MM
            ));
        }
        if centre_distance_m + planet.tip_radius_m >= ring.root_radius_m {
            errors.push(format!(
                "the planet's tip circle reaches the ring's root circle (no radial clearance: {:.4} mm + {:.4} mm >= {:.4} mm)",
                centre_distance_m / MM,
                planet.tip_radius_m / MM,
                ring.root_radius_m / MM
            ));
        }
        if ring.thickness_at_radius_m(ring.tip_radius_m) <= 0.0 {
            errors.push("the ring's teeth are pointed at their tip circle: lower `planetary.profile_shift_ring`'s magnitude".into());
        }
        if eps < 1.0 {
            errors.push(format!(
                "the ring-planet contact ratio {eps:.4} is below 1: the pair cannot mesh continuously"
            ));
        }
        if !errors.is_empty() {
            return Err(GeometryError(errors));
        }
        Ok(Self {
            module_m,
            pressure_angle_rad: alpha,
            face_width_m,
            planet: planet.clone(),
            ring,
            centre_distance_m,
            operating_pressure_angle_rad: alpha_w,
            loa_length_m: loa,
            rho_start_m: rho_start,
            rho_end_m: rho_end,
            rho_pitch_m: rb1 * alpha_w.tan(),
            base_pitch_m: base_pitch,
            contact_ratio: eps,
        })
    }

    /// The ring's radius of curvature at the contact where the planet's is rho1, m:
    /// rho2 = rho1 + N1N2 (both tangency points on one side of the contact).
    pub fn rho_ring(&self, rho1_m: f64) -> f64 {
        rho1_m + self.loa_length_m
    }

    /// Mesh period in planet rotation relative to the carrier, rad: 2 pi / z_p.
    pub fn mesh_angle_rad(&self) -> f64 {
        2.0 * PI / self.planet.teeth as f64
    }

    /// Largest number of tooth pairs in contact at once: ceil(epsilon).
    pub fn max_pairs(&self) -> usize {
        self.contact_ratio.ceil() as usize
    }

    /// Positions rho1 (m) of the pairs in contact at mesh phase `phase_rad` (planet
    /// rotation since pair 0 entered contact at the path's lower end): pair k entered k
    /// mesh periods earlier, rho1 = rho_start + r_b1 phase + k p_b <= rho_end.
    pub fn pairs_in_contact(&self, phase_rad: f64) -> impl Iterator<Item = f64> + '_ {
        let period = self.mesh_angle_rad();
        let base = (phase_rad / period).floor() * period;
        let rho0 = self.rho_start_m + self.planet.base_radius_m * (phase_rad - base);
        (0..self.max_pairs())
            .map(move |k| rho0 + k as f64 * self.base_pitch_m)
            .filter(move |rho| *rho <= self.rho_end_m + 1e-15)
    }
}
