//! A planetary set's lumped parameters derived from its geometry (docs/MODEL.md 12.4):
//! each derived mass and inertia against the hollow-cylinder formula computed here from
//! the set's radii by hand, the derived run against the same values written into
//! `[planetary.lumped]` (a second path through the case file), a partial table (the given
//! key wins, the rest derived), and a derived key out of range refused naming it.

mod common;

use common::planetary::run_case;
use common::rejected;
use serde_json::Value;
use std::f64::consts::PI;
use std::path::Path;

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// (mass kg, polar inertia kg m^2) of a steel (7850 kg/m^3, `dynamics.blank_density`'s
/// default) hollow cylinder of width `b` between radii `ri` and `ro` (m):
/// rho pi b (ro^2 - ri^2) and m (ro^2 + ri^2) / 2.
fn cylinder(ri: f64, ro: f64, b: f64) -> (f64, f64) {
    let m = 7850.0 * PI * b * (ro * ro - ri * ri);
    (m, m * (ro * ro + ri * ri) / 2.0)
}

/// Relative difference.
fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

#[test]
fn derived_masses_and_inertias_are_the_bodies_hand_formulas() {
    // The default set: 24 / 30 / 84 teeth, module 2 mm, face 20 mm, no profile shift,
    // dedendum 1.25 modules: reference radii 24, 30 and 84 mm, ring root radius
    // 84 + 1.25 x 2 = 86.5 mm, carrier radius (24 + 30) = 54 mm.
    let (_d, s) = run_case("stiffness", "[planetary]\n");
    let v = &s["planetary"]["lumped_parameters"]["values"];
    let (m, b) = (2e-3, 20e-3);
    let (r_s, r_p, r_rf, r_c) = (24e-3, 30e-3, 86.5e-3, 54e-3);
    let bodies = [
        // Sun and planet: solid disks out to the reference radius.
        ("sun", cylinder(0.0, r_s, b)),
        ("planet", cylinder(0.0, r_p, b)),
        // Ring: root circle out to a 3.5-module rim (ISO 6336-3's Y_B = 1 rim).
        ("ring", cylinder(r_rf, r_rf + 3.5 * m, b)),
        // Carrier: two plates b/2 thick (one face width together), radius r_c + r_p.
        ("carrier", cylinder(0.0, r_c + r_p, b)),
    ];
    // 1e-12: the program's radii come through the geometry's own arithmetic (m z / 2,
    // r + m (h_f - x), the operating centre distance at zero shift), a few roundings.
    for (name, (mass, inertia)) in bodies {
        let got_m = f(&v[format!("mass_{name}_kg")]);
        let got_j = f(&v[format!("inertia_{name}_kg_m2")]);
        assert!(rel(got_m, mass) < 1e-12, "{name}: {got_m} vs {mass}");
        assert!(rel(got_j, inertia) < 1e-12, "{name}: {got_j} vs {inertia}");
    }
    // Radii: base radii r cos 20 deg and the carrier radius, in mm.
    let c = 20f64.to_radians().cos();
    for (key, want) in [
        ("base_radius_sun_mm", 24.0 * c),
        ("base_radius_planet_mm", 30.0 * c),
        ("base_radius_ring_mm", 84.0 * c),
        ("carrier_radius_mm", 54.0),
    ] {
        assert!(rel(f(&v[key]), want) < 1e-12, "{key}: {} vs {want}", v[key]);
    }
    // Supports as the pair's `[dynamics]` defaults: bearings 5e8 N/m; sun in (motor
    // coupling 4e7), carrier out (load coupling 4e7), ring fixed (100 x 4e7).
    for key in ["sun", "planet", "ring", "carrier"] {
        assert_eq!(f(&v[format!("bearing_stiffness_{key}_n_per_m")]), 5e8);
    }
    assert_eq!(f(&v["torsional_stiffness_sun_nm_per_rad"]), 4e7);
    assert_eq!(f(&v["torsional_stiffness_carrier_nm_per_rad"]), 4e7);
    assert_eq!(f(&v["torsional_stiffness_ring_nm_per_rad"]), 4e9);
    // The mean mesh stiffnesses are the meshes' own (reported beside them).
    let p = &s["planetary"];
    assert_eq!(
        v["mesh_stiffness_sun_planet_n_per_m"],
        p["mesh_stiffness_sun_planet"]["mean_n_per_m"]
    );
    assert_eq!(
        v["mesh_stiffness_ring_planet_n_per_m"],
        p["mesh_stiffness_ring_planet"]["mean_n_per_m"]
    );
    // The modal table is given without [planetary.lumped]: 3 (N + 3) = 21 coordinates.
    let freqs = p["modes"]["undamped_natural_frequencies_hz"]
        .as_array()
        .unwrap();
    assert_eq!(freqs.len(), 21);
}

/// The derived values of `s` written as a `[planetary.lumped]` table (`{:?}`: the
/// shortest text that reads back as the same f64).
fn lumped_table(values: &Value) -> String {
    let mut t = String::from("[planetary.lumped]\n");
    for (k, v) in values.as_object().unwrap() {
        t += &format!("{k} = {:?}\n", f(v));
    }
    t
}

/// Every CSV of the run folder `dir`, by name.
fn csvs(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .map(|p| (p.display().to_string(), std::fs::read(&p).unwrap()))
        .map(|(p, b)| (p.rsplit('/').next().unwrap().to_owned(), b))
        .collect();
    v.sort();
    v
}

#[test]
fn derived_values_written_into_the_table_give_the_same_dynamics() {
    let (d1, s1) = run_case("dynamics", "[planetary]\n");
    let values = &s1["planetary_dynamics"]["lumped_parameters"]["values"];
    let (d2, s2) = run_case(
        "dynamics",
        &format!("[planetary]\n{}", lumped_table(values)),
    );
    let (mut p1, mut p2) = (
        s1["planetary_dynamics"].clone(),
        s2["planetary_dynamics"].clone(),
    );
    // Only the record of which keys were derived differs (all of them, then none).
    assert_eq!(
        p2["lumped_parameters"]["derived_keys"],
        Value::Array(vec![])
    );
    p1["lumped_parameters"]["derived_keys"] = Value::Null;
    p2["lumped_parameters"]["derived_keys"] = Value::Null;
    assert_eq!(p1, p2);
    let (c1, c2) = (csvs(&d1.path().join("out")), csvs(&d2.path().join("out")));
    assert!(!c1.is_empty());
    assert_eq!(c1, c2, "the CSVs differ");
}

#[test]
fn a_partial_table_keeps_its_key_and_derives_the_rest() {
    let (_d, all) = run_case("stiffness", "[planetary]\n");
    let (_e, one) = run_case(
        "stiffness",
        "[planetary]\n[planetary.lumped]\nmass_sun_kg = 1.5\ninertia_ring_kg_m2 = \"derived\"\n",
    );
    let lp = |s: &Value| s["planetary"]["lumped_parameters"].clone();
    let (all, one) = (lp(&all), lp(&one));
    for (k, v) in all["values"].as_object().unwrap() {
        let want = if k == "mass_sun_kg" {
            &Value::from(1.5)
        } else {
            v
        };
        assert_eq!(&one["values"][k], want, "{k}");
    }
    let derived = one["derived_keys"].as_array().unwrap();
    assert_eq!(derived.len(), 21);
    assert!(!derived.contains(&Value::from("mass_sun_kg")));
}

#[test]
fn a_lumped_key_out_of_range_exits_2_naming_it() {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("case.toml");
    std::fs::write(
        &case,
        "[planetary]\n[planetary.lumped]\nbearing_stiffness_planet_n_per_m = 0\n",
    )
    .unwrap();
    rejected(
        &["stiffness", "--config", case.to_str().unwrap()],
        &["planetary.lumped.bearing_stiffness_planet_n_per_m", "0"],
    );
}

#[test]
fn signals_run_on_the_default_set_alone_and_report_the_values_used() {
    // `[planetary]` with nothing else: the sensor on the ring hears the derived set; the
    // values it used are those `gearwear stiffness` derives for the same set.
    let (_d, sig) = run_case("signals", "[planetary]\n");
    let (_e, st) = run_case("stiffness", "[planetary]\n");
    assert_eq!(
        sig["planetary_signals"]["lumped_parameters"],
        st["planetary"]["lumped_parameters"]
    );
}
