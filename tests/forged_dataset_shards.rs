//! A forged dataset shard (the predict-merge finding of issue 22, in `dataset-merge`): a
//! real dataset whose `state/dataset.json` is edited to claim 2e9 records. The merge once
//! sized the index's list of missing records by that claim and aborted on allocation. It
//! must refuse a count its own axes do not give, at once and naming the file; a forgery
//! that makes the axes agree (2e9 noise realisations) is refused too, its description
//! recomputed from its design (issue 33), in bounded memory; nothing outside the output
//! changes. Forged records (a label, an indicator, another record's signal) are refused
//! by the merge's recomputation of the resume's sample.
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
    dataset_of(DESIGN, &[])
}

/// A new temporary folder holding `files` (name, text) and the dataset of `design`
/// (written as `design.toml` beside them) in `ds`.
fn dataset_of(design: &str, files: &[(&str, &str)]) -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
    for (name, text) in files {
        std::fs::write(d.path().join(name), text).unwrap();
    }
    std::fs::write(d.path().join("design.toml"), design).unwrap();
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
fn a_dataset_shard_claiming_2e9_records_is_refused_in_bounded_memory() {
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

    // Count and axes forged to agree (1 x 2 x 1 x 1 x 1e9 = 2e9): the description is
    // recomputed from its own design (issue 33: metadata from the design, never from an
    // input), which gives 1 realisation: refused within the address-space limit, naming
    // the file, nothing written (it was once merged with 2e9 - 1 records missing).
    edit(&d.path().join("ds"), |v| {
        v["axes"]["noise_realisations"] = 1_000_000_000_u64.into();
    });
    let before = snapshot(d.path());
    let r = gearwear_within_address_space(
        &["dataset-merge", "-q", &p("ds"), "--out", &p("merged")],
        ADDRESS_SPACE_BYTES,
    );
    assert_refused_touching_nothing(
        &r,
        &[
            "state/dataset.json",
            "not the description its own design gives",
        ],
        d.path(),
        &d.path().join("merged"),
        &before,
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

/// SHA-256 of `bytes` as lower-case hex (as a sidecar names its signal), computed here by
/// `sha256sum` so the forgery does not lean on the program's own checksum code.
fn sha256_hex(path: &Path) -> String {
    let out = std::process::Command::new("sha256sum")
        .arg(path)
        .output()
        .unwrap();
    String::from_utf8(out.stdout).unwrap()[..64].to_owned()
}

/// Edit record `id`'s sidecar in the shard `ds` with `f` (its signal checksum left as it
/// is, or set by `f`: the sidecar carries no other checksum a forger would recompute).
fn edit_sidecar(ds: &Path, id: usize, f: impl Fn(&mut serde_json::Value)) {
    let car = ds.join(format!("records/{id:07}.json"));
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&car).unwrap()).unwrap();
    f(&mut v);
    std::fs::write(&car, serde_json::to_string_pretty(&v).unwrap()).unwrap();
}

/// Issue 33: a shard's sidecar edited in a field its identity does not cover (max wear
/// 99 um, an RMS of 1e308, the remaining cycles) was merged with exit 0 as written. The
/// merge now recomputes the sample of the resume's rule (here every record: 2 states of at
/// most 8) and compares it bit for bit: refused, naming the shard, the record and the
/// field, before the target exists.
/// `dataset-merge ds --out merged` in `d` (with `extra` arguments): refused with exit 2,
/// the message holding every one of `needles`, `merged` never created, nothing changed.
fn refused_merge(d: &Path, extra: &[&str], needles: &[&str]) {
    let p = |s: &str| d.join(s).to_str().unwrap().to_owned();
    let before = snapshot(d);
    let (ds, merged) = (p("ds"), p("merged"));
    let mut args = vec!["dataset-merge", ds.as_str(), "--out", merged.as_str()];
    args.extend(extra);
    let r = common::gearwear(&args);
    assert_refused_touching_nothing(&r, needles, d, &d.join("merged"), &before);
}

#[test]
fn a_shard_with_an_edited_label_or_indicator_is_refused_before_the_target_is_opened() {
    type Edit = fn(&mut serde_json::Value);
    let edits: [(Edit, &str); 3] = [
        (
            |v| v["labels"]["max_wear_pinion_um"] = 99.0.into(),
            "labels.max_wear_pinion_um",
        ),
        (
            |v| v["labels"]["indicators"][0]["rms"] = 1e308.into(),
            "labels.indicators.0.rms",
        ),
        (
            |v| v["labels"]["remaining_cycles"] = 1.0.into(),
            "labels.remaining_cycles",
        ),
    ];
    for (forge, field) in edits {
        let d = real_dataset();
        let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
        edit_sidecar(&d.path().join("ds"), 1, forge);
        refused_merge(d.path(), &[], &[&p("ds"), "record 1 ", field, "not merged"]);
    }
}

/// Issue 33: another record's signal put in place of record 0's, with its SHA-256 put in
/// the sidecar, was kept by a resume once and merged. Refused, naming the record and the
/// signal; the target not created.
#[test]
fn a_shard_with_another_records_signal_is_refused() {
    let d = real_dataset();
    let ds = d.path().join("ds");
    let (other, mine) = (
        ds.join("signals/0000001.parquet"),
        ds.join("signals/0000000.parquet"),
    );
    std::fs::copy(&other, &mine).unwrap();
    let sha = sha256_hex(&mine);
    edit_sidecar(&ds, 0, |v| v["signal_sha256"] = sha.clone().into());
    refused_merge(
        d.path(),
        &[],
        &["record 0 ", "another signal", "0000000.parquet"],
    );
}

/// The transfer path: a shard's description keeps only the file's hash, so a merge of a
/// design with a transfer-path file is given the file (`--transfer-path`, as the design's
/// `transfer_path` gives it to `dataset`); missing or another file: refused naming the
/// option, nothing written; the right file: merged.
#[test]
fn a_merge_recomputes_through_the_transfer_path_file_it_is_given() {
    let modal = |gain: f64| {
        format!("sensors = [\"a\"]\n[[mode]]\nfrequency_hz = 2100\ndamping_ratio = 0.02\ngains_per_kg = [[{gain}, 0.025, 0.005, 0.02]]\n")
    };
    let d = dataset_of(
        &format!("transfer_path = \"path.toml\"\n{DESIGN}"),
        &[
            ("path.toml", &modal(0.0075)),
            ("other.toml", &modal(0.0080)),
        ],
    );
    let p = |s: &str| d.path().join(s).to_str().unwrap().to_owned();
    refused_merge(d.path(), &[], &["as its transfer path", "path.toml"]);
    let other = p("other.toml");
    refused_merge(
        d.path(),
        &["--transfer-path", &other],
        &["other.toml", "is not the file"],
    );
    let merged = d.path().join("merged");
    let (ds, path) = (p("ds"), p("path.toml"));
    let r = common::gearwear(&[
        "dataset-merge",
        "-q",
        &ds,
        "--out",
        &p("merged"),
        "--transfer-path",
        &path,
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    assert_eq!(
        std::fs::read(merged.join("index.csv")).unwrap(),
        std::fs::read(d.path().join("ds/index.csv")).unwrap(),
        "the merge of the whole set is not its index"
    );
}
