//! Band-limited interpolation of a uniformly sampled signal at arbitrary instants: a
//! Kaiser-windowed sinc (Smith, "Digital Audio Resampling", CCRMA; Oppenheim & Schafer,
//! Sect. 4.6 and 7.5.3).
//!
//! `x(t) = sum_n x[n] sinc(f_s t - n) w(f_s t - n)`, w the Kaiser window of half-width
//! `HALF_WIDTH` samples with beta for 100 dB. The kernel passes content up to 0.4 f_s
//! with an error below ~1e-5 of its amplitude: the recorded channels are band-limited to
//! f_s / 2.56 by the anti-alias filter (`super::antialias`), so this resamples them to
//! any angle grid without the error of a polynomial interpolation, which at 0.4 f_s would
//! be tens of percent. Samples beyond the ends of the signal count as zero, so within
//! `HALF_WIDTH` samples of either end the interpolation is not band-limited; callers keep
//! away from the ends.

use super::antialias::{bessel_i0, kaiser_beta};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Half-width of the kernel, samples.
pub(crate) const HALF_WIDTH: usize = 16;
/// Edge of the kernel's passband over the sampling rate: flat within ~1e-5 up to it (the
/// Kaiser window's transition, (100 - 8) / (2.285 x 2 pi x 32) = 0.2 f_s wide, centred on
/// f_s / 2). Above it the kernel rolls off (0.4 % low at 0.423 f_s, 37 % at 0.49 f_s), so
/// what a TSA holds above it is left out of its indicators.
pub(crate) const PASSBAND_OVER_FS: f64 = 0.4;
/// Kernel table points per sample (linear interpolation between them: error ~1e-6).
const TABLE_PER_SAMPLE: usize = 1024;

fn kernel_table() -> &'static [f64] {
    static TABLE: OnceLock<Vec<f64>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let beta = kaiser_beta(100.0);
        let i0b = bessel_i0(beta);
        let l = HALF_WIDTH as f64;
        (0..=HALF_WIDTH * TABLE_PER_SAMPLE + 1)
            .map(|i| {
                let d = i as f64 / TABLE_PER_SAMPLE as f64;
                if d >= l {
                    return 0.0;
                }
                let sinc = if d == 0.0 {
                    1.0
                } else {
                    (PI * d).sin() / (PI * d)
                };
                let r = d / l;
                sinc * bessel_i0(beta * (1.0 - r * r).sqrt()) / i0b
            })
            .collect()
    })
}

/// The kernel at distance `d` samples.
#[inline]
fn kernel(table: &[f64], d: f64) -> f64 {
    let u = d.abs() * TABLE_PER_SAMPLE as f64;
    let i = u as usize;
    if i + 1 >= table.len() {
        return 0.0;
    }
    let w = u - i as f64;
    table[i] * (1.0 - w) + table[i + 1] * w
}

/// `x` (sampled at `fs_hz`, sample 0 at time 0) at time `t_s`.
pub fn at(x: &[f64], fs_hz: f64, t_s: f64) -> f64 {
    Weights::at(x.len(), fs_hz, t_s).apply(x)
}

/// The kernel's weights of the samples around one instant: what [`at`] sums, computed
/// once for signals sampled alike (the channels of one record), bit for bit the same.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Weights {
    /// First sample weighted.
    first: usize,
    /// Samples weighted (at most 2 `HALF_WIDTH`).
    count: usize,
    /// Their weights, in sample order.
    w: [f64; 2 * HALF_WIDTH],
}

impl Weights {
    /// The weights at time `t_s` of a signal of `len` samples at `fs_hz`.
    pub(crate) fn at(len: usize, fs_hz: f64, t_s: f64) -> Self {
        let table = kernel_table();
        let u = t_s * fs_hz;
        let c = u.floor() as isize;
        let l = HALF_WIDTH as isize;
        let lo = (c - l + 1).max(0);
        let hi = (c + l).min(len as isize - 1);
        let mut w = [0.0; 2 * HALF_WIDTH];
        let count = (hi - lo + 1).max(0) as usize;
        for (k, n) in (lo..=hi).enumerate() {
            w[k] = kernel(table, u - n as f64);
        }
        // Nothing weighted (an instant beyond the ends): an empty sum, as `at` gave.
        let first = if count == 0 { 0 } else { lo as usize };
        Self { first, count, w }
    }

    /// The interpolated value of `x` (the signal the weights were made for).
    #[inline]
    pub(crate) fn apply(&self, x: &[f64]) -> f64 {
        x[self.first..self.first + self.count]
            .iter()
            .zip(&self.w)
            .map(|(x, w)| x * w)
            .sum()
    }
}

/// Whether `t_s` lies far enough from both ends of `n` samples at `fs_hz` for the
/// interpolation to be band-limited.
pub fn inside(n: usize, fs_hz: f64, t_s: f64) -> bool {
    let u = t_s * fs_hz;
    u >= HALF_WIDTH as f64 && u <= n as f64 - 1.0 - HALF_WIDTH as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tones_up_to_0_4_fs_are_interpolated_to_1e_5() {
        let fs = 1000.0;
        for f in [13.7, 150.3, 290.1, 390.0] {
            let x: Vec<f64> = (0..2000)
                .map(|i| (2.0 * PI * f * i as f64 / fs + 0.4).cos())
                .collect();
            for k in 0..200 {
                let t = 0.5 + 0.9 * k as f64 / 200.0 + 1.3e-4;
                let want = (2.0 * PI * f * t + 0.4).cos();
                assert!((at(&x, fs, t) - want).abs() < 2e-5, "{f} Hz at {t}");
            }
        }
        // On a sample it returns the sample.
        let x: Vec<f64> = (0..100).map(|i| (i as f64).sin()).collect();
        assert!((at(&x, 1.0, 40.0) - x[40]).abs() < 1e-12);
    }
}
