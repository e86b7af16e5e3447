//! The planetary dynamic model (`planetary_dynamic`) with constant mesh stiffness and no
//! damping against the time-invariant lumped model (`planetary_lumped`, Lin & Parker
//! 1999): the poles of its Jacobian about the loaded static state are +-i omega_k with
//! omega_k the lumped model's natural frequencies (a second assembly, from the model's own deflection gradients and
//! contact logic, against the dense K = sum k g g^T with a symmetric eigensolver). Its
//! analytic Jacobian equals the right-hand side's finite differences.

use super::integrator::{finite_difference_jacobian, OdeSystem};
use super::planetary_dynamic::{MeshStiffnessSource, PlanetaryDynamic};
use super::planetary_lumped::PlanetaryLumped;
use nalgebra::DVector;
use std::f64::consts::PI;

/// Lin & Parker's (1999) Table 1 set with N equally spaced planets, every member held in
/// rotation (torsional supports of carrier and sun added so no rigid rotation is free).
fn lin_parker(n: usize) -> PlanetaryLumped {
    PlanetaryLumped {
        planet_angles_rad: (0..n).map(|k| 2.0 * PI * k as f64 / n as f64).collect(),
        mass_kg: [5.43, 2.35, 0.4, 0.66],
        inertia_over_r2_kg: [6.29, 3.0, 0.39, 0.61],
        radius_m: [0.0884, 0.1375, 0.0387, 0.05015],
        mesh_stiffness_n_per_m: [5e8, 5e8],
        bearing_n_per_m: [1e8; 4],
        torsional_n_per_m: [1e8, 1e9, 1e7],
        pressure_angle_rad: 24.6f64.to_radians(),
    }
}

/// The dynamic model of `p` (damping ratio `zeta`) with its lumped mesh stiffness, loaded by a sun
/// torque so that every mesh is compressed, and its static state [q, 0].
fn loaded(p: &PlanetaryLumped, zeta: f64) -> (PlanetaryDynamic, DVector<f64>) {
    let a = p.pressure_angle_rad;
    let source = MeshStiffnessSource::Constant(p.mesh_stiffness_n_per_m);
    let mut sys = PlanetaryDynamic::new(p.clone(), [a, a], source, 1.0, zeta);
    sys.force_n[PlanetaryDynamic::rotation_index(2)] = 1e3;
    let q = sys.static_deflection().unwrap();
    let n = sys.dofs();
    let mut y = DVector::zeros(2 * n);
    y.rows_mut(0, n).copy_from(&q);
    (sys, y)
}

#[test]
fn undamped_poles_are_the_lumped_models_natural_frequencies() {
    for planets in [3, 4, 5] {
        let p = lin_parker(planets);
        let (mut sys, y) = loaded(&p, 0.0);
        // The analytic Jacobian (equal to the right-hand side's finite differences, the
        // next test) is the exact linearisation: every mesh stays compressed about y.
        let jac = sys.jacobian(0.0, &y).unwrap();
        let mut poles: Vec<f64> = jac
            .complex_eigenvalues()
            .iter()
            .filter(|l| l.im > 0.0)
            .map(|l| {
                // Undamped: the real parts are the eigensolver's rounding only, which in
                // this badly scaled state matrix (entries 1 and k / m up to ~1e9 1/s^2)
                // reaches 4e-8 of |lambda| (measured); 1e-6 allows it.
                assert!(l.re.abs() < 1e-6 * l.norm(), "{planets} planets: pole {l}");
                l.im / (2.0 * PI)
            })
            .collect();
        poles.sort_by(f64::total_cmp);
        let modes = p.modes();
        assert_eq!(poles.len(), modes.len(), "{planets} planets");
        // Eigenvalues of the nonsymmetric, badly scaled 2n x 2n state matrix (Schur) err
        // by up to 2.2e-6 relative on the degenerate pairs (measured; the stiffness
        // matrices themselves agree to 1e-12, the next test): 1e-5.
        for (f, m) in poles.iter().zip(&modes) {
            assert!(
                (f / m.frequency_hz - 1.0).abs() < 1e-5,
                "{planets} planets: pole {f} Hz vs mode {} Hz",
                m.frequency_hz
            );
        }
    }
}

#[test]
fn stiffness_in_the_jacobian_is_the_lumped_models() {
    for planets in [3, 4, 5] {
        let p = lin_parker(planets);
        let (mut sys, y) = loaded(&p, 0.0);
        let jac = sys.jacobian(0.0, &y).unwrap();
        let n = sys.dofs();
        let m = p.mass_diagonal();
        let k = p.stiffness();
        // -M J_21 against K = sum k g g^T: the same sums in another order, so equal to
        // rounding (1e-12 of the largest entry).
        let err = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .map(|(i, j)| (-m[i] * jac[(n + i, j)] - k[(i, j)]).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-12 * k.amax(), "{planets} planets: {err}");
    }
}

#[test]
fn analytic_jacobian_equals_finite_differences() {
    let p = lin_parker(4);
    let (mut sys, y) = loaded(&p, 0.05);
    let f_y = sys.rhs(0.0, &y);
    let floor = DVector::from_element(y.len(), 1e-6);
    let fd = finite_difference_jacobian(&mut sys, 0.0, &y, &f_y, &floor);
    let an = sys.jacobian(0.0, &y).unwrap();
    // Linear about y: the differences err by rounding, ~1e-7 of the largest entry.
    let scale = an.amax();
    assert!((fd - an).amax() < 1e-6 * scale);
}

#[test]
fn mean_state_matrix_is_the_jacobian_with_every_mesh_compressed() {
    // The steady-state search's linear model against the right-hand side's own
    // linearisation: with constant stiffness and every mesh compressed (a loaded static
    // state) the two are assemblies of one matrix, equal to rounding.
    let p = lin_parker(4);
    let (mut sys, y) = loaded(&p, 0.05);
    let jac = sys.jacobian(0.3, &y).unwrap();
    let mean = sys.mean_state_matrix();
    assert!((jac - mean).amax() <= 1e-12 * sys.mean_state_matrix().amax());
}

#[test]
fn the_period_grid_keeps_every_sample_and_adds_the_jumps() {
    use super::planetary_grid::period_grid;
    // By hand, 4 samples over a 2 s period (0, 0.5, 1, 1.5, 2 s): the jump at 0.25
    // cycles falls on the sample at 0.5 s, the one at 0.3 cycles is a node of its own at
    // 0.6 s, the one 1e-9 cycles after 0.5 (4e-9 of a sample interval, below the merge
    // distance 1e-6) is marked on the sample at 1 s.
    let g = period_grid(&[0.25, 0.3, 0.5 + 1e-9], 2.0, 4);
    let t: Vec<f64> = g.iter().map(|n| n.t_s).collect();
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    let want = [0.0, 0.5, 0.6, 1.0, 1.5, 2.0];
    assert_eq!(t.len(), want.len(), "{t:?}");
    assert!(t.iter().zip(want).all(|(a, b)| close(*a, b)), "{t:?}");
    let sample: Vec<bool> = g.iter().map(|n| n.sample).collect();
    let jump: Vec<bool> = g.iter().map(|n| n.jump).collect();
    assert_eq!(sample, [true, true, false, true, true, true]);
    assert_eq!(jump, [false, true, true, true, false, false]);
}
