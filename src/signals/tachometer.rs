//! The tachometer: a pulse train of N pulses per revolution of a chosen shaft, recorded
//! through the same anti-alias filter as the accelerometers (as a data acquisition
//! system records a tachometer on an analog channel, e.g. PHM 2009), and the pulse times
//! read back from the record.
//!
//! Pulse k (k = 0, 1, ...) rises when the shaft's angle reaches 2 pi k / N (angle 0 at
//! time 0, where the mesh phase is 0 too) and stays at `HIGH_V` for half the pulse
//! interval (TTL level, 50 % duty), 0 V otherwise. The shaft angle is its nominal
//! rotation, the angle the model's mesh phase follows (`dynamics::model`: the vibratory
//! twist, ~1e-5 rad, is neglected there and here).
//!
//! Pulse times are read as rising crossings of half the high level (re-armed below a
//! quarter of it), first by linear interpolation between samples, then refined on the
//! band-limited interpolant of the record (`super::interp`) by the secant method: the
//! filtered edge is a band-limited ramp a few samples long, on which a straight line
//! between two samples is off by a few percent of a sample.

use super::interp;
use super::periodic::PeriodicSignal;
use realfft::num_complex::Complex64;
use std::f64::consts::PI;

/// Level of a pulse, V.
pub(crate) const HIGH_V: f64 = 5.0;
/// Fraction of the pulse interval the signal is high.
pub(crate) const DUTY: f64 = 0.5;

/// The pulse train of a shaft turning at constant speed with period `revolution_s`, `n`
/// pulses per revolution, as a Fourier series up to `max_hz` (period = one pulse
/// interval): c_0 = V d, c_k = 2 V e^(-i pi k d) sin(pi k d) / (pi k).
pub fn pulse_series(revolution_s: f64, n: usize, max_hz: f64) -> PeriodicSignal {
    let period = revolution_s / n as f64;
    let harmonics = (max_hz * period).floor() as usize + 1;
    let coefficients = (0..harmonics)
        .map(|k| {
            if k == 0 {
                return Complex64::new(HIGH_V * DUTY, 0.0);
            }
            let kk = k as f64;
            Complex64::from_polar(
                2.0 * HIGH_V * (PI * kk * DUTY).sin() / (PI * kk),
                -PI * kk * DUTY,
            )
        })
        .collect();
    PeriodicSignal {
        period_s: period,
        coefficients,
    }
}

/// Times of the rising edges in a tachometer record sampled at `fs_hz` (module docs).
pub fn rising_edges(x: &[f64], fs_hz: f64) -> Vec<f64> {
    let (level, rearm) = (0.5 * HIGH_V, 0.25 * HIGH_V);
    let mut armed = x.first().is_some_and(|v| *v < rearm);
    let mut edges = Vec::new();
    for i in 1..x.len() {
        if x[i] < rearm {
            armed = true;
        }
        if armed && x[i - 1] < level && x[i] >= level {
            armed = false;
            let frac = (level - x[i - 1]) / (x[i] - x[i - 1]);
            let mut t = (i as f64 - 1.0 + frac) / fs_hz;
            if interp::inside(x.len(), fs_hz, t) {
                t = refine(x, fs_hz, t, level);
            }
            edges.push(t);
        }
    }
    edges
}

/// The crossing of `level` near `t` on the band-limited interpolant (secant steps).
fn refine(x: &[f64], fs: f64, t: f64, level: f64) -> f64 {
    let f = |t: f64| interp::at(x, fs, t) - level;
    let (mut a, mut b) = (t - 0.1 / fs, t + 0.1 / fs);
    let (mut fa, mut fb) = (f(a), f(b));
    for _ in 0..8 {
        if fb == fa {
            break;
        }
        let c = b - fb * (b - a) / (fb - fa);
        // A step out of the sample interval around the first estimate is not the edge.
        if (c - t).abs() > 1.0 / fs {
            return t;
        }
        (a, fa) = (b, fb);
        b = c;
        fb = f(b);
        if (b - a).abs() < 1e-9 / fs {
            break;
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signals::antialias::AntiAliasFilter;

    #[test]
    fn series_mean_and_level_are_the_pulse_trains() {
        let p = pulse_series(0.1, 4, 200_000.0);
        // Mean V d; in the middle of the high half the sum tends to V (Gibbs only at edges).
        assert!((p.coefficients[0].re - 2.5).abs() < 1e-15);
        assert!((p.at(0.25 * p.period_s) - HIGH_V).abs() < 1e-2);
        assert!(p.at(0.75 * p.period_s).abs() < 1e-2);
    }

    #[test]
    fn edges_of_a_filtered_pulse_train_are_found_to_a_thousandth_of_a_sample() {
        let fs = 25_600.0;
        let aa = AntiAliasFilter::design(fs, 100.0);
        // 29.3 Hz shaft, 3 pulses a revolution: edges at k / (3 x 29.3) s.
        let rev = 1.0 / 29.3;
        let p = pulse_series(rev, 3, 0.5 * aa.internal_rate_hz);
        let filtered = p.map(|k, f| p.coefficients[k] * aa.response(f));
        let x = filtered.sample(0.0, fs, 25_600);
        let edges = rising_edges(&x, fs);
        assert!(edges.len() >= 85, "{}", edges.len());
        for t in &edges {
            let k = (t * 3.0 / rev).round();
            let want = k * rev / 3.0;
            assert!((t - want).abs() < 1e-3 / fs, "{t} vs {want}");
        }
    }
}
