//! Every kept record's labels recomputed (issue 33, "every record verified"): a resume
//! and a merge recompute the signals of at most eight physical states (a steady-state
//! solve each), but the labels of every kept record from the verified wear trajectory
//! and the design. A label forged in records no sample can reach is refused all the
//! same: with 20 states and 18 forged records, at least 12 are outside any sample, and
//! every one of the 18 must be named (by the sample's recomputation or by the labels'
//! check), on a single pair, on a merge's shard and on a gear train.

mod common;

use common::{gearwear, stderr};
use serde_json::Value;
use std::path::Path;

/// States recomputed whole by a resume or a merge (`MAX_RECOMPUTED_STATES`).
const SAMPLED: usize = 8;

/// One condition, `states` states, one speed, one noise realisation: a record per state.
fn pair_design(states: usize) -> String {
    format!(
        "seed = 3\n[run_to_failure]\nstates = {states}\nmax_cycles = 1e4\nwear_limit_um = 10\n\
         [operating]\ninput_speed_hz = [30]\n[records]\nnoise_realisations = 1\n"
    )
}

fn dataset(dir: &Path, out: &str, extra: &[&str]) -> std::process::Output {
    let p = |s: &str| dir.join(s).to_str().unwrap().to_owned();
    let mut a = vec![
        "dataset".to_owned(),
        "-q".to_owned(),
        "--design".to_owned(),
        p("design.toml"),
        "--out".to_owned(),
        p(out),
    ];
    a.extend(extra.iter().map(|s| s.to_string()));
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    gearwear(&a)
}

/// Require success of a run.
fn ok(r: &std::process::Output) {
    assert!(r.status.success(), "{}", stderr(r));
}

/// Apply `edit` to the labels of record `id`'s sidecar in `ds` (the signal and its
/// checksum untouched: only the index would carry the forgery).
fn forge(ds: &Path, id: usize, edit: &dyn Fn(&mut Value)) {
    let p = ds.join(format!("records/{id:07}.json"));
    let mut v: Value = serde_json::from_slice(&std::fs::read(&p).unwrap()).unwrap();
    edit(&mut v["labels"]);
    std::fs::write(&p, serde_json::to_vec_pretty(&v).unwrap()).unwrap();
}

fn scale(v: &mut Value, f: f64) {
    *v = (v.as_f64().unwrap() * f).into();
}

/// The dataset's own files (records, signals, trajectories, index and metadata), by
/// path, for "no record changed" (a refused run may mark the folder incomplete).
fn files(ds: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for sub in ["records", "signals", "state"] {
        for e in std::fs::read_dir(ds.join(sub)).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(ds).unwrap().to_string_lossy().into_owned();
            out.push((rel, std::fs::read(&p).unwrap()));
        }
    }
    for f in ["index.csv", "metadata.json"] {
        out.push((f.into(), std::fs::read(ds.join(f)).unwrap()));
    }
    out.sort();
    out
}

/// The refusal names every forged record's sidecar, and at least `forged - SAMPLED` of
/// them through the labels' check (those no sample recomputed).
fn assert_all_named(err: &str, ds: &Path, forged: &[usize], field: &str) {
    for id in forged {
        let name = ds.join(format!("records/{id:07}.json"));
        assert!(
            err.contains(&format!("{}: record {id}", name.display())),
            "record {id} not named:\n{err}"
        );
    }
    let by_labels = err
        .lines()
        .filter(|l| l.contains("from the design and its verified wear trajectory"))
        .filter(|l| l.contains(&format!("`{field}`")))
        .count();
    assert!(
        by_labels >= forged.len() - SAMPLED,
        "{by_labels} of {} forged records found by the labels' check:\n{err}",
        forged.len()
    );
}

#[test]
fn a_resume_refuses_a_label_forged_in_any_record() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), pair_design(20)).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    let ds = dir.path().join("ds");
    let forged: Vec<usize> = (1..19).collect();
    for &id in &forged {
        forge(&ds, id, &|l| scale(&mut l["max_wear_pinion_um"], 1.5));
    }
    let before = files(&ds);
    let r = dataset(dir.path(), "ds", &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert_all_named(&stderr(&r), &ds, &forged, "max_wear_pinion_um");
    assert!(files(&ds) == before, "a refused resume changed a record");

    // The library's verification of the folder finds every one of them as well.
    let v = gearwear::app::dataset::jobs::verify_folder(
        &gearwear::app::dataset::DesignSource::file(&dir.path().join("design.toml")).unwrap(),
        &ds,
        SAMPLED,
        11,
    )
    .unwrap();
    assert_all_named(&v.problems.join("\n"), &ds, &forged, "max_wear_pinion_um");
}

#[test]
fn a_merge_refuses_a_label_forged_in_any_record_of_a_shard() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), pair_design(40)).unwrap();
    ok(&dataset(dir.path(), "s1", &["--shard", "1/2"]));
    ok(&dataset(dir.path(), "s2", &["--shard", "2/2"]));
    // Shard 2 holds the odd states (records 1, 3, ..., 39): forge 18 of its 20.
    let s2 = dir.path().join("s2");
    let forged: Vec<usize> = (3..39).step_by(2).collect();
    for &id in &forged {
        forge(&s2, id, &|l| scale(&mut l["remaining_cycles"], 0.5));
    }
    let p = |s: &str| dir.path().join(s).to_str().unwrap().to_owned();
    let r = gearwear(&[
        "dataset-merge",
        "-q",
        &p("s1"),
        &p("s2"),
        "--out",
        &p("merged"),
    ]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert_all_named(&stderr(&r), &s2, &forged, "remaining_cycles");
    assert!(!dir.path().join("merged/index.csv").exists());
}

#[test]
fn a_resume_refuses_a_stage_label_forged_in_any_record_of_a_train() {
    let dir = tempfile::tempdir().unwrap();
    let case = format!(
        "{}/examples/two_stage_reducer.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    // Coarse grids keep the 20 train states cheap (the labels do not depend on them).
    let design = format!(
        "case = {case:?}\nseed = 5\nset = [\"numerics.steps_per_mesh_period=60\", \
         \"numerics.evaluated_mesh_periods=2\", \"stiffness.table_points_per_mesh_period=60\", \
         \"signals.record_length=0.05\"]\n[run_to_failure]\nstates = 20\nmax_cycles = 2e4\n\
         wear_limit_um = 50\n[records]\nnoise_realisations = 1\n"
    );
    std::fs::write(dir.path().join("design.toml"), design).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    let ds = dir.path().join("ds");
    let forged: Vec<usize> = (1..19).collect();
    for &id in &forged {
        forge(&ds, id, &|l| {
            scale(&mut l["stages"][1]["max_wear_gear_um"], 1.25)
        });
    }
    let r = dataset(dir.path(), "ds", &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert_all_named(&stderr(&r), &ds, &forged, "stages.1.max_wear_gear_um");
}
