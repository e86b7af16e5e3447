//! Fuzz target over everything a user hands gearwear as a case: the TOML text, `--set`
//! overrides and `--vary` axes are parsed and validated; a valid case within a small
//! budget is built into a model and evaluated once, cheaply (the mesh stiffness and the
//! quasi-static twin), and every number it gives must be finite.
//!
//! Input: NUL-separated chunks. The first is the case file; each further chunk is a
//! `--set` override, or, when it starts with `vary:`, a `--vary` axis.
//! Run: scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

mod common;

use gearwear::config::load::case_with;
use gearwear::config::load_case;
use gearwear::study::sweep::{parse_vary, SweepPlan};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let mut chunks = text.split('\0');
    let case_text = chunks.next().unwrap_or("");
    let mut sets = Vec::new();
    let mut axes = Vec::new();
    for c in chunks {
        match c.strip_prefix("vary:") {
            Some(v) => {
                if let Ok(a) = parse_vary(v) {
                    axes.push(a);
                }
            }
            None => sets.push(c.to_owned()),
        }
    }
    if let (Ok(plan), Ok(base)) = (SweepPlan::new(axes), load_case(case_text, &sets)) {
        // Each case of a small plan must load or be refused, never panic.
        for id in 0..plan.len().min(4) {
            let _ = case_with(&base, &plan.settings_of(id));
        }
    }
    common::check_case(case_text, &sets);
});
