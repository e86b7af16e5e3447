//! Hostile inputs and folders (issues 21 and 22): each test reproduces an attack or a
//! fault a hostile tester found and shows it refused or harmless, and that files outside
//! the output folder are untouched, content and inode.

mod common;

use common::{gearwear, stderr, CHEAP};
use std::collections::BTreeMap;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Every file under a folder with its content and inode, links not followed.
#[derive(Debug, PartialEq)]
struct Snapshot(BTreeMap<PathBuf, (Vec<u8>, u64)>);

fn snapshot(root: &Path) -> Snapshot {
    let mut m = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let p = e.path();
            let md = std::fs::symlink_metadata(&p).unwrap();
            if md.is_dir() {
                stack.push(p);
            } else if md.is_file() {
                m.insert(p.clone(), (std::fs::read(&p).unwrap(), md.ino()));
            } else {
                m.insert(p.clone(), (Vec::new(), md.ino()));
            }
        }
    }
    Snapshot(m)
}

/// A folder of precious files outside any output folder.
fn outside(d: &Path) -> PathBuf {
    let o = d.join("outside");
    std::fs::create_dir_all(o.join("sub")).unwrap();
    std::fs::write(o.join("victim.txt"), b"precious").unwrap();
    std::fs::write(o.join("thesis.tex"), b"\\documentclass{article}").unwrap();
    std::fs::write(o.join("sub/notes.txt"), b"notes").unwrap();
    o
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A short `run` (a few updates).
fn run_args(out: &Path) -> Vec<String> {
    [
        "run",
        "-q",
        "--set",
        "wear.total_cycles=5e3",
        "--out",
        s(out),
    ]
    .iter()
    .map(|x| x.to_string())
    .collect()
}

fn run_in(out: &Path, extra: &[&str]) -> std::process::Output {
    let mut a = run_args(out);
    a.extend(extra.iter().map(|x| x.to_string()));
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    gearwear(&refs)
}

/// `args` must end within `secs` seconds (a FIFO must not block it); returns its output.
fn within(args: &[&str], secs: u64) -> std::process::Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if t0.elapsed() > Duration::from_secs(secs) {
            let _ = child.kill();
            panic!("gearwear {args:?} still runs after {secs} s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

fn mkfifo(p: &Path) {
    rustix::fs::mkfifoat(rustix::fs::CWD, p, rustix::fs::Mode::from_raw_mode(0o600)).unwrap();
}

#[test]
fn a_planted_manifest_deletes_nothing_even_through_a_linked_subfolder() {
    let d = tempfile::tempdir().unwrap();
    let o = outside(d.path());
    let before = snapshot(&o);
    let out = d.path().join("out");
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("notes.txt"), b"mine").unwrap();
    std::os::unix::fs::symlink(&o, out.join("csv")).unwrap();
    // Left by another tool, or planted: it lists the user's files, through the link too.
    let manifest = serde_json::json!({
        "program": "gearwear", "version": "0", "command": "run",
        "files": [
            {"path": "notes.txt", "sha256": "0", "bytes": 4},
            {"path": "csv/victim.txt", "sha256": "0", "bytes": 8},
            {"path": "csv/thesis.tex", "sha256": "0", "bytes": 4},
        ],
        "state_files": ["csv/sub/notes.txt"],
    });
    std::fs::write(out.join("manifest.json"), manifest.to_string()).unwrap();
    let r = run_in(&out, &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert!(stderr(&r).contains("manifest.json"), "{}", stderr(&r));
    assert_eq!(snapshot(&o), before);
    assert_eq!(std::fs::read(out.join("notes.txt")).unwrap(), b"mine");
    // A state file planted in gearwear's own format is no better: it was not written
    // for this folder (another folder's identity), so it is refused too.
    std::fs::remove_file(out.join("manifest.json")).unwrap();
    let fake = serde_json::json!({
        "format": "gearwear-output-state", "version": 1,
        "folder": {"dev": 1, "ino": 2}, "command": "run",
        "outputs": [{"path": "csv/victim.txt", "dev": 1, "ino": 2, "bytes": 8, "sha256": "0"}],
        "state_files": [], "staging": [],
    });
    std::fs::write(out.join(".gearwear-state.json"), fake.to_string()).unwrap();
    let r = run_in(&out, &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert!(stderr(&r).contains("another folder"), "{}", stderr(&r));
    assert_eq!(snapshot(&o), before);
}

#[test]
fn a_linked_subfolder_is_refused_and_never_written_through() {
    let d = tempfile::tempdir().unwrap();
    let o = outside(d.path());
    let before = snapshot(&o);
    let out = d.path().join("out");
    std::fs::create_dir(&out).unwrap();
    std::os::unix::fs::symlink(&o, out.join("csv")).unwrap();
    let r = run_in(&out, &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert!(stderr(&r).contains("symbolic link"), "{}", stderr(&r));
    assert_eq!(snapshot(&o), before);
    // Its results are not lost: they are kept in a visible folder of the output folder.
    let kept = std::fs::read_dir(&out).unwrap().flatten().any(|e| {
        e.file_name()
            .to_string_lossy()
            .starts_with("gearwear-unpublished-")
    });
    assert!(
        kept || stderr(&r).contains("could not be kept"),
        "{}",
        stderr(&r)
    );
}

#[test]
fn hard_linked_lock_and_checkpoint_are_refused_and_their_targets_untouched() {
    let d = tempfile::tempdir().unwrap();
    let o = outside(d.path());
    let out = d.path().join("out");
    std::fs::create_dir(&out).unwrap();
    // The lock: a hard link to an outside file.
    std::fs::hard_link(o.join("victim.txt"), out.join(".gearwear.lock")).unwrap();
    let before = snapshot(&o);
    let r = run_in(&out, &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert!(stderr(&r).contains("hard links"), "{}", stderr(&r));
    assert_eq!(snapshot(&o), before);
    std::fs::remove_file(out.join(".gearwear.lock")).unwrap();
    // The checkpoint: a finished run, its checkpoint replaced by a hard link to an
    // outside file holding a copy of it; resuming must not rewrite the outside file.
    assert!(run_in(&out, &[]).status.success());
    let ck = out.join("checkpoint_dynamic.jsonl");
    let copy = o.join("copy.jsonl");
    std::fs::copy(&ck, &copy).unwrap();
    std::fs::remove_file(&ck).unwrap();
    std::fs::hard_link(&copy, &ck).unwrap();
    let before = snapshot(&o);
    let r = run_in(&out, &["--resume"]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert!(stderr(&r).contains("hard links"), "{}", stderr(&r));
    assert_eq!(snapshot(&o), before);
}

#[test]
fn swapping_output_folders_and_files_for_links_during_runs_writes_nothing_outside() {
    let d = tempfile::tempdir().unwrap();
    let o = outside(d.path());
    let before = snapshot(&o);
    let out = d.path().join("out");
    assert!(run_in(&out, &[]).status.success());
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let swapper = {
        let (out, o, stop) = (out.clone(), o.clone(), stop.clone());
        std::thread::spawn(move || {
            let mut swaps = 0u64;
            let csv = out.join("csv");
            let aside = out.join("csv.aside");
            while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                // The csv folder becomes a link to the outside folder, and back ...
                if std::fs::rename(&csv, &aside).is_ok() {
                    let _ = std::os::unix::fs::symlink(&o, &csv);
                    std::thread::yield_now();
                    let _ = std::fs::remove_file(&csv);
                    let _ = std::fs::rename(&aside, &csv);
                }
                // ... and a CSV becomes a link to an outside file.
                let f = csv.join("fig02_mesh_stiffness.csv");
                let _ = std::fs::remove_file(&f);
                let _ = std::os::unix::fs::symlink(o.join("victim.txt"), &f);
                swaps += 1;
            }
            swaps
        })
    };
    for _ in 0..6 {
        let _ = run_in(&out, &["--replace"]);
    }
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    let swaps = swapper.join().unwrap();
    assert!(swaps > 100, "only {swaps} swaps");
    assert_eq!(snapshot(&o), before, "after {swaps} swaps");
}

#[test]
fn no_file_is_made_in_the_temporary_folder() {
    // Figures used to be drawn through TMPDIR/gearwear-plot-PID-N.png, opened with
    // create-and-truncate, so a planted link there redirected the write. They are now
    // encoded in memory: the temporary folder stays as it was, links and all.
    let d = tempfile::tempdir().unwrap();
    let o = outside(d.path());
    let tmp = d.path().join("tmp");
    std::fs::create_dir(&tmp).unwrap();
    for n in 0..64 {
        let _ = std::os::unix::fs::symlink(
            o.join("victim.txt"),
            tmp.join(format!("gearwear-plot-{n}-0.png")),
        );
    }
    let before = (snapshot(&o), snapshot(&tmp));
    let out = d.path().join("out");
    let a = run_args(&out);
    let r = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(&a)
        .env("TMPDIR", &tmp)
        .output()
        .unwrap();
    assert!(r.status.success(), "{}", stderr(&r));
    assert_eq!((snapshot(&o), snapshot(&tmp)), before);
}

#[test]
fn fifos_and_devices_as_inputs_are_refused_at_once() {
    let d = tempfile::tempdir().unwrap();
    let fifo = d.path().join("fifo");
    mkfifo(&fifo);
    let out = d.path().join("out");
    let f = s(&fifo);
    let o = s(&out);
    for args in [
        vec!["dynamics", "--config", f, "--out", o],
        vec![
            "sweep",
            "--config",
            f,
            "--vary",
            "operating.input_speed_hz=20,30",
            "--out",
            o,
        ],
        vec!["dynamics", "--transmission-error", f, "--out", o],
        vec!["dynamics", "--transmission-error", "/dev/zero", "--out", o],
        vec!["calibrate", "--observations", f, "--out", o],
        vec!["calibrate", "--observations", "/dev/zero", "--out", o],
        vec![
            "predict",
            "--posterior",
            f,
            "--limit-um",
            "10",
            "--cycles",
            "1e5",
            "--out",
            o,
        ],
        vec!["predict-merge", f, "--out", o],
    ] {
        let r = within(&args, 20);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{args:?}: {e}");
        assert!(e.contains("FIFO") || e.contains("device"), "{args:?}: {e}");
    }
}

#[test]
fn fifos_in_the_output_folder_are_refused_at_once() {
    let d = tempfile::tempdir().unwrap();
    // The lock, the state file, the manifest, a checkpoint to resume, a sweep case file.
    for (name, args) in [
        (".gearwear.lock", vec!["dynamics"]),
        (".gearwear-state.json", vec!["dynamics"]),
        ("manifest.json", vec!["dynamics"]),
        (
            "checkpoint_dynamic.jsonl",
            vec!["wear", "--mode", "dynamic", "--resume"],
        ),
        (
            "cases/0.json",
            vec!["sweep", "--vary", "operating.input_speed_hz=20,30"],
        ),
    ] {
        let out = d.path().join(name.replace(['.', '/'], "_"));
        std::fs::create_dir_all(out.join("cases")).unwrap();
        mkfifo(&out.join(name));
        let mut a = args.clone();
        a.extend(CHEAP);
        a.extend(["--out", s(&out)]);
        let r = within(&a, 30);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{name}: {e}");
        assert!(e.contains("FIFO") || e.contains("no record"), "{name}: {e}");
    }
}

/// A small dataset design: one condition, two states, one speed, one record each.
const SMALL_DESIGN: &str = r#"
seed = 3
set = ["signals.record_length=0.05", "numerics.steps_per_mesh_period=60",
       "stiffness.table_points_per_mesh_period=60", "wear.block_cycles=5e3"]
[run_to_failure]
states = 2
max_cycles = 1e4
wear_limit_um = 2
[records]
noise_realisations = 1
"#;

fn design_in(d: &Path, text: &str) -> PathBuf {
    let p = d.join("design.toml");
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn the_signal_and_duty_jobs_refuse_fifo_inputs_at_once() {
    let d = tempfile::tempdir().unwrap();
    let fifo = d.path().join("fifo");
    mkfifo(&fifo);
    let out = d.path().join("out");
    // A case whose load spectrum is read from the FIFO, and a design naming it as its case.
    let case = d.path().join("spectrum.toml");
    std::fs::write(&case, "[load_spectrum]\nfile = \"fifo\"\n").unwrap();
    let design = d.path().join("d.toml");
    std::fs::write(&design, "case = \"fifo\"\n").unwrap();
    let (f, o) = (s(&fifo), s(&out));
    for args in [
        vec!["dataset", "--design", f, "--out", o],
        vec!["dataset", "--design", s(&design), "--out", o],
        vec!["signals", "--transfer-path", f, "--out", o],
        vec!["wear", "--config", s(&case), "--out", o],
        vec!["load-spectrum", "--history", f, "--out", o],
    ] {
        let r = within(&args, 20);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{args:?}: {e}");
        assert!(e.contains("FIFO"), "{args:?}: {e}");
    }
    assert!(!out.exists(), "a refused job wrote its folder");
}

#[test]
fn a_dataset_over_the_run_budget_is_refused_before_it_starts() {
    let d = tempfile::tempdir().unwrap();
    // 1e9 cycles in blocks of 1: far over ten minutes of trajectories.
    let text = SMALL_DESIGN
        .replace("wear.block_cycles=5e3", "wear.block_cycles=1")
        .replace("max_cycles = 1e4", "max_cycles = 1e9");
    let design = design_in(d.path(), &text);
    let out = d.path().join("ds");
    let r = within(&["dataset", "--design", s(&design), "--out", s(&out)], 20);
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(2), "{e}");
    assert!(e.contains("budget") && e.contains("--budget-scale"), "{e}");
    assert!(!out.exists(), "a refused dataset wrote its folder");
}

#[test]
fn a_dataset_folder_never_writes_through_planted_files_links_or_forged_sidecars() {
    let d = tempfile::tempdir().unwrap();
    let o = outside(d.path());
    let before = snapshot(&o);
    let design = design_in(d.path(), SMALL_DESIGN);
    let args = |out: &Path| {
        vec![
            "dataset".to_string(),
            "--design".into(),
            s(&design).into(),
            "--out".into(),
            s(out).into(),
        ]
    };
    let go = |out: &Path| {
        let a = args(out);
        let refs: Vec<&str> = a.iter().map(String::as_str).collect();
        gearwear(&refs)
    };
    // 1. `signals/` a link to the outside folder: refused, nothing written through it.
    let linked = d.path().join("linked");
    std::fs::create_dir_all(&linked).unwrap();
    std::os::unix::fs::symlink(&o, linked.join("signals")).unwrap();
    let r = go(&linked);
    assert!(
        !r.status.success(),
        "a linked signals/ folder was written through"
    );
    assert_eq!(snapshot(&o), before);
    // 2. A user's file and a hard link to an outside file at record names: left alone.
    let planted = d.path().join("planted");
    std::fs::create_dir_all(planted.join("records")).unwrap();
    std::fs::create_dir_all(planted.join("signals")).unwrap();
    std::fs::write(planted.join("records/0000000.json"), b"my notes").unwrap();
    std::fs::hard_link(
        o.join("victim.txt"),
        planted.join("signals/0000001.parquet"),
    )
    .unwrap();
    let _ = go(&planted);
    assert_eq!(
        std::fs::read(planted.join("records/0000000.json")).unwrap(),
        b"my notes"
    );
    assert_eq!(snapshot(&o), before);
    // 3. A finished dataset whose sidecar is edited to name (and hash) an outside file:
    //    the sidecar is not trusted, the record is computed again, the file untouched.
    let ds = d.path().join("ds");
    let r = go(&ds);
    assert!(r.status.success(), "{}", stderr(&r));
    let car = ds.join("records/0000000.json");
    let mut v: serde_json::Value = serde_json::from_slice(&std::fs::read(&car).unwrap()).unwrap();
    let victim = o.join("victim.txt");
    v["labels"]["file"] = serde_json::json!(s(&victim));
    v["signal_sha256"] = serde_json::json!(gearwear::checksum::sha256_hex(b"precious"));
    std::fs::write(&car, serde_json::to_vec_pretty(&v).unwrap()).unwrap();
    let r = go(&ds);
    assert!(r.status.success(), "{}", stderr(&r));
    let said = String::from_utf8_lossy(&r.stdout).into_owned();
    assert!(said.contains("(1 computed, 1 reused)"), "{said}");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&car).unwrap()).unwrap();
    assert_eq!(v["labels"]["file"], "signals/0000000.parquet");
    assert_eq!(snapshot(&o), before);
}
