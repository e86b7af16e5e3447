//! Names a dataset run would write that hold something gearwear must not replace (a link
//! to a file elsewhere, a FIFO, a hard link, a link in place of a sub-folder) are refused
//! as the output folder's problem, exit code 2 naming the path, before the folder is
//! claimed or any record computed: nothing in it changes (issue 33: they were refused
//! safely, but only after the run, with exit code 1).
mod common;

use common::{gearwear, ok, stderr};
use std::collections::BTreeMap;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};

/// One state of one condition, two records of 0.05 s on coarse grids.
const DESIGN: &str = "seed = 3\nset = [\"signals.record_length=0.05\", \"numerics.steps_per_mesh_period=60\", \"numerics.evaluated_mesh_periods=2\", \"stiffness.table_points_per_mesh_period=60\", \"wear.block_cycles=1e4\"]\n[run_to_failure]\nstates = 2\nmax_cycles = 2e4\n[records]\nnoise_realisations = 1\n";

/// Every entry under `dir` as (kind, size, modification time, inode), no link followed
/// and nothing opened (a FIFO would block a reader).
fn listing(dir: &Path) -> BTreeMap<PathBuf, (String, u64, i64, u64)> {
    let mut all = BTreeMap::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let m = std::fs::symlink_metadata(&p).unwrap();
        let kind = format!("{:?}", m.file_type());
        // The folder's bookkeeping (its lock and the record of its output set) is
        // rewritten whenever a command opens the folder: compared by content instead.
        let bookkeeping = p
            .file_name()
            .unwrap()
            .to_string_lossy()
            .starts_with(".gearwear");
        let (time, inode) = if bookkeeping {
            (0, 0)
        } else {
            (m.mtime() * 1_000_000_000 + m.mtime_nsec(), m.ino())
        };
        all.insert(p.clone(), (kind, m.len(), time, inode));
        if m.is_dir() {
            all.extend(listing(&p));
        }
    }
    all
}

/// Put something at a path (`at`), given a user's file elsewhere (`to`).
type Plant = fn(&Path, &Path);

#[test]
fn planted_names_are_refused_with_exit_2_before_anything_changes() {
    let dir = tempfile::tempdir().unwrap();
    let design = dir.path().join("d.toml");
    std::fs::write(&design, DESIGN).unwrap();
    let design = design.to_str().unwrap();
    let elsewhere = dir.path().join("elsewhere.txt");
    std::fs::write(&elsewhere, "a user's file").unwrap();
    let plants: [(&str, &str, Plant); 4] = [
        ("signals/0000001.parquet", "symbolic link", |at, to| {
            std::os::unix::fs::symlink(to, at).unwrap()
        }),
        ("records/0000001.json", "FIFO", |at, _| {
            let s = std::process::Command::new("mkfifo")
                .arg(at)
                .status()
                .unwrap();
            assert!(s.success());
        }),
        ("signals/0000001.parquet", "hard links", |at, to| {
            std::fs::hard_link(to, at).unwrap()
        }),
        ("records", "not a folder", |at, to| {
            std::fs::remove_dir_all(at).unwrap();
            std::os::unix::fs::symlink(to.parent().unwrap(), at).unwrap()
        }),
    ];
    for (i, (name, words, plant)) in plants.iter().enumerate() {
        let out = dir.path().join(format!("out{i}"));
        let out_s = out.to_str().unwrap();
        ok(&["dataset", "--design", design, "--out", out_s, "-q"]);
        // The record's files removed (as if never finished), then the name planted.
        for f in ["signals/0000001.parquet", "records/0000001.json"] {
            std::fs::remove_file(out.join(f)).unwrap();
        }
        plant(&out.join(name), &elsewhere);
        let before = listing(&out);
        let state = std::fs::read(out.join(".gearwear-state.json")).unwrap();
        let r = gearwear(&["dataset", "--design", design, "--out", out_s, "-q"]);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{name}: {e}");
        assert!(
            e.contains(&out.join(name).display().to_string()),
            "{name}: {e}"
        );
        assert!(e.contains(words), "{name}: {e}");
        let after = listing(&out);
        let changed: Vec<_> = after
            .iter()
            .filter(|(p, v)| before.get(*p) != Some(v))
            .collect();
        assert_eq!(after.len(), before.len(), "{name}: files came or went");
        assert!(changed.is_empty(), "{name}: changed {changed:?}");
        assert_eq!(
            std::fs::read(out.join(".gearwear-state.json")).unwrap(),
            state
        );
        assert_eq!(
            std::fs::read_to_string(&elsewhere).unwrap(),
            "a user's file"
        );
    }
}

#[test]
fn planted_names_at_a_merge_s_targets_are_refused_with_exit_2_before_anything_changes() {
    // The merge copies every shard's records into its folder: a link to a user's file at
    // a record's name there is refused before the folder is claimed (issue 33: a merge
    // refused it only when it came to write that name, exit code 1, its folder marked).
    let dir = tempfile::tempdir().unwrap();
    let design = dir.path().join("d.toml");
    std::fs::write(&design, DESIGN).unwrap();
    let design = design.to_str().unwrap();
    let shards = dir.path().join("shards");
    let shards_s = shards.to_str().unwrap();
    for s in ["1/2", "2/2"] {
        ok(&[
            "dataset", "--design", design, "--out", shards_s, "--shard", s, "-q",
        ]);
    }
    let elsewhere = dir.path().join("elsewhere.txt");
    std::fs::write(&elsewhere, "a user's file").unwrap();
    let out = dir.path().join("merged");
    std::fs::create_dir_all(out.join("signals")).unwrap();
    let name = "signals/0000001.parquet";
    std::os::unix::fs::symlink(&elsewhere, out.join(name)).unwrap();
    let before = listing(&out);
    let r = gearwear(&[
        "dataset-merge",
        shards_s,
        "--out",
        out.to_str().unwrap(),
        "-q",
    ]);
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(2), "{e}");
    assert!(e.contains(&out.join(name).display().to_string()), "{e}");
    assert!(e.contains("symbolic link"), "{e}");
    assert_eq!(listing(&out), before, "the merge's folder changed");
    assert_eq!(
        std::fs::read_to_string(&elsewhere).unwrap(),
        "a user's file"
    );
    // Without the planted link the same merge goes through.
    std::fs::remove_file(out.join(name)).unwrap();
    ok(&[
        "dataset-merge",
        shards_s,
        "--out",
        out.to_str().unwrap(),
        "-q",
    ]);
}
