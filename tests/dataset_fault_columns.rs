//! A dataset's index states the tooth fault each record's model applies (issue 33: a
//! pair's index had only the free-text `fault` and `severity` labels): the count of the
//! case's `[[fault]]` tables, then the first one's gear, tooth, kind and size, each read
//! back against the design's own tables; every record's sidecar holds all of them.

mod common;

use common::ok;

const DESIGN: &str = r#"
seed = 3
set = ["signals.record_length=0.12", "numerics.steps_per_mesh_period=60",
       "stiffness.table_points_per_mesh_period=60"]
[run_to_failure]
cycles = [0]
max_cycles = 1e3
wear_limit_um = 50
[records]
noise_realisations = 1
[[condition]]
name = "healthy"
[[condition]]
name = "cracked"
[[condition.case.fault]]
kind = "crack"
gear = "pinion"
tooth = 3
crack_depth_mm = 1.5
[[condition]]
name = "pitted_and_broken"
[[condition.case.fault]]
kind = "spall"
gear = "gear"
tooth = 7
spall_position_mm = 0.5
spall_length_mm = 1.0
spall_depth_um = 20
[[condition.case.fault]]
kind = "broken_tip"
gear = "pinion"
tooth = 0
removed_height_mm = 0.5
"#;

#[test]
fn the_index_names_each_records_fault_as_its_case_gives_it() {
    let dir = tempfile::tempdir().unwrap();
    let design = dir.path().join("design.toml");
    std::fs::write(&design, DESIGN).unwrap();
    let out = dir.path().join("ds");
    ok(&[
        "dataset",
        "--design",
        design.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let (h, rows) = common::read_csv(&out.join("index.csv"));
    let col = |name: &str| -> Vec<String> {
        let c = h
            .iter()
            .position(|x| x == name)
            .unwrap_or_else(|| panic!("no {name}: {h:?}"));
        rows.iter().map(|r| r[c].clone()).collect()
    };
    let num = |name: &str| -> Vec<f64> { col(name).iter().map(|x| x.parse().unwrap()).collect() };
    // One record per condition, in the design's order; the values are the design's.
    assert_eq!(
        col("condition"),
        ["healthy", "cracked", "pitted_and_broken"]
    );
    assert_eq!(num("fault_count"), [0.0, 1.0, 2.0]);
    assert_eq!(col("fault_gear"), ["", "pinion", "gear"]);
    assert_eq!(num("fault_stage"), [0.0, 0.0, 0.0]);
    assert_eq!(num("fault_tooth"), [-1.0, 3.0, 7.0]);
    assert_eq!(col("fault_kind"), ["", "crack", "spall"]);
    assert_eq!(num("fault_crack_depth_mm"), [0.0, 1.5, 0.0]);
    assert_eq!(num("fault_spall_depth_um"), [0.0, 0.0, 20.0]);
    // The broken tip is the second table: in the sidecar, not in the first's columns.
    assert_eq!(num("fault_removed_height_mm"), [0.0, 0.0, 0.0]);
    let car = std::fs::read(out.join("records/0000002.json")).unwrap();
    let v: serde_json::Value = serde_json::from_slice(&car).unwrap();
    let faults = v["labels"]["faults"].as_array().unwrap();
    assert_eq!(faults.len(), 2);
    assert_eq!(faults[1]["kind"], "broken_tip");
    assert_eq!(faults[1]["removed_height_mm"].as_f64(), Some(0.5));
    assert_eq!(faults[0]["spall_depth_um"].as_f64(), Some(20.0));
    // The metadata gives each new column its unit and meaning.
    let meta: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("metadata.json")).unwrap()).unwrap();
    let text = meta.to_string();
    for name in ["fault_count", "fault_gear", "fault_crack_depth_mm"] {
        assert!(text.contains(name), "metadata lacks {name}");
    }
}
