//! `gearwear stiffness` on a gear train (`[[stage]]`): each stage's single-pair study,
//! checked against the single-pair path run on its own (the built binary).

mod common;
use common::{ok, read_csv};
use serde_json::Value;
use std::path::Path;

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

fn summary(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

/// The keys of a single pair's stiffness summary that a train's `meshes` entry repeats.
const PAIR_KEYS: [&str; 6] = [
    "contact_ratio",
    "mesh_stiffness",
    "quasi_static_te",
    "iso6336",
    "mesh_stiffness_other_fillet_setting",
    "geometry",
];

#[test]
fn a_one_stage_train_gives_the_single_pairs_stiffness_exactly() {
    // The paper's pair as a one-stage train: the same numbers, bit for bit (the stage's
    // model is the case's own pair at the case's own operating point).
    let d = tempfile::tempdir().unwrap();
    let train = write(d.path(), "train.toml", "[[stage]]\n");
    let (a, b) = (d.path().join("pair"), d.path().join("train"));
    ok(&["-q", "stiffness", "--out", a.to_str().unwrap()]);
    let stdout = common::gearwear(&[
        "stiffness",
        "--config",
        &train,
        "--out",
        b.to_str().unwrap(),
    ]);
    assert!(stdout.status.success());
    let shown = String::from_utf8_lossy(&stdout.stdout);
    assert!(shown.contains("stage 1 (19/31): contact ratio"), "{shown}");
    assert_eq!(
        std::fs::read(a.join("mesh_stiffness.csv")).unwrap(),
        std::fs::read(b.join("mesh_stiffness_stage1.csv")).unwrap()
    );
    let (sa, sb) = (summary(&a), summary(&b));
    let mesh = &sb["meshes"][0];
    assert_eq!(mesh["stage"], 1);
    assert_eq!(mesh["teeth"], serde_json::json!([19, 31]));
    for k in PAIR_KEYS {
        assert_eq!(sa[k], mesh[k], "{k}");
    }
}

#[test]
fn each_stage_of_a_two_stage_train_is_its_pair_alone_at_its_own_torque() {
    // Stage 2 (23/47, module 2.5) written as a single pair with the torque its pinion
    // carries: the input's 60 N m times stage 1's ratio of base radii, 31/19 (one module
    // and pressure angle: r_b2 / r_b1 = z2 / z1).
    let d = tempfile::tempdir().unwrap();
    let stage2 = "module_mm = 2.5\nteeth_pinion = 23\nteeth_gear = 47\nface_width_mm = 25\n";
    let train = write(
        d.path(),
        "train.toml",
        &format!("[operating]\ninput_speed_hz = 30\nload_torque_nm = 60\nload_torque_shaft = \"pinion\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n\n[[stage]]\n{stage2}"),
    );
    let pair = write(
        d.path(),
        "pair.toml",
        &format!(
            "[operating]\ninput_speed_hz = {}\nload_torque_nm = {}\nload_torque_shaft = \"pinion\"\n\n[gear]\n{stage2}",
            30.0 * 19.0 / 31.0,
            60.0 * 31.0 / 19.0
        ),
    );
    let (a, b) = (d.path().join("pair"), d.path().join("train"));
    ok(&[
        "-q",
        "stiffness",
        "--config",
        &pair,
        "--out",
        a.to_str().unwrap(),
    ]);
    ok(&[
        "-q",
        "stiffness",
        "--config",
        &train,
        "--out",
        b.to_str().unwrap(),
    ]);
    let (sa, sb) = (summary(&a), summary(&b));
    let mesh = &sb["meshes"][1];
    assert_eq!(mesh["stage"], 2);
    // The stiffness does not depend on the operating point: identical.
    for k in ["contact_ratio", "mesh_stiffness", "iso6336", "geometry"] {
        assert_eq!(sa[k], mesh[k], "{k}");
    }
    // The quasi-static TE at the torque through stage 1 (the train's r_b2 / r_b1 against
    // 31/19 written here: a few ulp of the force, 1e-12 relative is ample).
    let (h, ra) = read_csv(&a.join("mesh_stiffness.csv"));
    let (_, rb) = read_csv(&b.join("mesh_stiffness_stage2.csv"));
    let te = h.iter().position(|c| c == "quasi_static_te_um").unwrap();
    assert_eq!(ra.len(), rb.len());
    for (x, y) in ra.iter().zip(&rb) {
        let (x, y): (f64, f64) = (x[te].parse().unwrap(), y[te].parse().unwrap());
        assert!((x - y).abs() <= 1e-12 * x.abs().max(1e-9), "{x} vs {y}");
    }
    // Stage 1 is the paper's pair: its mean stiffness is the single pair's.
    assert_eq!(
        sb["meshes"][0]["mesh_stiffness"]["mean_n_per_m"],
        summary_of_paper(d.path())["mesh_stiffness"]["mean_n_per_m"]
    );
    assert!(
        b.join("mesh_stiffness_stage1.png").exists()
            && b.join("mesh_stiffness_stage2.png").exists()
    );
}

fn summary_of_paper(dir: &Path) -> Value {
    let p = dir.join("paper");
    ok(&["-q", "stiffness", "--out", p.to_str().unwrap()]);
    summary(&p)
}
