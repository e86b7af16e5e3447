//! Bad per-tooth inputs are exit-2 errors that name the key, the tooth and the valid
//! range (a per-tooth array of the wrong length names both lengths), before anything is
//! computed.

mod common;
use common::rejected;

#[test]
fn tooth_indices_and_array_lengths_name_the_key_and_the_range() {
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=crack",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=19",
            "--set",
            "fault.crack_depth_mm=0.5",
        ],
        &["`fault.tooth` = 19", "pinion", "0 to 18"],
    );
    rejected(
        &["dynamics", "--set", "teeth.pitch_error_gear_um=[1,2,3]"],
        &["`teeth.pitch_error_gear_um`", "3 values", "31 teeth"],
    );
    rejected(
        &["stiffness", "--set", "teeth.profile_form_pinion_um=[1,2]"],
        &["`teeth.profile_form_pinion_um`", "2 values", "(19)"],
    );
    rejected(
        &["dynamics", "--set", "teeth.accuracy_grade=13"],
        &["`teeth.accuracy_grade` = 13", "[1, 12]"],
    );
    rejected(
        &["dynamics", "--set", "teeth.accuracy_grade=0"],
        &["`teeth.accuracy_grade` = 0", "[1, 12]"],
    );
}

#[test]
fn faults_and_reliefs_the_geometry_cannot_hold_name_the_key_tooth_and_range() {
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=crack",
            "--set",
            "fault.gear=gear",
            "--set",
            "fault.tooth=3",
            "--set",
            "fault.crack_depth_mm=6",
        ],
        &[
            "`fault.crack_depth_mm` = 6",
            "gear tooth 3",
            "deeper than the tooth",
            "valid [0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=2",
            "--set",
            "fault.spall_position_mm=0",
            "--set",
            "fault.spall_length_mm=20",
            "--set",
            "fault.spall_depth_um=50",
        ],
        &[
            "`fault.spall_length_mm` = 20",
            "pinion tooth 2",
            "longer than the active profile",
            "valid (0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=2",
            "--set",
            "fault.spall_position_mm=4.3",
            "--set",
            "fault.spall_length_mm=1",
            "--set",
            "fault.spall_depth_um=50",
        ],
        &[
            "`fault.spall_position_mm` = 4.3",
            "pinion tooth 2",
            "off the active profile",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "modification.tip_relief_um=10",
            "--set",
            "modification.tip_relief_length_mm=9",
        ],
        &[
            "`modification.tip_relief_length_mm` = 9",
            "longer than the addendum",
            "valid (0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=broken_tip",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=1",
            "--set",
            "fault.removed_height_mm=6",
        ],
        &[
            "`fault.removed_height_mm` = 6",
            "pinion tooth 1",
            "valid (0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=gear",
            "--set",
            "fault.tooth=1",
            "--set",
            "fault.crack_depth_mm=1",
        ],
        &[
            "`fault.crack_depth_mm`",
            "does not apply",
            "`fault.spall_position_mm` is required",
        ],
    );
}

#[test]
fn pedrero_load_sharing_on_teeth_that_differ_names_both_keys() {
    // Pedrero's law (paper eq. 7) has no place for one pair's gap or softer tooth: asked
    // for explicitly on teeth that differ, it is refused, naming the law's key and what
    // makes the teeth differ.
    rejected(
        &[
            "stiffness",
            "--set",
            "teeth.runout_gear_um=2",
            "--set",
            "contact.load_sharing=pedrero",
            // Eq. (7) is for the nominal path only (refused with corner contact first).
            "--set",
            "contact.path=nominal",
        ],
        &[
            "`contact.load_sharing` = \"pedrero\"",
            "`[teeth]`",
            "\"stiffness\"",
        ],
    );
    rejected(
        &[
            "stiffness",
            "--set",
            "wear.worn_geometry=worn",
            "--set",
            "contact.load_sharing=pedrero",
            "--set",
            "contact.path=nominal",
        ],
        &[
            "`contact.load_sharing` = \"pedrero\"",
            "`wear.worn_geometry` = \"worn\"",
        ],
    );
}

/// The number after `prefix` in `msg`.
fn number_after(msg: &str, prefix: &str) -> f64 {
    let at = msg
        .find(prefix)
        .unwrap_or_else(|| panic!("`{prefix}` in {msg}"))
        + prefix.len();
    let s: String = msg[at..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-')
        .collect();
    s.parse()
        .unwrap_or_else(|_| panic!("number after `{prefix}` in {msg}"))
}

fn spall_at_tip(depth_um: f64, position_mm: f64) -> Vec<String> {
    [
        "stiffness".to_string(),
        "--set".into(),
        "fault.kind=spall".into(),
        "--set".into(),
        "fault.gear=pinion".into(),
        "--set".into(),
        "fault.tooth=2".into(),
        "--set".into(),
        "fault.spall_length_mm=0.5".into(),
        "--set".into(),
        format!("fault.spall_position_mm={position_mm}"),
        "--set".into(),
        format!("fault.spall_depth_um={depth_um}"),
    ]
    .to_vec()
}

#[test]
fn a_spall_deeper_than_95_percent_of_the_tip_thickness_by_hand_is_refused() {
    // Hand geometry of the paper's pinion (standard involute relations, not the model's
    // tooth beam): half the base-circle tooth angle psi_b = pi/(2z) + 2x tan(a)/z + inv(a),
    // at the tip circle psi_a = psi_b - inv(a_a) with cos(a_a) = r_b / r_a, half-thickness
    // r_a sin(psi_a). A spall whose upper edge is at the tip contact may take 95 % of the
    // thickness there (the beam model's limit, docs/MODEL.md 9.5).
    let case = gearwear::config::case::GearSection::default();
    let pair = gearwear::geometry::GearPair::from_case(&case).unwrap();
    let g = &pair.pinion;
    let (z, x, a) = (
        case.teeth_pinion as f64,
        case.profile_shift_pinion,
        case.pressure_angle_deg.to_radians(),
    );
    let inv = |t: f64| t.tan() - t;
    let psi_b = std::f64::consts::PI / (2.0 * z) + 2.0 * x * a.tan() / z + inv(a);
    let a_tip = (g.base_radius_m / g.tip_radius_m).acos();
    let h_tip = g.tip_radius_m * (psi_b - inv(a_tip)).sin();
    let d_max_um = 0.95 * 2.0 * h_tip * 1e6;
    // Upper edge of a 0.5 mm spall 1e-7 mm below the tip contact (roll length from the
    // pitch point to the tip: sqrt(r_a^2 - r_b^2) - r_b tan(alpha_w)); the thickness
    // changes by ~1e-10 of itself over that step.
    let tip_roll_mm = ((g.tip_radius_m.powi(2) - g.base_radius_m.powi(2)).sqrt()
        - g.base_radius_m * pair.operating_pressure_angle_rad.tan())
        * 1e3;
    let position = tip_roll_mm - 0.25 - 1e-7;
    let deep = spall_at_tip(d_max_um * 1.001, position);
    let msg = rejected(
        &deep.iter().map(String::as_str).collect::<Vec<_>>(),
        &["`fault.spall_depth_um`", "pinion tooth 2", "valid (0,"],
    );
    // The shown limit is rounded down to 0.1 µm.
    let shown = number_after(&msg, "valid (0, ");
    assert!(
        shown <= d_max_um + 1e-6 && shown > d_max_um - 0.1 - 1e-6,
        "shown {shown} µm, hand {d_max_um} µm: {msg}"
    );
    // Just inside the limit runs.
    let inside = spall_at_tip(d_max_um * 0.999, position);
    let dir = tempfile::tempdir().unwrap();
    let mut args: Vec<&str> = inside.iter().map(String::as_str).collect();
    let out = dir.path().join("out");
    args.extend(["-q", "--out", out.to_str().unwrap()]);
    common::ok(&args);
}

#[test]
fn every_limit_a_geometry_message_shows_is_itself_accepted() {
    // A limit shown rounded to nearest can lie outside the valid range (a broken tip of
    // the whole tooth height m (h_a* + h_f*) = 3.5 * 2.25 = 4.5 mm, computed as 4.49999...,
    // was shown as "(0, 4.5000]" and 4.5 refused). Each closed limit a refusal shows must
    // itself be accepted.
    let dir = tempfile::tempdir().unwrap();
    let accepted = |sets: &[String]| {
        let out = dir.path().join("ok");
        let mut a = vec![
            "stiffness",
            "-q",
            "--replace",
            "--out",
            out.to_str().unwrap(),
        ];
        for s in sets {
            a.extend(["--set", s.as_str()]);
        }
        common::ok(&a);
    };
    let tip = |h: &str| {
        vec![
            "fault.kind=broken_tip".to_string(),
            "fault.gear=gear".into(),
            "fault.tooth=4".into(),
            format!("fault.removed_height_mm={h}"),
        ]
    };
    let msg = rejected(
        &[
            "stiffness",
            "--set",
            "fault.kind=broken_tip",
            "--set",
            "fault.gear=gear",
            "--set",
            "fault.tooth=4",
            "--set",
            "fault.removed_height_mm=4.6",
        ],
        &["`fault.removed_height_mm` = 4.6", "gear tooth 4"],
    );
    let h = number_after(&msg, "valid (0, ");
    // Whole depth m (h_a* + h_f*) of the paper's teeth (module 3.5, 1 + 1.25), shown
    // rounded down to 1e-4 mm.
    let case = gearwear::config::case::GearSection::default();
    let depth = case.module_mm * (case.addendum_coefficient + case.dedendum_coefficient);
    assert!(h <= depth && h > depth - 1e-4 - 1e-12, "{h} vs {depth}");
    accepted(&tip(&format!("{h}")));
    let spall = |p: &str| {
        vec![
            "fault.kind=spall".to_string(),
            "fault.gear=pinion".into(),
            "fault.tooth=0".into(),
            "fault.spall_length_mm=1".into(),
            "fault.spall_depth_um=20".into(),
            format!("fault.spall_position_mm={p}"),
        ]
    };
    let msg = rejected(
        &[
            "stiffness",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=0",
            "--set",
            "fault.spall_length_mm=1",
            "--set",
            "fault.spall_depth_um=20",
            "--set",
            "fault.spall_position_mm=50",
        ],
        &[
            "`fault.spall_position_mm` = 50",
            "with length 1 mm",
            "pinion tooth 0",
        ],
    );
    let lo = number_after(&msg, "within [");
    let hi = number_after(&msg, &format!("within [{lo:.4}, "));
    accepted(&spall(&format!("{lo}")));
    accepted(&spall(&format!("{hi}")));
    let msg = rejected(
        &[
            "stiffness",
            "--set",
            "modification.tip_relief_um=5",
            "--set",
            "modification.tip_relief_length_mm=20",
        ],
        &["`modification.tip_relief_length_mm` = 20"],
    );
    let l = number_after(&msg, "valid (0, ");
    accepted(&[
        "modification.tip_relief_um=5".to_string(),
        format!("modification.tip_relief_length_mm={l}"),
    ]);
}
