//! `gearwear dynamics` on a planetary set with planet pin position errors and a floating
//! sun (`planetary.planet_tangential_error_um`, `planet_radial_error_um`,
//! `floating_sun`): the statics fact of a floating sun with three planets (equal shares
//! whatever the error, Kahraman 1994; Bodas & Kahraman 2004) in the quasi-static and the
//! dynamic steady state, unequal shares with four, and bad inputs exiting 2 naming the
//! key. The shares' values are checked against a hand calculation in
//! `src/dynamics/tests_planetary_load_sharing.rs`.

mod common;

use common::planetary::lin_parker_lumped;
use common::{gearwear, read_csv, rejected, stderr};

/// Carrier torsional support (the output's shaft to the load), N m/rad.
const CARRIER_SHAFT: f64 = 1e6;

/// A case file of the 24 / 30 / 84 set with `n` planets ((24 + 84) / n whole for 3, 4).
fn case_file(dir: &std::path::Path, n: usize) -> String {
    let p = dir.join(format!("case{n}.toml"));
    let text = format!(
        "[planetary]\nplanets = {n}\nteeth_sun = 24\nteeth_planet = 30\nteeth_ring = 84\nmodule_mm = 2.0\n{}",
        lin_parker_lumped(CARRIER_SHAFT)
    );
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

/// The summary's `planetary_dynamics` and the rows of `load_sharing.csv` of a run.
fn run(n: usize, sets: &[&str]) -> (serde_json::Value, Vec<String>, Vec<Vec<String>>) {
    let d = tempfile::tempdir().unwrap();
    let case = case_file(d.path(), n);
    let out = d.path().join("out");
    let mut args = vec!["dynamics", "-q", "--config", &case];
    for s in sets {
        args.extend(["--set", s]);
    }
    args.extend(["--out", out.to_str().unwrap()]);
    let o = gearwear(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let (names, rows) = read_csv(&out.join("load_sharing.csv"));
    (s["planetary_dynamics"].clone(), names, rows)
}

fn numbers(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[test]
fn a_floating_sun_equalises_three_planets_in_statics_and_dynamics_not_four() {
    let (p, names, rows) = run(
        3,
        &[
            "planetary.planet_tangential_error_um=[20, 0, 0]",
            "planetary.floating_sun=true",
        ],
    );
    // Static: the sun's three balances fix the three forces (rounding only, 1e-9).
    for l in numbers(&p["load_sharing_factor_static"]) {
        assert!((l - 1.0).abs() < 1e-9, "{p}");
    }
    // Dynamic means: the sun's lateral inertia force has zero mean over a steady period,
    // so the same balances hold for the means; the tolerance is the means' integration
    // error (1e-4, as in tests/planetary_dynamics_cli.rs).
    for key in ["load_sharing_factor", "load_sharing_factor_ring"] {
        for l in numbers(&p[key]) {
            assert!((l - 1.0).abs() < 1e-4, "{key}: {p}");
        }
    }
    assert_eq!(p["floating_sun"], true);
    assert_eq!(numbers(&p["planet_tangential_error_um"]), [20.0, 0.0, 0.0]);
    // The table holds the summary's numbers, one row per planet.
    assert_eq!(rows.len(), 3);
    let j = names.iter().position(|c| c == "static_share").unwrap();
    for (r, l) in rows.iter().zip(numbers(&p["load_sharing_factor_static"])) {
        assert_eq!(r[j].parse::<f64>().unwrap(), l);
    }

    // Four planets: the floating sun cannot equalise (four forces, three balances); the
    // +20 um planet, held back from the sun's drive, carries less than 1/N (at 60 N m the
    // preload of 20 um is a large part of its load: more than 5 % off).
    for floating in ["true", "false"] {
        let (p, _, _) = run(
            4,
            &[
                "planetary.planet_tangential_error_um=[20, 0, 0, 0]",
                &format!("planetary.floating_sun={floating}"),
            ],
        );
        let l = numbers(&p["load_sharing_factor_static"]);
        assert!(l[0] < 0.95, "floating {floating}: {l:?}");
        let d = numbers(&p["load_sharing_factor"]);
        assert!(d[0] < 0.95, "floating {floating}: {d:?}");
    }
}

#[test]
fn bad_pin_errors_exit_2_naming_the_key() {
    let d = tempfile::tempdir().unwrap();
    let case = case_file(d.path(), 4);
    let args = |set: &'static str| ["dynamics", "--config", case.as_str(), "--set", set];
    rejected(
        &args("planetary.planet_tangential_error_um=[20, 0, 0]"),
        &[
            "planetary.planet_tangential_error_um",
            "3 values",
            "one per planet",
        ],
    );
    rejected(
        &args("planetary.planet_radial_error_um=[nan, 0, 0, 0]"),
        &["planetary.planet_radial_error_um", "[-1000, 1000]"],
    );
    rejected(
        &args("planetary.planet_tangential_error_um=[0, 0, 2000, 0]"),
        &[
            "planetary.planet_tangential_error_um",
            "2000",
            "[-1000, 1000]",
        ],
    );
    // 500 um at 60 N m: planet 1's preload exceeds its share of the load, its meshes
    // would open (a planet held by nothing in a model without back flanks).
    rejected(
        &args("planetary.planet_tangential_error_um=[500, 0, 0, 0]"),
        &[
            "planetary.planet_tangential_error_um",
            "planet 1",
            "no load",
        ],
    );
    rejected(
        &args("planetary.floating_sun=3"),
        &["planetary.floating_sun", "true or false"],
    );
}
