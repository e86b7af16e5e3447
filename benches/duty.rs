//! Benchmarks of duty cycles (issue 20): a wear study under a 10-bin load spectrum
//! against the one-point study, and the spectrum of a one-million-sample history.
//!
//! Run: `cargo bench --bench duty` (short: `-- --warm-up-time 1 --measurement-time 3`).
//!
//! - `duty/one_point_model_and_both_modes_4e4`: the paper's case, model and both wear
//!   studies to 4e4 cycles, as `wear_study/model_and_both_modes_4e4` of the pipeline
//!   benchmark (sequential), the reference the spectrum is measured against;
//! - `duty/spectrum_1_bin_4e4`: the same as a one-bin spectrum (the spectrum path: both
//!   modes in parallel);
//! - `duty/spectrum_10_bins_4e4`: ten bins (20-45 Hz, 40-90 N m, shares 0.1), models
//!   and both modes, bins in parallel within each update;
//! - `duty/history_1e6_to_spectrum`: parse a CSV of 1e6 samples (in memory), count its
//!   load duration distribution (10 x 5 classes, linear) and make the spectrum.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use gearwear::config::case::TorqueShaft;
use gearwear::config::{load_case, Case};
use gearwear::duty::history::{parse_history, DEFAULT_GAP_FACTOR};
use gearwear::duty::ldd::{load_duration_distribution, LddSettings};
use gearwear::duty::wear::{run_spectrum_modes, SpectrumRun};
use gearwear::duty::SpectrumModel;
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;

fn quick() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

/// Models of every bin and both spectrum runs to the case's total cycles.
fn spectrum_study(case: &Case) -> Vec<SpectrumRun> {
    let sm = SpectrumModel::from_case(case).expect("valid spectrum");
    let starts = [WearMode::Dynamic, WearMode::QuasiStatic]
        .map(|m| SpectrumRun::new(m, sm.shares.clone()))
        .to_vec();
    run_spectrum_modes(&sm, starts, &|_, _| Ok(())).expect("runs")
}

fn ten_bins() -> Case {
    let bins: Vec<String> = (0..10)
        .map(|i| {
            format!(
                "{{torque_nm = {}, input_speed_hz = {}, share = 0.1}}",
                40.0 + 5.0 * i as f64,
                20.0 + 2.5 * i as f64
            )
        })
        .collect();
    load_case(
        &format!("[load_spectrum]\nbins = [{}]\n", bins.join(", ")),
        &[],
    )
    .expect("valid case")
}

fn wear(c: &mut Criterion) {
    let mut g = c.benchmark_group("duty");
    g.sampling_mode(SamplingMode::Flat);
    g.bench_function("one_point_model_and_both_modes_4e4", |b| {
        b.iter(|| {
            let m = Model::from_case(&Case::default()).expect("paper");
            let run = |mode| run_wear(&m, WearRun::new(mode), &mut |_| Ok(())).expect("runs");
            (run(WearMode::Dynamic), run(WearMode::QuasiStatic))
        })
    });
    let one = load_case(
        "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 1}]\n",
        &[],
    )
    .expect("valid case");
    g.bench_function("spectrum_1_bin_4e4", |b| {
        b.iter(|| spectrum_study(black_box(&one)))
    });
    let ten = ten_bins();
    let runs = spectrum_study(&ten);
    println!(
        "spectrum_10_bins_4e4: {} dynamic and {} quasi-static updates (initial included)",
        runs[0].records.len(),
        runs[1].records.len()
    );
    g.bench_function("spectrum_10_bins_4e4", |b| {
        b.iter(|| spectrum_study(black_box(&ten)))
    });
    g.finish();
}

/// A 1e6-sample history at 100 Hz: torque and speed wandering over their range.
fn history_csv(n: usize) -> Vec<u8> {
    let mut t = String::with_capacity(40 * n);
    t.push_str("time_s,torque_nm,input_speed_hz\n");
    for i in 0..n {
        let s = 0.01 * i as f64;
        let q = 60.0 + 30.0 * (s / 37.0).sin() + 5.0 * (s * 1.3).sin();
        let f = 30.0 + 12.0 * (s / 91.0).sin();
        t.push_str(&format!("{s},{q},{f}\n"));
    }
    t.into_bytes()
}

fn history(c: &mut Criterion) {
    let bytes = history_csv(1_000_000);
    let mut g = c.benchmark_group("duty");
    g.sampling_mode(SamplingMode::Flat);
    g.bench_function("history_1e6_to_spectrum", |b| {
        b.iter(|| {
            let h = parse_history(black_box(&bytes), DEFAULT_GAP_FACTOR).expect("valid");
            let l = load_duration_distribution(&h, LddSettings::default());
            l.spectrum(TorqueShaft::Pinion).expect("load")
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = quick();
    targets = wear, history
}
criterion_main!(benches);
