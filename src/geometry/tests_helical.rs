use super::*;
use crate::config::case::Derivable;
use crate::config::case::GearSection;

/// The built-in (paper) pair's normal section with a helix.
fn paper(beta_deg: f64, hand: Hand) -> HelicalPair {
    let h = HelixSpec {
        helix_angle_deg: beta_deg,
        hand_pinion: hand,
    };
    HelicalPair::from_case(&GearSection::default(), &h).unwrap()
}

/// ISO/TR 6336-30:2017 Example 1: m_n = 8 mm, z = 17/103, x_n = 0.145/0, beta = 15.8 deg,
/// alpha_n = 20 deg, b = 100 mm, a_w = 500 mm, ISO 53 profile D (h_aP = 1, h_fP = 1.4,
/// rho_fP = 0.39 m_n). Data as in `tests/iso6336_tr_example.rs`.
fn tr_example_1() -> HelicalPair {
    let g = GearSection {
        module_mm: 8.0,
        teeth_pinion: 17,
        teeth_gear: 103,
        pressure_angle_deg: 20.0,
        addendum_coefficient: 1.0,
        dedendum_coefficient: 1.4,
        profile_shift_pinion: 0.145,
        profile_shift_gear: 0.0,
        face_width_mm: 100.0,
        centre_distance_mm: Some(500.0),
        hub_bore_radius_pinion_mm: Derivable::Derived,
        hub_bore_radius_gear_mm: Derivable::Derived,
        tool_tip_radius_coefficient: 0.39,
        ..GearSection::default()
    };
    let h = HelixSpec {
        helix_angle_deg: 15.8,
        hand_pinion: Hand::Right,
    };
    HelicalPair::from_case(&g, &h).unwrap()
}

/// Mean of `f` over one mesh period by the midpoint rule at `n` phases.
fn period_mean(p: &HelicalPair, n: usize, f: impl Fn(f64) -> f64) -> f64 {
    let period = p.transverse.mesh_angle_rad();
    (0..n)
        .map(|i| f(period * (i as f64 + 0.5) / n as f64))
        .sum::<f64>()
        / n as f64
}

#[test]
fn zero_helix_is_the_spur_pair_bit_for_bit() {
    let g = GearSection::default();
    let h = HelicalPair::from_case(&g, &HelixSpec::spur()).unwrap();
    assert_eq!(h.transverse, GearPair::from_case(&g).unwrap());
    assert_eq!(h.overlap_ratio, 0.0);
    assert_eq!(h.base_helix_angle_rad, 0.0);
    assert_eq!(h.virtual_teeth, [19.0, 31.0]);
    assert_eq!(h.total_contact_ratio, h.transverse.contact_ratio);
    // Every line spans the face: the length is b times the pairs in contact.
    let b = h.face_width_m;
    for i in 0..50 {
        let phase = h.transverse.mesh_angle_rad() * (i as f64 + 0.5) / 50.0;
        let pairs = h.transverse.pairs_in_contact(phase).count() as f64;
        assert!((h.contact_length_m(phase) - pairs * b).abs() < 1e-15);
    }
    assert!((h.min_contact_length_m() - b).abs() < 1e-15); // floor(1.60) b
}

#[test]
fn tr_6336_30_example_1_geometry_against_published_values() {
    let p = tr_example_1();
    // Tip diameters stated to 0.01 mm: 159.66 / 872.35 mm.
    let da = [
        p.transverse.pinion.tip_radius_m,
        p.transverse.gear.tip_radius_m,
    ]
    .map(|r| 2e3 * r);
    assert!(
        (da[0] - 159.66).abs() < 5e-3 && (da[1] - 872.35).abs() < 5e-3,
        "{da:?}"
    );
    // Virtual numbers of teeth published to 3 decimals: 18.905 / 114.543.
    assert!(
        (p.virtual_teeth[0] - 18.905).abs() < 5e-4,
        "{:?}",
        p.virtual_teeth
    );
    assert!(
        (p.virtual_teeth[1] - 114.543).abs() < 5e-4,
        "{:?}",
        p.virtual_teeth
    );
    // epsilon_alpha is implied by the published c' = 12.37047 and c_gamma_alpha = 17.46485
    // N/(mm um) through c_gamma_alpha = c' (0.75 eps_alpha + 0.25): 1.549086 (+-1e-6 from
    // the 5-decimal rounding). The published values follow from the drawing's tip
    // diameters, rounded to 0.01 mm; the nominal diameters used here give eps_alpha up to
    // 4.5e-4 larger (tests/iso6336_tr_example.rs derives that bound), so 5e-4.
    let eps_implied = (17.46485 / 12.37047 - 0.25) / 0.75;
    let ea = p.transverse_contact_ratio;
    assert!((ea - eps_implied).abs() < 5e-4, "{ea} vs {eps_implied}");
    // Overlap ratio by the normal-section formula eps_beta = b sin(beta) / (pi m_n) (ISO
    // 21771), independent of the base-helix route the pair takes: 1.08343.
    let eb = 0.1 * 15.8f64.to_radians().sin() / (PI * 0.008);
    assert!(
        (p.overlap_ratio - eb).abs() < 1e-12,
        "{} vs {eb}",
        p.overlap_ratio
    );
    assert!((p.total_contact_ratio - ea - eb).abs() < 1e-12);
    // ISO 21771 identities: p_bn = p_bt cos(beta_b); sin(beta_b) = sin(beta) cos(alpha_n).
    let pbn = p.normal_base_pitch_m();
    assert!((pbn / (p.transverse.base_pitch_m * p.base_helix_angle_rad.cos()) - 1.0).abs() < 1e-13);
    let sb = p.helix_angle_rad.sin() * p.normal_pressure_angle_rad.cos();
    assert!((p.base_helix_angle_rad.sin() - sb).abs() < 1e-14);
    eprintln!(
        "TR 6336-30 Ex. 1: eps_alpha {ea:.5} (implied {eps_implied:.5}), eps_beta {:.5}, eps_gamma {:.5}, beta_b {:.4} deg",
        p.overlap_ratio,
        p.total_contact_ratio,
        p.base_helix_angle_rad.to_degrees()
    );
}

#[test]
fn mean_contact_length_is_b_eps_alpha_over_cos_beta_b() {
    // The exact contact length is piecewise linear in phase for beta > 0: the midpoint
    // rule over n = 20 000 phases errs by ~slope change x step^2 at each kink, far below
    // 1e-9. At beta = 0 it is a step function with two jumps of b per period, each costing
    // the midpoint rule at most b / n.
    let n = 20_000;
    for beta in [0.0, 8.0, 15.0, 22.5, 30.0, 40.0] {
        let p = paper(beta, Hand::Right);
        let mean = period_mean(&p, n, |ph| p.contact_length_m(ph));
        let exact = p.mean_contact_length_m();
        let tol = if beta == 0.0 {
            2.0 * p.face_width_m / n as f64
        } else {
            1e-9 * exact
        };
        assert!((mean - exact).abs() < tol, "beta {beta}: {mean} vs {exact}");
    }
}

#[test]
fn minimum_contact_length_against_the_closed_form() {
    // Dense sampling of the exact lengths against AGMA 908's / Niemann's L_min. L changes
    // with the pinion's roll at most by (lines ending in the zone) / (tan beta_b cos beta_b)
    // per metre of roll (4 ends, beta >= 8 deg: < 30); 100 000 samples per base pitch
    // (6 mm) step 6e-8 m, so the sampled minimum lies within 2e-6 m of the true one.
    let mut branches = [false; 2];
    for beta in [8.0, 12.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0] {
        let p = paper(beta, Hand::Right);
        let n = 100_000;
        let period = p.transverse.mesh_angle_rad();
        let sampled = (0..n)
            .map(|i| p.contact_length_m(period * i as f64 / n as f64))
            .fold(f64::INFINITY, f64::min);
        let closed = p.min_contact_length_m();
        assert!(
            (sampled - closed).abs() < 2e-6,
            "beta {beta}: {sampled} vs {closed}"
        );
        let (ea, eb) = (p.transverse_contact_ratio, p.overlap_ratio);
        branches[usize::from(eb.fract() > 1.0 - ea.fract())] = true;
    }
    assert_eq!(
        branches,
        [true, true],
        "both branches of the formula exercised"
    );
}

#[test]
fn integer_overlap_ratio_gives_a_constant_contact_length() {
    // b = n pi m_n / sin(beta): eps_beta = n exactly; every phase then has the mean length.
    for (beta, n) in [(15.0f64, 1.0), (30.0, 1.0), (30.0, 2.0)] {
        let g = GearSection {
            face_width_mm: n * PI * 2.0 / beta.to_radians().sin(),
            ..GearSection::default()
        };
        let h = HelixSpec {
            helix_angle_deg: beta,
            hand_pinion: Hand::Left,
        };
        let p = HelicalPair::from_case(&g, &h).unwrap();
        assert!((p.overlap_ratio - n).abs() < 1e-12);
        let mean = p.mean_contact_length_m();
        for i in 0..1000 {
            let phase = p.transverse.mesh_angle_rad() * i as f64 / 1000.0;
            let l = p.contact_length_m(phase);
            assert!(
                (l / mean - 1.0).abs() < 1e-9,
                "beta {beta} n {n}: {l} vs {mean}"
            );
        }
        assert!((p.min_contact_length_m() / mean - 1.0).abs() < 1e-12);
    }
}

#[test]
fn left_hand_is_the_right_hand_mirrored_across_the_face() {
    // s = -1 with y' = b - y is s = +1 shifted back by b tan(beta_b) of roll.
    let (r, l) = (paper(20.0, Hand::Right), paper(20.0, Hand::Left));
    let shift = r.face_width_m * r.base_helix_angle_rad.tan() / r.transverse.pinion.base_radius_m;
    for i in 0..200 {
        let phase = 0.013 * i as f64;
        let (a, b) = (l.contact_length_m(phase), r.contact_length_m(phase - shift));
        assert!((a - b).abs() < 1e-12, "{phase}: {a} vs {b}");
    }
    assert_eq!(Hand::Right.mate(), Hand::Left);
}

#[test]
fn contact_lines_lie_on_the_zone_and_follow_the_transverse_pairs() {
    // At a face position y the pairs in contact are the transverse section's at the phase
    // advanced by the stagger: the lines crossing y are exactly those pairs.
    let p = paper(25.0, Hand::Right);
    let rb1 = p.transverse.pinion.base_radius_m;
    for i in 0..40 {
        let phase = 0.0071 * i as f64;
        let lines = p.contact_lines(phase);
        for j in 0..16 {
            let y = p.face_width_m * (j as f64 + 0.5) / 16.0;
            let crossing = lines
                .iter()
                .filter(|l| l.face_m.0 <= y && y <= l.face_m.1)
                .count();
            let section = p
                .transverse
                .pairs_in_contact(phase + p.stagger_m(y) / rb1)
                .count();
            assert_eq!(crossing, section, "phase {phase} y {y}");
        }
        for l in &lines {
            assert!(0.0 <= l.face_m.0 && l.face_m.1 <= p.face_width_m);
        }
    }
}

#[test]
fn bad_helix_angles_and_hands_are_errors_naming_the_key() {
    for beta in [-1.0, 45.0, 60.0, f64::NAN, f64::INFINITY] {
        let h = HelixSpec {
            helix_angle_deg: beta,
            hand_pinion: Hand::Right,
        };
        let e = HelicalPair::from_case(&GearSection::default(), &h).unwrap_err();
        assert!(
            e.0[0].contains("`gear.helix_angle_deg`") && e.0[0].contains("[0, 45)"),
            "{e:?}"
        );
    }
    let e = Hand::parse("gear.helix_hand_pinion", "up")
        .unwrap_err()
        .0
        .join("; ");
    assert!(e.contains("gear.helix_hand_pinion") && e.contains("\"up\"") && e.contains("\"left\""));
    assert_eq!(Hand::parse("k", "left"), Ok(Hand::Left));
}
