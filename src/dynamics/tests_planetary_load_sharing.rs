//! Static load sharing of a planetary set with planet pin position errors
//! (`PlanetaryDynamic::set_pin_errors`, `static_mesh_forces`) against a hand calculation
//! of the compliances that does not use the program's matrices or its projection of the
//! error onto the lines of action.
//!
//! The hand calculation: ring and carrier rigid laterally (supports of 1e16 N/m in the
//! program), the sun on a lateral bearing k_bs (rigid, finite or 0: floating). A pin error
//! (e_t, e_r) moves the pin, so the pin springs read x_c cos psi + y_c sin psi + e_r - zeta
//! and -x_c sin psi + y_c cos psi + u_c + e_t - eta. A planet's moment balance makes its
//! sun and ring mesh forces equal (F_n), its radial and tangential balances give zeta and
//! eta, and the sum of its two mesh compressions, F_n / k_s + F_n / k_r, then reads
//!   c F_n = w + y_s cos psi_sn - x_s sin psi_sn - e_n,
//!   c = 1/k_s + 1/k_r + ((sin a_s - sin a_r)^2 + (cos a_s + cos a_r)^2) / k_p,
//!   e_n = e_r (sin a_s - sin a_r) + e_t (cos a_s + cos a_r),
//! w = u_s + u_r - (cos a_s + cos a_r) u_c common to every planet. With the sun's balance
//! (sum F_n = P, its lateral force sum F_n (-sin psi_sn, cos psi_sn) + k_bs (x_s, y_s) = 0)
//! these are N + 3 linear equations in F_n, w, x_s, y_s, solved here with nalgebra.

use super::planetary_dynamic::{MeshStiffnessSource, PlanetaryDynamic};
use super::planetary_lumped::PlanetaryLumped;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// Mesh stiffness sun-planet and ring-planet, planet pin stiffness, N/m.
const K_SUN: f64 = 5e8;
const K_RING: f64 = 6e8;
const K_PIN: f64 = 1e8;
/// "Rigid" supports, N/m: 1e8 times the pins, so the hand calculation's rigid members
/// differ from the program's by a relative ~1e-8 (a member's motion under an unbalanced
/// ~1e3 N is 1e-13 m, against mesh compressions of ~1e-5 m).
const RIGID: f64 = 1e16;
/// The force on the sun's u (its torque over its base radius), N.
const P: f64 = 1e4;

/// The program's model: N equally spaced planets, ring and carrier rigid laterally, the
/// ring's rotation on a stiff support, the carrier's on a finite one (the output), the sun
/// on the lateral bearing `k_sun_bearing`, its rotation free and driven by P.
fn program_shares(
    n: usize,
    alpha: [f64; 2],
    k_sun_bearing: f64,
    errors_m: &[(f64, f64)],
) -> Vec<f64> {
    let p = PlanetaryLumped {
        planet_angles_rad: angles(n),
        mass_kg: [5.43, 2.35, 0.4, 0.66],
        inertia_over_r2_kg: [6.29, 3.0, 0.39, 0.61],
        radius_m: [0.0884, 0.1375, 0.0387, 0.05015],
        mesh_stiffness_n_per_m: [K_SUN, K_RING],
        bearing_n_per_m: [RIGID, RIGID, k_sun_bearing, K_PIN],
        torsional_n_per_m: [1e9, RIGID, 0.0],
        pressure_angle_rad: alpha[0],
    };
    let mut sys = PlanetaryDynamic::new(
        p,
        alpha,
        MeshStiffnessSource::Constant([K_SUN, K_RING]),
        1.0,
        0.0,
    );
    sys.force_n[PlanetaryDynamic::rotation_index(2)] = P;
    sys.set_pin_errors(errors_m);
    let f = sys.static_mesh_forces().expect("a grounded set");
    // Each planet's moment balance: its ring mesh carries what its sun mesh does (a
    // check of the program's static state; 1e-6 of the mean, the rounding of K's spread).
    for k in 0..n {
        assert!((f[k] - f[n + k]).abs() < 1e-6 * P / n as f64, "{f:?}");
    }
    shares(&f[..n])
}

fn angles(n: usize) -> Vec<f64> {
    (0..n).map(|k| 2.0 * PI * k as f64 / n as f64).collect()
}

fn shares(f: &[f64]) -> Vec<f64> {
    let s: f64 = f.iter().sum();
    f.iter().map(|v| f.len() as f64 * v / s).collect()
}

/// The hand calculation of the module docs: the planets' shares N F_n / P.
fn hand_shares(n: usize, alpha: [f64; 2], k_sun_bearing: f64, errors_m: &[(f64, f64)]) -> Vec<f64> {
    let [a_s, a_r] = alpha;
    let d = a_s.sin() - a_r.sin();
    let c_sum = a_s.cos() + a_r.cos();
    let c = 1.0 / K_SUN + 1.0 / K_RING + (d * d + c_sum * c_sum) / K_PIN;
    let m = n + 3;
    let mut a = DMatrix::zeros(m, m);
    let mut b = DVector::zeros(m);
    for (k, psi) in angles(n).iter().enumerate() {
        let (s, co) = (psi - a_s).sin_cos();
        let (e_t, e_r) = errors_m[k];
        a[(k, k)] = c;
        a[(k, n)] = -1.0;
        a[(k, n + 1)] = s;
        a[(k, n + 2)] = -co;
        b[k] = -(e_r * d + e_t * c_sum);
        a[(n, k)] = 1.0;
        a[(n + 1, k)] = -s;
        a[(n + 2, k)] = co;
    }
    b[n] = P;
    a[(n + 1, n + 1)] = k_sun_bearing;
    a[(n + 2, n + 2)] = k_sun_bearing;
    let z = a.lu().solve(&b).expect("solvable");
    (0..n).map(|k| n as f64 * z[k] / P).collect()
}

fn um(t: f64, r: f64) -> (f64, f64) {
    (t * 1e-6, r * 1e-6)
}

/// Agreement of program and hand calculation: the rigid members' 1e-8 and the rounding
/// of K's spread of 1e8 (~1e-8 of the forces) leave well under 1e-6 of a share.
const TOL: f64 = 1e-6;

fn assert_close(got: &[f64], want: &[f64], what: &str) {
    for (g, w) in got.iter().zip(want) {
        assert!(
            (g - w).abs() < TOL,
            "{what}: program {got:?}, hand {want:?}"
        );
    }
}

#[test]
fn a_fixed_sun_shares_as_the_closed_form_of_series_planet_paths() {
    // Rigid sun, a_s = a_r: x_s = y_s = 0, so F_n = P/N + (mean(e) - e_n) / c, with
    // e_n = 2 e_t cos a (a radial error drops out of the path).
    let a = 20f64.to_radians();
    let errors = [um(20.0, 0.0), um(0.0, 15.0), um(-5.0, 0.0), um(0.0, 0.0)];
    let c = 1.0 / K_SUN + 1.0 / K_RING + 4.0 * a.cos().powi(2) / K_PIN;
    let e: Vec<f64> = errors.iter().map(|(t, _)| 2.0 * t * a.cos()).collect();
    let mean = e.iter().sum::<f64>() / 4.0;
    let closed: Vec<f64> = e
        .iter()
        .map(|en| 1.0 + 4.0 * (mean - en) / (c * P))
        .collect();
    assert_close(
        &hand_shares(4, [a, a], RIGID, &errors),
        &closed,
        "hand vs closed form",
    );
    assert_close(
        &program_shares(4, [a, a], RIGID, &errors),
        &closed,
        "program vs closed form",
    );
    // The +20 um planet is off-loaded by a share the size of its preload: a real effect.
    assert!(closed[0] < 0.9, "{closed:?}");
}

#[test]
fn finite_and_floating_suns_with_tangential_and_radial_errors_match_the_hand_system() {
    // Unequal pressure angles, so a radial error also moves the path.
    let alpha = [21f64.to_radians(), 19f64.to_radians()];
    for n in [3, 4, 5] {
        let errors: Vec<(f64, f64)> = (0..n)
            .map(|k| {
                um(
                    [20.0, -8.0, 3.0, 0.0, 11.0][k],
                    [0.0, 25.0, -10.0, 6.0, 0.0][k],
                )
            })
            .collect();
        for k_bs in [RIGID, 2e8, 0.0] {
            assert_close(
                &program_shares(n, alpha, k_bs, &errors),
                &hand_shares(n, alpha, k_bs, &errors),
                &format!("N = {n}, sun bearing {k_bs:e} N/m"),
            );
        }
    }
}

#[test]
fn a_floating_sun_equalises_three_planets_but_not_four() {
    // Kahraman 1994, Bodas & Kahraman 2004: with three planets the floating sun's two
    // lateral balances and its torque fix the three mesh forces alone (statics), so they
    // are equal whatever the error; with four they are not.
    let a = 20f64.to_radians();
    let three = program_shares(3, [a, a], 0.0, &[um(20.0, 0.0), um(0.0, 0.0), um(0.0, 0.0)]);
    // Statics alone: the rounding of the solve only (1e-9 of a share is far above it).
    for s in &three {
        assert!((s - 1.0).abs() < 1e-9, "{three:?}");
    }
    let four = program_shares(
        4,
        [a, a],
        0.0,
        &[um(20.0, 0.0), um(0.0, 0.0), um(0.0, 0.0), um(0.0, 0.0)],
    );
    let spread = four.iter().fold(0.0f64, |m, s| m.max((s - 1.0).abs()));
    assert!(spread > 0.01, "{four:?}");
    // The floating sun pairs opposite planets (1 with 3, 2 with 4): its lateral balance
    // needs F_1 - F_3 = 0 and F_2 - F_4 = 0 with planets at 90 deg.
    assert!(
        (four[0] - four[2]).abs() < 1e-9 && (four[1] - four[3]).abs() < 1e-9,
        "{four:?}"
    );
    // Without errors every planet carries 1/N (symmetry).
    for s in program_shares(4, [a, a], RIGID, &[(0.0, 0.0); 4]) {
        assert!((s - 1.0).abs() < 1e-9, "{s}");
    }
}
