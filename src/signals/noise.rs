//! Seeded random signals: measurement noise and the band-limited load-torque fluctuation.
//!
//! Every draw comes from a ChaCha8 stream selected by (seed, stream index)
//! (`rng::stream`), so a record's noise depends only on its seed and channel,
//! never on the thread or shard that computed it.
//!
//! - Measurement noise is white and Gaussian, added to the recorded samples, given either
//!   as a signal-to-noise ratio, sigma = RMS(x - mean x) / 10^(SNR/20) (the SNR in dB of
//!   the powers), or as an amplitude spectral density d, one-sided and flat from 0 to the
//!   Nyquist frequency, sigma = d sqrt(f_s / 2).
//! - The torque fluctuation is Gaussian noise with a flat spectrum from 0 to the
//!   bandwidth B and nothing above (white noise transformed, cut above B, transformed
//!   back), scaled so that the realisation's RMS is the one asked for.

use crate::rng::stream;
use rand_distr::{Distribution, StandardNormal};
use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;

/// `n` independent standard normal draws of stream `index` under `seed`.
pub(crate) fn standard_normal(seed: u64, index: u64, n: usize) -> Vec<f64> {
    let mut r = stream(seed, index);
    (0..n).map(|_| StandardNormal.sample(&mut r)).collect()
}

/// Noise standard deviation for a signal-to-noise ratio `snr_db` on `x`.
pub(crate) fn sigma_for_snr(x: &[f64], snr_db: f64) -> f64 {
    let m = x.iter().sum::<f64>() / x.len().max(1) as f64;
    let p = x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / x.len().max(1) as f64;
    p.sqrt() / 10f64.powf(snr_db / 20.0)
}

/// Noise standard deviation for a one-sided amplitude density `d` (unit/sqrt(Hz)) over
/// the band 0..f_s/2.
pub(crate) fn sigma_for_density(density: f64, fs_hz: f64) -> f64 {
    density * (0.5 * fs_hz).sqrt()
}

/// Band-limited Gaussian noise: `n` samples at `fs_hz`, flat from 0 to `bandwidth_hz`
/// (the mean removed), with RMS exactly `rms` (module docs).
pub(crate) fn band_limited(
    seed: u64,
    index: u64,
    n: usize,
    fs_hz: f64,
    bandwidth_hz: f64,
    rms: f64,
) -> Vec<f64> {
    if n == 0 || rms == 0.0 {
        return vec![0.0; n];
    }
    let mut x = standard_normal(seed, index, n);
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(n);
    let ifft = planner.plan_fft_inverse(n);
    let mut spec = fft.make_output_vec();
    fft.process(&mut x, &mut spec)
        .expect("FFT buffers sized by the plan");
    let df = fs_hz / n as f64;
    for (k, c) in spec.iter_mut().enumerate() {
        if k == 0 || k as f64 * df > bandwidth_hz {
            *c = Complex64::new(0.0, 0.0);
        }
    }
    if let Some(last) = spec.last_mut() {
        last.im = 0.0;
    }
    if n.is_multiple_of(2) {
        spec[0].im = 0.0;
    }
    let mut out = ifft.make_output_vec();
    ifft.process(&mut spec, &mut out)
        .expect("FFT buffers sized by the plan");
    let have = (out.iter().map(|v| v * v).sum::<f64>() / n as f64).sqrt();
    let scale = if have > 0.0 { rms / have } else { 0.0 };
    out.iter_mut().for_each(|v| *v *= scale);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_draws_other_stream_other_draws() {
        assert_eq!(standard_normal(5, 1, 100), standard_normal(5, 1, 100));
        assert_ne!(standard_normal(5, 1, 100), standard_normal(5, 2, 100));
    }

    #[test]
    fn band_limited_noise_has_its_rms_and_no_power_above_its_band() {
        let (fs, n, b) = (1000.0, 20_000, 50.0);
        let x = band_limited(3, 0, n, fs, b, 2.5);
        let rms = (x.iter().map(|v| v * v).sum::<f64>() / n as f64).sqrt();
        assert!((rms - 2.5).abs() < 1e-12);
        // Power above B: zero up to round-off.
        let mut planner = RealFftPlanner::<f64>::new();
        let fft = planner.plan_fft_forward(n);
        let mut spec = fft.make_output_vec();
        fft.process(&mut x.clone(), &mut spec).unwrap();
        let (mut inside, mut outside) = (0.0, 0.0);
        for (k, c) in spec.iter().enumerate() {
            if k as f64 * fs / n as f64 > b {
                outside += c.norm_sqr();
            } else {
                inside += c.norm_sqr();
            }
        }
        assert!(outside < 1e-24 * inside, "{outside:e} vs {inside:e}");
    }
}
