//! Benchmarks of the tooth-resolved mesh (issue 18).
//!
//! Run: `cargo bench --bench teeth`. Groups:
//! - `hunting`: the steady state of the paper's pair with a pitch error on every tooth of
//!   both gears (ISO 1328-1 class 5 drawn, seed 1): 589 mesh periods, one core (target
//!   < 0.5 s), beside one warm mesh period of identical teeth, and the cold steady state
//!   of the paper case beside the same case with every per-tooth input zero (identical
//!   teeth stay on the one-period path);
//! - `tooth_wear`: the per-tooth wear study of that pair to 4e4 cycles, dynamic and
//!   quasi-static in parallel on 2 threads (target < 10 s).
//!
//! The work counts (mesh periods integrated, steps) are printed once before timing.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use gearwear::config::case::Case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::study::wear_loop::{run_wear_modes, WearMode, WearRun};
use gearwear::study::Model;

/// The paper's pair with every tooth's pitch drawn for ISO 1328-1 class 5.
fn graded(model_edit: impl FnOnce(&mut Case)) -> Model {
    let mut case = Case::default();
    case.teeth.accuracy_grade = Some(5);
    case.teeth.error_seed = Some(1);
    model_edit(&mut case);
    Model::from_case(&case).expect("valid case")
}

fn hunting(c: &mut Criterion) {
    let model = graded(|_| {});
    let wear = model.new_wear_state();
    let r = model.dynamic(&wear, &ExternalError::none()).unwrap();
    println!(
        "hunting steady state: {} mesh periods of excitation, {} integrated, {} steps, periodicity {:.2e}",
        r.excitation_periods, r.periods_to_converge, r.steps, r.periodicity_error
    );
    let mut g = c.benchmark_group("hunting");
    g.sampling_mode(SamplingMode::Flat)
        .sample_size(10)
        .measurement_time(Duration::from_secs(20));
    g.bench_function("steady_state_589_periods_grade5", |b| {
        b.iter(|| black_box(model.dynamic(&wear, &ExternalError::none()).unwrap()))
    });
    let plain = Model::from_case(&Case::default()).unwrap();
    let new = plain.new_wear_state();
    let warm = plain
        .dynamic(&new, &ExternalError::none())
        .unwrap()
        .end_state;
    // Identical teeth stay on the paper's path (issue 18): a case whose per-tooth inputs are
    // all zero builds no tooth-resolved mesh, so its cold steady state costs what the
    // paper case's does (test `zero_per_tooth_inputs_are_the_paper_case_bit_for_bit`
    // checks the numbers are the same bit for bit).
    let mut zero_case = Case::default();
    zero_case.teeth.pitch_error_pinion_um = Some(vec![0.0; 19]);
    zero_case.teeth.runout_gear_um = Some(0.0);
    let zero = Model::from_case(&zero_case).unwrap();
    assert!(zero.teeth.is_none());
    g.bench_function("cold_paper_case", |b| {
        b.iter(|| black_box(plain.dynamic(&new, &ExternalError::none()).unwrap()))
    });
    g.bench_function("cold_zero_per_tooth_inputs", |b| {
        b.iter(|| {
            black_box(
                zero.dynamic(&zero.new_wear_state(), &ExternalError::none())
                    .unwrap(),
            )
        })
    });
    g.bench_function("warm_mesh_period_identical_teeth", |b| {
        b.iter(|| {
            black_box(
                plain
                    .dynamic_from(&new, &ExternalError::none(), Some(&warm))
                    .unwrap(),
            )
        })
    });
    g.finish();
}

fn tooth_wear(c: &mut Criterion) {
    let model = graded(|_| {});
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let study = || {
        pool.install(|| {
            run_wear_modes(
                &model,
                vec![
                    WearRun::new(WearMode::Dynamic),
                    WearRun::new(WearMode::QuasiStatic),
                ],
                &|_, _| Ok(()),
            )
            .unwrap()
        })
    };
    let runs = study();
    println!(
        "per-tooth wear to 4e4 cycles: {} dynamic and {} quasi-static updates",
        runs[0].records.len() - 1,
        runs[1].records.len() - 1
    );
    let mut g = c.benchmark_group("tooth_wear");
    g.sampling_mode(SamplingMode::Flat)
        .sample_size(10)
        .measurement_time(Duration::from_secs(60));
    g.bench_function("wear_study_4e4_cycles_grade5_2_threads", |b| {
        b.iter(|| black_box(study()))
    });
    g.finish();
}

criterion_group!(benches, hunting, tooth_wear);
criterion_main!(benches);
