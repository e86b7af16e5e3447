//! `gearwear run` on a gear train (`[[stage]]`): each study's files are the bytes that
//! study's own command writes (an independent path through the application: the
//! stiffness, dynamics and wear jobs run on their own), the run's summary and report hold
//! every stage, a killed run resumes to the bytes of an uninterrupted one, and bad input
//! is refused as the single pair's run refuses it, naming the stage.

mod common;
use common::{
    assert_nested_study, gearwear, kill_when, number_after, published, read_csv, rejected, stderr,
};
use std::path::{Path, PathBuf};

/// The two-stage reducer (19/31 then 23/47) at 30 Hz and 60 N m on the input shaft,
/// `extra` appended to stage 2's table.
fn case(dir: &Path, extra: &str) -> String {
    let p = dir.join("train.toml");
    std::fs::write(
        &p,
        format!(
            "[operating]\ninput_speed_hz = 30\nload_torque_nm = 60\nload_torque_shaft = \"pinion\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n\n[[stage]]\nmodule_mm = 2.5\nteeth_pinion = 23\nteeth_gear = 47\nface_width_mm = 25\n{extra}"
        ),
    )
    .unwrap();
    p.to_str().unwrap().to_owned()
}

/// `gearwear -q COMMAND --config CONFIG` to 2e4 input cycles (6 dynamic updates: a few
/// seconds) into `out`, with `extra` arguments.
fn args(command: &str, config: &str, out: &Path, extra: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = ["-q", command, "--config", config]
        .iter()
        .map(|s| s.to_string())
        .collect();
    a.extend([
        "--set".into(),
        "wear.total_cycles=2e4".into(),
        "--out".into(),
    ]);
    a.push(out.to_str().unwrap().into());
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
fn each_study_of_a_train_run_is_the_bytes_of_its_own_command() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), "");
    let run = d.path().join("run");
    run_ok(&args("run", &config, &run, &[]));
    for study in ["stiffness", "dynamics", "wear"] {
        let alone = d.path().join(study);
        run_ok(&args(study, &config, &alone, &[]));
        // Every file of the study (summary, tables, figures), none left out or added.
        assert_nested_study(&run, &alone, study);
        // The wear job's checkpoints are the run's too (same case, same updates).
        if study == "wear" {
            for m in ["dynamic", "quasi_static"] {
                for s in [1, 2] {
                    let f = format!("checkpoint_{m}_stage{s}.jsonl");
                    assert!(
                        std::fs::read(alone.join(&f)).unwrap()
                            == std::fs::read(run.join(&f)).unwrap(),
                        "{f}"
                    );
                }
            }
        }
    }
    check_summary_and_report(&run);
}

/// The run's own summary against numbers computed here from the teeth and from the
/// wear study's tables; the report's sections.
fn check_summary_and_report(run: &Path) {
    let s = json(&run.join("summary.json"));
    assert_eq!(s["metadata"]["command"], "run");
    // Overall ratio by hand: (31/19) (47/23), to round-off.
    let ratio = 31.0 / 19.0 * 47.0 / 23.0;
    let got = s["train"]["overall_ratio"].as_f64().unwrap();
    assert!((got / ratio - 1.0).abs() < 1e-14, "{got} vs {ratio}");
    let meshes = s["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 2);
    // Stage 2's pinion turns at 30 Hz x 19/31 (1800 rpm x 19/31); its torque is the input
    // torque x 31/19 (no losses in the operating point), its mesh frequency 23 x its speed.
    let rpm2 = 1800.0 * 19.0 / 31.0;
    let close = |v: &serde_json::Value, x: f64| (v.as_f64().unwrap() / x - 1.0).abs() < 1e-12;
    assert!(close(&meshes[1]["pinion_speed_rpm"], rpm2));
    assert!(close(&meshes[1]["pinion_torque_nm"], 60.0 * 31.0 / 19.0));
    assert!(close(&meshes[1]["mesh_frequency_hz"], 23.0 * rpm2 / 60.0));
    // The limiting mesh: the deepest final wear (either flank) of the wear study's
    // history table, read here.
    for mode in ["dynamic", "quasi_static"] {
        let (h, rows) = read_csv(&run.join(format!("wear/wear_history_{mode}.csv")));
        let col = |n: &str| h.iter().position(|c| c == n).unwrap();
        let (st, p, g) = (
            col("stage"),
            col("max_wear_pinion_um"),
            col("max_wear_gear_um"),
        );
        let last = &rows[rows.len() - 2..];
        let depth = |r: &Vec<String>| r[p].parse::<f64>().unwrap().max(r[g].parse().unwrap());
        let weakest = last
            .iter()
            .max_by(|a, b| depth(a).total_cmp(&depth(b)))
            .unwrap();
        assert_eq!(
            s["limiting_mesh"][mode]["stage"]
                .as_u64()
                .unwrap()
                .to_string(),
            weakest[st],
            "{mode}"
        );
    }
    let html = std::fs::read_to_string(run.join("report.html")).unwrap();
    for needle in [
        "The train",
        "Stage 1: z = 19/31",
        "Stage 2: z = 23/47",
        "limits the life",
    ] {
        assert!(html.contains(needle), "report lacks `{needle}`");
    }
    // Per stage: its stiffness, force and three wear figures, all embedded.
    let images = html.matches("<img").count();
    assert_eq!(images, 1 + 2 * 5, "figures embedded in the report");
}

#[test]
fn a_killed_train_run_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), "");
    let (full, cut): (PathBuf, PathBuf) = (d.path().join("full"), d.path().join("cut"));
    run_ok(&args("run", &config, &full, &[]));
    // Killed once stage 2's dynamic log holds two updates (header + 2 lines).
    let log = cut.join("checkpoint_dynamic_stage2.partial.jsonl");
    let ready = || std::fs::read_to_string(&log).map_or(0, |t| t.lines().count()) >= 3;
    kill_when(&args("run", &config, &cut, &[]), &ready);
    run_ok(&args("run", &config, &cut, &["--resume"]));
    let (a, b) = (published(&full), published(&cut));
    assert_eq!(
        a.iter().map(|f| &f.0).collect::<Vec<_>>(),
        b.iter().map(|f| &f.0).collect::<Vec<_>>()
    );
    for ((p, x), (_, y)) in a.iter().zip(&b) {
        assert!(x == y, "{p}: the resumed run's bytes differ");
    }
}

#[test]
fn bad_input_to_a_train_run_is_refused_naming_the_stage_or_key() {
    let d = tempfile::tempdir().unwrap();
    let train = case(d.path(), "");
    // The single pair's run refuses these keys (tests/cli_input.rs); so does a train's.
    for (set, needle) in [
        ("wear.threshold_um=1e-9", "`wear.threshold_um`"),
        ("wear.total_cycles=1e12", "`wear.total_cycles`"),
        ("wear.block_cycles=0.5", "`wear.block_cycles`"),
    ] {
        rejected(&["run", "--config", &train, "--set", set], &[needle]);
    }
    // A stage's own key out of range: the stage named.
    let bad = tempfile::tempdir().unwrap();
    let bad_train = case(bad.path(), "bearing_stiffness_gear_n_per_m = 1e3\n");
    rejected(
        &["run", "--config", &bad_train],
        &["`stage.bearing_stiffness_gear_n_per_m` = 1000", "(stage 2)"],
    );
    // Resuming from nothing.
    rejected(
        &["run", "--config", &train, "--resume"],
        &["--resume", "does not exist"],
    );
}

#[test]
fn a_faulty_stage_is_reported_with_its_fault_and_every_tooths_wear() {
    let d = tempfile::tempdir().unwrap();
    let crack = "\n[[fault]]\nstage = 1\ngear = \"pinion\"\ntooth = 3\nkind = \"crack\"\ncrack_depth_mm = 0.8\n";
    let config = case(d.path(), crack);
    let run = d.path().join("run");
    run_ok(&args("run", &config, &run, &[]));
    let report = std::fs::read_to_string(run.join("report.html")).unwrap();
    assert!(
        report.contains("Fault: crack on pinion tooth 3."),
        "{report}"
    );
    for (mode, label) in [("dynamic", "dynamic"), ("quasi_static", "quasi-static")] {
        assert!(report.contains(&format!(
            "Stage 1: wear of every tooth at the end of the {label} wear run"
        )));
        // The report's numbers against the wear study's own per-tooth table: the
        // cracked tooth's deepest point, and the deepest of the other pinion teeth.
        let (names, rows) = read_csv(&run.join(format!("wear/csv/teeth_wear_{mode}_stage1.csv")));
        let deepest = |keep: &dyn Fn(&str) -> bool| {
            let mut most = 0.0_f64;
            for row in &rows {
                for (n, v) in names.iter().zip(row) {
                    if n.starts_with("pinion_tooth") && keep(n) {
                        most = most.max(v.parse::<f64>().unwrap());
                    }
                }
            }
            most
        };
        let own = deepest(&|n| n == "pinion_tooth3_um");
        let others = deepest(&|n| n != "pinion_tooth3_um");
        let line = format!("{label}: the deepest wear of pinion tooth 3 is ");
        let shown_own = number_after(&report, &line);
        let shown_others = number_after(&report, " other teeth ");
        // Shown to 4 significant digits: within half a unit of the fourth.
        assert!((shown_own / own - 1.0).abs() < 1e-3, "{shown_own} vs {own}");
        if mode == "dynamic" {
            assert!(
                (shown_others / others - 1.0).abs() < 1e-3,
                "{shown_others} vs {others}"
            );
        }
        // The cracked tooth is softer: it carries less of the load and wears less.
        assert!(own < others, "{mode}: {own} vs {others}");
    }
}
