//! The compliance a tooth fault adds to a ring tooth (`internal::RingToothBeam`), as a
//! function of the contact position: the external tooth's crack and spall
//! (`tooth_faults`) carried over to the internal tooth's potential-energy integrals
//! (docs/MODEL.md 12.14).
//!
//! **Root crack** (Chen & Shao, Eng. Fail. Anal. 18 (2011) 2149, the cracked section, as
//! `tooth_faults`; its placement in a ring tooth as Liang, Zuo & Pandey, Mech. Mach.
//! Theory 76 (2014) 20, place a crack in a planet's tooth). The ring tooth's root is its
//! outer (root) circle, where it joins the rim, and its thickest section; the crack starts
//! there at the flank the planet loads (the side in tension: the line-of-action force
//! bends the tooth away from that flank as it does an external tooth) and runs into the
//! tooth at angle nu to its centreline over a depth q, its tip h_q = h_f - q sin(nu) from
//! the centreline (h_f the root section's half-thickness). On the cracked side a section
//! of height Y keeps min(h, l(Y)) (l the limit line), at least h - q sin(nu):
//! t(Y) = h + min(h, max(l(Y), h - q sin nu)), area t b, second moment t^3 b / 12, the
//! moment arm still from the centreline. The limit line: parallel to the centreline,
//! l = h_q, while h_q >= h_tip (the tooth's half-thickness at its tip circle, its thinnest
//! section); else the line from the crack tip (at the root's height) to the cracked
//! flank's tip corner (Mohammed, Rantatalo & Aidanpaa 2013, as `tooth_faults`).
//! Assumptions: the crack's own height along the tooth (q cos nu) is not modelled (the
//! sections are reduced from the root towards the tip, as in the sources); the rim under
//! the crack stays rigid (the ring mesh's rigid-rim assumption, 12.2); and since the ring
//! tooth thickens towards its root, a parallel limit line cuts only the sections thicker
//! than 2 h_q, all near the root: a crack of a given depth removes a smaller share of a
//! ring tooth than of an external tooth, whose root is its thinnest part below the
//! contact. Partial face width: slices in parallel, k = (1 - w) k(0) + w k(q).
//!
//! **Spall** (Saxena, Parey & Chouksey 2016, as `tooth_faults`): a pit of depth d over a
//! share f of the face between two of the ring's own radii of curvature rho2 (its centre
//! `spall_position_mm` from the pitch point towards the ring's tip, i.e. towards smaller
//! rho2: the ring's tip is its inner circle). Over the pit's heights the section loses the
//! pit's rectangle at the loaded flank; with the contact inside a partial-width pit the
//! Hertz line is (1 - f) b long. A ring tooth's contact softens with a pit between it and
//! the root, i.e. at radii above the contact's.

use super::internal::RingToothBeam;
use super::potential_energy::GaussLegendre;
use super::tooth_faults::{cracked_section, pitted_section, Crack, Spall};

/// Largest crack depth that leaves the ring tooth attached: its reach across the root,
/// q sin(nu), below the root's full thickness 2 h_f, m.
pub fn ring_crack_max_depth_m(beam: &RingToothBeam, angle_rad: f64) -> f64 {
    2.0 * beam.root_section().0 / angle_rad.sin()
}

/// Beam compliance (m/N) of the ring tooth at its own contact rho2 (m) with a
/// through-face root crack of depth `depth_m` at `angle_rad` (module docs).
fn cracked_ring_compliance(beam: &RingToothBeam, depth_m: f64, angle_rad: f64, rho2_m: f64) -> f64 {
    let b = beam.face_width_m;
    let (h_root, y_root) = beam.root_section();
    let (h_tip, y_tip) = beam.tip_section();
    let reach = depth_m * angle_rad.sin();
    let h_q = h_root - reach;
    let limit = |y: f64| {
        if h_q >= h_tip || y_root <= y_tip {
            h_q
        } else {
            h_q + (h_tip - h_q) * ((y_root - y) / (y_root - y_tip)).clamp(0.0, 1.0)
        }
    };
    beam.compliance_with_section_split(rho2_m, GaussLegendre::default_rule(), &[], |h, y| {
        cracked_section(h, limit(y), reach, h_root, b)
    })
    .total_m_per_n()
}

/// Compliance (m/N) a root crack adds to the ring tooth at its own contact rho2 (m):
/// 1/k_cracked - 1/k_healthy of the tooth beam, slices of a partial crack in parallel
/// (module docs). Zero for a crack of zero depth.
pub fn ring_crack_compliance_m_per_n(beam: &RingToothBeam, crack: &Crack, rho2_m: f64) -> f64 {
    if crack.depth_m <= 0.0 {
        return 0.0;
    }
    let c0 = beam.compliance(rho2_m).total_m_per_n();
    let cracked = cracked_ring_compliance(beam, crack.depth_m, crack.angle_rad, rho2_m);
    let w = crack.width_fraction.clamp(0.0, 1.0);
    let k = if w >= 1.0 {
        1.0 / cracked
    } else {
        (1.0 - w) / c0 + w / cracked
    };
    1.0 / k - c0
}

/// Deepest pit a spall on a ring tooth holds: [`Spall::MAX_THICKNESS_SHARE`] of the
/// thickness 2h at its edge nearer the tip (the ring tooth's thinner edge), m.
pub fn ring_spall_max_depth_m(beam: &RingToothBeam, spall: &Spall) -> f64 {
    let h = beam.flank_point(beam.radius_at_m(spall.rho_lo_m)).0;
    Spall::MAX_THICKNESS_SHARE * 2.0 * h
}

/// Compliance (m/N) a spall (own rho2 of the ring, m) adds to the ring tooth's beam and,
/// with the contact inside a partial-width pit, to the Hertz contact (`hertz_m_per_n` =
/// 1/k_h of the full face), at its own contact rho2 (m). The section over the pit's
/// heights is the rectangle less the pit's, its second moment about the shifted centroid,
/// as `tooth_faults::spall_compliance_m_per_n` (whose notes on the moment arm apply).
pub fn ring_spall_compliance_m_per_n(
    beam: &RingToothBeam,
    spall: &Spall,
    hertz_m_per_n: f64,
    rho2_m: f64,
) -> f64 {
    let b = beam.face_width_m;
    let f = spall.width_fraction.clamp(0.0, 1.0);
    let edges = [spall.rho_lo_m, spall.rho_hi_m].map(|r| beam.radius_at_m(r));
    let (y_lo, y_hi) = (beam.flank_point(edges[0]).1, beam.flank_point(edges[1]).1);
    let rule = GaussLegendre::default_rule();
    let pitted = beam.compliance_with_section_split(rho2_m, rule, &edges, |h, y| {
        if y < y_lo || y > y_hi || f <= 0.0 {
            return (2.0 * h * b, 2.0 * h * h * h * b / 3.0);
        }
        pitted_section(h, b, f, spall.depth_m)
    });
    let mut extra = pitted.total_m_per_n() - beam.compliance(rho2_m).total_m_per_n();
    if spall.contains(rho2_m) && f < 1.0 {
        extra += hertz_m_per_n * f / (1.0 - f);
    }
    extra
}

#[cfg(test)]
#[path = "tests_ring_tooth_faults.rs"]
mod tests;
