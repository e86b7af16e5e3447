//! Tests of the SDIRK stepper on linear problems with closed-form solutions, and of its
//! Jacobian/LU reuse policy.

use nalgebra::{Complex, Const, Matrix2, SMatrix, SVector, Vector1, Vector2};

use super::tableau::{ALEXANDER3, GAMMA};
use super::{OdeSystem, Sdirk, SdirkOptions, Stepper};

/// Newton settings far below the discretisation errors measured here, so that the
/// tests see the method, not the nonlinear solver.
fn tight() -> SdirkOptions {
    SdirkOptions {
        abs_tol: 1e-15,
        rel_tol: 1e-13,
        ..SdirkOptions::default()
    }
}

/// `y' = M y + u cos(w t)` with an analytic Jacobian.
struct Linear<const N: usize> {
    m: SMatrix<f64, N, N>,
    u: SVector<f64, N>,
    w: f64,
}

impl<const N: usize> OdeSystem<Const<N>> for Linear<N> {
    fn rhs(&mut self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N> {
        self.m * y + self.u * (self.w * t).cos()
    }
    fn jacobian(&mut self, _t: f64, _y: &SVector<f64, N>) -> Option<SMatrix<f64, N, N>> {
        Some(self.m)
    }
}

/// `R(z) = P(z) / (1 - gamma z)^3`, the stability function of any 3-stage order-3 SDIRK
/// with diagonal gamma (Hairer & Wanner II, Sect. IV.6), from gamma alone: an
/// independent check of both the tableau and the stepping code.
fn r_closed_form(z: Complex<f64>) -> Complex<f64> {
    let g = GAMMA;
    let p = [1.0, 1.0 - 3.0 * g, 0.5 - 3.0 * g + 3.0 * g * g];
    let num = p[0] + z * (p[1] + z * p[2]); // cubic term is zero for the L-stable gamma
    num / (1.0 - z * g).powi(3)
}

#[test]
fn one_step_on_dahlquist_equation_multiplies_by_r() {
    for &hl in &[-0.1, -1.0, -10.0, -1e3, -1e8] {
        let mut sys = Linear::<1> {
            m: SMatrix::from_element(hl),
            u: Vector1::zeros(),
            w: 0.0,
        };
        let mut stepper = Sdirk::<Const<1>>::new(1.0, tight()).unwrap();
        let mut y = Vector1::new(1.0);
        stepper.step(&mut sys, 0.0, &mut y).unwrap();
        let r_tab = ALEXANDER3
            .stability_function(Complex::new(hl, 0.0), false)
            .re;
        let r_cf = r_closed_form(Complex::new(hl, 0.0)).re;
        // Linear problem with exact Jacobian: Newton is exact up to round-off of a few
        // flops on O(1) numbers, so agreement to ~1e-14 absolute.
        assert!(
            (y[0] - r_tab).abs() < 1e-14,
            "h*lambda = {hl}: {} vs {r_tab}",
            y[0]
        );
        assert!((r_tab - r_cf).abs() < 1e-14);
    }
}

/// (a) Prothero-Robinson `y' = lambda (y - sin t) + cos t`, exact `y = sin t`, with
/// `lambda = -1e8`, through the default finite-difference Jacobian (closure system).
#[test]
fn prothero_robinson_stays_on_the_slow_solution() {
    let lambda = -1e8;
    let mut sys = |t: f64, y: &Vector1<f64>| Vector1::new(lambda * (y[0] - t.sin()) + t.cos());
    for &h in &[0.1, 0.05, 0.02, 0.01] {
        let mut stepper = Sdirk::<Const<1>>::new(h, tight()).unwrap();
        let (mut t, mut y) = (0.0, Vector1::new(0.0));
        let n = (10.0 / h).round() as usize;
        let mut max_err: f64 = 0.0;
        for _ in 0..n {
            stepper.step(&mut sys, t, &mut y).unwrap();
            t += h;
            max_err = max_err.max((y[0] - t.sin()).abs());
        }
        println!("Prothero-Robinson h = {h}: max |y - sin t| over [0, 10] = {max_err:.2e}");
        // Stiff-limit analysis (Hairer & Wanner II, Sect. IV.15): the stage errors are
        // (h lambda A)^{-1} times the stage quadrature defects O(h^2 g''), i.e.
        // C h / |lambda| with C = O(1) (|g''| <= 1, entries of A^{-1} ~ 1-5). An unstable
        // or ringing method would instead show errors growing to O(1).
        assert!(max_err < h / lambda.abs(), "h = {h}: {max_err:e}");
    }
}

/// (b) `y' = M y`, `M = P diag(-1, -1e7) P^{-1}`: observed order 3 on the slow mode.
#[test]
fn stiff_linear_2x2_converges_with_order_three() {
    let p = Matrix2::new(1.0, 1.0, 0.5, -1.0);
    let p_inv = p.try_inverse().unwrap();
    let m = p * Matrix2::new(-1.0, 0.0, 0.0, -1e7) * p_inv;
    let y0 = Vector2::new(1.0, 2.0);
    let t_end: f64 = 1.0;
    // Exact: P diag(e^-t, e^-1e7 t) P^{-1} y0; the fast factor underflows to 0.
    let exact = p * Matrix2::new((-t_end).exp(), 0.0, 0.0, 0.0) * p_inv * y0;
    let mut errors = Vec::new();
    for &n in &[10usize, 20, 40, 80] {
        let h = t_end / n as f64;
        let mut sys = Linear::<2> {
            m,
            u: Vector2::zeros(),
            w: 0.0,
        };
        let mut stepper = Sdirk::<Const<2>>::new(h, tight()).unwrap();
        let (mut t, mut y) = (0.0, y0);
        stepper.advance(&mut sys, &mut t, &mut y, n).unwrap();
        errors.push((y - exact).norm());
    }
    let ratios: Vec<f64> = errors.windows(2).map(|e| e[0] / e[1]).collect();
    println!(
        "2x2 stiff linear: errors {:?}, ratios {ratios:.3?}",
        errors
            .iter()
            .map(|e| format!("{e:.3e}"))
            .collect::<Vec<_>>()
    );
    // Order 3 gives ratio 2^3 = 8 as h -> 0; the O(h^4) term shifts it by a few % at
    // h = 0.1.
    for r in &ratios {
        assert!((7.0..9.0).contains(r), "ratio {r}");
    }
}

/// (c) Undamped oscillator: the energy decays per step by exactly |R(i w h)|^2.
#[test]
fn harmonic_oscillator_energy_decays_as_stability_function_predicts() {
    let w = 2.0 * std::f64::consts::PI; // period 1 s
    let steps_per_period = 50;
    let h = 1.0 / steps_per_period as f64;
    let mut sys = Linear::<2> {
        m: Matrix2::new(0.0, 1.0, -w * w, 0.0),
        u: Vector2::zeros(),
        w: 0.0,
    };
    let energy = |y: &Vector2<f64>| 0.5 * (y[1] * y[1] + w * w * y[0] * y[0]);
    let mut stepper = Sdirk::<Const<2>>::new(h, tight()).unwrap();
    let (mut t, mut y) = (0.0, Vector2::new(1.0, 0.0));
    let e0 = energy(&y);
    let periods = 10;
    stepper
        .advance(&mut sys, &mut t, &mut y, periods * steps_per_period)
        .unwrap();
    let decay_per_period = (energy(&y) / e0).powf(1.0 / periods as f64);
    // In coordinates (w x, v) the system matrix is skew-symmetric, so one step is a
    // normal map with eigenvalues R(+-i w h) of equal modulus: the energy is multiplied
    // by |R(i w h)|^2 each step, for any initial state.
    let predicted = r_closed_form(Complex::new(0.0, w * h))
        .norm()
        .powi(2 * steps_per_period as i32);
    println!("oscillator, w h = {:.4}: energy factor per period {decay_per_period:.10}, |R|^100 = {predicted:.10}", w * h);
    // Only round-off (~500 steps x 1e-16) separates the two.
    assert!((decay_per_period - predicted).abs() < 1e-12);
    // And the decay is real (numerical dissipation of the L-stable method, O((w h)^4)
    // per step), eight orders of magnitude above the round-off tolerance above.
    assert!(predicted < 1.0 - 1e-4);
}

/// (d) Damped forced oscillator `x'' + 2 zeta w x' + w^2 x = F cos(W t)`: steady-state
/// amplitude `F / sqrt((w^2 - W^2)^2 + (2 zeta w W)^2)` and phase
/// `atan2(2 zeta w W, w^2 - W^2)` (e.g. Rao, Mechanical Vibrations, eq. 3.60-3.61).
#[test]
fn damped_forced_oscillator_reaches_closed_form_steady_state() {
    let (w, zeta, f) = (2.0 * std::f64::consts::PI, 0.05, 1.0); // rad/s, -, m/s^2
    let big_w = 1.3 * w;
    let amp = f / ((w * w - big_w * big_w).powi(2) + (2.0 * zeta * w * big_w).powi(2)).sqrt();
    let phase = (2.0 * zeta * w * big_w).atan2(w * w - big_w * big_w);
    let period = 2.0 * std::f64::consts::PI / big_w;
    for &per_period in &[100usize, 200] {
        let h = period / per_period as f64;
        let mut sys = Linear::<2> {
            m: Matrix2::new(0.0, 1.0, -w * w, -2.0 * zeta * w),
            u: Vector2::new(0.0, f),
            w: big_w,
        };
        let mut stepper = Sdirk::<Const<2>>::new(h, tight()).unwrap();
        // 130 forcing periods = 100 s: the free response has decayed by
        // exp(-zeta w 100 s) = 2e-14.
        let (mut t, mut y) = (0.0, Vector2::new(0.0, 0.0));
        stepper
            .advance(&mut sys, &mut t, &mut y, 130 * per_period)
            .unwrap();
        // Fourier coefficients over 10 whole periods: the rectangle rule is exact for
        // trigonometric polynomials of degree < samples, so it adds no error.
        let (mut a, mut b) = (0.0, 0.0);
        let n = 10 * per_period;
        for _ in 0..n {
            a += y[0] * (big_w * t).cos();
            b += y[0] * (big_w * t).sin();
            stepper.advance(&mut sys, &mut t, &mut y, 1).unwrap();
        }
        let (a, b) = (2.0 * a / n as f64, 2.0 * b / n as f64);
        let amp_err = (a.hypot(b) - amp).abs() / amp;
        let phase_err = (b.atan2(a) - phase).abs();
        println!(
            "forced oscillator, {per_period} steps/period: amplitude {:.8e} (exact {amp:.8e}), rel. error {amp_err:.2e}, phase error {phase_err:.2e} rad",
            a.hypot(b)
        );
        // Order-3 global error ~ (W h)^3 = (2 pi / 100)^3 = 2.5e-4 at worst, times an
        // error constant below 1.
        assert!(amp_err < 2.5e-4 && phase_err < 2.5e-4);
    }
}

/// Jacobian and LU are reused across stages and steps while Newton contracts fast;
/// finite differences cost N + 1 rhs calls per Jacobian.
#[test]
fn linear_problem_factorises_once_and_counts_work() {
    let m = Matrix2::new(-2.0, 1.0, 1.0, -1e6);
    let mut sys_fd = move |_t: f64, y: &Vector2<f64>| m * y;
    let mut stepper = Sdirk::<Const<2>>::new(0.01, SdirkOptions::default()).unwrap();
    let (mut t, mut y) = (0.0, Vector2::new(1.0, 1.0));
    let first = stepper.step(&mut sys_fd, t, &mut y).unwrap();
    t += 0.01;
    assert_eq!(first.jacobian_evals, 1);
    assert_eq!(first.lu_factorizations, 1);
    // Every Newton iteration costs one rhs call; the FD Jacobian N + 1 = 3 more.
    assert_eq!(first.rhs_calls, first.newton_iterations + 3);
    let rest = stepper.advance(&mut sys_fd, &mut t, &mut y, 200).unwrap();
    // A linear system's Jacobian is constant: no refresh in 200 steps.
    assert_eq!(rest.jacobian_evals, 0);
    assert_eq!(rest.lu_factorizations, 0);
    assert_eq!(rest.steps, 200);
    assert_eq!(rest.rhs_calls, rest.newton_iterations);
    // With the exact Jacobian one correction solves each (linear) stage equation; a
    // second one measures the rate unless the first was already within ~9 tolerances
    // (see the stopping rule in sdirk.rs): 1 or 2 iterations per stage.
    assert!(rest.newton_iterations >= 600 && rest.newton_iterations <= 1200);
    let total = stepper.stats();
    assert_eq!(total.steps, 201);
    assert_eq!(total.rhs_calls, first.rhs_calls + rest.rhs_calls);
}

/// A stiffness jump makes the stale LU diverge: the stage is redone with a Jacobian
/// evaluated at the stage time, and the solution still follows the exact one.
#[test]
fn stiffness_jump_triggers_refresh_and_retry() {
    // y' = -k(t) (y - cos t), k jumping from 1e6 to 5e6 1/s at t = 0.5 s. After the
    // initial layer the solution is the slow manifold y = cos t + sin t / k - cos t / k^2
    // + ... (expansion in 1/k).
    let k = |t: f64| if t < 0.5 { 1e6 } else { 5e6 };
    let mut sys = move |t: f64, y: &Vector1<f64>| Vector1::new(-k(t) * (y[0] - t.cos()));
    let h = 0.01;
    let mut stepper = Sdirk::<Const<1>>::new(h, SdirkOptions::default()).unwrap();
    let (mut t, mut y) = (0.0, Vector1::new(1.0));
    let stats = stepper.advance(&mut sys, &mut t, &mut y, 100).unwrap();
    // Stale matrix 1 + h g 1e6 against the true 1 + h g 5e6: Newton multiplies the error
    // by |1 - 5| = 4 > 1 -> exactly one failure, one refresh at the stage time, no error.
    assert_eq!(stats.retries, 1, "{stats:?}");
    // One Jacobian at the start, one for the retry.
    assert_eq!(stats.jacobian_evals, 2, "{stats:?}");
    // Stiff-limit error C h / k ~ 2e-9 (see the Prothero-Robinson test); the 1/k^2 term
    // of the expansion is 4e-14.
    let slow = t.cos() + t.sin() / k(t);
    assert!((y[0] - slow).abs() < 1e-8, "{} vs {slow}", y[0]);
}

/// A slowly drifting Jacobian is refreshed when the contraction rate exceeds
/// `refresh_rate`, without any Newton failure.
#[test]
fn drifting_jacobian_is_refreshed_on_slow_contraction() {
    // y' = -k(t) (y - cos t) with k = 1e6 (1 + t) 1/s. With J frozen at t_J the rate is
    // theta ~ 1 - k(t_J)/k(t) (stiff limit), which passes 0.1 when k grew by 11 %:
    // over t in [0, 1] (k doubles) that is ln 2 / ln(1/0.9) = 6.6 refreshes + the first.
    let k = |t: f64| 1e6 * (1.0 + t);
    let mut sys = move |t: f64, y: &Vector1<f64>| Vector1::new(-k(t) * (y[0] - t.cos()));
    let mut stepper = Sdirk::<Const<1>>::new(0.01, SdirkOptions::default()).unwrap();
    let (mut t, mut y) = (0.0, Vector1::new(1.0));
    let stats = stepper.advance(&mut sys, &mut t, &mut y, 100).unwrap();
    println!("drifting Jacobian: {stats:?}");
    assert_eq!(stats.retries, 0, "{stats:?}");
    assert!((6..=10).contains(&stats.jacobian_evals), "{stats:?}");
    // Slow manifold y = cos t + sin t / k + O(1/k^2); stiff-limit error ~ h / k = 5e-9.
    let slow = t.cos() + t.sin() / k(t);
    assert!((y[0] - slow).abs() < 1e-8, "{} vs {slow}", y[0]);
}
