//! The dataset design parser under random TOML-ish text (issue 33's fuzz target for the
//! design file, as a property test: cargo-fuzz needs a nightly toolchain, the target
//! itself is fuzz/fuzz_targets/dataset_design.rs): never a panic; a design it accepts
//! has finite axes in their ranges, a record count within 2^53, and finite budget and
//! trajectory-size estimates.

use gearwear::io::input::InputError;
use gearwear::study::budget::{estimate_dataset, trajectory_bytes, RecordSize};
use gearwear::study::dataset::design::MAX_RECORDS;
use gearwear::study::dataset::plan::{plan_of, Shard};
use gearwear::study::dataset::{parse_design, StateChoice};
use proptest::prelude::*;

const SECTIONS: [&str; 8] = [
    "",
    "[run_to_failure]",
    "[operating]",
    "[records]",
    "[[condition]]",
    "[condition.case]",
    "[condition.case.operating]",
    "[condition.case.wear]",
];

const KEYS: [&str; 20] = [
    "seed",
    "states",
    "cycles",
    "max_cycles",
    "wear_limit_um",
    "input_speed_hz",
    "load_torque_nm",
    "noise_realisations",
    "disk_budget_gib",
    "csv",
    "name",
    "fault",
    "severity",
    "set",
    "case",
    "transfer_path",
    "block_cycles",
    "total_cycles",
    "x",
    "states.x",
];

fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<i64>().prop_map(|i| i.to_string()),
        any::<f64>().prop_map(|x| format!("{x:e}")),
        (-20i32..20).prop_map(|e| format!("1e{e}")),
        Just("nan".to_owned()),
        Just("inf".to_owned()),
        Just("-inf".to_owned()),
        Just("18446744073709551615".to_owned()),
        Just("true".to_owned()),
        "[a-z_ ]{0,8}".prop_map(|s| format!("\"{s}\"")),
        prop::collection::vec(-1e4..1e4f64, 0..6).prop_map(|v| format!("{v:?}")),
        Just("[\"signals.ramp_end_speed_hz=60\"]".to_owned()),
        Just("{}".to_owned()),
        "[ -~]{0,12}",
    ]
}

fn design_text() -> impl Strategy<Value = String> {
    let line =
        (0..SECTIONS.len(), 0..KEYS.len(), value(), any::<bool>()).prop_map(|(s, k, v, header)| {
            if header {
                format!("{}\n{} = {v}\n", SECTIONS[s], KEYS[k])
            } else {
                format!("{} = {v}\n", KEYS[k])
            }
        });
    prop_oneof![
        prop::collection::vec(line, 0..10).prop_map(|l| l.concat()),
        "[ -~\n]{0,200}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn the_design_parser_never_panics_and_what_it_accepts_is_bounded(
        text in design_text(),
        case_text in prop_oneof![Just(String::new()), "[ -~\n]{0,60}"],
    ) {
        let read = |_: &str| -> Result<String, InputError> { Ok(case_text.clone()) };
        if let Ok(d) = parse_design(&text, "design.toml", &read) {
            let plan = plan_of(&d);
            let records = [plan.conditions, plan.states, plan.speeds, plan.loads, plan.realisations]
                .iter()
                .try_fold(1u64, |a, n| a.checked_mul(*n as u64));
            prop_assert!(records.is_some_and(|r| r <= MAX_RECORDS), "{text}");
            prop_assert!((1.0..=1e11).contains(&d.max_cycles));
            prop_assert!(d.wear_limit_um > 0.0 && d.wear_limit_um <= 1000.0);
            prop_assert!(d.speeds_hz.iter().chain(&d.torques_nm).all(|x| x.is_finite() && *x > 0.0));
            if let StateChoice::Cycles(c) = &d.states {
                prop_assert!(c.iter().all(|x| x.is_finite() && *x >= 0.0));
            }
            prop_assert!(d.conditions.iter().all(|c| c.severity.is_finite()));
            for c in &d.conditions {
                prop_assert!(trajectory_bytes(&c.case, d.max_cycles).is_finite());
            }
            let e = estimate_dataset(&d, Shard { index: 1, count: 1 }, 2, RecordSize { samples: 1e4, channels: 1.0 });
            prop_assert!(e.seconds().is_finite() && e.memory_bytes().is_finite());
        }
    }
}
