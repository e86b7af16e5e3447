//! Helical pairs through the case file (`gear.helix_angle_deg`, `gear.helix_hand_pinion`,
//! `stiffness.slices`): `gearwear stiffness` writes the slice model's results, a helix
//! angle of 0 is the spur pair whatever the hand and slice count, and every study built on
//! the planar dynamic model but `gearwear dynamics` refuses a helical case with exit 2.

mod common;

use common::{gearwear, rejected, stderr};
use std::path::Path;

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

fn stiffness(dir: &Path, sets: &[&str]) {
    let mut args = vec!["stiffness", "-q", "--out", dir.to_str().unwrap()];
    for s in sets {
        args.extend(["--set", s]);
    }
    let o = gearwear(&args);
    assert_eq!(o.status.code(), Some(0), "{sets:?}: {}", stderr(&o));
}

#[test]
fn a_zero_helix_angle_is_the_spur_pair_whatever_the_hand_and_slices() {
    let d = tempfile::tempdir().unwrap();
    let (spur, zero) = (d.path().join("spur"), d.path().join("zero"));
    stiffness(&spur, &[]);
    stiffness(
        &zero,
        &[
            "gear.helix_angle_deg=0",
            "gear.helix_hand_pinion=\"left\"",
            "stiffness.slices=7",
        ],
    );
    // The spur study's files, byte for byte: the keys are ignored at 0 deg.
    for f in ["mesh_stiffness.csv", "mesh_stiffness.png"] {
        assert!(
            std::fs::read(spur.join(f)).unwrap() == std::fs::read(zero.join(f)).unwrap(),
            "{f} differs"
        );
    }
    let (a, b) = (summary(&spur), summary(&zero));
    for k in [
        "contact_ratio",
        "mesh_stiffness",
        "quasi_static_te",
        "iso6336",
        "geometry",
    ] {
        assert_eq!(a[k], b[k], "{k}");
    }
    assert!(b.get("helical").is_none(), "{b}");
}

#[test]
fn a_helical_case_reports_the_contact_ratios_of_the_closed_forms() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("h");
    stiffness(&out, &["gear.helix_angle_deg=20"]);
    let s = summary(&out);
    let h = &s["helical"];
    let f = |v: &serde_json::Value| v.as_f64().unwrap();
    // The built-in pair's normal section: m_n = 2 mm, alpha_n = 20 deg, b = 20 mm.
    let (beta, alpha_n, b_mm, mn_mm) = (20f64.to_radians(), 20f64.to_radians(), 20.0, 2.0);
    // Overlap ratio epsilon_beta = b sin(beta) / (pi m_n) (ISO 21771), by hand.
    let eps_beta = b_mm * beta.sin() / (std::f64::consts::PI * mn_mm);
    assert!((f(&h["epsilon_beta"]) - eps_beta).abs() < 1e-12, "{h}");
    // Base helix angle sin(beta_b) = sin(beta) cos(alpha_n).
    let beta_b = (beta.sin() * alpha_n.cos()).asin().to_degrees();
    assert!(
        (f(&h["base_helix_angle_deg"]) - beta_b).abs() < 1e-10,
        "{h}"
    );
    // Transverse contact ratio of the transverse section, by hand: r = z m_t / 2,
    // r_b = r cos(alpha_t), r_a = r + m_n (h_a* = 1, no shift, standard centre distance
    // a = r1 + r2), epsilon_alpha = (sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2)
    // - a sin(alpha_t)) / (pi m_t cos(alpha_t)).
    let mt = mn_mm / beta.cos();
    let at = (alpha_n.tan() / beta.cos()).atan();
    let (r1, r2) = (19.0 * mt / 2.0, 31.0 * mt / 2.0);
    let path = |r: f64| ((r + mn_mm).powi(2) - (r * at.cos()).powi(2)).sqrt();
    let eps_alpha =
        (path(r1) + path(r2) - (r1 + r2) * at.sin()) / (std::f64::consts::PI * mt * at.cos());
    // 1e-9: the program solves the same geometry through its spur section builder.
    assert!(
        (f(&h["epsilon_alpha"]) - eps_alpha).abs() < 1e-9,
        "{h} {eps_alpha}"
    );
    assert!(
        (f(&h["epsilon_gamma"]) - eps_alpha - eps_beta).abs() < 1e-9,
        "{h}"
    );
    // Virtual teeth z_n = z / (cos^2(beta_b) cos(beta)).
    let zn = 19.0 / (beta_b.to_radians().cos().powi(2) * beta.cos());
    assert!((f(&h["virtual_teeth"][0]) - zn).abs() < 1e-9, "{h}");
    assert_eq!(h["slices"], 400);
    // Each slice sweeps the transverse pair's curve, so the slice mean differs from the
    // full-width spur pair's only by the Hertz term on the inclined line (its compliance
    // scaled by 1 / cos(beta_b) = 1.056): softer, by a part of the Hertz share of the
    // compliance (a few per cent at most).
    let mean = f(&s["mesh_stiffness"]["mean_n_per_m"]);
    let spur_mean = f(&s["mesh_stiffness_spur_transverse"]["mean_n_per_m"]);
    let ratio = mean / spur_mean;
    assert!(ratio < 1.0 && ratio > 0.98, "{mean} {spur_mean}");
    // The centre of pressure stays on the face.
    let cop = &s["centre_of_pressure_mm"];
    assert!(f(&cop["min"]) > 0.0 && f(&cop["max"]) < b_mm, "{cop}");
    assert!(f(&s["iso6336"]["c_prime_n_per_mm_um"]) > 0.0, "{s}");
    assert!(out.join("mesh_stiffness.csv").exists() && out.join("mesh_stiffness.png").exists());
}

#[test]
fn studies_on_the_planar_dynamics_refuse_a_helical_case() {
    // `gearwear dynamics` has the planar helical model (tests/helical_dynamics.rs),
    // `gearwear wear` its wear per slice (tests/helical_wear.rs), `gearwear signals` its
    // steady record (tests/helical_signals.rs), `gearwear sweep` both
    // (tests/helical_sweep.rs), `gearwear run` all of them (tests/helical_run.rs), and
    // `dataset`, `calibrate` and `predict` its wear model (tests/helical_dataset.rs): of
    // `studies_on_the_dynamic_model` (tests/common) none is left, and `signals` records a
    // run-up too (tests/helical_transient.rs). What the planar model does not take stands
    // in: Pedrero's load-sharing law (a spur pair's), refused naming the keys.
    rejected(
        &[
            "signals",
            "--set",
            "gear.helix_angle_deg=12.5",
            "--set",
            "contact.load_sharing=pedrero",
        ],
        &["gear.helix_angle_deg", "contact.load_sharing", "pedrero"],
    );
}

#[test]
fn bad_helix_keys_name_the_key_and_the_range() {
    rejected(
        &["stiffness", "--set", "gear.helix_angle_deg=45"],
        &["gear.helix_angle_deg", "[0, 45)"],
    );
    rejected(
        &["stiffness", "--set", "gear.helix_hand_pinion=\"up\""],
        &["gear.helix_hand_pinion", "\"left\""],
    );
    rejected(
        &["stiffness", "--set", "stiffness.slices=0"],
        &["stiffness.slices", "[1, 10000]"],
    );
}
