//! Acquisition checks: what the anti-alias filter lets through to the record, and the
//! noise levels, measured on records.

use super::bearing::BearingForces;
use super::chain::{NoiseSpec, RecordLength, SignalChain, STANDARD_GRAVITY};
use super::frf_table::{Frf, FrfTable};
use super::record::{add_noise, Kinematics, PeriodicRecord, Record};
use super::transfer::{PathModel, TransferPath};
use realfft::num_complex::Complex64;
use std::f64::consts::PI;

/// A path of unit accelerance (1 m/s^2 per N) from the pinion's y force to one sensor,
/// flat to 200 kHz.
fn flat_chain(fs: f64, a_db: f64) -> SignalChain {
    let one = Frf {
        frequency_hz: vec![0.0, 2e5],
        value: vec![Complex64::new(1.0, 0.0); 2],
    };
    let mut frf: [Frf; 4] = Default::default();
    frf[1] = one;
    let mut c = SignalChain::default_chain();
    c.path = TransferPath {
        sensors: vec!["s".into()],
        model: PathModel::Table(FrfTable {
            sensors: vec!["s".into()],
            frf: vec![frf],
        }),
        description: "flat".into(),
        placement: "test".into(),
    };
    c.acquisition.sampling_rate_hz = fs;
    c.acquisition.anti_alias_attenuation_db = a_db;
    c.length = RecordLength::Seconds(1.0);
    c
}

/// A pinion y force of amplitude 1 N at `f_hz`.
fn tone(f_hz: f64) -> BearingForces {
    let period = 1.0 / f_hz;
    let n = 256;
    let t: Vec<f64> = (0..n).map(|i| period * i as f64 / n as f64).collect();
    let fy = t.iter().map(|t| (2.0 * PI * f_hz * t).cos()).collect();
    let w = 2.0 * PI * f_hz;
    let rate = |end: usize| -> Vec<f64> {
        (0..n)
            .map(|i| -w * (w * period * (i + end) as f64 / n as f64).sin())
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

const KIN: Kinematics = Kinematics {
    pinion_hz: 20.0,
    gear_hz: 20.0,
    teeth_pinion: 20,
    teeth_gear: 20,
};

fn record_of(f_hz: f64, chain: &SignalChain) -> Record {
    let n = chain.samples(KIN.pinion_hz);
    PeriodicRecord::new(&tone(f_hz), &KIN, chain).render(chain, n)
}

/// Amplitude of the component at `f_hz` (a whole number of cycles in the record).
fn amplitude_at(x: &[f64], fs: f64, f_hz: f64) -> f64 {
    let w = 2.0 * PI * f_hz / fs;
    let (mut c, mut s) = (0.0, 0.0);
    for (n, v) in x.iter().enumerate() {
        c += v * (w * n as f64).cos();
        s += v * (w * n as f64).sin();
    }
    2.0 * (c * c + s * s).sqrt() / x.len() as f64
}

#[test]
fn tones_above_the_new_nyquist_frequency_are_attenuated_by_the_stated_amount() {
    let fs = 25_600.0;
    for a_db in [60.0, 100.0] {
        let chain = flat_chain(fs, a_db);
        // A passband tone (at f_s / 2.56) comes through whole.
        let x = record_of(10_000.0, &chain);
        assert!((amplitude_at(&x.channels[0].1, fs, 10_000.0) - 1.0).abs() < 1e-3);
        // Tones above f_s / 2: each aliases to its distance from the nearest multiple of
        // f_s; the record
        // shows it there at the filter's stopband level.
        let mut worst_db = f64::NEG_INFINITY;
        for f in [
            12_810.0, 12_850.0, 13_000.0, 14_100.0, 17_900.0, 23_000.0, 30_000.0, 51_000.0,
        ] {
            let r = f % fs;
            let alias = r.min(fs - r);
            let x = record_of(f, &chain);
            let a = amplitude_at(&x.channels[0].1, fs, alias);
            let db = 20.0 * a.log10();
            worst_db = worst_db.max(db);
            // At least the stated attenuation (0.5 dB for Kaiser's approximate length
            // formula).
            let bound = -a_db + 0.5;
            assert!(db < bound, "A = {a_db} dB, tone {f} Hz: {db:.1} dB");
        }
        println!("anti-alias filter A = {a_db} dB: worst alias at {worst_db:.1} dB");
        // And not by accident: the worst tone lies within 12 dB of the stated level (the
        // stopband ripple of a Kaiser design peaks near its edge).
        assert!(
            worst_db > -a_db - 12.0,
            "A = {a_db}: worst {worst_db:.1} dB"
        );
    }
}

#[test]
fn noise_at_a_stated_snr_has_that_snr() {
    let fs = 25_600.0;
    let mut chain = flat_chain(fs, 100.0);
    chain.length = RecordLength::Seconds(4.0);
    let clean = record_of(1_234.0, &chain);
    for snr in [0.0, 20.0, 40.0] {
        chain.acquisition.noise = NoiseSpec::SnrDb(snr);
        chain.acquisition.noise_seed = 9;
        let mut noisy = clean.clone();
        add_noise(&mut noisy, &chain);
        let (x, y) = (&clean.channels[0].1, &noisy.channels[0].1);
        let p_signal = x.iter().map(|v| v * v).sum::<f64>();
        let p_noise = x.iter().zip(y).map(|(a, b)| (b - a) * (b - a)).sum::<f64>();
        let ratio = p_signal / p_noise;
        // Power ratio within 5 % (the issue); the estimate's scatter over 102400 samples
        // is sqrt(2 / N) = 0.44 %.
        let want = 10f64.powf(snr / 10.0);
        println!(
            "SNR {snr} dB: measured {:.3} dB (power ratio {:+.2} %)",
            10.0 * ratio.log10(),
            100.0 * (ratio / want - 1.0)
        );
        assert!(
            (ratio / want - 1.0).abs() < 0.05,
            "SNR {snr}: {ratio} vs {want}"
        );
    }
}

#[test]
fn noise_density_sets_the_noise_power_over_the_band() {
    let fs = 25_600.0;
    let mut chain = flat_chain(fs, 100.0);
    chain.length = RecordLength::Seconds(4.0);
    // 100 ug/sqrt(Hz) over 0..12.8 kHz: sigma = 1e-4 g x sqrt(12800) = 11.3 mg.
    chain.acquisition.noise = NoiseSpec::DensityUgPerSqrtHz(100.0);
    let clean = record_of(1_234.0, &chain);
    let mut noisy = clean.clone();
    add_noise(&mut noisy, &chain);
    let n = clean.len() as f64;
    let var = clean.channels[0]
        .1
        .iter()
        .zip(&noisy.channels[0].1)
        .map(|(a, b)| (b - a) * (b - a))
        .sum::<f64>()
        / n;
    let want = (100e-6 * STANDARD_GRAVITY).powi(2) * fs / 2.0;
    println!(
        "noise density: variance {:+.2} % of d^2 f_s / 2",
        100.0 * (var / want - 1.0)
    );
    assert!((var / want - 1.0).abs() < 0.05, "{var} vs {want}");
}
