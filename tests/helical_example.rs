//! examples/helical_pair.toml, the README's helical pair: it is the paper's pair apart
//! from its helix, hand, crowning and contact path (compared with the built-in case
//! given those keys), the README names it, and the commands in its header run on it,
//! with what a symmetric crowning implies of their results.

mod common;

use gearwear::config::load_case;
use std::path::{Path, PathBuf};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/helical_pair.toml")
}

#[test]
fn the_example_is_the_papers_pair_with_a_crowned_15_degree_helix() {
    let text = std::fs::read_to_string(example()).unwrap();
    let file = load_case(&text, &[]).expect("the example loads");
    let sets: Vec<String> = [
        "gear.helix_angle_deg=15",
        "gear.helix_hand_pinion=\"right\"",
        "modification.crowning_um=10",
        "contact.path=\"nominal\"",
    ]
    .map(String::from)
    .to_vec();
    let by_hand = load_case("", &sets).expect("the built-in case with the keys");
    assert_eq!(file, by_hand);
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    assert!(readme.contains("examples/helical_pair.toml"));
}

#[test]
fn the_commands_of_its_header_run_and_the_crowned_load_is_centred() {
    // Every `#   gearwear ...` line of the example's header, run in a fresh folder.
    let text = std::fs::read_to_string(example()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let mut ran = Vec::new();
    for line in text.lines().filter_map(|l| l.strip_prefix("#   gearwear ")) {
        // The example from the repository, each output folder in `dir`.
        let args: Vec<String> = line
            .split_whitespace()
            .map(|w| match w {
                "examples/helical_pair.toml" => example().to_string_lossy().into_owned(),
                _ if w.starts_with("helical_") => dir.path().join(w).to_string_lossy().into_owned(),
                _ => w.to_owned(),
            })
            .collect();
        let mut a = vec!["-q"];
        a.extend(args.iter().map(String::as_str));
        common::ok(&a);
        ran.push(args[0].clone());
    }
    assert_eq!(ran, ["stiffness", "dynamics", "wear", "sweep"]);
    let json = |p: &str| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(dir.path().join(p)).unwrap()).unwrap()
    };
    // A crowning symmetric about the face centre on an unmodified, aligned pair loads the
    // face symmetrically: the centre of pressure is at b/2 = 10 mm. Over a mesh period the
    // contact lines' stagger breaks the symmetry at each instant, so the static and the
    // dynamic mean centres are within 1 % of b of it (measured 10.000 and 10.010 mm), and
    // the crowning gives K_Hbeta > 1 (peak over mean).
    let s = json("helical_stiffness/summary.json");
    let d = json("helical_dynamics/summary.json");
    for (what, f) in [("static", &s["face_load"]), ("dynamic", &d["face_load"])] {
        let c = f["centre_of_pressure_mm"].as_f64().unwrap();
        assert!((c - 10.0).abs() < 0.2, "{what}: {c}");
        assert!(f["k_h_beta"].as_f64().unwrap() > 1.0, "{what}: {f}");
    }
    // The sweep's row at 15 deg is the dynamics study's case: the same K_Hbeta.
    let (h, rows) = common::read_csv(&dir.path().join("helical_sweep/sweep.csv"));
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    let row = rows.iter().find(|r| r[0] == "15").expect("a row at 15 deg");
    let k: f64 = row[col("k_h_beta")].parse().unwrap();
    assert_eq!(k, d["face_load"]["k_h_beta"].as_f64().unwrap());
    assert!(dir
        .path()
        .join("helical_wear/wear_map_dynamic.png")
        .exists());
}
