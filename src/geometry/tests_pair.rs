//! Tests of the pair's geometry: hand values, the path of contact, the pairs in contact.

use super::*;

fn paper() -> GearPair {
    GearPair::from_case(&GearSection::default()).expect("paper pair is valid")
}

#[test]
fn paper_pair_matches_hand_values() {
    // docs/PAPER_NOTES.md hand-derived values, quoted to 3 decimals (mm), 4 for the contact ratio.
    let p = paper();
    let mm = 1e3;
    assert!((p.pinion.base_radius_m * mm - 17.854).abs() < 5e-4);
    assert!((p.gear.base_radius_m * mm - 29.130).abs() < 5e-4);
    assert!((p.pinion.tip_radius_m * mm - 21.0).abs() < 1e-9);
    assert!((p.gear.tip_radius_m * mm - 33.0).abs() < 1e-9);
    assert!((p.pinion.root_radius_m * mm - 16.5).abs() < 1e-9);
    assert!((p.gear.root_radius_m * mm - 28.5).abs() < 1e-9);
    assert!((p.centre_distance_m * mm - 50.0).abs() < 1e-9);
    assert!(
        (p.contact_ratio - 1.6022).abs() < 5e-4,
        "{}",
        p.contact_ratio
    );
    assert!(p.pinion.root_radius_m < p.pinion.base_radius_m);
    assert!(p.gear.root_radius_m < p.gear.base_radius_m);
}

#[test]
fn pitch_point_lies_on_path_and_splits_loa_by_ratio() {
    // At the pitch point rho1/rho2 = r_b1/r_b2 = z1/z2 (similar triangles).
    let p = paper();
    let r1 = p.rho_pitch_m;
    let r2 = p.rho_gear(r1);
    assert!((r1 / r2 - 19.0 / 31.0).abs() < 1e-12);
    assert!(p.rho_start_m < r1 && r1 < p.rho_end_m);
}

#[test]
fn shifted_pair_contact_ratio_against_iso_formula() {
    // ISO 21771 closed form: eps = [sqrt(ra1^2-rb1^2)+sqrt(ra2^2-rb2^2) - a_w sin(alpha_w)] / p_b
    let g = GearSection {
        profile_shift_pinion: 0.3,
        profile_shift_gear: -0.1,
        ..Default::default()
    };
    let p = GearPair::from_case(&g).unwrap();
    let eps = ((p.pinion.tip_radius_m.powi(2) - p.pinion.base_radius_m.powi(2)).sqrt()
        + (p.gear.tip_radius_m.powi(2) - p.gear.base_radius_m.powi(2)).sqrt()
        - p.centre_distance_m * p.operating_pressure_angle_rad.sin())
        / (PI * p.module_m * p.pressure_angle_rad.cos());
    assert!((p.contact_ratio - eps).abs() < 1e-12);
    // Positive shift sum opens the centre distance.
    assert!(p.centre_distance_m > 0.050);
}

#[test]
fn pairs_in_contact_counts_follow_contact_ratio() {
    // Fraction of a mesh period in double contact = eps - 1.
    let p = paper();
    let n = 10_000;
    let doubles = (0..n)
        .filter(|i| {
            p.pairs_in_contact(p.mesh_angle_rad() * (*i as f64 + 0.5) / n as f64)
                .count()
                == 2
        })
        .count();
    let frac = doubles as f64 / n as f64;
    assert!((frac - (p.contact_ratio - 1.0)).abs() < 2.0 / n as f64);
}

#[test]
fn the_nominal_reach_enumerates_the_pairs_in_contact() {
    let p = paper();
    let reach = p.nominal_reach();
    let period = p.mesh_angle_rad();
    for i in 0..=400 {
        let d = period * (i as f64 / 100.0 - 1.3);
        for decide in [d, d + 1e-9, d - 1e-9] {
            let a: Vec<(i64, f64)> = p
                .pairs_in_contact_decided(d, decide)
                .map(|(k, r)| (k as i64, r))
                .collect();
            let b: Vec<(i64, f64)> = p.pairs_in_reach_decided(reach, d, decide).collect();
            assert_eq!(a, b);
            let key = ((decide / period).floor(), a.len());
            assert_eq!(key, p.decided_set_in(reach, decide));
        }
    }
    assert_eq!(p.reach_change_phases(reach), p.contact_change_phases());
}

#[test]
fn a_wider_reach_follows_every_pair_within_it() {
    // Independent bookkeeping: pair of mesh cycle c entered A at phase c period, so at
    // phase x it lies at rho_A + r_b1 (x - c period); it is followed while that lies
    // in the reach. The set changes exactly at the reach's change phases.
    let p = paper();
    let reach = Reach {
        start_m: p.rho_start_m - 1.3e-3,
        end_m: p.rho_end_m + 2.1e-3,
    };
    let period = p.mesh_angle_rad();
    let rb1 = p.pinion.base_radius_m;
    let changes = p.reach_change_phases(reach);
    assert_eq!(changes.len(), 3);
    let mut last_key: Option<(f64, (f64, usize))> = None;
    for i in 0..5000 {
        let x = period * (i as f64 + 0.5) / 1000.0;
        let cycle = (x / period).floor() as i64;
        let want: Vec<(i64, f64)> = (cycle - 3..=cycle + 3)
            .rev()
            .map(|c| (cycle - c, p.rho_start_m + rb1 * (x - c as f64 * period)))
            .filter(|(_, r)| *r >= reach.start_m && *r <= reach.end_m)
            .collect();
        let got: Vec<(i64, f64)> = p.pairs_in_reach_decided(reach, x, x).collect();
        assert_eq!(want.len(), got.len(), "phase {x}");
        for (w, g) in want.iter().zip(&got) {
            assert_eq!(w.0, g.0);
            assert!((w.1 - g.1).abs() < 1e-12);
        }
        let key = p.decided_set_in(reach, x);
        assert_eq!(key.0, (cycle - got[0].0) as f64);
        // A change of the set between neighbouring samples brackets a change phase.
        if let Some((prev_x, prev_key)) = last_key {
            if prev_key != key {
                let (a, b) = ((prev_x / period).fract(), (x / period).fract());
                let hit = changes.iter().any(|c| {
                    let c = c / period;
                    if a < b {
                        a < c && c <= b
                    } else {
                        c > a || c <= b
                    }
                });
                assert!(
                    hit,
                    "set changed between {prev_x} and {x} off a change phase"
                );
            }
        }
        last_key = Some((x, key));
    }
}

#[test]
fn too_short_addendum_gives_contact_ratio_error() {
    let g = GearSection {
        addendum_coefficient: 0.5,
        teeth_pinion: 12,
        teeth_gear: 13,
        ..Default::default()
    };
    let e = GearPair::from_case(&g).unwrap_err();
    assert!(e.0.iter().any(|m| m.contains("contact ratio")), "{e:?}");
}

#[test]
fn small_pinion_meeting_large_gear_interferes() {
    // 8 teeth against 60 without shift: the classic interference case (z_min ~ 17).
    let g = GearSection {
        teeth_pinion: 8,
        teeth_gear: 60,
        ..Default::default()
    };
    let e = GearPair::from_case(&g).unwrap_err();
    assert!(e.0.iter().any(|m| m.contains("interference")), "{e:?}");
}
