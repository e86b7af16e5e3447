//! Potential energy method for one involute spur tooth (paper eq. 10-11): bending, shear
//! and axial-compressive compliances of the tooth as a cantilever on its centreline, and
//! the linearised Hertz contact stiffness.
//!
//! Sources: Yang & Sun, J. Mech. Transm. Autom. Des. 107 (1985) 306; Tian, MSc thesis,
//! Univ. of Alberta (2004); Chaari, Fakhfakh & Haddar, Eur. J. Mech. A 28 (2009) 461;
//! for the straight part between root and base circle (root circle below the base
//! circle): Wan et al., Mech. Syst. Signal Process. 62-63 (2015) 1; Liang, Zuo & Pandey,
//! Mech. Mach. Theory 76 (2014) 20; Ma et al., Eng. Fail. Anal. 48 (2015) 204.
//!
//! Tooth frame: y along the tooth centreline from the gear centre, h = half-thickness
//! across it. Unwinding the involute from the base circle, the point whose generating
//! line is tangent at polar angle alpha (from the centreline, towards the opposite flank)
//! has roll angle u = alpha + alpha_2 and
//!   h(alpha) = r_b [(alpha + alpha_2) cos(alpha) - sin(alpha)],
//!   y(alpha) = r_b [(alpha + alpha_2) sin(alpha) + cos(alpha)],
//!   dy = r_b (alpha + alpha_2) cos(alpha) d alpha,
//! and the normal there (the line of action) makes the angle alpha with the perpendicular
//! to the centreline. Contact at radius of curvature rho gives alpha_1 = rho / r_b - alpha_2.
//! The tests check this parametrisation against `Gear::thickness_at_radius_m`.

use crate::config::case::MaterialsSection;
use crate::geometry::Gear;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Timoshenko shear correction factor of a rectangular section (Yang & Sun 1985).
const SHEAR_FACTOR: f64 = 1.2;

/// Young's moduli (Pa) and Poisson's ratios of the two gears.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElasticPair {
    /// Young's modulus of the pinion E_1, Pa.
    pub e_pinion_pa: f64,
    /// Poisson's ratio of the pinion nu_1.
    pub nu_pinion: f64,
    /// Young's modulus of the gear E_2, Pa.
    pub e_gear_pa: f64,
    /// Poisson's ratio of the gear nu_2.
    pub nu_gear: f64,
}

impl ElasticPair {
    /// From the case's `[materials]` section (moduli in GPa there).
    pub fn from_case(m: &MaterialsSection) -> Self {
        Self {
            e_pinion_pa: m.youngs_modulus_pinion_gpa * 1e9,
            nu_pinion: m.poisson_ratio_pinion,
            e_gear_pa: m.youngs_modulus_gear_gpa * 1e9,
            nu_gear: m.poisson_ratio_gear,
        }
    }

    /// Messages for moduli that are not positive or Poisson ratios outside (-1, 0.5).
    pub fn validate(&self) -> Vec<String> {
        let mut errs = Vec::new();
        for (name, e, nu) in [
            ("pinion", self.e_pinion_pa, self.nu_pinion),
            ("gear", self.e_gear_pa, self.nu_gear),
        ] {
            if !(e.is_finite() && e > 0.0) {
                errs.push(format!(
                    "{name}: Young's modulus must be positive, got {e} Pa"
                ));
            }
            if !(nu > -1.0 && nu < 0.5) {
                errs.push(format!(
                    "{name}: Poisson ratio must lie in (-1, 0.5), got {nu}"
                ));
            }
        }
        errs
    }
}

/// Linearised Hertz contact stiffness of a spur tooth pair, N/m (paper eq. 11, from Yang &
/// Sun 1985): k_h = pi E b / (4 (1 - nu^2)).
///
/// For two different materials, (1 - nu^2)/E is replaced by the mean of the two bodies'
/// (1 - nu_i^2)/E_i, i.e. E/(1 - nu^2) by the harmonic mean of E_i/(1 - nu_i^2): each body
/// contributes its own compliance to the line-contact approach (Johnson, *Contact
/// Mechanics*, sec. 4.2: 1/E* = sum (1 - nu_i^2)/E_i). Equal materials give eq. 11.
pub fn hertz_stiffness_n_per_m(face_width_m: f64, m: &ElasticPair) -> f64 {
    let c_mean = 0.5
        * ((1.0 - m.nu_pinion.powi(2)) / m.e_pinion_pa + (1.0 - m.nu_gear.powi(2)) / m.e_gear_pa);
    PI * face_width_m / (4.0 * c_mean)
}

/// Gauss-Legendre rule on [-1, 1]; nodes by Newton iteration on P_n from its three-term
/// recurrence (as Numerical Recipes' `gauleg`), accurate to ~1e-15.
#[derive(Debug, Clone)]
pub(crate) struct GaussLegendre {
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl GaussLegendre {
    /// n-point rule (n >= 1).
    pub fn new(n: usize) -> Self {
        let n = n.max(1);
        let mut nodes = vec![0.0; n];
        let mut weights = vec![0.0; n];
        let nf = n as f64;
        for i in 0..n.div_ceil(2) {
            // Tricomi's initial guess for the i-th root.
            let mut x = (PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                // P_n(x) and P_n'(x) by the three-term recurrence.
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let kf = k as f64;
                    let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
                    p0 = p1;
                    p1 = p2;
                }
                dp = nf * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            nodes[i] = -x;
            nodes[n - 1 - i] = x;
            weights[i] = w;
            weights[n - 1 - i] = w;
        }
        Self { nodes, weights }
    }

    /// The shared 20-point rule, built once.
    pub(crate) fn default_rule() -> &'static Self {
        static RULE: OnceLock<GaussLegendre> = OnceLock::new();
        RULE.get_or_init(|| GaussLegendre::new(20))
    }

    /// Integral of f over [a, b] (several integrands at once, summed component-wise).
    pub(crate) fn integrate3(&self, a: f64, b: f64, f: impl Fn(f64) -> [f64; 3]) -> [f64; 3] {
        let (half, mid) = (0.5 * (b - a), 0.5 * (b + a));
        let mut s = [0.0; 3];
        for (x, w) in self.nodes.iter().zip(&self.weights) {
            let v = f(mid + half * x);
            for k in 0..3 {
                s[k] += w * v[k];
            }
        }
        s.map(|v| v * half)
    }
}

/// Compliances of one tooth for a unit force along the line of action, m/N.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ToothCompliance {
    /// 1/k_b.
    pub bending_m_per_n: f64,
    /// 1/k_s.
    pub shear_m_per_n: f64,
    /// 1/k_a.
    pub axial_m_per_n: f64,
}

impl ToothCompliance {
    /// Total tooth compliance 1/k_b + 1/k_s + 1/k_a, m/N.
    pub fn total_m_per_n(&self) -> f64 {
        self.bending_m_per_n + self.shear_m_per_n + self.axial_m_per_n
    }
}

/// One tooth as a cantilever of variable section clamped at the root circle.
#[derive(Debug, Clone, PartialEq)]
pub struct ToothBeam {
    /// Base circle radius r_b, m.
    pub base_radius_m: f64,
    /// alpha_2, half the angular tooth thickness at the base circle, rad.
    pub half_base_angle_rad: f64,
    /// Root circle radius r_f, m (where the beam is clamped).
    pub root_radius_m: f64,
    /// Face width b, m.
    pub face_width_m: f64,
    /// Young's modulus E, Pa.
    pub youngs_modulus_pa: f64,
    /// Shear modulus G = E / (2 (1 + nu)), Pa.
    pub shear_modulus_pa: f64,
    /// Lower limit of the involute part: -alpha_2, or the root circle's alpha if r_f > r_b.
    alpha_start: f64,
    /// Straight part [y_root, y_base] with half-thickness h_b, when r_f < r_b.
    straight: Option<(f64, f64, f64)>,
}

impl ToothBeam {
    /// The tooth of `gear`, face width b (m), Young's modulus E (Pa), Poisson ratio nu.
    pub fn new(gear: &Gear, face_width_m: f64, e_pa: f64, nu: f64) -> Self {
        let rb = gear.base_radius_m;
        let a2 = gear.half_base_angle_rad;
        let rf = gear.root_radius_m;
        let (alpha_start, straight) = if rf < rb {
            // Wan / Liang / Ma convention: constant half-thickness h_b = r_b sin(alpha_2)
            // from the root circle (clamp) up to the base circle.
            let hb = rb * a2.sin();
            let y_root = (rf * rf - hb * hb).max(0.0).sqrt();
            (-a2, Some((y_root, rb * a2.cos(), hb)))
        } else {
            // Involute point on the root circle: roll angle u = sqrt(r_f^2/r_b^2 - 1).
            ((rf * rf / (rb * rb) - 1.0).sqrt() - a2, None)
        };
        Self {
            base_radius_m: rb,
            half_base_angle_rad: a2,
            root_radius_m: rf,
            face_width_m,
            youngs_modulus_pa: e_pa,
            shear_modulus_pa: e_pa / (2.0 * (1.0 + nu)),
            alpha_start,
            straight,
        }
    }

    /// alpha_1 = rho / r_b - alpha_2: angle of the line of action to the perpendicular of
    /// the centreline at the contact with radius of curvature rho (m), rad.
    pub fn contact_angle_rad(&self, rho_m: f64) -> f64 {
        rho_m / self.base_radius_m - self.half_base_angle_rad
    }

    /// (h, y) of the involute point with parameter alpha, m.
    pub fn involute_point(&self, alpha: f64) -> (f64, f64) {
        let u = alpha + self.half_base_angle_rad;
        let (s, c) = alpha.sin_cos();
        (
            self.base_radius_m * (u * c - s),
            self.base_radius_m * (u * s + c),
        )
    }

    /// theta_f: half angle of the tooth at the root circle, rad (for the fillet
    /// foundation). Straight root part: asin(h_b / r_f); otherwise the involute's polar
    /// angle there, alpha_2 - inv(alpha_rf) with cos(alpha_rf) = r_b / r_f.
    pub fn root_half_angle_rad(&self) -> f64 {
        match self.straight {
            Some((_, _, hb)) => (hb / self.root_radius_m).clamp(-1.0, 1.0).asin(),
            None => {
                let a = (self.base_radius_m / self.root_radius_m).acos();
                self.half_base_angle_rad - (a.tan() - a)
            }
        }
    }

    /// Half-thickness and height (m) of the section at the root circle, where the beam
    /// is clamped (and where a root crack starts).
    pub fn root_section(&self) -> (f64, f64) {
        match self.straight {
            Some((y_root, _, hb)) => (hb, y_root),
            None => self.involute_point(self.alpha_start),
        }
    }

    /// Height above the gear centre (m) where the force line through the contact at rho
    /// crosses the tooth centreline: y_c - h_c tan(alpha_1).
    pub fn force_centreline_crossing_m(&self, rho_m: f64) -> f64 {
        let a1 = self.contact_angle_rad(rho_m);
        let (hc, yc) = self.involute_point(a1);
        yc - hc * a1.tan()
    }

    /// Bending, shear and axial compliances for contact at radius of curvature rho (m),
    /// with the shared 20-point rule.
    pub fn compliance(&self, rho_m: f64) -> ToothCompliance {
        self.compliance_with_rule(rho_m, GaussLegendre::default_rule())
    }

    /// As [`Self::compliance`] with a given quadrature rule (per smooth sub-interval).
    ///
    /// With M(y) = F[cos(a1)(y_c - y) - sin(a1) h_c], I = (2h)^3 b / 12, A = 2 h b
    /// (Yang & Sun 1985; Tian 2004, eq. 2.19-2.21):
    ///   1/k_b = int M^2/(F^2 E I) dy,  1/k_s = int 1.2 cos^2(a1)/(G A) dy,
    ///   1/k_a = int sin^2(a1)/(E A) dy,   from the root circle to the contact.
    pub(crate) fn compliance_with_rule(&self, rho_m: f64, rule: &GaussLegendre) -> ToothCompliance {
        let b = self.face_width_m;
        self.compliance_with_section(rho_m, rule, |h, _| (2.0 * h * b, 2.0 * h * h * h * b / 3.0))
    }

    /// As [`Self::compliance_with_rule`] with the cross-section at each height given by
    /// `section(h, y) -> (area m^2, second moment m^4)` (h the flank's half-thickness and
    /// y the height, m) instead of the full 2h x b rectangle: a cracked or pitted tooth
    /// (`stiffness::tooth_faults`). The moment arm stays measured from the centreline.
    /// The section must be smooth in the height; see
    /// [`Self::compliance_with_section_split`] for one that jumps.
    pub(crate) fn compliance_with_section(
        &self,
        rho_m: f64,
        rule: &GaussLegendre,
        section: impl Fn(f64, f64) -> (f64, f64),
    ) -> ToothCompliance {
        self.compliance_with_section_split(rho_m, rule, &[], section)
    }

    /// As [`Self::compliance_with_section`] for a section that jumps at the flank points
    /// of involute parameters `breaks_rad`, ascending (alpha, as [`Self::involute_point`] takes it;
    /// alpha = rho / r_b - alpha_2 for the flank point of radius of curvature rho): a pit's
    /// or a worn zone's edges. The involute part is integrated piecewise between the breaks
    /// that fall inside it, so each piece is smooth and the Gauss rule keeps its accuracy
    /// (one rule across a jump is only first-order accurate in the node spacing, ~0.5 mm
    /// on the paper's teeth, and a pit of 0.2 mm height may hold no node at all).
    pub(crate) fn compliance_with_section_split(
        &self,
        rho_m: f64,
        rule: &GaussLegendre,
        breaks_rad: &[f64],
        section: impl Fn(f64, f64) -> (f64, f64),
    ) -> ToothCompliance {
        let a1 = self.contact_angle_rad(rho_m);
        let (hc, yc) = self.involute_point(a1);
        let (s1, c1) = a1.sin_cos();
        let (e, g) = (self.youngs_modulus_pa, self.shear_modulus_pa);
        // Integrands per unit dy at half-thickness h and height y.
        let per_dy = |h: f64, y: f64| -> [f64; 3] {
            let m = c1 * (yc - y) - s1 * hc;
            let (area, inertia) = section(h, y);
            [
                m * m / (e * inertia),
                SHEAR_FACTOR * c1 * c1 / (g * area),
                s1 * s1 / (e * area),
            ]
        };
        let mut sum = [0.0; 3];
        if a1 > self.alpha_start {
            // Involute part, integrated in alpha (smooth: h > 0 below a non-pointed tip),
            // piece by piece between the section's jumps.
            // No allocation: the breaks come ascending (checked in debug builds).
            debug_assert!(breaks_rad.windows(2).all(|w| w[0] <= w[1]));
            let ends = breaks_rad
                .iter()
                .copied()
                .filter(|b| *b > self.alpha_start && *b < a1)
                .chain(std::iter::once(a1));
            let mut from = self.alpha_start;
            for to in ends {
                let piece = rule.integrate3(from, to, |al| {
                    let (h, y) = self.involute_point(al);
                    let dy = self.base_radius_m * (al + self.half_base_angle_rad) * al.cos();
                    per_dy(h, y).map(|v| v * dy)
                });
                for k in 0..3 {
                    sum[k] += piece[k];
                }
                from = to;
            }
        }
        if let Some((y_root, y_base, hb)) = self.straight {
            let part = rule.integrate3(y_root, y_base, |y| per_dy(hb, y));
            for k in 0..3 {
                sum[k] += part[k];
            }
        }
        ToothCompliance {
            bending_m_per_n: sum[0],
            shear_m_per_n: sum[1],
            axial_m_per_n: sum[2],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;
    use crate::geometry::GearPair;

    fn paper() -> GearPair {
        GearPair::from_case(&GearSection::default()).unwrap()
    }

    fn beams(p: &GearPair) -> [ToothBeam; 2] {
        [
            ToothBeam::new(&p.pinion, p.face_width_m, 205e9, 0.3),
            ToothBeam::new(&p.gear, p.face_width_m, 205e9, 0.3),
        ]
    }

    #[test]
    fn gauss_legendre_is_exact_for_polynomials_and_matches_tables() {
        // An n-point rule integrates degree 2n-1 exactly: x^38 on [0, 1] = 1/39.
        let r = GaussLegendre::new(20);
        let v = r.integrate3(0.0, 1.0, |x| [x.powi(38), x.powi(2), 1.0]);
        assert!((v[0] - 1.0 / 39.0).abs() < 1e-14);
        assert!((v[1] - 1.0 / 3.0).abs() < 1e-15 && (v[2] - 1.0).abs() < 1e-14);
        // Abramowitz & Stegun table 25.4, n = 3: nodes 0, +-0.774596669241483, weights 8/9, 5/9.
        let r3 = GaussLegendre::new(3);
        assert!((r3.nodes[2] - 0.774_596_669_241_483).abs() < 1e-15);
        assert!((r3.weights[1] - 8.0 / 9.0).abs() < 1e-15);
    }

    #[test]
    fn involute_parametrisation_matches_gear_tooth_thickness() {
        // Independent geometry: the contact point lies at radius sqrt(r_b^2 + rho^2) and
        // its polar angle from the centreline is half the tooth thickness / r (ISO 21771,
        // `Gear::thickness_at_radius_m`).
        let p = paper();
        for (g, beam) in [(&p.pinion, &beams(&p)[0]), (&p.gear, &beams(&p)[1])] {
            for rho in [0.5e-3, 3e-3, g.tip_rho_m()] {
                let (h, y) = beam.involute_point(beam.contact_angle_rad(rho));
                let r = h.hypot(y);
                assert!((r - g.radius_at_rho(rho)).abs() < 1e-15);
                let half_s = r * h.atan2(y);
                assert!((2.0 * half_s - g.thickness_at_radius_m(r)).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn doubling_quadrature_points_changes_result_below_1e_8() {
        // Convergence of the 20-point rule on each sub-interval (tolerance set by the task).
        let p = paper();
        let r40 = GaussLegendre::new(40);
        for (g, beam) in [(&p.pinion, &beams(&p)[0]), (&p.gear, &beams(&p)[1])] {
            let tip = g.tip_rho_m();
            for rho in [0.0, 0.2e-3, 0.25 * tip, 0.5 * tip, 0.75 * tip, tip] {
                let a = beam.compliance(rho);
                let b = beam.compliance_with_rule(rho, &r40);
                for (x, y) in [
                    (a.bending_m_per_n, b.bending_m_per_n),
                    (a.shear_m_per_n, b.shear_m_per_n),
                    (a.axial_m_per_n, b.axial_m_per_n),
                ] {
                    if y > 0.0 {
                        assert!(((x - y) / y).abs() < 1e-8, "rho {rho}: {x} vs {y}");
                    }
                }
            }
        }
    }

    fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
        let dx = (b - a) / n as f64;
        let inner: f64 = (1..n)
            .map(|i| f(a + i as f64 * dx) * (2 + 2 * (i % 2)) as f64)
            .sum();
        (f(a) + f(b) + inner) * dx / 3.0
    }

    #[test]
    fn bending_matches_direct_integration_in_y() {
        // Second method: Simpson in y (4000 panels on each part), the half-thickness h(y)
        // found by bisection on y(alpha), so dy/d(alpha) is not used. Error O(dy^4) with
        // dy ~ 1 um: far below 1e-7 relative.
        let p = paper();
        let beam = &beams(&p)[0];
        let a1 = beam.contact_angle_rad(p.rho_pitch_m);
        let (hc, yc) = beam.involute_point(a1);
        let (s1, c1) = a1.sin_cos();
        let (yr, yb, hb) = beam.straight.unwrap();
        let h_of_y = |y: f64| {
            let (mut lo, mut hi) = (-beam.half_base_angle_rad, a1);
            for _ in 0..200 {
                let m = 0.5 * (lo + hi);
                *(if beam.involute_point(m).1 < y {
                    &mut lo
                } else {
                    &mut hi
                }) = m;
            }
            beam.involute_point(lo).0
        };
        let eb = beam.youngs_modulus_pa * beam.face_width_m;
        let f = |y: f64, h: f64| (c1 * (yc - y) - s1 * hc).powi(2) / (eb * 2.0 * h.powi(3) / 3.0);
        let direct =
            simpson(|y| f(y, h_of_y(y)), yb, yc, 4000) + simpson(|y| f(y, hb), yr, yb, 4000);
        let gauss = beam.compliance(p.rho_pitch_m).bending_m_per_n;
        assert!((direct / gauss - 1.0).abs() < 1e-7, "{direct} vs {gauss}");
    }

    #[test]
    fn load_at_base_circle_reduces_to_uniform_cantilever() {
        // rho = 0: only the straight part (constant section) remains; closed forms for a
        // uniform cantilever of length L loaded by the force components at its end.
        let p = paper();
        let beam = &beams(&p)[1];
        let c = beam.compliance(0.0);
        let (yr, yb, hb) = beam.straight.unwrap();
        let (s1, c1) = (-beam.half_base_angle_rad).sin_cos();
        let l = yb - yr;
        let (e, g, b) = (
            beam.youngs_modulus_pa,
            beam.shear_modulus_pa,
            beam.face_width_m,
        );
        let ei = e * 2.0 * hb.powi(3) * b / 3.0;
        let bend = (c1 * c1 * l.powi(3) / 3.0 - c1 * s1 * hb * l * l + (s1 * hb).powi(2) * l) / ei;
        let shear = 1.2 * c1 * c1 * l / (g * 2.0 * hb * b);
        let axial = s1 * s1 * l / (e * 2.0 * hb * b);
        assert!((c.bending_m_per_n / bend - 1.0).abs() < 1e-12);
        assert!((c.shear_m_per_n / shear - 1.0).abs() < 1e-12);
        assert!((c.axial_m_per_n / axial - 1.0).abs() < 1e-12);
    }

    #[test]
    fn compliance_grows_towards_the_tip() {
        // A longer lever arm can only add strain energy (bending dominates).
        let p = paper();
        for beam in beams(&p) {
            let mut last = 0.0;
            for i in 0..=20 {
                let rho = 1e-3 + 8e-3 * i as f64 / 20.0;
                let c = beam.compliance(rho).total_m_per_n();
                assert!(c > last, "{rho}");
                last = c;
            }
        }
    }

    #[test]
    fn hertz_stiffness_matches_eq_11_by_hand() {
        // pi * 205e9 * 0.020 / (4 * (1 - 0.09)) = 1.28805e10 / 3.64 = 3.53861e9 N/m.
        let m = ElasticPair::from_case(&MaterialsSection::default());
        let k = hertz_stiffness_n_per_m(0.020, &m);
        assert!((k / 3.53861e9 - 1.0).abs() < 2e-6, "{k}");
        // Mixed materials: symmetric, and between the two single-material values.
        let pair = |e1, n1, e2, n2| ElasticPair {
            e_pinion_pa: e1,
            nu_pinion: n1,
            e_gear_pa: e2,
            nu_gear: n2,
        };
        let km = hertz_stiffness_n_per_m(0.02, &pair(205e9, 0.3, 110e9, 0.34));
        let swapped = hertz_stiffness_n_per_m(0.02, &pair(110e9, 0.34, 205e9, 0.3));
        assert!((km - swapped).abs() < 1e-6 * km);
        let soft = pair(110e9, 0.34, 110e9, 0.34);
        assert!(km < k && km > hertz_stiffness_n_per_m(0.02, &soft));
    }
}
