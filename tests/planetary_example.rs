//! `examples/planetary_set.toml`, the README's four-planet set: it reads as a planetary
//! case whose teeth meet the conditions its comments state (checked here by hand, not by
//! the program's geometry), the README names it, and `gearwear stiffness` and `gearwear
//! dynamics` run it with the kinematics and the static torque split that Willis' equation
//! and a torque balance give.

mod common;

use common::planetary::run_case;
use gearwear::config::load_case;

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn example() -> String {
    std::fs::read_to_string(root().join("examples/planetary_set.toml")).unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn the_example_is_a_four_planet_set_that_assembles_and_the_readme_names_it() {
    let case = load_case(&example(), &[]).unwrap_or_else(|e| panic!("{:?}", e.problems));
    let p = case.planetary.expect("a [planetary] case");
    assert_eq!(p.planets, 4);
    assert!(p.planet_angles_deg.is_none(), "equally spaced");
    let (zs, zp, zr) = (p.teeth_sun, p.teeth_planet, p.teeth_ring);
    // Unshifted gears on one centre distance: z_r = z_s + 2 z_p.
    assert_eq!(zr, zs + 2 * zp);
    // Assembly of equally spaced planets: (z_s + z_r) / N a whole number.
    assert_eq!((zs + zr) % p.planets, 0);
    // Neighbouring planets clear: 2 a sin(pi / N) above the tip diameter m (z_p + 2).
    let a_mm = p.module_mm * (zs + zp) as f64 / 2.0;
    let gap_mm = 2.0 * a_mm * (std::f64::consts::PI / p.planets as f64).sin();
    assert!(gap_mm > p.module_mm * (zp + 2) as f64, "{gap_mm}");
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    assert!(readme.contains("(examples/planetary_set.toml)"));
}

#[test]
fn its_stiffness_and_dynamics_run_with_willis_speeds_and_the_static_torque_split() {
    let text = example();
    let case = load_case(&text, &[]).unwrap();
    let p = case.planetary.clone().unwrap();
    let (zs, zr) = (p.teeth_sun as f64, p.teeth_ring as f64);
    let input_hz = case.operating.input_speed_hz;
    let (_d, s) = run_case("stiffness", &text);
    let k = &s["planetary"]["kinematics"];
    // Willis, ring fixed, sun in: f_c = f_s / (1 + z_r / z_s); mesh frequency z_r f_c;
    // planet pass N f_c (to rounding: 1e-12 relative).
    let carrier = input_hz / (1.0 + zr / zs);
    for (got, want) in [
        (f(&k["speed_carrier_hz"]), carrier),
        (f(&k["ratio_input_to_output"]), 1.0 + zr / zs),
        (f(&k["mesh_frequency_hz"]), zr * carrier),
        (f(&k["planet_pass_frequency_hz"]), 4.0 * carrier),
    ] {
        assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
    }
    let (_d, s) = run_case("dynamics", &text);
    let pd = &s["planetary_dynamics"];
    // Every mesh carries T_s / (N r_bs) on average, r_bs = m z_s cos(alpha) / 2; the
    // means are integrated with a midpoint rule to 1e-4 relative (as in
    // tests/planetary_dynamics_cli.rs).
    let r_bs = p.module_mm * 1e-3 * zs * p.pressure_angle_deg.to_radians().cos() / 2.0;
    let want = case.operating.load_torque_nm / (4.0 * r_bs);
    let meshes = pd["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 8);
    for m in meshes {
        assert!((f(&m["mean_force_n"]) / want - 1.0).abs() < 1e-4, "{m}");
    }
    for l in pd["load_sharing_factor"].as_array().unwrap() {
        assert!((f(l) - 1.0).abs() < 1e-4, "{l}");
    }
}
