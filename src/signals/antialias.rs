//! The anti-alias filter of the acquisition and decimation to the sampling rate.
//!
//! The "analog" signal is represented at an internal rate D f_s (D = `OVERSAMPLING`).
//! Before it is decimated to f_s it passes a linear-phase low-pass FIR designed by the
//! Kaiser window method (Kaiser 1974; Oppenheim & Schafer, *Discrete-Time Signal
//! Processing*, 3rd ed., Sect. 7.5.3):
//!
//! - passband edge f_p = f_s / 2.56 (the usable band of vibration analysers: f_s = 2.56
//!   f_max), stopband edge f_st = f_s / 2 (the new Nyquist frequency), cut-off at their
//!   middle;
//! - stopband attenuation A dB (`signals.anti_alias_attenuation_db`): beta = 0.1102 (A - 8.7)
//!   for A > 50, 0.5842 (A - 21)^0.4 + 0.07886 (A - 21) for 21 <= A <= 50, else 0;
//!   length N = ceil((A - 8) / (2.285 dw)) + 1 taps, dw = 2 pi (f_st - f_p) / (D f_s),
//!   rounded up to an odd number so the delay (N - 1)/2 is a whole sample;
//! - so every tone at or above f_s / 2, which would alias, is attenuated by at least A dB,
//!   and the passband ripple is about 10^(-A/20).
//!
//! The filter's delay is removed (output sample n is the filtered signal at time n / f_s),
//! so the recorded channels are not shifted against the tachometer or each other.

use std::f64::consts::PI;

/// Internal oversampling of the analog representation over the sampling rate.
pub(crate) const OVERSAMPLING: usize = 8;

/// Ratio f_s / f_p of the sampling rate to the passband edge.
pub(crate) const SAMPLING_OVER_PASSBAND: f64 = 2.56;

/// A linear-phase low-pass FIR at the internal rate, with its delay removed.
#[derive(Debug, Clone, PartialEq)]
pub struct AntiAliasFilter {
    /// Taps (odd count, symmetric).
    pub taps: Vec<f64>,
    /// Internal rate D f_s, Hz.
    pub internal_rate_hz: f64,
    /// Sampling rate f_s of the decimated record, Hz.
    pub sampling_rate_hz: f64,
    /// Stopband attenuation at and above f_s / 2, dB.
    pub attenuation_db: f64,
}

/// Zeroth-order modified Bessel function of the first kind (power series; converges for
/// every argument, 1e-17 relative terms end it).
pub(crate) fn bessel_i0(x: f64) -> f64 {
    let (mut sum, mut term, y) = (1.0, 1.0, 0.25 * x * x);
    let mut k = 1.0;
    while term > 1e-17 * sum {
        term *= y / (k * k);
        sum += term;
        k += 1.0;
    }
    sum
}

/// Kaiser's beta for a stopband attenuation of `a_db`.
pub(crate) fn kaiser_beta(a_db: f64) -> f64 {
    if a_db > 50.0 {
        0.1102 * (a_db - 8.7)
    } else if a_db >= 21.0 {
        0.5842 * (a_db - 21.0).powf(0.4) + 0.07886 * (a_db - 21.0)
    } else {
        0.0
    }
}

impl AntiAliasFilter {
    /// The filter for sampling rate `fs_hz` and stopband attenuation `a_db` (module docs).
    pub fn design(fs_hz: f64, a_db: f64) -> Self {
        let d = OVERSAMPLING as f64;
        let rate = d * fs_hz;
        let (fp, fst) = (fs_hz / SAMPLING_OVER_PASSBAND, 0.5 * fs_hz);
        let dw = 2.0 * PI * (fst - fp) / rate;
        let mut n = ((a_db - 8.0) / (2.285 * dw)).ceil().max(1.0) as usize + 1;
        if n.is_multiple_of(2) {
            n += 1;
        }
        let beta = kaiser_beta(a_db);
        let fc = 0.5 * (fp + fst) / rate; // cycles per internal sample
        let mid = (n - 1) as f64 / 2.0;
        let i0b = bessel_i0(beta);
        let taps = (0..n)
            .map(|i| {
                let m = i as f64 - mid;
                let ideal = if m == 0.0 {
                    2.0 * fc
                } else {
                    (2.0 * PI * fc * m).sin() / (PI * m)
                };
                let r = m / mid.max(1.0);
                ideal * bessel_i0(beta * (1.0 - r * r).max(0.0).sqrt()) / i0b
            })
            .collect();
        Self {
            taps,
            internal_rate_hz: rate,
            sampling_rate_hz: fs_hz,
            attenuation_db: a_db,
        }
    }

    /// Zero-phase frequency response at `f_hz` (the delay removed): real, periodic in
    /// the internal rate.
    pub fn response(&self, f_hz: f64) -> f64 {
        let c = self.taps.len() / 2;
        let w = 2.0 * PI * f_hz / self.internal_rate_hz;
        self.taps[c]
            + 2.0
                * (1..=c)
                    .map(|m| self.taps[c + m] * (w * m as f64).cos())
                    .sum::<f64>()
    }

    /// The zero-phase response at the `n / 2 + 1` frequencies k r / n of an `n`-point
    /// transform at the internal rate r (exactly `response` there, by one FFT).
    pub(crate) fn response_grid(&self, n: usize) -> Vec<f64> {
        let c = self.half_length();
        let mut a = vec![0.0; n];
        for (m, h) in self.taps.iter().enumerate() {
            let k = (m as isize - c as isize).rem_euclid(n as isize) as usize;
            a[k] += h;
        }
        let mut planner = realfft::RealFftPlanner::<f64>::new();
        let fft = planner.plan_fft_forward(n);
        let mut spec = fft.make_output_vec();
        fft.process(&mut a, &mut spec)
            .expect("FFT buffers sized by the plan");
        spec.iter().map(|c| c.re).collect()
    }

    /// Half the filter length in internal samples (its delay).
    pub(crate) fn half_length(&self) -> usize {
        self.taps.len() / 2
    }

    /// Filter `x` (at the internal rate, sample 0 at time 0) and keep every D-th sample:
    /// output n is the filtered signal at internal sample n D. Samples beyond the ends of
    /// `x` count as the end values held (a signal at rest before and after).
    #[cfg(test)]
    pub(crate) fn decimate(&self, x: &[f64]) -> Vec<f64> {
        if x.is_empty() {
            return Vec::new();
        }
        let c = self.half_length() as isize;
        let last = x.len() as isize - 1;
        let n_out = x.len().div_ceil(OVERSAMPLING);
        (0..n_out)
            .map(|n| {
                let centre = (n * OVERSAMPLING) as isize;
                self.taps
                    .iter()
                    .enumerate()
                    .map(|(k, h)| h * x[(centre + c - k as isize).clamp(0, last) as usize])
                    .sum()
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bessel_i0_matches_tabulated_values() {
        // Abramowitz & Stegun, Table 9.8: I0(1) = 1.266065878, e^-5 I0(5) = 0.1835408126.
        assert!((bessel_i0(1.0) - 1.266_065_878).abs() < 1e-9);
        assert!((bessel_i0(5.0) * (-5.0f64).exp() - 0.183_540_812_6).abs() < 1e-10);
    }

    #[test]
    fn response_meets_the_design() {
        let f = AntiAliasFilter::design(25_600.0, 100.0);
        // Passband: ripple ~ 1e-5 for A = 100 dB (Kaiser's ripple equals the stopband
        // deviation); 1e-4 leaves room for the approximate length formula.
        for k in 0..=100 {
            let fr = 10_000.0 * k as f64 / 100.0;
            assert!(
                (f.response(fr) - 1.0).abs() < 1e-4,
                "{fr}: {}",
                f.response(fr)
            );
        }
        // Stopband from f_s / 2 to the internal Nyquist frequency: <= -100 dB (Kaiser's
        // formula is approximate to ~1 dB; 0.5 dB of slack).
        let limit = 10f64.powf(-99.5 / 20.0);
        for k in 0..=2000 {
            let fr = 12_800.0 + (f.internal_rate_hz / 2.0 - 12_800.0) * k as f64 / 2000.0;
            assert!(f.response(fr).abs() < limit, "{fr}: {:e}", f.response(fr));
        }
    }

    #[test]
    fn response_grid_is_the_response_at_the_grid_frequencies() {
        let f = AntiAliasFilter::design(25_600.0, 80.0);
        let n = 3000;
        let g = f.response_grid(n);
        for k in [0, 17, 300, 1499] {
            let fr = k as f64 * f.internal_rate_hz / n as f64;
            assert!((g[k] - f.response(fr)).abs() < 1e-12, "{k}");
        }
    }

    #[test]
    fn decimation_of_a_tone_keeps_phase_and_amplitude() {
        let fs = 10_000.0;
        let f = AntiAliasFilter::design(fs, 90.0);
        let rate = f.internal_rate_hz;
        let tone = 1_234.5;
        let x: Vec<f64> = (0..80_000)
            .map(|i| (2.0 * PI * tone * i as f64 / rate).sin())
            .collect();
        let y = f.decimate(&x);
        // Away from the ends (held values there), y(n) = sin(2 pi f n / fs) to the
        // passband ripple (~3e-5 at 90 dB).
        let edge = f.half_length() / OVERSAMPLING + 1;
        for (n, v) in y.iter().enumerate().take(y.len() - edge).skip(edge) {
            let want = (2.0 * PI * tone * n as f64 / fs).sin();
            assert!((v - want).abs() < 2e-4, "{n}: {v} vs {want}");
        }
    }
}
