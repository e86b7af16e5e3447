//! `gearwear calibrate`, `predict` and `predict-merge` as a user meets them: every class
//! of bad input answered with exit code 2 and a message naming the row or key, the
//! promised files, and a sharded prediction merged back to the unsharded one.

use std::path::Path;
mod common;

use common::{gearwear, rejected as assert_rejected, stderr};

/// A cheap case: coarser numerics than the paper's defaults (the commands' plumbing is
/// under test here, not the physics) and a prior of k over [k0/2, 2 k0].
const CASE: &str = "[numerics]\nsteps_per_mesh_period = 60\nevaluated_mesh_periods = 2\n\
[wear]\npoints_per_profile = 31\n\
[calibration]\nwear_coefficient_min_m2_per_n = 1.25e-16\nwear_coefficient_max_m2_per_n = 5e-16\n";

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

#[test]
fn bad_inputs_exit_2_naming_the_row_or_key() {
    let d = tempfile::tempdir().unwrap();
    let obs = |name: &str, text: &str| write(d.path(), name, text);
    let cases = [
        (
            obs(
                "neg.csv",
                "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um\n0,0,0.1\n-10,1,0.1\n",
            ),
            vec!["row 2", "negative"],
        ),
        (
            obs("order.csv", "cycles,dte_max_um\n0,17\n2e4,17.1\n1e4,17.2\n"),
            vec!["row 3", "non-decreasing"],
        ),
        (
            obs("name.csv", "cycles,wear_um\n0,0\n1e4,1\n"),
            vec!["unknown column `wear_um`", "max_wear_pinion_um"],
        ),
        (
            obs(
                "nan.csv",
                "cycles,velocity_y_pinion_rms_mm_per_s\n0,1.6\n1e4,inf\n",
            ),
            vec!["row 2", "velocity_y_pinion_rms_mm_per_s", "not finite"],
        ),
        (
            obs("sigma.csv", "cycles,dte_max_um,sigma_dte_max_um\n0,17,-1\n"),
            vec!["row 1", "sigma_dte_max_um"],
        ),
    ];
    for (file, needles) in &cases {
        assert_rejected(&["calibrate", "--observations", file], needles);
    }
    let good = obs("good.csv", "cycles,max_wear_pinion_um\n1e4,1.5\n2e4,3\n");
    // A prior with no support names both keys.
    assert_rejected(
        &[
            "calibrate",
            "--observations",
            &good,
            "--set",
            "calibration.wear_coefficient_min_m2_per_n=1e-15",
            "--set",
            "calibration.wear_coefficient_max_m2_per_n=1e-16",
        ],
        &[
            "calibration.wear_coefficient_min_m2_per_n",
            "calibration.wear_coefficient_max_m2_per_n",
            "no support",
        ],
    );
    assert_rejected(
        &[
            "calibrate",
            "--observations",
            &good,
            "--set",
            "calibration.roughness_scale_min=0",
        ],
        &["calibration.roughness_scale_min"],
    );
    assert_rejected(
        &["calibrate", "--observations", "missing.csv"],
        &["missing.csv"],
    );
    // predict: the flags and the posterior file.
    assert_rejected(
        &["predict", "--limit-um", "-1", "--cycles", "1e5"],
        &["--limit-um"],
    );
    assert_rejected(
        &["predict", "--limit-um", "10", "--cycles", "0"],
        &["--cycles"],
    );
    let post = obs(
        "post.csv",
        "sample,wear_coefficient_m2_per_n\n0,2.5e-16\n1,nan\n",
    );
    assert_rejected(
        &[
            "predict",
            "--posterior",
            &post,
            "--limit-um",
            "10",
            "--cycles",
            "1e5",
        ],
        &["row 2", "wear_coefficient_m2_per_n"],
    );
    assert_rejected(
        &[
            "predict",
            "--limit-um",
            "10",
            "--cycles",
            "1e5",
            "--shard",
            "3/2",
        ],
        &["--shard"],
    );
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn calibrate_then_predict_sharded_and_merged() {
    let d = tempfile::tempdir().unwrap();
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
    let case = write(d.path(), "case.toml", CASE);
    // Wear measurements near what k0 gives (~0.15 um per 1000 cycles).
    let obs = write(
        d.path(),
        "obs.csv",
        "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um,velocity_y_pinion_rms_mm_per_s\n\
         5000,,,1.5\n10000,1.5,0.2,1.45\n15000,,,1.4\n20000,3.0,0.2,1.38\n",
    );
    let o = gearwear(&[
        "calibrate",
        "--config",
        &case,
        "--observations",
        &obs,
        "--out",
        &p("cal"),
        "--samples",
        "300",
        "--check-runs",
        "1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in [
        "posterior_samples.csv",
        "posterior_band.csv",
        "summary.json",
        "posterior.png",
        "posterior_band.png",
        "report.html",
    ] {
        assert!(d.path().join("cal").join(f).exists(), "{f}");
    }
    let s = json(&d.path().join("cal/summary.json"));
    let k = &s["parameters"][0];
    let (lo, med, hi) = (
        k["ci90"][0].as_f64().unwrap(),
        k["median"].as_f64().unwrap(),
        k["ci90"][1].as_f64().unwrap(),
    );
    assert!(1.25e-16 < lo && lo < med && med < hi && hi < 5e-16, "{k}");
    assert_eq!(s["method"], "grid");
    // Wear near what k0 gives: the fit check finds every observation inside its band
    // (the rules' limits at n = 6: 3 outside, 1.8 sigma beyond), and the report says so.
    let fit = &s["fit_check"];
    assert_eq!(fit["observations"], 6, "{fit}");
    assert!(fit["warning"].is_null(), "{fit}");
    assert!(!stderr(&o).contains("does not fit"), "{}", stderr(&o));
    let report = std::fs::read_to_string(d.path().join("cal/report.html")).unwrap();
    assert!(
        report.contains("Fit check: ") && report.contains("consistent with the calibrated model")
    );
    assert_eq!(
        s["observations"][1]["noise"],
        "inferred (Jeffreys prior, marginalised)"
    );

    let post = p("cal/posterior_samples.csv");
    let common = [
        "predict",
        "--config",
        &case,
        "--posterior",
        &post,
        "--limit-um",
        "2.5",
        "--cycles",
        "4e4",
        "--seed",
        "7",
        "--samples",
        "120",
        "--grid-points",
        "21",
        "--check-runs",
        "1",
    ];
    let run = |extra: &[&str]| {
        let mut a: Vec<&str> = common.to_vec();
        a.extend(extra);
        let o = gearwear(&a);
        assert!(o.status.success(), "{}", stderr(&o));
    };
    run(&["--out", &p("whole")]);
    run(&["--out", &p("shards"), "--shard", "1/2"]);
    run(&["--out", &p("shards"), "--shard", "2/2"]);
    let o = gearwear(&["predict-merge", &p("shards"), "--out", &p("merged")]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in [
        "life_samples.csv",
        "fan_wear.csv",
        "fan_vibration.csv",
        "fan_wear.png",
        "life.png",
        "fan_vibration.png",
        "report.html",
        "summary.json",
    ] {
        assert!(d.path().join("whole").join(f).exists(), "{f}");
    }
    // Samples depend on (seed, index) only: the merged shards are the unsharded run.
    for f in ["life_samples.csv", "fan_wear.csv", "fan_vibration.csv"] {
        let a = std::fs::read_to_string(d.path().join("whole").join(f)).unwrap();
        let b = std::fs::read_to_string(d.path().join("merged").join(f)).unwrap();
        assert_eq!(a, b, "{f}");
    }
    let w = json(&d.path().join("whole/summary.json"));
    let m = json(&d.path().join("merged/summary.json"));
    assert_eq!(w["remaining_life_cycles"], m["remaining_life_cycles"]);
    assert!(w["remaining_life_cycles"]["median"].as_f64().unwrap() > 0.0);
    assert!(
        !std::fs::read_to_string(d.path().join("whole/life_samples.csv"))
            .unwrap()
            .contains("NaN")
    );
}

#[test]
fn calibrating_to_data_the_model_cannot_fit_warns_and_says_so_in_the_summary_and_report() {
    // Wear of 3 um already at 2500 cycles and barely more at 20 000 (sigma 0.1 um): a
    // wear law through zero that is about linear in the cycles meets at most one end,
    // whatever the wear coefficient (the prior's largest gives ~1.5 um at 5000 cycles).
    let d = tempfile::tempdir().unwrap();
    let case = write(d.path(), "case.toml", CASE);
    let obs = write(
        d.path(),
        "obs.csv",
        "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um\n\
         2500,3.0,0.1\n5000,3.1,0.1\n10000,3.2,0.1\n20000,3.3,0.1\n",
    );
    let out = d.path().join("cal");
    let o = gearwear(&[
        "calibrate",
        "--config",
        &case,
        "--observations",
        &obs,
        "--out",
        out.to_str().unwrap(),
        "--samples",
        "300",
        "--check-runs",
        "0",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("the model does not fit the observations"),
        "{err}"
    );
    let s = json(&out.join("summary.json"));
    let fit = &s["fit_check"];
    let far = fit["largest_excess_sigma"].as_f64().unwrap();
    assert!(far > fit["excess_limit_sigma"].as_f64().unwrap(), "{fit}");
    assert!(err.contains(&format!("{far:.1} noise sigma")), "{err}");
    assert!(fit["warning"].as_str().unwrap().contains("noise sigma"));
    let report = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(report.contains("Warning: the model does not fit"));
}
