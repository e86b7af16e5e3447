//! `gearwear sweep` / `sweep-merge` end to end, through the binary.
//!
//! The reference for a sweep row is a second path through the program: the single-case
//! commands (`gearwear dynamics`, `gearwear wear`) run on the same case. Cases are kept
//! cheap (coarse time and stiffness grids, two evaluated mesh periods).

mod common;

use common::{gearwear, ok, read_csv, sweep, CHEAP};
use std::collections::BTreeMap;

/// One row as column -> cell.
fn row_map(h: &[String], row: &[String]) -> BTreeMap<String, String> {
    h.iter().cloned().zip(row.iter().cloned()).collect()
}

fn num(m: &BTreeMap<String, String>, k: &str) -> f64 {
    m[k].parse().unwrap_or_else(|_| panic!("{k} = `{}`", m[k]))
}

/// Both numbers come from the same deterministic computation on the same case and are
/// written in round-trip formats (`{:e}` in the CSV, ryu in JSON), so they should agree
/// to the last bit; 1e-12 relative only allows for a differently ordered unit
/// conversion and is ~1e4 times below any physical change between neighbouring cases.
fn assert_same(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
        "{what}: sweep {a} vs single run {b}"
    );
}

#[test]
fn rows_equal_single_dynamics_runs() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    sweep(&["--vary", "operating.input_speed_hz=25:35:5"], &out);
    let (h, rows) = read_csv(&out.join("sweep.csv"));
    assert_eq!(h[0], "operating.input_speed_hz");
    assert_eq!(h[1], "case_id");
    assert_eq!(rows.len(), 3, "STOP 35 lands on the grid and is included");
    for (i, row) in rows.iter().enumerate() {
        let m = row_map(&h, row);
        assert_eq!(m["case_id"], i.to_string());
        let speed = &m["operating.input_speed_hz"];
        assert_eq!(speed, &(25 + 5 * i).to_string());
        let single = d.path().join(format!("single{i}"));
        let set = format!("operating.input_speed_hz={speed}");
        let mut a = vec!["dynamics"];
        a.extend(CHEAP);
        a.extend(["--set", &set, "--out", single.to_str().unwrap()]);
        ok(&a);
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(single.join("summary.json")).unwrap())
                .unwrap();
        let f = |v: &serde_json::Value| v.as_f64().unwrap();
        assert_same(num(&m, "dte_max_um"), f(&s["dte"]["max_um"]), "max DTE");
        assert_same(
            num(&m, "velocity_y_pinion_rms_mm_per_s"),
            f(&s["velocity_y_pinion"]["rms_mm_per_s"]),
            "RMS dy_p/dt",
        );
        assert_same(
            num(&m, "mesh_force_mean_n"),
            f(&s["mesh_force"]["mean_n"]),
            "mean force",
        );
        assert_same(
            num(&m, "mesh_force_max_n"),
            f(&s["mesh_force"]["max_n"]),
            "max force",
        );
        assert_same(
            num(&m, "dynamic_factor"),
            f(&s["mesh_force"]["dynamic_factor"]),
            "dynamic factor",
        );
        for k in 0..4 {
            assert_same(
                num(&m, &format!("mesh_harmonic{}_mm_per_s", k + 1)),
                f(&s["mesh_harmonics"]["velocity_y_pinion"][k]),
                "mesh harmonic",
            );
        }
        // The stored case is the single run's case (same resolved-case hash).
        let rec: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(out.join(format!("cases/{i}.json"))).unwrap(),
        )
        .unwrap();
        assert_eq!(rec["case_sha256"], s["metadata"]["case_sha256"]);
    }
}

#[test]
fn wear_row_equals_single_wear_run() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    sweep(
        &["--run", "wear", "--vary", "operating.input_speed_hz=40"],
        &out,
    );
    let (h, rows) = read_csv(&out.join("sweep.csv"));
    let m = row_map(&h, &rows[0]);
    let single = d.path().join("single");
    let mut a = vec!["wear"];
    a.extend(CHEAP);
    a.extend([
        "--set",
        "operating.input_speed_hz=40",
        "--mode",
        "both",
        "--out",
        single.to_str().unwrap(),
    ]);
    ok(&a);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(single.join("summary.json")).unwrap())
            .unwrap();
    let last = |v: &serde_json::Value| v.as_array().unwrap().last().unwrap().as_f64().unwrap();
    // summary.json interpolates each series at the final cycle count (t = 1), which can
    // differ from the final value by an ulp: within the 1e-12 of `assert_same`.
    assert_same(
        num(&m, "wear_max_pinion_dynamic_um"),
        last(&s["max_wear_pinion_um"]["dynamic"]),
        "pinion wear, dynamic",
    );
    assert_same(
        num(&m, "wear_max_gear_dynamic_um"),
        last(&s["max_wear_gear_um"]["dynamic"]),
        "gear wear, dynamic",
    );
    assert_same(
        num(&m, "wear_max_pinion_quasi_static_um"),
        last(&s["max_wear_pinion_um"]["quasi_static"]),
        "pinion wear, quasi-static",
    );
    assert_same(
        num(&m, "wear_max_gear_quasi_static_um"),
        last(&s["max_wear_gear_um"]["quasi_static"]),
        "gear wear, quasi-static",
    );
    assert_eq!(
        num(&m, "wear_updates_dynamic"),
        s["updates"]["dynamic"].as_f64().unwrap()
    );
    assert_eq!(
        num(&m, "wear_updates_quasi_static"),
        s["updates"]["quasi_static"].as_f64().unwrap()
    );
    // Neither run stopped early (summary.json lists none), so both reach the case's
    // total cycles.
    assert_eq!(s["stopped"], serde_json::json!({}));
    for col in ["wear_cycles_dynamic", "wear_cycles_quasi_static"] {
        assert_eq!(num(&m, col), last(&s["cycles"]), "{col}");
    }
    assert!(
        num(&m, "wear_updates_dynamic") >= 1.0,
        "a wear run has updates"
    );
}

const TWO_AXES: [&str; 4] = [
    "--vary",
    "operating.input_speed_hz=20,30,40",
    "--vary",
    "operating.load_torque_nm=40:60:20",
];

#[test]
fn shards_merge_to_the_unsharded_table() {
    let d = tempfile::tempdir().unwrap();
    let full = d.path().join("full");
    sweep(&TWO_AXES, &full);
    let (h, rows) = read_csv(&full.join("sweep.csv"));
    // First --vary varies slowest: case_id = 2 i_speed + i_torque.
    let order: Vec<(String, String)> = rows.iter().map(|r| (r[0].clone(), r[1].clone())).collect();
    let want: Vec<(String, String)> = ["20", "30", "40"]
        .iter()
        .flat_map(|s| ["40", "60"].map(|t| (s.to_string(), t.to_string())))
        .collect();
    assert_eq!(order, want);
    assert_eq!(h[2], "case_id");

    // Separate directories, then merge.
    let (a, b, m) = (d.path().join("a"), d.path().join("b"), d.path().join("m"));
    for (dir, s) in [(&a, "1/2"), (&b, "2/2")] {
        let mut x = TWO_AXES.to_vec();
        x.extend(["--shard", s]);
        sweep(&x, dir);
    }
    let (_, rows_a) = read_csv(&a.join("sweep_shard_1_of_2.csv"));
    assert_eq!(
        rows_a.iter().map(|r| r[2].as_str()).collect::<Vec<_>>(),
        ["0", "2", "4"],
        "round-robin"
    );
    ok(&[
        "sweep-merge",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--out",
        m.to_str().unwrap(),
    ]);
    let merged = std::fs::read(m.join("sweep.csv")).unwrap();
    assert_eq!(merged, std::fs::read(full.join("sweep.csv")).unwrap());

    // Three shards sharing one directory (shared storage), merged into a CSV file.
    let shared = d.path().join("shared");
    for s in ["1/3", "2/3", "3/3"] {
        let mut x = TWO_AXES.to_vec();
        x.extend(["--shard", s]);
        sweep(&x, &shared);
    }
    let file = d.path().join("merged.csv");
    ok(&[
        "sweep-merge",
        shared.to_str().unwrap(),
        "--out",
        file.to_str().unwrap(),
    ]);
    assert_eq!(std::fs::read(&file).unwrap(), merged);
}

#[test]
fn rerun_skips_finished_cases() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    let args = ["--vary", "operating.input_speed_hz=20:35:5"];
    let first = sweep(&args, &out);
    assert!(
        first.contains("0 already finished (skipped), 4 to run"),
        "{first}"
    );
    let table = std::fs::read(out.join("sweep.csv")).unwrap();
    let case = |i: usize| out.join(format!("cases/{i}.json"));
    let before: Vec<_> = (0..4)
        .map(|i| std::fs::metadata(case(i)).unwrap().modified().unwrap())
        .collect();
    std::fs::remove_file(case(2)).unwrap();

    let second = sweep(&args, &out);
    assert!(
        second.contains("3 already finished (skipped), 1 to run"),
        "{second}"
    );
    for i in [0, 1, 3] {
        let now = std::fs::metadata(case(i)).unwrap().modified().unwrap();
        assert_eq!(now, before[i], "case {i} was rewritten");
    }
    assert!(case(2).exists(), "the deleted case is recomputed");
    assert_eq!(
        std::fs::read(out.join("sweep.csv")).unwrap(),
        table,
        "the reassembled table is the same"
    );

    // Another base case changes every resolved-case hash: nothing is reused.
    let mut other = args.to_vec();
    other.extend(["--set", "operating.load_torque_nm=50"]);
    let third = sweep(&other, &out);
    assert!(
        third.contains("0 already finished (skipped), 4 to run"),
        "{third}"
    );
}

#[test]
fn bad_vary_is_exit_2_naming_key_and_value_before_running() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("never");
    let cases: [(&str, &[&str]); 7] = [
        (
            "operating.input_speed_hz=40:20:5",
            &["operating.input_speed_hz", "empty range"],
        ),
        (
            "operating.input_speed_hz=20:40:0",
            &["operating.input_speed_hz", "STEP"],
        ),
        (
            "operating.input_speed_hz=20:40:-5",
            &["operating.input_speed_hz", "STEP"],
        ),
        (
            "operating.input_speed_hz=30,-5",
            &["operating.input_speed_hz", "`-5`"],
        ),
        (
            "operating.speed_hz=30,40",
            &["operating.speed_hz", "unknown key"],
        ),
        (
            "numerics.steps_per_mesh_period=60.5",
            &["numerics.steps_per_mesh_period", "60.5"],
        ),
        (
            "friction.model=none,coulomb",
            &["friction.model", "coulomb"],
        ),
    ];
    for (vary, expect) in cases {
        let o = gearwear(&["sweep", "--vary", vary, "--out", out.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{vary}: {err}");
        for e in expect {
            assert!(err.contains(e), "{vary}: `{e}` not in: {err}");
        }
    }
    // A combination whose geometry fails is also caught before any case runs.
    let o = gearwear(&[
        "sweep",
        "--vary",
        "gear.profile_shift_pinion=0,1.0",
        "--vary",
        "operating.input_speed_hz=30",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("gear.profile_shift_pinion=1.0"));
    assert!(
        !out.exists(),
        "nothing may run (or be written) on bad input"
    );
}

#[test]
fn merge_rejects_conflicting_rows_and_mixed_sweeps() {
    let d = tempfile::tempdir().unwrap();
    let a = d.path().join("a");
    sweep(&["--vary", "operating.input_speed_hz=25,30"], &a);
    // The same case with a changed number.
    let text = std::fs::read_to_string(a.join("sweep.csv")).unwrap();
    let (h, rows) = read_csv(&a.join("sweep.csv"));
    let dte = h.iter().position(|c| c == "dte_max_um").unwrap();
    let changed = text.replacen(&rows[1][dte], "1e3", 1);
    assert_ne!(changed, text);
    let bad = d.path().join("bad.csv");
    std::fs::write(&bad, changed).unwrap();
    // A merge of two inputs must fail with exit 2 saying `needle`.
    let refused = |x: &std::path::Path, y: &std::path::Path, needle: &str| {
        let o = gearwear(&[
            "sweep-merge",
            x.to_str().unwrap(),
            y.to_str().unwrap(),
            "--out",
            d.path().join("m").to_str().unwrap(),
        ]);
        let e = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{e}");
        assert!(e.contains(needle), "{needle}: {e}");
    };
    // Without its sweep description, a table cannot be placed: refused.
    refused(&a, &bad, "no description");
    std::fs::copy(a.join("sweep.json"), d.path().join("bad.json")).unwrap();
    refused(&a, &bad, "case_id 1");

    // Another varied key.
    let b = d.path().join("b");
    sweep(&["--vary", "operating.load_torque_nm=50"], &b);
    refused(&a, &b, "mixed sweeps");

    // Same key, other values: shards 1/2 and 2/2 of two different sweeps have disjoint
    // case ids, so only the sweep descriptions can tell them apart.
    let (p, q) = (d.path().join("p"), d.path().join("q"));
    sweep(
        &["--vary", "operating.input_speed_hz=25,30", "--shard", "1/2"],
        &p,
    );
    sweep(
        &["--vary", "operating.input_speed_hz=50,60", "--shard", "2/2"],
        &q,
    );
    refused(&p, &q, "mixed sweeps");
}

#[test]
fn speed_sweep_marks_harmonic_crossings_of_the_damped_mesh_poles() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    sweep(&["--vary", "operating.input_speed_hz=10:60:25"], &out);
    assert!(out.join("sweep.png").exists());
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sweep.json")).unwrap()).unwrap();
    // Modes of the base case as `gearwear dynamics` reports them.
    let single = d.path().join("single");
    let mut a = vec!["dynamics"];
    a.extend(CHEAP);
    a.extend(["--out", single.to_str().unwrap()]);
    ok(&a);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(single.join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(meta["modes"]["mesh_poles"], s["mesh_poles"]);
    assert_eq!(
        meta["modes"]["undamped_natural_frequencies_hz"],
        s["undamped_natural_frequencies_hz"]
    );
    let poles: Vec<f64> = s["mesh_poles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["damped_frequency_hz"].as_f64().unwrap())
        .collect();
    // Expected: every (pole, k) with f_p / (k z1) in [10, 60] Hz, z1 = 19 (the default),
    // k = 1..4.
    let mut want: Vec<(usize, u64)> = Vec::new();
    for (i, f) in poles.iter().enumerate() {
        for k in 1..=4u64 {
            if (10.0..=60.0).contains(&(f / (k as f64 * 19.0))) {
                want.push((i + 1, k));
            }
        }
    }
    let got = meta["resonance_crossings"].as_array().unwrap();
    assert!(
        want.len() >= 2,
        "the default case's mesh pole is in reach of 10-60 Hz x 19 x 1..4"
    );
    let mut got_pairs: Vec<(usize, u64)> = got
        .iter()
        .map(|c| {
            (
                c["pole"].as_u64().unwrap() as usize,
                c["harmonic"].as_u64().unwrap(),
            )
        })
        .collect();
    got_pairs.sort_unstable();
    want.sort_unstable();
    assert_eq!(got_pairs, want);
    for c in got {
        let (k, v, f) = (
            c["harmonic"].as_f64().unwrap(),
            c["input_speed_hz"].as_f64().unwrap(),
            c["pole_frequency_hz"].as_f64().unwrap(),
        );
        // k z1 f_in = f_p to rounding (one multiply and one divide).
        assert!((k * 19.0 * v - f).abs() <= 1e-12 * f, "{c}");
    }
}
