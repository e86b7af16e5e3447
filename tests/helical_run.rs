//! `gearwear run` on a helical pair (docs/MODEL.md 11.5), through the binary, on
//! examples/helical_pair.toml made short: each study's files are the bytes that study's own
//! command writes (an independent path through the application: the stiffness, dynamics
//! and wear jobs run on their own), so the wear histories and the per-slice wear map CSVs
//! are `gearwear wear`'s byte for byte and the new teeth's dynamics summary is `gearwear
//! dynamics`'; the wear states hold what the wear study wrote; a killed or cut run resumes
//! to the bytes of an uninterrupted one; what the helical model refuses is refused by
//! `run` with `gearwear wear`'s message; a helix angle of 0 is still the spur pair's run.

mod common;
use common::resume::{cut_log, cut_then_resumed_is_unchanged, edit_update, refused};
use common::{assert_nested_study, gearwear, kill_when, published, read_csv, rejected, stderr};
use std::path::{Path, PathBuf};

fn example() -> String {
    concat!(env!("CARGO_MANIFEST_DIR"), "/examples/helical_pair.toml").to_owned()
}

/// The example made short: 8 face slices (the crowning's lead gaps still load them
/// unevenly), coarse grids, and 2e4 cycles at a 0.05 µm threshold: a few updates per
/// mode, seconds in all.
const SHORT: [&str; 5] = [
    "stiffness.slices=8",
    "numerics.steps_per_mesh_period=60",
    "stiffness.table_points_per_mesh_period=60",
    "wear.total_cycles=2e4",
    "wear.threshold_um=0.05",
];

/// `gearwear -q COMMAND --config EXAMPLE --set SHORT... --out OUT EXTRA...`.
fn args(command: &str, out: &Path, extra: &[&str]) -> Vec<String> {
    args_of(Some(&example()), command, out, extra)
}

/// [`args`] of `config` (None: the built-in case).
fn args_of(config: Option<&str>, command: &str, out: &Path, extra: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = vec!["-q".into(), command.into()];
    if let Some(c) = config {
        a.extend(["--config".to_string(), c.to_string()]);
    }
    for s in SHORT {
        a.extend(["--set".to_string(), s.to_string()]);
    }
    a.extend(["--out".to_string(), out.to_str().unwrap().to_string()]);
    a.extend(extra.iter().map(|s| s.to_string()));
    a
}

fn run_ok(a: &[String]) {
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    let o = gearwear(&refs);
    assert!(o.status.success(), "{a:?}: {}", stderr(&o));
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn each_study_of_a_helical_run_is_the_bytes_of_its_own_command() {
    let d = tempfile::tempdir().unwrap();
    let run = d.path().join("run");
    run_ok(&args("run", &run, &[]));
    for study in ["stiffness", "dynamics", "wear"] {
        let alone = d.path().join(study);
        run_ok(&args(study, &alone, &[]));
        // Every file of the study (summary, tables, figures), none left out or added:
        // for the wear, both histories, the profiles and `wear_map_MODE.csv`; for the
        // dynamics, its `summary.json` of the new teeth.
        assert_nested_study(&run, &alone, study);
        if study == "wear" {
            // The wear job's checkpoints are the run's too (same case, same updates).
            for m in ["dynamic", "quasi_static"] {
                let f = format!("checkpoint_{m}.jsonl");
                assert!(
                    std::fs::read(alone.join(&f)).unwrap() == std::fs::read(run.join(&f)).unwrap(),
                    "{f}"
                );
                // What the nesting compared: the per-slice wear map and the histories.
                for f in [format!("csv/wear_map_{m}.csv"), format!("updates_{m}.csv")] {
                    assert!(run.join("wear").join(&f).exists(), "{f}");
                }
            }
        }
    }
    check_states(&run);
    check_report(&run);
}

/// The run's wear states against the studies' files: the new teeth's numbers are the
/// dynamics study's summary; each worn state's deepest wear is the one asked, and its
/// roughness lies between the new teeth's and the wear study's at the end (the roughness
/// law falls with wear: docs/MODEL.md section 4).
fn check_states(run: &Path) {
    let s = json(&run.join("summary.json"));
    assert_eq!(s["metadata"]["command"], "run");
    let h = &s["helical_run"];
    let d = json(&run.join("dynamics/summary.json"));
    assert_eq!(h["new_teeth"]["dte"], d["dte"]);
    assert_eq!(h["new_teeth"]["helical"], d["helical"]);
    let states = h["wear_states"].as_array().unwrap();
    let wear: Vec<f64> = states
        .iter()
        .map(|x| x["max_wear_um"].as_f64().unwrap())
        .collect();
    assert_eq!(wear, [0.0, 0.1, 0.5, 1.0]);
    // The new teeth: the same response, summarised once by the dynamics report and once
    // by the run's wear states (`ResponseSummary`): equal to round-off.
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
    let n = &states[0];
    assert!(close(
        n["dte_max_um"].as_f64().unwrap(),
        d["dte"]["max_um"].as_f64().unwrap()
    ));
    assert!(close(
        n["mesh_force_mean_n"].as_f64().unwrap(),
        d["mesh_force"]["mean_n"].as_f64().unwrap()
    ));
    let w = json(&run.join("wear/summary.json"));
    assert_eq!(h["wear"]["wear_map"], w["wear_map"]);
    // The roughness of a worn state: between the new teeth's and the end of the dynamic
    // run's (the last row of its history table, read here).
    let (head, rows) = read_csv(&run.join("wear/updates_dynamic.csv"));
    assert!(rows.len() >= 3, "{} dynamic updates", rows.len() - 1);
    let col = head.iter().position(|c| c == "roughness_um").unwrap();
    let first: f64 = rows[0][col].parse().unwrap();
    let last: f64 = rows.last().unwrap()[col].parse().unwrap();
    assert!(close(n["roughness_um"].as_f64().unwrap(), first));
    for x in &states[1..] {
        let r = x["roughness_um"].as_f64().unwrap();
        assert!(r <= first + 1e-12 && r >= last.min(first) - 1e-12, "{x}");
    }
}

/// The report: its sections, every figure embedded (the studies' own and the wear
/// states'), each figure's data beside it.
fn check_report(run: &Path) {
    let html = std::fs::read_to_string(run.join("report.html")).unwrap();
    for needle in [
        "helical pair",
        "The pair and its mesh stiffness",
        "ISO 6336-1",
        "new teeth and worn states",
        "with new teeth and at three wear states",
        "Wear across the face",
        "wear_map_dynamic",
    ] {
        assert!(html.contains(needle), "report lacks `{needle}`");
    }
    // The stiffness study's two figures (slice stiffness, static face load), the dynamic
    // face load, Fig. 4-10 at the wear states (7), Fig. 11-13 and per mode the wear map
    // and the worn profiles.
    assert_eq!(html.matches("<img").count(), 2 + 1 + 7 + 3 + 2 * 2);
    for stem in ["fig04_dte", "fig07_mesh_harmonics", "fig10_friction_force"] {
        assert!(run.join(format!("{stem}.png")).exists(), "{stem}");
        let (h, rows) = read_csv(&run.join(format!("csv/{stem}.csv")));
        assert!(!h.is_empty() && !rows.is_empty(), "{stem}");
    }
    // Fig. 7: one point per wear state, new teeth first.
    let (_, rows) = read_csv(&run.join("csv/fig07_mesh_harmonics.csv"));
    assert_eq!(rows.len(), 4);
}

#[test]
fn a_killed_or_cut_helical_run_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let (full, cut): (PathBuf, PathBuf) = (d.path().join("full"), d.path().join("cut"));
    run_ok(&args("run", &full, &[]));
    // Killed once the dynamic log holds two updates (header + 2 lines).
    let log = cut.join("checkpoint_dynamic.partial.jsonl");
    let ready = || std::fs::read_to_string(&log).map_or(0, |t| t.lines().count()) >= 3;
    kill_when(&args("run", &cut, &[]), &ready);
    run_ok(&args("run", &cut, &["--resume"]));
    let (a, b) = (published(&full), published(&cut));
    assert_eq!(
        a.iter().map(|f| &f.0).collect::<Vec<_>>(),
        b.iter().map(|f| &f.0).collect::<Vec<_>>()
    );
    for ((p, x), (_, y)) in a.iter().zip(&b) {
        assert!(x == y, "{p}: the resumed run's bytes differ");
    }
    // A finished run whose last checkpoints were cut off (the dynamic log torn in its
    // third update, the quasi-static one after its first): resumed, the same bytes.
    let again = d.path().join("again");
    let cut_logs = |out: &Path| {
        cut_log(&out.join("checkpoint_dynamic.jsonl"), 2, true);
        cut_log(&out.join("checkpoint_quasi_static.jsonl"), 1, false);
    };
    let a = args("run", &again, &[]);
    cut_then_resumed_is_unchanged(&a, &again, &cut_logs);
    // A run started afresh would give the same bytes: that the resume continues the logs
    // shows in its refusal of one whose update 2 was edited (its checksum left as it was).
    edit_update(&again.join("checkpoint_dynamic.jsonl"), 2, false, &|v| {
        v["wear"]["cycles"] = serde_json::json!(v["wear"]["cycles"].as_f64().unwrap() + 1.0);
    });
    refused(
        &a,
        "an edited log",
        &["checkpoint_dynamic.jsonl", "line 4", "checksum"],
    );
}

#[test]
fn what_the_helical_model_refuses_is_refused_by_run_as_by_wear() {
    let dir = tempfile::tempdir().unwrap();
    let fault = dir.path().join("fault.toml");
    std::fs::write(
        &fault,
        "[gear]\nhelix_angle_deg = 15\n\n[[fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 3\ncrack_depth_mm = 1.0\n",
    )
    .unwrap();
    let train = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/two_stage_reducer.toml"
    );
    let fault = fault.to_str().unwrap();
    let helix = "gear.helix_angle_deg=15";
    // (arguments after the command, the keys the message names)
    // (Per-tooth inputs are taken by both, docs/MODEL.md 11.13: tests/helical_tooth_wear.rs;
    // a fault's bad span is refused by both alike.)
    let cases: [(Vec<&str>, &[&str]); 5] = [
        (
            vec![
                "--set",
                helix,
                "--set",
                "modification.tip_relief_um=5",
                "--set",
                "modification.tip_relief_length_mm=1",
            ],
            &["`[modification]`"],
        ),
        (
            vec!["--set", helix, "--set", "wear.worn_geometry=\"worn\""],
            &["wear.worn_geometry"],
        ),
        (
            vec!["--set", helix, "--set", "contact.load_sharing=\"pedrero\""],
            &["contact.load_sharing"],
        ),
        (
            vec!["--config", fault, "--set", "fault.face_start_mm=30"],
            &["fault.face_start_mm"],
        ),
        (
            vec!["--set", helix, "--config", train],
            &["gear.helix_angle_deg", "[[stage]]"],
        ),
    ];
    for (extra, keys) in cases {
        let with = |command: &'static str| {
            let mut a = vec![command];
            a.extend(&extra);
            a
        };
        // Exit 2, the keys named, no panic and no output folder (nothing was run).
        let by_run = rejected(&with("run"), keys);
        let by_wear = rejected(&with("wear"), keys);
        assert_eq!(by_run, by_wear, "{extra:?}: not `gearwear wear`'s message");
    }
}

#[test]
fn a_helix_angle_of_0_is_the_spur_pairs_run() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("spur");
    // The built-in pair (the example's crowning is a lead key, which the spur run
    // refuses), its helix angle given as 0.
    run_ok(&args_of(
        None,
        "run",
        &out,
        &["--set", "gear.helix_angle_deg=0"],
    ));
    let s = json(&out.join("summary.json"));
    // The spur run's own outputs: Fig. 2 of the paper's report and its three wear states,
    // no study folders and no helical block.
    assert!(s.get("helical_run").is_none(), "{s}");
    assert_eq!(s["wear_states"].as_array().unwrap().len(), 3);
    assert!(out.join("fig02_mesh_stiffness.png").exists());
    assert!(!out.join("stiffness").exists() && !out.join("wear").exists());
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(!html.contains("helical pair"));
}
