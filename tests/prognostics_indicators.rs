//! Condition indicators as prognostics observations (issue 19): a known wear coefficient
//! is recovered from synthetic observations of indicators that a monitoring system
//! computes from its accelerometer.
//!
//! The observations are made independently of the forward model's reading: at each
//! observation's cycle count the wear state of a true wear run at k0 is rebuilt exactly
//! (the last update advanced by its per-cycle increments, paper eq. 17), recorded through
//! the signal chain and analysed; the calibration sees them only through the surrogate
//! (reference runs at other k, indicators at their updates, linear between updates).

use gearwear::config::Case;
use gearwear::prognostics::calibrate::{calibrate, CalibrationSettings};
use gearwear::prognostics::forward::run_trajectory;
use gearwear::prognostics::indicator;
use gearwear::prognostics::observations::{Observations, Series};
use gearwear::prognostics::prior::Prior;
use gearwear::prognostics::{Quantity, Surrogate};
use gearwear::rng;
use gearwear::signals::setup::chain_of;
use gearwear::study::model::Model;
use gearwear::study::signal_record::record_case;
use gearwear::wear::WearState;
use rand_distr::{Distribution, Normal};

/// Cycle counts of the observations: one trend reading every 4000 cycles.
const OBS_CYCLES: [f64; 10] = [4e3, 8e3, 12e3, 16e3, 20e3, 24e3, 28e3, 32e3, 36e3, 40e3];

#[test]
fn a_known_wear_coefficient_is_recovered_from_condition_indicator_trends() {
    let mut case = Case::default();
    // A quarter-second record: 7 pinion revolutions at the default speed, enough for the
    // TSA's indicators and 4x cheaper than the default second.
    case.signals.record_length = 0.25;
    let k0 = case.wear.coefficient_m2_per_n;
    case.calibration.wear_coefficient_min_m2_per_n = Some(k0 / 10.0);
    case.calibration.wear_coefficient_max_m2_per_n = Some(3.0 * k0);
    let prior = Prior::from_case(&case).unwrap();
    let names = ["input_rms", "input_pinion_tsa_rms"];
    let qs: Vec<Quantity> = names.iter().map(|n| Quantity::parse(n).unwrap()).collect();

    // The truth: a true wear run at k0, indicators of the exact states at OBS_CYCLES.
    let truth = run_trajectory(&case, None, 4e4).unwrap();
    assert!(truth.failure.is_none(), "{:?}", truth.failure);
    let model = Model::from_case(&case).unwrap();
    let setup = chain_of(&case, None, case.operating.input_speed_hz).unwrap();
    let state_at = |c: f64| -> WearState {
        let j = truth.records.partition_point(|r| r.wear.cycles <= c) - 1;
        let r = &truth.records[j];
        let n = c - r.wear.cycles;
        let adv = |h: &[f64], d: &[f64]| h.iter().zip(d).map(|(a, b)| a + n * b).collect();
        WearState {
            cycles: c,
            pinion_m: adv(&r.wear.pinion_m, &r.increment_pinion_m),
            gear_m: adv(&r.wear.gear_m, &r.increment_gear_m),
            teeth: None,
            slices: None,
        }
    };
    let exact: Vec<Vec<f64>> = OBS_CYCLES
        .iter()
        .map(|c| {
            let rec = record_case(&model, &setup, &state_at(*c)).unwrap();
            qs.iter()
                .map(|q| match q {
                    Quantity::Indicator(i) => indicator::value(&rec.analysis, *i).unwrap(),
                    _ => unreachable!(),
                })
                .collect()
        })
        .collect();
    let new = record_case(&model, &setup, &WearState::new(model.grid.len())).unwrap();
    for (k, name) in names.iter().enumerate() {
        let Quantity::Indicator(i) = qs[k] else {
            unreachable!()
        };
        let v0 = indicator::value(&new.analysis, i).unwrap();
        let trend: Vec<String> = exact.iter().map(|v| format!("{:.4}", v[k])).collect();
        println!(
            "{name}: new {v0:.4}, at 4e3..4e4 cycles {}",
            trend.join(" ")
        );
    }

    // Observations with Gaussian scatter of 1 % of each indicator's value when new: the
    // day-to-day scatter of a trended RMS (temperature, load, mounting), larger than the
    // statistical error of a quarter-second record's RMS (~1e-3 for 6400 samples).
    let mut r = rng::stream(19, 0);
    let series = qs
        .iter()
        .enumerate()
        .map(|(k, q)| {
            let Quantity::Indicator(i) = q else {
                unreachable!()
            };
            let sigma = 0.01 * indicator::value(&new.analysis, *i).unwrap();
            let noise = Normal::new(0.0, sigma).unwrap();
            Series {
                quantity: *q,
                cycles: OBS_CYCLES.to_vec(),
                values: exact.iter().map(|v| v[k] + noise.sample(&mut r)).collect(),
                sigma: Some(vec![sigma; OBS_CYCLES.len()]),
            }
        })
        .collect();
    let obs = Observations { series };

    let mut sur = Surrogate::build(&case, &prior, 4e4, 2, &|| {}).unwrap();
    sur.attach_indicators(&case, &qs, &|| {}).unwrap();
    let settings = CalibrationSettings {
        samples: 2000,
        seed: 19,
        grid_cells: 400,
        walkers: 32,
        steps: 2000,
    };
    let cal = calibrate(&prior, &obs, &sur, &settings, &|| {}).unwrap();
    let ln_k: Vec<f64> = cal.samples.iter().map(|t| t[0].ln()).collect();
    let mean = ln_k.iter().sum::<f64>() / ln_k.len() as f64;
    let sd = (ln_k.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / ln_k.len() as f64).sqrt();
    let p = &cal.summary[0];
    println!(
        "k0 {k0:.4e}: posterior median {:.4e}, 90 % interval [{:.4e}, {:.4e}]; ln k mean - ln k0 = {:.4}, sd {sd:.4}",
        p.median,
        p.ci05,
        p.ci95,
        mean - k0.ln()
    );
    // Informative: the prior's sd of ln k (uniform over a factor 30) is 0.98; the
    // indicators must narrow it at least tenfold, or the check below says nothing.
    assert!(sd < 0.098, "posterior sd of ln k {sd}");
    // Recovered: one noise realisation, a near-Gaussian posterior: the truth lies within
    // 3 sd of the posterior mean with 99.7 % probability (the surrogate's own error is
    // below a tenth of the spread, src/prognostics/tests_calibration.rs).
    assert!(
        (mean - k0.ln()).abs() < 3.0 * sd,
        "{} vs {sd}",
        mean - k0.ln()
    );
}
