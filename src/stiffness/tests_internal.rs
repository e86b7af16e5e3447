//! Tests of the ring tooth's and the internal pair's stiffness against a rack's closed
//! geometry, a second integration, and the ordering the tooth shapes force.

use super::internal::{InternalMeshStiffness, RingToothBeam};
use super::potential_energy::{ElasticPair, ToothBeam};
use crate::config::case::MaterialsSection;
use crate::config::case::{Derivable, GearSection};
use crate::config::planetary::PlanetarySection;
use crate::geometry::internal::InternalGear;
use crate::geometry::pair::{Gear, GearPair};
use crate::geometry::planetary::PlanetarySet;
use std::f64::consts::PI;

const E: f64 = 206e9;
const NU: f64 = 0.3;
const M: f64 = 2e-3;
const B: f64 = 0.02;

fn alpha() -> f64 {
    20f64.to_radians()
}

fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let dx = (b - a) / n as f64;
    let inner: f64 = (1..n)
        .map(|i| f(a + i as f64 * dx) * (2 + 2 * (i % 2)) as f64)
        .sum();
    (f(a) + f(b) + inner) * dx / 3.0
}

/// A rack tooth (module M, no shift) loaded on its pitch line, clamped 1.25 M deeper:
/// half-thickness pi M / 4 + d tan(alpha) at depth d, force at alpha to the pitch line.
/// Total compliance (bending, shear, axial) by Simpson, m/N.
fn rack_compliance() -> f64 {
    let a = alpha();
    let (sa, ca) = a.sin_cos();
    let hc = PI * M / 4.0;
    let g = E / (2.0 * (1.0 + NU));
    let f = |d: f64| {
        let h = hc + d * a.tan();
        let m = ca * d - sa * hc;
        m * m / (E * 2.0 * h.powi(3) * B / 3.0)
            + 1.2 * ca * ca / (g * 2.0 * h * B)
            + sa * sa / (E * 2.0 * h * B)
    };
    simpson(f, 0.0, 1.25 * M, 2000)
}

fn ring(z: usize) -> InternalGear {
    InternalGear::generated(z, 0.0, M, alpha(), 1.0, 1.25)
}

fn external(z: usize) -> Gear {
    // An external gear of z teeth (module M, 20 deg, no shift) with its root 1.25 m under
    // the reference circle, as the pair builds it.
    let g = GearSection {
        module_mm: M * 1e3,
        teeth_pinion: z as i64,
        teeth_gear: z as i64,
        hub_bore_radius_pinion_mm: Derivable::Derived,
        hub_bore_radius_gear_mm: Derivable::Derived,
        ..Default::default()
    };
    GearPair::from_case(&g).expect("valid").pinion
}

#[test]
fn ring_and_external_teeth_tend_to_the_rack_from_either_side() {
    // The ring's tooth widens towards its root faster than a rack's, the external tooth
    // slower: c_ring(z) < c_rack < c_external(z), both gaps shrinking like 1/z.
    let rack = rack_compliance();
    let mut last_gap = f64::INFINITY;
    for z in [100, 1000, 10_000, 100_000] {
        let r = ring(z);
        let beam = RingToothBeam::new(&r, B, E, NU);
        let c_ring = beam
            .compliance(r.base_radius_m * alpha().tan())
            .total_m_per_n();
        let g = external(z);
        let ext = ToothBeam::new(&g, B, E, NU);
        let c_ext = ext
            .compliance(g.base_radius_m * alpha().tan())
            .total_m_per_n();
        assert!(
            c_ring < rack && rack < c_ext,
            "z {z}: {c_ring} {rack} {c_ext}"
        );
        let gap = (rack - c_ring) / rack;
        assert!(
            gap < last_gap / 5.0 || z == 100,
            "z {z}: {gap} after {last_gap}"
        );
        last_gap = gap;
    }
    // At z = 1e5 the ring tooth is the rack to O(1/z) (a few 1e-5; Simpson's error on the
    // rack is below 1e-12).
    assert!(last_gap < 1e-4, "{last_gap}");
}

#[test]
fn ring_bending_matches_direct_integration_in_height() {
    // Second method: Simpson in Y (4000 panels), the half-thickness at each height found
    // by bisection on the radius, so neither dY/dr nor the integration in r is used.
    // Error O(dY^4) with dY ~ 1 um: below 1e-7 relative.
    let r = ring(84);
    let beam = RingToothBeam::new(&r, B, E, NU);
    let rho2 = r.base_radius_m * alpha().tan() + 1e-3;
    let r_c = r.base_radius_m.hypot(rho2);
    let (hc, yc) = beam.flank_point(r_c);
    let (sb, cb) = beam.load_angle_rad(rho2).sin_cos();
    let y_root = beam.flank_point(r.root_radius_m).1;
    let h_of_y = |y: f64| {
        let (mut lo, mut hi) = (r_c, r.root_radius_m);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if beam.flank_point(mid).1 < y {
                lo = mid
            } else {
                hi = mid
            }
        }
        beam.flank_point(lo).0
    };
    let f = |y: f64| {
        let h = h_of_y(y);
        (cb * (y - yc) - sb * hc).powi(2) / (E * 2.0 * h.powi(3) * B / 3.0)
    };
    let direct = simpson(f, yc, y_root, 4000);
    let gauss = beam.compliance(rho2).bending_m_per_n;
    assert!((direct / gauss - 1.0).abs() < 1e-7, "{direct} vs {gauss}");
}

#[test]
fn load_angle_and_flank_lie_on_the_ring_involute() {
    // The contact at rho2 lies at radius sqrt(r_b^2 + rho2^2) and its polar angle from the
    // tooth's centreline is half the tooth's thickness there (ISO 21771).
    let r = ring(84);
    let beam = RingToothBeam::new(&r, B, E, NU);
    for rho2 in [r.tip_rho_m(), 30e-3, 35e-3] {
        let rc = r.base_radius_m.hypot(rho2);
        let (h, y) = beam.flank_point(rc);
        assert!((h.hypot(y) - rc).abs() < 1e-15);
        assert!((2.0 * rc * h.atan2(y) - r.thickness_at_radius_m(rc)).abs() < 1e-13);
        // beta = alpha_rc + theta_c > alpha_rc: the ring's load leans towards its root.
        assert!(beam.load_angle_rad(rho2) > (rho2 / r.base_radius_m).atan());
    }
}

#[test]
fn ring_planet_mesh_is_stiffer_than_sun_planet_mesh() {
    // The concave ring flank and its root-thickened tooth make the internal mesh the
    // stiffer one (as Liang, Zuo & Pandey 2014 find); both meshes share the planet, the
    // Hertz term and the face width, so only the mating tooth and the path differ.
    let s = PlanetarySet::from_case(&PlanetarySection::default()).unwrap();
    let el = ElasticPair::from_case(&MaterialsSection::default());
    let internal = InternalMeshStiffness::new(&s.ring_planet, &el, false);
    let external = super::mesh::MeshStiffness::new(&s.sun_planet, &el, 41, false).unwrap();
    let (ki, ke) = (
        internal.mean_stiffness_n_per_m(),
        external.mean_stiffness_n_per_m(),
    );
    assert!(ki > ke, "{ki} vs {ke}");
    // Single-pair stiffness at the pitch point too.
    let kp_i = internal.pair_stiffness_n_per_m(s.ring_planet.rho_pitch_m);
    let kp_e = external.pair_stiffness_n_per_m(s.sun_planet.rho_pitch_m);
    assert!(kp_i > kp_e, "{kp_i} vs {kp_e}");
    // The mean equals the phase average of the total (pairs in parallel), 2000 phases:
    // the midpoint rule's error on the step function is below 1e-3.
    let n = 2000;
    let per = s.ring_planet.mesh_angle_rad();
    let avg: f64 = (0..n)
        .map(|i| internal.total_stiffness_n_per_m(per * (i as f64 + 0.5) / n as f64))
        .sum::<f64>()
        / n as f64;
    assert!((avg / ki - 1.0).abs() < 1e-3, "{avg} vs {ki}");
}
