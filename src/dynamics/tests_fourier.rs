use super::*;
use std::f64::consts::PI;

/// A reproducible uniform deviate in [0, 1) (a small LCG: test data only).
fn uniform(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// Non-uniform points over [t0, t0 + period): spacings from 0.01 to 1 of the mean, with
/// runs of short steps as after a mesh event.
fn grid(n: usize, t0: f64, period: f64, seed: u64) -> Vec<f64> {
    let mut s = seed;
    let raw: Vec<f64> = (0..n)
        .map(|i| {
            let short = i % 37 < 5;
            if short {
                0.01 + 0.05 * uniform(&mut s)
            } else {
                0.2 + uniform(&mut s)
            }
        })
        .collect();
    let total: f64 = raw.iter().sum();
    let mut t = Vec::with_capacity(n);
    let mut acc = t0;
    for r in raw {
        t.push(acc);
        acc += r / total * period;
    }
    t
}

/// C_k of the interpolant by a second method: composite 24-point Gauss-Legendre on every
/// step of the cubic times e^(-i w_k (t - origin)), summed directly (no cells, no FFT, no
/// series).
fn by_quadrature(h: &HermitePeriod, origin: f64, k: usize) -> Complex64 {
    let (x, w) = legendre_24();
    let wk = 2.0 * PI * k as f64 / h.period_s;
    let mut sum = Complex64::new(0.0, 0.0);
    for j in 0..h.t.len() {
        let s = h.step(j);
        for (g, wg) in x.iter().zip(&w) {
            let u = 0.5 * s.h * (1.0 + g);
            let t = s.t0 + u;
            sum += Complex64::from_polar(s.at(u) * wg * 0.5 * s.h, -wk * (t - origin));
        }
    }
    sum * if k == 0 { 1.0 } else { 2.0 } / h.period_s
}

/// 24-point Gauss-Legendre rule (Newton on P_24 from Chebyshev guesses), checked against
/// exact polynomial integrals in `the_tests_own_24_point_rule_integrates_degree_47_exactly`.
fn legendre_24() -> (Vec<f64>, Vec<f64>) {
    let n = 24;
    let mut x = Vec::new();
    let mut w = Vec::new();
    for i in 0..n {
        let mut z = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                let dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                x.push(z);
                w.push(2.0 / ((1.0 - z * z) * dp * dp));
                break;
            }
        }
    }
    (x, w)
}

#[test]
fn the_tests_own_24_point_rule_integrates_degree_47_exactly() {
    // The second method's rule is computed by a Newton iteration like the module's own;
    // what makes it independent is this check against the exact integrals of x^p on
    // [-1, 1] (2 / (p + 1) for even p, 0 for odd), the defining property of a 24-point
    // Gauss rule (exact to degree 2 * 24 - 1 = 47). Round-off of 24 terms of size <= 2:
    // ~1e-15; 1e-14 allowed.
    let (x, w) = legendre_24();
    assert_eq!(x.len(), 24, "every node converged");
    for p in 0..=47 {
        let q: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(p)).sum();
        let exact = if p % 2 == 1 {
            0.0
        } else {
            2.0 / (p + 1) as f64
        };
        assert!((q - exact).abs() < 1e-14, "degree {p}: {q} vs {exact}");
    }
}

#[test]
fn gauss_legendre_integrates_degree_25_exactly() {
    let (x, w) = gauss_legendre();
    for p in 0..=25 {
        let q: f64 = x.iter().zip(w).map(|(x, w)| w * x.powi(p)).sum();
        let exact = if p % 2 == 1 {
            0.0
        } else {
            2.0 / (p + 1) as f64
        };
        assert!((q - exact).abs() < 1e-14, "degree {p}: {q} vs {exact}");
    }
}

#[test]
fn coefficients_of_any_piecewise_cubic_match_direct_quadrature() {
    // Random values and slopes on a non-uniform grid, the slope jumping at every point
    // (slope_end[j] != slope_start[j + 1]) as the velocity's does at a mesh event; the
    // period starts off the time origin. Lines 0..=300 (far beyond the points' own
    // Nyquist at some steps, below it at others).
    let (period, t0, origin) = (1.7e-3, 0.37e-3, 0.1e-3);
    let t = grid(400, t0, period, 7);
    let mut s = 11;
    let x: Vec<f64> = (0..t.len()).map(|_| uniform(&mut s) - 0.5).collect();
    let d0: Vec<f64> = (0..t.len())
        .map(|_| (uniform(&mut s) - 0.5) / period * 50.0)
        .collect();
    let d1: Vec<f64> = (0..t.len())
        .map(|_| (uniform(&mut s) - 0.5) / period * 50.0)
        .collect();
    let h = HermitePeriod {
        t,
        x,
        slope_start: d0,
        slope_end: d1,
        period_s: period,
    };
    let c = h.coefficients(origin, 300);
    let scale = c.iter().fold(0.0_f64, |m, v| m.max(v.norm()));
    let mut worst = 0.0_f64;
    for k in (0..=300).step_by(7).chain([1, 2, 299, 300]) {
        let q = by_quadrature(&h, origin, k);
        worst = worst.max((c[k] - q).norm() / scale);
    }
    println!(
        "piecewise cubic: largest difference to direct quadrature {worst:.2e} of the largest line"
    );
    // Round-off of sums over ~1e4 quadrature terms: ~1e-15 relative; 1e-12 allowed.
    assert!(worst < 1e-12, "{worst:e}");
}

#[test]
fn a_trigonometric_polynomial_on_integrator_like_points_gives_its_lines_to_1e_9() {
    // x = 0.3 + sum_k a_k cos(w_k t + phi_k), k = 1, 2, 5, 17, sampled with its exact
    // derivative on 3000 non-uniform points per period: the Hermite interpolant's error is
    // h^4 x'''' / 384 <= (2 pi 17 / 3000 x 5)^4 / 384 ~ 1e-9 of a_17 on the longest steps,
    // and averages down over the period. Every other line is zero.
    let period = 1.0 / 570.0;
    let lines = [
        (1, 2.0, 0.3),
        (2, 0.7, -1.1),
        (5, 0.25, 2.0),
        (17, 0.05, 0.4),
    ];
    let t = grid(3000, 0.0, period, 3);
    let w = |k: usize| 2.0 * PI * k as f64 / period;
    let x: Vec<f64> = t
        .iter()
        .map(|t| {
            0.3 + lines
                .iter()
                .map(|(k, a, p)| a * (w(*k) * t + p).cos())
                .sum::<f64>()
        })
        .collect();
    let dx: Vec<f64> = t
        .iter()
        .map(|t| {
            lines
                .iter()
                .map(|(k, a, p)| -a * w(*k) * (w(*k) * t + p).sin())
                .sum::<f64>()
        })
        .collect();
    // The slope at the end of step j is the one at the next point (the last step ends on
    // the period's first point).
    let mut next = dx[1..].to_vec();
    next.push(dx[0]);
    let h = HermitePeriod {
        t,
        x,
        slope_start: dx,
        slope_end: next,
        period_s: period,
    };
    let c = h.coefficients(0.0, 40);
    assert!((c[0].re - 0.3).abs() < 1e-9 && c[0].im.abs() < 1e-12);
    let mut worst = 0.0_f64;
    for (k, ck) in c.iter().enumerate().skip(1) {
        let want = lines
            .iter()
            .find(|(kk, _, _)| *kk == k)
            .map_or(Complex64::new(0.0, 0.0), |(_, a, p)| {
                Complex64::from_polar(*a, *p)
            });
        worst = worst.max((ck - want).norm());
    }
    println!("trigonometric polynomial: largest line error {worst:.2e} (amplitudes 0.05-2)");
    assert!(worst < 1e-9, "{worst:e}");
}

#[test]
fn the_linear_interpolant_is_the_chords() {
    // The triangle wave x = t on [0, 1], 2 - t on [1, 2] (period 2) has its corners on
    // points, so the chords are the signal: x = 1/2 - (4 / pi^2) sum_(k odd) cos(pi k t)
    // / k^2, i.e. C_0 = 1/2 and C_k = -4 / (pi k)^2 for odd k, 0 for even k.
    let period = 2.0;
    let t: Vec<f64> = vec![0.0, 0.3, 1.0, 1.25, 1.9];
    let x: Vec<f64> = t
        .iter()
        .map(|t| if *t <= 1.0 { *t } else { 2.0 - t })
        .collect();
    let h = HermitePeriod::linear(t, x, period);
    let c = h.coefficients(0.0, 9);
    assert!((c[0].re - 0.5).abs() < 1e-14);
    for (k, ck) in c.iter().enumerate().skip(1) {
        let want = if k % 2 == 1 {
            -4.0 / (PI * k as f64).powi(2)
        } else {
            0.0
        };
        assert!(
            (ck - Complex64::new(want, 0.0)).norm() < 1e-14,
            "k = {k}: {ck}"
        );
    }
}
