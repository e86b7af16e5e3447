//! The run budget's count of a steady record's harmonics (`study::budget::signals::
//! record_harmonics`, read from the case alone before any model is built) against the
//! harmonics the record itself synthesises (`signals::record::PeriodicRecord`): the
//! budget's time and memory for a record are proportional to these counts, which grow as
//! the speed falls (a 0.05 Hz record at 25.6 kHz has 2e6 tachometer harmonics), so an
//! undercount would let a slow record past the budget and exhaust the memory.

use gearwear::config::{load_case, Case};
use gearwear::dynamics::excitation::ExternalError;
use gearwear::signals::setup::chain_of;
use gearwear::study::budget::signals::record_harmonics;
use gearwear::study::signal_record::periodic_record;
use gearwear::study::Model;
use gearwear::wear::WearState;

/// The record's own counts: harmonics 0..=K of the response (every input has them) and
/// of the tachometer's pulse train.
fn synthesised(case: &Case) -> (usize, usize) {
    let model = Model::from_case(case).unwrap();
    let setup = chain_of(case, None, case.operating.input_speed_hz).unwrap();
    let r = model
        .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
        .unwrap();
    let p = periodic_record(&model, &setup, &r);
    let response = p.inputs[0].coefficients.len();
    assert!(p.inputs.iter().all(|i| i.coefficients.len() == response));
    (response, p.tachometer.coefficients.len())
}

fn check(case: &Case, what: &str) {
    let counted = record_harmonics(case).expect("countable periods");
    let (response, tachometer) = synthesised(case);
    // The record keeps harmonics 0..=floor(top T) (the response; the tachometer's pulse
    // train floor(top T_p) + 1 of them): the count top T is within one of the length.
    // The periods are exact rationals of the teeth and the speed, so no other slack.
    for (name, c, n) in [
        ("response", counted.response, response),
        ("tachometer", counted.tachometer, tachometer),
    ] {
        assert!(
            (c - n as f64).abs() <= 1.0 + 1e-9 * c,
            "{what}: {name} harmonics counted {c}, synthesised {n}"
        );
    }
}

fn case(sets: &[&str]) -> Case {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    load_case("", &sets).unwrap()
}

#[test]
fn the_budget_counts_a_slow_records_harmonics() {
    // 0.5 Hz: 1 mesh period of 0.105 s and a 2 s revolution at 204.8 kHz internal.
    check(&case(&["operating.input_speed_hz=0.5"]), "0.5 Hz");
    check(
        &case(&[
            "operating.input_speed_hz=2",
            "signals.tachometer_shaft=\"gear\"",
            "signals.tachometer_pulses_per_revolution=10",
            "signals.sampling_rate_hz=51200",
        ]),
        "2 Hz, gear shaft, 10 pulses, 51.2 kHz",
    );
}

#[test]
fn the_budget_counts_a_tooth_resolved_records_period() {
    // Every tooth drawn: the response repeats over 19 x 31 = 589 mesh periods.
    check(
        &case(&["teeth.accuracy_grade=5", "signals.record_length=0.1"]),
        "ISO grade 5",
    );
}

#[test]
fn the_budget_counts_a_trains_base_period_and_sensor_shaft() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/two_stage_reducer.toml"
    ))
    .unwrap();
    for sets in [
        vec![
            "signals.sensor_stage=2",
            "signals.tachometer_shaft=\"gear\"",
        ],
        vec!["signals.sensor_stage=1"],
    ] {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        let c = load_case(&text, &sets).unwrap();
        check(&c, &format!("two-stage train {sets:?}"));
    }
}
