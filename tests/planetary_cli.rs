//! A planetary set through the case file (`[planetary]`, `[planetary.lumped]`):
//! `gearwear stiffness` writes the set's geometry, kinematics, mesh stiffness and phases
//! and the lumped model's natural frequencies; checked against closed forms, the spur
//! study of the same sun-planet pair and Lin & Parker's (1999) published Table 2. Every
//! study on the dynamic model that is not built for a set refuses it (`dynamics`, `signals`,
//! `wear`, `run` and `sweep --run dynamics` take it), and bad sets exit 2 naming the key.

mod common;

use common::planetary::lin_parker_lumped;
use common::{gearwear, rejected, stderr, studies_on_the_dynamic_model};
use std::path::Path;

/// A four-planet 24 / 30 / 84 set, module 2 mm (the section's defaults, written out).
const SET: &str = "[planetary]\nplanets = 4\nteeth_sun = 24\nteeth_planet = 30\nteeth_ring = 84\nmodule_mm = 2.0\n";

fn write_case(dir: &Path, text: &str) -> String {
    let p = dir.join("case.toml");
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

fn run_ok(args: &[&str]) {
    let o = gearwear(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
}

/// `gearwear stiffness` on the case `text`: its folder (kept alive) and `summary.json`.
fn stiffness_of(text: &str) -> (tempfile::TempDir, serde_json::Value) {
    let d = tempfile::tempdir().unwrap();
    let case = write_case(d.path(), text);
    let out = d.path().join("out");
    run_ok(&[
        "stiffness",
        "-q",
        "--config",
        &case,
        "--out",
        out.to_str().unwrap(),
    ]);
    let s = summary(&out);
    (d, s)
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn stiffness_writes_the_sets_kinematics_geometry_and_meshes() {
    let (d, s) = stiffness_of(SET);
    let p = &s["planetary"];
    // Sun in at 30 Hz, ring fixed: Willis gives f_c = f_s z_s / (z_s + z_r) = 30 * 24 / 108;
    // the mesh frequency z_r f_c, the planet pass N f_c, the ratio 1 + z_r / z_s = 4.5.
    // Closed forms in a few operations: 1e-12 relative.
    let k = &p["kinematics"];
    let fc = 30.0 * 24.0 / 108.0;
    for (key, want) in [
        ("speed_carrier_hz", fc),
        ("speed_ring_hz", 0.0),
        ("mesh_frequency_hz", 84.0 * fc),
        ("planet_pass_frequency_hz", 4.0 * fc),
        ("ratio_input_to_output", 4.5),
        (
            "speed_planet_relative_to_carrier_hz",
            -(30.0 - fc) * 24.0 / 30.0,
        ),
    ] {
        assert!(
            (f(&k[key]) - want).abs() <= 1e-12 * want.abs().max(1.0),
            "{key}: {k}"
        );
    }
    // Standard gears: the carrier radius m (z_s + z_p) / 2 = 54 mm, both meshes at 20 deg;
    // equally spaced planets at 90 deg steps; z_s / N = 6 whole: every sun mesh in phase,
    // and the even z_p puts the ring mesh half a cycle from the sun mesh (Parker & Lin 2004).
    let g = &p["geometry"];
    assert!((f(&g["carrier_radius_mm"]) - 54.0).abs() < 1e-9, "{g}");
    assert!((f(&g["operating_pressure_angle_ring_planet_deg"]) - 20.0).abs() < 1e-9);
    let angles: Vec<f64> = g["planet_angles_deg"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    assert_eq!(angles, [0.0, 90.0, 180.0, 270.0]);
    let ph = &p["mesh_phases"];
    assert!(ph["sun_planet_cycles"]
        .as_array()
        .unwrap()
        .iter()
        .all(|v| f(v) == 0.0));
    assert!((f(&ph["ring_to_sun_cycles"]) - 0.5).abs() < 1e-12, "{ph}");
    // No [planetary.lumped]: every lumped value derived from the geometry, the modes
    // given (3 (N + 3) = 21 coordinates).
    let freqs = p["modes"]["undamped_natural_frequencies_hz"]
        .as_array()
        .unwrap();
    assert_eq!(freqs.len(), 21);
    // The sun-planet mesh is the spur pair 24 / 30 of the same module and face width: the
    // spur study (without the fillet foundation, as the planetary meshes) gives the same
    // mean stiffness, through another path (1e-9: the same tables, summed alike).
    let spur = d.path().join("spur");
    run_ok(&[
        "stiffness",
        "-q",
        "--out",
        spur.to_str().unwrap(),
        "--set",
        "gear.teeth_pinion=24",
        "--set",
        "gear.teeth_gear=30",
        "--set",
        "stiffness.fillet_foundation=false",
    ]);
    let spur_mean = f(&summary(&spur)["mesh_stiffness"]["mean_n_per_m"]);
    let sun = &p["mesh_stiffness_sun_planet"];
    assert!(
        (f(&sun["mean_n_per_m"]) / spur_mean - 1.0).abs() < 1e-9,
        "{sun} vs {spur_mean}"
    );
    // The ring mesh: its extremes bracket its mean.
    let ring = &p["mesh_stiffness_ring_planet"];
    assert!(f(&ring["min_n_per_m"]) < f(&ring["mean_n_per_m"]));
    assert!(f(&ring["mean_n_per_m"]) < f(&ring["max_n_per_m"]));
}

#[test]
fn stiffness_gives_lin_and_parkers_natural_frequencies_for_a_lumped_set() {
    let (_d, s) = stiffness_of(&format!("{SET}\n{}", lin_parker_lumped(0.0)));
    let m = &s["planetary"]["modes"];
    let freqs: Vec<f64> = m["undamped_natural_frequencies_hz"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    let classes: Vec<&str> = m["mode_classes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(freqs.len(), 21);
    // Lin & Parker (1999) Table 2, N = 4, every mode listed with its multiplicity.
    let mut table: Vec<(f64, &str)> = Vec::new();
    for hz in [0.0, 1536.6, 1970.6, 2625.7, 7773.6, 13071.1] {
        table.push((hz, "rotational"));
    }
    for hz in [727.0, 1091.0, 1892.8, 2342.5, 7189.9, 10437.6] {
        table.extend([(hz, "translational"); 2]);
    }
    for hz in [1808.2, 5963.8, 6981.7] {
        table.push((hz, "planet"));
    }
    table.sort_by(|a, b| a.0.total_cmp(&b.0));
    for ((got, class), (want, want_class)) in freqs.iter().zip(&classes).zip(&table) {
        assert_eq!(class, want_class, "{got} Hz");
        // As the library's comparison (dynamics::tests_planetary_published): the print's
        // half unit (0.05 Hz, 0.5 Hz for the values transcribed as whole hertz) plus 2e-5
        // of the frequency; the case file's inertias carry 17 digits, far below that.
        let half_unit = if want.fract() == 0.0 { 0.5 } else { 0.05 };
        assert!(
            (got - want).abs() <= half_unit + 2e-5 * want,
            "{got} vs {want}"
        );
    }
}

#[test]
fn studies_on_the_dynamic_model_refuse_a_planetary_case() {
    // `gearwear dynamics`, `gearwear signals`, `gearwear wear`, `gearwear run` and
    // `gearwear sweep` (of dynamics and of wear) take a planetary set
    // (tests/planetary_dynamics_cli.rs, tests/planetary_signals_cli.rs,
    // tests/planetary_wear.rs, tests/planetary_run.rs, tests/planetary_sweep.rs,
    // tests/planetary_wear_sweep.rs); every other study on the dynamic model in
    // `studies_on_the_dynamic_model` does.
    let taken = ["dynamics", "signals", "wear", "run", "sweep"];
    for cmd in studies_on_the_dynamic_model() {
        assert!(taken.contains(&cmd[0]), "{cmd:?}: is it refused?");
    }
}

#[test]
fn bad_sets_exit_2_naming_the_key() {
    let d = tempfile::tempdir().unwrap();
    let bad = |text: &str, needles: &[&str]| {
        let case = write_case(d.path(), text);
        rejected(&["stiffness", "--config", &case], needles);
    };
    // (25 + 85) / 4 is not whole: no equal spacing.
    bad(
        "[planetary]\nplanets = 4\nteeth_sun = 25\nteeth_planet = 30\nteeth_ring = 85\n",
        &["planetary.planets", "assembly condition"],
    );
    // z_r below z_s + 2 z_p = 84.
    bad(
        "[planetary]\nteeth_ring = 80\n",
        &["planetary.teeth_ring", "too small", "84"],
    );
    // Nine planets on a 54 mm carrier radius: centres 36.9 mm apart, tips 64 mm across.
    bad(
        "[planetary]\nplanets = 9\n",
        &["planetary.planets", "collide"],
    );
    bad(
        "[planetary]\ninput = \"ring\"\n",
        &["planetary.input", "\"ring\"", "fixed"],
    );
    bad(
        "[planetary]\nplanet_angles_deg = [0, 180, 90, 270]\n",
        &["planetary.planet_angles_deg", "increase"],
    );
    bad(
        "[planetary]\nteeth_moon = 3\n",
        &["[planetary]", "teeth_moon"],
    );
    bad(
        "[planetary]\nmodule_mm = -2\n",
        &["planetary.module_mm", "-2"],
    );
    // A lumped set with a negative mass.
    let lumped = lin_parker_lumped(0.0).replace("mass_sun_kg = 0.4", "mass_sun_kg = -0.4");
    bad(
        &format!("{SET}\n{lumped}"),
        &["planetary.lumped.mass_sun_kg", "-0.4", "(0, 1e6]"],
    );
}

#[test]
fn a_lumped_key_set_on_the_command_line_equals_the_key_in_the_file() {
    use gearwear::config::load_case;
    // Second method: the value written in the file's [planetary.lumped] table.
    let file = format!("{SET}{}", lin_parker_lumped(1e6));
    let written = file.replace("mass_sun_kg = 0.4", "mass_sun_kg = 0.5");
    let by_set = load_case(&file, &["planetary.lumped.mass_sun_kg=0.5".into()]).unwrap();
    assert_eq!(by_set, load_case(&written, &[]).unwrap());
    assert_ne!(by_set, load_case(&file, &[]).unwrap());
    // Its range is the schema's, checked as for a key in the file.
    let e = load_case(&file, &["planetary.lumped.mass_sun_kg=-1".into()])
        .unwrap_err()
        .to_string();
    assert!(e.contains("planetary.lumped.mass_sun_kg"), "{e}");
}
