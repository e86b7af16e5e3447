//! A forged prediction shard (issue 22): a real shard of `predict --shard 1/2` whose JSON
//! is edited to claim 2e9 samples, its manifest's SHA-256 and size recomputed so that the
//! file looks untouched. `predict-merge` once built the list of missing sample indices
//! for every claimed sample (4 GiB). It must refuse the claim at once, naming it, and at
//! the range's end (1e7 samples, which it accepts) count the missing samples instead of
//! listing them, in bounded memory; nothing outside its output folder changes.
#![cfg(target_os = "linux")]

mod common;

use common::{snapshot, stderr};
use sha2::{Digest, Sha256};
use std::path::Path;
use std::process::Output;

/// Address space the merge may use, bytes. A merge of a few dozen samples needs tens of
/// MB (measured: under 14 MB resident, and it runs within a 256 MiB address space); a
/// list of 2e9 (or 1e7 x 8-byte) indices alone would need 16 GB (80 MB), so an
/// allocation per claimed sample fails here instead of passing unnoticed.
const ADDRESS_SPACE_BYTES: u64 = 512 << 20;

/// `gearwear args` under the address-space limit.
fn bounded(args: &[&str]) -> Output {
    common::gearwear_within_address_space(args, ADDRESS_SPACE_BYTES)
}

/// Rewrites the shard to claim `samples` and recomputes its manifest entry, as a forger
/// who knows the format would.
fn forge(shards: &Path, samples: u64) {
    let shard = shards.join("predict_shard_1_of_2.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&shard).unwrap()).unwrap();
    v["identity"]["settings"]["samples"] = samples.into();
    let text = serde_json::to_string_pretty(&v).unwrap();
    std::fs::write(&shard, &text).unwrap();
    let man = shards.join("predict_shard_1_of_2.manifest.json");
    let mut m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&man).unwrap()).unwrap();
    let entry = m["files"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|f| f["path"] == "predict_shard_1_of_2.json")
        .expect("the manifest lists the shard");
    entry["sha256"] = format!("{:x}", Sha256::digest(text.as_bytes())).into();
    entry["bytes"] = text.len().into();
    std::fs::write(&man, serde_json::to_string_pretty(&m).unwrap()).unwrap();
}

#[test]
fn a_shard_forged_to_claim_2e9_samples_is_refused_at_once_and_touches_nothing() {
    let d = tempfile::tempdir().unwrap();
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
    // A cheap case (the merge is under test, not the physics): prior samples, surrogate.
    std::fs::write(
        d.path().join("case.toml"),
        "[numerics]\nsteps_per_mesh_period = 60\nevaluated_mesh_periods = 2\n\
         [wear]\npoints_per_profile = 31\n",
    )
    .unwrap();
    let o = common::gearwear(&[
        "predict",
        "-q",
        "--config",
        &p("case.toml"),
        "--limit-um",
        "2.5",
        "--cycles",
        "4e4",
        "--seed",
        "7",
        "--samples",
        "40",
        "--grid-points",
        "11",
        "--check-runs",
        "0",
        "--shard",
        "1/2",
        "--out",
        &p("shards"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));

    forge(&d.path().join("shards"), 2_000_000_000);
    let before = snapshot(d.path());
    let r = bounded(&["predict-merge", &p("shards"), "--out", &p("merged")]);
    common::assert_refused_touching_nothing(
        &r,
        &["predict_shard_1_of_2.json", "samples = 2e9", "[1, 1e7]"],
        d.path(),
        &d.path().join("merged"),
        &before,
    );

    // At the range's end the claim is accepted by the range but not by the budget (it
    // is estimated from the claimed samples), and with the budget dropped the merge
    // counts the missing samples and lists at most 100, within the address-space limit.
    forge(&d.path().join("shards"), 10_000_000);
    let e = stderr(&bounded(&[
        "predict-merge",
        &p("shards"),
        "--out",
        &p("merged"),
    ]));
    assert!(
        e.contains("over its budget") && e.contains("the shards' samples"),
        "{e}"
    );
    let before = snapshot(d.path());
    let r = bounded(&[
        "--no-budget",
        "predict-merge",
        &p("shards"),
        "--out",
        &p("merged"),
    ]);
    let e = stderr(&r);
    assert!(r.status.success(), "{e}");
    assert!(e.contains("9999980 of 10000000 samples missing"), "{e}");
    let s: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(d.path().join("merged/summary.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(s["missing_samples"]["count"], 9_999_980);
    let first = s["missing_samples"]["first"].as_array().unwrap();
    assert_eq!(first.len(), 100);
    // Shard 1 of 2 holds the even indices: the missing ones begin 1, 3, 5.
    assert_eq!(first[..3], [1, 3, 5]);
    let after = snapshot(d.path());
    for (path, bytes) in &before {
        assert_eq!(after.get(path), Some(bytes), "{} changed", path.display());
    }
}
