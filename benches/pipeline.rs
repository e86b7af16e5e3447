//! Benchmarks of the gearwear pipeline on the paper's case (issue 6).
//!
//! Run: `cargo bench --bench pipeline` (criterion is built without its plotting feature,
//! see docs/PERFORMANCE.md; pass `-- --noplot` if the features are ever turned back on).
//! Filter with a substring, e.g. `cargo bench --bench pipeline -- scaling_steps`.
//!
//! Groups:
//! - `stiffness`: the mesh-stiffness table (400 points, fillet foundation on);
//! - `evaluation`: one steady-state dynamic and one quasi-static evaluation of new teeth
//!   (the default extended contact; the dynamic one also on the nominal path only),
//!   a warm-started dynamic one, and dynamic ones at 2 Hz and at the contact-loss
//!   resonance (50 Hz, brake speed imposed);
//! - `wear_study`: `run_wear` to 4e4 cycles, each mode, and both modes including the
//!   model build (the figure the < 1 s target is about);
//! - `scaling_*`: cost against steps per mesh period, wear grid points and total cycles;
//! - `train`: one cold steady state of the two-stage reducer of
//!   `examples/two_stage_reducer.toml` (14 coordinates, 28 states, two meshes).
//!
//! The work counts that explain the times (integrator steps, rhs calls, LU
//! factorisations, number of wear-loop evaluations) are printed once per benchmark,
//! before it is timed (and only if the filter selects it): timing alone cannot tell
//! "more work" from "slower work".

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode};
use gearwear::config::case::{Case, ContactPathModel};
use gearwear::dynamics::excitation::ExternalError;
use gearwear::geometry::GearPair;
use gearwear::stiffness::mesh::MeshStiffness;
use gearwear::stiffness::potential_energy::ElasticPair;
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;
use gearwear::wear::WearState;

/// The paper's case with `edit` applied, assembled.
fn model_with(edit: impl FnOnce(&mut Case)) -> Model {
    let mut case = Case::default();
    edit(&mut case);
    Model::from_case(&case).expect("the paper's case is valid")
}

/// A whole wear study of one mode from new teeth, no checkpointing.
fn wear_study(model: &Model, mode: WearMode) -> WearRun {
    run_wear(model, WearRun::new(mode), &mut |_| Ok(())).expect("the paper's case runs")
}

/// Runs `f` the first time only: criterion calls a benchmark's closure several times
/// (warm-up, samples), the work counts need printing once.
fn once(done: &mut bool, f: impl FnOnce()) {
    if !*done {
        *done = true;
        f();
    }
}

/// Prints the integrator work of one steady-state evaluation.
fn print_steady_work(label: &str, model: &Model, wear: &WearState) {
    let r = model
        .dynamic(wear, &ExternalError::none())
        .expect("steady state");
    println!(
        "{label} work: {} steps, {} rhs calls, {} LU factorisations, {} periods to converge",
        r.steps, r.rhs_evaluations, r.factorizations, r.periods_to_converge
    );
}

/// Prints the number of evaluations (records, the initial one included) of a wear study.
fn print_wear_work(label: &str, model: &Model, mode: WearMode) {
    println!(
        "{label} {} evaluations (records, initial included): {}",
        mode.name(),
        wear_study(model, mode).records.len()
    );
}

/// Criterion settings for a 2-core machine: 10 samples, short warm-up and measurement.
/// Criterion stretches the measurement time by itself when 10 samples do not fit.
fn quick() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

fn stiffness(c: &mut Criterion) {
    let case = Case::default();
    let pair = GearPair::from_case(&case.gear).expect("paper's pair");
    let elastic = ElasticPair::from_case(&case.materials);
    let points = case.stiffness.table_points_per_mesh_period as usize;
    let mut g = c.benchmark_group("stiffness");
    g.bench_function("mesh_table_400_fillet", |b| {
        b.iter(|| MeshStiffness::new(black_box(&pair), &elastic, points, true).expect("valid pair"))
    });
    g.finish();
}

fn evaluation(c: &mut Criterion) {
    let model = model_with(|_| {});
    let wear = WearState::new(model.grid.len());
    let none = ExternalError::none();
    let mut g = c.benchmark_group("evaluation");
    let mut printed = false;
    g.bench_function("steady_state_dynamic", |b| {
        once(&mut printed, || {
            print_steady_work("evaluation/steady_state_dynamic", &model, &wear)
        });
        b.iter(|| {
            model
                .dynamic(black_box(&wear), &none)
                .expect("steady state")
        })
    });
    // The paper's own contact model (perfect involutes meeting on the nominal path only)
    // beside the default extended contact: issue 32 allows the corner contact at most 1.3
    // times the nominal path's cold steady state.
    let nominal = model_with(|c| c.contact.path = ContactPathModel::Nominal);
    let mut printed = false;
    g.bench_function("steady_state_dynamic_nominal_path", |b| {
        once(&mut printed, || {
            print_steady_work(
                "evaluation/steady_state_dynamic_nominal_path",
                &nominal,
                &wear,
            )
        });
        b.iter(|| {
            nominal
                .dynamic(black_box(&wear), &none)
                .expect("steady state")
        })
    });
    g.bench_function("quasi_static", |b| {
        b.iter(|| model.quasi_static(black_box(&wear), &none))
    });
    // Warm start from the periodic state of the same case (a wear update or continuation
    // step starts from a neighbouring one).
    let start = model.dynamic(&wear, &none).expect("steady state").end_state;
    g.bench_function("steady_state_dynamic_warm", |b| {
        b.iter(|| {
            model
                .dynamic_from(black_box(&wear), &none, Some(&start))
                .expect("steady state")
        })
    });
    // Low speed (error-controlled steps in the boundary layers after each mesh event) and
    // the contact-loss resonance of the brake-imposed boundary (contact switches located
    // as events, slow convergence of the search).
    for (name, sets) in [
        (
            "steady_state_dynamic_2hz",
            vec!["operating.input_speed_hz=2"],
        ),
        (
            "steady_state_dynamic_contact_loss_50hz",
            vec![
                "operating.input_speed_hz=50",
                "operating.speed_boundary=brake_speed_imposed",
            ],
        ),
    ] {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        let case = gearwear::config::load_case("", &sets).expect("valid case");
        let m = Model::from_case(&case).expect("valid model");
        let mut printed = false;
        g.bench_function(name, |b| {
            once(&mut printed, || {
                print_steady_work(&format!("evaluation/{name}"), &m, &wear)
            });
            b.iter(|| m.dynamic(black_box(&wear), &none).expect("steady state"))
        });
    }
    g.finish();
}

fn wear_studies(c: &mut Criterion) {
    let model = model_with(|_| {});
    let mut g = c.benchmark_group("wear_study");
    g.sampling_mode(SamplingMode::Flat);
    for (name, mode) in [
        ("dynamic_4e4", WearMode::Dynamic),
        ("quasi_static_4e4", WearMode::QuasiStatic),
    ] {
        let mut printed = false;
        g.bench_function(name, |b| {
            once(&mut printed, || print_wear_work("wear_study", &model, mode));
            b.iter(|| wear_study(black_box(&model), mode))
        });
    }
    // What `gearwear wear` computes (sequentially here, no output files): build the model,
    // then both studies.
    g.bench_function("model_and_both_modes_4e4", |b| {
        b.iter(|| {
            let m = model_with(|_| {});
            (
                wear_study(&m, WearMode::Dynamic),
                wear_study(&m, WearMode::QuasiStatic),
            )
        })
    });
    g.finish();
}

fn scaling_steps(c: &mut Criterion) {
    let mut g = c.benchmark_group("scaling_steps_per_mesh_period");
    for steps in [100_i64, 200, 400] {
        let model = model_with(|c| c.numerics.steps_per_mesh_period = steps);
        let wear = WearState::new(model.grid.len());
        let none = ExternalError::none();
        let label = format!("scaling_steps_per_mesh_period/{steps}");
        let mut printed = false;
        g.bench_with_input(BenchmarkId::from_parameter(steps), &model, |b, m| {
            once(&mut printed, || print_steady_work(&label, m, &wear));
            b.iter(|| m.dynamic(black_box(&wear), &none).expect("steady state"))
        });
    }
    g.finish();
}

/// Dynamic wear study with one wear-section setting changed; prints the number of
/// evaluations (the cost driver) before timing.
fn scaling_wear<T: Copy + std::fmt::Display>(
    c: &mut Criterion,
    name: &str,
    values: &[T],
    edit: impl Fn(&mut Case, T),
) {
    let mut g = c.benchmark_group(name);
    g.sampling_mode(SamplingMode::Flat);
    for &v in values {
        let model = model_with(|c| edit(c, v));
        let label = format!("{name}/{v}");
        let mut printed = false;
        g.bench_with_input(BenchmarkId::from_parameter(v), &model, |b, m| {
            once(&mut printed, || {
                print_wear_work(&label, m, WearMode::Dynamic)
            });
            b.iter(|| wear_study(black_box(m), WearMode::Dynamic))
        });
    }
    g.finish();
}

fn scaling_points(c: &mut Criterion) {
    scaling_wear(
        c,
        "scaling_points_per_profile",
        &[51_i64, 101, 201],
        |c, v| c.wear.points_per_profile = v,
    );
}

fn scaling_cycles(c: &mut Criterion) {
    scaling_wear(c, "scaling_total_cycles", &[1e4, 2e4, 4e4, 8e4], |c, v| {
        c.wear.total_cycles = v
    });
}

/// The two-stage reducer of the examples: one steady state from the static equilibrium
/// (its base period is one turn of the intermediate shaft, 31 and 23 mesh periods).
fn train(c: &mut Criterion) {
    let text = include_str!("../examples/two_stage_reducer.toml");
    let case = gearwear::config::load_case(text, &[]).expect("the example is valid");
    let model = Model::from_case(&case).expect("the example assembles");
    let wear = WearState::new(model.grid.len());
    let none = ExternalError::none();
    let mut g = c.benchmark_group("train");
    let mut printed = false;
    g.bench_function("two_stage_steady_state", |b| {
        once(&mut printed, || {
            print_steady_work("train/two_stage_steady_state", &model, &wear)
        });
        b.iter(|| {
            model
                .dynamic(black_box(&wear), &none)
                .expect("steady state")
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = quick();
    targets = stiffness, evaluation, wear_studies, scaling_steps, scaling_points, scaling_cycles, train
}
criterion_main!(benches);
