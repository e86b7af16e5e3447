//! A dataset folder belongs to the design that made it (issue 33): a run, a shard or a
//! merge of another design into a complete folder is refused with exit 2, naming the
//! folder, before anything in it changes (before, a shard of another design exited 0 and
//! left 6 of 12 index rows false).

mod common;

use common::{gearwear, ok, snapshot, stderr};
use std::path::Path;

/// A tiny design: one state of one condition, two records of 0.05 s on coarse grids.
fn design(seed: u64) -> String {
    format!(
        "seed = {seed}\nset = [\"signals.record_length=0.05\", \"numerics.steps_per_mesh_period=60\", \"numerics.evaluated_mesh_periods=2\", \"stiffness.table_points_per_mesh_period=60\", \"wear.block_cycles=1e4\"]\n[run_to_failure]\nstates = 2\nmax_cycles = 2e4\n[records]\nnoise_realisations = 1\n"
    )
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

#[test]
fn another_design_is_refused_before_the_folder_changes() {
    let dir = tempfile::tempdir().unwrap();
    let a = write(dir.path(), "a.toml", &design(1));
    let b = write(dir.path(), "b.toml", &design(2));
    let out = dir.path().join("out");
    let out_s = out.to_str().unwrap();
    // The line on standard error says what was written: 2 states x 1 realisation.
    let e = ok(&["dataset", "--design", &a, "--out", out_s, "-q"]);
    let line = |c, r| {
        format!("dataset: 2 records ({c} computed, {r} reused), index and metadata -> {out_s}/")
    };
    assert!(e.contains(&line(2, 0)), "{e}");
    // The same design again: a resume, allowed (nothing to compute).
    let e = ok(&["dataset", "--design", &a, "--out", out_s, "-q"]);
    assert!(e.contains(&line(0, 2)), "{e}");
    let before = snapshot(&out);
    for extra in [&[][..], &["--shard", "1/2"][..]] {
        let mut args = vec!["dataset", "--design", &b, "--out", out_s, "-q"];
        args.extend(extra);
        let r = gearwear(&args);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{extra:?}: {e}");
        assert!(e.contains("another design") && e.contains(out_s), "{e}");
        assert_eq!(snapshot(&out), before, "{extra:?}: the folder changed");
    }
    // Shards of design b merged into a's folder: refused too.
    let shards = dir.path().join("b_shards");
    let shards_s = shards.to_str().unwrap();
    for s in ["1/2", "2/2"] {
        ok(&[
            "dataset", "--design", &b, "--out", shards_s, "--shard", s, "-q",
        ]);
    }
    let r = gearwear(&["dataset-merge", shards_s, "--out", out_s, "-q"]);
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(2), "{e}");
    assert!(e.contains("another design"), "{e}");
    assert_eq!(snapshot(&out), before, "the merge changed the folder");
    // --replace: the user's explicit choice.
    ok(&["dataset", "--design", &b, "--out", out_s, "--replace", "-q"]);
}

/// The design key a dataset folder's description names.
fn key_of(root: &Path) -> String {
    let v: serde_json::Value =
        serde_json::from_slice(&std::fs::read(root.join("state/dataset.json")).unwrap()).unwrap();
    v["dataset_key"].as_str().unwrap().to_owned()
}

#[test]
fn two_designs_started_at_once_into_an_empty_folder_one_is_refused_and_nothing_mixes() {
    // An unsharded run and a shard take different set locks; the folder-wide claim makes
    // one of them the folder's owner and refuses the other (exit 2), whichever comes
    // first, in every trial.
    let dir = tempfile::tempdir().unwrap();
    let a = write(dir.path(), "a.toml", &design(1));
    let b = write(dir.path(), "b.toml", &design(2));
    for trial in 0..3 {
        let out = dir.path().join(format!("out{trial}"));
        let out_s = out.to_str().unwrap().to_owned();
        let spawn = |design: &str, extra: &[&str]| {
            std::process::Command::new(env!("CARGO_BIN_EXE_gearwear"))
                .args(["dataset", "-q", "--design", design, "--out", &out_s])
                .args(extra)
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        };
        let (pa, pb) = (spawn(&a, &[]), spawn(&b, &["--shard", "1/2"]));
        let (ra, rb) = (
            pa.wait_with_output().unwrap(),
            pb.wait_with_output().unwrap(),
        );
        let codes = (ra.status.code(), rb.status.code());
        let (winner, loser) = match codes {
            (Some(0), Some(2)) => (&a, &rb),
            (Some(2), Some(0)) => (&b, &ra),
            _ => panic!(
                "trial {trial}: exits {codes:?}, expected one 0 and one 2: {} / {}",
                stderr(&ra),
                stderr(&rb)
            ),
        };
        let e = stderr(loser);
        assert!(
            e.contains("another design") || e.contains("being written by another gearwear"),
            "trial {trial}: {e}"
        );
        // Only the winner's records, under the winner's key: a resume of the winner's
        // design is accepted, the loser's refused.
        let key = key_of(&out);
        for entry in std::fs::read_dir(out.join("records")).unwrap() {
            let car: serde_json::Value =
                serde_json::from_slice(&std::fs::read(entry.unwrap().path()).unwrap()).unwrap();
            assert_eq!(
                car["dataset_key"].as_str(),
                Some(key.as_str()),
                "trial {trial}"
            );
        }
        let shard: &[&str] = if winner == &b {
            &["--shard", "1/2"]
        } else {
            &[]
        };
        let mut again = vec!["dataset", "-q", "--design", winner, "--out", &out_s];
        again.extend(shard);
        ok(&again);
        assert_eq!(key_of(&out), key, "trial {trial}");
        assert!(!out.join("INCOMPLETE").exists(), "trial {trial}");
    }
}

/// A folder whose description names a key of any text (damaged or foreign) is refused as
/// another design's, with exit 2; the message shows the key's first 12 characters. A key
/// whose 12th byte falls inside a character ("a" then two-byte "é"s: byte 12 is the
/// middle of the sixth "é") once made the message slice a `str` inside a character: a
/// panic, exit 101, found while writing the shard-description fuzz target.
#[test]
fn a_description_key_of_any_characters_is_refused_without_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let a = write(dir.path(), "a.toml", &design(1));
    for forged in [
        "aéééééééééé",
        "日本語のキーは十二文字を超える",
        "a\u{1F600}\u{1F600}\u{1F600}",
    ] {
        let out = dir.path().join("out");
        std::fs::create_dir_all(out.join("state")).unwrap();
        let body = serde_json::json!({ "dataset_key": forged });
        std::fs::write(out.join("state/dataset.json"), body.to_string()).unwrap();
        let before = snapshot(&out);
        let r = gearwear(&[
            "dataset",
            "--design",
            &a,
            "--out",
            out.to_str().unwrap(),
            "-q",
        ]);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{forged}: {e}");
        let shown: String = forged.chars().take(12).collect();
        assert!(
            e.contains("another design") && e.contains(&shown),
            "{forged}: {e}"
        );
        assert_eq!(snapshot(&out), before, "{forged}: the folder changed");
        std::fs::remove_dir_all(&out).unwrap();
    }
}
