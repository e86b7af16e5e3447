//! `gearwear wear --resume` on a planetary set (`[planetary]`, docs/MODEL.md 12.9): a run
//! interrupted after k updates of the whole set (killed, or its mesh logs cut as a kill
//! between two appends leaves them) resumes to the bytes of an uninterrupted run (every
//! published table, the summary, the manifest and the logs); an edited log, or another
//! case's, is refused with exit 2 saying why, even when its checksums and header were
//! rewritten to pass (the records are replayed and recomputed, not trusted).

mod common;
use common::resume::{
    cut_log, cut_then_resumed_is_unchanged, edit_update, foreign_logs_refused,
    killed_then_resumed_is_uninterrupted, refused, resuming_a_finished_run_changes_nothing, run,
    scale_at,
};
use std::path::{Path, PathBuf};

/// The default set (24 / 30 / 84, four planets, sun in at `torque` N m, ring fixed,
/// carrier out) with a wear threshold of 0.1 µm: to 2e4 input cycles, 7 updates after the
/// new teeth, each block cut by a member flank's threshold (so the replay must recompute
/// the block and the flank that cut it), about 1.5 s of CPU both modes.
fn case(dir: &Path, torque: f64) -> String {
    let p = dir.join(format!("set_{torque}.toml"));
    std::fs::write(
        &p,
        format!("[operating]\nload_torque_nm = {torque}\n[planetary]\n[wear]\ntotal_cycles = 20000\nthreshold_um = 0.1\n"),
    )
    .unwrap();
    p.to_str().unwrap().to_owned()
}

fn args(config: &str, mode: &str, out: &Path, extra: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = ["-q", "wear", "--mode", mode, "--config", config, "--out"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    a.push(out.to_str().unwrap().into());
    a.extend(extra.iter().map(|s| s.to_string()));
    a
}

#[test]
fn logs_cut_between_the_appends_of_an_update_resume_to_the_same_bytes() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let out = d.path().join("w");
    let cut = |out: &Path| {
        let limited = std::fs::read_to_string(out.join("wear_history_dynamic.csv")).unwrap();
        assert!(
            limited.lines().skip(2).any(|l| !l.ends_with(",0")),
            "no block was cut by a flank's threshold: the replay would not be tested on it"
        );
        // Dynamic: killed between the appends of update 4 (the sun meshes hold it, ring
        // mesh 1 half of it, the other ring meshes not). Quasi-static: after update 3.
        for m in 1..=4 {
            let log = |mode: &str, kind: &str| {
                out.join(format!("checkpoint_{mode}_{kind}_planet_{m}.jsonl"))
            };
            cut_log(&log("dynamic", "sun"), 5, false);
            cut_log(&log("dynamic", "ring"), 4, m == 1);
            cut_log(&log("quasi_static", "sun"), 4, false);
            cut_log(&log("quasi_static", "ring"), 4, false);
        }
    };
    cut_then_resumed_is_unchanged(&args(&config, "both", &out, &[]), &out, &cut);
}

#[test]
fn a_killed_planetary_run_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let (full, cut) = (d.path().join("full"), d.path().join("cut"));
    // Killed once the last mesh's log holds three updates.
    killed_then_resumed_is_uninterrupted(
        &|out| args(&config, "dynamic", out, &[]),
        (&full, &cut),
        "checkpoint_dynamic_ring_planet_4.partial.jsonl",
        3,
    );
}

/// Multiply the number at `key` (a JSON pointer) of update `at` of the log `path` by `f`
/// (when `key` names an array, its largest element: a point where the profile has worn),
/// with a fresh checksum when `rehash`.
fn scale(path: &Path, rehash: bool, at: usize, key: &str, f: f64) {
    edit_update(path, at, rehash, &|v| {
        scale_at(v, key, at, f);
    });
}

#[test]
fn edited_and_foreign_planetary_checkpoints_are_refused_saying_why() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let out = d.path().join("w");
    let a = args(&config, "dynamic", &out, &[]);
    assert!(run(&a).status.success());
    let logs: Vec<PathBuf> = ["sun", "ring"]
        .iter()
        .flat_map(|k| (1..=4).map(move |p| format!("checkpoint_dynamic_{k}_planet_{p}.jsonl")))
        .map(|n| out.join(n))
        .collect();
    let original: Vec<String> = logs
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    let restore = || {
        for (p, t) in logs.iter().zip(&original) {
            std::fs::write(p, t).unwrap();
        }
    };
    let ring2 = &logs[5];
    // A plain edit breaks the line's checksum, named with the file.
    scale(ring2, false, 2, "/wear/gear_m", 1.5);
    refused(
        &a,
        "plain edit",
        &["checkpoint_dynamic_ring_planet_2", "line 4", "checksum"],
    );
    restore();
    // With a recomputed checksum: the ring's wear seen by planet 2's ring mesh at update 2
    // is not its wear at update 1 advanced over the replayed block.
    scale(ring2, true, 2, "/wear/gear_m", 1.5);
    refused(
        &a,
        "wear x 1.5",
        &[
            "update 2 (line 4), mesh ring_planet_2",
            "advanced over the block",
        ],
    );
    restore();
    // The rate of the last update is chained to nothing: only recomputing the whole set's
    // response catches it.
    let last = original[5].lines().count() - 2;
    scale(ring2, true, last, "/increment_gear_m", 1.0 + 1e-9);
    refused(
        &a,
        "last rate x (1 + 1e-9)",
        &[
            &format!("update {last} (line {}), mesh ring_planet_2", last + 2),
            "not what this case's model computes",
        ],
    );
    restore();
    // A response figure of the first update (planet 3's sun mesh force).
    scale(&logs[2], true, 0, "/summary/mesh_force_mean_n", 1.0 + 1e-9);
    refused(
        &a,
        "mean force",
        &[
            "update 0 (line 2), mesh sun_planet_3",
            "not what this case's model",
        ],
    );
    restore();
    // A sun mesh's log copied over a ring mesh's: their grids differ in rho, not in
    // length, so the replay's wear chain or the recomputation must catch it.
    std::fs::write(ring2, &original[1]).unwrap();
    refused(&a, "sun log as ring log", &["mesh ring_planet_2"]);
    restore();
    // A mesh's log missing.
    std::fs::remove_file(&logs[7]).unwrap();
    refused(&a, "missing log", &["the log of a mesh is missing"]);
    restore();
    // Another case's logs (70 N m instead of 60): refused by their header ...
    let other = d.path().join("other");
    assert!(run(&args(&case(d.path(), 70.0), "dynamic", &other, &[]))
        .status
        .success());
    foreign_logs_refused(&a, &logs, &other);
    restore();
    // Untouched, it resumes (nothing left to compute) to the same results.
    resuming_a_finished_run_changes_nothing(&a, &out);
}
