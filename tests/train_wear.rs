//! `gearwear wear` on a gear train (`[[stage]]`): each mesh worn at its own cycle count,
//! checked against the single-pair study run on its own (the built binary), the cycle
//! counts of the tooth numbers, and bad input.

mod common;
use common::{read_csv, rejected};
use std::path::{Path, PathBuf};

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

/// `gearwear wear` of `config` (None: the paper's case) with `sets`, into `dir/name`.
fn wear(dir: &Path, name: &str, config: Option<&str>, mode: &str, sets: &[&str]) -> PathBuf {
    common::run_into(dir, name, &["wear", "--mode", mode], config, sets)
}

/// A column of a CSV as numbers.
fn column(path: &Path, name: &str) -> Vec<f64> {
    let (h, rows) = read_csv(path);
    let i = h
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("{name} in {path:?}"));
    rows.iter().map(|r| r[i].parse().unwrap()).collect()
}

#[test]
fn a_one_stage_train_wears_as_the_single_pair_bit_for_bit() {
    // The paper's pair as a one-stage train, both modes to 2e4 cycles: the same updates
    // and profiles, byte for byte (one mesh, one cycle factor of exactly 1).
    let d = tempfile::tempdir().unwrap();
    let train = write(d.path(), "train.toml", "[[stage]]\n");
    let total = "wear.total_cycles=20000";
    let a = wear(d.path(), "pair", None, "both", &[total]);
    let b = wear(d.path(), "train", Some(&train), "both", &[total]);
    for mode in ["dynamic", "quasi_static"] {
        for (x, y) in [
            (
                format!("updates_{mode}.csv"),
                format!("updates_{mode}_stage1.csv"),
            ),
            (
                format!("wear_profiles_{mode}.csv"),
                format!("wear_profiles_{mode}_stage1.csv"),
            ),
        ] {
            assert_eq!(
                std::fs::read(a.join(&x)).unwrap(),
                std::fs::read(b.join(&y)).unwrap(),
                "{x} vs {y}"
            );
        }
        let h = b.join(format!("wear_history_{mode}.csv"));
        assert_eq!(
            column(&h, "max_wear_pinion_um"),
            column(&a.join(format!("updates_{mode}.csv")), "max_wear_pinion_um")
        );
    }
}

const STAGE2: &str = "module_mm = 2.5\nteeth_pinion = 23\nteeth_gear = 47\nface_width_mm = 25\n";

/// Input speed (Hz) and torque on the input shaft (N m) of the two-stage train.
const INPUT: (f64, f64) = (30.0, 60.0);

fn two_stage(dir: &Path) -> String {
    write(
        dir,
        "train.toml",
        &format!(
            "[operating]\ninput_speed_hz = {}\nload_torque_nm = {}\nload_torque_shaft = \"pinion\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n\n[[stage]]\n{STAGE2}",
            INPUT.0, INPUT.1
        ),
    )
}

/// Blocks of 1e4 input cycles to 4e4, never cut by the threshold (1e6 um): the updates
/// of a mesh fall at fixed multiples of its cycle factor, as they do for its pair alone
/// given blocks and total scaled by the factor.
const BLOCK: f64 = 1e4;
const TOTAL: f64 = 4e4;

/// The two-stage train's wear study in `mode` with [`BLOCK`] and [`TOTAL`], into
/// `dir/train`.
fn two_stage_run(dir: &Path, mode: &str) -> PathBuf {
    let train = two_stage(dir);
    let block = format!("wear.block_cycles={BLOCK}");
    let total = format!("wear.total_cycles={TOTAL}");
    let sets = [block.as_str(), total.as_str(), "wear.threshold_um=1e6"];
    wear(dir, "train", Some(&train), mode, &sets)
}

#[test]
fn in_the_quasi_static_mode_each_mesh_wears_as_its_pair_alone_at_its_own_cycles() {
    let d = tempfile::tempdir().unwrap();
    let t = two_stage_run(d.path(), "quasi-static");
    // Stage k alone: its pair at its pinion's speed and torque (friction-free through the
    // base radii: r_gb / r_pb = z_g / z_p, one module and pressure angle per stage), run
    // for c_k times the input cycles, c_1 = 1, c_2 = 19/31 (the tooth counts).
    let c2 = 19.0 / 31.0;
    let stages = [("", 1.0, INPUT.1), (STAGE2, c2, INPUT.1 / c2)];
    for (k, (gear, c, torque)) in stages.iter().enumerate() {
        let case = write(
            d.path(),
            &format!("pair{k}.toml"),
            &format!(
                "[operating]\ninput_speed_hz = {}\nload_torque_nm = {torque}\nload_torque_shaft = \"pinion\"\n\n[gear]\n{gear}\n[wear]\nblock_cycles = {}\ntotal_cycles = {}\nthreshold_um = 1e6\n",
                INPUT.0 * c,
                BLOCK * c,
                TOTAL * c
            ),
        );
        let p = wear(
            d.path(),
            &format!("pair{k}"),
            Some(&case),
            "quasi-static",
            &[],
        );
        let s = k + 1;
        let alone = p.join("updates_quasi_static.csv");
        let in_train = t.join(format!("updates_quasi_static_stage{s}.csv"));
        let (ca, cb) = (column(&alone, "cycles"), column(&in_train, "cycles"));
        assert_eq!(ca.len(), cb.len(), "stage {s}: updates");
        for (x, y) in ca.iter().zip(&cb) {
            // Cycle counts: c_k n summed against n c_k, a few ulp.
            assert!(
                (x - y).abs() <= 1e-12 * x.max(1.0),
                "stage {s}: cycles {x} vs {y}"
            );
        }
        for col in ["max_wear_pinion_um", "max_wear_gear_um"] {
            let (a, b) = (column(&alone, col), column(&in_train, col));
            for (i, (x, y)) in a.iter().zip(&b).enumerate() {
                // The first block comes from new teeth: the same equilibria, the same
                // wear to round-off (1e-12). Later, worn teeth: the train's quasi-static
                // response samples every mesh at the nodes of the base period (both
                // meshes' events), the pair alone at its own, and the gap and loads are
                // interpolated linearly between samples, so the two drift apart by that
                // interpolation's error: measured 7e-6 relative after three worn
                // updates (stage 1, gear flank), 1e-4 bounds it with room.
                let tol = if i <= 1 { 1e-12 } else { 1e-4 };
                assert!(
                    (x - y).abs() <= tol * x.abs(),
                    "stage {s} {col} update {i}: alone {x} vs train {y}"
                );
            }
        }
    }
}

/// Trapezoid integral of `y` over `x`.
fn integral(x: &[f64], y: &[f64]) -> f64 {
    x.windows(2)
        .zip(y.windows(2))
        .map(|(a, b)| 0.5 * (b[0] + b[1]) * (a[1] - a[0]))
        .sum()
}

#[test]
fn wear_volumes_follow_the_cycle_counts_of_the_tooth_numbers() {
    let d = tempfile::tempdir().unwrap();
    let t = two_stage_run(d.path(), "dynamic");
    // One shaft carries stage 1's gear and stage 2's pinion: equal revolutions, and the
    // input's times 19/31 (tooth counts, not the program's speeds). Different products
    // of the same numbers: 1e-12 relative.
    let h = t.join("wear_history_dynamic.csv");
    let (stage, pin, gear, input) = (
        column(&h, "stage"),
        column(&h, "pinion_cycles"),
        column(&h, "gear_cycles"),
        column(&h, "input_cycles"),
    );
    for i in (0..stage.len()).step_by(2) {
        assert_eq!((stage[i], stage[i + 1]), (1.0, 2.0));
        assert!((gear[i] - pin[i + 1]).abs() <= 1e-12 * pin[i + 1].max(1.0));
        assert!((pin[i + 1] - input[i] * 19.0 / 31.0).abs() <= 1e-12 * input[i].max(1.0));
        assert!(
            (gear[i + 1] - input[i] * 19.0 / 31.0 * 23.0 / 47.0).abs() <= 1e-12 * input[i].max(1.0)
        );
    }
    // Archard over the first block (new teeth, rates held): the volume each flank lost
    // (per unit width, integral of depth along the path) is its volume rate per pinion
    // cycle times its pinion's cycles. So the ratio of the stages' volumes over their
    // volume rates is their cycle ratio 19/31 (up to the CSV's round-trip printing,
    // 1e-12).
    let lost = |s: usize| {
        let p = t.join(format!("wear_profiles_dynamic_stage{s}.csv"));
        let rho = column(&p, "rho1_mm");
        let v = integral(&rho, &column(&p, "wear_pinion_um_u1"));
        let rate = integral(&rho, &column(&p, "rate_pinion_um_per_kcycle_u0")) / 1e3;
        v / rate
    };
    let ratio = lost(2) / lost(1);
    assert!((ratio - 19.0 / 31.0).abs() <= 1e-12, "{ratio}");
    // The summary names the mesh with the deepest wear as the one that limits the life.
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(t.join("summary.json")).unwrap()).unwrap();
    let deepest = |m: usize| {
        let f = &v["meshes"][m]["final"]["dynamic"];
        f["max_wear_pinion_um"]
            .as_f64()
            .unwrap()
            .max(f["max_wear_gear_um"].as_f64().unwrap())
    };
    let weakest = if deepest(0) >= deepest(1) { 1 } else { 2 };
    assert_eq!(v["limiting_mesh"]["dynamic"]["stage"], weakest);
}

#[test]
fn bad_wear_keys_and_options_on_a_train_are_refused_naming_them() {
    let d = tempfile::tempdir().unwrap();
    let train = two_stage(d.path());
    for (set, needle) in [
        ("wear.threshold_um=0", "`wear.threshold_um`"),
        ("wear.total_cycles=-5", "`wear.total_cycles`"),
        ("wear.block_cycles=0.5", "`wear.block_cycles`"),
    ] {
        rejected(&["wear", "--config", &train, "--set", set], &[needle]);
    }
    // Resuming from a folder that does not exist, or holds no train checkpoints
    // (tests/train_wear_resume.rs resumes real ones).
    rejected(
        &["wear", "--config", &train, "--resume"],
        &["--resume", "does not exist"],
    );
    let empty = d.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    let o = common::gearwear(&[
        "wear",
        "--config",
        &train,
        "--resume",
        "--out",
        empty.to_str().unwrap(),
    ]);
    let e = common::stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains("no checkpoint") && e.contains("checkpoint_dynamic_stage1.jsonl"),
        "{e}"
    );
}
