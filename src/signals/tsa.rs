//! Time-synchronous averaging by tachometer angle (McFadden 1987, "A revised model for the
//! extraction of periodic waveforms by time domain averaging", MSSP 1(1); computed order
//! tracking after Fyfe & Munck 1997, "Analysis of computed order tracking", MSSP 11(2)).
//!
//! 1. The tachometer's shaft has turned 2 pi k / N at its k-th pulse time t_k (counted
//!    from the first pulse in the record).
//! 2. The time at any angle theta comes from the quadratic through three neighbouring
//!    pulses (Fyfe & Munck's quadratic fit: exact at constant speed and at constant
//!    acceleration).
//! 3. The analysed shaft turns `ratio` times as fast (z_tach / z_analysed for the other
//!    shaft of the pair); one of its revolutions is M samples at equal angles, M the power
//!    of two at or above the samples per revolution (nothing of the recorded band lost),
//!    each read from the record by band-limited interpolation (`super::interp`).
//! 4. The TSA is the mean over the complete revolutions inside the record. What is
//!    periodic per revolution stays; what is not (noise, the other shaft's components)
//!    falls as 1 / sqrt(revolutions) for uncorrelated noise.

use super::interp;

/// A time-synchronous average: one revolution of the analysed shaft.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Tsa {
    /// M samples at equal angles 2 pi m / M from the first pulse.
    pub values: Vec<f64>,
    /// Revolutions averaged.
    pub revolutions: usize,
    /// Mean revolution period of the analysed shaft, s.
    pub revolution_s: f64,
}

/// Time at tachometer-shaft angle `theta` (rad from the first pulse), from the pulse times
/// `edges` with `n` pulses per revolution (module docs, step 2).
pub(crate) fn time_at_angle(edges: &[f64], n: usize, theta: f64) -> f64 {
    let step = 2.0 * std::f64::consts::PI / n as f64;
    let u = theta / step;
    let last = edges.len() - 1;
    if last == 0 {
        return edges[0];
    }
    let k = (u.floor().max(0.0) as usize).min(last - 1);
    if last == 1 {
        return edges[0] + (edges[1] - edges[0]) * u;
    }
    let j = if k == 0 { 1 } else { k.min(last - 1) };
    // Lagrange quadratic through pulses j-1, j, j+1 in the variable u.
    let (u0, u1, u2) = ((j - 1) as f64, j as f64, (j + 1) as f64);
    let (t0, t1, t2) = (edges[j - 1], edges[j], edges[j + 1]);
    t0 * (u - u1) * (u - u2) / ((u0 - u1) * (u0 - u2))
        + t1 * (u - u0) * (u - u2) / ((u1 - u0) * (u1 - u2))
        + t2 * (u - u0) * (u - u1) / ((u2 - u0) * (u2 - u1))
}

/// The TSA of `x` (sampled at `fs_hz`) for the shaft that turns `ratio` times per
/// revolution of the tachometer's shaft, whose pulses (`n` per revolution) came at
/// `edges`. `None` when the record holds no complete revolution inside its usable part.
/// (The analysis averages its channels together, [`synchronous_averages`].)
#[cfg(test)]
pub fn synchronous_average(
    x: &[f64],
    fs_hz: f64,
    edges: &[f64],
    n: usize,
    ratio: f64,
) -> Option<Tsa> {
    synchronous_averages(&[x], fs_hz, edges, n, ratio).map(|mut t| t.remove(0))
}

/// [`synchronous_average`] of every channel of `xs` (equal lengths, sampled alike): the
/// angle grid's times and interpolation weights computed once for all of them (the TSA's
/// main cost), each channel's average the same, bit for bit, as alone.
pub fn synchronous_averages(
    xs: &[&[f64]],
    fs_hz: f64,
    edges: &[f64],
    n: usize,
    ratio: f64,
) -> Option<Vec<Tsa>> {
    let len = xs.first()?.len();
    if edges.len() < 2 || ratio <= 0.0 || xs.iter().any(|x| x.len() != len) {
        return None;
    }
    let two_pi = 2.0 * std::f64::consts::PI;
    let tach_span = two_pi * (edges.len() - 1) as f64 / n as f64;
    let span_s = edges[edges.len() - 1] - edges[0];
    let revolution_s = span_s / (tach_span / two_pi) / ratio;
    let m = ((fs_hz * revolution_s).ceil() as usize)
        .next_power_of_two()
        .max(16);
    let mut sums = vec![vec![0.0; m]; xs.len()];
    let mut revolutions = 0;
    let mut r = 0;
    loop {
        let end_theta = two_pi * (r + 1) as f64 / ratio;
        if end_theta > tach_span + 1e-12 {
            break;
        }
        let times: Vec<f64> = (0..m)
            .map(|i| {
                let psi = two_pi * (r as f64 + i as f64 / m as f64);
                time_at_angle(edges, n, psi / ratio)
            })
            .collect();
        let end = time_at_angle(edges, n, end_theta);
        r += 1;
        if !interp::inside(len, fs_hz, times[0]) || !interp::inside(len, fs_hz, end) {
            continue;
        }
        for (i, t) in times.iter().enumerate() {
            let w = interp::Weights::at(len, fs_hz, *t);
            for (sum, x) in sums.iter_mut().zip(xs) {
                sum[i] += w.apply(x);
            }
        }
        revolutions += 1;
    }
    (revolutions > 0).then(|| {
        sums.into_iter()
            .map(|sum| Tsa {
                values: sum.iter().map(|s| s / revolutions as f64).collect(),
                revolutions,
                revolution_s,
            })
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signals::noise::band_limited;
    use std::f64::consts::PI;

    /// A signal periodic per revolution (orders 1, 19 and 21 of a shaft at `f` Hz).
    fn per_rev(f: f64, t: f64) -> f64 {
        let a = 2.0 * PI * f * t;
        0.3 * a.sin() + (19.0 * a).cos() + 0.2 * (21.0 * a + 1.0).sin()
    }

    #[test]
    fn tsa_of_a_signal_periodic_per_revolution_is_one_revolution_of_it() {
        let (fs, f) = (25_600.0, 30.0);
        let x: Vec<f64> = (0..25_600).map(|i| per_rev(f, i as f64 / fs)).collect();
        // One pulse per revolution from t = 0.01 s; exact times.
        let t0 = 0.01;
        let edges: Vec<f64> = (0..29).map(|k| t0 + k as f64 / f).collect();
        let tsa = synchronous_average(&x, fs, &edges, 1, 1.0).unwrap();
        assert_eq!(tsa.values.len(), 1024);
        assert!(tsa.revolutions >= 26);
        let mut worst = 0.0_f64;
        for (m, v) in tsa.values.iter().enumerate() {
            let want = per_rev(f, t0 + m as f64 / 1024.0 / f);
            // Band-limited interpolation error (~1e-5 of each component, interp.rs).
            assert!((v - want).abs() < 3e-5, "{m}: {v} vs {want}");
            worst = worst.max((v - want).abs());
        }
        println!(
            "TSA of a per-revolution signal over {} revolutions: largest error {worst:.2e} (amplitudes 0.2-1)",
            tsa.revolutions
        );
    }

    #[test]
    fn mesh_harmonics_in_the_passband_pass_within_1e_4_and_the_rest_is_left_out() {
        // The default record's pinion: 30 Hz, 19 teeth, f_s = 25.6 kHz; mesh harmonics
        // h = 1..22 (570 Hz to 12.54 kHz) of amplitude 1 / h. The TSA's passband ends at
        // 0.4 f_s (10.24 kHz, order 341): harmonics 1-17 lie in it and must come out within
        // 1e-4 (the interpolation's 1e-5 ripple, with the averaging's round-off); 18-22
        // lie above it, where the resampling rolls off (harmonic 22 at 0.49 f_s ~37 % low),
        // and the components leave them out of every derived signal and indicator.
        use crate::signals::components::{components, ComponentSettings};
        let (fs, f, z) = (25_600.0, 30.0, 19usize);
        let x: Vec<f64> = (0..25_600)
            .map(|i| {
                let t = i as f64 / fs;
                (1..=22)
                    .map(|h| (2.0 * PI * (h * z) as f64 * f * t + 0.1 * h as f64).cos() / h as f64)
                    .sum()
            })
            .collect();
        let edges: Vec<f64> = (0..30).map(|k| k as f64 / f).collect();
        let tsa = synchronous_average(&x, fs, &edges, 1, 1.0).unwrap();
        let top =
            (crate::signals::interp::PASSBAND_OVER_FS * fs * tsa.revolution_s).floor() as usize;
        assert_eq!(top, 341);
        let settings = ComponentSettings {
            top_order: Some(top),
            ..ComponentSettings::default()
        };
        let c = components(&tsa.values, z, settings);
        let whole = components(&tsa.values, z, ComponentSettings::default());
        for h in 1..=22 {
            let k = h * z;
            let want = 1.0 / h as f64;
            if k <= top {
                let got = c.order_amplitude(k);
                assert!((got / want - 1.0).abs() < 1e-4, "h = {h}: {got} vs {want}");
            } else {
                assert_eq!(c.order_amplitude(k), 0.0, "h = {h} above the passband");
            }
        }
        // Without the passband the top harmonic is what the resampling makes of it.
        let h22 = whole.order_amplitude(22 * z) * 22.0;
        println!("harmonic 22 (0.49 f_s) through the resampling: {h22:.3} of its amplitude; harmonic 17 in band: {:.6}", c.order_amplitude(17 * z) * 17.0);
        assert!(h22 < 0.9, "{h22}");
        // The in-band TSA holds nothing above the passband.
        let rms_in = (c.in_band.iter().map(|v| v * v).sum::<f64>() / c.in_band.len() as f64).sqrt();
        let want_rms = ((1..=17).map(|h| 0.5 / (h * h) as f64).sum::<f64>()).sqrt();
        assert!(
            (rms_in / want_rms - 1.0).abs() < 1e-4,
            "{rms_in} vs {want_rms}"
        );
    }

    #[test]
    fn tsa_of_the_other_shaft_uses_the_ratio() {
        // Tachometer on a shaft at 30 Hz (3 pulses/rev); analysed shaft at 30 x 19/31 Hz.
        let (fs, f_tach) = (20_000.0, 30.0);
        let ratio = 19.0 / 31.0;
        let f = f_tach * ratio;
        let x: Vec<f64> = (0..60_000).map(|i| per_rev(f, i as f64 / fs)).collect();
        let edges: Vec<f64> = (0..260)
            .map(|k| 0.002 + k as f64 / (3.0 * f_tach))
            .collect();
        let tsa = synchronous_average(&x, fs, &edges, 3, ratio).unwrap();
        let m = tsa.values.len();
        for (i, v) in tsa.values.iter().enumerate() {
            let want = per_rev(f, 0.002 + i as f64 / m as f64 / f);
            assert!((v - want).abs() < 3e-5, "{i}");
        }
    }

    #[test]
    fn non_synchronous_noise_falls_as_one_over_root_averages() {
        let (fs, f) = (10_000.0, 25.0);
        let n = 10_000 * 33;
        // Band-limited noise (below 0.39 fs, as a recorded channel), RMS 1.
        let noise = band_limited(11, 0, n, fs, fs / 2.56, 1.0);
        let edges: Vec<f64> = (0..820).map(|k| 0.01 + k as f64 / f).collect();
        let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
        let mut ratios = Vec::new();
        for revs in [4usize, 16, 64, 256] {
            let tsa = synchronous_average(&noise, fs, &edges[..revs + 1], 1, 1.0).unwrap();
            assert_eq!(tsa.revolutions, revs);
            ratios.push(rms(&tsa.values) * (revs as f64).sqrt());
        }
        // RMS(TSA) sqrt(N) stays at the noise RMS (1); each estimate is a mean over 512
        // correlated samples of a chi-square variable: ~5 % scatter, 15 % allowed.
        println!("RMS(TSA) sqrt(N) / RMS(noise) for N = 4, 16, 64, 256: {ratios:.3?}");
        for r in &ratios {
            assert!((r - 1.0).abs() < 0.15, "{ratios:?}");
        }
    }
}
