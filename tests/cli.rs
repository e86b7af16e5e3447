//! The command line as a user meets it: promised files and keys, and every class of bad
//! input answered with a message naming the key and value, exit code 2, and no output.

use std::path::Path;
mod common;

use common::{gearwear, rejected as assert_rejected, stderr};

#[test]
fn bad_inputs_exit_with_code_2_and_a_clear_message() {
    // Unknown key: names it and the valid keys of its section.
    assert_rejected(
        &["stiffness", "--set", "operating.speed=3"],
        &["operating.speed", "operating.input_speed_hz"],
    );
    // Wrong type.
    assert_rejected(
        &["stiffness", "--set", "gear.module_mm=\"two\""],
        &["gear.module_mm", "a number in [0.1, 50]"],
    );
    // Out of range / non-physical.
    assert_rejected(
        &["dynamics", "--set", "dynamics.mass_pinion_kg=0"],
        &["dynamics.mass_pinion_kg", "0"],
    );
    assert_rejected(
        &["dynamics", "--set", "gear.face_width_mm=-20"],
        &["gear.face_width_mm", "-20"],
    );
    assert_rejected(
        &[
            "dynamics",
            "--set",
            "dynamics.bearing_stiffness_gear_n_per_m=-5e8",
        ],
        &["dynamics.bearing_stiffness_gear_n_per_m"],
    );
    assert_rejected(
        &["wear", "--set", "wear.coefficient_m2_per_n=-1e-16"],
        &["wear.coefficient_m2_per_n", "[0, 1e-11]"],
    );
    // Viscosity of 1 cP or less with the Xu model.
    assert_rejected(
        &["dynamics", "--set", "lubricant.viscosity_cp=1"],
        &["lubricant.viscosity_cp", "> 1"],
    );
    // Contact ratio below 1.
    assert_rejected(
        &[
            "stiffness",
            "--set",
            "gear.addendum_coefficient=0.5",
            "--set",
            "gear.teeth_pinion=12",
            "--set",
            "gear.teeth_gear=13",
        ],
        &["contact ratio"],
    );
    // Tip interference.
    assert_rejected(
        &[
            "stiffness",
            "--set",
            "gear.teeth_pinion=8",
            "--set",
            "gear.teeth_gear=60",
        ],
        &["interference"],
    );
    // Several problems at once: one message each.
    let o = gearwear(&[
        "stiffness",
        "--set",
        "gear.module_mm=-1",
        "--set",
        "wear.total_cycles=0",
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        err.contains("gear.module_mm") && err.contains("wear.total_cycles"),
        "{err}"
    );
    // A missing case file.
    assert_rejected(
        &["stiffness", "--config", "/nonexistent/case.toml"],
        &["/nonexistent/case.toml"],
    );
    // A malformed transmission-error file.
    let dir = tempfile::tempdir().unwrap();
    let te = dir.path().join("te.csv");
    std::fs::write(&te, "angle,err\n1,2\n").unwrap();
    assert_rejected(
        &["dynamics", "--transmission-error", te.to_str().unwrap()],
        &["pinion_angle_deg,error_um"],
    );
}

#[test]
fn undercut_is_a_warning_not_an_error() {
    // 14 teeth on a 20 deg rack without shift is undercut (z_min = 2/sin^2(20 deg) = 17)
    // but meshes with 20 teeth without interference. (Both teeth lie outside Sainsot's
    // fillet-foundation fit, theta_f > 0.12 rad: extrapolated knowingly here.)
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s");
    let o = gearwear(&[
        "stiffness",
        "--set",
        "gear.teeth_pinion=14",
        "--set",
        "gear.teeth_gear=20",
        "--set",
        "stiffness.allow_fillet_extrapolation=true",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("warning") && stderr(&o).contains("undercut"));
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn finite_numbers_only(v: &serde_json::Value) -> bool {
    match v {
        serde_json::Value::Null => false,
        serde_json::Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        serde_json::Value::Array(a) => a.iter().all(finite_numbers_only),
        serde_json::Value::Object(o) => o.values().all(finite_numbers_only),
        _ => true,
    }
}

#[test]
fn stiffness_command_writes_the_promised_files_and_keys() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s");
    let o = gearwear(&["stiffness", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in ["summary.json", "mesh_stiffness.csv", "mesh_stiffness.png"] {
        assert!(out.join(f).exists(), "{f} missing");
    }
    let s = json(&out.join("summary.json"));
    for p in [
        "/contact_ratio",
        "/mesh_stiffness/min_n_per_m",
        "/mesh_stiffness/max_n_per_m",
        "/mesh_stiffness/mean_n_per_m",
        "/iso6336/c_prime_n_per_mm_um",
        "/iso6336/c_gamma_alpha_n_per_mm_um",
        "/quasi_static_te/min_um",
        "/quasi_static_te/max_um",
        "/metadata/version",
        "/metadata/case_sha256",
        "/metadata/case/gear/module_mm",
    ] {
        assert!(s.pointer(p).is_some(), "{p} missing");
    }
    assert!((s["contact_ratio"].as_f64().unwrap() - 1.6022).abs() < 5e-4);
    let mut no_meta = s.clone();
    no_meta.as_object_mut().unwrap().remove("metadata");
    assert!(finite_numbers_only(&no_meta));
}

#[test]
fn same_case_gives_the_same_numbers_every_time() {
    // Determinism: two runs write identical summaries.
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a");
    let b = dir.path().join("b");
    for d in [&a, &b] {
        let o = gearwear(&["dynamics", "--out", d.to_str().unwrap()]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let (mut x, mut y) = (json(&a.join("summary.json")), json(&b.join("summary.json")));
    x.as_object_mut().unwrap().remove("metadata");
    y.as_object_mut().unwrap().remove("metadata");
    assert_eq!(x, y);
    assert!(finite_numbers_only(&x));
}

#[test]
fn config_reference_in_docs_is_current() {
    // docs/CONFIG.md is generated from the schema; a stale copy fails here.
    let o = gearwear(&["config", "--markdown"]);
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/CONFIG.md"))
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        doc,
        "regenerate: gearwear config --markdown > docs/CONFIG.md"
    );
}

#[test]
fn run_on_a_reduced_case_writes_every_promised_file_with_finite_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r");
    let o = gearwear(&[
        "run",
        "--set",
        "wear.total_cycles=6000",
        "--set",
        "numerics.evaluated_mesh_periods=4",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let figs = [
        "fig02_mesh_stiffness",
        "fig04_dte",
        "fig05_velocity_y_pinion",
        "fig06_spectrum",
        "fig07_mesh_harmonics",
        "fig08_mesh_force",
        "fig09_friction_coefficient",
        "fig10_friction_force",
        "fig11_force_and_wear_initial",
        "fig12_wear_rate_evolution",
        "fig13_max_accumulated_wear",
        "worn_profiles_dynamic",
        "worn_profiles_quasi_static",
    ];
    for f in figs {
        assert!(out.join(format!("{f}.png")).exists(), "{f}.png missing");
        assert!(
            out.join("csv").join(format!("{f}.csv")).exists(),
            "{f}.csv missing"
        );
    }
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert_eq!(html.matches("data:image/png;base64,").count(), figs.len());
    // No paragraph or table cell of prose (over 80 characters) is said twice: the
    // comparison's explanations, shared by the three wear states, are written once.
    let mut seen = std::collections::HashSet::new();
    for tag in ["p", "td"] {
        for piece in html.split(&format!("<{tag}")).skip(1) {
            let body = piece.split_once('>').map_or("", |x| x.1);
            let text = body.split(&format!("</{tag}>")).next().unwrap_or("");
            if text.len() > 80 && !text.contains('<') {
                assert!(seen.insert(text.to_string()), "said twice: {text}");
            }
        }
    }
    assert!(seen.len() > 5, "the report's prose was not found");
    // The micrometre is spelled µm in the report and the headline (names keep `_um`).
    for (what, text) in [
        ("report.html", html.as_str()),
        ("headline", &*String::from_utf8_lossy(&o.stdout)),
    ] {
        assert!(
            !text.contains(" um") && !text.contains("(um)"),
            "{what} spells um"
        );
    }
    assert!(html.contains(" µm"));
    let mut s = json(&out.join("summary.json"));
    s.as_object_mut().unwrap().remove("metadata");
    assert!(finite_numbers_only(&s), "non-finite number in summary.json");
    for k in [
        "/paper_comparison/dte_max_um_at_0.5um_wear/ours",
        "/paper_comparison/ratio_max_wear_dynamic_to_static/paper",
        "/paper_comparison/mesh_force_mean_n_at_1um_wear/relative_deviation",
    ] {
        assert!(s.pointer(k).is_some(), "{k} missing");
    }
}

#[test]
fn wear_resume_from_a_truncated_checkpoint_reaches_the_same_numbers() {
    // Simulate a kill after the second update: keep only the first records of the
    // checkpoint, resume, and compare with the uninterrupted run.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("w");
    let o = out.to_str().unwrap();
    let args = [
        "wear",
        "--mode",
        "dynamic",
        "--set",
        "wear.total_cycles=1.5e4",
        "--out",
        o,
    ];
    assert!(gearwear(&args).status.success());
    let full = json(&out.join("summary.json"));
    // The checkpoint is a log, a header line and one line per update: keep the header
    // and two updates, plus half of the third line, as a kill during a write leaves it.
    let ck = out.join("checkpoint_dynamic.jsonl");
    let text = std::fs::read_to_string(&ck).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() > 4);
    let cut = format!(
        "{}\n{}\n{}\n{}",
        lines[0],
        lines[1],
        lines[2],
        &lines[3][..lines[3].len() / 2]
    );
    std::fs::write(&ck, cut).unwrap();
    let mut resumed_args = args.to_vec();
    resumed_args.push("--resume");
    assert!(gearwear(&resumed_args).status.success());
    let resumed = json(&out.join("summary.json"));
    for k in ["cycles", "max_wear_pinion_um", "max_wear_gear_um"] {
        assert_eq!(full[k], resumed[k], "{k}");
    }
    // A checkpoint of another case is refused.
    let o2 = gearwear(&[
        "wear",
        "--mode",
        "dynamic",
        "--resume",
        "--set",
        "wear.total_cycles=2e4",
        "--out",
        o,
    ]);
    assert_eq!(o2.status.code(), Some(2), "{}", stderr(&o2));
}
