//! Fuzz target: a posterior samples file for `gearwear predict` (arbitrary bytes as CSV).
//! It must parse or be refused with messages, never panic; every parameter read must lie
//! in its documented range (`prognostics::samples::RANGES`), and the span a surrogate
//! would cover must be a valid prior.
//! Run: scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

use gearwear::prognostics::samples::{read_samples, MAX_ROWS, RANGES};
use gearwear::prognostics::Prior;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let Ok(rows) = read_samples(&text, "posterior.csv", [2.5e-16, 1.0, 60.0]) else {
        return;
    };
    assert!(!rows.is_empty() && rows.len() <= MAX_ROWS);
    for t in &rows {
        for (i, (lo, hi)) in RANGES.iter().enumerate() {
            assert!((*lo..=*hi).contains(&t[i]), "parameter {i} = {}", t[i]);
        }
    }
    let span = Prior::spanning(&rows);
    for p in &span.params {
        assert!(p.lo > 0.0 && p.lo <= p.hi && p.hi.is_finite());
    }
});
