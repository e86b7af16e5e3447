//! `gearwear wear --resume` on a gear train (`[[stage]]`): a run interrupted after k
//! updates of the whole train (killed, or its mesh logs cut as a kill between two appends
//! leaves them) resumes to the bytes of an uninterrupted run; a checkpoint that is
//! tampered with, of another case, or of another stage is refused with exit 2 saying why,
//! even when its checksums and header were rewritten to pass (the records are replayed and
//! recomputed, not trusted).

mod common;
use common::resume::{
    cut_log, cut_then_resumed_is_unchanged, foreign_logs_refused,
    killed_then_resumed_is_uninterrupted, refused, resuming_a_finished_run_changes_nothing, run,
    scale_at, sha,
};
use std::path::{Path, PathBuf};

/// The two-stage reducer of `examples/two_stage_reducer.toml` (19/31 then 23/47) at
/// 30 Hz and 60 N m, with `torque` on the input shaft instead of 60 when given.
fn case(dir: &Path, torque: f64) -> String {
    let p = dir.join(format!("train_{torque}.toml"));
    std::fs::write(
        &p,
        format!(
            "[operating]\ninput_speed_hz = 30\nload_torque_nm = {torque}\nload_torque_shaft = \"pinion\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n\n[[stage]]\nmodule_mm = 2.5\nteeth_pinion = 23\nteeth_gear = 47\nface_width_mm = 25\n"
        ),
    )
    .unwrap();
    p.to_str().unwrap().to_owned()
}

/// `gearwear wear` of `config` in `mode` to 2e4 input cycles into `out`: with the case's
/// threshold, 6 updates after the new teeth, 5 of them cut by stage 1's threshold (so the
/// replay must recompute which mesh cut each block), a few seconds.
fn args(config: &str, mode: &str, out: &Path, extra: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = [
        "-q",
        "wear",
        "--mode",
        mode,
        "--config",
        config,
        "--set",
        "wear.total_cycles=2e4",
        "--out",
    ]
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
        assert!(out.join("wear_history_dynamic.csv").exists());
        // Killed between the appends of update 3 (dynamic: stage 1 holds it, stage 2 half
        // of it) and after update 2 (quasi-static: both logs hold updates 0..=2).
        for (file, keep, torn) in [
            ("checkpoint_dynamic_stage1.jsonl", 4, false),
            ("checkpoint_dynamic_stage2.jsonl", 3, true),
            ("checkpoint_quasi_static_stage1.jsonl", 3, false),
            ("checkpoint_quasi_static_stage2.jsonl", 3, false),
        ] {
            cut_log(&out.join(file), keep, torn);
        }
    };
    cut_then_resumed_is_unchanged(&args(&config, "both", &out, &[]), &out, &cut);
}

#[test]
fn a_killed_train_run_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let (full, cut) = (d.path().join("full"), d.path().join("cut"));
    // Killed once stage 2's log holds two updates.
    killed_then_resumed_is_uninterrupted(
        &|out| args(&config, "dynamic", out, &[]),
        (&full, &cut),
        "checkpoint_dynamic_stage2.partial.jsonl",
        2,
    );
}

/// Rewrite the record lines of a log through `edit` (update index, record JSON), with
/// fresh checksums when `rehash`, so that only the replay or the recomputation can catch
/// the edit.
fn tamper(path: &Path, rehash: bool, edit: &dyn Fn(usize, &mut serde_json::Value)) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut out = String::new();
    for (i, line) in text.lines().enumerate() {
        let (sum, json) = line.split_once(' ').unwrap();
        if i == 0 {
            out.push_str(line);
        } else {
            let v: serde_json::Value = serde_json::from_str(json).unwrap();
            let mut e = v.clone();
            edit(i - 1, &mut e);
            if e == v {
                out.push_str(line); // untouched lines keep their text
            } else {
                let j = serde_json::to_string(&e).unwrap();
                let s = if rehash { sha(&j) } else { sum.to_owned() };
                out.push_str(&format!("{s} {j}"));
            }
        }
        out.push('\n');
    }
    std::fs::write(path, out).unwrap();
}

/// Multiply the number at `key` (a JSON pointer) of update `at` by `f`; when `key` names
/// an array, its largest element (a point where the profile has worn).
fn scale(at: usize, key: &'static str, f: f64) -> impl Fn(usize, &mut serde_json::Value) {
    move |i, v| {
        if i != at {
            return;
        }
        scale_at(v, key, at, f);
    }
}

#[test]
fn tampered_foreign_and_swapped_train_checkpoints_are_refused_saying_why() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let out = d.path().join("w");
    let a = args(&config, "dynamic", &out, &[]);
    assert!(run(&a).status.success());
    let logs: Vec<PathBuf> = (1..=2)
        .map(|s| out.join(format!("checkpoint_dynamic_stage{s}.jsonl")))
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
    let s2 = &logs[1];
    // A plain edit breaks the line's checksum, named with the file.
    tamper(s2, false, &scale(2, "/wear/gear_m", 1.5));
    refused(
        &a,
        "plain edit",
        &["checkpoint_dynamic_stage2", "line 4", "checksum"],
    );
    restore();
    // With recomputed checksums: stage 2's gear wear at update 2 is not its wear at update 1
    // advanced over the replayed block.
    tamper(s2, true, &scale(2, "/wear/gear_m", 1.5));
    refused(
        &a,
        "wear x 1.5",
        &["update 2 (line 4), stage 2", "advanced over the block"],
    );
    restore();
    // The rate of the last update is chained to nothing: only recomputing the whole
    // train's response catches it.
    let last = original[1].lines().count() - 2;
    tamper(s2, true, &scale(last, "/increment_gear_m", 1.0 + 1e-9));
    refused(
        &a,
        "last rate x (1 + 1e-9)",
        &[
            &format!("update {last} (line {}), stage 2", last + 2),
            "not what this case's model computes",
        ],
    );
    restore();
    // A response figure of a middle update (its mean mesh force).
    tamper(
        s2,
        true,
        &scale(3, "/summary/mesh_force_mean_n", 1.0 + 1e-9),
    );
    refused(
        &a,
        "mean force",
        &["update 3 (line 5), stage 2", "not what this case's model"],
    );
    restore();
    // Stage 1's log copied over stage 2's (same case, same mode): the periodic end
    // state of the train is kept with stage 1's records only.
    std::fs::write(s2, &original[0]).unwrap();
    refused(
        &a,
        "stage 1 as stage 2",
        &["stage 2", "stage 1's record only"],
    );
    restore();
    // Another case's logs (70 N m instead of 60): refused by their header ...
    let other = d.path().join("other");
    let b = args(&case(d.path(), 70.0), "dynamic", &other, &[]);
    assert!(run(&b).status.success());
    foreign_logs_refused(&a, &logs, &other);
    restore();
    // Untouched, it resumes (nothing left to compute) to the same results.
    resuming_a_finished_run_changes_nothing(&a, &out);
}

#[test]
fn tampered_checkpoints_of_a_train_with_a_faulty_stage_are_refused_saying_why() {
    // Stage 1's pinion tooth 3 cracked 0.8 mm: each stage-1 record holds a wear profile
    // and a rate per tooth (`wear.teeth`, `increment_teeth`). Quasi-static (the replay
    // and the recomputation are those of the dynamic mode, without the periodic state).
    let d = tempfile::tempdir().unwrap();
    let config = d.path().join("faulty.toml");
    let text = std::fs::read_to_string(case(d.path(), 60.0)).unwrap()
        + "\n[[fault]]\nstage = 1\ngear = \"pinion\"\ntooth = 3\nkind = \"crack\"\ncrack_depth_mm = 0.8\n";
    std::fs::write(&config, text).unwrap();
    let out = d.path().join("w");
    let a = args(config.to_str().unwrap(), "quasi-static", &out, &[]);
    let o = run(&a);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let s1 = out.join("checkpoint_quasi_static_stage1.jsonl");
    let original = std::fs::read_to_string(&s1).unwrap();
    let restore = || std::fs::write(&s1, &original).unwrap();
    let last = original.lines().count() - 2;
    // The cracked tooth's own wear at update 2 (its deepest point): not update 1's
    // advanced over the block, nor the roughness the record states for its wear.
    tamper(&s1, true, &scale(2, "/wear/teeth/pinion_m/3", 1.5));
    refused(
        &a,
        "cracked tooth's wear x 1.5",
        &["update 2 (line 4), stage 1", "cannot be resumed"],
    );
    restore();
    // The cracked tooth's rate at the last update, chained to nothing: caught only by
    // recomputing the train's response with the fault.
    tamper(
        &s1,
        true,
        &scale(last, "/increment_teeth/pinion_m/3", 1.0 + 1e-9),
    );
    refused(
        &a,
        "cracked tooth's last rate x (1 + 1e-9)",
        &[
            &format!("update {last} (line {}), stage 1", last + 2),
            "not what this case's model computes",
        ],
    );
    restore();
    // The cracked tooth's rate swapped with a sound one's at the last update (every
    // number in it one the model computed, for another tooth).
    tamper(&s1, true, &move |i, v| {
        if i == last {
            let t = v.pointer_mut("/increment_teeth/pinion_m").unwrap();
            let t = t.as_array_mut().unwrap();
            t.swap(3, 4);
        }
    });
    refused(
        &a,
        "cracked and sound tooth swapped",
        &[&format!("update {last} (line {}), stage 1", last + 2)],
    );
    restore();
    resuming_a_finished_run_changes_nothing(&a, &out);
}
