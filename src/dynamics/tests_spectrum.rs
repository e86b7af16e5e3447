use super::*;
use crate::dynamics::model::dof;
use crate::dynamics::response::{DynamicResponse, Signals};
use crate::dynamics::summary::velocity_y_spectrum;
use realfft::num_complex::Complex64;
use std::f64::consts::PI;

/// A periodic test signal of known Fourier coefficients: three harmonics of the period
/// plus a transient that no uniform grid of 256 points per period resolves, the response
/// of the velocity to a kick of the acceleration at t_a: B = A s (1 - s)^2 for
/// s = (t - t_a) / w in [0, 1] (w a few microseconds), 0 elsewhere. B is continuous (a
/// velocity is), a cubic between its knots t_a and t_a + w, with a jump of its slope of
/// A / w at t_a (the force jumps at a mesh event) and a smooth end.
struct Known {
    period: f64,
    lines: [(usize, f64, f64); 3],
    kick_at: f64,
    kick_width: f64,
    kick: f64,
}

impl Known {
    fn w(&self, k: usize) -> f64 {
        2.0 * PI * k as f64 / self.period
    }

    /// Value and slope at t (inside the period); `right`: the limit from the right at the
    /// kick's start.
    fn at(&self, t: f64, right: bool) -> (f64, f64) {
        let (mut x, mut d) = (0.0, 0.0);
        for (k, a, p) in self.lines {
            x += a * (self.w(k) * t + p).cos();
            d -= a * self.w(k) * (self.w(k) * t + p).sin();
        }
        let s = (t - self.kick_at) / self.kick_width;
        if (s > 0.0 || (s == 0.0 && right)) && s <= 1.0 {
            x += self.kick * s * (1.0 - s).powi(2);
            d += self.kick * ((1.0 - s).powi(2) - 2.0 * s * (1.0 - s)) / self.kick_width;
        }
        (x, d)
    }

    /// C_k (one-sided, phase at t = 0) of the whole signal. The kick's by the jump
    /// formula for a piecewise polynomial: int_0^T B e^(-i w t) dt = sum over its knots
    /// e^(-i w tau) sum_m [B^(m)(tau+) - B^(m)(tau-)] / (i w)^(m+1). With
    /// B = A (s - 2 s^2 + s^3): at t_a the jumps of B, B', B'', B''' are 0, A/w, -4A/w^2,
    /// 6A/w^3; at t_a + w they are 0, 0, -2A/w^2, -6A/w^3.
    fn line(&self, k: usize) -> Complex64 {
        let mut c = Complex64::new(0.0, 0.0);
        for (kk, a, p) in self.lines {
            if kk == k {
                c += Complex64::from_polar(a, p);
            }
        }
        let w = self.w(k);
        let iw = Complex64::new(0.0, w);
        let (a, wd) = (self.kick, self.kick_width);
        let knots = [
            (
                self.kick_at,
                [0.0, a / wd, -4.0 * a / (wd * wd), 6.0 * a / wd.powi(3)],
            ),
            (
                self.kick_at + wd,
                [0.0, 0.0, -2.0 * a / (wd * wd), -6.0 * a / wd.powi(3)],
            ),
        ];
        let mut b = Complex64::new(0.0, 0.0);
        for (tau, jumps) in knots {
            let mut sum = Complex64::new(0.0, 0.0);
            for (m, j) in jumps.iter().enumerate() {
                sum += j / iw.powu(m as u32 + 1);
            }
            b += sum * Complex64::from_polar(1.0, -w * tau);
        }
        c + b * 2.0 / self.period
    }
}

/// The signal sampled as the integrator samples: an event-aligned grid of `per_period`
/// points per period with short steps after the kick (its start and end are points).
fn integrator_like(k: &Known, per_period: usize) -> DynamicResponse {
    let mut t: Vec<f64> = (0..per_period)
        .map(|i| k.period * i as f64 / per_period as f64)
        .filter(|t| (*t - k.kick_at).abs() > 1e-12 && (*t - k.kick_at - k.kick_width).abs() > 1e-12)
        .collect();
    for i in 0..=6 {
        t.push(k.kick_at + k.kick_width * i as f64 / 6.0);
    }
    t.sort_by(f64::total_cmp);
    t.dedup_by(|a, b| (*a - *b).abs() < 1e-15);
    let n = t.len();
    let mut sig = Signals::new(8, 1);
    for (j, tj) in t.iter().enumerate() {
        let t1 = if j + 1 < n { t[j + 1] } else { k.period };
        let mut v = [0.0; 8];
        v[dof::YP] = k.at(*tj, true).0;
        let mut a0 = [0.0; 8];
        a0[dof::YP] = k.at(*tj, true).1;
        let mut a1 = [0.0; 8];
        a1[dof::YP] = k.at(t1 % k.period, false).1;
        sig.time_s.push(*tj);
        sig.velocity.push(&v);
        sig.step_acceleration[0].push(&a0);
        sig.step_acceleration[1].push(&a1);
    }
    DynamicResponse {
        signals: sig,
        mesh_period_s: k.period,
        excitation_periods: 1,
        ..DynamicResponse::default()
    }
}

#[test]
fn a_periodic_signal_of_known_lines_gives_them_to_1e_9_through_the_spectrum_path() {
    // 570 Hz, harmonics 1, 2, 5 of 2, 0.5, 0.1 and a 4 us kick of slope 0.3 / 4 us (what the bearing
    // dampers' fast decay after a mesh event looks like), sampled on 4000 points per
    // period: the Hermite interpolant's error on the harmonics, (2 pi 5 / 4000)^4 / 384 of
    // 0.1 ~ 1e-12, is far below 1e-9; the kick is a cubic on its points, exact.
    let known = Known {
        period: 1.0 / 570.0,
        lines: [(1, 2.0, 0.3), (2, 0.5, -1.0), (5, 0.1, 2.5)],
        kick_at: 0.4 / 570.0,
        kick_width: 4e-6,
        kick: 0.3,
    };
    let r = integrator_like(&known, 4000);
    let s = velocity_y_spectrum(&r);
    assert_eq!(s.bins_per_harmonic, 1);
    let mut worst = 0.0_f64;
    for k in 1..s.amplitude.len() {
        worst = worst.max((s.amplitude[k] - known.line(k).norm()).abs());
    }
    println!(
        "{} lines: largest error {worst:.2e} (line 1: {:.12} vs {:.12}; kick lines ~{:.2e})",
        s.amplitude.len() - 1,
        s.amplitude[1],
        known.line(1).norm(),
        2.0 * 0.3 * known.kick_width / 12.0 / known.period
    );
    assert!(worst < 1e-9, "{worst:e}");
    // The same through a coarser grid (230 points per period, as the solver records the
    // paper's case): the harmonics are then known to the Hermite error only, but the
    // kick, a cubic on its points, stays exact: the lines of the kick alone (harmonics
    // removed) are exact to round-off on any grid.
    let kick_only = Known {
        lines: [(1, 0.0, 0.0), (2, 0.0, 0.0), (5, 0.0, 0.0)],
        ..known
    };
    let r = integrator_like(&kick_only, 230);
    let s = velocity_y_spectrum(&r);
    let mut worst = 0.0_f64;
    for k in 1..s.amplitude.len() {
        worst = worst.max((s.amplitude[k] - kick_only.line(k).norm()).abs());
    }
    // The reference's jump formula cancels (w_k w)^-4 ~ 1e7 at the lowest lines: ~1e-11.
    assert!(worst < 1e-10, "kick on 230 points: {worst:e}");
}

#[test]
fn a_window_of_repeated_periods_has_nothing_between_its_harmonics() {
    // The window repeats one period P times: every line that is not a multiple of P is
    // zero up to round-off (~1e-16 of the signal).
    let known = Known {
        period: 1.0 / 570.0,
        lines: [(1, 2.0, 0.3), (2, 0.5, -1.0), (5, 0.1, 2.5)],
        kick_at: 0.4 / 570.0,
        kick_width: 4e-6,
        kick: 0.3,
    };
    let one = integrator_like(&known, 300);
    let p = 4;
    let mut r = one.clone();
    for c in 1..p {
        let s = &one.signals;
        r.signals
            .time_s
            .extend(s.time_s.iter().map(|t| t + c as f64 * known.period));
        for v in s.velocity.iter() {
            r.signals.velocity.push(v);
        }
        for j in 0..2 {
            for a in s.step_acceleration[j].iter() {
                r.signals.step_acceleration[j].push(a);
            }
        }
    }
    let s = velocity_y_spectrum(&r);
    assert_eq!(s.bins_per_harmonic, p);
    let off = (1..s.amplitude.len())
        .filter(|k| k % p != 0)
        .fold(0.0_f64, |m, k| m.max(s.amplitude[k]));
    assert!(off < 1e-13, "{off:e}");
    assert!((s.harmonic(1) - velocity_y_spectrum(&one).harmonic(1)).abs() < 1e-13);
}

#[test]
fn time_rms_of_sine_is_amplitude_over_root_two() {
    let n = 1000;
    let t: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
    let x: Vec<f64> = t.iter().map(|t| (2.0 * PI * t).sin()).collect();
    // Trapezoid on a periodic smooth integrand is spectrally accurate.
    assert!((time_rms(&t, &x, 1.0) - 0.5f64.sqrt()).abs() < 1e-12);
    assert!(time_mean(&t, &x, 1.0).abs() < 1e-12);
}
