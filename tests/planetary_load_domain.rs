//! A planetary set refuses a load its flanks cannot carry elastically, as a single pair
//! does: the sun-planet mesh's Hertz pressure at its pitch point under an equal share of
//! the sun's torque above 10 GPa is refused (exit 2) before any work. The threshold
//! torque is computed here by hand from the gear data and the torque split.

mod common;

use common::planetary::lin_parker_lumped;
use common::{gearwear, rejected, stderr};

/// The 24 / 30 / 84 set of module 2 mm, 20 mm wide, four planets, unshifted, steel
/// (E = 205 GPa, nu = 0.3: the case's defaults), with `input` and `output` members.
fn case_file(dir: &tempfile::TempDir, input: &str, output: &str) -> String {
    let path = dir.path().join("planetary.toml");
    let text = format!(
        "[planetary]\nplanets = 4\nteeth_sun = 24\nteeth_planet = 30\nteeth_ring = 84\nmodule_mm = 2.0\ninput = \"{input}\"\noutput = \"{output}\"\nfixed = \"ring\"\n{}",
        lin_parker_lumped(1e6)
    );
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

/// The input torque, N m, at which a sun-planet mesh reaches 10 GPa at its pitch point
/// (Johnson 1985: p0 = sqrt(w E* / (pi R)), w = F / b, 1/R = 1/rho_s + 1/rho_p, rho =
/// r sin(20 deg) at the pitch point of unshifted gears; 1/E* = 2 (1 - nu^2) / E); the
/// sun's torque is the input's over `share` (Willis), shared by four sun meshes at the
/// sun's base radius.
fn threshold_nm(share: f64) -> f64 {
    let alpha = 20f64.to_radians();
    let (rho_s, rho_p) = (24e-3 * alpha.sin(), 30e-3 * alpha.sin());
    let r_eff = rho_s * rho_p / (rho_s + rho_p);
    let e_star = 205e9 / (2.0 * (1.0 - 0.3 * 0.3));
    let force = 10e9_f64.powi(2) * std::f64::consts::PI * r_eff * 20e-3 / e_star;
    force * 4.0 * 24e-3 * alpha.cos() * share
}

#[test]
fn a_load_beyond_the_elastic_range_is_refused_at_the_hand_threshold() {
    let dir = tempfile::tempdir().unwrap();
    // Sun in: the sun carries the input torque; carrier in: the sun carries
    // T_c / (1 + z_r / z_s) = T_c / 4.5.
    for (input, output, share) in [("sun", "carrier", 1.0), ("carrier", "sun", 4.5)] {
        let file = case_file(&dir, input, output);
        let t = threshold_nm(share);
        // 1 % either side: the model's geometry and moduli are the hand values, so the
        // threshold is the same to rounding.
        let below = format!("operating.load_torque_nm={}", 0.99 * t);
        let o = gearwear(&[
            "stiffness",
            "-q",
            "--config",
            &file,
            "--set",
            &below,
            "--out",
            dir.path().join(format!("ok_{input}")).to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{input} in at 0.99 x: {}",
            stderr(&o)
        );
        let above = format!("operating.load_torque_nm={}", 1.01 * t);
        for command in ["stiffness", "dynamics"] {
            rejected(
                &[command, "--config", &file, "--set", &above],
                &[
                    "`operating.load_torque_nm`",
                    "more than this planetary set's flanks can carry",
                    "above 10 GPa",
                ],
            );
        }
    }
}
