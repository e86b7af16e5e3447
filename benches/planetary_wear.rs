//! Benchmark of a planetary set's wear study (issue 31, `study::planetary_wear`).
//!
//! Run: `cargo bench --bench planetary_wear`. Group `planetary_wear`, the default
//! `[planetary]` set (24 / 30 / 84, four planets, module 2 mm, lumped values derived from
//! the geometry, sun in at the case's speed and 60 N m, ring fixed, carrier out), default
//! numerics (200 samples per mesh period):
//! - `update_dynamic_4_planets`: one update of the dynamic study from new teeth (the set's
//!   cold steady state and the Archard increments of its 8 meshes);
//! - `study_quasi_static_4e4_carrier_revs`: the whole quasi-static study to 4e4 carrier
//!   revolutions (1.8e5 sun revolutions, 18 updates of 1e4).
//!
//! The whole dynamic study to 4e4 carrier revolutions is 19 such updates (about 3.7 s of CPU
//! measured through `gearwear wear --mode dynamic`); it is left out here as too long for
//! criterion's ten samples on the shared machine.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use gearwear::config::load_case;
use gearwear::study::planetary_wear::{new_teeth, PlanetaryWearModel};
use gearwear::study::planetary_wear_loop::{run_planetary_wear, update_of, PlanetaryWearRun};
use gearwear::study::wear_loop::WearMode;

/// Criterion settings for a shared 2-core machine: 10 samples, short warm-up.
fn quick() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(8))
}

fn planetary_wear(c: &mut Criterion) {
    let case = load_case("[planetary]\n[wear]\ntotal_cycles = 180000\n", &[]).unwrap();
    let model = PlanetaryWearModel::from_case(&case).unwrap();
    let mut g = c.benchmark_group("planetary_wear");
    g.bench_function("update_dynamic_4_planets", |b| {
        b.iter(|| {
            black_box(update_of(&model, WearMode::Dynamic, (0.0, None), new_teeth(&model)).unwrap())
        })
    });
    g.bench_function("study_quasi_static_4e4_carrier_revs", |b| {
        b.iter(|| {
            let run = PlanetaryWearRun::new(WearMode::QuasiStatic);
            black_box(run_planetary_wear(&model, &case.wear, run, &mut |_| Ok(())).unwrap())
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = quick();
    targets = planetary_wear
}
criterion_main!(benches);
