//! Tilting degrees of freedom of a helical pair (docs/MODEL.md 11.8) against independent
//! facts: the statics of the mean tilts (moments of the axial force by hand from the
//! case's torque and geometry), the axial model as the limit of stiff tilting bearings, no
//! tilt at a vanishing helix angle, and the refusals.

mod common;

use common::rejected;
use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::study::Model;
use gearwear::wear::WearState;

fn model_of(sets: &[&str]) -> Model {
    let sets: Vec<String> = sets.iter().map(|x| x.to_string()).collect();
    Model::helical_from_case(&load_case("", &sets).expect("valid case")).expect("valid model")
}

fn steady(m: &Model) -> DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .expect("steady state")
}

fn tilt_of(m: &Model, r: &DynamicResponse) -> serde_json::Value {
    gearwear::report::dynamics_helical::helical_summary(m, r).unwrap()["tilt"].clone()
}

fn num(v: &serde_json::Value, path: &[&str]) -> f64 {
    let mut x = v;
    for p in path {
        x = &x[*p];
    }
    x.as_f64().unwrap_or_else(|| panic!("{path:?} in {v}"))
}

#[test]
fn the_mean_tilts_are_the_axial_force_moments_over_the_bearings() {
    // Statics, by hand from the case: with no friction the mean transverse mesh force is
    // F = T / r_b1 (T the pinion torque), its axial part F tan(beta_b) s. About the line
    // of action d the axial force acts at the base radius: the pinion's bearing carries
    // -s F tan(beta_b) r_b1 = -s T tan(beta_b), the gear's -s T tan(beta_b) r_b2 / r_b1
    // (its axial force is opposite, its lever on the other side of the plane), so
    // b = moment / k_t. About n (the plane of action's normal) the two axial forces form
    // a couple of arm N1N2 = L = (r_1 + r_2) sin(alpha_t) (standard centre distance) on
    // the pair; the mesh's own tilting spring and mean lever act between the bodies and
    // cancel from the sum: k_t (a_p + a_g) = s F tan(beta_b) L. tan(beta_b) =
    // tan(beta) cos(alpha_t), tan(alpha_t) = tan(alpha_n) / cos(beta) (ISO 21771).
    // Tolerance 1e-6 of the moment: the periodic solution's residual on a mean (as the
    // axial reactions' test) with ~200 samples per period, slope-corrected.
    for (hand, s) in [("right", 1.0), ("left", -1.0)] {
        let hand_key = format!("gear.helix_hand_pinion=\"{hand}\"");
        let k_t = 1e5;
        let m = model_of(&[
            "gear.helix_angle_deg=15",
            "friction.model=\"none\"",
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e5",
            "dynamics.bearing_tilt_stiffness_gear_nm_per_rad=1e5",
            &hand_key,
        ]);
        let r = steady(&m);
        let tilt = tilt_of(&m, &r);
        let c = &m.case;
        let beta = 15f64.to_radians();
        let alpha_t = (c.gear.pressure_angle_deg.to_radians().tan() / beta.cos()).atan();
        let tan_bb = beta.tan() * alpha_t.cos();
        let t = c.operating.load_torque_nm;
        let (z1, z2) = (c.gear.teeth_pinion as f64, c.gear.teeth_gear as f64);
        let r1 = 0.5 * c.gear.module_mm * 1e-3 / beta.cos() * z1;
        let r2 = r1 * z2 / z1;
        let rb1 = r1 * alpha_t.cos();
        let f = t / rb1;
        let b_p = -s * t * tan_bb / k_t;
        let b_g = b_p * z2 / z1;
        let couple = s * f * tan_bb * (r1 + r2) * alpha_t.sin();
        let got_bp = num(&tilt, &["pinion", "about_line_of_action_mean_rad"]);
        let got_bg = num(&tilt, &["gear", "about_line_of_action_mean_rad"]);
        let got_sum = k_t
            * (num(&tilt, &["pinion", "about_plane_normal_mean_rad"])
                + num(&tilt, &["gear", "about_plane_normal_mean_rad"]));
        eprintln!(
            "{hand}: b_p {got_bp:.6e} vs {b_p:.6e}, b_g {got_bg:.6e} vs {b_g:.6e}, couple {got_sum:.6e} vs {couple:.6e} N m"
        );
        assert!((got_bp - b_p).abs() <= 1e-6 * b_p.abs(), "{hand}");
        assert!((got_bg - b_g).abs() <= 1e-6 * b_g.abs(), "{hand}");
        assert!((got_sum - couple).abs() <= 1e-6 * couple.abs(), "{hand}");
        // The relative tilt loads the face linearly: K_Hbeta above 1, from the mean tilt.
        let k = num(&tilt, &["k_h_beta_of_mean_tilt"]);
        assert!(k > 1.0 && k < 2.0, "{k}");
    }
}

/// Largest |a - b| over the samples of two responses on the same steps, over the mean
/// of |b|.
fn relative_gap(a: &[f64], b: &[f64]) -> f64 {
    let mean = b.iter().map(|x| x.abs()).sum::<f64>() / b.len() as f64;
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / mean
}

#[test]
fn stiff_tilting_bearings_converge_to_the_model_without_tilt() {
    // The tilting bearings k_t are in series with the mesh along the tilting entries g of
    // its gradient: the mesh sees 1/k_eff = 1/k_m + |g_tilt|^2 / k_t, |g_tilt|^2 = mu^2 +
    // (s t r_b1)^2 + (mu - s t L)^2 + (s t r_b2)^2 ~ 2e-4 m^2 on the built-in pair, a
    // relative change k_m |g|^2 / k_t = 4e8 x 2e-4 / 1e12 = 8e-8 at 1e12 N m/rad: the
    // force differs from the axial model's by far less than 1e-5 of its mean, and the
    // gap grows with 1/k_t (1e4 times softer: at least 20 times more gap; measured 2e-8
    // at 1e12, near the solver's floor, 2e-7 at 1e10 and 7e-2 at 1e8, where the
    // undamped tilting modes, 20 to 135 kHz, join the response).
    let base = [
        "gear.helix_angle_deg=15",
        "dynamics.bearing_axial_stiffness_pinion_n_per_m=5e8",
    ];
    let axial = steady(&model_of(&base));
    let gap_at = |k: &str| {
        let kp = format!("dynamics.bearing_tilt_stiffness_pinion_nm_per_rad={k}");
        let kg = format!("dynamics.bearing_tilt_stiffness_gear_nm_per_rad={k}");
        let sets = [base[0], base[1], kp.as_str(), kg.as_str()];
        let r = steady(&model_of(&sets));
        let n = r.signals.time_s.len().min(axial.signals.time_s.len());
        let f = |x: &DynamicResponse| x.signals.meshes[0].mesh_force_n[..n].to_vec();
        relative_gap(&f(&r), &f(&axial))
    };
    let (f12, f8) = (gap_at("1e12"), gap_at("1e8"));
    eprintln!("force gap to the axial model: {f12:.2e} at 1e12, {f8:.2e} at 1e8 N m/rad");
    assert!(f12 < 1e-5, "{f12}");
    assert!(f8 > 20.0 * f12, "{f8} against {f12}");
}

#[test]
fn a_vanishing_helix_angle_tilts_nothing() {
    // beta -> 0: the axial force and the axial levers vanish (s t -> 0) and the uniform
    // face load has no moment about the face centre, so nothing excites the tilts; at
    // beta = 15 deg the same bearings tilt by ~1e-4 rad. Bound: 1e-6 of that (beta =
    // 1e-6 deg gives s t ~ 2e-8, moments ~ F s t L ~ 1e-6 N m, tilts ~ 1e-11 rad).
    let tilts = |beta: &str| {
        let key = format!("gear.helix_angle_deg={beta}");
        let m = model_of(&[
            &key,
            "stiffness.slices=40",
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e5",
            "dynamics.bearing_tilt_stiffness_gear_nm_per_rad=1e5",
        ]);
        let r = steady(&m);
        let t = tilt_of(&m, &r);
        let mut largest: f64 = 0.0;
        for body in ["pinion", "gear"] {
            for what in [
                "about_plane_normal_mean_rad",
                "about_plane_normal_amplitude_rad",
                "about_line_of_action_mean_rad",
                "about_line_of_action_amplitude_rad",
            ] {
                largest = largest.max(num(&t, &[body, what]).abs());
            }
        }
        largest
    };
    let (small, helical) = (tilts("1e-6"), tilts("15"));
    eprintln!("largest tilt: {small:.3e} rad at 1e-6 deg, {helical:.3e} rad at 15 deg");
    assert!(helical > 1e-5, "{helical}");
    assert!(small < 1e-6 * helical, "{small}");
}

#[test]
fn the_tilting_keys_are_refused_where_not_built_and_bad_values_named() {
    let key = "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad";
    let set = format!("{key}=1e5");
    for cmd in ["wear", "run"] {
        rejected(
            &[cmd, "--set", "gear.helix_angle_deg=15", "--set", &set],
            &[key, "does not take them"],
        );
    }
    rejected(
        &[
            "dynamics",
            "--config",
            "examples/two_stage_reducer.toml",
            "--set",
            &set,
        ],
        &[key, "gear train"],
    );
    for (key, value, range) in [
        (
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad",
            "0",
            "[1000, 1e12]",
        ),
        (
            "dynamics.bearing_tilt_stiffness_gear_nm_per_rad",
            "1e13",
            "[1000, 1e12]",
        ),
        (
            "dynamics.bearing_tilt_damping_pinion_nm_s_per_rad",
            "-1",
            "[0, 1e6]",
        ),
        (
            "dynamics.bearing_tilt_damping_gear_nm_s_per_rad",
            "nan",
            "[0, 1e6]",
        ),
    ] {
        let set = format!("{key}={value}");
        rejected(
            &[
                "dynamics",
                "--set",
                "gear.helix_angle_deg=15",
                "--set",
                &set,
            ],
            &[key, range],
        );
    }
}

#[test]
fn tilt_damping_without_its_stiffness_is_warned_about_not_ignored() {
    // Without `dynamics.bearing_tilt_stiffness_pinion_nm_per_rad` the pinion's tilting is
    // held rigidly: a damping given alone has nothing to act on, so the model says so; the
    // gear's axial damping without its axial stiffness likewise (one warning per key).
    let m = model_of(&[
        "gear.helix_angle_deg=15",
        "contact.path=\"nominal\"",
        "dynamics.bearing_tilt_damping_pinion_nm_s_per_rad=100",
        "dynamics.bearing_axial_damping_gear_n_s_per_m=50",
    ]);
    for key in [
        "`dynamics.bearing_tilt_damping_pinion_nm_s_per_rad` = 100 is ignored: without `dynamics.bearing_tilt_stiffness_pinion_nm_per_rad`",
        "`dynamics.bearing_axial_damping_gear_n_s_per_m` = 50 is ignored: without `dynamics.bearing_axial_stiffness_gear_n_per_m`",
    ] {
        let found = m.warnings.iter().filter(|w| w.contains(key)).count();
        assert_eq!(found, 1, "{key}: {:?}", m.warnings);
    }
}

#[test]
fn on_a_spur_pair_the_tilting_keys_are_ignored_with_a_warning_by_every_study() {
    // A spur pair has no tilting model: the keys are warned about and ignored whichever
    // study builds it, a load spectrum's model included (it refused them while `wear`
    // warned); on a helical pair the same model refuses them.
    let spectrum = |helix: &str| {
        let sets: Vec<String> = [
            format!("gear.helix_angle_deg={helix}"),
            "contact.path=\"nominal\"".into(),
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e5".into(),
        ]
        .into();
        gearwear::duty::SpectrumModel::dynamics_from_case(&load_case("", &sets).unwrap())
    };
    let spur = spectrum("0").expect("a spur pair ignores the tilting keys");
    let warned = spur.bins[0].warnings.iter().any(|w| {
        w.contains("`dynamics.bearing_tilt_stiffness_pinion_nm_per_rad` = 100000 is ignored")
    });
    assert!(warned, "{:?}", spur.bins[0].warnings);
    let refusal = spectrum("15")
        .err()
        .expect("refused on a helical pair")
        .0
        .join(" ");
    assert!(refusal.contains("does not take them"), "{refusal}");
}

#[test]
fn the_mean_relative_tilt_follows_the_mesh_lever_and_tilting_stiffness() {
    // Statics about the plane of action's normal, derived by hand (docs/MODEL.md 11.8):
    // the slices' moment is mu F + J tau on the pinion and s t L F - (mu F + J tau) on the
    // gear, each held by its bearing (k_t a = moment), so with c = 1 / k_t
    //   tau = F (s t L c_g - mu (c_p + c_g)) / (1 + J (c_p + c_g)).
    // Unequal bearings, so that mu and J do not cancel (the sum test above cancels them);
    // mu and J from the summary (checked by time averages in src/study/helical_tilt.rs),
    // F = T / r_b1 and L = (r_1 + r_2) sin(alpha_t) by hand. The model's mesh terms are
    // time-invariant and linear in tau, so the period means obey this exactly: 1e-6 as the
    // test above (the periodic solution's residual on a mean).
    for (hand, s) in [("right", 1.0), ("left", -1.0)] {
        let hand_key = format!("gear.helix_hand_pinion=\"{hand}\"");
        let (kp, kg) = (1e5, 3e5);
        let m = model_of(&[
            "gear.helix_angle_deg=15",
            "friction.model=\"none\"",
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e5",
            "dynamics.bearing_tilt_stiffness_gear_nm_per_rad=3e5",
            &hand_key,
        ]);
        let tilt = tilt_of(&m, &steady(&m));
        let c = &m.case;
        let beta = 15f64.to_radians();
        let alpha_t = (c.gear.pressure_angle_deg.to_radians().tan() / beta.cos()).atan();
        let tan_bb = beta.tan() * alpha_t.cos();
        let (z1, z2) = (c.gear.teeth_pinion as f64, c.gear.teeth_gear as f64);
        let r1 = 0.5 * c.gear.module_mm * 1e-3 / beta.cos() * z1;
        let l = (r1 + r1 * z2 / z1) * alpha_t.sin();
        let f = c.operating.load_torque_nm / (r1 * alpha_t.cos());
        let mu = num(&tilt, &["mesh_centre_lever_m"]);
        let j = num(&tilt, &["mesh_tilting_stiffness_nm_per_rad"]);
        let (cp, cg) = (1.0 / kp, 1.0 / kg);
        let tau = f * (s * tan_bb * l * cg - mu * (cp + cg)) / (1.0 + j * (cp + cg));
        let got = num(&tilt, &["relative_tilt_mean_rad"]);
        assert!(
            (got - tau).abs() <= 1e-6 * tau.abs(),
            "{hand}: tau {got:.6e}, by hand {tau:.6e}"
        );
    }
}

#[test]
fn a_tilt_that_would_unload_a_face_end_is_refused_before_the_run() {
    // A soft tilting bearing (1e3 N m/rad) on a pair with a long line of action (150 gear
    // teeth) and a narrow face: the static tilt of the test above gives K_Hbeta well over
    // 2, half the face unloaded, beyond the linear law; refused naming the keys.
    let sets: Vec<String> = [
        "gear.helix_angle_deg=20",
        "gear.teeth_gear=150",
        "gear.face_width_mm=10",
        "gear.hub_bore_radius_gear_mm=\"derived\"",
        "contact.path=\"nominal\"",
        "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e3",
        "dynamics.bearing_tilt_stiffness_gear_nm_per_rad=1e3",
    ]
    .map(String::from)
    .into();
    let case = load_case("", &sets).expect("valid case");
    let err = Model::helical_from_case(&case)
        .err()
        .expect("refused")
        .0
        .join(" ");
    assert!(
        err.contains("`dynamics.bearing_tilt_stiffness_pinion_nm_per_rad` = 1000")
            && err.contains("unload a face end"),
        "{err}"
    );
}
