//! A tooth thinned by wear in the potential energy integrals (severe wear, issue 18): the
//! flank that carries the load has lost w(rho) normal to the profile, so at height y the
//! section is t = 2h - w / cos(alpha_1) thick instead of 2h (area t b, second moment
//! t^3 b / 12, moment arm from the centreline as for the cracked tooth, `tooth_faults`),
//! with alpha_1 = rho / r_b - alpha_2 the involute parameter of the flank point at that
//! height (`ToothBeam::involute_point`), whose flank normal (cos alpha_1, sin alpha_1)
//! makes the angle alpha_1 with the horizontal section line: a normal offset w moves the
//! flank along the section by w / cos(alpha_1) ([`thinning_m`]). Below the start of
//! active profile nothing is worn.

use super::potential_energy::{GaussLegendre, ToothBeam};
use crate::geometry::flank_shape::interpolate_clamped;

/// Compliance (m/N) the wear `wear_m` at own radii of curvature `rho_m` (ascending, the
/// worn part of the flank) adds to `beam` loaded at own rho `load_rho_m`.
pub fn worn_compliance_m_per_n(
    beam: &ToothBeam,
    rho_m: &[f64],
    wear_m: &[f64],
    load_rho_m: f64,
) -> f64 {
    if wear_m.iter().all(|w| *w <= 0.0) || rho_m.is_empty() {
        return 0.0;
    }
    let (lo, hi) = (rho_m[0], rho_m[rho_m.len() - 1]);
    let rb = beam.base_radius_m;
    let b = beam.face_width_m;
    // The worn zone's ends, where the section jumps (the wear is deepest at the start of
    // active profile), split the integral (`ToothBeam::compliance_with_section_split`).
    let ends = [lo, hi].map(|r| beam.contact_angle_rad(r));
    let rule = GaussLegendre::default_rule();
    let worn = beam.compliance_with_section_split(load_rho_m, rule, &ends, |h, y| {
        // The flank point at this height: radius r, radius of curvature sqrt(r^2 - rb^2).
        let r2 = h * h + y * y;
        let rho = (r2 - rb * rb).max(0.0).sqrt();
        let w = if r2 > rb * rb && rho >= lo && rho <= hi {
            interpolate_clamped(rho_m, wear_m, rho).max(0.0)
        } else {
            0.0
        };
        let t = (2.0 * h - thinning_m(beam, rho, w)).max(1e-3 * h);
        (t * b, t * t * t * b / 12.0)
    });
    worn.total_m_per_n() - beam.compliance(load_rho_m).total_m_per_n()
}

/// How much thinner (m) the section through the flank point of own radius of curvature
/// `rho_m` becomes when the flank there loses `wear_m` normal to the involute: the flank
/// normal at involute parameter alpha_1 = rho / r_b - alpha_2 is (cos alpha_1,
/// sin alpha_1) in the tooth's (h, y) frame (`ToothBeam::involute_point`: P - T =
/// r_b u (cos alpha_1, sin alpha_1)), so a parallel offset w of the flank moves it along
/// the horizontal section line by w / cos(alpha_1), to first order in w (the next term is
/// a relative w tan^2(alpha_1) / (2 rho), from the offset's curvature 1 / (rho - w)).
pub fn thinning_m(beam: &ToothBeam, rho_m: f64, wear_m: f64) -> f64 {
    wear_m / beam.contact_angle_rad(rho_m).cos()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;
    use crate::geometry::GearPair;

    /// Half-thickness (m) at height `y` of the flank whose polar angle from the centreline
    /// at radius r is psi(r) = `half_angle` - inv(alpha_r), cos(alpha_r) = r_b / r (the
    /// textbook polar form of the involute tooth), by bisection on r: a second description
    /// of the flank, independent of `ToothBeam::involute_point`.
    fn half_thickness_at(rb: f64, half_angle: f64, y: f64) -> f64 {
        let psi = |r: f64| {
            let a = (rb / r).acos();
            half_angle - (a.tan() - a)
        };
        let (mut lo, mut hi) = (rb, 2.0 * rb);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid * psi(mid).cos() < y {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo * psi(lo).sin()
    }

    #[test]
    fn a_uniform_normal_wear_thins_the_section_as_the_rotated_involute_does() {
        // A flank worn by a uniform depth w normal to the involute is the parallel curve at
        // distance w, which is the involute of the same base circle turned towards the
        // centreline by w / r_b (the unwinding string is w shorter). Its half-thickness at
        // height y, against the nominal one at the same height, is the exact thinning of the
        // section. thinning_m is its first-order form w / cos(alpha_1); the second-order
        // term follows from the offset's curvature (the circle of radius rho - w about the
        // same base tangency point, cut by the horizontal through the flank point):
        // exact = w / cos(alpha_1) (1 + w tan^2(alpha_1) / (2 rho) + O((w / rho)^2)).
        // With that term added, what remains is bounded by (w / rho)^2 (8e-7 at the tip for
        // 10 um, 2e-3 at the start of active profile for 75 um), far below the factor
        // 1 / cos(alpha_1) under test (15 % at the tip).
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let beam = ToothBeam::new(&p.pinion, p.face_width_m, 205e9, 0.3);
        let (rb, a2) = (beam.base_radius_m, beam.half_base_angle_rad);
        for w in [10e-6, 75e-6] {
            for i in 0..=20 {
                let rho = p.rho_start_m + (p.rho_end_m - p.rho_start_m) * i as f64 / 20.0;
                let r = rb.hypot(rho);
                let a_r = (rb / r).acos();
                let psi = a2 - (a_r.tan() - a_r);
                let (h, y) = (r * psi.sin(), r * psi.cos());
                let exact = h - half_thickness_at(rb, a2 - w / rb, y);
                let a1 = beam.contact_angle_rad(rho);
                let second = w * a1.tan().powi(2) / (2.0 * rho);
                let rel = thinning_m(&beam, rho, w) * (1.0 + second) / exact - 1.0;
                assert!(rel.abs() < (w / rho).powi(2), "w {w}, rho {rho}: {rel:e}");
            }
        }
        // The factor is the flank normal's: 1 / cos(alpha_1) = 1.15 at the pinion's tip.
        let tip = thinning_m(&beam, p.rho_end_m, 1.0);
        assert!((tip - 1.0 / (p.rho_end_m / rb - a2).cos()).abs() < 1e-15 && tip > 1.15);
    }

    #[test]
    fn the_worn_beam_is_the_beam_of_the_rotated_involutes_section() {
        // The compliance the code adds for a uniform wear over the active flank, against
        // the potential energy integrals over the exact worn section (nominal
        // half-thickness plus the rotated involute's at each height, the worn part being
        // the active flank as in the code). The two sections differ by the second-order
        // term of the thinning above (at most w tan^2(alpha_1) / (2 rho) = 1.2e-3 of it at
        // 75 um); the added compliance is near-linear in the thinning, so its relative
        // difference stays below twice that.
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let beam = ToothBeam::new(&p.pinion, p.face_width_m, 205e9, 0.3);
        let (rb, a2, b) = (
            beam.base_radius_m,
            beam.half_base_angle_rad,
            beam.face_width_m,
        );
        let (lo, hi) = (p.rho_start_m, p.rho_end_m);
        let grid: Vec<f64> = (0..=40).map(|i| lo + (hi - lo) * i as f64 / 40.0).collect();
        // The reference integrates piecewise over 400 pieces of the worn zone (and its ends),
        // a quadrature of its own.
        let fine: Vec<f64> = (0..=400)
            .map(|i| beam.contact_angle_rad(lo + (hi - lo) * i as f64 / 400.0))
            .collect();
        for w in [10e-6, 75e-6] {
            let wear = vec![w; grid.len()];
            let bound = 2.0 * w * (hi / rb - a2).tan().powi(2) / (2.0 * hi);
            for load in [p.rho_pitch_m, hi] {
                let code = worn_compliance_m_per_n(&beam, &grid, &wear, load);
                let exact = beam
                    .compliance_with_section_split(
                        load,
                        GaussLegendre::default_rule(),
                        &fine,
                        |h, y| {
                            let rho = (h * h + y * y - rb * rb).max(0.0).sqrt();
                            let t = if h * h + y * y > rb * rb && rho >= lo && rho <= hi {
                                h + half_thickness_at(rb, a2 - w / rb, y)
                            } else {
                                2.0 * h
                            };
                            (t * b, t * t * t * b / 12.0)
                        },
                    )
                    .total_m_per_n()
                    - beam.compliance(load).total_m_per_n();
                let rel = code / exact - 1.0;
                assert!(
                    rel.abs() < bound,
                    "w {w}, load {load}: {rel:e} (bound {bound:e})"
                );
            }
        }
    }
}
