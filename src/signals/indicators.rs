//! Condition indicators: the standard definitions (docs/SIGNALS.md lists them with their
//! sources).
//!
//! With x̄ the mean and N samples, the normalised moment of order p is
//! N^(p/2 - 1) sum (x - x̄)^p / (sum (x - x̄)^2)^(p/2).
//!
//! Of the recorded signal (Večeř, Kreidl & Šmíd 2005, Acta Polytechnica 45(6)):
//! - RMS = sqrt(mean x^2); crest factor CF = max |x| / RMS; kurtosis = moment 4
//!   (1.5 for a sine, 3 for Gaussian noise).
//!
//! Of the TSA of a shaft and its derived signals (`super::components`):
//! - FM0 = (max - min of the TSA) / sum_{h=1..H} A(h z) (Stewart 1977; Zakrajsek et al.
//!   1993), A(k) the amplitude of shaft order k, z the teeth of the analysed shaft's gear
//!   and H = `signals.mesh_harmonics` ([`super::components::ComponentSettings`]): 2 for a
//!   pure mesh tone;
//! - FM4 = moment 4 of the difference signal (Stewart 1977);
//! - M6A, M8A = moments 6 and 8 of the difference signal (Martin 1989);
//! - NA4 = N sum (r - r̄)^4 / [(1/M) sum_j sum_i (r_ij - r̄_j)^2]^2, r the residual
//!   signal of the current record and the mean in brackets over the residual variances
//!   of the M records of the run so far, the current one included (Zakrajsek 1993): with
//!   M = 1 it is the residual's kurtosis;
//! - NB4 = NA4 with the envelope of the band-pass signal in place of the residual
//!   (Zakrajsek, Handschuh & Decker 1994);
//! - ER = RMS(difference) / RMS(regular) (energy ratio, Swansson 1980);
//! - a derived signal with nothing above round-off (RMS below 1e-12 of the TSA's) has
//!   no shape, and its moment indicators are reported as 0;
//! - sideband level factor SLF = (A(z - 1) + A(z + 1)) / RMS(TSA) and sideband index
//!   SI = (A(z - 1) + A(z + 1)) / 2, the first-order sidebands of the mesh fundamental
//!   (Lebold et al. 2000).

use super::components::Components;
use serde::{Deserialize, Serialize};

/// Mean of `x`.
fn mean(x: &[f64]) -> f64 {
    x.iter().sum::<f64>() / x.len().max(1) as f64
}

/// sum (x - x̄)^p.
fn central_sum(x: &[f64], p: i32) -> f64 {
    let m = mean(x);
    x.iter().map(|v| (v - m).powi(p)).sum()
}

/// Normalised central moment of order `p` (module docs); 0 for a constant signal.
pub fn normalised_moment(x: &[f64], p: i32) -> f64 {
    let n = x.len() as f64;
    let s2 = central_sum(x, 2);
    if s2 <= 0.0 {
        return 0.0;
    }
    n.powi(p / 2 - 1) * central_sum(x, p) / s2.powi(p / 2)
}

/// Root mean square sqrt(mean x^2), in the unit of `x` (0 for an empty slice).
pub fn rms(x: &[f64]) -> f64 {
    (x.iter().map(|v| v * v).sum::<f64>() / x.len().max(1) as f64).sqrt()
}

/// Crest factor max |x| / RMS, dimensionless (0 for a zero signal).
pub fn crest_factor(x: &[f64]) -> f64 {
    let r = rms(x);
    if r > 0.0 {
        x.iter().fold(0.0, |m: f64, v| m.max(v.abs())) / r
    } else {
        0.0
    }
}

/// Kurtosis, the normalised moment of order 4 (1.5 for a sine, 3 for Gaussian noise).
pub fn kurtosis(x: &[f64]) -> f64 {
    normalised_moment(x, 4)
}

/// Variance of `x` about its mean (for NA4's and NB4's history).
pub fn variance(x: &[f64]) -> f64 {
    central_sum(x, 2) / x.len().max(1) as f64
}

/// NA4 (or NB4) of `x` given the variances of the earlier records of the run; the
/// current record's variance is added to the mean (module docs).
pub fn na4(x: &[f64], earlier_variances: &[f64]) -> f64 {
    let v = variance(x);
    let mean_var =
        (earlier_variances.iter().sum::<f64>() + v) / (earlier_variances.len() + 1) as f64;
    if mean_var <= 0.0 {
        return 0.0;
    }
    central_sum(x, 4) / x.len().max(1) as f64 / (mean_var * mean_var)
}

/// Indicators of the whole recorded signal.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct SignalIndicators {
    /// Root mean square, in the channel's unit.
    pub rms: f64,
    /// Crest factor max |x| / RMS, dimensionless.
    pub crest_factor: f64,
    /// Kurtosis (normalised moment 4), dimensionless.
    pub kurtosis: f64,
}

impl SignalIndicators {
    /// The indicators of the recorded signal `x`.
    pub fn of(x: &[f64]) -> Self {
        Self {
            rms: rms(x),
            crest_factor: crest_factor(x),
            kurtosis: kurtosis(x),
        }
    }
}

/// Indicators of the TSA of one shaft. NA4 and NB4 are those of the record alone (M = 1);
/// `residual_variance` and `envelope_variance` let a run's later records form theirs.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ShaftIndicators {
    /// Revolutions averaged into the TSA.
    pub revolutions: usize,
    /// RMS of the TSA, in the channel's unit.
    pub tsa_rms: f64,
    /// FM0: peak-to-peak of the TSA over the sum of the mesh harmonic amplitudes (Stewart 1977).
    pub fm0: f64,
    /// FM4: kurtosis of the difference signal (Stewart 1977).
    pub fm4: f64,
    /// M6A: normalised moment 6 of the difference signal (Martin 1989).
    pub m6a: f64,
    /// M8A: normalised moment 8 of the difference signal (Martin 1989).
    pub m8a: f64,
    /// NA4 of the record alone: kurtosis of the residual signal (Zakrajsek 1993).
    pub na4: f64,
    /// NB4 of the record alone: kurtosis of the band-pass envelope (Zakrajsek, Handschuh &
    /// Decker 1994).
    pub nb4: f64,
    /// Energy ratio RMS(difference) / RMS(regular) (Swansson 1980).
    pub energy_ratio: f64,
    /// Sideband level factor (A(z - 1) + A(z + 1)) / RMS(TSA) (Lebold et al. 2000).
    pub sideband_level_factor: f64,
    /// Sideband index (A(z - 1) + A(z + 1)) / 2, in the channel's unit (Lebold et al. 2000).
    pub sideband_index: f64,
    /// Variance of the residual signal, in the channel's unit squared (for a run's NA4).
    pub residual_variance: f64,
    /// Variance of the band-pass envelope, in the channel's unit squared (for a run's NB4).
    pub envelope_variance: f64,
}

impl ShaftIndicators {
    /// The indicators of a TSA (its samples and derived signals), `revolutions` averaged.
    pub fn of(tsa: &[f64], c: &Components, revolutions: usize) -> Self {
        // The TSA within its passband (all of it unless the settings cut it).
        let tsa: &[f64] = if c.in_band.len() == tsa.len() {
            &c.in_band
        } else {
            tsa
        };
        let pp = tsa.iter().fold(f64::MIN, |m, v| m.max(*v))
            - tsa.iter().fold(f64::MAX, |m, v| m.min(*v));
        let mesh_sum: f64 = c.mesh_harmonics().map(|k| c.order_amplitude(k)).sum();
        let z = c.mesh_order;
        let sidebands = c.order_amplitude(z - 1) + c.order_amplitude(z + 1);
        let tsa_rms = {
            let m = mean(tsa);
            (tsa.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / tsa.len().max(1) as f64).sqrt()
        };
        let regular_rms = rms(&c.regular);
        // A derived signal with nothing above round-off has no shape: its moments are
        // ratios of rounding errors. Below 1e-12 of the TSA's RMS they are reported as 0.
        let floor = 1e-12 * tsa_rms;
        let shaped = |x: &[f64]| variance(x).sqrt() > floor;
        let moment = |x: &[f64], p: i32| {
            if shaped(x) {
                normalised_moment(x, p)
            } else {
                0.0
            }
        };
        Self {
            revolutions,
            tsa_rms,
            fm0: if mesh_sum > 0.0 { pp / mesh_sum } else { 0.0 },
            fm4: moment(&c.difference, 4),
            m6a: moment(&c.difference, 6),
            m8a: moment(&c.difference, 8),
            na4: if shaped(&c.residual) {
                na4(&c.residual, &[])
            } else {
                0.0
            },
            nb4: if shaped(&c.envelope) {
                na4(&c.envelope, &[])
            } else {
                0.0
            },
            energy_ratio: if regular_rms > 0.0 {
                rms(&c.difference) / regular_rms
            } else {
                0.0
            },
            sideband_level_factor: if tsa_rms > 0.0 {
                sidebands / tsa_rms
            } else {
                0.0
            },
            sideband_index: 0.5 * sidebands,
            residual_variance: variance(&c.residual),
            envelope_variance: variance(&c.envelope),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signals::components::{components, ComponentSettings};
    use crate::signals::noise::standard_normal;
    use std::f64::consts::PI;

    #[test]
    fn kurtosis_of_a_sine_is_1_5_and_of_gaussian_noise_3() {
        // A sine over whole periods: mean(sin^4) / mean(sin^2)^2 = (3/8) / (1/4) = 1.5,
        // exact on equally spaced samples of whole periods (round-off only).
        let x: Vec<f64> = (0..4096)
            .map(|i| (2.0 * PI * 7.0 * i as f64 / 4096.0).sin())
            .collect();
        assert!((kurtosis(&x) - 1.5).abs() < 1e-12, "{}", kurtosis(&x));
        assert!((crest_factor(&x) - 2f64.sqrt()).abs() < 1e-12);
        // Gaussian: 3, with standard error sqrt(24 / N) = 0.0049 at N = 1e6; 4 sigma.
        let g = standard_normal(1, 0, 1_000_000);
        assert!((kurtosis(&g) - 3.0).abs() < 0.02, "{}", kurtosis(&g));
        // Moments 6 and 8 of a Gaussian: 15 and 105 (slower estimates: 10 % and 25 %).
        assert!((normalised_moment(&g, 6) - 15.0).abs() < 1.5);
        assert!((normalised_moment(&g, 8) - 105.0).abs() < 25.0);
        println!(
            "kurtosis: sine {:.15}, Gaussian (1e6 samples) {:.4}; moments 6, 8 of the Gaussian {:.2}, {:.1}",
            kurtosis(&x),
            kurtosis(&g),
            normalised_moment(&g, 6),
            normalised_moment(&g, 8)
        );
    }

    #[test]
    fn fm0_of_a_pure_mesh_tone_is_two() {
        // TSA = A cos(z theta) with M = 1024, z = 19: peak-to-peak 2A, one mesh harmonic
        // of amplitude A: FM0 = 2.
        let (m, z, a) = (1024, 19, 3.7);
        let x: Vec<f64> = (0..m)
            .map(|i| a * (2.0 * PI * z as f64 * i as f64 / m as f64).cos())
            .collect();
        let c = components(&x, z, ComponentSettings::default());
        let ind = ShaftIndicators::of(&x, &c, 1);
        // The sampled minimum misses -A by at most A (1 - cos(pi z / M)) = 1.7e-3 A.
        assert!((ind.fm0 - 2.0).abs() < 1.7e-3, "{}", ind.fm0);
        println!("FM0 of a pure mesh tone: {:.6}", ind.fm0);
        // Nothing but the mesh tone: no difference signal, no sidebands.
        assert_eq!(ind.fm4, 0.0);
        assert!(ind.sideband_index < 1e-12 && ind.energy_ratio < 1e-12);
    }

    /// TSA with mesh harmonics h = 1..5 of amplitudes `amps` (cosines in phase) of mesh
    /// order 16 on M = 1024 points, so that both extremes fall on samples (i = 0 and
    /// i = 32, half a mesh period), plus shaft order 7 (not a mesh harmonic).
    fn five_mesh_harmonics(amps: &[f64; 5], other: f64) -> Vec<f64> {
        let (m, z) = (1024, 16);
        (0..m)
            .map(|i| {
                let u = 2.0 * PI * z as f64 * i as f64 / m as f64;
                let a = 2.0 * PI * i as f64 / m as f64;
                amps.iter()
                    .enumerate()
                    .map(|(h, amp)| amp * ((h + 1) as f64 * u).cos())
                    .sum::<f64>()
                    + other * (7.0 * a).cos()
            })
            .collect()
    }

    #[test]
    fn fm0_is_the_peak_to_peak_over_the_first_h_mesh_harmonics() {
        // x(u) = cos u + 0.1 cos 2u + 0.05 cos 3u + 0.02 cos 4u + 0.01 cos 5u, u = 16 a:
        // maximum at u = 0: 1.18; at u = pi: -1 + 0.1 - 0.05 + 0.02 - 0.01 = -0.94, a
        // minimum (x'(pi) = 0, x''(pi) = 1 - 0.4 + 0.45 - 0.32 + 0.25 > 0; the harmonics
        // above the first sum to 0.18 < 1, so no other minimum goes lower, checked below
        // on the samples). Peak-to-peak 2.12. FM0 with H harmonics: 2.12 / sum_{h<=H} A_h.
        let amps = [1.0, 0.1, 0.05, 0.02, 0.01];
        let x = five_mesh_harmonics(&amps, 0.0);
        let pp =
            x.iter().fold(f64::MIN, |m, v| m.max(*v)) - x.iter().fold(f64::MAX, |m, v| m.min(*v));
        assert!((pp - 2.12).abs() < 1e-12, "{pp}");
        for (h, denominator) in [
            (1, 1.0),
            (2, 1.1),
            (3, 1.15),
            (4, 1.17),
            (5, 1.18),
            (8, 1.18),
        ] {
            let settings = ComponentSettings {
                mesh_harmonics: h,
                ..ComponentSettings::default()
            };
            let c = components(&x, 16, settings);
            let fm0 = ShaftIndicators::of(&x, &c, 1).fm0;
            let hand = 2.12 / denominator;
            println!("FM0 with H = {h}: {fm0:.15} (hand {hand:.15})");
            // Round-off of a 1024-point FFT: ~1e-15 relative.
            assert!(
                (fm0 - hand).abs() < 1e-12 * hand,
                "H = {h}: {fm0} vs {hand}"
            );
        }
        // Content that is not a mesh harmonic changes the peak-to-peak, not the sum: with
        // 0.3 cos(7 a) added the extremes move (checked on the samples), the sum stays 1.17.
        let y = five_mesh_harmonics(&amps, 0.3);
        let c = components(&y, 16, ComponentSettings::default());
        let pp_y =
            y.iter().fold(f64::MIN, |m, v| m.max(*v)) - y.iter().fold(f64::MAX, |m, v| m.min(*v));
        assert!(pp_y > 2.12 + 0.1);
        assert!((ShaftIndicators::of(&y, &c, 1).fm0 - pp_y / 1.17).abs() < 1e-12 * pp_y);
    }

    #[test]
    fn every_tsa_indicator_against_its_definition_on_a_hand_built_tsa() {
        // TSA (M = 1024, mesh order z = 16, angle a):
        //   3 cos(16 a) [mesh]  + AM of the mesh tone: 3 m cos(a) cos(16 a), m = 0.2, i.e.
        //   sidebands 15 and 17 of 0.3 each  + 0.5 cos(40 a) [difference: not a mesh order,
        //   not a sideband, not shaft orders 1-2]  + 0.25 cos(a) [shaft order 1].
        let (m, z) = (1024usize, 16usize);
        let am = 0.2;
        let x: Vec<f64> = (0..m)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / m as f64;
                3.0 * (1.0 + am * a.cos()) * (16.0 * a).cos()
                    + 0.5 * (40.0 * a).cos()
                    + 0.25 * a.cos()
            })
            .collect();
        let c = components(&x, z, ComponentSettings::default());
        let ind = ShaftIndicators::of(&x, &c, 1);
        let close = |name: &str, got: f64, want: f64| {
            println!("{name}: {got:.12} (definition {want:.12})");
            assert!(
                (got - want).abs() < 1e-10 * want.abs().max(1.0),
                "{name}: {got} vs {want}"
            );
        };
        // Difference signal = 0.5 cos(40 a): moments of a sine, mean(s^p) / mean(s^2)^(p/2)
        // = (p-1)!! / p!! / 2^(-p/2): 3/2, 5/2, 35/8.
        close("FM4", ind.fm4, 1.5);
        close("M6A", ind.m6a, 2.5);
        close("M8A", ind.m8a, 4.375);
        // Residual = sidebands + 0.5 cos(40 a) (shaft order 1 and the mesh tone removed):
        // 0.6 cos(a) cos(16 a) + 0.5 cos(40 a); NA4 with M = 1 = its kurtosis, by quadrature
        // of the definition on the samples (an independent sum, not the FFT path).
        let r: Vec<f64> = (0..m)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / m as f64;
                0.6 * a.cos() * (16.0 * a).cos() + 0.5 * (40.0 * a).cos()
            })
            .collect();
        let k4 = {
            let n = m as f64;
            let s2: f64 = r.iter().map(|v| v * v).sum();
            n * r.iter().map(|v| v.powi(4)).sum::<f64>() / (s2 * s2)
        };
        close("NA4", ind.na4, k4);
        // Band 9..=23 around order 16 holds the AM tone: envelope 3 (1 + 0.2 cos a), whose
        // deviation from its mean is a sine: NB4 (M = 1) = 1.5.
        close("NB4", ind.nb4, 1.5);
        // Energy ratio: RMS(0.5 cos 40a) / RMS(regular = the rest).
        let regular_ms = (9.0 + 0.09 + 0.09 + 0.0625) / 2.0;
        close("ER", ind.energy_ratio, (0.125f64 / regular_ms).sqrt());
        // Sidebands 15 and 17: 0.3 each. SI = 0.3, SLF = 0.6 / RMS(TSA).
        let tsa_rms = ((9.0 + 0.09 + 0.09 + 0.25 + 0.0625) / 2.0f64).sqrt();
        close("TSA RMS", ind.tsa_rms, tsa_rms);
        close("SI", ind.sideband_index, 0.3);
        close("SLF", ind.sideband_level_factor, 0.6 / tsa_rms);
        // FM0: the one mesh harmonic is 3; the peak-to-peak on the samples.
        let pp =
            x.iter().fold(f64::MIN, |m, v| m.max(*v)) - x.iter().fold(f64::MAX, |m, v| m.min(*v));
        close("FM0", ind.fm0, pp / 3.0);
    }

    #[test]
    fn signal_indicators_against_their_definitions() {
        // Square wave +-2 (half the samples each): RMS 2, crest factor 1, kurtosis 1.
        let x: Vec<f64> = (0..1000)
            .map(|i| if i % 10 < 5 { 2.0 } else { -2.0 })
            .collect();
        let s = SignalIndicators::of(&x);
        assert!((s.rms - 2.0).abs() < 1e-14 && (s.crest_factor - 1.0).abs() < 1e-14);
        assert!((s.kurtosis - 1.0).abs() < 1e-14, "{}", s.kurtosis);
        // One spike of 10 among 99 zeros: RMS 1, crest factor 10, kurtosis by hand:
        // mean 0.1, sum d^4 = 9.9^4 + 99 x 0.1^4, sum d^2 = 9.9^2 + 99 x 0.1^2 = 99.
        let mut y = vec![0.0; 100];
        y[37] = 10.0;
        let s = SignalIndicators::of(&y);
        let k = 100.0 * (9.9f64.powi(4) + 99.0 * 1e-4) / (99.0 * 99.0);
        assert!((s.rms - 1.0).abs() < 1e-14 && (s.crest_factor - 10.0).abs() < 1e-13);
        assert!((s.kurtosis - k).abs() < 1e-12 * k, "{} vs {k}", s.kurtosis);
    }

    #[test]
    fn na4_matches_a_hand_computation_on_a_short_signal() {
        // r = [1, -2, 3, 0] (mean 0.5): deviations 0.5, -2.5, 2.5, -0.5;
        // sum d^4 = 0.0625 + 39.0625 + 39.0625 + 0.0625 = 78.25; variance = 13 / 4 = 3.25.
        // Alone: NA4 = 4 x 78.25 / 13^2 = 1.852071...
        let r = [1.0, -2.0, 3.0, 0.0];
        assert!((na4(&r, &[]) - 4.0 * 78.25 / 169.0).abs() < 1e-14);
        // After two earlier records of residual variance 1 and 2: mean variance
        // (1 + 2 + 3.25) / 3 = 2.0833..., NA4 = (78.25 / 4) / 2.0833^2 = 4.5072.
        let want = (78.25 / 4.0) / ((6.25f64 / 3.0) * (6.25 / 3.0));
        println!(
            "NA4: alone {:.15} (hand {:.15}); after two records {:.15} (hand {want:.15})",
            na4(&r, &[]),
            4.0 * 78.25 / 169.0,
            na4(&r, &[1.0, 2.0])
        );
        assert!(
            (na4(&r, &[1.0, 2.0]) - want).abs() < 1e-13,
            "{}",
            na4(&r, &[1.0, 2.0])
        );
    }

    #[test]
    fn sidebands_and_energy_ratio_by_hand() {
        // TSA = 2 cos(19 a) + 0.4 cos(18 a) + 0.6 cos(20 a) + 0.1 cos(7 a).
        let (m, z) = (512, 19);
        let x: Vec<f64> = (0..m)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / m as f64;
                2.0 * (19.0 * a).cos()
                    + 0.4 * (18.0 * a).cos()
                    + 0.6 * (20.0 * a).cos()
                    + 0.1 * (7.0 * a).cos()
            })
            .collect();
        let c = components(&x, z, ComponentSettings::default());
        let ind = ShaftIndicators::of(&x, &c, 1);
        let tsa_rms = ((4.0 + 0.16 + 0.36 + 0.01) / 2.0f64).sqrt();
        assert!((ind.sideband_index - 0.5).abs() < 1e-12);
        assert!((ind.sideband_level_factor - 1.0 / tsa_rms).abs() < 1e-12);
        // Difference = 0.1 cos(7a); regular = the rest: ER = 0.1 / sqrt(4 + 0.16 + 0.36).
        let er = 0.1 / (4.0f64 + 0.16 + 0.36).sqrt();
        assert!((ind.energy_ratio - er).abs() < 1e-12);
        // FM4 of a single sine in the difference signal: 1.5.
        assert!((ind.fm4 - 1.5).abs() < 1e-9);
        println!(
            "sideband index {:.15} (0.5), SLF {:.15} ({:.15}), ER {:.15} ({er:.15}), FM4 {:.12} (1.5)",
            ind.sideband_index,
            ind.sideband_level_factor,
            1.0 / tsa_rms,
            ind.energy_ratio,
            ind.fm4
        );
    }
}
