//! `gearwear wear` on planetary sets other than sun in / ring fixed (docs/MODEL.md 12.9):
//! carrier in, sun out, ring fixed (a wind turbine's step-up), and ring in, sun out,
//! carrier fixed (a star set), checked against independent facts:
//! - the torque balance of the set in the quasi-static wear run's loads: the torque each
//!   member's meshes put on it (the sun's N sun-mesh forces times its base radius, the
//!   ring's N ring-mesh forces times its base radius) equals the input torque times the
//!   configuration's torque ratio, T_s : T_r : T_c = 1 : z_r / z_s : -(1 + z_r / z_s)
//!   (Willis, the planets in torque balance; the model has no friction), base radii by
//!   hand m z cos(alpha) / 2;
//! - identical, equally spaced planets without errors wear alike (both modes);
//! - the tooth contacts per input revolution equal Willis' kinematics by hand.

mod common;

use common::planetary::{run_case, run_case_with};
use std::f64::consts::PI;

/// The default set (24 / 30 / 84, four planets in phase, module 2 mm, 20 degrees) with the
/// configuration `io` (input, output, fixed), a torque `torque_nm` on the input member,
/// and a short wear study (2e4 input cycles in blocks of 1e4).
fn case(io: [&str; 3], torque_nm: f64, mode_cycles: (f64, f64)) -> String {
    format!(
        "[operating]\nload_torque_nm = {torque_nm}\n[planetary]\ninput = \"{}\"\noutput = \"{}\"\nfixed = \"{}\"\n[wear]\ntotal_cycles = {}\nblock_cycles = {}\n",
        io[0], io[1], io[2], mode_cycles.0, mode_cycles.1
    )
}

const ZS: f64 = 24.0;
const ZP: f64 = 30.0;
const ZR: f64 = 84.0;
const PLANETS: usize = 4;

/// Base radius of a member of `z` teeth, m: m z cos(alpha) / 2, m = 2 mm, alpha = 20 deg.
fn base_radius_m(z: f64) -> f64 {
    2e-3 * z * (20.0 * PI / 180.0).cos() / 2.0
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Every planet's final (depth µm, volume mm^3) in `mode` equals planet 1's within `tol`.
fn planets_alike(s: &serde_json::Value, mode: &str, tol: f64) {
    let members = s["planetary_wear"]["members"].as_array().unwrap();
    let planets: Vec<(f64, f64)> = members
        .iter()
        .filter(|m| m["member"].as_str().unwrap().starts_with("planet_"))
        .map(|m| {
            let fin = &m["final"][mode];
            (f(&fin["max_wear_um"]), f(&fin["volume_mm3"]))
        })
        .collect();
    assert_eq!(planets.len(), PLANETS);
    assert!(planets[0].0 > 0.0, "{mode}: the planets did not wear");
    for (i, p) in planets.iter().enumerate() {
        for (a, b, what) in [(p.0, planets[0].0, "depth"), (p.1, planets[0].1, "volume")] {
            assert!(
                (a / b - 1.0).abs() <= tol,
                "{mode}: planet {} {what} {a} against planet 1's {b}",
                i + 1
            );
        }
    }
}

/// The configurations: (input, output, fixed), the input's torque per unit of the
/// sun's |T_in / T_s| (Willis: 1 + z_r / z_s for the carrier, z_r / z_s for the ring),
/// and the tooth contacts per input revolution by hand [sun, planet flank, ring]:
/// - carrier in, ring fixed: the sun turns 1 + z_r / z_s per carrier revolution, so
///   z_r / z_s relative to the carrier, meeting the N planets each time (N z_r / z_s);
///   a planet turns (z_s / z_p)(z_r / z_s) = z_r / z_p relative to the carrier; the ring
///   turns once relative to the carrier, meeting N planets;
/// - ring in, carrier fixed: relative to the (fixed) carrier the ring turns once and the
///   sun z_r / z_s times, so the same counts per input revolution.
fn configurations() -> [([&'static str; 3], f64, [f64; 3]); 2] {
    let n = PLANETS as f64;
    let counts = [n * ZR / ZS, ZR / ZP, n];
    [
        (["carrier", "sun", "ring"], 1.0 + ZR / ZS, counts),
        (["ring", "sun", "carrier"], ZR / ZS, counts),
    ]
}

#[test]
fn the_quasi_static_loads_balance_the_torques_of_each_configuration() {
    for (io, input_per_sun, _) in configurations() {
        let torque = 60.0;
        // Quasi-static only: the dynamic run of these wear depths reaches contact loss
        // (docs/MODEL.md 12.9, "A limit seen").
        let text = case(io, torque, (2e4, 1e4));
        let (d, s) = run_case_with("wear", &text, &["--mode", "quasi-static"]);
        let (head, rows) =
            common::read_csv(&d.path().join("out").join("mesh_history_quasi_static.csv"));
        let col = |name: String| head.iter().position(|h| *h == name).unwrap();
        assert_eq!(
            rows.len(),
            3,
            "{io:?}: updates at 0, 1e4 and 2e4 input cycles"
        );
        for r in &rows {
            let sum = |kind: &str| -> f64 {
                (1..=PLANETS)
                    .map(|p| {
                        r[col(format!("mean_force_{kind}_planet_{p}_n"))]
                            .parse::<f64>()
                            .unwrap()
                    })
                    .sum()
            };
            // The sun's torque from its meshes, and the ring's from its meshes.
            let t_sun = sum("sun") * base_radius_m(ZS);
            let t_ring = sum("ring") * base_radius_m(ZR);
            let want_sun = torque / input_per_sun;
            let want_ring = want_sun * ZR / ZS;
            // The equilibrium is solved by LU (backward stable) and the mean forces are
            // printed exactly: measured 3e-15; 1e-9 as the issue asks.
            for (got, want, what) in [(t_sun, want_sun, "sun"), (t_ring, want_ring, "ring")] {
                assert!(
                    (got / want - 1.0).abs() < 1e-9,
                    "{io:?} at {} input cycles: {what} torque {got} N m, by Willis {want}",
                    r[0]
                );
            }
        }
        // In phase (z_s / N = 6): every planet's equations are the same at every instant,
        // they differ by round-off only.
        planets_alike(&s, "quasi_static", 1e-12);
    }
}

#[test]
fn tooth_contacts_per_input_revolution_follow_willis_for_each_configuration() {
    for (io, _, counts) in configurations() {
        let (_d, s) = run_case("wear", &case(io, 60.0, (2e3, 1e3)));
        for m in s["planetary_wear"]["members"].as_array().unwrap() {
            let name = m["member"].as_str().unwrap();
            let want = match name {
                "sun" => counts[0],
                "ring" => counts[2],
                _ => counts[1],
            };
            let got = f(&m["tooth_contacts_per_input_cycle"]);
            assert!(
                (got / want - 1.0).abs() < 1e-12,
                "{io:?}: {name} {got} contacts per input revolution, by hand {want}"
            );
        }
        // The dynamic run too wears the identical planets alike (same equations, in phase).
        planets_alike(&s, "dynamic", 1e-12);
    }
}

/// The dynamic steady state of the carrier-in set once its sun has worn more than its
/// mesh deflection (the first block's wear, 0.50 µm against ~0.4 µm: the meshes open for
/// part of the period, docs/MODEL.md 12.9) is found at the case's own settings within a
/// few dozen mesh periods, and it is the steady state: the mean mesh forces balance the
/// input torque as Willis' torque split by hand gives it. Before the search fixed its step
/// sequence near the orbit, the one-period map jumped by the size of the local errors
/// (1.2e-5 of the state's scale against a steady-state tolerance of 1e-6) and the search
/// ran to `numerics.max_mesh_periods` (measured: no steady state after 80 periods).
#[test]
fn the_worn_carrier_in_set_reaches_its_dynamic_steady_state() {
    use gearwear::dynamics::planetary_steady::{solve_planetary_steady_state, PlanetarySettings};
    use gearwear::study::planetary_wear::{new_teeth, wear_gaps, PlanetaryWearModel};
    use gearwear::study::planetary_wear_loop::{next_block, update_of};
    use gearwear::study::wear_loop::WearMode;
    let torque = 60.0;
    let text = case(["carrier", "sun", "ring"], torque, (2e4, 1e4));
    let c = gearwear::config::load::load_case(&text, &[]).unwrap();
    let model = PlanetaryWearModel::from_case(&c).unwrap();
    let new = update_of(&model, WearMode::Dynamic, (0.0, None), new_teeth(&model)).unwrap();
    let (_, _, wears) = next_block(&model, &c.wear, &new).unwrap();
    let gaps = wear_gaps(&model, &wears);
    let sun_wear = gaps[0].values_m().iter().fold(0.0_f64, |a, b| a.max(*b));
    assert!(
        sun_wear > 4e-7,
        "the first block wore the sun mesh {sun_wear} m only"
    );
    let mut sys = model.dynamics.model.clone();
    sys.set_wear_gaps(gaps);
    // 40 periods: the linearised set's slowest mode decays to 0.84 per mesh period, so a
    // plain search would need ~80 to gain 1e-6 from the static start; the shooting takes
    // 11 (measured). The case's settings otherwise (tolerance 1e-5, 200 samples).
    let settings = PlanetarySettings {
        max_periods: 40,
        ..model.dynamics.settings
    };
    let r = solve_planetary_steady_state(&mut sys, &settings).unwrap();
    let f = &r.mean_forces_n;
    assert!(
        r.mesh_forces_n.iter().flatten().any(|x| *x <= 0.0),
        "the worn meshes were expected to open for part of the period"
    );
    // Willis with the carrier in: the sun's torque T / (1 + z_r / z_s), the ring's z_r / z_s
    // times it (no friction). The mean forces are integrated to ~2e-5 (docs/MODEL.md 12.6)
    // and the steady state is 1e-6 of the state from periodic: 1e-4 as
    // tests/planetary_dynamics_cli.rs.
    let want_sun = torque / (1.0 + ZR / ZS);
    let t_sun: f64 = f[..PLANETS].iter().sum::<f64>() * base_radius_m(ZS);
    let t_ring: f64 = f[PLANETS..].iter().sum::<f64>() * base_radius_m(ZR);
    for (got, want, what) in [
        (t_sun, want_sun, "sun"),
        (t_ring, want_sun * ZR / ZS, "ring"),
    ] {
        assert!(
            (got / want - 1.0).abs() < 1e-4,
            "{what} torque {got} N m, by Willis {want}"
        );
    }
}
