//! Lead modifications and misalignment through the case file (`[modification]`
//! crowning_um, end_relief_*, helix_slope_deviation_um; `operating.misalignment_*`):
//! `gearwear stiffness` writes the face load distribution (docs/MODEL.md 11.2); zero gaps
//! change nothing of the spur study; the statics of the slice springs; bad inputs exit 2;
//! the studies without a gap across the face refuse the keys.

mod common;

use common::{gearwear, read_csv, rejected, stderr};
use std::path::Path;

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

/// `gearwear stiffness` into `dir`; returns its stderr.
fn stiffness(dir: &Path, sets: &[&str]) -> String {
    let mut args = vec!["stiffness", "--out", dir.to_str().unwrap()];
    for s in sets {
        args.extend(["--set", s]);
    }
    let o = gearwear(&args);
    assert_eq!(o.status.code(), Some(0), "{sets:?}: {}", stderr(&o));
    stderr(&o)
}

/// A column of `face_load.csv` as numbers.
fn column(dir: &Path, name: &str) -> Vec<f64> {
    let (h, rows) = read_csv(&dir.join("face_load.csv"));
    let i = h.iter().position(|c| c == name).expect(name);
    rows.iter().map(|r| r[i].parse().unwrap()).collect()
}

#[test]
fn zero_gaps_leave_the_spur_study_unchanged_with_a_uniform_face_load() {
    let d = tempfile::tempdir().unwrap();
    let (plain, zero) = (d.path().join("plain"), d.path().join("zero"));
    stiffness(&plain, &[]);
    stiffness(
        &zero,
        &[
            "modification.crowning_um=0",
            "operating.misalignment_um=0",
            "stiffness.slices=10",
        ],
    );
    for f in ["mesh_stiffness.csv", "pair_load.csv"] {
        assert!(
            std::fs::read(plain.join(f)).unwrap() == std::fs::read(zero.join(f)).unwrap(),
            "{f} differs"
        );
    }
    assert!(!plain.join("face_load.csv").exists());
    // Every slice of a spur pair alike, no gap: w = F/b everywhere (rounding: 1e-12).
    let fl = &summary(&zero)["face_load"];
    assert!((fl["k_h_beta"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    let w_m = fl["mean_load_per_width_n_per_mm"].as_f64().unwrap();
    for w in column(&zero, "load_per_width_mean_n_per_mm") {
        assert!((w - w_m).abs() < 1e-12 * w_m);
    }
}

#[test]
fn a_symmetric_crowning_centres_the_load_with_its_peak_at_mid_face() {
    // A spur pair: its slices are alike at every mesh position, the crowning symmetric,
    // so the load is symmetric about b/2 (rounding: 1e-9 of b) and largest where the gap
    // is 0, at the middle (N odd: the middle slice).
    let d = tempfile::tempdir().unwrap();
    stiffness(
        d.path(),
        &["modification.crowning_um=20", "stiffness.slices=41"],
    );
    let fl = &summary(d.path())["face_load"];
    let b = fl["face_width_mm"].as_f64().unwrap();
    let c = fl["centre_of_pressure_mm"].as_f64().unwrap();
    assert!((c - b / 2.0).abs() < 1e-9 * b, "{c}");
    assert!(fl["k_h_beta"].as_f64().unwrap() > 1.0);
    let w = column(d.path(), "load_per_width_mean_n_per_mm");
    let peak = w.iter().cloned().fold(0.0, f64::max);
    assert_eq!(w[20], peak);
    let gap = column(d.path(), "gap_um");
    assert_eq!(gap[20], 0.0);
}

#[test]
fn a_misalignment_moves_the_centre_of_pressure_as_hand_statics_predicts() {
    // Spur pair, N slices of equal stiffness k'(phi) b / N, gap s y (s b = the
    // misalignment), full contact: w(y) = w_m + k'(phi) s (b/2 - y) (tests_face_load.rs
    // derives it), so over a period the centre moves from b/2 by
    //   -k'_bar s b^2 (1 - 1/N^2) / (12 w_m)
    // and K_Hbeta = 1 + k'_bar s (b/2 - b/(2N)) / w_m. k'_bar is taken here as the mean
    // mesh stiffness over b (exact for its spline); the study averages 72 positions of a
    // stiffness that jumps where pairs enter, a rectangle-rule error near 1 %: 2 %
    // allowed. The helix slope deviation is the same linear gap: the same numbers.
    let d = tempfile::tempdir().unwrap();
    let (mis, slope) = (d.path().join("mis"), d.path().join("slope"));
    stiffness(
        &mis,
        &["operating.misalignment_um=5", "stiffness.slices=40"],
    );
    stiffness(
        &slope,
        &[
            "modification.helix_slope_deviation_um=5",
            "stiffness.slices=40",
        ],
    );
    let s_all = summary(&mis);
    let fl = &s_all["face_load"];
    assert_eq!(fl, &summary(&slope)["face_load"]);
    assert_eq!(fl["fewest_loaded_slices"], 40, "full contact");
    let b = fl["face_width_mm"].as_f64().unwrap() * 1e-3;
    let w_m = fl["mean_load_per_width_n_per_mm"].as_f64().unwrap() * 1e3;
    let kb = s_all["mesh_stiffness"]["mean_n_per_m"].as_f64().unwrap() / b;
    let s = 5e-6 / b;
    let n = 40.0;
    let shift_hand = -kb * s * b * b * (1.0 - 1.0 / (n * n)) / (12.0 * w_m);
    let shift = fl["centre_of_pressure_mm"].as_f64().unwrap() * 1e-3 - b / 2.0;
    assert!(
        (shift - shift_hand).abs() < 0.02 * shift_hand.abs(),
        "{shift} vs {shift_hand}"
    );
    let k_hand = 1.0 + kb * s * (b / 2.0 - b / (2.0 * n)) / w_m;
    let k = fl["k_h_beta"].as_f64().unwrap();
    assert!(
        (k - k_hand).abs() < 0.02 * (k_hand - 1.0),
        "{k} vs {k_hand}"
    );
    // A misalignment normal to the plane of action opens no gap: warned and ignored.
    let normal = d.path().join("normal");
    let err = stiffness(
        &normal,
        &[
            "operating.misalignment_um=5",
            "operating.misalignment_plane=\"normal\"",
            "stiffness.slices=40",
        ],
    );
    assert!(err.contains("misalignment_plane"), "{err}");
    assert!((summary(&normal)["face_load"]["k_h_beta"].as_f64().unwrap() - 1.0).abs() < 1e-12);
}

#[test]
fn a_helical_case_writes_its_face_load_and_a_crowning_raises_k_h_beta() {
    let d = tempfile::tempdir().unwrap();
    let (plain, crowned) = (d.path().join("plain"), d.path().join("crowned"));
    let helix = ["gear.helix_angle_deg=15", "stiffness.slices=100"];
    stiffness(&plain, &helix);
    stiffness(
        &crowned,
        &[helix[0], helix[1], "modification.crowning_um=20"],
    );
    let k0 = summary(&plain)["face_load"]["k_h_beta"].as_f64().unwrap();
    let k1 = summary(&crowned)["face_load"]["k_h_beta"].as_f64().unwrap();
    assert!(k0 >= 1.0 && k1 > k0, "{k0} {k1}");
    // The gaps leave the mesh stiffness as it is.
    assert!(
        std::fs::read(plain.join("mesh_stiffness.csv")).unwrap()
            == std::fs::read(crowned.join("mesh_stiffness.csv")).unwrap()
    );
    assert!(crowned.join("face_load.png").exists());
}

#[test]
fn bad_lead_inputs_exit_2_naming_key_value_and_range() {
    let st = |sets: &[&str]| {
        let mut a = vec!["stiffness"];
        for s in sets {
            a.extend(["--set", *s]);
        }
        a.into_iter().map(String::from).collect::<Vec<_>>()
    };
    let cases: [(Vec<String>, Vec<&str>); 5] = [
        (
            st(&[
                "modification.crowning_um=900",
                "gear.module_mm=0.3",
                "gear.hub_bore_radius_gear_mm=\"derived\"",
                "gear.hub_bore_radius_pinion_mm=\"derived\"",
            ]),
            vec!["modification.crowning_um", "900", "tooth depth", "[0, 675"],
        ),
        (
            st(&[
                "modification.end_relief_um=5",
                "modification.end_relief_length_mm=11",
            ]),
            vec!["modification.end_relief_length_mm", "11", "(0, 10] mm"],
        ),
        (
            st(&["modification.end_relief_um=5"]),
            vec!["modification.end_relief_length_mm", "both or neither"],
        ),
        (
            st(&["operating.misalignment_um=900", "stiffness.slices=4"]),
            vec![
                "operating.misalignment_um",
                "900",
                "single slice",
                "at most about",
            ],
        ),
        (
            st(&["modification.crowning_um=2000"]),
            vec!["modification.crowning_um", "2000", "[0, 1000]"],
        ),
    ];
    for (args, needles) in &cases {
        let a: Vec<&str> = args.iter().map(String::as_str).collect();
        rejected(&a, needles);
    }
    // No gap across the face in the spur pair's dynamic model and the studies on it:
    // refused there, naming the key (the helical dynamics takes them:
    // tests/helical_lead_dynamics.rs).
    rejected(
        &["dynamics", "--set", "modification.crowning_um=20"],
        &["modification.crowning_um", "gearwear stiffness"],
    );
    rejected(
        &["signals", "--set", "operating.misalignment_um=5"],
        &["operating.misalignment_um", "gearwear stiffness"],
    );
}
