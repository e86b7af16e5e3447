//! `gearwear dynamics` on a planetary case (`[planetary]` with `[planetary.lumped]`, or
//! with its values derived from the geometry),
//! checked against independent facts: the mean mesh forces against the static torque
//! split (sun torque / (N r_bs) per sun mesh, the same on each ring mesh by a planet's
//! torque balance), load sharing factors of 1 for equally spaced planets without errors,
//! and Parker & Lin's (2004) phasing rule on the summed sun-mesh force of a sequentially
//! phased set; bad inputs exit 2 naming the key.

mod common;

use common::planetary::{lin_parker_lumped, run_case};
use common::{read_csv, rejected};

/// Carrier torsional support (the output's shaft to the load), N m/rad.
const CARRIER_SHAFT: f64 = 1e6;

/// An in-phase set: 24 / 30 / 84, four planets (z_s / N = 6).
const IN_PHASE: (usize, usize, usize, usize) = (4, 24, 30, 84);
/// A sequentially phased set: 26 / 29 / 84, five planets (z_s / N = 5.2).
const SEQUENTIAL: (usize, usize, usize, usize) = (5, 26, 29, 84);

/// Run `gearwear dynamics` on the set; its output folder (kept alive) and summary.
fn dynamics_of(set: (usize, usize, usize, usize)) -> (tempfile::TempDir, serde_json::Value) {
    let (n, zs, zp, zr) = set;
    dynamics_of_text(&format!(
        "[planetary]\nplanets = {n}\nteeth_sun = {zs}\nteeth_planet = {zp}\nteeth_ring = {zr}\nmodule_mm = 2.0\n{}",
        lin_parker_lumped(CARRIER_SHAFT)
    ))
}

/// Run `gearwear dynamics` on the case `text`; its output folder (kept alive) and summary.
fn dynamics_of_text(text: &str) -> (tempfile::TempDir, serde_json::Value) {
    run_case("dynamics", text)
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The sun's base radius, m: m z_s cos(20 deg) / 2 (standard gears, module 2 mm).
fn sun_base_radius_m(zs: usize) -> f64 {
    2e-3 * zs as f64 * 20f64.to_radians().cos() / 2.0
}

#[test]
fn mean_mesh_forces_are_the_static_torque_split_and_planets_share_equally() {
    for set in [IN_PHASE, SEQUENTIAL] {
        let (_d, s) = dynamics_of(set);
        check_static_split(&s, set);
    }
}

#[test]
fn the_default_set_with_every_lumped_value_derived_balances_and_shares_equally() {
    // `[planetary]` alone (24 / 30 / 84, four planets, module 2: IN_PHASE): masses,
    // inertias and supports derived from the geometry (docs/MODEL.md 12.4).
    let (_d, s) = dynamics_of_text("[planetary]\n");
    check_static_split(&s, IN_PHASE);
    let derived = s["planetary_dynamics"]["lumped_parameters"]["derived_keys"]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(derived, 22, "every key of [planetary.lumped] derived");
}

/// The mean mesh forces of `s` (the summary of a run of `set` at the default 60 N m, sun
/// in) are the static torque split, and the planets share equally.
fn check_static_split(s: &serde_json::Value, set: (usize, usize, usize, usize)) {
    let p = &s["planetary_dynamics"];
    let (n, zs, _, _) = set;
    // Sun in at the case's 60 N m: every sun mesh carries 60 / (N r_bs) on average
    // (the sun's mean acceleration over a steady period is zero), and every ring
    // mesh the same (a planet's torque balance: r_bp (F_s - F_r) has zero mean).
    let want = 60.0 / (n as f64 * sun_base_radius_m(zs));
    // The means are integrated between recorded samples with a midpoint rule whose
    // error is at most 2e-5 of the mean (a stiffness jump times half a sub-interval),
    // plus the integration's 1e-5 local tolerance: 1e-4 relative.
    for m in p["meshes"].as_array().unwrap() {
        let got = f(&m["mean_force_n"]);
        assert!(
            (got / want - 1.0).abs() < 1e-4,
            "{}: {got} vs {want}",
            m["mesh"]
        );
        assert!(f(&m["max_force_n"]) >= got, "{m}");
    }
    // Identical, equally spaced planets without errors: each carries 1/N (same
    // tolerance, the factors are ratios of those means).
    for l in p["load_sharing_factor"].as_array().unwrap() {
        assert!((f(l) - 1.0).abs() < 1e-4, "{set:?}: {l}");
    }
    assert!(f(&p["dynamic_factor_sun_planet"]) >= 1.0);
    // The recorded period is a period: integrated from the search's last start, its
    // end state equals its start within the case's steady-state tolerance (1e-6 of
    // the state's scales, `numerics.steady_state_tolerance`).
    assert!(f(&p["periodicity"]) < 1e-6, "{set:?}: {}", p["periodicity"]);
}

/// |h-th DFT coefficient| / samples of `x` (one period).
fn harmonic(x: &[f64], h: usize) -> f64 {
    let n = x.len() as f64;
    let (mut re, mut im) = (0.0, 0.0);
    for (k, v) in x.iter().enumerate() {
        let a = 2.0 * std::f64::consts::PI * (h * k) as f64 / n;
        re += v * a.cos();
        im -= v * a.sin();
    }
    re.hypot(im) / n
}

#[test]
fn sequential_phasing_cancels_the_net_sun_force_harmonics_not_multiple_of_n() {
    // Parker & Lin (2004): with equally spaced, identical planets each planet's steady
    // response is planet 1's delayed by its phase gamma_n = frac(z_s psi_n / 2 pi) (the
    // set's cyclic symmetry), so the sum of the sun meshes' forces (the net torque on the
    // sun over r_bs) keeps only the harmonics h with h z_s / N whole: for 26 / 5 the
    // multiples of 5, where the N meshes add in phase (sum = N x one mesh's).
    let (d, _) = dynamics_of(SEQUENTIAL);
    let (names, rows) = read_csv(&d.path().join("out/mesh_forces.csv"));
    let col = |name: &str| -> Vec<f64> {
        let j = names.iter().position(|c| c == name).unwrap();
        rows.iter().map(|r| r[j].parse().unwrap()).collect()
    };
    let meshes: Vec<Vec<f64>> = (1..=5)
        .map(|p| col(&format!("sun_planet_{p}_force_n")))
        .collect();
    let sum: Vec<f64> = (0..rows.len())
        .map(|k| meshes.iter().map(|m| m[k]).sum())
        .collect();
    let mean = harmonic(&sum, 0);
    // The residual is the integration error (local tolerance 1e-5 of the state's scale,
    // so ~1e-5 of the force) that the cyclic shift does not repeat exactly: 1e-4 of the
    // summed mean force leaves a margin of 10 and is below every one-mesh harmonic
    // h = 1..10 of this set (~0.3 to 6 N, i.e. > 1.2e-4 of the 2456 N sum).
    let tol = 1e-4 * mean;
    for h in 1..=10 {
        let one = harmonic(&meshes[0], h);
        let all = harmonic(&sum, h);
        if h % 5 == 0 {
            assert!((all - 5.0 * one).abs() < tol, "h = {h}: {all} vs 5 x {one}");
        } else {
            assert!(all < tol, "h = {h}: {all} should cancel ({one} per mesh)");
            assert!(one > tol, "h = {h}: one mesh's {one} too small to test");
        }
    }
}

#[test]
fn bad_planetary_dynamics_inputs_exit_2_naming_the_key() {
    let d = tempfile::tempdir().unwrap();
    let case = |text: &str| {
        let p = d.path().join("case.toml");
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_owned()
    };
    let set = "[planetary]\nplanets = 4\n";
    // One key out of its range in an otherwise derived table.
    let negative = case(&format!("{set}[planetary.lumped]\nmass_ring_kg = -2\n"));
    rejected(
        &["dynamics", "--config", &negative],
        &["planetary.lumped.mass_ring_kg", "-2", "(0, 1e6]"],
    );
    let free_output = case(&format!("{set}{}", lin_parker_lumped(0.0)));
    rejected(
        &["dynamics", "--config", &free_output],
        &[
            "planetary.lumped.torsional_stiffness_carrier_nm_per_rad",
            "= 0",
            "output",
        ],
    );
    let te = case(&format!("{set}{}", lin_parker_lumped(CARRIER_SHAFT)));
    rejected(
        &[
            "dynamics",
            "--config",
            &te,
            "--transmission-error",
            "/nonexistent.csv",
        ],
        &["planetary"],
    );
}
