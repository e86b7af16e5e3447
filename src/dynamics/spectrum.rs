//! Signal statistics and amplitude spectra.
//!
//! The evaluated window spans P whole mesh periods of a mesh-periodic response, so mesh
//! harmonic h falls exactly on DFT bin h P and a periodic signal has nothing in the bins
//! between. That holds only if the samples themselves repeat from period to period:
//! the signal is resampled (linearly) onto a uniform grid of a whole number m of points
//! per mesh period (the integrator's step is adaptive, with mesh events and contact
//! changes as nodes, so its grid is neither uniform nor necessarily the same in every
//! period), so sample i + m is the same phase as sample i. No window
//! is applied: over a whole number of periods the rectangular window is exact (a window
//! such as Hann would spread each harmonic into the bins h P +- 1, i.e. side lines at
//! +- f_mesh / P at half the harmonic's height, which look like modulation sidebands).
//! The one-sided amplitude is 2 |X_k| / n (n = m P points; |X_k| / n at 0 and Nyquist),
//! so bin h P holds the amplitude of harmonic h.

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

/// Amplitude spectrum of a signal sampled on `t` over `periods` whole mesh periods of
/// length `mesh_period_s` (rectangular window, see the module notes). The mean is removed
/// first. Points per period: the next power of two at or above the samples per period
/// (at least 16), so the resampling keeps every sample's detail.
pub fn amplitude_spectrum(t: &[f64], x: &[f64], mesh_period_s: f64, periods: usize) -> Spectrum {
    if t.len() < 4 || periods == 0 {
        return Spectrum::default();
    }
    let window = mesh_period_s * periods as f64;
    let per_period = t.len().div_ceil(periods).next_power_of_two().max(16);
    let n = per_period * periods;
    let mut u = resample_periodic(t, x, window, n);
    let m = mean(&u);
    for v in &mut u {
        *v -= m;
    }
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(n);
    let mut spec = fft.make_output_vec();
    if fft.process(&mut u, &mut spec).is_err() {
        return Spectrum::default();
    }
    let df = 1.0 / window;
    let nyquist = n.is_multiple_of(2).then_some(n / 2);
    Spectrum {
        frequency_hz: (0..spec.len()).map(|k| k as f64 * df).collect(),
        amplitude: spec
            .iter()
            .enumerate()
            .map(|(k, c)| {
                let one_sided = if k == 0 || Some(k) == nyquist {
                    1.0
                } else {
                    2.0
                };
                one_sided * c.norm() / n as f64
            })
            .collect(),
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
        // Linear interpolation of a smooth signal at ~256 points per period: the amplitude
        // error is O((2 pi h / 256)^2 / 12) ~ 5e-5 relative for h <= 3.
        assert!((s.harmonic(1) - 2.0).abs() < 2e-3, "{}", s.harmonic(1));
        assert!(s.harmonic(2).abs() < 2e-3);
        assert!((s.harmonic(3) - 0.5).abs() < 2e-3, "{}", s.harmonic(3));
        assert!((s.frequency_hz[s.bins_per_harmonic] - f).abs() < 1e-9);
    }

    /// Share of the spectrum's energy in bins that are not mesh harmonics.
    fn off_harmonic_share(s: &Spectrum) -> f64 {
        let b = s.bins_per_harmonic;
        let e = |keep: &dyn Fn(usize) -> bool| -> f64 {
            s.amplitude
                .iter()
                .enumerate()
                .filter(|(k, _)| keep(*k))
                .map(|(_, a)| a * a)
                .sum()
        };
        e(&|k| k % b != 0) / e(&|_| true)
    }

    /// An exactly periodic signal with a jump (a mesh force at a pair's exit), sampled as
    /// the integrator samples: the event-aligned grid of `grid::period_nodes`, repeated
    /// over `periods` mesh periods, nodes 0..n-1 of each period.
    fn integrator_like_signal(periods: usize) -> (Vec<f64>, Vec<f64>, f64, f64) {
        use crate::config::case::GearSection;
        use crate::dynamics::grid::period_nodes;
        use crate::geometry::GearPair;
        let pair = GearPair::from_case(&GearSection::default()).unwrap();
        let omega = 2.0 * PI * 30.0;
        let nodes = period_nodes(&pair, omega, 200);
        let period = nodes[nodes.len() - 1];
        let exit = (pair.contact_ratio - 1.0) * period;
        let x_of = |tau: f64| {
            let ph = 2.0 * PI * tau / period;
            let step = if tau >= exit { -400.0 } else { 0.0 };
            3300.0 + 250.0 * ph.sin() + 80.0 * (2.0 * ph + 0.3).cos() + step
        };
        let (mut t, mut x) = (Vec::new(), Vec::new());
        for p in 0..periods {
            for &tau in &nodes[..nodes.len() - 1] {
                t.push(p as f64 * period + tau);
                x.push(x_of(tau));
            }
        }
        (t, x, period, omega)
    }

    #[test]
    fn exactly_periodic_signal_has_energy_only_on_its_harmonics() {
        // The samples repeat exactly from period to period, so after resampling onto a
        // whole number of points per period every bin between harmonics is zero up to
        // round-off (~1e-16 of the signal, 1e-32 in energy); 1e-9 is the bound.
        for periods in [1, 3, 4] {
            let (t, x, period, _) = integrator_like_signal(periods);
            let s = amplitude_spectrum(&t, &x, period, periods);
            let share = off_harmonic_share(&s);
            assert!(share < 1e-9, "P = {periods}: off-harmonic share {share:e}");
        }
        // The same test on a Hann-windowed spectrum fails: side lines at bins h P +- 1 of
        // a quarter of each harmonic's energy carry 1/3 of the total.
        let (t, x, period, _) = integrator_like_signal(4);
        let n = 1024;
        let mut u = resample_periodic(&t, &x, 4.0 * period, n);
        let m = mean(&u);
        for (i, v) in u.iter_mut().enumerate() {
            *v = (*v - m) * (0.5 - 0.5 * (2.0 * PI * i as f64 / n as f64).cos());
        }
        let mut planner = RealFftPlanner::<f64>::new();
        let fft = planner.plan_fft_forward(n);
        let mut spec = fft.make_output_vec();
        fft.process(&mut u, &mut spec).unwrap();
        let hann = Spectrum {
            frequency_hz: vec![0.0; spec.len()],
            amplitude: spec.iter().map(|c| c.norm()).collect(),
            bins_per_harmonic: 4,
        };
        let share = off_harmonic_share(&hann);
        assert!((share - 1.0 / 3.0).abs() < 0.01, "Hann: {share}");
    }

    #[test]
    fn rectangular_amplitudes_are_the_fourier_amplitudes() {
        // Scaling 2 |X_k| / n: bin h P must hold the amplitude of harmonic h of what was
        // sampled, i.e. of the samples' periodic linear interpolant. Second method: its
        // Fourier coefficients by the midpoint rule on 1e5 points per period (error
        // ~1e-5 at the interpolant's kinks), independent of the resampling and the FFT.
        let (t, x, period, _) = integrator_like_signal(4);
        let s = amplitude_spectrum(&t, &x, period, 4);
        let per_period = (s.amplitude.len() - 1) * 2 / 4;
        let n = 100_000;
        for h in 1..=4 {
            let (mut a, mut b) = (0.0, 0.0);
            for i in 0..n {
                let tt = t[0] + period * (i as f64 + 0.5) / n as f64;
                let v = interp(&t, &x, 4.0 * period, tt);
                let w = 2.0 * PI * h as f64 * (tt - t[0]) / period;
                a += v * w.cos();
                b += v * w.sin();
            }
            let amp = 2.0 * (a * a + b * b).sqrt() / n as f64;
            // The resampled signal aliases the interpolant's harmonics above m / 2
            // (m = points per period) onto the ones below. Only the 400 N jump has
            // content there, 2 J / (pi h') at harmonic h'; the nearest folds m -+ h
            // bring at most 4 J / (pi m) = 2 N for m = 256 (the farther ones fall off as
            // 1/h'^2: the interpolant smears the jump over one node spacing).
            let bound = 4.0 * 400.0 / (PI * per_period as f64);
            assert!(
                (s.harmonic(h) - amp).abs() < bound,
                "h = {h}: {} vs {amp} (bound {bound})",
                s.harmonic(h)
            );
        }
        // A pure sine of amplitude 2 on the same grid: exact up to the linear
        // interpolation between nodes (relative (2 pi / 200)^2 / 12 < 1e-4).
        let x: Vec<f64> = t
            .iter()
            .map(|t| 2.0 * (2.0 * PI * t / period).sin())
            .collect();
        let s = amplitude_spectrum(&t, &x, period, 4);
        assert!((s.harmonic(1) - 2.0).abs() < 2e-4, "{}", s.harmonic(1));
    }

    /// Periodic linear interpolation of (t, x) at tt (test helper).
    fn interp(t: &[f64], x: &[f64], window: f64, tt: f64) -> f64 {
        let j = t.partition_point(|v| *v <= tt).saturating_sub(1);
        let (ta, xa) = (t[j], x[j]);
        let (tb, xb) = if j + 1 < t.len() {
            (t[j + 1], x[j + 1])
        } else {
            (t[0] + window, x[0])
        };
        xa + (xb - xa) * (tt - ta) / (tb - ta)
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
