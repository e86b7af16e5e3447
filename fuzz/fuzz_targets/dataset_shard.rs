//! Fuzz target: a shard's description (`state/dataset.json`; arbitrary bytes) read as
//! `dataset-merge` reads each input's (`app::dataset::merge::check_description`: its
//! record count against its axes, its key recomputed from its design, cases and
//! transfer-path hash), and as a run reads the description of the folder it writes into
//! (`folder::described_key`, `owner_problem`). A description the merge accepts (mutations
//! outside the key's fields keep the key) is then used as the merge uses it: the real
//! sidecars of both seed datasets indexed under it (`index_tables`: identity of each
//! record recomputed from the description's axes, sampling rate and unit from its
//! `record`), with the trends table and figure. The trajectories' recomputation by the
//! wear law (a model per input) is left out.
//! Seeds: fuzz/seeds/dataset_shard (the two real datasets of `dataset_common`).
//! Run: FUZZ_TARGET=dataset_shard scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

mod dataset_common;

use dataset_common::{index_and_trends, real_sidecars};
use gearwear::app::dataset::folder::{described_key, owner_problem};
use gearwear::app::dataset::merge::check_description;
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    // As the folder a run writes into: its key shown in the refusal of another design.
    if let Ok(k) = described_key(data, Path::new("out/state/dataset.json")) {
        let _ = owner_problem(Path::new("out"), &k, "b328ae0c93398756138ba2b36c439a86");
    }
    let Ok((key, total)) = check_description(Path::new("shard"), Some(data)) else {
        return;
    };
    let body: serde_json::Value = serde_json::from_slice(data).expect("checked as JSON");
    assert_eq!(body["dataset_key"].as_str(), Some(key.as_str()));
    index_and_trends(real_sidecars().to_vec(), &body, total);
});
