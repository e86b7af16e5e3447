//! The involute helical pair on parallel axes: helix angle and hand, normal and transverse
//! sections, base helix angle, transverse, overlap and total contact ratios, the contact
//! lines inclined on the plane of action, and the virtual spur gear of the tooth form.
//!
//! The case's `[gear]` section is read as the normal section (the basic rack's): module
//! m_n, pressure angle alpha_n, addendum, dedendum and tool-tip coefficients in m_n, and
//! profile shifts x_n. The transverse section is a spur pair built by [`GearPair`] from
//! the transverse values (ISO 21771:2007, clause 4 and 5):
//!   m_t = m_n / cos(beta),  tan(alpha_t) = tan(alpha_n) / cos(beta),
//!   x_t m_t = x_n m_n (the rack moves by the same length),
//!   h_a, h_f unchanged in length (their coefficients in m_t are h* cos(beta)),
//!   tan(beta_b) = tan(beta) cos(alpha_t)  (equivalently sin(beta_b) = sin(beta) cos(alpha_n)).
//! So the radii, the operating transverse pressure angle (inv alpha_wt = inv alpha_t +
//! 2 tan(alpha_n) (x_n1 + x_n2)/(z1 + z2)), the centre distance, the path of contact and
//! epsilon_alpha are ISO 21771's. The rack's tip radius rho_fP (in the normal section) is
//! carried into the transverse section so that the straight flank ends at the same height,
//! rho_fPt (1 - sin alpha_t) = rho_fP (1 - sin alpha_n): the form circle (undercut limit) is
//! exact, the fillet's exact transverse shape (an ellipse-like curve) is not modelled.
//!
//! Plane of action: coordinates u along the transverse path of contact (from its start A,
//! m) and y across the face (0 <= y <= b, along the pinion's angular velocity, m). A contact
//! line is inclined at beta_b to the axial direction: pair k lies on
//!   u = r_b1 phi + k p_bt + s y tan(beta_b),  s = +1 for a right-hand pinion, -1 for left,
//! phi the pinion rotation since pair 0 entered contact at the face y = 0. (A right-hand
//! helix turns the tooth forward, in the sense of rotation, as y grows, so the section at y
//! has rolled y tan(beta_b) further along the path.) Each contact line is 1/cos(beta_b)
//! longer than its axial extent.

use super::pair::{GearPair, GeometryError};
use crate::config::case::GearSection;
use std::f64::consts::PI;

/// Largest helix angle accepted, deg (exclusive). Beyond ~45 deg parallel-axis helical
/// gears are rare and ISO 6336's stiffness and load factors are not made for them.
pub const MAX_HELIX_ANGLE_DEG: f64 = 45.0;

/// Hand of a helix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hand {
    /// Left-hand helix.
    Left,
    /// Right-hand helix (a right-handed screw).
    Right,
}

impl Hand {
    /// `"left"` or `"right"`; anything else is an error naming the key, the value and the
    /// valid values.
    pub fn parse(key: &str, value: &str) -> Result<Hand, GeometryError> {
        match value {
            "left" => Ok(Hand::Left),
            "right" => Ok(Hand::Right),
            _ => Err(GeometryError(vec![format!(
                "`{key}` = {value:?} is invalid: it must be \"left\" or \"right\""
            )])),
        }
    }

    /// The mate's hand on parallel axes: the other one.
    pub fn mate(self) -> Hand {
        match self {
            Hand::Left => Hand::Right,
            Hand::Right => Hand::Left,
        }
    }

    /// s = +1 (right) or -1 (left): the sign of the stagger along the path of contact as y
    /// grows along the pinion's angular velocity (module docs).
    pub fn stagger_sign(self) -> f64 {
        match self {
            Hand::Left => -1.0,
            Hand::Right => 1.0,
        }
    }
}

/// The helix of a pair: what a helical case adds to the spur `[gear]` section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HelixSpec {
    /// Helix angle at the reference cylinder beta, deg; 0 is a spur pair.
    pub helix_angle_deg: f64,
    /// Hand of the pinion's helix; the gear has the other.
    pub hand_pinion: Hand,
}

impl HelixSpec {
    /// A spur pair: beta = 0 (the hand is then immaterial).
    pub fn spur() -> Self {
        Self {
            helix_angle_deg: 0.0,
            hand_pinion: Hand::Right,
        }
    }
}

/// One contact line on the plane of action at a mesh phase.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLine {
    /// Tooth pair index k in the current mesh period, as in
    /// [`GearPair::pairs_in_contact`]: at the face y = 0 the pair lies k base pitches
    /// further along the path than the pair that entered there at the period's start
    /// (k < 0: a pair that reaches y = 0 only in a later period).
    pub pair: i64,
    /// Axial extent [y_start, y_end] of the line in contact, m.
    pub face_m: (f64, f64),
    /// Positions u along the transverse path of contact (from its start A) at y_start and
    /// y_end, m.
    pub path_m: (f64, f64),
    /// Length of the line in contact, (y_end - y_start) / cos(beta_b), m.
    pub length_m: f64,
}

/// A helical pair on parallel axes. Build with [`HelicalPair::from_case`].
#[derive(Debug, Clone, PartialEq)]
pub struct HelicalPair {
    /// Helix angle at the reference cylinder beta, rad.
    pub helix_angle_rad: f64,
    /// Hand of the pinion's helix (the gear's is [`Hand::mate`]).
    pub hand_pinion: Hand,
    /// Normal module m_n, m.
    pub normal_module_m: f64,
    /// Normal pressure angle alpha_n, rad.
    pub normal_pressure_angle_rad: f64,
    /// Transverse module m_t = m_n / cos(beta), m.
    pub transverse_module_m: f64,
    /// Transverse pressure angle alpha_t = atan(tan(alpha_n) / cos(beta)), rad.
    pub transverse_pressure_angle_rad: f64,
    /// Base helix angle beta_b = atan(tan(beta) cos(alpha_t)), rad.
    pub base_helix_angle_rad: f64,
    /// Face width b, m.
    pub face_width_m: f64,
    /// The transverse section as a spur pair (radii, path of contact, base pitch p_bt,
    /// epsilon_alpha); its face width is b.
    pub transverse: GearPair,
    /// Transverse contact ratio epsilon_alpha = g_alpha / p_bt.
    pub transverse_contact_ratio: f64,
    /// Overlap ratio epsilon_beta = b tan(beta_b) / p_bt = b sin(beta) / (pi m_n).
    pub overlap_ratio: f64,
    /// Total contact ratio epsilon_gamma = epsilon_alpha + epsilon_beta.
    pub total_contact_ratio: f64,
    /// Virtual numbers of teeth z_n = z / (cos^2(beta_b) cos(beta)) of pinion and gear.
    pub virtual_teeth: [f64; 2],
}

impl HelicalPair {
    /// Build the pair from the case's `[gear]` section, read as the normal section, and
    /// the helix. A helix angle outside [0, [`MAX_HELIX_ANGLE_DEG`]) is an error naming
    /// `gear.helix_angle_deg`; the transverse section's problems are [`GearPair`]'s.
    pub fn from_case(g: &GearSection, helix: &HelixSpec) -> Result<Self, GeometryError> {
        let beta_deg = helix.helix_angle_deg;
        if !(0.0..MAX_HELIX_ANGLE_DEG).contains(&beta_deg) {
            return Err(GeometryError(vec![format!(
                "`gear.helix_angle_deg` = {beta_deg} is invalid: it must lie in [0, {MAX_HELIX_ANGLE_DEG}) deg (0 is a spur pair)"
            )]));
        }
        let beta = beta_deg.to_radians();
        let transverse = GearPair::from_case(&transverse_section(g, beta))?;
        let alpha_n = g.pressure_angle_deg.to_radians();
        let alpha_t = transverse.pressure_angle_rad;
        let beta_b = (beta.tan() * alpha_t.cos()).atan();
        let b = transverse.face_width_m;
        let eps_alpha = transverse.contact_ratio;
        let eps_beta = b * beta_b.tan() / transverse.base_pitch_m;
        let zn = |z: usize| z as f64 / (beta_b.cos().powi(2) * beta.cos());
        Ok(Self {
            helix_angle_rad: beta,
            hand_pinion: helix.hand_pinion,
            normal_module_m: g.module_mm * 1e-3,
            normal_pressure_angle_rad: alpha_n,
            transverse_module_m: transverse.module_m,
            transverse_pressure_angle_rad: alpha_t,
            base_helix_angle_rad: beta_b,
            face_width_m: b,
            virtual_teeth: [zn(transverse.pinion.teeth), zn(transverse.gear.teeth)],
            transverse_contact_ratio: eps_alpha,
            overlap_ratio: eps_beta,
            total_contact_ratio: eps_alpha + eps_beta,
            transverse,
        })
    }

    /// Normal base pitch p_bn = pi m_n cos(alpha_n), m (ISO 21771): the transverse base
    /// pitch times cos(beta_b).
    pub fn normal_base_pitch_m(&self) -> f64 {
        PI * self.normal_module_m * self.normal_pressure_angle_rad.cos()
    }

    /// Axial pitch p_x = p_bt / tan(beta_b) = pi m_n / sin(beta), m; infinite for a spur pair.
    pub fn axial_pitch_m(&self) -> f64 {
        self.transverse.base_pitch_m / self.base_helix_angle_rad.tan()
    }

    /// How far the section at face position y (m) has rolled along the path of contact
    /// ahead of the section at y = 0: s y tan(beta_b), m (module docs).
    pub fn stagger_m(&self, y_m: f64) -> f64 {
        self.hand_pinion.stagger_sign() * y_m * self.base_helix_angle_rad.tan()
    }

    /// The contact lines in contact at pinion rotation `phase_rad` (rad since pair 0
    /// entered contact at y = 0): each line's part inside the contact zone
    /// 0 <= u <= g_alpha, 0 <= y <= b of the plane of action (module docs). Exact.
    pub fn contact_lines(&self, phase_rad: f64) -> Vec<ContactLine> {
        let p = &self.transverse;
        let (pb, g_alpha, b) = (p.base_pitch_m, p.path_length_m(), self.face_width_m);
        let slope = self.stagger_m(1.0); // du/dy
        let cos_b = self.base_helix_angle_rad.cos();
        let period = p.mesh_angle_rad();
        let cycle = (phase_rad / period).floor();
        let u0 = p.pinion.base_radius_m * (phase_rad - cycle * period);
        // u of line k spans u0 + k pb + [min(0, slope b), max(0, slope b)].
        let (lo, hi) = (slope.min(0.0) * b, slope.max(0.0) * b);
        let k_first = ((-hi - u0) / pb).floor() as i64;
        let k_last = ((g_alpha - lo - u0) / pb).ceil() as i64;
        let mut lines = Vec::new();
        for k in k_first..=k_last {
            let u_k = u0 + k as f64 * pb;
            let (y0, y1) = if slope == 0.0 {
                if (0.0..=g_alpha).contains(&u_k) {
                    (0.0, b)
                } else {
                    continue;
                }
            } else {
                let (a, c) = ((0.0 - u_k) / slope, (g_alpha - u_k) / slope);
                (a.min(c).max(0.0), a.max(c).min(b))
            };
            if y1 > y0 {
                lines.push(ContactLine {
                    pair: k,
                    face_m: (y0, y1),
                    path_m: (u_k + slope * y0, u_k + slope * y1),
                    length_m: (y1 - y0) / cos_b,
                });
            }
        }
        lines
    }

    /// Total length of the contact lines in contact at `phase_rad`, m.
    pub fn contact_length_m(&self, phase_rad: f64) -> f64 {
        self.contact_lines(phase_rad)
            .iter()
            .map(|l| l.length_m)
            .sum()
    }

    /// Mean length of the contact lines over a mesh period, b epsilon_alpha / cos(beta_b),
    /// m: each line sweeps the zone's g_alpha b area, of which 1 / (p_bt cos beta_b) of a
    /// length per unit area is in contact on average.
    pub fn mean_contact_length_m(&self) -> f64 {
        self.face_width_m * self.transverse_contact_ratio / self.base_helix_angle_rad.cos()
    }

    /// Minimum length of the contact lines over a mesh period, m (AGMA 908-B89, eq. for
    /// L_min; the same as Niemann & Winter, *Maschinenelemente* II, for helical gears):
    /// with n_r, n_a the fractional parts of epsilon_alpha and epsilon_beta,
    ///   L_min = b/cos(beta_b) (eps_alpha - n_a n_r / eps_beta)            if n_a <= 1 - n_r,
    ///   L_min = b/cos(beta_b) (eps_alpha - (1 - n_a)(1 - n_r) / eps_beta) otherwise
    /// (AGMA writes n_a n_r p_x with p_x = b / eps_beta). For eps_beta < 1, n_a / eps_beta = 1;
    /// a spur pair gives floor(eps_alpha) b.
    pub fn min_contact_length_m(&self) -> f64 {
        let (ea, eb) = (self.transverse_contact_ratio, self.overlap_ratio);
        let (nr, na) = (ea - ea.floor(), eb - eb.floor());
        let scale = self.face_width_m / self.base_helix_angle_rad.cos();
        let lost = if na <= 1.0 - nr {
            // n_a / eps_beta -> 1 as eps_beta -> 0 (n_a = eps_beta below 1).
            let na_over_eb = if eb < 1.0 { 1.0 } else { na / eb };
            na_over_eb * nr
        } else {
            (1.0 - na) * (1.0 - nr) / eb
        };
        scale * (ea - lost)
    }
}

/// The transverse section of a helical pair's `[gear]` section (read as the normal
/// section) for helix angle `beta_rad`, as a spur section (module docs). beta = 0 returns
/// the section unchanged, bit for bit.
pub fn transverse_section(g: &GearSection, beta_rad: f64) -> GearSection {
    if beta_rad == 0.0 {
        return g.clone();
    }
    let c = beta_rad.cos();
    let alpha_n = g.pressure_angle_deg.to_radians();
    let alpha_t = (alpha_n.tan() / c).atan();
    // rho_fPt m_t (1 - sin alpha_t) = rho_fP m_n (1 - sin alpha_n), m_n / m_t = cos(beta).
    let tip = g.tool_tip_radius_coefficient * c * (1.0 - alpha_n.sin()) / (1.0 - alpha_t.sin());
    GearSection {
        module_mm: g.module_mm / c,
        pressure_angle_deg: alpha_t.to_degrees(),
        addendum_coefficient: g.addendum_coefficient * c,
        dedendum_coefficient: g.dedendum_coefficient * c,
        profile_shift_pinion: g.profile_shift_pinion * c,
        profile_shift_gear: g.profile_shift_gear * c,
        tool_tip_radius_coefficient: tip,
        ..g.clone()
    }
}

#[cfg(test)]
#[path = "tests_helical.rs"]
mod tests;
