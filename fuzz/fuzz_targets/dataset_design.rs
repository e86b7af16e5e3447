//! Fuzz target over a dataset design file: the text (and the text of the case file it
//! names, after a NUL) parsed and validated; a design it accepts must number at most
//! 2^53 records and give finite budget and trajectory-size estimates.
//! Run: scripts/fuzz.sh (docs/RELIABILITY.md). Without a nightly toolchain the same
//! property runs as tests/dataset_design_props.rs.

#![no_main]

use gearwear::study::budget::{estimate_dataset, trajectory_bytes, RecordSize};
use gearwear::study::dataset::design::MAX_RECORDS;
use gearwear::io::input::InputError;
use gearwear::study::dataset::parse_design;
use gearwear::study::dataset::plan::{plan_of, Shard};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let mut chunks = text.splitn(2, '\0');
    let design = chunks.next().unwrap_or("").to_owned();
    let case = chunks.next().unwrap_or("").to_owned();
    let read = |_: &str| -> Result<String, InputError> { Ok(case.clone()) };
    if let Ok(d) = parse_design(&design, "design.toml", &read) {
        assert!(plan_of(&d).records() as u64 <= MAX_RECORDS);
        for c in &d.conditions {
            assert!(trajectory_bytes(&c.case, d.max_cycles).is_finite());
        }
        let e = estimate_dataset(
            &d,
            Shard { index: 1, count: 1 },
            2,
            RecordSize {
                samples: 1e4,
                channels: 1.0,
            },
        );
        assert!(e.seconds().is_finite() && e.memory_bytes().is_finite());
    }
});
