//! Axial degrees of freedom of a helical pair (docs/MODEL.md 11.6) against independent
//! facts: the statics of the mean axial bearing reactions (ISO 6336-1's axial force
//! F_t tan(beta) from the case's torque by hand), the planar model as the limit of stiff
//! axial bearings, the natural frequencies against a nonsymmetric eigen-solution of the
//! matrices assembled by hand, the refusals of bad values, and the wear study running on
//! the same model.

mod common;

use common::{gearwear, rejected, stderr};
use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::study::modes::ModalAnalysis;
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;
use gearwear::wear::WearState;
use nalgebra::DMatrix;

const STIFF: [&str; 2] = [
    "dynamics.bearing_axial_stiffness_pinion_n_per_m=5e8",
    "dynamics.bearing_axial_stiffness_gear_n_per_m=7e8",
];

fn helical(sets: &[&str]) -> Model {
    let sets: Vec<String> = sets.iter().map(|x| x.to_string()).collect();
    Model::helical_from_case(&load_case("", &sets).expect("valid case")).expect("valid model")
}

fn steady(m: &Model) -> DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .expect("steady state")
}

fn with(base: &[&str], more: &[&str]) -> Vec<String> {
    base.iter().chain(more).map(|x| x.to_string()).collect()
}

fn model_of(sets: &[String]) -> Model {
    let s: Vec<&str> = sets.iter().map(String::as_str).collect();
    helical(&s)
}

/// Column `name` of the summary's `axial_bearings` block for `body`.
fn bearing(v: &serde_json::Value, body: &str, name: &str) -> f64 {
    v["axial_bearings"][body][name]
        .as_f64()
        .unwrap_or_else(|| panic!("{body}.{name} in {v}"))
}

#[test]
fn the_mean_axial_bearing_reactions_are_the_axial_force_of_the_torque() {
    // Statics, independent of the model: over a period of the steady state every
    // acceleration averages to zero, so the pinion's torque balance gives a mean mesh
    // force T / r_b1 (no friction) and each axial bearing carries the mean axial force
    // F_t tan(beta), F_t = T / r_1 at the reference circle (ISO 6336-1's F_x), computed
    // here from ISO 21771's transverse module by hand. Right hand: the pinion is pushed
    // along its angular velocity (+), the gear the other way; the left hand reverses both.
    // Tolerance 1e-6 of F_t tan(beta) (the issue's): the periodic solution's residual
    // (1e-6 of the state scales, far smaller on a mean) and the slope-corrected trapezoid
    // on ~200 samples per period (fourth order) are below it.
    for (hand, sign) in [("right", 1.0), ("left", -1.0)] {
        let hand_key = format!("gear.helix_hand_pinion=\"{hand}\"");
        let sets = with(
            &STIFF,
            &[
                "gear.helix_angle_deg=15",
                "friction.model=\"none\"",
                hand_key.as_str(),
            ],
        );
        let m = model_of(&sets);
        let r = steady(&m);
        let c = &m.case;
        let beta = 15f64.to_radians();
        let r1 = 0.5 * c.gear.module_mm * 1e-3 / beta.cos() * c.gear.teeth_pinion as f64;
        let fx = c.operating.load_torque_nm / r1 * beta.tan();
        let h = gearwear::report::dynamics_helical::helical_summary(&m, &r).unwrap();
        for (body, s) in [("pinion", sign), ("gear", -sign)] {
            assert_eq!(h["axial_bearings"][body]["bearing"], "elastic");
            let mean = bearing(&h, body, "reaction_mean_n");
            eprintln!(
                "{hand} {body}: mean reaction relative error {:.2e}",
                (mean - s * fx).abs() / fx
            );
            assert!(
                (mean - s * fx).abs() <= 1e-6 * fx,
                "{hand} {body}: mean reaction {mean} N against {} N",
                s * fx
            );
            // The reaction swings about its mean with the mesh force.
            assert!(bearing(&h, body, "reaction_max_n") >= mean);
            assert!(bearing(&h, body, "reaction_min_n") <= mean);
            assert!(bearing(&h, body, "displacement_amplitude_m") > 0.0);
        }
        // The mean displacement is the mean load over the bearing's spring.
        let zp = bearing(&h, "pinion", "displacement_mean_m");
        assert!((zp * 5e8 - sign * fx).abs() <= 1e-6 * fx, "{zp}");
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
fn stiff_axial_bearings_converge_to_the_planar_model() {
    // The axial bearings k_a of pinion and gear are in series with the mesh spring along
    // the axial projection: the mesh sees 1/k_eff = 1/k_m + tan^2(beta_b) (1/k_a,p +
    // 1/k_a,g), a relative change of the stiffness 2 k_m tan^2(beta_b) / k_a (4e8 x 0.063
    // x 2 / 1e12 = 5e-5 at 1e12 N/m). The steady mesh force then differs from the planar
    // model's by that order (the stiffness swing it drives, ~10 %, times it), far below
    // the bound 1e-4 of the mean force, and the gap shrinks with 1/k_a: 100 times the
    // stiffness, at least 20 times less gap (the solver's 1e-6 tolerance is the floor).
    let base = ["gear.helix_angle_deg=15"];
    let planar = steady(&helical(&base));
    let gap_at = |k: &str| {
        let sets = with(
            &base,
            &[
                &format!("dynamics.bearing_axial_stiffness_pinion_n_per_m={k}"),
                &format!("dynamics.bearing_axial_stiffness_gear_n_per_m={k}"),
            ],
        );
        let r = steady(&model_of(&sets));
        // The same steady-state grid: compare sample by sample on the common times.
        let n = r.signals.time_s.len().min(planar.signals.time_s.len());
        let f = |x: &DynamicResponse| x.signals.meshes[0].mesh_force_n[..n].to_vec();
        let yp = |x: &DynamicResponse| x.signals.displacement.column(1)[..n].to_vec();
        (
            relative_gap(&f(&r), &f(&planar)),
            relative_gap(&yp(&r), &yp(&planar)),
            (r.meshes[0].mean_mesh_force_n / planar.meshes[0].mean_mesh_force_n - 1.0).abs(),
        )
    };
    let (f12, y12, mean12) = gap_at("1e12");
    let (f10, _, _) = gap_at("1e10");
    eprintln!(
        "planar gap: force {f12:.2e} at 1e12, {f10:.2e} at 1e10; y_p {y12:.2e}; mean {mean12:.2e}"
    );
    assert!(f12 < 1e-4, "mesh force gap at 1e12 N/m: {f12}");
    assert!(y12 < 1e-4, "y_pinion gap at 1e12 N/m: {y12}");
    assert!(mean12 < 1e-6, "mean mesh force {mean12}");
    assert!(f10 > 20.0 * f12, "gap at 1e10 {f10} against 1e12 {f12}");
}

/// K and M of the whole model at the mean mesh stiffness written out by hand:
/// `[x_p, y_p, x_g, y_g, phi_m, phi_p, phi_g, phi_b, z_p, z_g]`, the bearings, couplings
/// and the mesh spring along its gradient (sin a, cos a, -sin a, -cos a, 0, r_b1, -r_b2,
/// 0, -s tan(beta_b), s tan(beta_b)), a the operating transverse pressure angle.
fn hand_matrices(m: &Model, k_mesh: f64, coupled: bool) -> (DMatrix<f64>, Vec<f64>) {
    let l = &m.params.lumped;
    let p = &m.pair;
    let (kp, kg) = (
        l.bearing_stiffness_pinion_n_per_m,
        l.bearing_stiffness_gear_n_per_m,
    );
    let mut k = DMatrix::zeros(10, 10);
    for (i, v) in [kp, kp, kg, kg].iter().enumerate() {
        k[(i, i)] = *v;
    }
    for (a, b, v) in [
        (4, 5, l.coupling_stiffness_motor_nm_per_rad),
        (6, 7, l.coupling_stiffness_brake_nm_per_rad),
    ] {
        k[(a, a)] += v;
        k[(b, b)] += v;
        k[(a, b)] -= v;
        k[(b, a)] -= v;
    }
    k[(8, 8)] = 5e8;
    k[(9, 9)] = 7e8;
    let beta = 15f64.to_radians();
    let alpha_t = (m.case.gear.pressure_angle_deg.to_radians().tan() / beta.cos()).atan();
    let tan_bb = if coupled {
        beta.tan() * alpha_t.cos()
    } else {
        0.0
    };
    let (s, c) = p.operating_pressure_angle_rad.sin_cos();
    let g = [
        s,
        c,
        -s,
        -c,
        0.0,
        p.pinion.base_radius_m,
        -p.gear.base_radius_m,
        0.0,
        -tan_bb,
        tan_bb,
    ];
    for i in 0..10 {
        for j in 0..10 {
            k[(i, j)] += k_mesh * g[i] * g[j];
        }
    }
    let mass = vec![
        l.mass_pinion_kg,
        l.mass_pinion_kg,
        l.mass_gear_kg,
        l.mass_gear_kg,
        l.inertia_motor_kg_m2,
        l.inertia_pinion_kg_m2,
        l.inertia_gear_kg_m2,
        l.inertia_brake_kg_m2,
        l.mass_pinion_kg,
        l.mass_gear_kg,
    ];
    (k, mass)
}

#[test]
fn the_natural_frequencies_take_the_axial_torsional_coupling() {
    // The summary's undamped natural frequencies (study::modes, a symmetric eigen-solve
    // of the assembled matrices) against the eigenvalues of M^-1 K assembled by hand above
    // and solved by the nonsymmetric (Schur) solver, at the model's own mean mesh
    // stiffness; motor slip: every coordinate free. 1e-6 relative: both solvers are
    // backward stable to ~1e-12 of the largest eigenvalue (omega^2 ~ 1e13); the smallest
    // nonzero frequency (~1e3 rad^2/s^2... the rigid rotation is 0) is left out as it
    // carries that absolute error. Without the axial entries of the mesh gradient (the
    // same matrices, a = 0) some frequency moves by more than 1e-3: the coupling is
    // there, and the model has it.
    let sets = with(
        &STIFF,
        &[
            "gear.helix_angle_deg=15",
            "operating.speed_boundary=\"motor_slip\"",
        ],
    );
    let m = model_of(&sets);
    let modes = ModalAnalysis::of(&m);
    let k_mesh = gearwear::dynamics::modal::mean_mesh_stiffnesses(&m.system(
        &gearwear::dynamics::excitation::PairGap::none(),
        &ExternalError::none(),
        0.0,
    ))[0];
    let by_hand = |coupled: bool| {
        let (k, mass) = hand_matrices(&m, k_mesh, coupled);
        let a = DMatrix::from_fn(10, 10, |i, j| k[(i, j)] / mass[i]);
        let mut f: Vec<f64> = a
            .complex_eigenvalues()
            .iter()
            .map(|z| z.re.max(0.0).sqrt() / (2.0 * std::f64::consts::PI))
            .collect();
        f.sort_by(f64::total_cmp);
        f
    };
    let (hand, uncoupled) = (by_hand(true), by_hand(false));
    let got = &modes.undamped.frequency_hz;
    assert_eq!(got.len(), 10);
    for (g, h) in got.iter().zip(&hand).skip(1) {
        assert!((g - h).abs() <= 1e-6 * h, "{g} Hz against {h} Hz by hand");
    }
    let moved = got
        .iter()
        .zip(&uncoupled)
        .skip(1)
        .map(|(g, u)| (g - u).abs() / u)
        .fold(0.0, f64::max);
    eprintln!("frequencies {got:?}\nuncoupled {uncoupled:?}; largest move {moved:.3e}");
    assert!(moved > 1e-3, "the coupling moves no frequency: {moved}");
}

#[test]
fn bad_axial_bearing_values_are_refused_naming_the_key() {
    for (key, value, range) in [
        (
            "dynamics.bearing_axial_stiffness_pinion_n_per_m",
            "0",
            "[10000, 1e12]",
        ),
        (
            "dynamics.bearing_axial_stiffness_gear_n_per_m",
            "1e13",
            "[10000, 1e12]",
        ),
        (
            "dynamics.bearing_axial_damping_pinion_n_s_per_m",
            "-1",
            "[0, 1e8]",
        ),
        (
            "dynamics.bearing_axial_damping_gear_n_s_per_m",
            "nan",
            "[0, 1e8]",
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
fn gearwear_dynamics_writes_the_bearings_and_a_spur_pair_ignores_the_keys() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("h");
    let mut args = vec!["dynamics", "-q", "--out", out.to_str().unwrap()];
    for s in ["gear.helix_angle_deg=15", STIFF[0]] {
        args.extend(["--set", s]);
    }
    let o = gearwear(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let h = &s["helical"];
    assert_eq!(h["axial_bearings"]["pinion"]["bearing"], "elastic");
    assert_eq!(h["axial_bearings"]["gear"]["bearing"], "rigid");
    // The rigid gear bearing carries the mesh's axial force on the gear, the opposite of
    // the pinion's.
    let mean_p = bearing(h, "pinion", "reaction_mean_n");
    let mean_g = bearing(h, "gear", "reaction_mean_n");
    assert!(
        (mean_p + mean_g).abs() <= 1e-3 * mean_p.abs(),
        "{mean_p} {mean_g}"
    );
    let ts = std::fs::read_to_string(out.join("timeseries.csv")).unwrap();
    let header = ts.lines().next().unwrap();
    assert!(
        header.contains("z_pinion_m") && !header.contains("z_gear_m"),
        "{header}"
    );
    // A spur pair: the key changes nothing, with a warning naming it.
    let spur = d.path().join("s");
    let o = gearwear(&[
        "dynamics",
        "--out",
        spur.to_str().unwrap(),
        "--set",
        STIFF[0],
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("dynamics.bearing_axial_stiffness_pinion_n_per_m"),
        "{err}"
    );
    let ts = std::fs::read_to_string(spur.join("timeseries.csv")).unwrap();
    assert!(!ts.lines().next().unwrap().contains("z_pinion"));
}

#[test]
fn the_helical_wear_runs_with_axial_degrees_of_freedom() {
    // `gearwear wear` builds the same model: its dynamic mode's steady states carry the
    // axial coordinates (20 states) and wear the pair; the first update's wear differs
    // from the planar model's by less than the axial compliance's share (1 %: the mesh
    // sees a 2 k_m tan^2(beta_b) / k_a = 1e-2 softer spring at 5e8 N/m, its loads the
    // same in the mean).
    let base = ["gear.helix_angle_deg=15", "wear.total_cycles=2e4"];
    let sets = with(&base, &STIFF);
    let m = model_of(&sets);
    assert_eq!(m.state_len(), 20);
    let axial = run_wear(&m, WearRun::new(WearMode::Dynamic), &mut |_| Ok(())).expect("wear");
    let planar = run_wear(
        &helical(&base),
        WearRun::new(WearMode::Dynamic),
        &mut |_| Ok(()),
    )
    .expect("wear");
    let (a, p) = (
        axial.records.last().unwrap(),
        planar.records.last().unwrap(),
    );
    assert_eq!(a.end_state.as_ref().map(Vec::len), Some(20));
    let (wa, wp) = (a.wear.max_pinion_m(), p.wear.max_pinion_m());
    eprintln!("wear max pinion: axial {wa:.4e} m, planar {wp:.4e} m");
    // Above 1e-9: the axial coordinates couple (equal wear would mean no coupling).
    let rel = (wa / wp - 1.0).abs();
    assert!(wa > 0.0 && rel < 1e-2 && rel > 1e-9, "{wa} {wp}: {rel}");
}

#[test]
fn an_axial_shift_beyond_a_few_percent_of_the_face_is_warned() {
    // Statics: a pinion on an axial spring k_a under F_a = F_t tan(beta) (~0.8 kN for the
    // built-in load at 15 deg) shifts by F_a / k_a against the rigidly held gear: 82 mm
    // at 1e4 N/m, 4 times the 20 mm face (warned), 1.6 um at 5e8 N/m (not).
    let base = ["gear.helix_angle_deg=15"];
    let soft = model_of(&with(
        &base,
        &["dynamics.bearing_axial_stiffness_pinion_n_per_m=1e4"],
    ));
    let w = gearwear::study::helical_dynamics::axial_shift_warning(&soft, &steady(&soft));
    let w = w.expect("a shift of 4 face widths is warned");
    assert!(w.contains("dynamics.bearing_axial_stiffness_"), "{w}");
    let stiff = model_of(&with(&base, &STIFF));
    let none = gearwear::study::helical_dynamics::axial_shift_warning(&stiff, &steady(&stiff));
    assert_eq!(none, None);
    // A planar model has no axial coordinates to warn of.
    let planar = helical(&base);
    assert_eq!(
        gearwear::study::helical_dynamics::axial_shift_warning(&planar, &steady(&planar)),
        None
    );
}
