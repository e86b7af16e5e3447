//! Sweeps and interrupted runs (issue 22): edited case records with recomputed
//! checksums, sweeps too large to plan, timing in deterministic files, an interrupted
//! `run` that would mix two cases' checkpoints.

mod common;

use common::{gearwear, stderr};
use gearwear::study::sweep::CaseRecord;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn an_edited_case_record_with_a_recomputed_checksum_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    let args = [
        "sweep",
        "-q",
        "--vary",
        "operating.input_speed_hz=20,25,30",
        "--out",
        s(&out),
    ];
    assert!(gearwear(&args).status.success());
    let table = std::fs::read(out.join("sweep.csv")).unwrap();
    let case = out.join("cases").join("1.json");
    let text = std::fs::read_to_string(&case).unwrap();
    let mut r: CaseRecord = serde_json::from_str(&text).unwrap();
    r.results[0] = r.results[0].map(|x| x * 1.01);
    let forged = r.sealed(); // the checksum recomputed, as a forger would
    assert!(forged.verify().is_ok());
    std::fs::write(&case, serde_json::to_string_pretty(&forged).unwrap()).unwrap();
    let o = gearwear(&args);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("1.json") && e.contains("recomputed"), "{e}");
    assert_eq!(
        std::fs::read(out.join("sweep.csv")).unwrap(),
        table,
        "the table kept"
    );
    // Restored, it is used again.
    std::fs::write(&case, text).unwrap();
    assert!(gearwear(&args).status.success());
    assert_eq!(std::fs::read(out.join("sweep.csv")).unwrap(), table);
}

#[test]
fn sweeps_too_large_to_run_are_refused_in_milliseconds() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    // 910 000 cases: refused by the budget before any case is resolved.
    let t0 = Instant::now();
    let o = gearwear(&[
        "sweep",
        "--vary",
        "operating.input_speed_hz=10:100:0.1",
        "--vary",
        "operating.load_torque_nm=1:1000:1",
        "--out",
        s(&out),
    ]);
    let took = t0.elapsed();
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("budget") && e.contains("--shard"), "{e}");
    // The binary starts, parses 910 000 values and estimates in well under a second (the
    // bound is loose for a loaded machine; before, planning alone took minutes).
    assert!(took < Duration::from_secs(5), "{took:?}");
    assert!(!out.exists());
}

#[test]
fn sweep_json_is_the_same_bytes_on_every_run_and_resume() {
    let d = tempfile::tempdir().unwrap();
    let (a, b) = (d.path().join("a"), d.path().join("b"));
    let args = |o: &Path| {
        vec![
            "sweep".to_string(),
            "-q".into(),
            "--vary".into(),
            "operating.input_speed_hz=20,25,30".into(),
            "--out".into(),
            s(o).into(),
        ]
    };
    for o in [&a, &b] {
        let x = args(o);
        let r: Vec<&str> = x.iter().map(String::as_str).collect();
        assert!(gearwear(&r).status.success());
    }
    // A rerun skips every case: still the same bytes.
    let x = args(&b);
    let r: Vec<&str> = x.iter().map(String::as_str).collect();
    assert!(gearwear(&r).status.success());
    let json = |o: &Path| std::fs::read(o.join("sweep.json")).unwrap();
    assert_eq!(json(&a), json(&b));
    let text = String::from_utf8(json(&a)).unwrap();
    assert!(
        !text.contains("wall_time") && !text.contains("\"threads\""),
        "{text}"
    );
}

#[test]
fn an_interrupted_run_of_another_case_leaves_the_published_set_and_its_checkpoints() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("r");
    let base = [
        "run",
        "-q",
        "--set",
        "wear.total_cycles=2e4",
        "--out",
        s(&out),
    ];
    assert!(gearwear(&base).status.success());
    let published = |name: &str| std::fs::read(out.join(name)).unwrap();
    let (summary, ck) = (
        published("summary.json"),
        published("checkpoint_dynamic.jsonl"),
    );
    // The same folder, another case (35 Hz), killed after a few updates.
    let mut child = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(base)
        .args(["--set", "operating.input_speed_hz=35"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let partial = out.join("checkpoint_dynamic.partial.jsonl");
    let t0 = Instant::now();
    while std::fs::read_to_string(&partial).map_or(0, |t| t.lines().count()) < 3
        && t0.elapsed() < Duration::from_secs(60)
        && child.try_wait().unwrap().is_none()
    {
        std::thread::sleep(Duration::from_millis(2));
    }
    let _ = child.kill();
    let _ = child.wait();
    // The folder's set and its checkpoints are still the 30 Hz run's, whole.
    assert_eq!(published("summary.json"), summary);
    assert_eq!(published("checkpoint_dynamic.jsonl"), ck);
    // Resuming the 35 Hz run continues its own partial checkpoint; resuming the 30 Hz
    // one finds the 35 Hz partial file first and refuses it as another case's.
    let o = gearwear(&[&base[..], &["--resume"]].concat());
    if partial.exists() {
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains("another case"), "{}", stderr(&o));
    }
    let resumed = gearwear(
        &[
            &base[..],
            &[
                "--set",
                "operating.input_speed_hz=35",
                "--resume",
                "--replace",
            ],
        ]
        .concat(),
    );
    assert!(resumed.status.success(), "{}", stderr(&resumed));
    assert!(!partial.exists());
}
