//! Amplitude spectrum of a record (not periodic in its length): Hann window, scaled so a
//! tone on a bin shows its amplitude (2 |X_k| / sum w), the mean removed first.

use realfft::RealFftPlanner;

/// (frequency, amplitude) of `x` sampled at `fs_hz`, bins 0..=n/2.
pub fn hann_amplitude_spectrum(x: &[f64], fs_hz: f64) -> (Vec<f64>, Vec<f64>) {
    let n = x.len();
    if n < 4 {
        return (Vec::new(), Vec::new());
    }
    let mean = x.iter().sum::<f64>() / n as f64;
    let w: Vec<f64> = (0..n)
        .map(|i| 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / n as f64).cos())
        .collect();
    let sum_w: f64 = w.iter().sum();
    let mut u: Vec<f64> = x.iter().zip(&w).map(|(v, w)| (v - mean) * w).collect();
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(n);
    let mut spec = fft.make_output_vec();
    fft.process(&mut u, &mut spec)
        .expect("FFT buffers sized by the plan");
    let df = fs_hz / n as f64;
    let f = (0..spec.len()).map(|k| k as f64 * df).collect();
    let a = spec.iter().map(|c| 2.0 * c.norm() / sum_w).collect();
    (f, a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tone_on_a_bin_shows_its_amplitude() {
        let (fs, n) = (1000.0, 1000);
        let x: Vec<f64> = (0..n)
            .map(|i| 3.0 + 0.7 * (2.0 * std::f64::consts::PI * 50.0 * i as f64 / fs).sin())
            .collect();
        let (f, a) = hann_amplitude_spectrum(&x, fs);
        assert_eq!(f[50], 50.0);
        assert!((a[50] - 0.7).abs() < 1e-12, "{}", a[50]);
        // Hann spreads the tone over bins 49..=51 only (at half height beside it).
        assert!((a[49] - 0.35).abs() < 1e-12 && a[47] < 1e-12);
    }
}
