//! The involute spur pair: radii, operating pressure angle, path of contact, contact
//! ratio, and the mappings between pinion rotation and position on the line of action.
//!
//! Positions on the line of action (LOA) are measured as the pinion's radius of
//! curvature `rho1` (m): the distance from the pinion's tangency point N1. The gear's
//! radius of curvature at the same contact is `rho2 = N1N2 - rho1` (paper eq. 4:
//! r_gi = L - r_pi, with L = N1N2 = (r_pb + r_gb) tan(alpha_w)).
//! Sources: ISO 21771 (cylindrical gear geometry); Litvin & Fuentes, *Gear Geometry and
//! Applied Theory* (2004), ch. 10.

use super::involute::{inv, inv_inverse};
use crate::config::case::{Derivable, GearSection};
use std::f64::consts::PI;

/// One gear of the pair (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Gear {
    /// Number of teeth z.
    pub teeth: usize,
    /// Profile shift coefficient x (dimensionless, positive away from the centre).
    pub profile_shift: f64,
    /// Reference (pitch) radius r = m z / 2, m.
    pub pitch_radius_m: f64,
    /// Base radius r_b = r cos(alpha), m.
    pub base_radius_m: f64,
    /// Tip radius r_a = r + m (h_a* + x), m.
    pub tip_radius_m: f64,
    /// Root radius r_f = r - m (h_f* - x), m.
    pub root_radius_m: f64,
    /// Half the angular tooth thickness at the base circle, rad:
    /// alpha_2 = pi/(2z) + 2 x tan(alpha)/z + inv(alpha).
    pub half_base_angle_rad: f64,
    /// Radius of curvature of the lowest generated involute point (rack-cutter limit), m;
    /// negative means undercut.
    pub form_rho_m: f64,
    /// Hub bore radius, m: the case's, or r_f / 2 when `"derived"`.
    pub bore_radius_m: f64,
    /// Half the angle the tooth's footing spans on the root circle, measured to where the
    /// root fillet meets the root circle (rad); see `fillet_junction_half_angle_rad`.
    pub fillet_junction_half_angle_rad: f64,
}

/// h_f = r_f / r_int of a `"derived"` hub bore: 2, well inside Sainsot's fitted range
/// 1.4 <= h_f <= 7 and what the built-in case's own bores give (8 / 16.5 mm: 2.06;
/// 14 / 28.5 mm: 2.04). A bore of half the root radius leaves a rim as deep as the teeth
/// are long on the sizes of the built-in pair.
pub(crate) const DERIVED_BORE_H_F: f64 = 2.0;

/// Half angle (rad) of a generated tooth's footing on the root circle: from the tooth
/// centreline to where the root fillet meets the root circle.
///
/// The rack cutter's flat tip generates the root circle; each of its corners, rounded with
/// radius rho_fP = `tool_tip_coefficient` m, generates a fillet, which meets the root
/// circle at the point the corner's tangency with the tip line generates. That point lies
/// E from the rack tooth's centreline (ISO 6336-3, tooth form factor, with no protuberance):
///   E = pi m / 4 - h_fP tan(alpha) - rho_fP (1 - sin alpha) / cos(alpha),
/// h_fP = `dedendum_coefficient` m the rack's addendum. The rack tooth's centreline is the
/// middle of a tooth space, pi m / 2 from the gear tooth's centreline along the rolling
/// line, and rolling maps a distance s along it to the angle s / r (r = m z / 2), so
///   theta_f = (pi m / 2 - E) / r  =  (2 / z) [pi/4 + h_f* tan(alpha) + rho* (1 - sin alpha) / cos(alpha)].
/// The profile shift moves the rack radially and so cancels out. If the two corner radii
/// overlap (E < 0) the fillets of neighbouring teeth meet on the root circle: theta_f = pi / z.
pub(crate) fn fillet_junction_half_angle_rad(
    teeth: f64,
    pressure_angle_rad: f64,
    dedendum_coefficient: f64,
    tool_tip_coefficient: f64,
) -> f64 {
    let a = pressure_angle_rad;
    let e_over_m = PI / 4.0
        - dedendum_coefficient * a.tan()
        - tool_tip_coefficient * (1.0 - a.sin()) / a.cos();
    (PI / 2.0 - e_over_m.max(0.0)) * 2.0 / teeth
}

impl Gear {
    /// Radius at a point of the involute with radius of curvature rho, m.
    pub fn radius_at_rho(&self, rho_m: f64) -> f64 {
        self.base_radius_m.hypot(rho_m)
    }

    /// Radius of curvature at the tip, m.
    pub fn tip_rho_m(&self) -> f64 {
        (self.tip_radius_m.powi(2) - self.base_radius_m.powi(2))
            .max(0.0)
            .sqrt()
    }

    /// Tooth thickness (arc) at radius r, m (ISO 21771):
    /// s(r) = 2 r (alpha_2 - inv(alpha_r)), cos(alpha_r) = r_b / r.
    pub fn thickness_at_radius_m(&self, r_m: f64) -> f64 {
        let a = (self.base_radius_m / r_m).clamp(-1.0, 1.0).acos();
        2.0 * r_m * (self.half_base_angle_rad - inv(a))
    }
}

/// The stretch of the line of action over which tooth pairs are followed, as pinion
/// radii of curvature rho1 (m): the path of contact (the paper's model), or beyond its
/// ends where tip corners may touch (`geometry::corner`, `dynamics::contact_path`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reach {
    /// rho1 where the stretch begins (the pair enters), m.
    pub start_m: f64,
    /// rho1 where the stretch ends (the pair leaves), m.
    pub end_m: f64,
}

/// A meshing involute spur pair. Build with [`GearPair::from_case`].
#[derive(Debug, Clone, PartialEq)]
pub struct GearPair {
    /// Module m, m.
    pub module_m: f64,
    /// Reference pressure angle alpha, rad.
    pub pressure_angle_rad: f64,
    /// Face width b, m.
    pub face_width_m: f64,
    /// The pinion (gear 1, on the input shaft).
    pub pinion: Gear,
    /// The gear (gear 2, on the output shaft).
    pub gear: Gear,
    /// Operating centre distance a_w, m.
    pub centre_distance_m: f64,
    /// Operating pressure angle alpha_w, rad.
    pub operating_pressure_angle_rad: f64,
    /// Length N1N2 of the line of action between the tangency points, m.
    pub loa_length_m: f64,
    /// rho1 where contact starts (gear tip meets pinion flank, point A), m.
    pub rho_start_m: f64,
    /// rho1 where contact ends (pinion tip, point E), m.
    pub rho_end_m: f64,
    /// rho1 at the pitch point, r_b1 tan(alpha_w), m.
    pub rho_pitch_m: f64,
    /// Base pitch p_b = 2 pi r_b1 / z1, m.
    pub base_pitch_m: f64,
    /// Transverse contact ratio epsilon_alpha = (rho_end - rho_start) / p_b.
    pub contact_ratio: f64,
    /// Non-fatal findings (undercut, thin tips).
    pub warnings: Vec<String>,
}

/// Geometry that cannot mesh: every problem found, each naming its key, value and range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", .0.join("; "))]
pub struct GeometryError(pub Vec<String>);

impl GearPair {
    /// Build the pair from the case's `[gear]` section (lengths in mm there): each gear as
    /// its rack generates it, the operating pressure angle and centre distance, the path of
    /// contact; every problem that keeps the pair from meshing at once.
    pub fn from_case(g: &GearSection) -> Result<Self, GeometryError> {
        let m = g.module_mm * MM;
        let alpha = g.pressure_angle_deg.to_radians();
        let z1 = g.teeth_pinion as f64;
        let z2 = g.teeth_gear as f64;
        let (x1, x2) = (g.profile_shift_pinion, g.profile_shift_gear);
        let mut errors = Vec::new();
        let mut warnings = Vec::new();

        let pinion = Gear::generated(g, z1, x1, g.hub_bore_radius_pinion_mm);
        let gear = Gear::generated(g, z2, x2, g.hub_bore_radius_gear_mm);
        errors.extend(body_problems(&pinion, &gear));
        let rb_sum = pinion.base_radius_m + gear.base_radius_m;
        let (alpha_w, a_w) = operating_angle(g, alpha, rb_sum, &mut errors);
        let loa = a_w * alpha_w.sin();
        let rho_end = pinion.tip_rho_m();
        let rho_start = loa - gear.tip_rho_m();
        let base_pitch = 2.0 * PI * pinion.base_radius_m / z1;
        let rho_pitch = pinion.base_radius_m * alpha_w.tan();
        let eps = (rho_end - rho_start) / base_pitch;
        let path = ContactPath {
            centre_distance_m: a_w,
            loa_length_m: loa,
            rho_start_m: rho_start,
            rho_end_m: rho_end,
            base_pitch_m: base_pitch,
            contact_ratio: eps,
        };
        tooth_form_problems(&pinion, &gear, m, &mut errors, &mut warnings);
        errors.extend(interference_problems(&pinion, &gear, &path));
        errors.extend(contact_ratio_problem(g, &pinion, &gear, rb_sum, &path));
        if !errors.is_empty() {
            return Err(GeometryError(errors));
        }
        Ok(Self {
            module_m: m,
            pressure_angle_rad: alpha,
            face_width_m: g.face_width_mm * MM,
            pinion,
            gear,
            centre_distance_m: a_w,
            operating_pressure_angle_rad: alpha_w,
            loa_length_m: loa,
            rho_start_m: rho_start,
            rho_end_m: rho_end,
            rho_pitch_m: rho_pitch,
            base_pitch_m: base_pitch,
            contact_ratio: eps,
            warnings,
        })
    }

    /// Mesh period in pinion rotation, rad: 2 pi / z1.
    pub fn mesh_angle_rad(&self) -> f64 {
        2.0 * PI / self.pinion.teeth as f64
    }

    /// Gear ratio z2 / z1.
    pub fn ratio(&self) -> f64 {
        self.gear.teeth as f64 / self.pinion.teeth as f64
    }

    /// Gear's radius of curvature at the contact where the pinion's is rho1, m.
    pub fn rho_gear(&self, rho1_m: f64) -> f64 {
        self.loa_length_m - rho1_m
    }

    /// Length of the path of contact, m.
    pub fn path_length_m(&self) -> f64 {
        self.rho_end_m - self.rho_start_m
    }

    /// Largest number of pairs that can be in contact at once: ceil(epsilon).
    pub fn max_pairs(&self) -> usize {
        self.contact_ratio.ceil() as usize
    }

    /// Positions rho1 (m) of the pairs in contact at mesh phase `phase_rad` (pinion
    /// rotation since the pair 0 entered contact at A, reduced to one mesh period).
    ///
    /// Pair k entered contact k mesh periods earlier: rho1 = rho_A + r_b1 phase + k p_b.
    /// Returns (k, rho1) for every pair with rho1 <= rho_E.
    pub fn pairs_in_contact(&self, phase_rad: f64) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.pairs_in_contact_decided(phase_rad, phase_rad)
    }

    /// As [`GearPair::pairs_in_contact`], but which pairs touch is decided at the phase
    /// `decide_rad` (e.g. the middle of an integration step) while their positions follow
    /// `phase_rad`. A step that ends exactly on a pair entering or leaving contact then
    /// sees one contact set on all its stages, so the stiffness jump falls between steps.
    pub(crate) fn pairs_in_contact_decided(
        &self,
        phase_rad: f64,
        decide_rad: f64,
    ) -> impl Iterator<Item = (usize, f64)> + '_ {
        let period = self.mesh_angle_rad();
        // floor-based reduction: f64::rem_euclid is a slow software fmod.
        let base = (decide_rad / period).floor() * period;
        let rb1 = self.pinion.base_radius_m;
        let rho_decide = self.rho_start_m + rb1 * (decide_rad - base);
        let rho0 = self.rho_start_m + rb1 * (phase_rad - base);
        (0..self.max_pairs())
            .filter(move |k| rho_decide + *k as f64 * self.base_pitch_m <= self.rho_end_m + 1e-15)
            .map(move |k| (k, rho0 + k as f64 * self.base_pitch_m))
    }

    /// The path of contact as a [`Reach`]: pairs followed from A to E only.
    pub fn nominal_reach(&self) -> Reach {
        Reach {
            start_m: self.rho_start_m,
            end_m: self.rho_end_m,
        }
    }

    /// As `GearPair::pairs_in_contact_decided` over `reach`: (k, rho1) of every pair
    /// whose position at `decide_rad` lies in the reach, k < 0 for the pairs that have not
    /// yet entered the path (pair k is mesh cycle n - k). Over the nominal reach these are
    /// exactly the pairs of `GearPair::pairs_in_contact_decided`.
    pub fn pairs_in_reach_decided(
        &self,
        reach: Reach,
        phase_rad: f64,
        decide_rad: f64,
    ) -> impl Iterator<Item = (i64, f64)> + '_ {
        let period = self.mesh_angle_rad();
        let base = (decide_rad / period).floor() * period;
        let rb1 = self.pinion.base_radius_m;
        let rho_decide = self.rho_start_m + rb1 * (decide_rad - base);
        let rho0 = self.rho_start_m + rb1 * (phase_rad - base);
        let (k_lo, k_hi) = self.reach_range(reach, rho_decide);
        (k_lo..=k_hi).map(move |k| (k, rho0 + k as f64 * self.base_pitch_m))
    }

    /// First and last k of the pairs in `reach` whose positions at the decision are
    /// rho_decide + k p_b (empty when first > last). The end is tested as
    /// [`GearPair::pairs_in_contact_decided`] tests rho_E; pairs that have not entered
    /// the path are counted only when the reach starts before it.
    fn reach_range(&self, reach: Reach, rho_decide: f64) -> (i64, i64) {
        let pb = self.base_pitch_m;
        let at = |k: i64| rho_decide + k as f64 * pb;
        let mut k_lo = 0;
        if reach.start_m < self.rho_start_m {
            while at(k_lo - 1) >= reach.start_m {
                k_lo -= 1;
            }
        }
        let mut k_hi = k_lo - 1;
        while at(k_hi + 1) <= reach.end_m + 1e-15 {
            k_hi += 1;
        }
        (k_lo, k_hi)
    }

    /// What [`GearPair::pairs_in_reach_decided`] takes from `decide_rad`: the mesh cycle
    /// of its first pair (the newest in the reach) and the number of pairs. Two decision
    /// angles with the same key give the same pairs at every phase. Over the nominal
    /// reach: the floor of the phase in mesh angles and the number of pairs in contact.
    pub fn decided_set_in(&self, reach: Reach, decide_rad: f64) -> (f64, usize) {
        let period = self.mesh_angle_rad();
        let cycle = (decide_rad / period).floor();
        let rho_decide =
            self.rho_start_m + self.pinion.base_radius_m * (decide_rad - cycle * period);
        let (k_lo, k_hi) = self.reach_range(reach, rho_decide);
        (cycle - k_lo as f64, (k_hi - k_lo + 1).max(0) as usize)
    }

    /// Mesh phases within one period (rad) where a pair enters or leaves `reach`, with the
    /// period's start: [`GearPair::contact_change_phases`] for the nominal reach.
    pub fn reach_change_phases(&self, reach: Reach) -> Vec<f64> {
        if reach == self.nominal_reach() {
            return self.contact_change_phases();
        }
        let rb1 = self.pinion.base_radius_m;
        let pb = self.base_pitch_m;
        let period = self.mesh_angle_rad();
        let mut v = vec![0.0];
        for edge in [reach.start_m, reach.end_m] {
            let ph = (edge - self.rho_start_m).rem_euclid(pb) / rb1;
            if ph > 1e-12 * period && ph < period * (1.0 - 1e-12) {
                v.push(ph);
            }
        }
        v.sort_by(f64::total_cmp);
        v
    }

    /// The mesh cycle under way at pinion rotation `decide_rad` (rad since t = 0): the
    /// pair that entered contact at the start of the current mesh period, as
    /// [`GearPair::pairs_in_contact_decided`] counts it (pair k of the contact set is
    /// cycle n - k).
    #[inline]
    pub(crate) fn mesh_cycle(&self, decide_rad: f64) -> i64 {
        (decide_rad / self.mesh_angle_rad()).floor() as i64
    }

    /// Pinion roll angle (rad) at LOA position rho1: rho1 / r_b1.
    pub fn pinion_roll_angle(&self, rho1_m: f64) -> f64 {
        rho1_m / self.pinion.base_radius_m
    }

    /// Mesh-phase boundaries inside one period where the number of pairs changes,
    /// rad of pinion rotation: [0, (eps - floor(eps)) * period].
    pub fn contact_change_phases(&self) -> Vec<f64> {
        let period = self.mesh_angle_rad();
        let frac = self.contact_ratio - self.contact_ratio.floor();
        let mut v = vec![0.0];
        if frac > 1e-12 {
            v.push(frac * period);
        }
        v
    }
}

/// Metres per millimetre: the case gives lengths in mm.
const MM: f64 = 1e-3;

impl Gear {
    /// A gear of `z` teeth and profile shift `x` as the case's rack generates it (ISO
    /// 21771), its hub bore the case's `bore` or r_f / [`DERIVED_BORE_H_F`].
    fn generated(g: &GearSection, z: f64, x: f64, bore: Derivable) -> Gear {
        let m = g.module_mm * MM;
        let alpha = g.pressure_angle_deg.to_radians();
        let r = m * z / 2.0;
        let r_f = r - m * (g.dedendum_coefficient - x);
        let rb = r * alpha.cos();
        // Lowest involute point the rack cutter generates (ISO 21771): the straight
        // part of the rack flank ends (h_f* - rho_f*(1 - sin alpha)) m below the datum.
        let h_straight =
            g.dedendum_coefficient - g.tool_tip_radius_coefficient * (1.0 - alpha.sin());
        Gear {
            teeth: z as usize,
            profile_shift: x,
            pitch_radius_m: r,
            base_radius_m: rb,
            tip_radius_m: r + m * (g.addendum_coefficient + x),
            root_radius_m: r_f,
            half_base_angle_rad: PI / (2.0 * z) + 2.0 * x * alpha.tan() / z + inv(alpha),
            form_rho_m: r * alpha.sin() - (h_straight - x) * m / alpha.sin(),
            bore_radius_m: bore.given().map_or(r_f / DERIVED_BORE_H_F, |b| b * MM),
            fillet_junction_half_angle_rad: fillet_junction_half_angle_rad(
                z,
                alpha,
                g.dedendum_coefficient,
                g.tool_tip_radius_coefficient,
            ),
        }
    }
}

/// A gear without a body (root radius not positive) or with its bore outside the root
/// circle.
fn body_problems(pinion: &Gear, gear: &Gear) -> Vec<String> {
    let mut errors = Vec::new();
    for (name, gr) in [("pinion", pinion), ("gear", gear)] {
        if gr.root_radius_m <= 0.0 {
            errors.push(format!(
                "the {name} has no body: its root radius m (z/2 - h_f* + x) = {:.4} mm is not positive (raise its number of teeth or its profile shift, or lower the dedendum coefficient)",
                gr.root_radius_m / MM
            ));
        } else if gr.bore_radius_m.partial_cmp(&gr.root_radius_m) != Some(std::cmp::Ordering::Less)
        {
            errors.push(format!(
                "`gear.hub_bore_radius_{name}_mm` = {} is invalid: the bore must lie inside the {name}'s root circle, radius {:.4} mm (\"derived\" gives half of it)",
                gr.bore_radius_m / MM,
                gr.root_radius_m / MM
            ));
        }
    }
    errors
}

/// Operating pressure angle alpha_w and centre distance a_w, rad and m: from the profile
/// shifts (zero backlash, ISO 21771: inv alpha_w = inv alpha + 2 tan alpha (x1 + x2) /
/// (z1 + z2)) or from a given centre distance (cos alpha_w = (r_b1 + r_b2) / a_w, which
/// must exceed the base radii's sum `rb_sum`).
fn operating_angle(
    g: &GearSection,
    alpha: f64,
    rb_sum: f64,
    errors: &mut Vec<String>,
) -> (f64, f64) {
    let (z1, z2) = (g.teeth_pinion as f64, g.teeth_gear as f64);
    let (x1, x2) = (g.profile_shift_pinion, g.profile_shift_gear);
    match g.centre_distance_mm {
        None => {
            let aw = inv_inverse(inv(alpha) + 2.0 * alpha.tan() * (x1 + x2) / (z1 + z2));
            (aw, rb_sum / aw.cos())
        }
        Some(a_mm) => {
            let a = a_mm * MM;
            if a <= rb_sum {
                errors.push(format!(
                    "`gear.centre_distance_mm` = {a_mm} is invalid: it must exceed the sum of the base radii, {:.4} mm",
                    rb_sum / MM
                ));
                (alpha, rb_sum / alpha.cos())
            } else {
                ((rb_sum / a).acos(), a)
            }
        }
    }
}

/// Pointed tips (an error), thin tips and undercut (warnings); `m` the module, m.
fn tooth_form_problems(
    pinion: &Gear,
    gear: &Gear,
    m: f64,
    errors: &mut Vec<String>,
    warnings: &mut Vec<String>,
) {
    for (name, gr) in [("pinion", pinion), ("gear", gear)] {
        let s_tip = gr.thickness_at_radius_m(gr.tip_radius_m);
        if s_tip <= 0.0 {
            errors.push(format!(
                "the {name}'s teeth are pointed (tip thickness {:.3} mm <= 0): reduce its profile shift or the addendum coefficient",
                s_tip / MM
            ));
        } else if s_tip < 0.2 * m {
            warnings.push(format!(
                "the {name}'s tip is thin: {:.3} mm < 0.2 m",
                s_tip / MM
            ));
        }
        if gr.form_rho_m < 0.0 {
            warnings.push(format!(
                "the {name} is undercut by the generating rack (lowest involute point {:.3} mm below the base circle's tangency): the model keeps the involute-to-root beam of the uncut tooth",
                -gr.form_rho_m / MM
            ));
        }
    }
}

/// The path of contact of a pair being built, for its checks (fields as [`GearPair`]'s).
struct ContactPath {
    centre_distance_m: f64,
    loa_length_m: f64,
    rho_start_m: f64,
    rho_end_m: f64,
    base_pitch_m: f64,
    contact_ratio: f64,
}

/// Tip interference: each tip must meet the mate inside its generated involute.
fn interference_problems(pinion: &Gear, gear: &Gear, path: &ContactPath) -> Vec<String> {
    let mut errors = Vec::new();
    let pin_limit = pinion.form_rho_m.max(0.0);
    if path.rho_start_m < pin_limit {
        errors.push(format!(
            "tip interference: the gear tip meets the pinion at rho1 = {:.3} mm, below the pinion's lowest involute point {:.3} mm (check profile shifts, addendum coefficient, centre distance)",
            path.rho_start_m / MM,
            pin_limit / MM
        ));
    }
    let gear_limit = gear.form_rho_m.max(0.0);
    if path.loa_length_m - path.rho_end_m < gear_limit {
        errors.push(format!(
            "tip interference: the pinion tip meets the gear at rho2 = {:.3} mm, below the gear's lowest involute point {:.3} mm",
            (path.loa_length_m - path.rho_end_m) / MM,
            gear_limit / MM
        ));
    }
    errors
}

/// A contact ratio below 1: the pair cannot mesh continuously. With a given centre
/// distance, the distances below which the teeth touch and mesh continuously (`rb_sum`
/// the base radii's sum, m).
fn contact_ratio_problem(
    g: &GearSection,
    pinion: &Gear,
    gear: &Gear,
    rb_sum: f64,
    path: &ContactPath,
) -> Option<String> {
    let eps = path.contact_ratio;
    match g.centre_distance_mm {
        Some(a_mm) if eps < 1.0 && path.centre_distance_m > rb_sum => {
            // sqrt(a^2 - (r_b1 + r_b2)^2) = N1N2 = T1 + T2 - eps p_b, T_i the tips'
            // reach along the line of action, so eps = c at a = sqrt(rb^2 + (T - c p_b)^2).
            let reach = pinion.tip_rho_m() + gear.tip_rho_m();
            let at = |c: f64| rb_sum.hypot(reach - c * path.base_pitch_m) / MM;
            Some(if eps <= 0.0 {
                format!(
                    "`gear.centre_distance_mm` = {a_mm} is too large: at this centre distance the teeth do not touch at all (their tips fall {:.3} mm short of each other along the line of action); they touch below {:.4} mm and mesh continuously (contact ratio >= 1) below {:.4} mm",
                    (path.rho_start_m - path.rho_end_m) / MM,
                    at(0.0),
                    at(1.0)
                )
            } else {
                format!(
                    "`gear.centre_distance_mm` = {a_mm} is too large: the teeth touch, but each pair leaves contact before the next one engages (contact ratio {eps:.3} < 1); the pair meshes continuously below {:.4} mm",
                    at(1.0)
                )
            })
        }
        _ if eps < 1.0 => Some(format!(
            "contact ratio {eps:.4} is below 1: the pair cannot mesh continuously (raise the addendum coefficient or the numbers of teeth)"
        )),
        _ => None,
    }
}

#[cfg(test)]
#[path = "tests_pair.rs"]
mod tests;
