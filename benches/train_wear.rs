//! Benchmark of the wear study of a gear train (issue 29).
//!
//! Run: `cargo bench --bench train_wear`. Group `train_wear`: the dynamic wear study of
//! the two-stage reducer of `examples/two_stage_reducer.toml` (19/31 then 23/47, 14
//! coordinates) to 4e4 input cycles, from new teeth, one run at a time (target < 1 s on 2
//! cores); beside it the paper's single pair, dynamic, to 4e4 cycles.
//!
//! The work counts (updates, input cycles) are printed once before timing.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use gearwear::config::case::Case;
use gearwear::config::load_case;
use gearwear::study::train_wear::{run_train_wear, TrainWearRun};
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;

fn two_stage() -> Model {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/two_stage_reducer.toml"
    ))
    .expect("the example exists");
    Model::from_case(&load_case(&text, &[]).expect("valid case")).expect("valid train")
}

fn train_wear(c: &mut Criterion) {
    let model = two_stage();
    let train = model.train.as_ref().expect("a train");
    let run = |m: &Model| {
        run_train_wear(m, train, TrainWearRun::new(WearMode::Dynamic), &mut |_| {
            Ok(())
        })
        .unwrap()
    };
    let r = run(&model);
    println!(
        "two-stage dynamic wear: {} updates to {} input cycles",
        r.updates.len() - 1,
        r.updates.last().map_or(0.0, |u| u.input_cycles)
    );
    let paper = Model::from_case(&Case::default()).unwrap();
    let mut g = c.benchmark_group("train_wear");
    g.sampling_mode(SamplingMode::Flat)
        .sample_size(10)
        .measurement_time(Duration::from_secs(20));
    g.bench_function("two_stage_dynamic_4e4_input_cycles", |b| {
        b.iter(|| black_box(run(&model)))
    });
    g.bench_function("paper_pair_dynamic_4e4_cycles", |b| {
        b.iter(|| {
            black_box(run_wear(&paper, WearRun::new(WearMode::Dynamic), &mut |_| Ok(())).unwrap())
        })
    });
    g.finish();
}

criterion_group!(benches, train_wear);
criterion_main!(benches);
