//! Tests of the internal gear, the internal pair and the planetary set against facts
//! found independently: a catalogue's worked example, a second construction of the path
//! of contact in the plane, hand-computed Willis ratios, and the phasing rules.

use super::internal::{internal_operating_angle_rad, InternalGear};
use super::planetary::PlanetarySet;
use crate::config::planetary::{Member, PlanetarySection};
use std::f64::consts::PI;

fn set(p: &PlanetarySection) -> PlanetarySet {
    PlanetarySet::from_case(p).expect("valid set")
}

fn errors(p: &PlanetarySection) -> Vec<String> {
    PlanetarySet::from_case(p).expect_err("invalid set").0
}

#[test]
fn ring_tooth_is_thicker_at_its_root_and_matches_the_reference_thickness() {
    // ISO 21771: s = m (pi/2 + 2 x tan alpha) at the reference circle, any x.
    let (m, a) = (2e-3, 20f64.to_radians());
    for x in [0.0, 0.3, -0.2] {
        let r = InternalGear::generated(84, x, m, a, 1.0, 1.25);
        let s_ref = m * (PI / 2.0 + 2.0 * x * a.tan());
        assert!((r.thickness_at_radius_m(r.pitch_radius_m) - s_ref).abs() < 1e-15);
        let (tip, root) = (
            r.thickness_at_radius_m(r.tip_radius_m),
            r.thickness_at_radius_m(r.root_radius_m),
        );
        assert!(tip < s_ref && s_ref < root, "{tip} {s_ref} {root}");
        // Tip inside, root outside the reference circle, by the basic rack's depths.
        assert!((r.pitch_radius_m - r.tip_radius_m - m * (1.0 + x)).abs() < 1e-15);
        assert!((r.root_radius_m - r.pitch_radius_m - m * (1.25 - x)).abs() < 1e-15);
    }
}

#[test]
fn operating_angle_matches_a_published_internal_pair() {
    // A worked internal-pair centre-distance calculation (scribd.com/doc/92821234,
    // catalogue sign: inv alpha_w = inv alpha + 2 tan alpha (x2 - x1) / (z2 - z1)):
    // z1 = 17, z2 = 96, m = 14 mm, x1 = 0.2, x2 = 0.5, alpha = 20 deg give inv alpha_w =
    // 0.01766871, alpha_w = 21.1251 deg and a = 557.0887 mm. Our ring shift has the other
    // sign (x_r = -0.5). Tolerances: half a unit of the last published digit.
    let a = 20f64.to_radians();
    let aw = internal_operating_angle_rad(a, 17.0, 0.2, 96.0, -0.5);
    assert!((super::involute::inv(aw) - 0.01766871).abs() < 5e-9);
    assert!(
        (aw.to_degrees() - 21.1251).abs() < 5e-5,
        "{}",
        aw.to_degrees()
    );
    let centre = 14.0 * (96.0 - 17.0) / 2.0 * a.cos() / aw.cos();
    assert!((centre - 557.0887).abs() < 5e-5, "{centre}");
}

/// The path of contact found a second way: in the plane, the line tangent to both base
/// circles on one side, cut by the planet's tip circle (contact inside it) and by the
/// ring's tip circle (contact outside it), the piece through the pitch point.
fn path_by_construction(s: &PlanetarySet) -> f64 {
    let rp = &s.ring_planet;
    let (rb1, rb2, a) = (
        rp.planet.base_radius_m,
        rp.ring.base_radius_m,
        rp.centre_distance_m,
    );
    // Ring centre at the origin, planet centre at (a, 0); the line n . p = c with
    // n . O2 - c = r_b2, n . O1 - c = r_b1, |n| = 1.
    let nx = -(rb2 - rb1) / a;
    let ny = (1.0 - nx * nx).sqrt();
    let c = -rb2;
    let (p0, d) = ((c * nx, c * ny), (-ny, nx));
    let at = |t: f64| (p0.0 + t * d.0, p0.1 + t * d.1);
    let inside_planet_tip = |t: f64| (at(t).0 - a).hypot(at(t).1) <= rp.planet.tip_radius_m;
    let outside_ring_tip = |t: f64| at(t).0.hypot(at(t).1) >= rp.ring.tip_radius_m;
    // The pitch point: where the line crosses the line of centres (y = 0).
    let t_pitch = -p0.1 / d.1;
    let ok = |t: f64| inside_planet_tip(t) && outside_ring_tip(t);
    assert!(ok(t_pitch));
    // Walk out from the pitch point to both ends by bisection.
    let end = |dir: f64| {
        let (mut lo, mut hi) = (0.0, 0.05);
        assert!(!ok(t_pitch + dir * hi));
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if ok(t_pitch + dir * mid) {
                lo = mid
            } else {
                hi = mid
            }
        }
        lo
    };
    end(1.0) + end(-1.0)
}

#[test]
fn internal_contact_ratio_equals_a_construction_in_the_plane() {
    for p in [
        PlanetarySection::default(),
        PlanetarySection {
            teeth_sun: 21,
            teeth_planet: 33,
            teeth_ring: 87,
            planets: 3,
            ..Default::default()
        },
        PlanetarySection {
            profile_shift_sun: 0.2,
            profile_shift_planet: -0.1,
            profile_shift_ring: 0.0,
            ..Default::default()
        },
    ] {
        let s = set(&p);
        let rp = &s.ring_planet;
        let eps = path_by_construction(&s) / rp.base_pitch_m;
        // Bisection to 2^-200 of 5 cm: the comparison is to rounding.
        assert!(
            (eps - rp.contact_ratio).abs() < 1e-9,
            "{eps} vs {}",
            rp.contact_ratio
        );
        // ISO 21771's closed form for internal pairs, written out.
        let iso = ((rp.planet.tip_radius_m.powi(2) - rp.planet.base_radius_m.powi(2)).sqrt()
            - (rp.ring.tip_radius_m.powi(2) - rp.ring.base_radius_m.powi(2)).sqrt()
            + rp.centre_distance_m * rp.operating_pressure_angle_rad.sin())
            / (PI * rp.module_m * rp.pressure_angle_rad.cos());
        assert!((iso - rp.contact_ratio).abs() < 1e-12);
        // An internal pair has a longer path than the sun pair of the same planet.
        assert!(rp.contact_ratio > s.sun_planet.contact_ratio);
    }
}

#[test]
fn standard_set_has_equal_centre_distances_and_pressure_angles() {
    let s = set(&PlanetarySection::default());
    let a = 2e-3 * (24.0 + 30.0) / 2.0;
    assert!((s.carrier_radius_m - a).abs() < 1e-15);
    assert!((s.ring_planet.centre_distance_m - a).abs() < 1e-15);
    assert!((s.ring_planet.operating_pressure_angle_rad - 20f64.to_radians()).abs() < 1e-7);
    // Shifts with x_r = -x_s - 2 x_p keep both meshes at one centre distance (z_r - z_p = z_s + z_p).
    let p = PlanetarySection {
        profile_shift_sun: 0.3,
        profile_shift_planet: 0.1,
        profile_shift_ring: -0.5,
        ..Default::default()
    };
    let s = set(&p);
    let w = (
        s.sun_planet.operating_pressure_angle_rad,
        s.ring_planet.operating_pressure_angle_rad,
    );
    assert!((w.0 - w.1).abs() < 1e-9, "{w:?}");
}

#[test]
fn willis_ratios_match_hand_computation() {
    // z_s = 24, z_r = 84: by hand, 1 + 84/24 = 4.5, 1 + 24/84 = 9/7, -84/24 = -3.5.
    let cases = [
        (Member::Sun, Member::Carrier, Member::Ring, 4.5),
        (Member::Carrier, Member::Sun, Member::Ring, 1.0 / 4.5),
        (Member::Ring, Member::Carrier, Member::Sun, 9.0 / 7.0),
        (Member::Carrier, Member::Ring, Member::Sun, 7.0 / 9.0),
        (Member::Sun, Member::Ring, Member::Carrier, -3.5),
        (Member::Ring, Member::Sun, Member::Carrier, -1.0 / 3.5),
    ];
    for (input, output, fixed, ratio) in cases {
        let s = set(&PlanetarySection {
            input,
            output,
            fixed,
            ..Default::default()
        });
        assert!(
            (s.ratio() - ratio).abs() < 1e-14,
            "{input:?} {output:?}: {}",
            s.ratio()
        );
        let w = s.member_speeds(10.0);
        assert_eq!(
            w[match fixed {
                Member::Sun => 0,
                Member::Carrier => 1,
                Member::Ring => 2,
            }],
            0.0
        );
        // The mesh frequency seen from the sun equals the ring's (Willis).
        assert!((s.mesh_frequency_hz(w) - 24.0 * (w[0] - w[1]).abs()).abs() < 1e-12);
        assert!(
            (s.planet_pass_frequency_hz(w) * 84.0 / 4.0 - s.mesh_frequency_hz(w)).abs() < 1e-12
        );
    }
}

/// Mesh phases by brute force: the smallest sun (or ring) rotation relative to the carrier
/// after which one of the member's teeth lies on planet n's line of centres, over all its
/// teeth, in mesh cycles, minus planet 1's.
fn brute_force_phases(teeth: usize, angles: &[f64], sense: f64) -> Vec<f64> {
    let pitch = 2.0 * PI / teeth as f64;
    let first = |psi: f64| {
        (0..teeth)
            .map(|k| (sense * (psi - k as f64 * pitch)).rem_euclid(2.0 * PI))
            .fold(f64::INFINITY, f64::min)
    };
    let t1 = first(angles[0]);
    angles
        .iter()
        .map(|psi| ((first(*psi) - t1) / pitch).rem_euclid(1.0))
        .collect()
}

fn close_mod_1(a: f64, b: f64) -> bool {
    let d = (a - b).rem_euclid(1.0);
    d < 1e-9 || 1.0 - d < 1e-9
}

#[test]
fn mesh_phases_follow_parker_and_lin() {
    // Sequentially phased: z_s = 25, z_r = 83, N = 4 (108 / 4 = 27): gamma_sn = n/4 by hand.
    let p = PlanetarySection {
        teeth_sun: 25,
        teeth_planet: 29,
        teeth_ring: 83,
        ..Default::default()
    };
    let s = set(&p);
    let sun = s.sun_planet_phases();
    for (n, g) in sun.iter().enumerate() {
        assert!(close_mod_1(*g, n as f64 * 0.25), "{sun:?}");
    }
    // Parker & Lin: on assembly positions the ring meshes carry the sun meshes' phases.
    for (a, b) in sun.iter().zip(s.ring_planet_phases()) {
        assert!(close_mod_1(*a, b));
    }
    // In phase: z_s / N an integer (24 / 4).
    assert!(set(&PlanetarySection::default())
        .sun_planet_phases()
        .iter()
        .all(|g| *g == 0.0));
    // Unequal spacing, checked by brute force over the teeth.
    let p = PlanetarySection {
        planets: 3,
        planet_angles_deg: Some(vec![0.0, 360.0 * 37.0 / 108.0, 360.0 * 73.0 / 108.0]),
        ..Default::default()
    };
    let s = set(&p);
    let bf_sun = brute_force_phases(24, &s.planet_angles_rad, 1.0);
    let bf_ring = brute_force_phases(84, &s.planet_angles_rad, -1.0);
    for n in 0..3 {
        assert!(
            close_mod_1(s.sun_planet_phases()[n], bf_sun[n]),
            "{:?} {bf_sun:?}",
            s.sun_planet_phases()
        );
        assert!(close_mod_1(s.ring_planet_phases()[n], bf_ring[n]));
    }
    assert!(!close_mod_1(bf_sun[1], 0.0));
}

#[test]
fn ring_sun_phase_is_half_for_even_planets_and_zero_for_odd() {
    // Standard gears: across the planet a tooth faces a tooth (even z_p) or a space (odd).
    assert!(close_mod_1(
        set(&PlanetarySection::default()).ring_sun_phase(),
        0.5
    ));
    let odd = PlanetarySection {
        teeth_sun: 25,
        teeth_planet: 29,
        teeth_ring: 83,
        ..Default::default()
    };
    assert!(close_mod_1(set(&odd).ring_sun_phase(), 0.0));
}

#[test]
fn bad_sets_are_refused_naming_the_key() {
    let has = |p: PlanetarySection, key: &str, what: &str| {
        let e = errors(&p);
        assert!(
            e.iter().any(|m| m.contains(key) && m.contains(what)),
            "{key}/{what}: {e:?}"
        );
    };
    // Six planets on a 54 mm carrier radius: centres 54 mm apart, tip diameter 64 mm.
    has(
        PlanetarySection {
            planets: 6,
            ..Default::default()
        },
        "planetary.planets",
        "collide",
    );
    // 108 / 5 is not an integer.
    has(
        PlanetarySection {
            planets: 5,
            ..Default::default()
        },
        "planetary.planets",
        "assembly condition",
    );
    has(
        PlanetarySection {
            teeth_ring: 82,
            ..Default::default()
        },
        "planetary.teeth_ring",
        "too small",
    );
    has(
        PlanetarySection {
            input: Member::Ring,
            ..Default::default()
        },
        "planetary.input",
        "both the input and the fixed",
    );
    has(
        PlanetarySection {
            planets: 3,
            planet_angles_deg: Some(vec![0.0, 240.0, 120.0]),
            ..Default::default()
        },
        "planetary.planet_angles_deg",
        "increase",
    );
    has(
        PlanetarySection {
            planets: 3,
            planet_angles_deg: Some(vec![0.0, 121.0, 240.0]),
            ..Default::default()
        },
        "planetary.planet_angles_deg",
        "assembly condition",
    );
    has(
        PlanetarySection {
            planets: 2,
            planet_angles_deg: Some(vec![0.0, 10.0]),
            teeth_sun: 24,
            ..Default::default()
        },
        "planetary.planet_angles_deg",
        "collide",
    );
}
