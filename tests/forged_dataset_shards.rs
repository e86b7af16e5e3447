//! A forged dataset shard (the predict-merge finding of issue 22, in `dataset-merge`): a
//! real dataset whose `state/dataset.json` is edited to claim 2e9 records. The merge once
//! sized the index's list of missing records by that claim and aborted on allocation. It
//! must refuse a count its own axes do not give, at once and naming the file; a forgery
//! that makes the axes agree (2e9 noise realisations) is merged in bounded memory (the
//! missing records counted, at most 1000 listed); nothing outside the output changes.
#![cfg(target_os = "linux")]

mod common;

use common::{
    assert_refused_touching_nothing, gearwear_within_address_space, ok, snapshot, stderr,
};
use std::path::Path;

/// Address space of the merge, bytes: a merge of a few records runs in tens of MB
/// (measured 6 MB resident for the refusal); a list of 2e9 8-byte ids needs 16 GB.
const ADDRESS_SPACE_BYTES: u64 = 512 << 20;

/// One condition, two states, one speed, one noise realisation: the cheapest dataset.
const DESIGN: &str =
    "seed = 3\n[run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 10\n\
[operating]\ninput_speed_hz = [30]\n[records]\nnoise_realisations = 1\n";

fn edit(root: &Path, f: impl Fn(&mut serde_json::Value)) {
    let p = root.join("state/dataset.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap();
    f(&mut v);
    std::fs::write(&p, serde_json::to_string(&v).unwrap()).unwrap();
}

/// A new temporary folder holding the dataset of [`DESIGN`] in `ds`.
fn real_dataset() -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
    std::fs::write(d.path().join("design.toml"), DESIGN).unwrap();
    ok(&[
        "dataset",
        "-q",
        "--design",
        &p("design.toml"),
        "--out",
        &p("ds"),
    ]);
    d
}

#[test]
fn a_dataset_shard_claiming_2e9_records_is_refused_or_merged_in_bounded_memory() {
    let d = real_dataset();
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();

    // The count alone edited: refused, naming the file, nothing written.
    edit(&d.path().join("ds"), |v| {
        v["records"] = 2_000_000_000_u64.into()
    });
    let before = snapshot(d.path());
    let r = gearwear_within_address_space(
        &["dataset-merge", &p("ds"), "--out", &p("merged")],
        ADDRESS_SPACE_BYTES,
    );
    assert_refused_touching_nothing(
        &r,
        &["state/dataset.json", "2000000000 records", "axes"],
        d.path(),
        &d.path().join("merged"),
        &before,
    );

    // Count and axes forged to agree (1 x 2 x 1 x 1 x 1e9 = 2e9): merged within the
    // address-space limit; the missing records counted exactly, 1000 listed.
    edit(&d.path().join("ds"), |v| {
        v["axes"]["noise_realisations"] = 1_000_000_000_u64.into();
    });
    let before = snapshot(&d.path().join("ds"));
    let r = gearwear_within_address_space(
        &["dataset-merge", "-q", &p("ds"), "--out", &p("merged")],
        ADDRESS_SPACE_BYTES,
    );
    assert!(r.status.success(), "{}", stderr(&r));
    let m: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(d.path().join("merged/metadata.json")).unwrap(),
    )
    .unwrap();
    // Two records were computed (states x realisations of the true design); under the
    // forged axes id 1 is (state 0, realisation 1), which its labels (state 1,
    // realisation 0) contradict: only record 0 is the forged design's and indexed
    // (issue 33: a record's identity recomputed from its id).
    assert_eq!(m["records_present"], 1);
    assert_eq!(m["records_missing_count"], 2_000_000_000_u64 - 1);
    assert_eq!(m["records_missing"].as_array().unwrap().len(), 1000);
    assert_eq!(
        snapshot(&d.path().join("ds")),
        before,
        "the input shard changed"
    );
}

/// A shard's sidecar whose indicator channels are renamed keeps every identity field the
/// design gives its id, so the merge once indexed it: both channels renamed `x` gave an
/// index with two `x_rms` columns (and no `input_rms` of that record), exit 0. A record's
/// channels are now checked against the description's sensors (`record.sensors`): the
/// record is counted missing, the index keeps the sensors' columns, each once.
#[test]
fn a_sidecar_naming_other_channels_is_counted_missing_not_indexed() {
    let d = real_dataset();
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
    let car = d.path().join("ds/records/0000000.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&car).unwrap()).unwrap();
    for c in v["labels"]["indicators"].as_array_mut().unwrap() {
        c["channel"] = "x".into();
    }
    std::fs::write(&car, serde_json::to_string_pretty(&v).unwrap()).unwrap();
    let r = common::gearwear(&["dataset-merge", "-q", &p("ds"), "--out", &p("merged")]);
    let index = std::fs::read_to_string(d.path().join("merged/index.csv"))
        .unwrap_or_else(|e| panic!("{e}: {}", stderr(&r)));
    let header: Vec<&str> = index.lines().next().unwrap().split(',').collect();
    let mut unique = header.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), header.len(), "duplicated columns: {header:?}");
    assert!(
        header.contains(&"input_rms") && !header.contains(&"x_rms"),
        "{header:?}"
    );
    let m: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(d.path().join("merged/metadata.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(m["records_missing"], serde_json::json!([0]), "{m}");
    assert_eq!(index.lines().count(), 2, "one record indexed: {index}");
}
