//! Fuzz target: a wear checkpoint (arbitrary bytes as `checkpoint_dynamic.jsonl`). It is
//! parsed under the case hash its own header names (so mutations reach the records), and
//! what parses is checked against the built-in case's model (`study::wear_check`): never
//! a panic. The recomputation of updates on resume is left out (milliseconds per input).
//! Seeds: fuzz/seeds/checkpoint (a real run's checkpoint).
//! Run: scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

use gearwear::config::Case;
use gearwear::store::checkpoint::parse_checkpoint;
use gearwear::study::wear_check::check_wear_run;
use gearwear::study::wear_loop::WearMode;
use gearwear::study::Model;
use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

fn model() -> &'static Model {
    static M: OnceLock<Model> = OnceLock::new();
    M.get_or_init(|| Model::from_case(&Case::default()).expect("the built-in case"))
}

/// The case hash a checkpoint's header names, if it has one.
fn header_hash(data: &[u8]) -> Option<String> {
    let line = data.split(|b| *b == b'\n').next()?;
    let (_, json) = std::str::from_utf8(line).ok()?.split_once(' ')?;
    let v: serde_json::Value = serde_json::from_str(json).ok()?;
    v["case_sha256"].as_str().map(str::to_owned)
}

fuzz_target!(|data: &[u8]| {
    if data.len() > 1 << 20 {
        return;
    }
    let hash = header_hash(data).unwrap_or_default();
    for mode in [WearMode::Dynamic, WearMode::QuasiStatic] {
        if let Ok(run) = parse_checkpoint(data, "checkpoint", mode, &hash) {
            let _ = check_wear_run(&run, model());
        }
    }
});
