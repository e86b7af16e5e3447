//! Records of a transient (run-up, coast-down, fluctuating load): the bearing forces of a
//! long integration on a uniform grid, through the transfer path and the anti-alias
//! filter by fast convolution, decimated to the sampling rate; the tachometer from the
//! drive's angle.
//!
//! 1. The integrator's steps, linear between their ends, are averaged over the cells of
//!    the internal grid (rate D f_s, `super::antialias::OVERSAMPLING`; `ForceSampler`),
//!    and the cells' box filter is divided out in step 3.
//! 2. Before t = 0 the periodic steady state at the starting speed is prepended (a lead-in
//!    of `LEAD_S`), so the housing is in its steady vibration when the record starts;
//!    the integration runs `TAIL_S` past the record's end.
//! 3. Sensor s = IFFT[H_aa(f) sum_j A_sj(f) F_j(f)] over the zero-padded grid: the linear
//!    path and the zero-phase anti-alias filter as one product (the same response the
//!    periodic records use), then every D-th sample from t = 0.
//! 4. The tachometer's pulse train is sampled on the internal grid by its exact mean over
//!    each sample interval (the shaft's angle linear within the 5 us interval), filtered
//!    by H_aa and decimated the same way.

use super::antialias::{AntiAliasFilter, OVERSAMPLING};
use super::area::box_response;
use super::bearing::BearingForces;
use super::chain::SignalChain;
use super::periodic::PeriodicSignal;
use super::record::Record;
use super::tachometer::{DUTY, HIGH_V};
use crate::dynamics::model::{dof, ContactModes, GearSystem};
use crate::dynamics::params::DynamicParams;
use crate::dynamics::period::PeriodObserver;
use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;
use std::f64::consts::PI;

/// Lead-in of the periodic steady state before t = 0, s: longer than the decay of the
/// housing modes (10 time constants of a 2 % mode at 2 kHz: 40 ms) and the filter.
pub(crate) const LEAD_S: f64 = 0.1;
/// Integration past the record's end, s: more than the anti-alias filter's half-length.
pub const TAIL_S: f64 = 0.01;

/// Bearing forces of an integration as means over the cells [i w, (i + 1) w) of the
/// internal grid from t = 0 (step 1; `super::area` for why means, not point values).
pub(crate) struct ForceSampler {
    pub cell_s: f64,
    /// Integrals of each force over each cell so far, N s.
    integrals: [Vec<f64>; 4],
    /// Cells complete (the integration has passed their end).
    complete: usize,
    stiffness: [f64; 4],
    damping: [f64; 4],
}

impl ForceSampler {
    pub fn new(rate_hz: f64, params: &DynamicParams) -> Self {
        let l = &params.lumped;
        let (kp, kg) = (
            l.bearing_stiffness_pinion_n_per_m,
            l.bearing_stiffness_gear_n_per_m,
        );
        let (cp, cg) = (
            l.bearing_damping_pinion_n_s_per_m,
            l.bearing_damping_gear_n_s_per_m,
        );
        Self {
            cell_s: 1.0 / rate_hz,
            integrals: Default::default(),
            complete: 0,
            stiffness: [kp, kp, kg, kg],
            damping: [cp, cp, cg, cg],
        }
    }

    /// Bearing forces of the single pair's pinion and gear (x, y) at state y.
    fn force(&self, y: &[f64]) -> [f64; 4] {
        let idx = [dof::XP, dof::YP, dof::XG, dof::YG];
        let n = y.len() / 2;
        std::array::from_fn(|j| self.stiffness[j] * y[idx[j]] + self.damping[j] * y[n + idx[j]])
    }

    /// The cell means of force `j` over the complete cells.
    pub fn means(&self, j: usize) -> Vec<f64> {
        self.integrals[j][..self.complete]
            .iter()
            .map(|s| s / self.cell_s)
            .collect()
    }

    /// Cells complete so far.
    pub fn cells(&self) -> usize {
        self.complete
    }
}

impl PeriodObserver for ForceSampler {
    fn point(&mut self, _: &GearSystem, _: f64, _: f64, _: &[f64]) {}

    fn step(&mut self, _: &GearSystem, t: f64, h: f64, y0: &[f64], y1: &[f64], _: ContactModes) {
        let (f0, f1) = (self.force(y0), self.force(y1));
        let w = self.cell_s;
        let (a, b) = (t.max(0.0), t + h);
        if b <= a {
            return;
        }
        let i1 = (b / w).ceil() as usize;
        for v in &mut self.integrals {
            if v.len() < i1 {
                v.resize(i1, 0.0);
            }
        }
        for i in (a / w).floor() as usize..i1 {
            let (lo, hi) = (a.max(i as f64 * w), b.min((i + 1) as f64 * w));
            if hi <= lo {
                continue;
            }
            let s = (0.5 * (lo + hi) - t) / h;
            for j in 0..4 {
                self.integrals[j][i] += (f0[j] + (f1[j] - f0[j]) * s) * (hi - lo);
            }
        }
        self.complete = (b / w).floor() as usize;
    }
}

/// Smallest n' >= n of the form 2^a 3^b 5^c (fast FFT lengths).
pub(crate) fn fast_len(n: usize) -> usize {
    let mut best = n.next_power_of_two();
    let mut p5 = 1;
    while p5 < best {
        let mut p35 = p5;
        while p35 < best {
            let mut m = p35;
            while m < n {
                m *= 2;
            }
            best = best.min(m);
            p35 *= 3;
        }
        p5 *= 5;
    }
    best
}

/// Mean of the pulse train over [u_a, u_b] in pulse intervals (u = N theta / 2 pi).
fn pulse_mean(ua: f64, ub: f64) -> f64 {
    let integral = |u: f64| u.floor() * DUTY + (u - u.floor()).min(DUTY);
    if ub > ua {
        HIGH_V * (integral(ub) - integral(ua)) / (ub - ua)
    } else {
        HIGH_V * if (ua - ua.floor()) < DUTY { 1.0 } else { 0.0 }
    }
}

/// The record of a transient (module docs): `sampled` the forces from t = 0 at the
/// internal rate, `lead` the steady state before it (one period of bearing forces),
/// `tach_angle(t)` the tachometer shaft's angle (rad, valid for t < 0 too), `samples` the
/// record's length.
pub(crate) fn transient_record(
    sampled: &ForceSampler,
    lead: &BearingForces,
    chain: &SignalChain,
    tach_angle: &dyn Fn(f64) -> f64,
    samples: usize,
) -> Record {
    let acq = &chain.acquisition;
    let fs = acq.sampling_rate_hz;
    let aa = AntiAliasFilter::design(fs, acq.anti_alias_attenuation_db);
    let rate = aa.internal_rate_hz;
    let lead_n = (LEAD_S * rate).round() as usize;
    let body = sampled.cells();
    let n = fast_len(lead_n + body + (LEAD_S * rate) as usize);
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(n);
    let ifft = planner.plan_fft_inverse(n);
    let spectrum_of = |x: &mut Vec<f64>| {
        let mut s = fft.make_output_vec();
        fft.process(x, &mut s)
            .expect("FFT buffers sized by the plan");
        s
    };
    let df = rate / n as f64;
    let inputs = force_spectra(sampled, lead, &spectrum_of, n, lead_n, rate);
    let h_aa = aa.response_grid(n);
    let back = |spec: &mut Vec<Complex64>| -> Vec<f64> {
        if let Some(last) = spec.last_mut() {
            last.im = 0.0;
        }
        spec[0].im = 0.0;
        let mut out = ifft.make_output_vec();
        ifft.process(spec, &mut out)
            .expect("FFT buffers sized by the plan");
        (0..samples)
            .map(|i| out.get(lead_n + i * OVERSAMPLING).copied().unwrap_or(0.0) / n as f64)
            .collect()
    };
    let factor = acq.unit.factor(acq.sensitivity_mv_per_g);
    let channels = chain
        .path
        .sensors
        .iter()
        .enumerate()
        .map(|(s, name)| {
            let mut spec: Vec<Complex64> = (0..inputs[0].len())
                .map(|k| {
                    let f = k as f64 * df;
                    let sum: Complex64 = (0..4)
                        .map(|j| chain.path.accelerance(s, j, f) * inputs[j][k])
                        .sum();
                    sum * (h_aa[k] * factor)
                })
                .collect();
            (name.clone(), back(&mut spec))
        })
        .collect();
    let mut tach = tach_cells(chain, tach_angle, lead_n + body, lead_n, rate);
    tach.resize(n, 0.0);
    let mut ts = spectrum_of(&mut tach);
    for (c, h) in ts.iter_mut().zip(&h_aa) {
        *c *= h;
    }
    Record {
        sampling_rate_hz: fs,
        channels,
        tachometer_v: back(&mut ts),
    }
}

/// The spectra (length `n` / 2 + 1, internal `rate` in Hz) of the four bearing forces of
/// the record: `lead_n` cells of the steady state `lead` then the transient's cell means,
/// mean removed, zero-padded to `n`, the cells' box filter divided out and moved back
/// half a cell so that sample i is the force at i / rate.
fn force_spectra(
    sampled: &ForceSampler,
    lead: &BearingForces,
    spectrum_of: &dyn Fn(&mut Vec<f64>) -> Vec<Complex64>,
    n: usize,
    lead_n: usize,
    rate: f64,
) -> Vec<Vec<Complex64>> {
    let w = 1.0 / rate;
    let df = rate / n as f64;
    // Cell means are the box-filtered signal at the cell centres (i + 1/2) w: divide the
    // box out and move back half a cell, so sample i is the signal at i w.
    let unbox: Vec<Complex64> = (0..n / 2 + 1)
        .map(|k| {
            let f = k as f64 * df;
            Complex64::from_polar(1.0 / box_response(f, w), -PI * f * w)
        })
        .collect();
    (0..4)
        .map(|j| {
            // The steady state's exact series (as a steady record takes it in), every
            // harmonic below the internal Nyquist frequency.
            let harmonics = (0.5 * rate * lead.period_s).floor() as usize;
            let p = PeriodicSignal::from_hermite(&lead.signal(j), harmonics);
            // The lead-in as cell means too: the box-filtered series at the cell centres.
            let boxed = p.map(|k, f| p.coefficients[k] * box_response(f, w));
            let mut x = boxed.sample((0.5 - lead_n as f64) * w, rate, lead_n);
            x.extend(sampled.means(j));
            // The mean force does not reach an accelerometer (zero accelerance at 0 Hz);
            // removing it keeps the zero padding from acting as a step.
            let mean = x.iter().sum::<f64>() / x.len() as f64;
            x.iter_mut().for_each(|v| *v -= mean);
            x.resize(n, 0.0);
            let mut s = spectrum_of(&mut x);
            s.iter_mut().zip(&unbox).for_each(|(c, u)| *c *= u);
            s
        })
        .collect()
}

/// The tachometer's voltage (V) as cell means at the internal `rate` (Hz): `cells` cells,
/// the first `lead_n` of them before t = 0, each the pulse train's mean over its cell.
fn tach_cells(
    chain: &SignalChain,
    tach_angle: &dyn Fn(f64) -> f64,
    cells: usize,
    lead_n: usize,
    rate: f64,
) -> Vec<f64> {
    let np = chain.tachometer.pulses_per_revolution as f64;
    let u = |t: f64| np * tach_angle(t) / (2.0 * PI);
    (0..cells)
        .map(|i| {
            let t = (i as f64 - lead_n as f64) / rate;
            pulse_mean(u(t - 0.5 / rate), u(t + 0.5 / rate))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fast_lengths_are_smooth_and_minimal() {
        assert_eq!(fast_len(1000), 1000);
        assert_eq!(fast_len(1001), 1024);
        assert_eq!(fast_len(2_070_000), 2_073_600);
        for n in [7, 97, 4097, 100_003] {
            let m = fast_len(n);
            let mut r = m;
            for p in [2, 3, 5] {
                while r.is_multiple_of(p) {
                    r /= p;
                }
            }
            assert!(m >= n && r == 1, "{n} -> {m}");
        }
    }

    #[test]
    fn pulse_mean_is_the_duty_over_whole_intervals_and_the_level_inside() {
        assert!((pulse_mean(0.0, 3.0) - HIGH_V * DUTY).abs() < 1e-12);
        assert_eq!(pulse_mean(0.1, 0.2), HIGH_V);
        assert_eq!(pulse_mean(-0.4, -0.3), 0.0);
        // Straddling the falling edge at 0.5: half high.
        assert!((pulse_mean(0.45, 0.55) - 0.5 * HIGH_V).abs() < 1e-12);
    }
}
