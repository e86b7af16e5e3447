//! `gearwear signals` on a gear train (`[[stage]]`): the one-stage train against the
//! single pair's record, the mesh lines of a two-stage reducer where the tooth counts
//! and the input speed put them, and a sensor stage the case does not have.

mod common;
use common::{read_csv, rejected};
use std::path::{Path, PathBuf};

const REDUCER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/examples/two_stage_reducer.toml"
);

/// `gearwear signals` of `config` (None: the paper's case) with `sets`, into `dir/name`.
fn signals(dir: &Path, name: &str, config: Option<&str>, sets: &[&str]) -> PathBuf {
    common::run_into(dir, name, &["signals"], config, sets)
}

#[test]
fn a_one_stage_train_records_as_the_single_pair_byte_for_byte() {
    // The paper's pair as a one-stage train: the same steady state (the assembly of one
    // stage is the paper's 8-DOF system, tests/train.rs), the same bearing forces from
    // the same coordinates, so every table of the record is the same bytes.
    let d = tempfile::tempdir().unwrap();
    let train = d.path().join("train.toml");
    std::fs::write(&train, "[[stage]]\n").unwrap();
    let a = signals(d.path(), "pair", None, &[]);
    let b = signals(d.path(), "train", Some(train.to_str().unwrap()), &[]);
    for f in [
        "record.csv",
        "spectrum.csv",
        "bearing_forces.csv",
        "tsa_pinion.csv",
        "tsa_gear.csv",
    ] {
        assert_eq!(
            std::fs::read(a.join(f)).unwrap(),
            std::fs::read(b.join(f)).unwrap(),
            "{f}"
        );
    }
}

/// The amplitude column `col` of a spectrum table, indexed by bin.
fn amplitudes(path: &Path, col: usize) -> Vec<f64> {
    let (_, rows) = read_csv(path);
    rows.iter().map(|r| r[col].parse().unwrap()).collect()
}

#[test]
fn a_stage_two_bearing_sensor_hears_both_meshes_at_z_times_shaft_speed() {
    // examples/two_stage_reducer.toml: input 30 Hz, 19/31 then 23/47. Independent of the
    // model: stage 1 meshes at 19 x 30 = 570 Hz, stage 2 at 23 x 30 x 19 / 31 = 422.90 Hz.
    let d = tempfile::tempdir().unwrap();
    let out = signals(d.path(), "s2", Some(REDUCER), &["signals.sensor_stage=2"]);
    let f_in = 30.0;
    let expected = [19.0 * f_in, 23.0 * f_in * 19.0 / 31.0];
    let spec = out.join("spectrum.csv");
    let (_, rows) = read_csv(&spec);
    let df: f64 = rows[1][0].parse::<f64>().unwrap() - rows[0][0].parse::<f64>().unwrap();
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    // The summary names the sensor stage's mesh and lists every mesh's frequency.
    let meshes = summary["kinematics"]["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 2);
    for (m, f) in meshes.iter().zip(expected) {
        // 1e-12 relative: the same product in another order of operations.
        assert!(
            (m["mesh_hz"].as_f64().unwrap() - f).abs() < 1e-12 * f,
            "{m}"
        );
    }
    assert!((summary["kinematics"]["mesh_hz"].as_f64().unwrap() - expected[1]).abs() < 1e-9);
    for col in [1, 2] {
        let a = amplitudes(&spec, col);
        let mut sorted = a.clone();
        sorted.sort_by(f64::total_cmp);
        let median = sorted[sorted.len() / 2];
        for f in expected {
            // The largest line within 8 bins of the mesh frequency (closer than any
            // shaft sideband: the slowest shaft turns at 30 x 19/31 x 23/47 = 9.0 Hz) lies
            // within one bin of it, and stands far (100x) above the spectrum's median.
            let k = (f / df).round() as usize;
            let peak = (k - 8..=k + 8)
                .max_by(|i, j| a[*i].total_cmp(&a[*j]))
                .unwrap();
            assert!(
                (peak as f64 * df - f).abs() <= df,
                "column {col}: line near {f} Hz at {} Hz",
                peak as f64 * df
            );
            assert!(
                a[peak] > 100.0 * median,
                "column {col}: {} vs {median}",
                a[peak]
            );
        }
    }
}

#[test]
fn a_sensor_stage_the_train_does_not_have_is_refused() {
    rejected(
        &[
            "signals",
            "--config",
            REDUCER,
            "--set",
            "signals.sensor_stage=3",
        ],
        &["signals.sensor_stage", "3", "1 to 2"],
    );
}
