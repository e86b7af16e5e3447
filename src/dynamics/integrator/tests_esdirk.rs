//! Tests of the ESDIRK3(2) pair: its order, the stage order that keeps it accurate on
//! stiff boundary layers, and the embedded error estimate that steers the step.

use nalgebra::{Const, Matrix2, SVector, Vector1, Vector2};

use super::tableau::ESDIRK32;
use super::{OdeSystem, Sdirk, SdirkOptions};

/// Newton settings far below the discretisation errors measured here.
fn tight() -> SdirkOptions {
    SdirkOptions {
        abs_tol: 1e-15,
        rel_tol: 1e-13,
        ..SdirkOptions::default()
    }
}

/// `n` fixed steps of size `h` with the ESDIRK from `(0, y)`; returns the end state.
fn integrate<S: OdeSystem<Const<N>>, const N: usize>(
    sys: &mut S,
    y0: SVector<f64, N>,
    h: f64,
    n: usize,
) -> SVector<f64, N> {
    let mut s = Sdirk::<Const<N>>::with_tableau(&ESDIRK32, h, tight()).unwrap();
    let (mut t, mut y) = (0.0, y0);
    for _ in 0..n {
        let tr = s.try_step(sys, t, &y, h).unwrap();
        s.accept(&tr);
        y = tr.y;
        t += h;
    }
    y
}

#[test]
fn esdirk_converges_with_order_three_on_a_stiff_linear_system() {
    // y' = M y, M = P diag(-1, -1e7) P^{-1}: the slow mode shows the classical order.
    let p = Matrix2::new(1.0, 1.0, 0.5, -1.0);
    let p_inv = p.try_inverse().unwrap();
    let m = p * Matrix2::new(-1.0, 0.0, 0.0, -1e7) * p_inv;
    let y0 = Vector2::new(1.0, 2.0);
    let exact = p * Matrix2::new((-1.0_f64).exp(), 0.0, 0.0, 0.0) * p_inv * y0;
    let mut sys = move |_t: f64, y: &Vector2<f64>| m * y;
    let errors: Vec<f64> = [10usize, 20, 40, 80]
        .iter()
        .map(|n| (integrate(&mut sys, y0, 1.0 / *n as f64, *n) - exact).norm())
        .collect();
    for w in errors.windows(2) {
        // 2^3 = 8 as h -> 0, shifted by a few % by the O(h^4) term at h = 0.1.
        let r = w[0] / w[1];
        assert!((7.0..9.5).contains(&r), "ratio {r} ({errors:?})");
    }
}

#[test]
fn stage_order_two_gives_second_order_in_the_stiff_limit() {
    // Prothero-Robinson y' = lambda (y - sin t) + cos t, exact sin t, lambda = -1e8: in
    // the stiff limit the error is governed by the stage order q (Hairer & Wanner II,
    // Sect. IV.15): O(h^(q+1) / |lambda|). SDIRK3 (q = 1) halving h halves its error;
    // the ESDIRK (q = 2) quarters it.
    let lambda = -1e8;
    let run = |esdirk: bool, h: f64| {
        let mut sys = |t: f64, y: &Vector1<f64>| Vector1::new(lambda * (y[0] - t.sin()) + t.cos());
        let mut s = if esdirk {
            Sdirk::<Const<1>>::with_tableau(&ESDIRK32, h, tight()).unwrap()
        } else {
            Sdirk::<Const<1>>::new(h, tight()).unwrap()
        };
        let (mut t, mut y, mut worst) = (0.0, Vector1::new(0.0), 0.0_f64);
        for _ in 0..(2.0 / h).round() as usize {
            let tr = s.try_step(&mut sys, t, &y, h).unwrap();
            s.accept(&tr);
            (y, t) = (tr.y, t + h);
            worst = worst.max((y[0] - t.sin()).abs());
        }
        worst
    };
    let sdirk = run(false, 0.02) / run(false, 0.01);
    let esdirk = run(true, 0.02) / run(true, 0.01);
    println!("Prothero-Robinson error ratios h/2: SDIRK3 {sdirk:.2}, ESDIRK {esdirk:.2}");
    assert!((1.6..2.6).contains(&sdirk), "SDIRK ratio {sdirk}");
    assert!((3.2..5.0).contains(&esdirk), "ESDIRK ratio {esdirk}");
}

#[test]
fn embedded_estimate_follows_the_local_error() {
    // y' = -y + sin t from y(0) = 1 (non-stiff, smooth): the estimate y - y_hat is the
    // local error of the order-2 embedded solution, O(h^3): halving h divides it by 8.
    let mut sys = |t: f64, y: &Vector1<f64>| Vector1::new(-y[0] + t.sin());
    let mut s = Sdirk::<Const<1>>::with_tableau(&ESDIRK32, 0.1, tight()).unwrap();
    s.set_error_tolerance(Vector1::new(1.0), Vector1::new(0.0))
        .unwrap();
    let y0 = Vector1::new(1.0);
    let e: Vec<f64> = [0.1, 0.05, 0.025]
        .iter()
        .map(|h| s.try_step(&mut sys, 0.3, &y0, *h).unwrap().error)
        .collect();
    for w in e.windows(2) {
        let r = w[0] / w[1];
        assert!((7.0..9.0).contains(&r), "ratio {r} ({e:?})");
    }
    // The true local error of the main (order 3) solution is far below the estimate.
    let h = 0.05;
    let tr = s.try_step(&mut sys, 0.0, &y0, h).unwrap();
    // Exact: y = 1.5 e^-t + (sin t - cos t) / 2.
    let exact = 1.5 * (-h).exp() + (h.sin() - h.cos()) / 2.0;
    assert!(
        (tr.y[0] - exact).abs() < 0.1 * tr.error,
        "{} vs {}",
        (tr.y[0] - exact).abs(),
        tr.error
    );
}

#[test]
fn stiff_components_do_not_inflate_the_estimate() {
    // y' = -1e8 (y - cos t): the solution sits on the slow manifold; the filtered
    // estimate of a step 1e6 times longer than the fast time scale must stay of the
    // size of the slow local error, not be |h lambda| = 1e4 times larger.
    let mut sys = |t: f64, y: &Vector1<f64>| Vector1::new(-1e8 * (y[0] - t.cos()));
    let mut s = Sdirk::<Const<1>>::with_tableau(&ESDIRK32, 0.01, tight()).unwrap();
    s.set_error_tolerance(Vector1::new(1e-6), Vector1::new(0.0))
        .unwrap();
    let y0 = Vector1::new(1.0 + 0.0_f64.sin() / 1e8);
    let tr = s.try_step(&mut sys, 0.0, &y0, 0.01).unwrap();
    assert!(tr.error < 1.0, "estimate {} of tolerance", tr.error);
    assert!((tr.y[0] - 0.01_f64.cos()).abs() < 1e-9);
}

#[test]
fn kept_matrices_serve_recurring_step_lengths_with_the_same_solution() {
    // Steps alternating h, h / 2, h / 4 on the stiff linear system (constant Jacobian,
    // one evaluation): without kept matrices every change of length factorises again;
    // with three kept, each length factorises once. The stage equations are solved to the
    // same Newton tolerance either way, so the two solutions agree to far below it
    // (1e-11 of |y|, the Newton tolerance 1e-13 relative times the steps' error growth).
    let p = Matrix2::new(1.0, 1.0, 0.5, -1.0);
    let p_inv = p.try_inverse().unwrap();
    let m = p * Matrix2::new(-1.0, 0.0, 0.0, -1e7) * p_inv;
    let run = |kept: usize| {
        let mut sys = move |_t: f64, y: &Vector2<f64>| m * y;
        let opts = SdirkOptions {
            kept_matrices: kept,
            ..tight()
        };
        let mut s = Sdirk::<Const<2>>::with_tableau(&ESDIRK32, 0.01, opts).unwrap();
        let (mut t, mut y) = (0.0, Vector2::new(1.0, 2.0));
        for i in 0..90 {
            let h = 0.01 / [1.0, 2.0, 4.0][i % 3];
            let tr = s.try_step(&mut sys, t, &y, h).unwrap();
            s.accept(&tr);
            (y, t) = (tr.y, t + h);
        }
        (y, s.stats())
    };
    let (y0, st0) = run(0);
    let (y3, st3) = run(3);
    assert_eq!(st0.jacobian_evals, 1);
    assert_eq!(st3.jacobian_evals, 1);
    assert_eq!(st0.lu_factorizations, 90);
    assert_eq!(st3.lu_factorizations, 3);
    assert!((y3 - y0).norm() < 1e-11 * y0.norm(), "{y0} vs {y3}");
}
