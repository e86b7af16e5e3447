//! The TSA's passband through the whole analysis (tachometer edges, angular resampling,
//! derived signals, indicators), against values written from the definitions: a record of
//! known mesh harmonics, some inside the passband (up to 0.4 f_s) and some above it.

use gearwear::signals::analysis::analyse;
use gearwear::signals::antialias::AntiAliasFilter;
use gearwear::signals::chain::{Shaft, TachometerSpec};
use gearwear::signals::components::ComponentSettings;
use gearwear::signals::record::{Kinematics, Record};
use gearwear::signals::tachometer::pulse_series;
use std::f64::consts::PI;

/// Amplitude and phase of mesh harmonic h.
fn line(h: usize) -> (f64, f64) {
    (1.0 / h as f64, 0.1 * h as f64)
}

/// The TSA written from the definition: M samples at mesh-phase angles 2 pi h z i / M
/// (angle 0 at a pulse, where the mesh phase is 0) of the harmonics `hs`.
fn tsa_of(hs: impl Iterator<Item = usize> + Clone, z: usize, m: usize) -> Vec<f64> {
    (0..m)
        .map(|i| {
            hs.clone()
                .map(|h| {
                    let (a, phi) = line(h);
                    a * (2.0 * PI * (h * z * i) as f64 / m as f64 + phi).cos()
                })
                .sum()
        })
        .collect()
}

#[test]
fn indicators_are_those_of_the_harmonics_inside_the_passband() {
    // The default record: 25.6 kHz, 1 s, pinion at 30 Hz, 19:31 teeth, one tachometer
    // pulse per pinion revolution (through the anti-alias filter, as recorded). The
    // channel holds mesh harmonics h = 1..22 (570 Hz to 12.54 kHz = 0.49 f_s), amplitude
    // 1 / h. The passband ends at 0.4 f_s = 10.24 kHz: harmonics 1-17 (up to 9.69 kHz)
    // lie in it, 18-22 above it. So each shaft's TSA, as the indicators see it, is the
    // sum of harmonics 1-17 at its sample angles, whatever the resampling makes of 18-22.
    let (fs, f_p, zp, zg) = (25_600.0, 30.0, 19usize, 31usize);
    let n = 25_600;
    let aa = AntiAliasFilter::design(fs, 100.0);
    let pulses = pulse_series(1.0 / f_p, 1, 0.5 * aa.internal_rate_hz);
    let tach = pulses
        .map(|k, f| pulses.coefficients[k] * aa.response(f))
        .sample(0.0, fs, n);
    let f_mesh = f_p * zp as f64;
    let x: Vec<f64> = (0..n)
        .map(|i| {
            let t = i as f64 / fs;
            (1..=22)
                .map(|h| {
                    let (a, phi) = line(h);
                    a * (2.0 * PI * h as f64 * f_mesh * t + phi).cos()
                })
                .sum()
        })
        .collect();
    let record = Record {
        sampling_rate_hz: fs,
        channels: vec![("input".to_string(), x)],
        tachometer_v: tach,
    };
    let kin = Kinematics {
        pinion_hz: f_p,
        gear_hz: f_p * zp as f64 / zg as f64,
        teeth_pinion: zp,
        teeth_gear: zg,
    };
    let spec = TachometerSpec {
        shaft: Shaft::Pinion,
        pulses_per_revolution: 1,
    };
    let analysis = analyse(&record, &kin, &spec, ComponentSettings::default());
    let shafts = &analysis[0].shafts;
    assert_eq!(shafts.len(), 2);
    // FM0's denominator: the amplitudes of mesh harmonics 1..4 (`signals.mesh_harmonics`).
    let mesh_sum: f64 = (1..=4).map(|h| line(h).0).sum();
    // The TSA's RMS of harmonics 1-17: sqrt(sum a_h^2 / 2) (orthogonal on M samples, as
    // every order 17 z <= 527 lies below M / 2). Harmonics 18-22 would add 0.37 % to it.
    let rms_want = (1..=17)
        .map(|h| 0.5 * line(h).0.powi(2))
        .sum::<f64>()
        .sqrt();
    for a in shafts {
        let z = match a.shaft {
            Shaft::Pinion => zp,
            Shaft::Gear => zg,
        };
        let m = a.tsa.values.len();
        let want = tsa_of(1..=17, z, m);
        let pp = |v: &[f64]| {
            v.iter().fold(f64::MIN, |m, x| m.max(*x)) - v.iter().fold(f64::MAX, |m, x| m.min(*x))
        };
        let fm0_want = pp(&want) / mesh_sum;
        let ind = a.indicators;
        // Tolerances: the resampling's passband ripple (~1e-5) and the pulse times'
        // error (1e-3 of a sample at worst, a phase error of 2.5e-3 rad at 0.4 f_s on
        // the highest harmonic, 1/17 of the amplitude) leave each in-band line within
        // ~1e-4; the sum of 17 such errors bounds the peak-to-peak's at 1e-3.
        for h in 1..=17 {
            let got = a.components.order_amplitude(h * z);
            assert!(
                (got / line(h).0 - 1.0).abs() < 1e-4,
                "{:?} harmonic {h}: {got}",
                a.shaft
            );
        }
        for h in 18..=22 {
            assert_eq!(a.components.order_amplitude(h * z), 0.0, "harmonic {h}");
        }
        assert!(
            (ind.fm0 / fm0_want - 1.0).abs() < 1e-3,
            "{:?} FM0 {} vs {fm0_want}",
            a.shaft,
            ind.fm0
        );
        assert!(
            (ind.tsa_rms / rms_want - 1.0).abs() < 1e-4,
            "{:?} TSA RMS {} vs {rms_want}",
            a.shaft,
            ind.tsa_rms
        );
        // Mesh harmonics only, every one in band or removed: no difference signal.
        assert!(
            ind.energy_ratio < 1e-4,
            "{:?} ER {}",
            a.shaft,
            ind.energy_ratio
        );
    }
}
