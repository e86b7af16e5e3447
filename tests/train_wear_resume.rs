//! `gearwear wear --resume` on a gear train (`[[stage]]`): a run interrupted after k
//! updates of the whole train (killed, or its mesh logs cut as a kill between two appends
//! leaves them) resumes to the bytes of an uninterrupted run; a checkpoint that is
//! tampered with, of another case, or of another stage is refused with exit 2 saying why,
//! even when its checksums and header were rewritten to pass (the records are replayed and
//! recomputed, not trusted).

mod common;
use common::{gearwear, kill_when, published, stderr};
use std::path::{Path, PathBuf};
use std::process::Output;

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

fn run(a: &[String]) -> Output {
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    gearwear(&refs)
}

/// Keep the header and `keep` updates of a log, and half of the next line when `torn`.
fn cut_log(path: &Path, keep: usize, torn: bool) {
    let text = std::fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() > keep + 1, "{path:?} has {} lines", lines.len());
    let mut out = lines[..keep + 1].join("\n") + "\n";
    if torn {
        let next = lines[keep + 1];
        out.push_str(&next[..next.len() / 2]);
    }
    std::fs::write(path, out).unwrap();
}

#[test]
fn logs_cut_between_the_appends_of_an_update_resume_to_the_same_bytes() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let out = d.path().join("w");
    let a = args(&config, "both", &out, &[]);
    let o = run(&a);
    assert!(o.status.success(), "{}", stderr(&o));
    let full = published(&out);
    assert!(full.iter().any(|(p, _)| p == "wear_history_dynamic.csv"));
    // Killed between the appends of update 3 (dynamic: stage 1 holds it, stage 2 half of
    // it) and after update 2 (quasi-static: both logs hold updates 0..=2).
    for (file, keep, torn) in [
        ("checkpoint_dynamic_stage1.jsonl", 4, false),
        ("checkpoint_dynamic_stage2.jsonl", 3, true),
        ("checkpoint_quasi_static_stage1.jsonl", 3, false),
        ("checkpoint_quasi_static_stage2.jsonl", 3, false),
    ] {
        cut_log(&out.join(file), keep, torn);
    }
    let mut resume = a.clone();
    resume.push("--resume".into());
    let o = run(&resume);
    assert!(o.status.success(), "{}", stderr(&o));
    let again = published(&out);
    assert_eq!(
        full.iter().map(|f| &f.0).collect::<Vec<_>>(),
        again.iter().map(|f| &f.0).collect::<Vec<_>>()
    );
    for ((p, x), (_, y)) in full.iter().zip(&again) {
        assert!(x == y, "{p}: the resumed run's bytes differ");
    }
}

#[test]
fn a_killed_train_run_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let config = case(d.path(), 60.0);
    let (full, cut) = (d.path().join("full"), d.path().join("cut"));
    let o = run(&args(&config, "dynamic", &full, &[]));
    assert!(o.status.success(), "{}", stderr(&o));
    // Killed once stage 2's log holds two updates (header + 2 lines).
    let log = cut.join("checkpoint_dynamic_stage2.partial.jsonl");
    let ready = || std::fs::read_to_string(&log).map_or(0, |t| t.lines().count()) >= 3;
    kill_when(&args(&config, "dynamic", &cut, &[]), &ready);
    let o = run(&args(&config, "dynamic", &cut, &["--resume"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        published(&full) == published(&cut),
        "resumed outputs differ"
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

fn sha(text: &str) -> String {
    gearwear::io::output_dir::sha256_hex(text.as_bytes())
}

/// Multiply the number at `key` (a JSON pointer) of update `at` by `f`; when `key` names
/// an array, its largest element (a point where the profile has worn).
fn scale(at: usize, key: &'static str, f: f64) -> impl Fn(usize, &mut serde_json::Value) {
    move |i, v| {
        if i != at {
            return;
        }
        let at_key = match v.pointer(key).unwrap().as_array() {
            Some(a) => {
                let k = (0..a.len())
                    .max_by(|p, q| a[*p].as_f64().unwrap().total_cmp(&a[*q].as_f64().unwrap()))
                    .unwrap();
                format!("{key}/{k}")
            }
            None => key.to_owned(),
        };
        let x = v.pointer_mut(&at_key).unwrap();
        let y = x.as_f64().unwrap();
        assert!(
            y > 0.0,
            "{key} of update {at} is {y}: the edit would change nothing"
        );
        *x = serde_json::json!(y * f);
    }
}

/// Resume `a` and require exit 2 with every one of `needles` in the message.
fn refused(a: &[String], what: &str, needles: &[&str]) {
    let mut resume = a.to_vec();
    resume.push("--resume".into());
    let o = run(&resume);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{what}: {e}");
    for n in needles {
        assert!(e.contains(n), "{what}: says `{n}`: {e}");
    }
    assert!(!e.contains("panicked"), "{what}: {e}");
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
    let hash = |t: &str| {
        let head: serde_json::Value =
            serde_json::from_str(t.lines().next().unwrap().split_once(' ').unwrap().1).unwrap();
        head["case_sha256"].as_str().unwrap().to_owned()
    };
    let (ours, theirs) = (
        hash(&original[0]),
        hash(&std::fs::read_to_string(other.join("checkpoint_dynamic_stage1.jsonl")).unwrap()),
    );
    assert_ne!(ours, theirs);
    for (s, p) in logs.iter().enumerate() {
        let t =
            std::fs::read_to_string(other.join(format!("checkpoint_dynamic_stage{}.jsonl", s + 1)))
                .unwrap();
        std::fs::write(p, &t).unwrap();
    }
    refused(
        &a,
        "another case",
        &["checkpoint_dynamic_stage1", "another case"],
    );
    // ... and, with the header forged to this case's hash, by recomputing its first
    // update: the records chain and replay as a run, but not as this case's.
    for p in &logs {
        let t = std::fs::read_to_string(p).unwrap();
        let (head, rest) = t.split_once('\n').unwrap();
        let json = head.split_once(' ').unwrap().1.replace(&theirs, &ours);
        std::fs::write(p, format!("{} {json}\n{rest}", sha(&json))).unwrap();
    }
    refused(
        &a,
        "another case, forged header",
        &["update 0 (line 2)", "not what this case's model computes"],
    );
    restore();
    // Untouched, it resumes (nothing left to compute) to the same results.
    let before = published(&out);
    let mut resume = a.clone();
    resume.push("--resume".into());
    let o = run(&resume);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(published(&out) == before);
}
