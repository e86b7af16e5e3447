//! Signal statistics and amplitude spectra.
//!
//! The evaluated window spans P whole mesh periods of a periodic response, so mesh
//! harmonic h is line h P of the window's Fourier series and a periodic signal has nothing
//! on the lines between. Each line is the exact Fourier coefficient of the solution over
//! the window (`super::fourier`: the cubic Hermite interpolant of the solver's steps,
//! integrated exactly, whatever the spacing of the steps), not an FFT of a resampled
//! copy: no window function, no interpolation onto a grid. Line k has the one-sided
//! amplitude |C_k| (x = mean + sum |C_k| cos(2 pi k t / window + phase)); the mean is
//! removed (line 0 is 0).

use super::fourier::HermitePeriod;

/// Root mean square.
pub fn rms(x: &[f64]) -> f64 {
    if x.is_empty() {
        return 0.0;
    }
    (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt()
}

/// Mean.
pub fn mean(x: &[f64]) -> f64 {
    if x.is_empty() {
        return 0.0;
    }
    x.iter().sum::<f64>() / x.len() as f64
}

/// Time average of x(t) on a non-uniform grid over [t_0, t_0 + window), trapezoidal,
/// with the window closing periodically on the first sample.
pub fn time_mean(t: &[f64], x: &[f64], window_s: f64) -> f64 {
    let n = t.len();
    if n == 0 {
        return 0.0;
    }
    let mut acc = 0.0;
    for i in 0..n {
        let (t1, x1) = if i + 1 < n {
            (t[i + 1], x[i + 1])
        } else {
            (t[0] + window_s, x[0])
        };
        acc += 0.5 * (x[i] + x1) * (t1 - t[i]);
    }
    acc / window_s
}

/// Time average of x(t) over [t_0, t_0 + window) as [`time_mean`], with each interval's
/// trapezoid corrected by its end slopes dx/dt (the Hermite-corrected trapezoid,
/// h (x_i + x_i+1) / 2 - h^2 (dx_i+1 - dx_i) / 12, fourth order where x is smooth;
/// Davis & Rabinowitz, *Methods of Numerical Integration*, 2nd ed. 1984, 2.9).
pub fn time_mean_with_slopes(t: &[f64], x: &[f64], dx: &[f64], window_s: f64) -> f64 {
    let n = t.len();
    if n == 0 {
        return 0.0;
    }
    let mut acc = 0.0;
    for i in 0..n {
        let (t1, x1, d1) = if i + 1 < n {
            (t[i + 1], x[i + 1], dx[i + 1])
        } else {
            (t[0] + window_s, x[0], dx[0])
        };
        let h = t1 - t[i];
        acc += 0.5 * (x[i] + x1) * h - h * h * (d1 - dx[i]) / 12.0;
    }
    acc / window_s
}

/// RMS of x(t) about zero on a non-uniform periodic grid (trapezoidal on x^2).
pub fn time_rms(t: &[f64], x: &[f64], window_s: f64) -> f64 {
    let sq: Vec<f64> = x.iter().map(|v| v * v).collect();
    time_mean(t, &sq, window_s).max(0.0).sqrt()
}

/// One-sided amplitude spectrum.
#[derive(Debug, Clone, Default)]
pub struct Spectrum {
    /// Frequency of each bin, Hz.
    pub frequency_hz: Vec<f64>,
    /// One-sided amplitude of each bin, in the signal's unit.
    pub amplitude: Vec<f64>,
    /// Bins per mesh harmonic (periods in the window).
    pub bins_per_harmonic: usize,
}

impl Spectrum {
    /// Amplitude of mesh harmonic h (1-based).
    pub fn harmonic(&self, h: usize) -> f64 {
        self.amplitude
            .get(h * self.bins_per_harmonic)
            .copied()
            .unwrap_or(0.0)
    }
}

/// Amplitude spectrum of `signal` (its period the window, `periods` whole mesh periods):
/// lines 0..=L of 1 / window (L = periods x half the points per period rounded up to a
/// power of two, at least 8 per period: the band the former resampled spectrum showed).
pub fn amplitude_spectrum(signal: &HermitePeriod, periods: usize) -> Spectrum {
    if signal.t.len() < 4 || periods == 0 || signal.period_s <= 0.0 {
        return Spectrum::default();
    }
    let per_period = signal.t.len().div_ceil(periods).next_power_of_two().max(16);
    let lines = per_period / 2 * periods;
    let c = signal.coefficients(signal.t[0], lines);
    let df = 1.0 / signal.period_s;
    Spectrum {
        frequency_hz: (0..=lines).map(|k| k as f64 * df).collect(),
        amplitude: c
            .iter()
            .enumerate()
            .map(|(k, c)| if k == 0 { 0.0 } else { c.norm() })
            .collect(),
        bins_per_harmonic: periods,
    }
}

/// Complex amplitudes C_1..=C_count of mesh harmonics 1..=count of `signal` (window of
/// `periods` mesh periods), phases referred to the window's start.
pub fn mesh_harmonics(
    signal: &HermitePeriod,
    periods: usize,
    count: usize,
) -> Vec<realfft::num_complex::Complex64> {
    if signal.t.len() < 2 || periods == 0 {
        return vec![Default::default(); count];
    }
    let c = signal.coefficients(signal.t[0], count * periods);
    (1..=count).map(|h| c[h * periods]).collect()
}

#[cfg(test)]
#[path = "tests_spectrum.rs"]
mod tests;
