//! Benchmarks of the signal chain and the condition indicators (issue 19).
//!
//! Run: `cargo bench --bench signals`. Groups:
//! - `record`: one 1 s record of the paper's case at 25.6 kHz (generic housing, two
//!   accelerometers and the tachometer, 30 dB SNR): the bearing forces of a steady state
//!   through the transfer path and anti-alias filter (`periodic`), rendered and sampled
//!   (`render`), the whole indicator set of both channels and both shafts (`indicators`),
//!   and end to end from the wear state (`steady_record`, steady state included);
//! - `dataset_state`: one physical state of a dataset with 10 noise realisations (its
//!   steady state, the noise-free record once, 10 noisy records with their indicators),
//!   a hundredth of the 1000-record target (< 60 s on 2 cores);
//! - `runup`: a 10 s run-up from 5 to 60 Hz input as one transient, noise-free record
//!   (target < 10 s).

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use gearwear::config::case::Case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::signals::analysis::analyse;
use gearwear::signals::record::add_noise;
use gearwear::signals::setup::{chain_of, ChainSetup};
use gearwear::study::dataset::plan::StateIndex;
use gearwear::study::dataset::records::{state_records, StateInputs};
use gearwear::study::dataset::trajectory::run_trajectory;
use gearwear::study::dataset::{Condition, Plan};
use gearwear::study::signal_record::{kinematics, periodic_record, steady_record};
use gearwear::study::transient_signals::transient_clean_record;
use gearwear::study::Model;

fn setup_of(case: &Case) -> ChainSetup {
    chain_of(case, None, case.signals.max_input_speed_hz(case)).expect("valid chain")
}

fn record(c: &mut Criterion) {
    let mut case = Case::default();
    case.signals.snr_db = Some(30.0);
    let model = Model::from_case(&case).unwrap();
    let setup = setup_of(&case);
    let wear = model.new_wear_state();
    let r = model.dynamic(&wear, &ExternalError::none()).unwrap();
    let kin = kinematics(&model);
    let chain = &setup.chain;
    let n = chain.samples(kin.shaft_hz(chain.tachometer.shaft));
    let p = periodic_record(&model, &setup, &r);
    let mut rec = p.render(chain, n);
    add_noise(&mut rec, chain);
    println!(
        "record: {} samples x {} channels + tachometer at {} Hz",
        rec.len(),
        rec.channels.len(),
        rec.sampling_rate_hz
    );
    let mut g = c.benchmark_group("record");
    g.sample_size(10);
    g.bench_function("periodic", |b| {
        b.iter(|| black_box(periodic_record(&model, &setup, &r)))
    });
    g.bench_function("render", |b| {
        b.iter(|| {
            let mut x = p.render(chain, n);
            add_noise(&mut x, chain);
            black_box(x)
        })
    });
    g.bench_function("indicators", |b| {
        b.iter(|| black_box(analyse(&rec, &kin, &chain.tachometer, setup.components)))
    });
    g.bench_function("steady_record", |b| {
        b.iter(|| black_box(steady_record(&model, &setup, &wear, &ExternalError::none()).unwrap()))
    });
    g.finish();
}

fn dataset_state(c: &mut Criterion) {
    let mut case = Case::default();
    case.signals.snr_db = Some(30.0);
    let model = Model::from_case(&case).unwrap();
    let setup = setup_of(&case);
    // A trajectory to 4e4 cycles (no limit reached); the state at 2e4 cycles.
    let trajectory = run_trajectory(&model, 4e4, 1.0).unwrap();
    let condition = Condition {
        name: "healthy".into(),
        fault: "none".into(),
        severity: 0.0,
        case: case.clone(),
    };
    let plan = Plan {
        conditions: 1,
        states: 1,
        speeds: 1,
        loads: 1,
        realisations: 10,
    };
    let inputs = StateInputs {
        model: &model,
        setup: &setup,
        condition: &condition,
        trajectory: &trajectory,
        cycles: 2e4,
        wear_limit_um: 1e6,
        design_seed: 1,
    };
    let index = StateIndex {
        condition: 0,
        state: 0,
        speed: 0,
        load: 0,
    };
    let state = || {
        let mut kept = 0usize;
        state_records(&inputs, &plan, 0, index, &mut |labels, rec| {
            kept += rec.len() + labels.indicators.len();
            Ok(())
        })
        .unwrap();
        kept
    };
    let mut g = c.benchmark_group("dataset_state");
    g.sampling_mode(SamplingMode::Flat).sample_size(10);
    g.bench_function("one_state_10_records", |b| b.iter(|| black_box(state())));
    g.finish();
}

fn runup(c: &mut Criterion) {
    let mut case = Case::default();
    case.operating.input_speed_hz = 5.0;
    case.signals.ramp_end_speed_hz = Some(60.0);
    case.signals.record_length = 10.0;
    let model = Model::from_case(&case).unwrap();
    let setup = setup_of(&case);
    let wear = model.new_wear_state();
    let mut g = c.benchmark_group("runup");
    g.sampling_mode(SamplingMode::Flat)
        .sample_size(10)
        .measurement_time(Duration::from_secs(30));
    g.bench_function("runup_10s_5_to_60hz", |b| {
        b.iter(|| black_box(transient_clean_record(&model, &setup, &wear).unwrap()))
    });
    g.finish();
}

criterion_group!(benches, record, dataset_state, runup);
criterion_main!(benches);
