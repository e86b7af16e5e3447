//! A recorded record: accelerometer channels and the tachometer at the sampling rate,
//! and how a periodic steady state becomes one.
//!
//! From a periodic response (one period T of the bearing forces):
//! 1. each bearing force as a Fourier series (`super::periodic`);
//! 2. sensor s: X_s(f_k) = H_aa(f_k) sum_j A_sj(f_k) F_j(f_k), the transfer path's
//!    accelerance and the anti-alias filter's response at each harmonic f_k = k / T,
//!    for f_k below the internal Nyquist frequency D f_s / 2 (`super::antialias`): the
//!    steady state of the linear path and filter, exactly;
//! 3. the tachometer's pulse train as its own Fourier series, through the same filter;
//! 4. both sampled at n / f_s from t = 0 (mesh phase 0, tachometer shaft at angle 0)
//!    for the record's length;
//! 5. converted to the channel unit, and measurement noise added (`super::noise`), one
//!    stream per channel: stream c of `noise_seed` for channel c;
//! 6. every sample rounded to float32, the precision of the record's files
//!    (`super::files`; [`Record::round_to_stored`]): the indicators are computed from
//!    the numbers a reader of the files gets, so they can be recomputed from the files.

use super::antialias::AntiAliasFilter;
use super::bearing::BearingForces;
use super::chain::{NoiseSpec, Shaft, SignalChain, STANDARD_GRAVITY};
use super::noise::{sigma_for_density, sigma_for_snr, standard_normal};
use super::periodic::PeriodicSignal;
use super::tachometer::pulse_series;
use realfft::num_complex::Complex64;

/// Shaft speeds and teeth of the pair a record comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kinematics {
    /// Pinion shaft speed, Hz.
    pub pinion_hz: f64,
    /// Gear shaft speed, Hz.
    pub gear_hz: f64,
    /// Teeth of the pinion z_1.
    pub teeth_pinion: usize,
    /// Teeth of the gear z_2.
    pub teeth_gear: usize,
}

impl Kinematics {
    /// Speed of shaft `shaft`, Hz.
    pub fn shaft_hz(&self, shaft: Shaft) -> f64 {
        match shaft {
            Shaft::Pinion => self.pinion_hz,
            Shaft::Gear => self.gear_hz,
        }
    }

    /// Mesh frequency f_1 z_1, Hz.
    pub fn mesh_hz(&self) -> f64 {
        self.pinion_hz * self.teeth_pinion as f64
    }

    /// Revolutions of `analysed` per revolution of `reference`.
    pub fn ratio(&self, analysed: Shaft, reference: Shaft) -> f64 {
        self.shaft_hz(analysed) / self.shaft_hz(reference)
    }
}

/// A record: channels in the chain's unit and the tachometer in volts.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// Sampling rate f_s, Hz.
    pub sampling_rate_hz: f64,
    /// (sensor name, samples) per accelerometer channel.
    pub channels: Vec<(String, Vec<f64>)>,
    /// Tachometer signal at each sample, V.
    pub tachometer_v: Vec<f64>,
}

impl Record {
    /// Number of samples per channel.
    pub fn len(&self) -> usize {
        self.tachometer_v.len()
    }

    /// Whether the record has no samples.
    pub fn is_empty(&self) -> bool {
        self.tachometer_v.is_empty()
    }

    /// Time of sample n, s.
    pub fn time_s(&self, n: usize) -> f64 {
        n as f64 / self.sampling_rate_hz
    }

    /// The first sample that is not a finite number, as (channel name, or `tachometer`,
    /// and sample index), or None: a record holding one is never written (issue 33: its
    /// channels came out empty and its indicators null, and a dataset dropped it from its
    /// index with exit 0). Checked after [`Self::round_to_stored`], where a value beyond
    /// float32's range has become infinite.
    pub fn non_finite(&self) -> Option<(String, usize)> {
        let bad = |v: &[f64]| v.iter().position(|x| !x.is_finite());
        self.channels
            .iter()
            .find_map(|(name, v)| bad(v).map(|i| (name.clone(), i)))
            .or_else(|| bad(&self.tachometer_v).map(|i| ("tachometer".to_string(), i)))
    }

    /// The error of a record holding a non-finite sample ([`Self::non_finite`]) made for
    /// `what` (a state, a command), naming the channel and the sample; Ok otherwise.
    pub fn check_finite(&self, what: &str) -> Result<(), String> {
        match self.non_finite() {
            None => Ok(()),
            Some((channel, i)) => Err(format!(
                "{what}: the record's channel `{channel}` is not a finite number at sample {i} (t = {} s): the record overflows; check what scales it (a transfer path's gains and modes, the sensitivity and gain of the chain, the load)",
                crate::format::shown(self.time_s(i))
            )),
        }
    }

    /// Round every sample to float32 (step 6 of the module docs), as the record's files
    /// hold it (`super::files`); a second call changes nothing.
    pub fn round_to_stored(&mut self) {
        let round = |v: &mut Vec<f64>| v.iter_mut().for_each(|x| *x = *x as f32 as f64);
        self.channels.iter_mut().for_each(|(_, x)| round(x));
        round(&mut self.tachometer_v);
    }
}

/// The noise-free, filtered periodic signals of a steady state (steps 1-3).
#[derive(Debug, Clone, PartialEq)]
pub struct PeriodicRecord {
    /// The bearing forces as Fourier series (N), in `bearing::INPUTS` order: the
    /// chain's inputs (step 1).
    pub inputs: Vec<PeriodicSignal>,
    /// Acceleration at each sensor, m/s^2, after the anti-alias filter.
    pub sensors: Vec<(String, PeriodicSignal)>,
    /// Tachometer voltage after the anti-alias filter.
    pub tachometer: PeriodicSignal,
}

impl PeriodicRecord {
    /// Steps 1-3 of the module docs.
    pub fn new(forces: &BearingForces, kin: &Kinematics, chain: &SignalChain) -> Self {
        let acq = &chain.acquisition;
        let aa = AntiAliasFilter::design(acq.sampling_rate_hz, acq.anti_alias_attenuation_db);
        let top = 0.5 * aa.internal_rate_hz;
        // Every harmonic below the internal Nyquist frequency (the filter leaves nothing
        // above it: 100 dB down from f_s / 2).
        let harmonics = (top * forces.period_s).floor() as usize;
        let inputs: Vec<PeriodicSignal> = (0..4)
            .map(|j| PeriodicSignal::from_hermite(&forces.signal(j), harmonics))
            .collect();
        let sensors = chain
            .path
            .sensors
            .iter()
            .enumerate()
            .map(|(s, name)| {
                let sig = inputs[0].map(|k, f| {
                    if f >= top {
                        return Complex64::new(0.0, 0.0);
                    }
                    let sum: Complex64 = inputs
                        .iter()
                        .enumerate()
                        .map(|(j, input)| chain.path.accelerance(s, j, f) * input.coefficients[k])
                        .sum();
                    sum * aa.response(f)
                });
                (name.clone(), sig)
            })
            .collect();
        let rev = 1.0 / kin.shaft_hz(chain.tachometer.shaft);
        let pulses = pulse_series(rev, chain.tachometer.pulses_per_revolution, top);
        let tachometer = pulses.map(|k, f| pulses.coefficients[k] * aa.response(f));
        Self {
            inputs,
            sensors,
            tachometer,
        }
    }

    /// The noise-free record of `samples` samples (steps 4-5 without the noise).
    pub fn render(&self, chain: &SignalChain, samples: usize) -> Record {
        let acq = &chain.acquisition;
        let fs = acq.sampling_rate_hz;
        let factor = acq.unit.factor(acq.sensitivity_mv_per_g);
        Record {
            sampling_rate_hz: fs,
            channels: self
                .sensors
                .iter()
                .map(|(name, sig)| {
                    let mut v = sig.sample(0.0, fs, samples);
                    v.iter_mut().for_each(|x| *x *= factor);
                    (name.clone(), v)
                })
                .collect(),
            tachometer_v: self.tachometer.sample(0.0, fs, samples),
        }
    }
}

/// Add the chain's measurement noise to the channels of `record` (step 5).
pub fn add_noise(record: &mut Record, chain: &SignalChain) {
    let acq = &chain.acquisition;
    let factor = acq.unit.factor(acq.sensitivity_mv_per_g);
    for (c, (_, x)) in record.channels.iter_mut().enumerate() {
        let sigma = match acq.noise {
            NoiseSpec::None => continue,
            NoiseSpec::SnrDb(snr) => sigma_for_snr(x, snr),
            NoiseSpec::DensityUgPerSqrtHz(d) => {
                sigma_for_density(d * 1e-6 * STANDARD_GRAVITY, acq.sampling_rate_hz) * factor
            }
        };
        let n = standard_normal(acq.noise_seed, c as u64, x.len());
        for (v, e) in x.iter_mut().zip(&n) {
            *v += sigma * e;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signals::chain::RecordLength;
    use crate::signals::transfer::{modal_accelerance, PathModel, StructuralMode, TransferPath};
    use std::f64::consts::PI;

    /// A chain with one sensor and one mode driven by the pinion's y force only.
    fn one_mode_chain(fr: f64, zeta: f64, gain: f64) -> SignalChain {
        let mut c = SignalChain::default_chain();
        c.path = TransferPath {
            sensors: vec!["s".into()],
            model: PathModel::Modal(vec![StructuralMode {
                frequency_hz: fr,
                damping_ratio: zeta,
                gains_per_kg: vec![[0.0, gain, 0.0, 0.0]],
            }]),
            description: "test".into(),
            placement: "test".into(),
        };
        c.length = RecordLength::Seconds(0.5);
        c
    }

    /// Harmonic bearing force F cos(w t) on the pinion in y over one period.
    fn harmonic_force(f_hz: f64, amp: f64) -> BearingForces {
        let period = 1.0 / f_hz;
        let n = 256;
        let t: Vec<f64> = (0..n).map(|i| period * i as f64 / n as f64).collect();
        let fy = t
            .iter()
            .map(|t| amp * (2.0 * PI * f_hz * t).cos())
            .collect();
        let w = 2.0 * PI * f_hz;
        let rate = |end: usize| -> Vec<f64> {
            (0..n)
                .map(|i| -amp * w * (w * period * (i + end) as f64 / n as f64).sin())
                .collect()
        };
        BearingForces {
            time_s: t,
            force_n: [vec![0.0; n], fy, vec![0.0; n], vec![0.0; n]],
            // The exact rate at each step's ends (the solver's slope data).
            rate_start_n_per_s: [vec![0.0; n], rate(0), vec![0.0; n], vec![0.0; n]],
            rate_end_n_per_s: [vec![0.0; n], rate(1), vec![0.0; n], vec![0.0; n]],
            period_s: period,
        }
    }

    /// The single-degree-of-freedom oscillator m u'' + c u' + k u = F cos(w t), integrated
    /// from rest by classical RK4 with 2000 steps a period until the start transient has
    /// died (e^(-zeta w_r t) < 1e-12): its acceleration over the last period, by the
    /// equation of motion. Independent of the modal formula and the Fourier machinery.
    fn sdof_steady_acceleration(m: f64, k: f64, c: f64, f_hz: f64, amp: f64) -> (f64, f64) {
        let w = 2.0 * PI * f_hz;
        let wr = (k / m).sqrt();
        let zeta = c / (2.0 * (k * m).sqrt());
        let settle = 28.0 / (zeta * wr);
        let per = 2000;
        let h = 1.0 / f_hz / per as f64;
        let periods = (settle * f_hz).ceil() as usize + 1;
        let acc = |t: f64, u: f64, v: f64| (amp * (w * t).cos() - c * v - k * u) / m;
        let (mut t, mut u, mut v) = (0.0, 0.0, 0.0);
        let (mut a_cos, mut a_sin) = (0.0, 0.0);
        for p in 0..periods {
            for _ in 0..per {
                if p + 1 == periods {
                    let a = acc(t, u, v);
                    a_cos += a * (w * t).cos();
                    a_sin += a * (w * t).sin();
                }
                let k1 = (v, acc(t, u, v));
                let k2 = (
                    v + 0.5 * h * k1.1,
                    acc(t + 0.5 * h, u + 0.5 * h * k1.0, v + 0.5 * h * k1.1),
                );
                let k3 = (
                    v + 0.5 * h * k2.1,
                    acc(t + 0.5 * h, u + 0.5 * h * k2.0, v + 0.5 * h * k2.1),
                );
                let k4 = (v + h * k3.1, acc(t + h, u + h * k3.0, v + h * k3.1));
                u += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
                v += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
                t += h;
            }
        }
        // a = A cos(w t + phase): the in-phase and quadrature parts over one period.
        let (re, im) = (2.0 * a_cos / per as f64, -2.0 * a_sin / per as f64);
        ((re * re + im * im).sqrt(), im.atan2(re))
    }

    #[test]
    fn a_record_with_a_sample_beyond_float32_is_named_not_written() {
        // A value finite as f64 but beyond float32's 3.4e38 becomes infinite when stored.
        let mut r = Record {
            sampling_rate_hz: 1000.0,
            channels: vec![("a".into(), vec![1.0, 2.0]), ("b".into(), vec![0.0, 1e39])],
            tachometer_v: vec![0.0, 5.0],
        };
        assert_eq!(r.non_finite(), None);
        r.round_to_stored();
        assert_eq!(r.non_finite(), Some(("b".to_string(), 1)));
        let e = r.check_finite("state 3, record 7").unwrap_err();
        assert!(
            e.contains("state 3, record 7") && e.contains("`b`") && e.contains("sample 1"),
            "{e}"
        );
        r.channels[1].1[1] = 0.0;
        r.tachometer_v[0] = f64::NAN;
        assert_eq!(r.non_finite(), Some(("tachometer".to_string(), 0)));
    }

    #[test]
    fn single_mode_path_gives_the_analytic_frf_at_the_drive_frequency() {
        // m = 4 kg, k = 6e8 N/m (1949 Hz), 3 % damping; force 100 N at 1500 and 2100 Hz.
        let (m, k): (f64, f64) = (4.0, 6e8);
        let c = 2.0 * 0.03 * (k * m).sqrt();
        let fr = (k / m).sqrt() / (2.0 * PI);
        let chain = one_mode_chain(fr, 0.03, 1.0 / m);
        let fs = chain.acquisition.sampling_rate_hz;
        for f in [1500.0, 2100.0] {
            let kin = Kinematics {
                pinion_hz: 25.0,
                gear_hz: 25.0,
                teeth_pinion: 19,
                teeth_gear: 19,
            };
            let rec = PeriodicRecord::new(&harmonic_force(f, 100.0), &kin, &chain);
            let x = &rec.render(&chain, 12_800).channels[0].1;
            // Amplitude and phase of the recorded tone by projection on whole periods of
            // the record (12800 samples at 25.6 kHz = 0.5 s: 750 and 1050 periods).
            let w = 2.0 * PI * f / fs;
            let (mut a_cos, mut a_sin) = (0.0, 0.0);
            for (n, v) in x.iter().enumerate() {
                a_cos += v * (w * n as f64).cos();
                a_sin += v * (w * n as f64).sin();
            }
            let (re, im) = (2.0 * a_cos / x.len() as f64, -2.0 * a_sin / x.len() as f64);
            let amp = (re * re + im * im).sqrt();
            let phase = im.atan2(re);
            let (amp_ode, phase_ode) = sdof_steady_acceleration(m, k, c, f, 100.0);
            let frf = modal_accelerance(1.0 / m, fr, 0.03, f) * 100.0;
            // The ODE agrees with the formula to RK4's error at 2000 steps a period.
            assert!(
                (amp_ode - frf.norm()).abs() < 1e-6 * frf.norm(),
                "{amp_ode} vs {}",
                frf.norm()
            );
            println!(
                "single-mode path at {f} Hz: amplitude {:+.2e} relative, phase {:+.2e} rad",
                amp / amp_ode - 1.0,
                phase - phase_ode
            );
            // The record: < 0.1 % (the bound); the passband ripple of the
            // anti-alias filter (1e-5) and the sampling's cubic (3e-6) are all it adds.
            assert!(
                (amp - amp_ode).abs() < 1e-3 * amp_ode,
                "{f}: {amp} vs {amp_ode}"
            );
            assert!(
                (phase - phase_ode).abs() < 1e-3,
                "{f}: {phase} vs {phase_ode}"
            );
        }
    }
}
