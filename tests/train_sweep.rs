//! `gearwear sweep` on a gear train (`[[stage]]`), through the binary: one column set per
//! mesh, checked against a second path through the program (`gearwear dynamics` on the
//! same case), the low-speed limit, the train's own damped mesh poles, and an
//! interrupted sweep resumed, shards merged, bad input refused.
//!
//! Cases are the two-stage example (examples/two_stage_reducer.toml) on coarse grids
//! (`common::CHEAP`).

mod common;

use common::{gearwear, kill_when, ok, read_csv, rejected, sweep, CHEAP};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The two-stage example reducer.
fn example() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/two_stage_reducer.toml")
        .to_string_lossy()
        .into_owned()
}

/// Rows of a sweep table as column -> number (empty cells NaN), keyed by column name.
fn rows(path: &Path) -> Vec<BTreeMap<String, f64>> {
    let (h, rows) = read_csv(path);
    rows.iter()
        .map(|r| {
            h.iter()
                .cloned()
                .zip(r.iter().map(|c| c.parse().unwrap_or(f64::NAN)))
                .collect()
        })
        .collect()
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn each_row_equals_gearwear_dynamics_on_the_same_case_mesh_by_mesh() {
    // Two cases varying the input torque and a stage key (`stage.2.face_width_mm`); each
    // row against `gearwear dynamics --set` of its values. Both come from the same
    // deterministic computation with the same unit conversions and are written in
    // round-trip formats, so they agree to the last bit: 1e-12 relative only allows a
    // differently ordered conversion, ~1e6 below the change between the two cases.
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    let config = example();
    sweep(
        &[
            "--config",
            &config,
            "--vary",
            "operating.load_torque_nm=60",
            "--vary",
            "stage.2.face_width_mm=20,25",
        ],
        &out,
    );
    let (h, _) = read_csv(&out.join("sweep.csv"));
    for k in 1..=2 {
        for c in [
            "mesh_frequency_hz",
            "dte_max_um",
            "mesh_force_mean_n",
            "mesh_force_max_n",
            "dynamic_factor",
        ] {
            let name = format!("stage{k}_{c}");
            assert!(h.contains(&name), "no column {name}: {h:?}");
        }
    }
    let table = rows(&out.join("sweep.csv"));
    assert_eq!(table.len(), 2);
    for (i, row) in table.iter().enumerate() {
        let width = row["stage.2.face_width_mm"];
        let single = d.path().join(format!("single{i}"));
        let set = format!("stage.2.face_width_mm={width}");
        let mut a = vec!["dynamics", "--config", &config];
        a.extend(CHEAP);
        a.extend(["--set", &set, "--out", single.to_str().unwrap()]);
        ok(&a);
        let s = json(&single.join("summary.json"));
        let same = |a: f64, b: f64, what: &str| {
            assert!(
                (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
                "case {i} {what}: sweep {a} vs dynamics {b}"
            );
        };
        // The pair's columns are the first mesh's, as the top level of summary.json.
        same(row["dte_max_um"], f(&s["dte"]["max_um"]), "max DTE");
        same(
            row["dynamic_factor"],
            f(&s["mesh_force"]["dynamic_factor"]),
            "dynamic factor",
        );
        let meshes = s["meshes"].as_array().unwrap();
        assert_eq!(meshes.len(), 2);
        for (k, m) in meshes.iter().enumerate() {
            let col = |c: &str| row[&format!("stage{}_{c}", k + 1)];
            same(
                col("mesh_frequency_hz"),
                f(&m["mesh_frequency_hz"]),
                "mesh frequency",
            );
            same(col("dte_max_um"), f(&m["dte"]["max_um"]), "max DTE");
            let force = &m["mesh_force"];
            same(col("mesh_force_mean_n"), f(&force["mean_n"]), "mean force");
            same(col("mesh_force_max_n"), f(&force["max_n"]), "max force");
            same(
                col("dynamic_factor"),
                f(&force["dynamic_factor"]),
                "dynamic factor",
            );
        }
    }
}

#[test]
fn at_very_low_speed_every_meshs_dynamic_factor_tends_to_one() {
    // Without friction the quasi-static mesh force is the shaft torque over the base
    // radius, constant (each mesh's force follows its torque), so max / mean -> 1 as the
    // mesh frequency falls far below the mesh poles (about 1 kHz and up): the dynamic
    // excess is the ringing of the contact-path transitions, whose duration grows as
    // 1 / speed. Measured on these grids: stage 1 1.092, 1.025, 1.0049 and stage 2 1.079,
    // 1.018, 1.0040 at 4, 1 and 0.25 Hz input. Checked: the excess falls with the speed
    // on every mesh, and is below 1 % at 0.25 Hz (mesh frequencies 4.75 and 3.5 Hz).
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    sweep(
        &[
            "--config",
            &example(),
            "--set",
            "friction.model=\"none\"",
            "--vary",
            "operating.input_speed_hz=0.25,1,4",
        ],
        &out,
    );
    let t = rows(&out.join("sweep.csv"));
    for k in 1..=2 {
        let df: Vec<f64> = t
            .iter()
            .map(|r| r[&format!("stage{k}_dynamic_factor")])
            .collect();
        assert!(
            df[0] < df[1] && df[1] < df[2],
            "stage {k}: dynamic factor {df:?} does not fall with the speed"
        );
        assert!(df.iter().all(|x| *x >= 1.0), "stage {k}: {df:?}");
        assert!(df[0] - 1.0 < 0.01, "stage {k} at 0.25 Hz: {}", df[0]);
    }
}

#[test]
fn a_speed_sweep_peaks_where_the_mesh_frequency_meets_a_damped_mesh_pole() {
    // The train's mesh poles from `gearwear dynamics` (its modal analysis, computed
    // apart from any sweep; tests/train.rs checks those poles against matrices assembled
    // by hand). Stage 1's mesh frequency 19 f_in meets the pole near 3.19 kHz (damping
    // ratio 0.12) at f_in = 168 Hz. The sweep from 130 to 200 Hz must peak inside, with
    // the mesh frequency at the peak within the pole's half-power band
    // f_d (1 +- zeta) (a single mode's response stays within 1/sqrt 2 of its peak there,
    // so a peak outside it is not this pole's; measured: 3.10 kHz at 162-164 Hz input,
    // 2.8 % below f_d, the mesh's nonlinear softening and the neighbouring modes).
    let d = tempfile::tempdir().unwrap();
    let config = example();
    let single = d.path().join("dyn");
    let mut a = vec!["dynamics", "--config", &config];
    a.extend(CHEAP);
    a.extend(["--out", single.to_str().unwrap()]);
    ok(&a);
    let s = json(&single.join("summary.json"));
    let poles: Vec<(f64, f64)> = s["mesh_poles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (f(&p["damped_frequency_hz"]), f(&p["damping_ratio"])))
        .collect();
    let out = d.path().join("sw");
    sweep(
        &[
            "--config",
            &config,
            "--vary",
            "operating.input_speed_hz=130:200:5",
        ],
        &out,
    );
    let t = rows(&out.join("sweep.csv"));
    let peak = (0..t.len())
        .max_by(|a, b| t[*a]["stage1_dynamic_factor"].total_cmp(&t[*b]["stage1_dynamic_factor"]))
        .unwrap();
    assert!(
        peak > 0 && peak + 1 < t.len(),
        "no interior peak: case {peak}"
    );
    let f_mesh = t[peak]["stage1_mesh_frequency_hz"];
    let (f_d, zeta) = poles
        .iter()
        .copied()
        .min_by(|a, b| (a.0 - f_mesh).abs().total_cmp(&(b.0 - f_mesh).abs()))
        .unwrap();
    assert!(
        (f_mesh - f_d).abs() < zeta * f_d,
        "peak at mesh frequency {f_mesh} Hz, nearest mesh pole {f_d} Hz (zeta {zeta})"
    );
    // The summary marks that crossing for stage 1 (harmonic 1 of order 19), at the speed
    // where 19 f_in is the pole's frequency.
    let sw = json(&out.join("sweep.json"));
    let st = sw["stages"].as_array().unwrap();
    assert_eq!(st.len(), 2);
    assert_eq!(f(&st[0]["mesh_frequency_per_input_hz"]), 19.0);
    let c = st[0]["resonance_crossings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["harmonic"] == 1 && (f(&c["pole_frequency_hz"]) - f_d).abs() < 1e-6 * f_d)
        .expect("the crossing is marked");
    assert!((19.0 * f(&c["input_speed_hz"]) - f_d).abs() < 1e-9 * f_d);
    // Stage 2's order is its mesh frequency per input rev/s from the sweep's own table.
    let r2 = t[0]["stage2_mesh_frequency_hz"] / t[0]["operating.input_speed_hz"];
    assert!((f(&st[1]["mesh_frequency_per_input_hz"]) - r2).abs() < 1e-9 * r2);
}

/// The sweep of the resume and shard tests: eight speeds of the example.
fn eight(config: &str) -> Vec<String> {
    let mut a: Vec<String> = ["sweep", "--config", config]
        .iter()
        .map(|s| s.to_string())
        .collect();
    a.extend(CHEAP.iter().map(|s| s.to_string()));
    a.extend(["--vary".into(), "operating.input_speed_hz=20:55:5".into()]);
    a
}

fn with_out(a: &[String], out: &Path, extra: &[&str]) -> Vec<String> {
    let mut a = a.to_vec();
    a.extend(extra.iter().map(|s| s.to_string()));
    a.extend(["--out".into(), out.to_string_lossy().into_owned()]);
    a
}

fn run(a: &[String]) -> String {
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    ok(&refs)
}

#[test]
fn a_killed_and_resumed_train_sweep_and_merged_shards_equal_one_uninterrupted_run() {
    let d = tempfile::tempdir().unwrap();
    let config = example();
    let base = eight(&config);
    let full: PathBuf = d.path().join("full");
    run(&with_out(&base, &full, &[]));
    let table = std::fs::read(full.join("sweep.csv")).unwrap();

    // Killed (SIGKILL) once two case records are on disk, then rerun.
    let cut = d.path().join("cut");
    let cases = cut.join("cases");
    kill_when(&with_out(&base, &cut, &[]), &|| {
        std::fs::read_dir(&cases).map_or(0, |r| r.count()) >= 2
    });
    let resumed = run(&with_out(&base, &cut, &[]));
    assert!(resumed.contains("already finished (skipped)"), "{resumed}");
    assert_eq!(std::fs::read(cut.join("sweep.csv")).unwrap(), table);
    assert_eq!(
        std::fs::read(cut.join("sweep.json")).unwrap(),
        std::fs::read(full.join("sweep.json")).unwrap()
    );

    // Two shards merged.
    let (a, b, m) = (d.path().join("a"), d.path().join("b"), d.path().join("m"));
    run(&with_out(&base, &a, &["--shard", "1/2"]));
    run(&with_out(&base, &b, &["--shard", "2/2"]));
    ok(&[
        "sweep-merge",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--out",
        m.to_str().unwrap(),
    ]);
    assert_eq!(std::fs::read(m.join("sweep.csv")).unwrap(), table);
    for k in [1, 2] {
        assert!(m.join(format!("sweep_stage{k}.png")).exists());
    }
    // A pair's shard is another sweep: refused.
    let pair = d.path().join("pair");
    sweep(
        &[
            "--vary",
            "operating.input_speed_hz=20:55:5",
            "--shard",
            "2/2",
        ],
        &pair,
    );
    let o = gearwear(&[
        "sweep-merge",
        a.to_str().unwrap(),
        pair.to_str().unwrap(),
        "--out",
        d.path().join("mixed").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", common::stderr(&o));
}

#[test]
fn bad_input_on_a_train_sweep_is_exit_2_naming_the_stage_and_key() {
    let config = example();
    let base = ["sweep", "--config", config.as_str()];
    let with = |extra: &[&'static str]| {
        let mut a = base.to_vec();
        a.extend(extra);
        a
    };
    rejected(
        &with(&["--vary", "stage.3.face_width_mm=20,25"]),
        &["stage.3.face_width_mm", "but the case has 2"],
    );
    rejected(
        &with(&["--vary", "stage.2.face_width_mm=20,-5"]),
        &["stage.2.face_width_mm", "-5"],
    );
    // A train under a load spectrum: its wear sweep is not built (refused before any case
    // runs, naming the key and the table).
    let d = tempfile::tempdir().unwrap();
    let spectrum = d.path().join("spectrum.toml");
    let text = std::fs::read_to_string(&config).unwrap()
        + "\n[load_spectrum]\nbins = [{ torque_nm = 60, input_speed_hz = 30, share = 1 }]\n";
    std::fs::write(&spectrum, text).unwrap();
    let spectrum = spectrum.to_str().unwrap();
    rejected(
        &[
            "sweep",
            "--config",
            spectrum,
            "--run",
            "wear",
            "--vary",
            "operating.load_torque_nm=50,60",
        ],
        &["--run", "gear train", "[load_spectrum]"],
    );
}

#[test]
fn a_train_wear_sweep_row_equals_gearwear_wear_on_the_same_case_mesh_by_mesh() {
    // Each row of `sweep --run wear` on the two-stage train against `gearwear wear` (both
    // modes) at the row's speed: every mesh's final flank depths, the limiting stage, the
    // update counts and input cycles from its summary.json, and the new-teeth columns
    // from `gearwear dynamics`. Same deterministic computation, same unit conversions,
    // round-trip formats: equal to the last bit; 1e-12 relative only allows a
    // differently ordered conversion (the two speeds' depths differ by ~10 %).
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    let config = example();
    let total = "wear.total_cycles=1e4";
    sweep(
        &[
            "--config",
            &config,
            "--run",
            "wear",
            "--set",
            total,
            "--vary",
            "operating.input_speed_hz=20,40",
        ],
        &out,
    );
    let table = rows(&out.join("sweep.csv"));
    assert_eq!(table.len(), 2);
    let same = |a: f64, b: f64, what: &str| {
        assert!(
            (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
            "{what}: sweep {a} vs single run {b}"
        );
    };
    for row in &table {
        let speed = format!(
            "operating.input_speed_hz={}",
            row["operating.input_speed_hz"]
        );
        let single = |job: &str| {
            let dir = d.path().join(format!("{job}{}", row["case_id"]));
            let mut a = vec![job, "--config", &config];
            a.extend(CHEAP);
            a.extend([
                "--set",
                total,
                "--set",
                &speed,
                "--out",
                dir.to_str().unwrap(),
            ]);
            ok(&a);
            json(&dir.join("summary.json"))
        };
        let w = single("wear");
        let dynamics = single("dynamics");
        for (mode, col) in [("dynamic", "dynamic"), ("quasi_static", "quasi_static")] {
            let stage = f(&w["limiting_mesh"][mode]["stage"]);
            assert!(stage == 1.0 || stage == 2.0);
            same(
                row[&format!("wear_limiting_stage_{col}")],
                stage,
                "limiting stage",
            );
            same(
                row[&format!("wear_updates_{col}")],
                f(&w["updates"][mode]),
                "updates",
            );
            same(
                row[&format!("wear_cycles_{col}")],
                f(&w["input_cycles"][mode]),
                "cycles",
            );
            for (k, m) in w["meshes"].as_array().unwrap().iter().enumerate() {
                let end = &m["final"][mode];
                for flank in ["pinion", "gear"] {
                    let depth = f(&end[format!("max_wear_{flank}_um")]);
                    assert!(depth > 0.0, "stage {} {flank} {mode} unworn", k + 1);
                    let name = format!("wear_max_{flank}_{col}_um");
                    same(row[&format!("stage{}_{name}", k + 1)], depth, &name);
                    // The pair's columns are the first mesh's.
                    if k == 0 {
                        same(row[&name], depth, &name);
                    }
                }
            }
        }
        // The new teeth's columns: the dynamic run's first update is the new-teeth
        // steady state that `gearwear dynamics` computes.
        same(row["dte_max_um"], f(&dynamics["dte"]["max_um"]), "max DTE");
        for (k, m) in dynamics["meshes"].as_array().unwrap().iter().enumerate() {
            let col = |c: &str| row[&format!("stage{}_{c}", k + 1)];
            same(col("dte_max_um"), f(&m["dte"]["max_um"]), "mesh max DTE");
            same(
                col("mesh_force_max_n"),
                f(&m["mesh_force"]["max_n"]),
                "max force",
            );
        }
    }
}

#[test]
fn a_train_followed_along_both_branches_finds_the_ordinary_sweeps_solutions() {
    // Continuation warm-starts each point from the previous point's periodic state of the
    // whole train. Near the 3.19 kHz mesh pole (no contact loss on these cases, so one
    // periodic solution) both branches must reach the solution an ordinary sweep finds
    // from the static equilibrium: the same to the steady-state criterion (1e-6 of a
    // period's change; 1e-5 relative on the forces allows for the last period's
    // residual; measured 1e-8).
    let d = tempfile::tempdir().unwrap();
    let config = example();
    let axis = "operating.input_speed_hz=155:170:5";
    let plain = d.path().join("plain");
    sweep(&["--config", &config, "--vary", axis], &plain);
    let cont = d.path().join("cont");
    sweep(
        &[
            "--config",
            &config,
            "--vary",
            axis,
            "--continuation",
            "both",
        ],
        &cont,
    );
    let p = rows(&plain.join("sweep.csv"));
    let c = rows(&cont.join("sweep.csv"));
    assert_eq!(c.len(), 2 * p.len(), "two branches of every point");
    for r in &c {
        let speed = r["operating.input_speed_hz"];
        let q = p
            .iter()
            .find(|q| q["operating.input_speed_hz"] == speed)
            .unwrap();
        for k in [1, 2] {
            for col in ["mesh_force_max_n", "dte_max_um", "dynamic_factor"] {
                let name = format!("stage{k}_{col}");
                let (a, b) = (r[&name], q[&name]);
                assert!(
                    (a - b).abs() <= 1e-5 * b.abs(),
                    "{speed} Hz {name}: branch {a} vs sweep {b}"
                );
            }
        }
    }
}
