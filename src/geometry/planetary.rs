//! A simple spur planetary set: sun, N identical planets on a carrier, ring. Its two
//! meshes per planet (sun-planet external, ring-planet internal), the assembly and
//! spacing conditions, the kinematics (Willis), and the relative phases of every mesh
//! (Parker & Lin 2004).
//!
//! Conventions: planet angles psi_n are measured on the carrier from planet 1
//! (psi_1 = 0), in the direction of the sun's rotation relative to the carrier. Speeds are
//! signed, one positive sense for all members.

use super::internal::{internal_operating_angle_rad, InternalGear, InternalPair};
use super::involute::inv;
use super::pair::{GearPair, GeometryError};
use crate::config::case::{Derivable, GearSection};
use crate::config::planetary::{Member, PlanetarySection};
use std::f64::consts::PI;

/// Metres per millimetre.
const MM: f64 = 1e-3;

/// How far (in ring-planet module units) the ring mesh's zero-backlash centre distance
/// may differ from the sun mesh's before the set is refused: 0.01 m, a tenth of a typical
/// backlash allowance; inside it the ring mesh runs at the carrier's radius.
const CENTRE_DISTANCE_TOLERANCE_MODULES: f64 = 0.01;

/// A planet angle is accepted this close (in tooth pitches of z_s + z_r) to an assembly
/// position 2 pi k / (z_s + z_r), and then set exactly on it: 1e-4 pitch, so a case may
/// write 360 k / (z_s + z_r) degrees to four decimals.
const ASSEMBLY_TOLERANCE_PITCHES: f64 = 1e-4;

/// A planetary set's geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetarySet {
    /// Planet angles psi_n on the carrier, rad, psi_1 = 0, increasing, each on an assembly
    /// position 2 pi k / (z_s + z_r).
    pub planet_angles_rad: Vec<f64>,
    /// The sun-planet pair: pinion = sun, gear = planet.
    pub sun_planet: GearPair,
    /// The ring-planet pair.
    pub ring_planet: InternalPair,
    /// Carrier radius (sun centre to planet pin), m: the sun-planet operating centre distance.
    pub carrier_radius_m: f64,
    /// The member the power comes in on.
    pub input: Member,
    /// The member the power leaves by.
    pub output: Member,
    /// The member held fixed.
    pub fixed: Member,
}

impl PlanetarySet {
    /// Build the set from `[planetary]`: every problem at once, each naming its key.
    pub fn from_case(p: &PlanetarySection) -> Result<Self, GeometryError> {
        let errs = p.range_problems();
        if !errs.is_empty() {
            return Err(GeometryError(errs));
        }
        let mut errors = Vec::new();
        let sun_planet = GearPair::from_case(&sun_planet_section(p)).map_err(|e| {
            GeometryError(
                e.0.into_iter()
                    .map(|m| format!("sun-planet mesh: {m}"))
                    .collect(),
            )
        })?;
        let a = sun_planet.centre_distance_m;
        let ring = ring_of(p);
        if let Some(msg) = centre_distance_problem(p, &sun_planet) {
            return Err(GeometryError(vec![msg]));
        }
        let ring_planet = InternalPair::new(
            &sun_planet.gear,
            ring,
            sun_planet.module_m,
            sun_planet.pressure_angle_rad,
            sun_planet.face_width_m,
            a,
        )
        .map_err(|e| {
            GeometryError(
                e.0.into_iter()
                    .map(|m| format!("ring-planet mesh: {m}"))
                    .collect(),
            )
        })?;
        let angles = planet_angles(p, &mut errors);
        errors.extend(collision_problems(
            p,
            &angles,
            a,
            sun_planet.gear.tip_radius_m,
        ));
        if !errors.is_empty() {
            return Err(GeometryError(errors));
        }
        Ok(Self {
            planet_angles_rad: angles,
            sun_planet,
            ring_planet,
            carrier_radius_m: a,
            input: p.input,
            output: p.output,
            fixed: p.fixed,
        })
    }

    /// Sun teeth z_s.
    pub fn teeth_sun(&self) -> usize {
        self.sun_planet.pinion.teeth
    }

    /// Planet teeth z_p.
    pub fn teeth_planet(&self) -> usize {
        self.sun_planet.gear.teeth
    }

    /// Ring teeth z_r.
    pub fn teeth_ring(&self) -> usize {
        self.ring_planet.ring.teeth
    }

    /// Number of planets N.
    pub fn planets(&self) -> usize {
        self.planet_angles_rad.len()
    }

    /// Signed speeds [sun, carrier, ring] (any unit) with the fixed member at rest and the
    /// input at `input_speed`, by Willis' equation (the speeds relative to the carrier are
    /// those of a fixed-axis train sun -> planet -> ring):
    ///   (w_s - w_c) / (w_r - w_c) = -z_r / z_s,  i.e.  z_s w_s + z_r w_r = (z_s + z_r) w_c.
    pub fn member_speeds(&self, input_speed: f64) -> [f64; 3] {
        let (zs, zr) = (self.teeth_sun() as f64, self.teeth_ring() as f64);
        // Speeds per unit speed of the free (non-fixed) members, solved from Willis.
        let unit = match self.fixed {
            Member::Ring => [1.0 + zr / zs, 1.0, 0.0],
            Member::Sun => [0.0, 1.0, 1.0 + zs / zr],
            Member::Carrier => [-zr / zs, 0.0, 1.0],
        };
        let scale = input_speed / unit[index(self.input)];
        unit.map(|w| w * scale)
    }

    /// The input member's torque per unit of the sun's, |T_input / T_s|, by the set's torque
    /// split T_s : T_r : T_c = 1 : z_r / z_s : -(1 + z_r / z_s) (Willis, with the planets'
    /// torque balance; dimensionless).
    pub fn input_torque_per_sun_torque(&self) -> f64 {
        let zrs = self.teeth_ring() as f64 / self.teeth_sun() as f64;
        match self.input {
            Member::Sun => 1.0,
            Member::Ring => zrs,
            Member::Carrier => 1.0 + zrs,
        }
    }

    /// Speed ratio w_input / w_output (signed; negative when the output turns the other way).
    pub fn ratio(&self) -> f64 {
        let w = self.member_speeds(1.0);
        w[index(self.input)] / w[index(self.output)]
    }

    /// Mesh frequency, Hz, from signed member speeds in Hz [sun, carrier, ring]:
    /// f_m = z_r |f_c - f_r| = z_s |f_s - f_c| (the teeth passing a planet's pin in the
    /// carrier's frame; the two are equal by Willis' equation).
    pub fn mesh_frequency_hz(&self, speeds_hz: [f64; 3]) -> f64 {
        self.teeth_ring() as f64 * (speeds_hz[1] - speeds_hz[2]).abs()
    }

    /// Planet-pass frequency at a sensor fixed on the ring, Hz: N |f_c - f_r|
    /// (McFadden & Smith 1985), from signed speeds in Hz [sun, carrier, ring].
    pub fn planet_pass_frequency_hz(&self, speeds_hz: [f64; 3]) -> f64 {
        self.planets() as f64 * (speeds_hz[1] - speeds_hz[2]).abs()
    }

    /// Relative phase of each sun-planet mesh to planet 1's, in mesh cycles in [0, 1)
    /// (Parker & Lin 2004, eq. 6): gamma_sn = frac(z_s psi_n / 2 pi): the fraction of a
    /// mesh cycle by which mesh n trails mesh 1 as the sun turns relative to the carrier.
    pub fn sun_planet_phases(&self) -> Vec<f64> {
        let zs = self.teeth_sun() as f64;
        self.planet_angles_rad
            .iter()
            .map(|psi| frac(zs * psi / (2.0 * PI)))
            .collect()
    }

    /// Relative phase of each ring-planet mesh to planet 1's, mesh cycles in [0, 1)
    /// (Parker & Lin 2004, eq. 7): gamma_rn = frac(-z_r psi_n / 2 pi) (the ring turns
    /// against the sun relative to the carrier). With psi_n on assembly positions,
    /// gamma_rn = gamma_sn.
    pub fn ring_planet_phases(&self) -> Vec<f64> {
        let zr = self.teeth_ring() as f64;
        self.planet_angles_rad
            .iter()
            .map(|psi| frac(-zr * psi / (2.0 * PI)))
            .collect()
    }

    /// Phase of a planet's ring mesh relative to its sun mesh, mesh cycles in [0, 1): the
    /// fraction of a mesh cycle between a planet flank's passing the sun mesh's pitch point
    /// and the next opposite flank's passing the ring mesh's pitch point.
    ///
    /// The two pitch points lie on the line of centres on either side of the planet (half
    /// a turn apart); the sun loads one flank, the ring the other. A planet tooth whose
    /// centreline is at the sun pitch point has its loaded flank tau_s = s(r_ws) / (2 r_ws)
    /// ahead, and the ring's loaded flank of a tooth at the ring pitch point lies tau_r
    /// behind, tau = psi_b - inv(alpha_w) the tooth's half angle on each operating pitch
    /// circle (ISO 21771). So the ring event trails by pi - tau_s - tau_r of planet
    /// rotation: gamma_rs = frac(z_p / 2 - z_p (tau_s + tau_r) / 2 pi). For standard gears
    /// (tau = pi / 2 z_p on both) this is 0 for an odd z_p and 1/2 for an even one
    /// (Parker & Lin 2004: a tooth faces a space, or a tooth, across the planet).
    pub fn ring_sun_phase(&self) -> f64 {
        frac(self.ring_sun_cycles())
    }

    /// The planet rotation (relative to the carrier, in mesh cycles) from a planet flank's
    /// passing the sun mesh's pitch point to the opposite flank's passing the ring mesh's,
    /// z_p / 2 - z_p (tau_s + tau_r) / 2 pi, unreduced ([`Self::ring_sun_phase`] is its
    /// fraction).
    pub fn ring_sun_cycles(&self) -> f64 {
        let planet = &self.sun_planet.gear;
        let zp = planet.teeth as f64;
        let tau_s = planet.half_base_angle_rad - inv(self.sun_planet.operating_pressure_angle_rad);
        let tau_r = planet.half_base_angle_rad - inv(self.ring_planet.operating_pressure_angle_rad);
        zp / 2.0 - zp * (tau_s + tau_r) / (2.0 * PI)
    }
}

/// Index of a member in [sun, carrier, ring].
fn index(m: Member) -> usize {
    match m {
        Member::Sun => 0,
        Member::Carrier => 1,
        Member::Ring => 2,
    }
}

/// Fractional part in [0, 1), with values within 1e-12 of an integer taken as 0 (a phase
/// that is an integer up to rounding of psi_n is in phase).
fn frac(v: f64) -> f64 {
    let f = v - v.floor();
    if f < 1e-12 || 1.0 - f < 1e-12 {
        0.0
    } else {
        f
    }
}

/// The sun-planet pair as a `[gear]` section (sun = pinion, planet = gear).
fn sun_planet_section(p: &PlanetarySection) -> GearSection {
    GearSection {
        module_mm: p.module_mm,
        teeth_pinion: p.teeth_sun,
        teeth_gear: p.teeth_planet,
        pressure_angle_deg: p.pressure_angle_deg,
        addendum_coefficient: p.addendum_coefficient,
        dedendum_coefficient: p.dedendum_coefficient,
        profile_shift_pinion: p.profile_shift_sun,
        profile_shift_gear: p.profile_shift_planet,
        face_width_mm: p.face_width_mm,
        centre_distance_mm: None,
        hub_bore_radius_pinion_mm: Derivable::Derived,
        hub_bore_radius_gear_mm: Derivable::Derived,
        tool_tip_radius_coefficient: p.tool_tip_radius_coefficient,
        ..GearSection::default()
    }
}

/// The ring of `[planetary]`.
fn ring_of(p: &PlanetarySection) -> InternalGear {
    InternalGear::generated(
        p.teeth_ring as usize,
        p.profile_shift_ring,
        p.module_mm * MM,
        p.pressure_angle_deg.to_radians(),
        p.addendum_coefficient_ring,
        p.dedendum_coefficient,
    )
}

/// The ring mesh's zero-backlash centre distance must equal the sun mesh's (the
/// carrier's radius) within [`CENTRE_DISTANCE_TOLERANCE_MODULES`]; for unshifted gears
/// that is z_r = z_s + 2 z_p. The message gives the ring shift that makes them equal.
fn centre_distance_problem(p: &PlanetarySection, sp: &GearPair) -> Option<String> {
    let alpha = sp.pressure_angle_rad;
    let (zp, zr) = (p.teeth_planet as f64, p.teeth_ring as f64);
    if zr <= zp {
        return Some(format!(
            "`planetary.teeth_ring` = {} is invalid: a ring needs more teeth than its planets ({})",
            p.teeth_ring, p.teeth_planet
        ));
    }
    let rb_diff = sp.module_m * (zr - zp) / 2.0 * alpha.cos();
    let aw =
        internal_operating_angle_rad(alpha, zp, p.profile_shift_planet, zr, p.profile_shift_ring);
    let a_ring = rb_diff / aw.cos();
    let a = sp.centre_distance_m;
    if (a_ring - a).abs() <= CENTRE_DISTANCE_TOLERANCE_MODULES * sp.module_m {
        return None;
    }
    let standard = p.teeth_sun + 2 * p.teeth_planet;
    let needed = if a > rb_diff {
        // inv(alpha_w) the carrier's radius asks of the ring mesh, solved for x_r.
        let inv_w = inv((rb_diff / a).acos());
        format!(
            "; `planetary.profile_shift_ring` = {:.4} would make them equal",
            (inv(alpha) - inv_w) * (zr - zp) / (2.0 * alpha.tan()) - p.profile_shift_planet
        )
    } else {
        String::new()
    };
    let what = if a_ring < a { "too small" } else { "too large" };
    Some(format!(
        "`planetary.teeth_ring` = {} is {what} for the sun and planets: the ring-planet mesh's centre distance {:.4} mm differs from the sun-planet mesh's {:.4} mm (unshifted gears need z_r = z_s + 2 z_p = {standard}){needed}",
        p.teeth_ring,
        a_ring / MM,
        a / MM
    ))
}

/// The planets' angles, rad: `planet_angles_deg` checked (one per planet, the first 0,
/// increasing below 360, each on an assembly position) and snapped onto 2 pi k / (z_s +
/// z_r); or equally spaced, which needs (z_s + z_r) / N to be an integer.
fn planet_angles(p: &PlanetarySection, errors: &mut Vec<String>) -> Vec<f64> {
    let n = p.planets as usize;
    let pitches = (p.teeth_sun + p.teeth_ring) as f64;
    let Some(deg) = &p.planet_angles_deg else {
        if (p.teeth_sun + p.teeth_ring) % p.planets != 0 {
            errors.push(format!(
                "`planetary.planets` = {n} cannot be equally spaced: the assembly condition (z_s + z_r) / N = ({} + {}) / {n} is not an integer (give `planetary.planet_angles_deg` on multiples of 360 / {} deg, or change the teeth or the number of planets)",
                p.teeth_sun, p.teeth_ring, p.teeth_sun + p.teeth_ring
            ));
        }
        return (0..n).map(|k| 2.0 * PI * k as f64 / n as f64).collect();
    };
    if deg.len() != n {
        errors.push(format!(
            "`planetary.planet_angles_deg` has {} angles: it needs one per planet ({n})",
            deg.len()
        ));
        return Vec::new();
    }
    let mut out = Vec::with_capacity(n);
    for (i, d) in deg.iter().enumerate() {
        let prev = if i == 0 { None } else { Some(deg[i - 1]) };
        let ordered = match prev {
            None => *d == 0.0,
            Some(q) => d.is_finite() && *d > q && *d < 360.0,
        };
        if !ordered {
            errors.push(format!(
                "`planetary.planet_angles_deg` is invalid at entry {} ({d}): the first angle must be 0 and the others increase strictly below 360",
                i + 1
            ));
            return Vec::new();
        }
        let k = d / 360.0 * pitches;
        if (k - k.round()).abs() > ASSEMBLY_TOLERANCE_PITCHES {
            errors.push(format!(
                "`planetary.planet_angles_deg` entry {} = {d} fails the assembly condition: a planet fits only at multiples of 360 / (z_s + z_r) = {:.6} deg (nearest: {:.6} deg)",
                i + 1,
                360.0 / pitches,
                k.round() * 360.0 / pitches
            ));
        }
        out.push(2.0 * PI * k.round() / pitches);
    }
    out
}

/// Adjacent planets (and the last and the first) must not overlap: their centres,
/// 2 a sin(delta psi / 2) apart, must be more than a planet's tip diameter apart.
fn collision_problems(
    p: &PlanetarySection,
    angles: &[f64],
    a_m: f64,
    tip_radius_m: f64,
) -> Vec<String> {
    let n = angles.len();
    let mut errs = Vec::new();
    if n < 2 {
        return errs;
    }
    for i in 0..n {
        let gap = if i + 1 < n {
            angles[i + 1] - angles[i]
        } else {
            2.0 * PI - angles[i]
        };
        let dist = 2.0 * a_m * (gap / 2.0).sin();
        if dist <= 2.0 * tip_radius_m {
            let key = if p.planet_angles_deg.is_some() {
                "planet_angles_deg"
            } else {
                "planets"
            };
            errs.push(format!(
                "`planetary.{key}`: planets {} and {} collide: their centres are {:.3} mm apart, less than a planet's tip diameter {:.3} mm",
                i + 1,
                (i + 1) % n + 1,
                dist / MM,
                2.0 * tip_radius_m / MM
            ));
        }
    }
    errs
}
