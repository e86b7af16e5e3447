//! Files that cannot be corrupted, mixed or redirected: tampered checkpoints are refused
//! with exit 2 naming the file, a killed run resumes to the same bytes, a second writer of
//! a folder is refused, a link planted in the output folder is not followed.

mod common;
use common::kill_when;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gearwear"))
}

fn gearwear(args: &[&str]) -> Output {
    bin().args(args).output().expect("binary runs")
}

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn sha(text: &str) -> String {
    gearwear::io::output_dir::sha256_hex(text.as_bytes())
}

/// A short dynamic wear study into `out` (a few updates, well under a second).
fn wear_args(out: &Path, extra: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = [
        "wear",
        "--mode",
        "dynamic",
        "--set",
        "wear.total_cycles=2e4",
        "-q",
        "--out",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    a.push(out.to_str().unwrap().into());
    a.extend(extra.iter().map(|s| s.to_string()));
    a
}

fn run_wear(out: &Path, extra: &[&str]) -> Output {
    let a = wear_args(out, extra);
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    gearwear(&refs)
}

/// Rewrite a checkpoint's record lines through `edit` (index, record JSON), with fresh
/// checksums when `rehash`, so that only the physics check can catch the edit.
fn tamper(path: &Path, rehash: bool, edit: &dyn Fn(usize, &mut serde_json::Value)) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut out = String::new();
    for (i, line) in text.lines().enumerate() {
        if i == 0 {
            out.push_str(line);
        } else {
            let (sum, json) = line.split_once(' ').unwrap();
            let mut v: serde_json::Value = serde_json::from_str(json).unwrap();
            edit(i - 1, &mut v);
            let j = serde_json::to_string(&v).unwrap();
            let s = if rehash { sha(&j) } else { sum.to_owned() };
            out.push_str(&format!("{s} {j}"));
        }
        out.push('\n');
    }
    std::fs::write(path, out).unwrap();
}

fn refused(out: &Path, needle: &str) {
    let o = run_wear(out, &["--resume"]);
    let e = err(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains("checkpoint_dynamic.jsonl"),
        "names the file: {e}"
    );
    assert!(e.contains(needle), "says `{needle}`: {e}");
    assert!(!e.contains("panicked"), "{e}");
}

fn fresh_run() -> (tempfile::TempDir, PathBuf, String) {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    assert!(run_wear(&out, &[]).status.success());
    let ck = out.join("checkpoint_dynamic.jsonl");
    let text = std::fs::read_to_string(&ck).unwrap();
    (d, ck, text)
}

#[test]
fn every_tampering_of_a_checkpoint_is_refused() {
    let (_d, ck, original) = fresh_run();
    let out = ck.parent().unwrap().to_path_buf();
    let restore = || std::fs::write(&ck, &original).unwrap();
    type Edit = Box<dyn Fn(usize, &mut serde_json::Value)>;
    let cases: Vec<(&str, Edit, &str)> = vec![
        (
            "values x 1.5",
            Box::new(|i, v| {
                if i == 1 {
                    for x in v["wear"]["pinion_m"].as_array_mut().unwrap() {
                        *x = serde_json::json!(x.as_f64().unwrap() * 1.5);
                    }
                }
            }),
            "update 1",
        ),
        (
            "wear of 1 m",
            Box::new(|i, v| {
                if i == 1 {
                    v["wear"]["pinion_m"][50] = serde_json::json!(1.0);
                }
            }),
            "update 1",
        ),
        (
            "negative cycles",
            Box::new(|i, v| {
                if i == 1 {
                    v["wear"]["cycles"] = serde_json::json!(-5.0);
                }
            }),
            "cycles",
        ),
        (
            "array of the wrong length",
            Box::new(|i, v| {
                if i == 1 {
                    v["increment_gear_m"].as_array_mut().unwrap().pop();
                }
            }),
            "points",
        ),
    ];
    for (what, edit, needle) in &cases {
        // Plain edits break the line's checksum ...
        tamper(&ck, false, edit.as_ref());
        refused(&out, "checksum");
        restore();
        // ... and edits with recomputed checksums break the physics.
        tamper(&ck, true, edit.as_ref());
        let o = run_wear(&out, &["--resume"]);
        assert_eq!(o.status.code(), Some(2), "{what}: {}", err(&o));
        assert!(err(&o).contains(needle), "{what}: {}", err(&o));
        restore();
    }
    // Records in reverse order (checksums intact: each line is whole).
    let mut lines: Vec<&str> = original.lines().collect();
    lines[1..].reverse();
    std::fs::write(&ck, lines.join("\n") + "\n").unwrap();
    refused(&out, "first update");
    restore();
    // One invalid UTF-8 byte.
    let mut bytes = original.clone().into_bytes();
    let at = bytes.len() / 2;
    bytes[at] = 0xff;
    std::fs::write(&ck, &bytes).unwrap();
    refused(&out, "UTF-8");
    restore();
    // Untouched, it resumes.
    assert!(run_wear(&out, &["--resume"]).status.success());
}

#[test]
fn a_quasi_static_checkpoint_copied_over_the_dynamic_one_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let mut a = wear_args(&out, &[]);
    a[2] = "both".into();
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    assert!(gearwear(&refs).status.success());
    std::fs::copy(
        out.join("checkpoint_quasi_static.jsonl"),
        out.join("checkpoint_dynamic.jsonl"),
    )
    .unwrap();
    refused(&out, "not a dynamic");
    // With the header forged to say "dynamic", the records still give it away: a
    // quasi-static update has no periodic end state to warm-start the next one from.
    let ck = out.join("checkpoint_dynamic.jsonl");
    let text = std::fs::read_to_string(&ck).unwrap();
    let (head, rest) = text.split_once('\n').unwrap();
    assert!(head.contains("quasi_static"), "{head}");
    let (_, json) = head.split_once(' ').unwrap();
    let json = json.replace("quasi_static", "dynamic");
    std::fs::write(&ck, format!("{} {json}\n{rest}", sha(&json))).unwrap();
    refused(&out, "periodic end state");
}

/// The published files of a folder (per its manifest), as bytes.
fn published(dir: &Path, manifest: &str) -> Vec<(String, Vec<u8>)> {
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join(manifest)).unwrap()).unwrap();
    m["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let p = f["path"].as_str().unwrap().to_owned();
            let b = std::fs::read(dir.join(&p)).unwrap();
            (p, b)
        })
        .collect()
}

#[test]
fn killed_long_commands_resume_to_the_same_bytes() {
    let d = tempfile::tempdir().unwrap();
    let lines =
        |p: PathBuf| move || std::fs::read_to_string(&p).map_or(0, |t| t.lines().count()) >= 3;
    // wear and run: killed after their second update, resumed, equal to an uninterrupted run.
    for cmd in ["wear", "run"] {
        let full = d.path().join(format!("{cmd}_full"));
        let cut = d.path().join(format!("{cmd}_cut"));
        let args = |out: &Path| -> Vec<String> {
            let mut a = wear_args(out, &[]);
            a[0] = cmd.into();
            if cmd == "run" {
                a.drain(1..3); // no --mode for run
            }
            a
        };
        let full_args = args(&full);
        let refs: Vec<&str> = full_args.iter().map(String::as_str).collect();
        assert!(gearwear(&refs).status.success());
        kill_when(
            &args(&cut),
            &lines(cut.join("checkpoint_dynamic.partial.jsonl")),
        );
        let mut resume = args(&cut);
        resume.push("--resume".into());
        let refs: Vec<&str> = resume.iter().map(String::as_str).collect();
        let o = gearwear(&refs);
        assert!(o.status.success(), "{cmd}: {}", err(&o));
        assert_eq!(
            published(&full, "manifest.json"),
            published(&cut, "manifest.json"),
            "{cmd}: resumed outputs differ"
        );
    }
    // sweep: killed after its first finished case, rerun: the same table.
    let full = d.path().join("sweep_full");
    let cut = d.path().join("sweep_cut");
    let sweep = |out: &Path| -> Vec<String> {
        [
            "sweep",
            "--vary",
            "operating.input_speed_hz=20:40:2.5",
            "-q",
            "--out",
        ]
        .iter()
        .map(|s| s.to_string())
        .chain([out.to_str().unwrap().to_owned()])
        .collect()
    };
    let a = sweep(&full);
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    assert!(gearwear(&refs).status.success());
    let cases = cut.join("cases");
    kill_when(&sweep(&cut), &|| {
        std::fs::read_dir(&cases).map_or(0, |r| r.count()) >= 1
    });
    let a = sweep(&cut);
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    assert!(gearwear(&refs).status.success());
    assert_eq!(
        std::fs::read(full.join("sweep.csv")).unwrap(),
        std::fs::read(cut.join("sweep.csv")).unwrap()
    );
}

#[test]
fn a_second_writer_of_a_folder_is_refused_and_told_who_holds_it() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    std::fs::create_dir(&out).unwrap();
    // Hold the folder's lock as a running gearwear would.
    let dir = gearwear::io::dir::Dir::open_root(&out).unwrap();
    let lock =
        gearwear::io::lock::OutputLock::acquire(&dir, ".gearwear.lock", "wear").expect("lock");
    let o = run_wear(&out, &[]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(err(&o).contains("another gearwear"), "{}", err(&o));
    drop(lock);
    assert!(run_wear(&out, &[]).status.success());
}

#[cfg(unix)]
#[test]
fn links_planted_in_the_output_folder_are_neither_followed_nor_removed() {
    use std::os::unix::fs::MetadataExt;
    let d = tempfile::tempdir().unwrap();
    let victim = d.path().join("victim.txt");
    std::fs::write(&victim, b"precious").unwrap();
    let ino = std::fs::metadata(&victim).unwrap().ino();
    let out = d.path().join("w");
    std::fs::create_dir(&out).unwrap();
    for names in [
        &["summary.json", "checkpoint_dynamic.jsonl"][..],
        &["manifest.json"][..],
    ] {
        for name in names {
            std::os::unix::fs::symlink(&victim, out.join(name)).unwrap();
        }
        let o = run_wear(&out, &[]);
        assert_eq!(o.status.code(), Some(2), "{}", err(&o));
        assert!(
            err(&o).contains("symbolic link") || err(&o).contains("no record"),
            "{}",
            err(&o)
        );
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
        assert_eq!(std::fs::metadata(&victim).unwrap().ino(), ino);
        for name in names {
            let m = std::fs::symlink_metadata(out.join(name)).unwrap();
            assert!(m.file_type().is_symlink(), "{name}: the link was removed");
            std::fs::remove_file(out.join(name)).unwrap();
        }
    }
    assert!(run_wear(&out, &[]).status.success());
}

/// Every file the manifest of `dir` lists is present with its checksum.
fn consistent_with_manifest(dir: &Path) -> bool {
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap()).unwrap();
    m["files"].as_array().unwrap().iter().all(|f| {
        std::fs::read(dir.join(f["path"].as_str().unwrap())).is_ok_and(|b| {
            gearwear::io::output_dir::sha256_hex(&b) == f["sha256"].as_str().unwrap()
        })
    })
}

#[cfg(target_os = "linux")]
#[test]
fn a_write_failure_mid_run_leaves_the_previous_complete_set() {
    use std::os::unix::process::CommandExt;
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("r");
    let o = out.to_str().unwrap();
    let base = ["run", "-q", "--set", "wear.total_cycles=5e3", "--out", o];
    assert!(gearwear(&base).status.success());
    let before = std::fs::read(out.join("summary.json")).unwrap();
    // Rerun at 40 Hz with files limited to 64 kB: the first large file (a figure, the
    // report) fails with EFBIG, as a full disk fails a write. SIGXFSZ is ignored so that
    // the write returns the error instead of killing the process (an ignored signal stays
    // ignored across exec).
    let mut cmd = bin();
    cmd.args(base)
        .args(["--set", "operating.input_speed_hz=40"]);
    unsafe {
        cmd.pre_exec(|| {
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            let lim = libc::rlimit {
                rlim_cur: 64 * 1024,
                rlim_max: 64 * 1024,
            };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let failed = cmd.output().unwrap();
    let e = err(&failed);
    assert_eq!(failed.status.code(), Some(2), "{e}");
    assert!(
        e.contains("cannot write") && e.contains(o),
        "names the path: {e}"
    );
    // The folder still holds the complete 30 Hz set.
    assert_eq!(std::fs::read(out.join("summary.json")).unwrap(), before);
    assert!(consistent_with_manifest(&out));
    assert!(!out.join("INCOMPLETE").exists());
    // And the next run cleans up after the failed one.
    assert!(gearwear(&base).status.success());
    let strays: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".gearwear-staging") || n.starts_with(".gearwear-tmp"))
        .collect();
    assert!(strays.is_empty(), "{strays:?}");
}

#[test]
fn a_merge_of_a_merge_and_a_shard_of_another_sweep_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let s = |p: &Path| p.to_str().unwrap().to_owned();
    let (a, b, m1, m2) = (
        d.path().join("a"),
        d.path().join("b"),
        d.path().join("m1"),
        d.path().join("m2"),
    );
    let sweep = |out: &Path, load: &str, shard: &str| {
        let o = gearwear(&[
            "sweep",
            "-q",
            "--set",
            &format!("operating.load_torque_nm={load}"),
            "--vary",
            "operating.input_speed_hz=20,25,30,35",
            "--shard",
            shard,
            "--out",
            &s(out),
        ]);
        assert!(o.status.success(), "{}", err(&o));
    };
    sweep(&a, "60", "1/2");
    sweep(&b, "50", "2/2");
    // A partial merge of the 60 N m sweep ...
    assert!(gearwear(&["sweep-merge", "-q", &s(&a), "--out", &s(&m1)])
        .status
        .success());
    // ... merged with a shard of the 50 N m sweep: disjoint case ids, different sweeps.
    let o = gearwear(&["sweep-merge", &s(&m1), &s(&b), "--out", &s(&m2)]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(err(&o).contains("different sweeps"), "{}", err(&o));
    assert!(!m2.join("sweep.csv").exists());
}

#[test]
fn an_edited_sweep_case_file_is_refused_naming_it() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    let o = out.to_str().unwrap();
    let args = [
        "sweep",
        "-q",
        "--vary",
        "operating.input_speed_hz=20,25",
        "--out",
        o,
    ];
    assert!(gearwear(&args).status.success());
    let case = out.join("cases").join("1.json");
    let text = std::fs::read_to_string(&case).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let x = v["results"][0].as_f64().unwrap();
    v["results"][0] = serde_json::json!(x * 1.5);
    std::fs::write(&case, serde_json::to_string_pretty(&v).unwrap()).unwrap();
    let r = gearwear(&args);
    assert_eq!(r.status.code(), Some(2), "{}", err(&r));
    assert!(
        err(&r).contains("1.json") && err(&r).contains("checksum"),
        "{}",
        err(&r)
    );
    // Restored, it is used again (skipped, not recomputed).
    std::fs::write(&case, text).unwrap();
    assert!(gearwear(&args).status.success());
}
