//! The planar dynamics of a helical pair (`study::helical_dynamics`, docs/MODEL.md 11.1)
//! checked against independent facts: the spur pair as the limit beta -> 0 with one slice,
//! the statics of the mean mesh force (torque balance) and so of the axial bearing
//! reaction, the static transmission error's dependence on the overlap ratio against the
//! contact-line length, the slice convergence, and a dynamic factor near 1 at low speed.

mod common;

use common::{gearwear, rejected, stderr};
use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;
use gearwear::wear::WearState;

fn case_sets(s: &[&str]) -> Vec<String> {
    s.iter().map(|x| x.to_string()).collect()
}

fn helical(sets: &[&str]) -> Model {
    Model::helical_from_case(&load_case("", &case_sets(sets)).expect("valid case"))
        .expect("valid helical model")
}

fn spur(sets: &[&str]) -> Model {
    Model::from_case(&load_case("", &case_sets(sets)).expect("valid case")).expect("valid model")
}

fn steady(m: &Model) -> DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .expect("steady state")
}

fn quasi_static(m: &Model) -> DynamicResponse {
    m.quasi_static(&WearState::new(m.grid.len()), &ExternalError::none())
}

/// Peak-to-peak over mean of a signal.
fn ptp_over_mean(v: &[f64]) -> f64 {
    let (lo, hi) = v
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(*x), b.max(*x))
        });
    (hi - lo) / (v.iter().sum::<f64>() / v.len() as f64)
}

#[test]
fn one_slice_at_a_vanishing_helix_angle_is_the_spur_pair() {
    // beta = 1e-6 deg, one slice (its own contact line): the transverse section is the
    // normal one to 1e-12 relative (m_t = m_n / cos beta, cos beta = 1 - 1.5e-16) and the
    // slice's Hertz term carries cos(beta_b), 1 - 1.4e-16. The responses then agree to
    // rounding amplified by the steady-state solver (its tolerance 1e-6): 1e-9 relative
    // allowed. Both on the nominal path (the helical model has no tip corners) and with
    // the load shared by compression (the helical lines always are).
    let common = [
        "contact.path=\"nominal\"",
        "contact.load_sharing=\"stiffness\"",
    ];
    let mut h = common.to_vec();
    h.extend(["gear.helix_angle_deg=1e-6", "stiffness.slices=1"]);
    let (a, b) = (
        ResponseSummary::of(&steady(&spur(&common))),
        ResponseSummary::of(&steady(&helical(&h))),
    );
    let close = |x: f64, y: f64, what: &str| {
        assert!(
            (x - y).abs() <= 1e-9 * x.abs().max(1e-30),
            "{what}: spur {x}, helical {y}"
        );
    };
    close(a.mesh_force_mean_n, b.mesh_force_mean_n, "mean force");
    close(a.mesh_force_max_n, b.mesh_force_max_n, "max force");
    close(a.mesh_force_min_n, b.mesh_force_min_n, "min force");
    close(a.dte_max_m, b.dte_max_m, "max DTE");
    close(a.dte_min_m, b.dte_min_m, "min DTE");
    close(
        a.friction_force_max_n,
        b.friction_force_max_n,
        "max friction",
    );
    close(
        a.velocity_y_pinion_rms_m_per_s,
        b.velocity_y_pinion_rms_m_per_s,
        "RMS pinion velocity",
    );
}

#[test]
fn many_slices_at_vanishing_helix_angles_are_the_spur_pair() {
    // 100 slices at helix angles whose line L = b tan(beta_b) ranges from far below the
    // rounding of a position on the path (1e-20 deg: L ~ 3e-24 m) to a slice spacing L / N
    // below the line table's finest spacing (1e-9 to 0.02 deg: L / N up to 7e-8 m against
    // the path / 1e5 = 9e-8 m): the slices are taken in phase, each a spur pair of width
    // b / N, and the potential-energy stiffness is linear in width, so the line is the
    // spur pair of the whole face. The responses agree as in the one-slice test above
    // (rounding of N k_slice against k, amplified by the steady-state solver: 1e-9
    // relative) plus the transverse section's own change: the module, the pressure angle
    // and the Hertz radii move by about 1 - cos(beta) (6e-8 at 0.02 deg, 4e-11 at 5e-4
    // deg), allowed 10 times over.
    let common = [
        "contact.path=\"nominal\"",
        "contact.load_sharing=\"stiffness\"",
    ];
    let a = ResponseSummary::of(&steady(&spur(&common)));
    for beta in ["1e-20", "1e-9", "1e-4", "5e-4", "0.02"] {
        let angle = format!("gear.helix_angle_deg={beta}");
        let mut h = common.to_vec();
        h.extend([angle.as_str(), "stiffness.slices=100"]);
        let b = ResponseSummary::of(&steady(&helical(&h)));
        let beta_rad = beta.parse::<f64>().unwrap().to_radians();
        let tol = 1e-9 + 10.0 * (1.0 - beta_rad.cos());
        for (x, y, what) in [
            (a.mesh_force_mean_n, b.mesh_force_mean_n, "mean force"),
            (a.mesh_force_max_n, b.mesh_force_max_n, "max force"),
            (a.dte_max_m, b.dte_max_m, "max DTE"),
            (
                a.friction_force_max_n,
                b.friction_force_max_n,
                "max friction",
            ),
        ] {
            assert!(
                (x - y).abs() <= tol * x.abs(),
                "{what} at {beta} deg: spur {x}, helical {y}"
            );
        }
    }
}

#[test]
fn the_mean_axial_reaction_is_the_tangential_force_times_tan_beta_b() {
    // Statics: over a period of the steady state every acceleration averages to zero, so
    // the pinion's torque balance gives a mean mesh force T_p / r_b1 exactly (no friction:
    // its moments would take a share). Independent of the model's own numbers: r_b1 and
    // beta_b from ISO 21771's transverse section by hand, T_p the case's load torque (on
    // the pinion by default). The axial force on the pinion is +F_t tan(beta_b) (right hand,
    // driving: along its angular velocity, docs/MODEL.md 11.6).
    // Tolerance 1e-6 of F_t (the issue's): the periodic solution's residual and Simpson's
    // rule on 200 steps per period are far below it.
    let m = helical(&["gear.helix_angle_deg=15", "friction.model=\"none\""]);
    let r = steady(&m);
    let c = &m.case;
    let (beta, alpha_n) = (15f64.to_radians(), c.gear.pressure_angle_deg.to_radians());
    let alpha_t = (alpha_n.tan() / beta.cos()).atan();
    let mt = c.gear.module_mm * 1e-3 / beta.cos();
    let rb1 = 0.5 * mt * c.gear.teeth_pinion as f64 * alpha_t.cos();
    let tan_bb = beta.tan() * alpha_t.cos();
    assert_eq!(
        c.operating.load_torque_shaft,
        gearwear::config::case::TorqueShaft::Pinion
    );
    let ft = c.operating.load_torque_nm / rb1;
    let h = gearwear::report::dynamics_helical::helical_summary(&m, &r).unwrap();
    let axial = h["axial_force_pinion"]["mean_n"].as_f64().unwrap();
    assert!(
        (axial - ft * tan_bb).abs() <= 1e-6 * ft,
        "mean axial {axial} N against F_t tan(beta_b) = {} N",
        ft * tan_bb
    );
    // The hand the case gives (right by default) is the hand reported; a left-hand
    // pinion is pushed against its angular velocity, by the same force.
    assert_eq!(h["hand_pinion"], "right");
    let left = helical(&[
        "gear.helix_angle_deg=15",
        "friction.model=\"none\"",
        "gear.helix_hand_pinion=\"left\"",
    ]);
    let h = gearwear::report::dynamics_helical::helical_summary(&left, &steady(&left)).unwrap();
    assert_eq!(h["hand_pinion"], "left");
    let axial = h["axial_force_pinion"]["mean_n"].as_f64().unwrap();
    assert!(
        (axial + ft * tan_bb).abs() <= 1e-6 * ft,
        "left hand: mean axial {axial} N against -F_t tan(beta_b)"
    );
}

#[test]
fn static_te_fluctuation_follows_the_contact_line_length() {
    // The contact lines' total length Lc(t) on the plane of action (Maatar & Velex 1996;
    // AGMA 908-B89's L_min) is constant when the overlap ratio eps_beta is whole and
    // fluctuates most near half-integers. A helical pair's stiffness follows Lc to first
    // order (stiffness per unit line length varies along the profile only), so the
    // static transmission error's peak-to-peak over its mean must do the same: checked
    // on the built-in normal section at beta = 20 deg, the face width chosen for each
    // eps_beta (b = eps_beta pi m_n / sin beta). Lc from the exact contact lines; its
    // fluctuation is 0 (to rounding) at whole eps_beta.
    let (beta, mn) = (20f64.to_radians(), 2.0);
    let run = |eps_b: f64| {
        let b_mm = eps_b * std::f64::consts::PI * mn / beta.sin();
        let m = helical(&[
            "gear.helix_angle_deg=20",
            &format!("gear.face_width_mm={b_mm}"),
            "friction.model=\"none\"",
        ]);
        let hp = &m.helical.as_ref().unwrap().pair;
        let period = hp.transverse.mesh_angle_rad();
        let lc: Vec<f64> = (0..2000)
            .map(|i| hp.contact_length_m(period * i as f64 / 2000.0))
            .collect();
        let r = quasi_static(&m);
        (
            ptp_over_mean(&lc),
            ptp_over_mean(&r.signals.meshes[0].dte_m),
        )
    };
    let results: Vec<(f64, f64, f64)> = [0.5, 1.0, 1.5, 2.0]
        .iter()
        .map(|e| {
            let (l, s) = run(*e);
            (*e, l, s)
        })
        .collect();
    for (e, lc, ste) in &results {
        eprintln!("eps_beta {e}: Lc ptp/mean {lc:.4}, STE ptp/mean {ste:.4}");
    }
    let ste = |i: usize| results[i].2;
    let lc = |i: usize| results[i].1;
    // Geometry: whole overlap ratios give a constant contact length.
    assert!(lc(1) < 1e-9 && lc(3) < 1e-9, "{results:?}");
    assert!(lc(0) > 0.1 && lc(2) > 0.05, "{results:?}");
    // The STE follows: at whole eps_beta its fluctuation is a small fraction of the
    // half-integers' (the slices' varying stiffness along the profile remains: 1/5 allowed).
    assert!(
        ste(1) < 0.2 * ste(0) && ste(1) < 0.2 * ste(2),
        "{results:?}"
    );
    assert!(ste(3) < 0.2 * ste(2), "{results:?}");
    // And the half-integers' fluctuations fall with eps_beta as Lc's does.
    assert!(ste(2) < ste(0) && lc(2) < lc(0), "{results:?}");
}

#[test]
fn doubling_the_slices_changes_mean_stiffness_and_static_te_by_under_a_thousandth() {
    // The convergence criterion at the default N = 400 (beta = 15 deg, eps_beta
    // 0.82): the mean mesh stiffness of the line table and the STE's peak-to-peak.
    let run = |n: usize| {
        let m = helical(&[
            "gear.helix_angle_deg=15",
            &format!("stiffness.slices={n}"),
            "friction.model=\"none\"",
        ]);
        let r = quasi_static(&m);
        let d = &r.signals.meshes[0].dte_m;
        let ptp = d.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - d.iter().cloned().fold(f64::INFINITY, f64::min);
        (m.mesh.mean_stiffness_n_per_m(), ptp)
    };
    let (k1, p1) = run(400);
    let (k2, p2) = run(800);
    eprintln!("N 400: k {k1:.6e}, STE ptp {p1:.6e}; N 800: k {k2:.6e}, STE ptp {p2:.6e}");
    assert!(((k2 - k1) / k1).abs() < 1e-3, "{k1} {k2}");
    assert!(((p2 - p1) / p1).abs() < 1e-3, "{p1} {p2}");
}

#[test]
fn at_low_speed_the_dynamic_factor_is_close_to_one() {
    // Far below the mesh resonance (5 Hz input: mesh frequency 95 Hz, the resonance in
    // the kHz) the mesh force follows the static load, which without friction is the
    // constant T / r_b1: max / mean within 1 % (measured 1.006; with Xu's friction 1.019,
    // the friction moments' own quasi-static swing at the pitch point; the spur pair on
    // the nominal path has 1.68 here, its whole-pair stiffness jumps ringing the mesh
    // mode). The extended contact path does not apply (no tip corners on helical slices).
    let m = helical(&[
        "gear.helix_angle_deg=15",
        "operating.input_speed_hz=5",
        "friction.model=\"none\"",
    ]);
    let s = ResponseSummary::of(&steady(&m));
    assert!(
        (s.dynamic_factor - 1.0).abs() < 0.01,
        "dynamic factor {}",
        s.dynamic_factor
    );
}

#[test]
fn helical_dynamics_writes_the_axial_force_and_refuses_what_it_lacks() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("h");
    let o = gearwear(&[
        "dynamics",
        "-q",
        "--out",
        out.to_str().unwrap(),
        "--set",
        "gear.helix_angle_deg=15",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(
        s["helical"]["axial_force_pinion"]["mean_n"]
            .as_f64()
            .unwrap()
            > 0.0
    );
    let ts = std::fs::read_to_string(out.join("timeseries.csv")).unwrap();
    assert!(ts.lines().next().unwrap().contains("axial_force_pinion_n"));
    // A total contact ratio above 4 lines: exit 2 naming the keys and the range.
    rejected(
        &[
            "dynamics",
            "--set",
            "gear.helix_angle_deg=30",
            "--set",
            "gear.face_width_mm=40",
        ],
        &["gear.helix_angle_deg", "gear.face_width_mm", "(0, 4]"],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "gear.helix_angle_deg=15",
            "--set",
            "contact.load_sharing=\"pedrero\"",
        ],
        &["contact.load_sharing", "pedrero"],
    );
}
