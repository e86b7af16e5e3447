//! Tests of the ring tooth's crack and spall compliance against a second integration
//! written from the geometry alone (Simpson in the radius, the height's derivative by
//! central differences) and the orderings the section model forces.

use super::*;
use crate::geometry::internal::InternalGear;
use crate::stiffness::internal::RingToothBeam;

const E: f64 = 206e9;
const NU: f64 = 0.3;
const M: f64 = 2e-3;
const B: f64 = 0.02;

fn ring() -> InternalGear {
    InternalGear::generated(84, 0.0, M, 20f64.to_radians(), 0.8, 1.25)
}

fn beam() -> RingToothBeam {
    RingToothBeam::new(&ring(), B, E, NU)
}

fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let dx = (b - a) / n as f64;
    let inner: f64 = (1..n)
        .map(|i| f(a + i as f64 * dx) * (2 + 2 * (i % 2)) as f64)
        .sum();
    (f(a) + f(b) + inner) * dx / 3.0
}

/// The ring tooth's beam compliance at contact radius `r_c` (m) with the section
/// `t(h, Y)` thick (full: 2h), by Simpson in r on `n` intervals from the contact to the
/// root circle: h = r sin(theta), Y = r cos(theta) of the ring's tooth angle, dY/dr by
/// central differences, the load at beta = acos(r_b / r_c) + theta(r_c) (docs/MODEL.md
/// 12.2), section area t b, second moment t^3 b / 12.
fn second_method(r_c: f64, t: impl Fn(f64, f64) -> f64, n: usize) -> f64 {
    let g = ring();
    let hy = |r: f64| {
        let th = g.half_tooth_angle_rad(r);
        (r * th.sin(), r * th.cos())
    };
    let beta = (g.base_radius_m / r_c).acos() + g.half_tooth_angle_rad(r_c);
    let (sb, cb) = beta.sin_cos();
    let (hc, yc) = hy(r_c);
    let gm = E / (2.0 * (1.0 + NU));
    let f = |r: f64| {
        let (h, y) = hy(r);
        let d = 1e-7;
        let dy = (hy(r + d).1 - hy(r - d).1) / (2.0 * d);
        let w = t(h, y);
        let (a, i) = (w * B, w.powi(3) * B / 12.0);
        let m = cb * (y - yc) - sb * hc;
        (m * m / (E * i) + 1.2 * cb * cb / (gm * a) + sb * sb / (E * a)) * dy
    };
    simpson(f, r_c, g.root_radius_m, n)
}

fn rho_at(r: f64) -> f64 {
    (r * r - ring().base_radius_m.powi(2)).sqrt()
}

#[test]
fn the_healthy_ring_tooth_is_the_same_whatever_its_integral_is_split_at() {
    let b = beam();
    let g = ring();
    let r_c = g.pitch_radius_m;
    let rho = rho_at(r_c);
    let whole = b.compliance(rho).total_m_per_n();
    let split = b
        .compliance_with_section_split(
            rho,
            GaussLegendre::default_rule(),
            &[r_c + 0.3e-3, r_c + 1.1e-3],
            |h, _| (2.0 * h * B, 2.0 * h * h * h * B / 3.0),
        )
        .total_m_per_n();
    // Two Gauss rules on smooth pieces agree to ~1e-12 (the 20-point rule's own error on
    // this integrand is far smaller than that).
    assert!((split / whole - 1.0).abs() < 1e-10, "{split} vs {whole}");
    // And the second method agrees (Simpson on 4000 intervals and the differenced height:
    // ~1e-9 relative).
    let other = second_method(r_c, |h, _| 2.0 * h, 4000);
    assert!((other / whole - 1.0).abs() < 1e-7, "{other} vs {whole}");
}

#[test]
fn a_ring_root_crack_matches_the_second_method_and_grows_with_depth() {
    let b = beam();
    let g = ring();
    let (h_root, y_root) = b.root_section();
    let (h_tip, y_tip) = b.tip_section();
    let nu = 45f64.to_radians();
    let q_max = ring_crack_max_depth_m(&b, nu);
    assert!((q_max * nu.sin() - 2.0 * h_root).abs() < 1e-15);
    for r_c in [g.tip_radius_m + 0.2e-3, g.pitch_radius_m] {
        let rho = rho_at(r_c);
        let c0 = b.compliance(rho).total_m_per_n();
        let crack = |q: f64, w: f64| Crack {
            depth_m: q,
            angle_rad: nu,
            width_fraction: w,
        };
        assert_eq!(
            ring_crack_compliance_m_per_n(&b, &crack(0.0, 1.0), rho),
            0.0
        );
        let mut last = 0.0;
        for i in 1..=9 {
            let q = q_max * i as f64 / 10.0;
            let extra = ring_crack_compliance_m_per_n(&b, &crack(q, 1.0), rho);
            assert!(extra > last, "r_c {r_c}, q {q}: {extra} <= {last}");
            let part = ring_crack_compliance_m_per_n(&b, &crack(q, 0.5), rho);
            assert!(part > 0.0 && part < extra);
            // The section of the module's docs, integrated by the second method: the
            // limit line parallel to the centreline while h_q >= h_tip, else from the
            // crack tip at the root to the tip corner.
            let reach = q * nu.sin();
            let h_q = h_root - reach;
            let t = |h: f64, y: f64| {
                let l = if h_q >= h_tip {
                    h_q
                } else {
                    h_q + (h_tip - h_q) * ((y_root - y) / (y_root - y_tip)).clamp(0.0, 1.0)
                };
                h + h.min(l.max(h - reach))
            };
            let other = second_method(r_c, t, 20000) - c0;
            // The cracked section has a kink where h meets the limit line, which the
            // model's 20-point Gauss rule integrates across (as the external tooth's,
            // `tooth_faults`) and Simpson on 2e4 intervals resolves: the rule errs by up to
            // ~3e-3 of the added compliance (measured 3.1e-3 at q = 0.1 q_max, where the
            // cut is thinnest), so 1e-2 of it.
            let tol = 1e-2 * other;
            assert!(
                (extra - other).abs() < tol,
                "r_c {r_c}, q {q}: {extra} vs {other}"
            );
            last = extra;
        }
    }
}

#[test]
fn a_ring_spall_softens_only_contacts_tipward_of_its_root_edge() {
    let b = beam();
    let g = ring();
    let p = rho_at(g.pitch_radius_m);
    let s = Spall {
        rho_lo_m: p - 0.5e-3,
        rho_hi_m: p + 0.5e-3,
        depth_m: 50e-6,
        width_fraction: 0.5,
    };
    let kh = 1.0 / 3.5e9;
    // Rootward of the pit (larger rho2, larger radius): the pit lies between the contact
    // and the tip, outside the loaded beam.
    assert!(ring_spall_compliance_m_per_n(&b, &s, kh, s.rho_hi_m + 0.2e-3).abs() < 1e-20);
    let inside = ring_spall_compliance_m_per_n(&b, &s, kh, p);
    assert!(inside > kh, "{inside}");
    let tipward = ring_spall_compliance_m_per_n(&b, &s, kh, s.rho_lo_m - 0.3e-3);
    assert!(tipward > 0.0 && tipward < kh, "{tipward}");
    // The pit's section by the second method for the tipward contact (a pit of 50 um
    // on about 4 mm of thickness; Simpson across the pit's jumps errs by ~1 interval's
    // share, hence 4e4 intervals and 1e-2 of the added compliance).
    let (y_lo, y_hi) = (
        b.flank_point(b.radius_at_m(s.rho_lo_m)).1,
        b.flank_point(b.radius_at_m(s.rho_hi_m)).1,
    );
    let r_c = b.radius_at_m(s.rho_lo_m - 0.3e-3);
    let c0 = b.compliance(s.rho_lo_m - 0.3e-3).total_m_per_n();
    let full = second_method(r_c, |h, _| 2.0 * h, 40000);
    // Equivalent thickness of the pitted section in bending is not a single t, so the
    // second method here checks the sign and size only: the pit removes 50 um x half the
    // face over 1 mm of height, between 0 and the share d f / 2h of the full-section
    // compliance over those heights.
    let share = 50e-6 * 0.5 / (2.0 * b.flank_point(b.radius_at_m(s.rho_lo_m)).0);
    assert!(y_hi > y_lo);
    assert!(
        tipward < 3.0 * share * full,
        "{tipward} vs {share} x {full}"
    );
    assert!((full / c0 - 1.0).abs() < 1e-7);
    assert!(ring_spall_max_depth_m(&b, &s) > 0.0);
}
