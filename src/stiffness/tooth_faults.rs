//! The compliance a tooth fault adds to the potential energy integrals of one tooth
//! (`potential_energy::ToothBeam`), as a function of the contact position.
//!
//! **Root crack** (Chen & Shao, Eng. Fail. Anal. 18 (2011) 2149; the cracked section of
//! Tian 2004 and Wu, Zuo & Parey, J. Sound Vib. 317 (2008) 608). A straight crack starts
//! at the root circle on the loaded flank's side and runs into the tooth at angle nu to
//! the centreline over a depth q, so its tip lies h_q = h_r - q sin(nu) from the
//! centreline (h_r the root's half-thickness; h_q < 0 past the centreline). Material on
//! the cracked side outside a limit line through the crack tip carries no stress; the
//! section at height y is t(y) = h(y) + min(h(y), l(y)) thick (area t b, second moment
//! t^3 b / 12, the moment arm still from the centreline as in the sources), and no
//! section loses more than the crack's reach q sin(nu) (the involute flank bulges out
//! above the base circle, by 0.16 % of the half-thickness on the paper's pinion, and a
//! line through a vanishing crack's tip would otherwise cut that bulge off). The limit
//! line: Chen & Shao's parallel to the centreline, l = h_q, while the crack leaves the
//! cracked side thicker than the tip (h_q >= h_tip); for deeper cracks, where that line
//! would leave no section above the crack, the line from the crack tip to the tip corner
//! of the cracked flank, the limit line Mohammed, Rantatalo & Aidanpaa (Eng. Fail. Anal.
//! 34 (2013) 235) proposed for large cracks; the two agree at h_q = h_tip, so the
//! compliance is continuous in q. The crack's own height (q cos nu) is not modelled,
//! as in the sources: the section is reduced from the root up. At q = 0 the section is
//! the uncracked one, so the compliance is exactly the healthy tooth's.
//!   Partial face width: the face cut into slices that act in parallel, each with the
//! crack depth it has (Chen & Shao 2011), k = (1/b) int k_slice(q(z)) dz. A crack that
//! has run at its depth q across a share w of the face from one side gives
//! k = (1 - w) k(0) + w k(q), continuous into the through crack at w = 1 (Chen & Shao
//! also let the depth fall towards the crack front; a uniform depth over the covered
//! width keeps one depth per crack, as the case file gives it).
//!
//! **Spall** (Saxena, Parey & Chouksey, Eng. Fail. Anal. 70 (2016) 200; Ma et al.,
//! Mech. Syst. Signal Process. 2015 review): a pit of depth d over a share f of the face
//! width and between two roll distances rho (along the line of action; its length on the
//! flank surface is (rho / r_b) times its roll length, `spall_gap_m`). Over its heights the
//! section loses the pit's rectangle at the loaded flank (area f b d, second moment about
//! the shifted centroid), which softens the tooth for every contact above the pit's lower
//! edge; with the contact inside it the Hertz line contact is (1 - f) b long (k_h scaled
//! by 1 - f). A pit across the whole face (f = 1) leaves the contact on its edges instead
//! (full length) and opens a gap (`dynamics::tooth_mesh`).

use super::potential_energy::{GaussLegendre, ToothBeam};
use std::f64::consts::PI;

/// A root crack (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crack {
    /// Crack length from the root along its path, m.
    pub depth_m: f64,
    /// Angle of the crack path to the tooth centreline, rad.
    pub angle_rad: f64,
    /// Share of the face width the crack has run across (1: through the face).
    pub width_fraction: f64,
}

impl Crack {
    /// Largest depth that leaves the tooth attached: the crack's reach across the root,
    /// q sin(nu), below the root's full thickness 2 h_r.
    pub fn max_depth_m(beam: &ToothBeam, angle_rad: f64) -> f64 {
        2.0 * beam.root_section().0 / angle_rad.sin()
    }
}

/// Beam compliance (bending + shear + axial, m/N) of `beam` at contact rho with a
/// through-face crack of depth `depth_m` at `angle_rad`; `tip_rho_m` locates the tip
/// corner of the flank.
fn cracked_beam_compliance(
    beam: &ToothBeam,
    tip_rho_m: f64,
    depth_m: f64,
    angle_rad: f64,
    rho_m: f64,
) -> f64 {
    let rule = GaussLegendre::default_rule();
    let b = beam.face_width_m;
    let (h_root, y_root) = beam.root_section();
    let (h_tip, y_tip) = beam.involute_point(beam.contact_angle_rad(tip_rho_m));
    let reach = depth_m * angle_rad.sin();
    let h_q = h_root - reach;
    let limit = |y: f64| {
        if h_q >= h_tip || y_tip <= y_root {
            h_q
        } else {
            h_q + (h_tip - h_q) * ((y - y_root) / (y_tip - y_root)).clamp(0.0, 1.0)
        }
    };
    beam.compliance_with_section(rho_m, rule, |h, y| {
        cracked_section(h, limit(y), reach, h_root, b)
    })
    .total_m_per_n()
}

/// The cracked section at half-thickness h (m) with the limit line at `limit_m` from the
/// centreline, the crack's reach q sin(nu) and the root's half-thickness (m), face width
/// b (m): (area m^2, second moment m^4) of t = h + min(h, max(limit, h - reach)) (module
/// docs; shared with the ring tooth, `ring_tooth_faults`).
pub(crate) fn cracked_section(
    h: f64,
    limit_m: f64,
    reach_m: f64,
    h_root_m: f64,
    b: f64,
) -> (f64, f64) {
    let cracked_side = h.min(limit_m.max(h - reach_m));
    let t = (h + cracked_side).max(1e-9 * h_root_m);
    (t * b, t * t * t * b / 12.0)
}

/// The pitted section at half-thickness h (m), face width b (m): the full 2h x b
/// rectangle less a pit `depth_m` deep (at most [`Spall::MAX_THICKNESS_SHARE`] of 2h)
/// over the share `f` of the face, (area m^2, second moment about the shifted centroid
/// m^4) by the parallel-axis theorem (shared with the ring tooth, `ring_tooth_faults`).
pub(crate) fn pitted_section(h: f64, b: f64, f: f64, depth_m: f64) -> (f64, f64) {
    let full = (2.0 * h * b, 2.0 * h * h * h * b / 3.0);
    // The pit u in [h - d, h] over width f b, u across the thickness from the centreline.
    let d = depth_m.min(Spall::MAX_THICKNESS_SHARE * 2.0 * h);
    let pit_area = f * b * d;
    let area = full.0 - pit_area;
    let first = -pit_area * (h - 0.5 * d);
    let second = full.1 - f * b * (h.powi(3) - (h - d).powi(3)) / 3.0;
    let u_bar = first / area;
    (area, second - area * u_bar * u_bar)
}

/// Compliance (m/N) the crack adds to the tooth at contact rho (its own radius of
/// curvature, m): 1/k_cracked - 1/k_healthy of the tooth beam, slices of a partial crack
/// in parallel (module docs). Zero for a crack of zero depth.
pub fn crack_compliance_m_per_n(
    beam: &ToothBeam,
    tip_rho_m: f64,
    crack: &Crack,
    rho_m: f64,
) -> f64 {
    if crack.depth_m <= 0.0 {
        return 0.0;
    }
    let c0 = beam.compliance(rho_m).total_m_per_n();
    let k_of = |q: f64| 1.0 / cracked_beam_compliance(beam, tip_rho_m, q, crack.angle_rad, rho_m);
    let w = crack.width_fraction.clamp(0.0, 1.0);
    let k = if w >= 1.0 {
        k_of(crack.depth_m)
    } else {
        (1.0 - w) / c0 + w * k_of(crack.depth_m)
    };
    1.0 / k - c0
}

/// A spall on one flank (SI; positions as the gear's own radius of curvature).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spall {
    /// Start of the pit as the gear's own radius of curvature, m.
    pub rho_lo_m: f64,
    /// End of the pit as the gear's own radius of curvature, m.
    pub rho_hi_m: f64,
    /// Depth of the pit normal to the flank, m.
    pub depth_m: f64,
    /// Share of the face width it covers.
    pub width_fraction: f64,
}

impl Spall {
    /// Largest share of the tooth's thickness 2h a pit may take at a section (beyond it
    /// the section is all but cut through and the beam model has no meaning).
    pub const MAX_THICKNESS_SHARE: f64 = 0.95;

    /// Whether the contact at own radius of curvature `rho_m` (m) lies on the pit.
    pub fn contains(&self, rho_m: f64) -> bool {
        rho_m >= self.rho_lo_m && rho_m <= self.rho_hi_m
    }

    /// Deepest pit the spall's extent holds: [`Self::MAX_THICKNESS_SHARE`] of the
    /// thickness 2h at its upper edge, where the tooth is thinnest, m.
    pub fn max_depth_m(&self, beam: &ToothBeam) -> f64 {
        let h = beam.involute_point(beam.contact_angle_rad(self.rho_hi_m)).0;
        Self::MAX_THICKNESS_SHARE * 2.0 * h
    }
}

/// Compliance (m/N) the spall adds to the tooth beam and, with the contact inside a
/// partial-width spall, to the Hertz contact (`hertz_m_per_n` = 1/k_h of the full face),
/// at contact rho (own radius of curvature, m).
///
/// Over the pit's heights the section is the full rectangle less the pit's, with its
/// second moment about the shifted centroid (parallel-axis theorem). The bending moment
/// keeps its arm from the tooth centreline (`ToothBeam::compliance_with_section`), as for
/// the cracked section: the axial force F sin(alpha_1) times the centroid's shift u_bar
/// (about d/2 towards the unpitted flank for a full-width pit of depth d) is left out of
/// the moment. Its relative size there is u_bar tan(alpha_1) / (y_c - y), y_c - y the
/// moment arm along the tooth: for a 50 µm pit 2 mm below the load at the pitch point of
/// the paper's pinion, 25e-6 x 0.27 / 2e-3 = 0.3 % of the moment, over the pit's
/// heights only.
pub fn spall_compliance_m_per_n(
    beam: &ToothBeam,
    spall: &Spall,
    hertz_m_per_n: f64,
    rho_m: f64,
) -> f64 {
    let rule = GaussLegendre::default_rule();
    let b = beam.face_width_m;
    let f = spall.width_fraction.clamp(0.0, 1.0);
    let y_of = |rho: f64| beam.involute_point(beam.contact_angle_rad(rho)).1;
    let (y_lo, y_hi) = (y_of(spall.rho_lo_m), y_of(spall.rho_hi_m));
    let edges = [spall.rho_lo_m, spall.rho_hi_m].map(|r| beam.contact_angle_rad(r));
    let pitted = beam.compliance_with_section_split(rho_m, rule, &edges, |h, y| {
        if y < y_lo || y > y_hi || f <= 0.0 {
            return (2.0 * h * b, 2.0 * h * h * h * b / 3.0);
        }
        pitted_section(h, b, f, spall.depth_m)
    });
    let mut extra = pitted.total_m_per_n() - beam.compliance(rho_m).total_m_per_n();
    if spall.contains(rho_m) && f < 1.0 {
        extra += hertz_m_per_n * f / (1.0 - f);
    }
    extra
}

/// The gap a spall across the whole face opens at own rho: the depth a convex mate sinks
/// into the slot before it rests on the nearer edge, min(d, s^2 / (2 R)), m (d the pit's
/// depth, R = `radius_m` the relative radius of curvature of the pair at the contact, m).
///
/// s is the distance from the contact to the nearer edge along the pitted flank's surface
/// (the sagitta x^2 / (2 R) of two curved surfaces holds for x in their common tangent
/// plane: Johnson, Contact Mechanics, 1985, section 4.1). The spall's edges are given as
/// roll distances rho (along the line of action, which is the surface normal, not in the
/// tangent plane); on an involute of base radius r_b (`base_radius_m`, the pitted
/// tooth's own, m) the arc length is ds = (rho / r_b) d rho, so between rho and an edge
/// rho_e it is s = |rho_e^2 - rho^2| / (2 r_b) exactly (Litvin & Fuentes, Gear Geometry
/// and Applied Theory, 2004, the involute's arc length rho^2 / (2 r_b)). The formula keeps
/// the leading term in s / rho: the involute's curvature changes along the slot (d(1/rho)/ds
/// = -r_b / rho^3), which changes the gap by a relative r_b s / (3 rho^2) at most (3 % for a
/// contact 0.25 mm of roll above the paper pinion's start of active profile, 1.6 % at its
/// pitch point with a 1 mm spall). Zero outside the spall and for a partial-width spall
/// (the contact stays on the intact width).
pub fn spall_gap_m(spall: &Spall, base_radius_m: f64, radius_m: f64, rho_m: f64) -> f64 {
    if spall.width_fraction < 1.0 || !spall.contains(rho_m) || radius_m <= 0.0 {
        return 0.0;
    }
    let arc = |edge: f64| (edge * edge - rho_m * rho_m).abs() / (2.0 * base_radius_m);
    let s = arc(spall.rho_lo_m).min(arc(spall.rho_hi_m));
    spall.depth_m.min(s * s / (2.0 * radius_m))
}

/// Degrees to radians.
pub fn deg(x: f64) -> f64 {
    x * PI / 180.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;
    use crate::geometry::GearPair;

    fn beam() -> (GearPair, ToothBeam) {
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let b = ToothBeam::new(&p.pinion, p.face_width_m, 205e9, 0.3);
        (p, b)
    }

    #[test]
    fn crack_compliance_is_zero_at_zero_depth_and_grows_with_depth() {
        let (p, b) = beam();
        let tip = p.pinion.tip_rho_m();
        let rho = p.rho_pitch_m;
        let crack = |q: f64, w: f64| Crack {
            depth_m: q,
            angle_rad: deg(45.0),
            width_fraction: w,
        };
        assert_eq!(
            crack_compliance_m_per_n(&b, tip, &crack(0.0, 1.0), rho),
            0.0
        );
        // A vanishing crack: no section loses more than its reach (1e-9 m of ~1.7 mm),
        // so the compliance changes by ~3 x 1e-9 / 1.7e-3 relative at most.
        let tiny = crack_compliance_m_per_n(&b, tip, &crack(1e-9, 1.0), rho);
        assert!(
            tiny.abs() < 1e-5 * b.compliance(rho).total_m_per_n(),
            "{tiny}"
        );
        let qmax = Crack::max_depth_m(&b, deg(45.0));
        let mut last = 0.0;
        for i in 1..=9 {
            let q = qmax * i as f64 / 10.0;
            let c = crack_compliance_m_per_n(&b, tip, &crack(q, 1.0), rho);
            assert!(c > last, "depth {q}: {c} <= {last}");
            // A partial crack adds less than a through crack of the same depth.
            let part = crack_compliance_m_per_n(&b, tip, &crack(q, 0.5), rho);
            assert!(part > 0.0 && part < c);
            last = c;
        }
    }

    #[test]
    fn spall_softens_only_contacts_at_or_above_it() {
        let (p, b) = beam();
        let s = Spall {
            rho_lo_m: p.rho_pitch_m,
            rho_hi_m: p.rho_pitch_m + 1e-3,
            depth_m: 50e-6,
            width_fraction: 0.5,
        };
        let kh = 1.0 / 3.5e9;
        assert!(spall_compliance_m_per_n(&b, &s, kh, s.rho_lo_m - 0.5e-3).abs() < 1e-20);
        let inside = spall_compliance_m_per_n(&b, &s, kh, s.rho_lo_m + 0.5e-3);
        // Inside: at least the Hertz part k_h (1 - f) -> f/(1-f) / k_h.
        assert!(inside > kh);
        let above = spall_compliance_m_per_n(&b, &s, kh, s.rho_lo_m + 1.5e-3);
        assert!(above > 0.0 && above < kh);
        // A partial-width spall opens no gap: the contact stays on the intact width.
        assert_eq!(
            spall_gap_m(&s, b.base_radius_m, 5e-3, s.rho_lo_m + 0.5e-3),
            0.0
        );
    }

    /// Point of the involute of base radius `rb` at roll distance `rho` (m), in the gear's
    /// frame, and the unit normal towards the mate (from the base tangency point to the
    /// point): the textbook parametrisation r_b (cos t + t sin t, sin t - t cos t), t = rho / r_b.
    fn involute(rb: f64, rho: f64) -> ([f64; 2], [f64; 2]) {
        let t = rho / rb;
        let (s, c) = t.sin_cos();
        ([rb * (c + t * s), rb * (s - t * c)], [s, -c])
    }

    /// Second method for the gap: the pitted flank's real involute points and the mate's
    /// osculating circle at the contact (radius rho_2, centred at the mate's base tangency
    /// point on the line of action), sunk along the line of action until it touches the
    /// nearer slot edge: |E - C + delta n| = rho_2 solved for the smaller root delta.
    fn sink_into_slot(rb: f64, rho: f64, rho2: f64, edges: [f64; 2], depth: f64) -> f64 {
        let (p, n) = involute(rb, rho);
        let c = [p[0] + rho2 * n[0], p[1] + rho2 * n[1]];
        edges.iter().fold(depth, |best, e| {
            let (q, _) = involute(rb, *e);
            let d = [q[0] - c[0], q[1] - c[1]];
            let dn = d[0] * n[0] + d[1] * n[1];
            let dd = d[0] * d[0] + d[1] * d[1];
            best.min(-dn - (dn * dn - (dd - rho2 * rho2)).sqrt())
        })
    }

    #[test]
    fn full_width_spall_gap_is_the_sink_of_the_mate_into_the_involute_slot() {
        // Spalls on the paper's pinion: 1 mm of roll centred at the pitch point, and 0.4 mm
        // of roll just above the start of active profile (where the flank is most curved).
        // The gap against the second method at contacts across each slot. The formula keeps
        // the leading term in s / rho; the involute's curvature falls along the slot
        // (d(1/rho)/ds = -r_b / rho^3), which changes the pitted flank's drop below the
        // tangent plane at the edge by a relative r_b s / (3 rho^2) (next term of its Taylor
        // series), and the tangent-plane distance differs from s by O((s / rho)^2): the
        // bound is 1.5 times that first term (it reaches 1.6 % at the pitch point and 3 %
        // near the start of active profile). The roll-length form of the sagitta this
        // replaces is off by (r_b / rho)^2 (7.5 at the pitch point), far outside.
        let (p, b) = beam();
        let rb = b.base_radius_m;
        let deep = 1e-3;
        for (lo, hi) in [
            (p.rho_pitch_m - 0.5e-3, p.rho_pitch_m + 0.5e-3),
            (p.rho_start_m + 0.05e-3, p.rho_start_m + 0.45e-3),
        ] {
            let s = Spall {
                rho_lo_m: lo,
                rho_hi_m: hi,
                depth_m: deep,
                width_fraction: 1.0,
            };
            for f in [0.1, 0.25, 0.5, 0.75, 0.9] {
                let rho = lo + f * (hi - lo);
                let rho2 = p.rho_gear(rho);
                let r = rho * rho2 / (rho + rho2);
                let gap = spall_gap_m(&s, rb, r, rho);
                let exact = sink_into_slot(rb, rho, rho2, [lo, hi], deep);
                let arc = ((rho * rho - lo * lo).min(hi * hi - rho * rho)) / (2.0 * rb);
                let bound = 1.5 * rb * arc / (3.0 * rho * rho);
                let rel = gap / exact - 1.0;
                assert!(
                    rel.abs() < bound,
                    "rho {rho}: {gap} vs {exact} ({rel:+e}, bound {bound:e})"
                );
            }
            // A shallow pit caps the gap at its depth (the mate bottoms out).
            let shallow = Spall { depth_m: 1e-7, ..s };
            let mid = 0.5 * (lo + hi);
            let r = mid * p.rho_gear(mid) / (mid + p.rho_gear(mid));
            assert_eq!(spall_gap_m(&shallow, rb, r, mid), 1e-7);
            // Outside the slot: no gap.
            assert_eq!(spall_gap_m(&s, rb, r, hi + 1e-6), 0.0);
        }
    }
}
