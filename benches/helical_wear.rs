//! Benchmark of a helical pair's wear study per slice (issue 30, `study::helical_wear`).
//!
//! Run: `cargo bench --bench helical_wear`. Group `helical_wear`: the built-in pair with
//! `gear.helix_angle_deg` = 15 (the default 400 face slices, the planar model of
//! docs/MODEL.md 11.1, default numerics), beside the same spur pair:
//! - `dynamic_4e4_cycles_helical_15deg`: the whole dynamic wear study to 4e4 pinion cycles
//!   (the target: under 2 s on 2 cores);
//! - `dynamic_4e4_cycles_spur`: the spur pair's, the reference.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use gearwear::config::load_case;
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;

/// Criterion settings for a shared 2-core machine: 10 samples, short warm-up.
fn quick() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(15))
}

fn helical_wear(c: &mut Criterion) {
    let sets = |beta: &str| {
        vec![
            format!("gear.helix_angle_deg={beta}"),
            "wear.total_cycles=4e4".to_string(),
        ]
    };
    let helical = Model::helical_from_case(&load_case("", &sets("15")).unwrap()).unwrap();
    let spur = Model::from_case(&load_case("", &sets("0")).unwrap()).unwrap();
    let mut g = c.benchmark_group("helical_wear");
    for (name, model) in [
        ("dynamic_4e4_cycles_helical_15deg", &helical),
        ("dynamic_4e4_cycles_spur", &spur),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                let run = WearRun::new(WearMode::Dynamic);
                black_box(run_wear(model, run, &mut |_| Ok(())).unwrap())
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = quick();
    targets = helical_wear
}
criterion_main!(benches);
