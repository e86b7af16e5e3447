//! Signal statistics and amplitude spectra.
//!
//! The evaluated window spans whole mesh periods of a mesh-periodic response, so mesh
//! harmonic h falls exactly on FFT bin h P (P periods in the window). The signal is
//! resampled onto a uniform grid (the integrator's grid is uniform within each segment
//! between mesh events, not across them), Hann-windowed and scaled by 2 / sum(w), which
//! makes the peak at an exact bin equal the harmonic's amplitude.

use realfft::RealFftPlanner;

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

/// RMS of x(t) about zero on a non-uniform periodic grid (trapezoidal on x^2).
pub fn time_rms(t: &[f64], x: &[f64], window_s: f64) -> f64 {
    let sq: Vec<f64> = x.iter().map(|v| v * v).collect();
    time_mean(t, &sq, window_s).max(0.0).sqrt()
}

/// One-sided amplitude spectrum.
#[derive(Debug, Clone, Default)]
pub struct Spectrum {
    pub frequency_hz: Vec<f64>,
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

/// Linear resampling of (t, x) onto `n` uniform points over [t0, t0 + window) with
/// periodic closure.
pub fn resample_periodic(t: &[f64], x: &[f64], window_s: f64, n: usize) -> Vec<f64> {
    let t0 = t[0];
    let mut out = Vec::with_capacity(n);
    let mut j = 0;
    for i in 0..n {
        let ti = t0 + window_s * i as f64 / n as f64;
        while j + 1 < t.len() && t[j + 1] <= ti {
            j += 1;
        }
        let (ta, xa) = (t[j], x[j]);
        let (tb, xb) = if j + 1 < t.len() {
            (t[j + 1], x[j + 1])
        } else {
            (t0 + window_s, x[0])
        };
        let w = if tb > ta { (ti - ta) / (tb - ta) } else { 0.0 };
        out.push(xa + (xb - xa) * w);
    }
    out
}

/// Hann-windowed amplitude spectrum of a signal sampled on `t` over `periods` whole
/// mesh periods of length `mesh_period_s`. The mean is removed first.
pub fn amplitude_spectrum(t: &[f64], x: &[f64], mesh_period_s: f64, periods: usize) -> Spectrum {
    if t.len() < 4 || periods == 0 {
        return Spectrum::default();
    }
    let window = mesh_period_s * periods as f64;
    let n = (t.len().next_power_of_two()).max(64);
    let mut u = resample_periodic(t, x, window, n);
    let m = mean(&u);
    let mut wsum = 0.0;
    for (i, v) in u.iter_mut().enumerate() {
        // Periodic Hann window (exact at integer bins for a whole-period record).
        let w = 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / n as f64).cos();
        *v = (*v - m) * w;
        wsum += w;
    }
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(n);
    let mut spec = fft.make_output_vec();
    if fft.process(&mut u, &mut spec).is_err() {
        return Spectrum::default();
    }
    let df = 1.0 / window;
    Spectrum {
        frequency_hz: (0..spec.len()).map(|k| k as f64 * df).collect(),
        amplitude: spec.iter().map(|c| 2.0 * c.norm() / wsum).collect(),
        bins_per_harmonic: periods,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn harmonic_amplitudes_of_a_known_signal() {
        // x = 3 + 2 sin(2 pi f t) + 0.5 cos(2 pi 3 f t) on a non-uniform grid over 8 periods.
        let f = 570.0;
        let periods = 8;
        let window = periods as f64 / f;
        let n = 8 * 256;
        let t: Vec<f64> = (0..n)
            .map(|i| {
                let u = i as f64 / n as f64;
                window * (u + 0.2 * (2.0 * PI * u).sin() / (2.0 * PI * 40.0))
            })
            .collect();
        let x: Vec<f64> = t
            .iter()
            .map(|t| 3.0 + 2.0 * (2.0 * PI * f * t).sin() + 0.5 * (6.0 * PI * f * t).cos())
            .collect();
        let s = amplitude_spectrum(&t, &x, 1.0 / f, periods);
        // Linear resampling of a smooth signal at ~256 points per period: the amplitude
        // error is O((2 pi h / 256)^2 / 12) ~ 5e-5 relative for h <= 3.
        assert!((s.harmonic(1) - 2.0).abs() < 2e-3, "{}", s.harmonic(1));
        assert!(s.harmonic(2).abs() < 2e-3);
        assert!((s.harmonic(3) - 0.5).abs() < 2e-3, "{}", s.harmonic(3));
        assert!((s.frequency_hz[s.bins_per_harmonic] - f).abs() < 1e-9);
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
}
