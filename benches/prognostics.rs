//! Benchmark of the prognostics pipeline on the paper's case (issue 12): calibrate the
//! wear coefficient from 10 observations (default prior: four decades around the case's
//! k), then predict 2000 trajectories to 1e6 cycles from the posterior, with the
//! remaining-life summary and the fan charts. Target: under 30 s on 2 cores.
//!
//! Run: `cargo bench --bench prognostics`. The time of each stage is printed once
//! before the timed iterations.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use gearwear::config::Case;
use gearwear::prognostics::calibrate::{calibrate, CalibrationSettings};
use gearwear::prognostics::forward::run_trajectory;
use gearwear::prognostics::observations::{Observations, Series};
use gearwear::prognostics::predict::{
    fans, run_sample, Forward, LifeSummary, PredictSettings, SampleSource,
};
use gearwear::prognostics::{Prior, Quantity, Surrogate};
use rayon::prelude::*;

/// Ten observations of the maximum pinion wear (sigma 0.2 um) and of the RMS velocity
/// (sigma inferred), every 4000 cycles, from a true run at 1.6 times the case's k.
fn observations(case: &Case) -> Observations {
    let mut c = case.clone();
    c.wear.coefficient_m2_per_n *= 1.6;
    let t = run_trajectory(&c, None, 4e4).expect("the paper's case runs");
    let cycles: Vec<f64> = (1..=10).map(|i| 4e3 * i as f64).collect();
    // A fixed, deterministic "noise" pattern (the benchmark times, it does not test).
    let wiggle = |i: usize, s: f64| s * ((i as f64 * 2.3).sin());
    let series = |q: Quantity, s: f64, sigma: Option<f64>| Series {
        quantity: q,
        cycles: cycles.clone(),
        values: cycles
            .iter()
            .enumerate()
            .map(|(i, c)| t.value(q, *c).expect("within the run") + wiggle(i, s))
            .collect(),
        sigma: sigma.map(|x| vec![x; cycles.len()]),
    };
    Observations {
        series: vec![
            series(Quantity::MaxWearPinion, 0.2, Some(0.2)),
            series(Quantity::VelocityRms, 0.02, None),
        ],
    }
}

/// Calibrate, then predict 2000 samples to 1e6 cycles; `log` prints stage times.
fn pipeline(case: &Case, obs: &Observations, log: bool) -> LifeSummary {
    let t0 = Instant::now();
    let prior = Prior::from_case(case).expect("default prior");
    let sur = Surrogate::build(case, &prior, obs.max_cycles(), 5, &|| {}).expect("model");
    let t1 = Instant::now();
    let set = CalibrationSettings {
        samples: 2000,
        seed: 1,
        grid_cells: 400,
        walkers: 32,
        steps: 2000,
    };
    let cal = calibrate(&prior, obs, &sur, &set, &|| {}).expect("posterior");
    let t2 = Instant::now();
    let span = Prior::spanning(&cal.samples);
    let pset = PredictSettings {
        limit_um: 10.0,
        cycles: 1e6,
        grid_points: 101,
        seed: 1,
        samples: 2000,
        stages: 1,
    };
    let psur = Surrogate::build(case, &span, pset.cycles, 5, &|| {}).expect("model");
    let t3 = Instant::now();
    let source = SampleSource::Posterior {
        rows: cal.samples.clone(),
        resample: false,
    };
    let fw = Forward::Surrogate(&psur);
    let out: Vec<_> = (0..pset.samples)
        .into_par_iter()
        .map(|i| run_sample(&fw, source.draw(i, pset.seed), i, &pset).expect("model"))
        .collect();
    let life = LifeSummary::of(&out);
    black_box(fans(&out, &pset));
    let t4 = Instant::now();
    if log {
        println!(
            "stages: calibration reference runs {:.2} s ({} runs), grid posterior {:.2} s, prediction reference runs {:.2} s ({} runs), 2000 samples + fans {:.2} s; k median {:.3e}, life median {:?}",
            (t1 - t0).as_secs_f64(),
            sur.runs(),
            (t2 - t1).as_secs_f64(),
            (t3 - t2).as_secs_f64(),
            psur.runs(),
            (t4 - t3).as_secs_f64(),
            cal.summary[0].median,
            life.median
        );
    }
    life
}

fn prognostics(c: &mut Criterion) {
    let case = Case::default();
    let obs = observations(&case);
    pipeline(&case, &obs, true);
    let mut g = c.benchmark_group("prognostics");
    g.sampling_mode(SamplingMode::Flat);
    g.bench_function("calibrate_10_obs_predict_2000_to_1e6", |b| {
        b.iter(|| pipeline(black_box(&case), &obs, false))
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(100))
        .measurement_time(Duration::from_secs(5));
    targets = prognostics
}
criterion_main!(benches);
