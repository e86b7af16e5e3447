//! Datasets from a study design: shards merged equal the unsharded dataset byte for
//! byte, the same seed gives the same bytes, every label is the value of the study that
//! produced it (per-tooth wear included), the indicator trends are the index's means
//! along each trajectory, a resumed run only computes what is missing, and a dataset
//! over its disk budget is refused before it starts.

mod common;

use common::{gearwear, ok, stderr};
use gearwear::io::input::InputError;
use gearwear::study::dataset::parse_design;
use gearwear::study::dataset::trajectory::run_trajectory;
use gearwear::study::Model;
use std::path::Path;

const DESIGN: &str = r#"
seed = 11
set = ["signals.snr_db=30", "signals.record_length=0.12", "numerics.steps_per_mesh_period=60",
       "stiffness.table_points_per_mesh_period=60", "wear.block_cycles=5e3"]
[run_to_failure]
states = 3
max_cycles = 3e4
wear_limit_um = 2
[operating]
input_speed_hz = [28, 32]
[records]
noise_realisations = 2
[[condition]]
name = "healthy"
[[condition]]
name = "rough"
[condition.case.surface]
roughness_table_rms_um = [0.42, 0.38, 0.30]
"#;

/// The case-file reader of a design that names no case file (never called).
fn no_file(path: &str) -> Result<String, InputError> {
    Err(InputError {
        path: path.into(),
        reason: "none".into(),
    })
}

fn write_design(dir: &Path, text: &str) -> String {
    std::fs::create_dir_all(dir).unwrap();
    let p = dir.join("design.toml");
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

fn dataset(design: &str, out: &Path, extra: &[&str]) -> String {
    let mut a = vec![
        "dataset",
        "--design",
        design,
        "--out",
        out.to_str().unwrap(),
    ];
    a.extend(extra);
    ok(&a)
}

/// Every file of the dataset proper (not manifests, locks or shard summaries), by path.
fn files(root: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for sub in ["signals", "records", "state"] {
        let mut names: Vec<_> = std::fs::read_dir(root.join(sub))
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        for n in names {
            let rel = format!("{sub}/{n}");
            out.push((rel.clone(), std::fs::read(root.join(&rel)).unwrap()));
        }
    }
    for f in [
        "index.parquet",
        "index.csv",
        "metadata.json",
        "indicator_trends.csv",
        "indicator_trends.png",
    ] {
        out.push((f.into(), std::fs::read(root.join(f)).unwrap()));
    }
    out
}

#[test]
fn shards_merge_to_the_unsharded_dataset_and_the_same_seed_gives_the_same_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let design = write_design(dir.path(), DESIGN);
    let whole = dir.path().join("whole");
    dataset(&design, &whole, &[]);
    // Three shards in separate folders (no shared file system), merged.
    let shards: Vec<_> = (1..=3).map(|i| dir.path().join(format!("s{i}"))).collect();
    for (i, s) in shards.iter().enumerate() {
        dataset(&design, s, &["--shard", &format!("{}/3", i + 1)]);
    }
    let merged = dir.path().join("merged");
    let mut a = vec!["dataset-merge"];
    a.extend(shards.iter().map(|s| s.to_str().unwrap()));
    a.extend(["--out", merged.to_str().unwrap()]);
    ok(&a);
    let (fw, fm) = (files(&whole), files(&merged));
    assert_eq!(fw.len(), fm.len());
    // 2 conditions x 3 states x 2 speeds x 2 realisations = 24 records.
    assert_eq!(
        fw.iter().filter(|(p, _)| p.starts_with("signals/")).count(),
        24
    );
    for ((pw, bw), (pm, bm)) in fw.iter().zip(&fm) {
        assert_eq!(pw, pm);
        assert!(
            bw == bm,
            "{pw} differs between the unsharded and the merged dataset"
        );
    }
    // The same design and seed again: the same bytes.
    let again = dir.path().join("again");
    dataset(&design, &again, &[]);
    assert!(files(&again) == fw, "a rerun gave other bytes");
    // Another seed: other noise, the same labels otherwise.
    let other = dir.path().join("other");
    let design2 = write_design(
        &dir.path().join("o"),
        &DESIGN.replace("seed = 11", "seed = 12"),
    );
    dataset(&design2, &other, &[]);
    let sig = |root: &Path| std::fs::read(root.join("signals/0000005.parquet")).unwrap();
    assert_ne!(sig(&other), sig(&whole));
}

#[test]
fn every_label_is_the_value_of_the_study_that_produced_it() {
    let dir = tempfile::tempdir().unwrap();
    let design = write_design(dir.path(), DESIGN);
    let out = dir.path().join("ds");
    dataset(&design, &out, &[]);
    let d = parse_design(DESIGN, "design.toml", &no_file).unwrap();
    let (h, rows) = common::read_csv(&out.join("index.csv"));
    let col = |name: &str| h.iter().position(|x| x == name).unwrap();
    assert_eq!(rows.len(), 24);
    for (c, cond) in d.conditions.iter().enumerate() {
        // The trajectory, run again independently of the dataset job.
        let model = Model::from_case(&cond.case).unwrap();
        let t = run_trajectory(&model, d.max_cycles, d.wear_limit_um * 1e-6).unwrap();
        let states = t.even_states(3);
        for row in rows.iter().filter(|r| r[col("condition")] == cond.name) {
            let id: usize = row[col("record_id")].parse().unwrap();
            // id = (((c x 3 + s) x 2 + v) x 1 + l) x 2 + r.
            let (r, v, s) = (id % 2, (id / 2) % 2, (id / 4) % 3);
            assert_eq!(id / 12, c);
            let num = |k: &str| row[col(k)].parse::<f64>().unwrap();
            assert_eq!(num("cycles"), states[s]);
            let w = t.state_at(states[s]).unwrap();
            assert_eq!(num("max_wear_pinion_um"), w.max_pinion_m() * 1e6);
            assert_eq!(num("max_wear_gear_um"), w.max_gear_m() * 1e6);
            let (rem, censored) = t.remaining(states[s]);
            assert_eq!(num("remaining_cycles"), rem);
            assert_eq!(
                row[col("failure_censored")],
                if censored { "1" } else { "0" }
            );
            assert_eq!(num("input_speed_hz"), d.speeds_hz[v]);
            assert_eq!(num("load_torque_nm"), 60.0);
            assert_eq!(num("realisation") as usize, r);
            assert_eq!(row[col("fault")], cond.fault);
            assert_eq!(num("severity"), cond.severity);
            assert_eq!(num("mesh_hz"), 19.0 * d.speeds_hz[v]);
            assert_eq!(num("sampling_rate_hz"), cond.case.signals.sampling_rate_hz);
        }
    }
    // Every index column has a unit and a meaning in the metadata, and the sensors' place
    // is said in words.
    let m: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("metadata.json")).unwrap()).unwrap();
    for name in &h {
        assert!(m["index_columns"][name].is_string(), "unit of {name}");
        let meaning = m["index_column_meanings"][name].as_str().unwrap_or("-");
        assert!(meaning.len() > 10, "meaning of {name}: {meaning:?}");
    }
    assert!(
        m["record"]["sensor_placement"]
            .as_str()
            .is_some_and(|p| p.contains("bearing housing")),
        "{}",
        m["record"]
    );
}

#[test]
fn a_resumed_dataset_computes_only_what_is_missing() {
    let dir = tempfile::tempdir().unwrap();
    let design = write_design(dir.path(), DESIGN);
    let out = dir.path().join("ds");
    dataset(&design, &out, &[]);
    let before = files(&out);
    // A killed run: two records lost, one signal file damaged.
    std::fs::remove_file(out.join("records/0000003.json")).unwrap();
    std::fs::remove_file(out.join("signals/0000010.parquet")).unwrap();
    std::fs::write(out.join("signals/0000017.parquet"), b"damaged").unwrap();
    let o = gearwear(&[
        "dataset",
        "--design",
        &design,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Records are computed per physical state (both realisations): 3 states, 6 records.
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(said.contains("(6 computed, 18 reused)"), "{said}");
    assert!(files(&out) == before, "the resumed dataset differs");
}

#[test]
fn a_dataset_over_its_disk_budget_or_with_a_bad_design_is_refused_before_it_starts() {
    let dir = tempfile::tempdir().unwrap();
    let big = DESIGN.replace(
        "noise_realisations = 2",
        "noise_realisations = 20000\ndisk_budget_gib = 1",
    );
    let design = write_design(dir.path(), &big);
    let out = dir.path().join("ds");
    let o = gearwear(&[
        "dataset",
        "--design",
        &design,
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("`records.disk_budget_gib` = 1") && err.contains("GiB"),
        "{err}"
    );
    assert!(!out.exists(), "a refused dataset wrote its folder");
    let bad = write_design(
        &dir.path().join("b"),
        "[operating]\ninput_speed_hz = [-3]\n",
    );
    let o = gearwear(&["dataset", "--design", &bad, "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`operating.input_speed_hz`"),
        "{}",
        stderr(&o)
    );
}

/// A tooth-resolved condition: pinion tooth 3 stands 4 um proud (excitation period 19
/// mesh periods), states between the wear loop's updates.
const TEETH_DESIGN: &str = r#"
seed = 5
set = ["signals.record_length=0.12", "numerics.steps_per_mesh_period=60",
       "stiffness.table_points_per_mesh_period=60", "wear.block_cycles=5e3",
       "teeth.pitch_error_pinion_um=[0,0,0,4,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]"]
[run_to_failure]
cycles = [0, 7e3, 1.3e4]
max_cycles = 2e4
wear_limit_um = 50
[records]
noise_realisations = 1
"#;

#[test]
fn per_tooth_wear_labels_are_each_tooths_own_wear_between_updates() {
    let dir = tempfile::tempdir().unwrap();
    let design = write_design(dir.path(), TEETH_DESIGN);
    let out = dir.path().join("ds");
    dataset(&design, &out, &[]);
    let d = parse_design(TEETH_DESIGN, "design.toml", &no_file).unwrap();
    // The wear loop run again independently; between two of its updates each grid point
    // of each tooth wears linearly in cycles (the loop holds the per-cycle wear of the
    // earlier update for the block, paper eq. 17), so the state at c cycles is the
    // interpolation of the two updates' own states.
    let model = Model::from_case(&d.conditions[0].case).unwrap();
    let t = run_trajectory(&model, d.max_cycles, d.wear_limit_um * 1e-6).unwrap();
    let teeth = |i: usize| t.records[i].wear.teeth.clone().expect("per-tooth wear");
    let mut spread = 0.0_f64;
    for (id, &c) in [0.0, 7e3, 1.3e4].iter().enumerate() {
        let text = std::fs::read(out.join(format!("records/{id:07}.json"))).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&text).unwrap();
        let labels = &v["labels"];
        assert_eq!(labels["cycles"].as_f64().unwrap(), c);
        let i = t.records.partition_point(|r| r.wear.cycles <= c) - 1;
        let (c0, c1) = (t.records[i].wear.cycles, t.records[i + 1].wear.cycles);
        let s = (c - c0) / (c1 - c0);
        for (key, gear) in [
            ("wear_pinion_tooth_um", true),
            ("wear_gear_tooth_um", false),
        ] {
            let (a, b) = (teeth(i), teeth(i + 1));
            let (a, b) = if gear {
                (a.pinion_m, b.pinion_m)
            } else {
                (a.gear_m, b.gear_m)
            };
            let got: Vec<f64> = labels[key]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            assert_eq!(got.len(), if gear { 19 } else { 31 });
            for (tooth, (pa, pb)) in a.iter().zip(&b).enumerate() {
                let want = pa
                    .iter()
                    .zip(pb)
                    .map(|(x, y)| x + s * (y - x))
                    .fold(0.0_f64, f64::max)
                    * 1e6;
                // Round-off of the advance (a sum of a few products) only.
                assert!(
                    (got[tooth] - want).abs() <= 1e-9 * want.max(1e-3),
                    "{key}[{tooth}] at {c} cycles: {} against {want}",
                    got[tooth]
                );
            }
            let max = got.iter().fold(0.0_f64, |m, x| m.max(*x));
            let min = got.iter().fold(f64::INFINITY, |m, x| m.min(*x));
            spread = spread.max(max - min);
            let deepest = labels[if gear {
                "max_wear_pinion_um"
            } else {
                "max_wear_gear_um"
            }]
            .as_f64()
            .unwrap();
            assert_eq!(max, deepest);
        }
    }
    // The proud tooth wears unlike its neighbours: the labels are not one value repeated.
    assert!(spread > 0.01, "per-tooth wear spread {spread} um");
}

#[test]
fn indicator_trends_are_the_index_means_along_each_trajectory() {
    let dir = tempfile::tempdir().unwrap();
    let design = write_design(dir.path(), DESIGN);
    let out = dir.path().join("ds");
    dataset(&design, &out, &[]);
    let (h, rows) = common::read_csv(&out.join("index.csv"));
    let col = |name: &str| h.iter().position(|x| x == name).unwrap();
    let (th, trend) = common::read_csv(&out.join("indicator_trends.csv"));
    let tcol = |name: &str| th.iter().position(|x| x == name).unwrap();
    // 2 conditions x 2 speeds, 3 states each.
    assert_eq!(trend.len(), 12);
    let followed = [
        "max_wear_pinion_um",
        "max_wear_gear_um",
        "input_rms",
        "input_kurtosis",
        "input_pinion_fm0",
        "input_pinion_fm4",
        "input_pinion_na4",
        "input_pinion_sideband_level_factor",
    ];
    for (k, t) in trend.iter().enumerate() {
        // The index rows of this condition, speed and state: the 2 noise realisations.
        let members: Vec<&Vec<String>> = rows
            .iter()
            .filter(|r| {
                r[col("condition")] == t[tcol("condition")]
                    && r[col("input_speed_hz")] == t[tcol("input_speed_hz")]
                    && r[col("trajectory_state")] == t[tcol("trajectory_state")]
            })
            .collect();
        assert_eq!(members.len(), 2);
        assert_eq!(t[tcol("realisations")], "2");
        assert_eq!(t[tcol("cycles")], members[0][col("cycles")]);
        for name in followed {
            let mean = members
                .iter()
                .map(|r| r[col(name)].parse::<f64>().unwrap())
                .sum::<f64>()
                / 2.0;
            let got: f64 = t[tcol(name)].parse().unwrap();
            // The same two numbers summed and halved: equal to the last bit or the CSV
            // digits' round trip.
            assert!(
                (got - mean).abs() <= 1e-12 * mean.abs().max(1e-300),
                "{name}, row {k}: {got} against {mean}"
            );
        }
        // States of a trajectory in order of cycles, wear growing along it.
        if k % 3 > 0 {
            let prev = &trend[k - 1];
            assert_eq!(prev[tcol("condition")], t[tcol("condition")]);
            let c = |r: &Vec<String>, n: &str| r[tcol(n)].parse::<f64>().unwrap();
            assert!(c(t, "cycles") > c(prev, "cycles"));
            assert!(c(t, "max_wear_pinion_um") > c(prev, "max_wear_pinion_um"));
        }
    }
    let png = std::fs::read(out.join("indicator_trends.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}
