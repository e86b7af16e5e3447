//! Tests on nonlinear problems (invariants, published values, self-convergence against a
//! second method), of RK4's order, and of error handling.

use nalgebra::{Const, Matrix2, SMatrix, Vector1, Vector2, Vector3};

use super::{
    finite_difference_jacobian, IntegratorError, OdeSystem, Rk4, Sdirk, SdirkOptions, Stepper,
};

/// Robertson's chemical kinetics (Robertson 1966; Hairer & Wanner II, Sect. IV.1,
/// eq. 1.4), dimensionless concentrations, time in s.
fn robertson(_t: f64, y: &Vector3<f64>) -> Vector3<f64> {
    let r1 = 0.04 * y[0];
    let r2 = 1e4 * y[1] * y[2];
    let r3 = 3e7 * y[1] * y[1];
    Vector3::new(-r1 + r2, r1 - r2 - r3, r3)
}

/// (e) Robertson: the linear invariant y1 + y2 + y3 = 1 is kept to round-off, and the
/// solution matches published values.
#[test]
fn robertson_conserves_mass_and_matches_published_values() {
    let mut sys = robertson;
    let opts = SdirkOptions {
        abs_tol: 1e-14,
        rel_tol: 1e-10,
        ..SdirkOptions::default()
    };
    let h = 1e-3;
    let mut stepper = Sdirk::<Const<3>>::new(h, opts).unwrap();
    let (mut t, mut y) = (0.0, Vector3::new(1.0, 0.0, 0.0));
    // t = 0.4 and 4: LSODE demo output (Hindmarsh, ODEPACK opkdmain.f, example 1), run
    // with rtol = 1e-4, atol = (1e-6, 1e-10, 1e-6): good to ~1e-4 relative, hence 2e-4.
    // t = 40: Hairer & Wanner II, Sect. IV.1, y(40) to 10 digits; our order-3 error at
    // h = 1e-3 is O(h^3) = 1e-9 times O(1) constants, hence 1e-8 relative.
    let checkpoints = [
        (400usize, [9.851712e-01, 3.386380e-05, 1.479493e-02], 2e-4),
        (4_000, [9.055333e-01, 2.240655e-05, 9.444430e-02], 2e-4),
        (40_000, [0.7158270687, 9.185534764e-6, 0.2841637457], 1e-8),
    ];
    let mut done = 0;
    let mut worst_mass: f64 = 0.0;
    for (n, reference, tol) in checkpoints {
        for _ in done..n {
            stepper.step(&mut sys, t, &mut y).unwrap();
            t += h;
            worst_mass = worst_mass.max((y.sum() - 1.0).abs());
        }
        done = n;
        println!(
            "Robertson t = {t:.1}: y = {:.12e} {:.12e} {:.12e}",
            y[0], y[1], y[2]
        );
        for i in 0..3 {
            let rel = (y[i] - reference[i]).abs() / reference[i];
            assert!(
                rel < tol,
                "t = {t}, y{} = {:e} vs {:e}",
                i + 1,
                y[i],
                reference[i]
            );
        }
    }
    println!("Robertson: max |y1 + y2 + y3 - 1| over 40000 steps = {worst_mass:.1e}");
    // Every step conserves u^T y (u = (1,1,1)) in exact arithmetic: u^T f = 0 gives
    // u^T J = 0, so u^T (I - h g J)^{-1} = u^T and every Newton update and stage
    // derivative sums to zero, whatever the Newton tolerance. Only round-off remains,
    // bounded by ~eps per step on these O(1) sums: 40000 eps = 8.9e-12.
    assert!(worst_mass < 40_000.0 * f64::EPSILON);
    assert_eq!(stepper.stats().steps, 40_000);
}

/// Van der Pol oscillator, mu = 1 (non-stiff): `x' = v`, `v' = mu (1 - x^2) v - x`,
/// with its analytic Jacobian.
struct VanDerPol {
    mu: f64,
}

impl OdeSystem<Const<2>> for VanDerPol {
    fn rhs(&mut self, _t: f64, y: &Vector2<f64>) -> Vector2<f64> {
        Vector2::new(y[1], self.mu * (1.0 - y[0] * y[0]) * y[1] - y[0])
    }
    fn jacobian(&mut self, _t: f64, y: &Vector2<f64>) -> Option<Matrix2<f64>> {
        Some(Matrix2::new(
            0.0,
            1.0,
            -2.0 * self.mu * y[0] * y[1] - 1.0,
            self.mu * (1.0 - y[0] * y[0]),
        ))
    }
}

/// (e) Van der Pol: no closed form, so the reference comes from the second method (RK4
/// with h = 1e-4, error ~ h^4 ~ 1e-16 relative to the SDIRK errors of >= 1e-8 measured
/// here). Order 3 is then observed from the error ratios.
#[test]
fn van_der_pol_converges_with_order_three_against_rk4_reference() {
    let t_end = 5.0;
    let y0 = Vector2::new(2.0, 0.0);
    let mut sys = VanDerPol { mu: 1.0 };
    let mut rk = Rk4::<Const<2>>::new(1e-4).unwrap();
    let (mut t, mut y_ref) = (0.0, y0);
    rk.advance(&mut sys, &mut t, &mut y_ref, 50_000).unwrap();
    let opts = SdirkOptions {
        abs_tol: 1e-15,
        rel_tol: 1e-13,
        ..SdirkOptions::default()
    };
    let mut errors = Vec::new();
    for &n in &[100usize, 200, 400, 800] {
        let mut stepper = Sdirk::<Const<2>>::new(t_end / n as f64, opts).unwrap();
        let (mut t, mut y) = (0.0, y0);
        stepper.advance(&mut sys, &mut t, &mut y, n).unwrap();
        errors.push((y - y_ref).norm());
    }
    let ratios: Vec<f64> = errors.windows(2).map(|e| e[0] / e[1]).collect();
    println!(
        "Van der Pol: errors {:?}, ratios {ratios:.3?}",
        errors
            .iter()
            .map(|e| format!("{e:.3e}"))
            .collect::<Vec<_>>()
    );
    // 2^3 = 8 asymptotically; the O(h^4) term still lowers it by ~10 % at h = 0.05.
    for r in &ratios {
        assert!((7.0..9.0).contains(r), "ratio {r}");
    }
}

/// RK4 order 4 on `y' = -2 t y^2`, exact `y = 1 / (1 + t^2)`.
#[test]
fn rk4_converges_with_order_four() {
    let mut sys = |t: f64, y: &Vector1<f64>| Vector1::new(-2.0 * t * y[0] * y[0]);
    let t_end = 2.0;
    let exact = 1.0 / (1.0 + t_end * t_end);
    let mut errors = Vec::new();
    for &n in &[10usize, 20, 40, 80] {
        let mut rk = Rk4::<Const<1>>::new(t_end / n as f64).unwrap();
        let (mut t, mut y) = (0.0, Vector1::new(1.0));
        let stats = rk.advance(&mut sys, &mut t, &mut y, n).unwrap();
        assert_eq!(stats.rhs_calls, 4 * n as u64);
        errors.push((y[0] - exact).abs());
    }
    let ratios: Vec<f64> = errors.windows(2).map(|e| e[0] / e[1]).collect();
    println!(
        "RK4: errors {:?}, ratios {ratios:.3?}",
        errors
            .iter()
            .map(|e| format!("{e:.3e}"))
            .collect::<Vec<_>>()
    );
    // 2^4 = 16 asymptotically; at h = 0.2 the O(h^5) term shifts it by up to ~20 %.
    for r in &ratios {
        assert!((13.0..19.0).contains(r), "ratio {r}");
    }
}

/// No real solution of the stage equation: `y' = 1e4 y^2`, `y0 = 1`, `h = 1` needs
/// `Y = 1 + h g 1e4 Y^2`, whose discriminant `1 - 4 h g 1e4 < 0`. Newton must fail with an
/// error, and leave y untouched.
#[test]
fn unsolvable_stage_returns_error_and_keeps_state() {
    let mut sys = |_t: f64, y: &Vector1<f64>| Vector1::new(1e4 * y[0] * y[0]);
    let mut stepper = Sdirk::<Const<1>>::new(1.0, SdirkOptions::default()).unwrap();
    let mut y = Vector1::new(1.0);
    let err = stepper.step(&mut sys, 0.0, &mut y).unwrap_err();
    assert!(
        matches!(err, IntegratorError::NewtonFailed { stage: 0, .. }),
        "{err}"
    );
    assert_eq!(y[0], 1.0);
    assert_eq!(stepper.stats().steps, 0);
    // Two Jacobian refreshes are tried before giving up.
    assert_eq!(stepper.stats().retries, 2);
}

/// A right-hand side that returns NaN (e.g. a model evaluated outside its domain) gives
/// an error, never NaN in the state; so does a NaN initial state.
#[test]
fn non_finite_rhs_or_state_is_an_error() {
    let mut sys = |_t: f64, y: &Vector1<f64>| Vector1::new(if y[0] > 1.5 { f64::NAN } else { 1.0 });
    let mut stepper = Sdirk::<Const<1>>::new(1.0, SdirkOptions::default()).unwrap();
    let mut y = Vector1::new(1.0);
    let err = stepper.step(&mut sys, 0.0, &mut y).unwrap_err();
    assert!(matches!(err, IntegratorError::NonFinite { .. }), "{err}");
    assert_eq!(y[0], 1.0);
    let mut y_nan = Vector1::new(f64::NAN);
    assert!(stepper.step(&mut sys, 0.0, &mut y_nan).is_err());
    let mut rk = Rk4::<Const<1>>::new(1.0).unwrap();
    assert!(rk.step(&mut sys, 0.0, &mut y).is_err());
    assert_eq!(y[0], 1.0);
}

#[test]
fn invalid_settings_are_rejected() {
    let bad = |f: fn(&mut SdirkOptions)| {
        let mut o = SdirkOptions::default();
        f(&mut o);
        Sdirk::<Const<2>>::new(0.1, o).is_err()
    };
    assert!(bad(|o| o.abs_tol = 0.0));
    assert!(bad(|o| o.rel_tol = f64::NAN));
    assert!(bad(|o| o.max_newton_iters = 0));
    assert!(bad(|o| o.refresh_rate = 1.0));
    assert!(Sdirk::<Const<2>>::new(0.0, SdirkOptions::default()).is_err());
    assert!(Sdirk::<Const<2>>::new(f64::INFINITY, SdirkOptions::default()).is_err());
    assert!(Rk4::<Const<2>>::new(-1.0).is_err());
    let mut s = Sdirk::<Const<2>>::new(0.1, SdirkOptions::default()).unwrap();
    assert!(s.set_abs_tol(Vector2::new(1e-9, 0.0)).is_err());
    assert!(s.set_step_size(f64::NAN).is_err());
}

/// The finite-difference Jacobian agrees with the analytic one.
#[test]
fn finite_difference_jacobian_matches_analytic() {
    let mut sys = VanDerPol { mu: 3.0 };
    let y = Vector2::new(1.3, -0.7);
    let f_y = sys.rhs(0.0, &y);
    let fd = finite_difference_jacobian(&mut sys, 0.0, &y, &f_y, &Vector2::repeat(1e-3));
    let exact: SMatrix<f64, 2, 2> = sys.jacobian(0.0, &y).unwrap();
    // Forward differences with d = sqrt(eps)|y| ~ 2e-8: truncation ~ d |f''| ~ 1e-7 and
    // cancellation ~ eps |f| / d ~ 1e-8, on entries of size ~ 5.
    assert!((fd - exact).amax() < 1e-6, "{fd} vs {exact}");
}
