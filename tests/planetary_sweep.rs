//! `gearwear sweep --run dynamics` on a planetary set (`examples/planetary_set.toml`):
//! every column of a row is `gearwear dynamics`' summary.json of the row's case (run on
//! its own, an independent path through the application); a key the set does not use
//! gives identical rows; a case with another number of planets and a continuation are
//! refused with exit 2 before any case runs (a wear sweep of a set:
//! tests/planetary_wear_sweep.rs).

mod common;
use common::{gearwear, read_csv, rejected, stderr};
use std::path::{Path, PathBuf};

fn config() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/planetary_set.toml")
        .to_string_lossy()
        .into_owned()
}

fn ok(args: &[&str]) {
    let o = gearwear(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
}

/// `gearwear sweep --run dynamics` of the example over `vary` into `out`: its header and
/// rows.
fn sweep(vary: &str, out: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let c = config();
    let o = out.to_str().unwrap();
    ok(&[
        "-q", "sweep", "--config", &c, "--run", "dynamics", "--vary", vary, "--out", o,
    ]);
    read_csv(&out.join("sweep.csv"))
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Equal to 1e-12 relative: both are the same computation's numbers, the CSV's written
/// to round trip exactly, so only a difference of program path could part them.
fn same(got: &str, want: f64, what: &str) {
    let g: f64 = got.parse().unwrap_or_else(|_| panic!("{what}: `{got}`"));
    assert!(
        (g - want).abs() <= 1e-12 * want.abs(),
        "{what}: sweep {g}, dynamics {want}"
    );
}

#[test]
fn every_column_of_a_planetary_row_is_the_dynamics_summary_of_its_case() {
    let d = tempfile::tempdir().unwrap();
    let (h, rows) = sweep("operating.load_torque_nm=100,150", &d.path().join("sweep"));
    assert_eq!(rows.len(), 2);
    let col = |name: &str| {
        h.iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column {name} in {h:?}"))
    };
    for (row, torque) in rows.iter().zip(["100", "150"]) {
        let out = d.path().join(format!("dynamics_{torque}"));
        let set = format!("operating.load_torque_nm={torque}");
        ok(&[
            "-q",
            "dynamics",
            "--config",
            &config(),
            "--set",
            &set,
            "--out",
            out.to_str().unwrap(),
        ]);
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap())
                .unwrap();
        let p = &s["planetary_dynamics"];
        let nominal = num(&p["nominal_mesh_force_n"]);
        let meshes = p["meshes"].as_array().unwrap();
        assert_eq!(meshes.len(), 8);
        for m in meshes {
            // `sun_planet_1` in the summary, `sun_planet1_` as a column prefix.
            let prefix = m["mesh"].as_str().unwrap().replace("planet_", "planet");
            let max = num(&m["max_force_n"]);
            same(
                &row[col(&format!("{prefix}_mesh_force_mean_n"))],
                num(&m["mean_force_n"]),
                &prefix,
            );
            same(
                &row[col(&format!("{prefix}_mesh_force_max_n"))],
                max,
                &prefix,
            );
            // The dynamic factor: largest force over the nominal (docs/MODEL.md 12.6), as
            // the summary's dynamic_factor_sun_planet is over the sun meshes.
            same(
                &row[col(&format!("{prefix}_dynamic_factor"))],
                max / nominal,
                &prefix,
            );
        }
        for (n, l) in p["load_sharing_factor"]
            .as_array()
            .unwrap()
            .iter()
            .enumerate()
        {
            same(
                &row[col(&format!("planet{}_load_sharing_factor", n + 1))],
                num(l),
                "share",
            );
        }
        // The pair's columns are the first sun-planet mesh's; the set has no DTE.
        same(
            &row[col("mesh_force_mean_n")],
            num(&meshes[0]["mean_force_n"]),
            "pair mean",
        );
        same(
            &row[col("dynamic_factor")],
            num(&meshes[0]["max_force_n"]) / nominal,
            "pair factor",
        );
        assert_eq!(row[col("dte_max_um")], "", "no DTE for a set");
    }
    // The larger torque loads every mesh more (a sanity check of the rows' order).
    let first = col("sun_planet1_mesh_force_mean_n");
    let f = |r: &Vec<String>| r[first].parse::<f64>().unwrap();
    assert!(f(&rows[1]) > f(&rows[0]));
}

#[test]
fn a_key_the_set_does_not_use_gives_identical_rows() {
    // `[gear]` is the single pair's; a planetary case does not use it (docs/MODEL.md 12.4).
    let d = tempfile::tempdir().unwrap();
    let (h, rows) = sweep("gear.teeth_pinion=19,21", &d.path().join("sweep"));
    assert_eq!(rows.len(), 2);
    let first = h.iter().position(|c| c == "case_id").unwrap() + 1;
    assert_eq!(rows[0][first..], rows[1][first..]);
}

#[test]
fn other_planet_counts_and_continuations_are_refused() {
    let c = config();
    // 23 + 85 = 108 assembles three and four planets alike: both are valid sets.
    let e = rejected(
        &["sweep", "--config", &c, "--vary", "planetary.planets=3,4"],
        &[
            "case 0 (planetary.planets=3) has 3 planet(s)",
            "the base case 4",
        ],
    );
    assert!(e.contains("planetary.planets"), "{e}");
    rejected(
        &[
            "sweep",
            "--config",
            &c,
            "--continuation",
            "both",
            "--vary",
            "operating.input_speed_hz=20,25,30",
        ],
        &["--continuation", "planetary set"],
    );
}

#[test]
fn a_helix_angle_on_a_planetary_set_is_refused_not_run_as_spur() {
    // The set's meshes are spur (helical sets are not built): a helix angle would be
    // ignored, so `dynamics` and a sweep varying it refuse it, naming the key.
    let c = config();
    for args in [
        vec![
            "dynamics",
            "--config",
            &c,
            "--set",
            "gear.helix_angle_deg=15",
        ],
        vec![
            "sweep",
            "--config",
            &c,
            "--vary",
            "gear.helix_angle_deg=0,15",
        ],
    ] {
        rejected(&args, &["`gear.helix_angle_deg` = 15", "[planetary]"]);
    }
}
