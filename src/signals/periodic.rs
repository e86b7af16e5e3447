//! Periodic signals as Fourier series: how a periodic steady state travels through the
//! (linear, time-invariant) transfer path and the anti-alias filter, and is sampled.
//!
//! A signal of period T is x(t) = Re sum_k c_k e^(i 2 pi k t / T), c_0 the mean. From
//! samples on any grid over one period it is resampled linearly onto a uniform grid of a
//! power-of-two number of points (at least the samples given) and transformed; the
//! linear interpolant of the samples is the signal (as for the spectra of
//! `dynamics::spectrum`). A linear filter multiplies each c_k by its response at k / T:
//! for a periodic input this is the filter's steady-state output, exactly. To be sampled
//! at arbitrary instants, the series is transformed back onto a fine uniform grid of at
//! least `GRID_PER_SAMPLE` points per sampling interval and interpolated there with a
//! four-point Lagrange cubic: for content below f_s / 2 the grid holds >= 32 points per
//! cycle, where the cubic's amplitude error is below 3e-6.

#[cfg(test)]
use super::area::{box_response, cell_means};
use crate::dynamics::fourier::HermitePeriod;
use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;

/// Fine-grid points per sampling interval when a series is sampled.
pub(crate) const GRID_PER_SAMPLE: f64 = 16.0;

/// A periodic signal as its one-sided complex Fourier amplitudes.
#[derive(Debug, Clone, PartialEq)]
pub struct PeriodicSignal {
    /// Period T, s.
    pub period_s: f64,
    /// c_0 (the mean), c_1, c_2, ...: x(t) = Re sum c_k e^(i 2 pi k t / T).
    pub coefficients: Vec<Complex64>,
}

impl PeriodicSignal {
    /// From samples `(t, x)` over one period starting at `t[0]` (the period closes on
    /// the first sample): the Fourier series of their piecewise-linear interpolant, from
    /// its means over a uniform grid of at least 4 cells per sample (`super::area`: the
    /// area of every short-lived layer kept) with the cells' box filter divided out.
    /// Harmonics up to half the grid are kept.
    #[cfg(test)]
    pub(crate) fn from_samples(t: &[f64], x: &[f64], period_s: f64) -> Self {
        let n = (4 * t.len()).next_power_of_two().max(16);
        let w = period_s / n as f64;
        let t0 = t.first().copied().unwrap_or(0.0);
        // Cell i is centred on t0 + i w.
        let mut u = cell_means(t, x, t0 - 0.5 * w, w, n, Some(period_s));
        let mut planner = RealFftPlanner::<f64>::new();
        let fft = planner.plan_fft_forward(n);
        let mut spec = fft.make_output_vec();
        // Lengths match by construction; an error here would be a bug in realfft's plan.
        fft.process(&mut u, &mut spec)
            .expect("FFT buffers sized by the plan");
        // The series starts at t[0]: shift every harmonic to time 0.
        let coefficients = spec
            .iter()
            .enumerate()
            .take(n / 2)
            .map(|(k, c)| {
                let scale = if k == 0 { 1.0 } else { 2.0 } / n as f64;
                let f = k as f64 / period_s;
                let shift = Complex64::from_polar(1.0, -2.0 * std::f64::consts::PI * f * t0);
                c * scale * shift / box_response(f, w)
            })
            .collect();
        Self {
            period_s,
            coefficients,
        }
    }

    /// The Fourier series of a solver's solution over one period, harmonics 0..=`harmonics`
    /// with phases at time 0: the exact coefficients of its cubic Hermite interpolant
    /// (`dynamics::fourier`; no resampling, so nothing the solver resolved between two
    /// samples is lost).
    pub fn from_hermite(signal: &HermitePeriod, harmonics: usize) -> Self {
        Self {
            period_s: signal.period_s,
            coefficients: signal.coefficients(0.0, harmonics),
        }
    }

    /// Frequency of harmonic k, Hz.
    pub fn frequency_hz(&self, k: usize) -> f64 {
        k as f64 / self.period_s
    }

    /// A signal of the same period whose harmonic k is `f(k, frequency)`.
    pub fn map(&self, f: impl Fn(usize, f64) -> Complex64) -> Self {
        Self {
            period_s: self.period_s,
            coefficients: (0..self.coefficients.len())
                .map(|k| f(k, self.frequency_hz(k)))
                .collect(),
        }
    }

    /// Value at time t (direct sum; for checks and short evaluations).
    pub fn at(&self, t_s: f64) -> f64 {
        let w = 2.0 * std::f64::consts::PI * t_s / self.period_s;
        self.coefficients
            .iter()
            .enumerate()
            .map(|(k, c)| (c * Complex64::from_polar(1.0, w * k as f64)).re)
            .sum()
    }

    /// The signal at `t_0 + n / fs_hz`, n = 0..count (module docs).
    pub fn sample(&self, t0_s: f64, fs_hz: f64, count: usize) -> Vec<f64> {
        let harmonics = self.coefficients.len();
        let want = (GRID_PER_SAMPLE * fs_hz * self.period_s).ceil() as usize;
        let m = want.max(2 * harmonics).max(16).next_power_of_two();
        let grid = self.on_grid(m);
        let h = self.period_s / m as f64;
        (0..count)
            .map(|n| {
                let t = t0_s + n as f64 / fs_hz;
                let u = (t / h).rem_euclid(m as f64);
                let i = u.floor();
                let s = u - i;
                let i = i as usize;
                let at = |d: isize| grid[((i as isize + d).rem_euclid(m as isize)) as usize];
                // Four-point Lagrange cubic on points -1, 0, 1, 2.
                let (y0, y1, y2, y3) = (at(-1), at(0), at(1), at(2));
                -s * (s - 1.0) * (s - 2.0) / 6.0 * y0 + (s + 1.0) * (s - 1.0) * (s - 2.0) / 2.0 * y1
                    - (s + 1.0) * s * (s - 2.0) / 2.0 * y2
                    + (s + 1.0) * s * (s - 1.0) / 6.0 * y3
            })
            .collect()
    }

    /// The signal on `m` uniform points over one period from time 0 (m a power of two,
    /// at least twice the harmonics).
    pub(crate) fn on_grid(&self, m: usize) -> Vec<f64> {
        let mut planner = RealFftPlanner::<f64>::new();
        let ifft = planner.plan_fft_inverse(m);
        let mut spec = ifft.make_input_vec();
        for (k, c) in self.coefficients.iter().enumerate().take(spec.len()) {
            // x_i = sum_k X_k e^(+i 2 pi k i / m) with X_0 = c_0, X_k = c_k / 2 (k > 0).
            spec[k] = if k == 0 {
                Complex64::new(c.re, 0.0)
            } else {
                c * 0.5
            };
        }
        if let Some(last) = spec.last_mut() {
            // The Nyquist bin of a real transform must be real.
            last.im = 0.0;
        }
        let mut out = ifft.make_output_vec();
        ifft.process(&mut spec, &mut out)
            .expect("FFT buffers sized by the plan");
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn coefficients_of_a_known_signal_on_a_shifted_grid() {
        // x = 1 + 2 cos(w t + 0.3) - 0.5 sin(3 w t) sampled from t0 = 0.37 T.
        let period = 2e-3;
        let t0 = 0.37 * period;
        let n = 4096;
        let t: Vec<f64> = (0..n).map(|i| t0 + period * i as f64 / n as f64).collect();
        let w = 2.0 * PI / period;
        let x: Vec<f64> = t
            .iter()
            .map(|t| 1.0 + 2.0 * (w * t + 0.3).cos() - 0.5 * (3.0 * w * t).sin())
            .collect();
        let p = PeriodicSignal::from_samples(&t, &x, period);
        // The series is that of the samples' linear interpolant: harmonic k of a smooth
        // signal is scaled by sinc^2(pi k / N) (the interpolation's triangle filter), N =
        // 4096 samples: 1 - 1.8e-6 at k = 3.
        assert!((p.coefficients[0].re - 1.0).abs() < 1e-12);
        assert!((p.coefficients[1] - Complex64::from_polar(2.0, 0.3)).norm() < 1e-5);
        assert!((p.coefficients[3] - Complex64::new(0.0, 0.5)).norm() < 1e-5);
        assert!((p.at(0.1 * period) - x_of(0.1 * period, w)).abs() < 1e-5);
        // Sampling at an incommensurate rate: the Lagrange cubic's error (module docs).
        let fs = 51_200.0 / 1.37;
        let s = p.sample(0.25e-3, fs, 500);
        for (i, v) in s.iter().enumerate() {
            let tt = 0.25e-3 + i as f64 / fs;
            assert!((v - x_of(tt, w)).abs() < 1e-5, "{i}");
        }
    }

    fn x_of(t: f64, w: f64) -> f64 {
        1.0 + 2.0 * (w * t + 0.3).cos() - 0.5 * (3.0 * w * t).sin()
    }
}
