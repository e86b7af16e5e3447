//! `gearwear sweep` on a helical pair (`gear.helix_angle_deg` > 0), through the binary:
//! every column of a row against a second path through the program (`gearwear dynamics`
//! and `gearwear wear` on that row's case, their summary.json), the spur row of a sweep
//! over the helix angle against a spur sweep (bit for bit), a resumed sweep and merged
//! shards against the whole sweep, and what a helical sweep still refuses.
//!
//! The pair is the paper's with beta = 15 deg, 8 slices and a 10 µm crowning (so the
//! dynamic face load exists), on coarse grids (`common::CHEAP`) and 2e4 cycles.

mod common;

use common::{ok, read_csv, rejected, sweep, CHEAP};
use std::collections::BTreeMap;
use std::path::Path;

/// The helical pair's settings (`--set` pairs).
const HELICAL: [&str; 8] = [
    "--set",
    "gear.helix_angle_deg=15",
    "--set",
    "stiffness.slices=8",
    "--set",
    "modification.crowning_um=10",
    "--set",
    "wear.total_cycles=2e4",
];

/// Rows of a sweep table: column -> cell text.
fn rows(path: &Path) -> Vec<BTreeMap<String, String>> {
    let (h, rows) = read_csv(path);
    rows.iter()
        .map(|r| h.iter().cloned().zip(r.iter().cloned()).collect())
        .collect()
}

fn num(row: &BTreeMap<String, String>, col: &str) -> f64 {
    let c = row.get(col).unwrap_or_else(|| panic!("no column {col}"));
    c.parse().unwrap_or(f64::NAN)
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Both come from the same deterministic computation with the same unit conversions, in
/// the same order, written in round-trip formats, so they agree to the last bit; 1e-12
/// relative only allows a differently ordered conversion, some 1e6 below the change
/// between the two cases (a third more torque).
fn same(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
        "{what}: sweep {a} vs single study {b}"
    );
}

/// `gearwear COMMAND` of the helical pair at `torque` into `dir/name`; its summary.json.
fn single(dir: &Path, name: &str, command: &[&str], torque: &str) -> serde_json::Value {
    let out = dir.join(name);
    let set = format!("operating.load_torque_nm={torque}");
    let mut a = command.to_vec();
    a.extend(CHEAP);
    a.extend(HELICAL);
    a.extend(["--set", &set, "--out", out.to_str().unwrap()]);
    ok(&a);
    json(&out.join("summary.json"))
}

/// The dynamics columns of `row` against `gearwear dynamics`' summary `s`, helical ones
/// included.
fn check_dynamics_columns(row: &BTreeMap<String, String>, s: &serde_json::Value, case: &str) {
    let pairs = [
        ("dte_max_um", &s["dte"]["max_um"]),
        (
            "velocity_y_pinion_rms_mm_per_s",
            &s["velocity_y_pinion"]["rms_mm_per_s"],
        ),
        ("mesh_force_mean_n", &s["mesh_force"]["mean_n"]),
        ("mesh_force_max_n", &s["mesh_force"]["max_n"]),
        ("dynamic_factor", &s["mesh_force"]["dynamic_factor"]),
        ("total_contact_ratio", &s["helical"]["total_contact_ratio"]),
        (
            "axial_force_pinion_mean_n",
            &s["helical"]["axial_force_pinion"]["mean_n"],
        ),
        ("k_h_beta", &s["face_load"]["k_h_beta"]),
        (
            "centre_of_pressure_mm",
            &s["face_load"]["centre_of_pressure_mm"],
        ),
    ];
    for (col, v) in pairs {
        same(num(row, col), f(v), &format!("case {case}, {col}"));
    }
    for k in 0..4 {
        same(
            num(row, &format!("mesh_harmonic{}_mm_per_s", k + 1)),
            f(&s["mesh_harmonics"]["velocity_y_pinion"][k]),
            &format!("case {case}, harmonic {}", k + 1),
        );
    }
}

/// The rows of a `--run run` sweep of the helical pair at 40 and 60 N m, into `dir/sw`.
fn two_torques(dir: &Path, run: &str) -> Vec<BTreeMap<String, String>> {
    let out = dir.join("sw");
    let mut a = HELICAL.to_vec();
    a.extend(["--run", run, "--vary", "operating.load_torque_nm=40,60"]);
    sweep(&a, &out);
    let t = rows(&out.join("sweep.csv"));
    assert_eq!(t.len(), 2);
    t
}

#[test]
fn each_dynamics_row_equals_gearwear_dynamics_on_its_case() {
    let d = tempfile::tempdir().unwrap();
    for row in &two_torques(d.path(), "dynamics") {
        let torque = &row["operating.load_torque_nm"];
        let s = single(d.path(), &format!("dyn{torque}"), &["dynamics"], torque);
        check_dynamics_columns(row, &s, torque);
        // The axial force is F tan(beta_b) along the pinion's angular velocity for its
        // right hand (the default; docs/MODEL.md 11.6), here from the row's own mean force.
        let axial = num(row, "axial_force_pinion_mean_n");
        assert!(axial > 0.0, "{axial}");
        let tan_bb = f(&s["helical"]["base_helix_angle_deg"]).to_radians().tan();
        let fm = num(row, "mesh_force_mean_n");
        // beta_b passes through degrees in summary.json (a few ulps): 1e-9 of F is far
        // above that and far below any other law (a cos or sin of beta_b is 3 % off).
        assert!((axial - fm * tan_bb).abs() <= 1e-9 * fm, "{axial} {fm}");
    }
}

#[test]
fn each_wear_row_equals_gearwear_wear_and_dynamics_on_its_case() {
    let d = tempfile::tempdir().unwrap();
    for row in &two_torques(d.path(), "wear") {
        let torque = &row["operating.load_torque_nm"];
        // The new teeth's columns: the first update of the dynamic wear run is the steady
        // state `gearwear dynamics` computes.
        let s = single(d.path(), &format!("dyn{torque}"), &["dynamics"], torque);
        check_dynamics_columns(row, &s, torque);
        let w = single(
            d.path(),
            &format!("wear{torque}"),
            &["wear", "--mode", "both"],
            torque,
        );
        for mode in ["dynamic", "quasi_static"] {
            let map = &w["wear_map"][mode];
            for flank in ["pinion", "gear"] {
                let what = format!("case {torque}, {mode} {flank}");
                same(
                    num(row, &format!("wear_max_{flank}_{mode}_um")),
                    f(&map[flank]["max_wear_um"]),
                    &what,
                );
                same(
                    num(row, &format!("wear_map_deepest_{flank}_position_{mode}_mm")),
                    f(&map[flank]["max_wear_position_mm"]),
                    &what,
                );
            }
            same(
                num(row, &format!("wear_updates_{mode}")),
                f(&w["updates"][mode]),
                &format!("case {torque}, {mode} updates"),
            );
            let cycles = w["cycles"].as_array().unwrap().last().unwrap();
            same(
                num(row, &format!("wear_cycles_{mode}")),
                f(cycles),
                "cycles",
            );
        }
    }
}

#[test]
fn the_spur_row_of_a_helix_angle_sweep_is_a_spur_sweeps_bit_for_bit() {
    // The case at beta = 0 is built by the spur model itself (`Model::dynamics_from_case`),
    // so its numbers are a spur sweep's to the last bit (compared as the CSV's text); its
    // helical columns are empty (a spur pair has no slice model). Without the crowning,
    // which a spur pair does not take.
    let d = tempfile::tempdir().unwrap();
    let common = [
        "--set",
        "stiffness.slices=8",
        "--set",
        "wear.total_cycles=2e4",
    ];
    let mixed = d.path().join("mixed");
    let mut a = common.to_vec();
    a.extend(["--run", "wear", "--vary", "gear.helix_angle_deg=0,15"]);
    sweep(&a, &mixed);
    let spur = d.path().join("spur");
    let mut a = common.to_vec();
    a.extend(["--run", "wear", "--vary", "operating.load_torque_nm=60"]);
    sweep(&a, &spur);
    let (m, s) = (
        rows(&mixed.join("sweep.csv")),
        rows(&spur.join("sweep.csv")),
    );
    let (h_spur, _) = read_csv(&spur.join("sweep.csv"));
    for col in h_spur
        .iter()
        .filter(|c| c.as_str() != "operating.load_torque_nm")
    {
        assert_eq!(m[0][col], s[0][col], "column {col}");
    }
    for col in [
        "total_contact_ratio",
        "axial_force_pinion_mean_n",
        "k_h_beta",
    ] {
        assert_eq!(m[0][col], "", "spur row, {col}");
        assert!(num(&m[1], col).is_finite() || col == "k_h_beta", "{col}");
    }
    // Without lead keys the helical row has no face load (as `gearwear dynamics`).
    assert_eq!(m[1]["k_h_beta"], "");
    // The helical case differs: its mesh is stiffer and smoother (epsilon_gamma 2.36).
    assert!(num(&m[1], "total_contact_ratio") > 2.0);
    assert!(num(&m[1], "dynamic_factor") < num(&m[0], "dynamic_factor"));

    // Rerun: every case is skipped (its record verified by recomputing a sample, the spur
    // case's empty helical columns included) and the table is the same bytes; two shards
    // merged give it too.
    let before = std::fs::read(mixed.join("sweep.csv")).unwrap();
    let mut a = common.to_vec();
    a.extend(["--run", "wear", "--vary", "gear.helix_angle_deg=0,15"]);
    let err = sweep(&a, &mixed);
    assert!(err.contains("2 skipped"), "{err}");
    assert_eq!(std::fs::read(mixed.join("sweep.csv")).unwrap(), before);
    let mut dirs = Vec::new();
    for s in ["1/2", "2/2"] {
        let dir = d.path().join(format!("shard{}", &s[..1]));
        let mut x = a.clone();
        x.extend(["--shard", s]);
        sweep(&x, &dir);
        dirs.push(dir.to_str().unwrap().to_owned());
    }
    let merged = d.path().join("merged");
    let mut m = vec!["sweep-merge", "--out", merged.to_str().unwrap()];
    m.extend(dirs.iter().map(String::as_str));
    ok(&m);
    assert_eq!(std::fs::read(merged.join("sweep.csv")).unwrap(), before);
}

#[test]
fn a_helical_sweep_refuses_what_its_model_does_not_take() {
    // Per-tooth errors in a wear sweep (a helical pair's teeth do not wear tooth by tooth
    // yet; a dynamics sweep takes them, docs/MODEL.md 11.9), named with the case, before
    // any case runs.
    rejected(
        &[
            "sweep",
            "--run",
            "wear",
            "--set",
            "gear.helix_angle_deg=15",
            "--set",
            "teeth.accuracy_grade=6",
            "--vary",
            "operating.input_speed_hz=20,30",
        ],
        &["[teeth]", "gear.helix_angle_deg", "case 0"],
    );
}

#[test]
fn a_rerun_whose_plan_adds_or_drops_the_helical_columns_recomputes_the_kept_case() {
    // A sweep of helix 0 then, into the same folder, of 0 and 15: the kept spur record
    // has no helical columns, which the new table has; reused as it was, its row would
    // not fit the header (the table could not be written). It is recomputed, and the
    // row equals the first run's numbers. Back to 0 alone: the record with the (empty)
    // helical columns is recomputed again, and the table is a fresh spur sweep's.
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    let vary = |v: &str| vec!["--vary".to_owned(), format!("gear.helix_angle_deg={v}")];
    let run = |v: &str, dir: &Path| {
        let a = vary(v);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        sweep(&a, dir)
    };
    run("0", &out);
    let first = rows(&out.join("sweep.csv"));
    let err = run("0,15", &out);
    assert!(err.contains("0 already finished"), "{err}");
    let both = rows(&out.join("sweep.csv"));
    assert_eq!(both.len(), 2);
    assert_eq!(both[0]["total_contact_ratio"], "");
    for (col, v) in &first[0] {
        assert_eq!(&both[0][col], v, "column {col}");
    }
    assert!(num(&both[1], "total_contact_ratio") > 2.0);
    run("0", &out);
    let fresh = d.path().join("fresh");
    run("0", &fresh);
    assert_eq!(
        std::fs::read(out.join("sweep.csv")).unwrap(),
        std::fs::read(fresh.join("sweep.csv")).unwrap()
    );
}
