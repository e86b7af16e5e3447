//! Helpers shared by the tests that run the binary.
#![allow(dead_code)]

pub mod figures;
pub mod helical;
pub mod linear;
pub mod paper;
pub mod planetary;
pub mod resume;
pub mod rusage;
pub mod train;

use std::path::Path;
use std::process::{Command, Output};

/// Coarse time and stiffness grids, two evaluated mesh periods: cheap cases.
pub const CHEAP: [&str; 6] = [
    "--set",
    "numerics.steps_per_mesh_period=60",
    "--set",
    "numerics.evaluated_mesh_periods=2",
    "--set",
    "stiffness.table_points_per_mesh_period=60",
];

/// Start `gearwear args`, kill it (SIGKILL) once `ready()` holds, then return; if it
/// finishes first (or after two minutes) it is left at that: resuming must work either
/// way.
pub fn kill_when(args: &[String], ready: &dyn Fn() -> bool) {
    use std::time::{Duration, Instant};
    let mut child = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    while !ready() && t0.elapsed() < Duration::from_secs(120) {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    let _ = child.kill();
    let _ = child.wait();
}

pub fn gearwear(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(args)
        .output()
        .expect("the gearwear binary runs")
}

/// Run and require success; returns stderr.
pub fn ok(args: &[&str]) -> String {
    let o = gearwear(args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(o.status.success(), "gearwear {args:?} failed: {err}");
    err
}

/// `gearwear -q command` (a command and its options) of `config` (None: the paper's
/// case) with `sets` (`--set`), into `dir/name`, which it returns; requires success.
pub fn run_into(
    dir: &Path,
    name: &str,
    command: &[&str],
    config: Option<&str>,
    sets: &[&str],
) -> std::path::PathBuf {
    let out = dir.join(name);
    let mut a = vec!["-q"];
    a.extend(command);
    a.extend(["--out", out.to_str().unwrap()]);
    if let Some(c) = config {
        a.extend(["--config", c]);
    }
    for s in sets {
        a.extend(["--set", s]);
    }
    ok(&a);
    out
}

/// `gearwear sweep` with the cheap settings, `extra` arguments and `--out out`.
pub fn sweep(extra: &[&str], out: &Path) -> String {
    let mut a = vec!["sweep"];
    a.extend(CHEAP);
    a.extend(extra);
    a.extend(["--out", out.to_str().unwrap()]);
    ok(&a)
}

/// CSV as header and rows of cells.
pub fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let mut r = csv::Reader::from_path(path).unwrap();
    let h = r.headers().unwrap().iter().map(str::to_owned).collect();
    let rows = r
        .records()
        .map(|x| x.unwrap().iter().map(str::to_owned).collect())
        .collect();
    (h, rows)
}

/// Standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The studies built on the dynamic model (a sweep of two speeds among them), each as its
/// command and options: what a case the model refuses must be refused by.
pub fn studies_on_the_dynamic_model() -> [Vec<&'static str>; 5] {
    [
        vec!["dynamics"],
        vec!["wear"],
        vec!["run"],
        vec!["signals"],
        vec!["sweep", "--vary", "operating.input_speed_hz=20,30"],
    ]
}

/// `args` (a command and its options, `--out` added) must exit 2 with a message holding
/// every needle, no panic, and no output folder; returns the message.
pub fn rejected(args: &[&str], needles: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let mut all = args.to_vec();
    all.extend(["--out", out.to_str().unwrap()]);
    let o = gearwear(&all);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: message lacks `{n}`: {err}");
    }
    assert!(!err.contains("panicked"), "{err}");
    assert!(!out.exists(), "{args:?}: output written despite the error");
    err
}

/// `gearwear args` with its address space limited to `bytes` (Linux `RLIMIT_AS`): an
/// allocation sized by a forged count then fails instead of passing unnoticed.
#[cfg(target_os = "linux")]
pub fn gearwear_within_address_space(args: &[&str], bytes: u64) -> Output {
    use std::os::unix::process::CommandExt;
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_gearwear"));
    cmd.args(args);
    // SAFETY: only async-signal-safe setrlimit runs between fork and exec.
    unsafe {
        cmd.pre_exec(move || {
            let lim = libc::rlimit {
                rlim_cur: bytes,
                rlim_max: bytes,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    cmd.output().unwrap()
}

/// Every file under `dir` with its bytes (a before/after check that nothing changed).
pub fn snapshot(dir: &Path) -> std::collections::BTreeMap<std::path::PathBuf, Vec<u8>> {
    let mut all = std::collections::BTreeMap::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            all.extend(snapshot(&p));
        } else {
            all.insert(p.clone(), std::fs::read(&p).unwrap());
        }
    }
    all
}

/// `r` is an exit-2 refusal whose message holds every one of `needles` (and no panic or
/// allocation failure), that made no `out` folder and left every file under `dir` as
/// `before` (a [`snapshot`] taken just before the run).
pub fn assert_refused_touching_nothing(
    r: &Output,
    needles: &[&str],
    dir: &Path,
    out: &Path,
    before: &std::collections::BTreeMap<std::path::PathBuf, Vec<u8>>,
) {
    let e = stderr(r);
    assert_eq!(r.status.code(), Some(2), "{e}");
    assert!(
        !e.contains("panicked") && !e.contains("memory allocation"),
        "{e}"
    );
    for needle in needles {
        assert!(e.contains(needle), "message lacks `{needle}`: {e}");
    }
    assert!(!out.exists(), "an output despite the error");
    assert_eq!(&snapshot(dir), before, "files outside the output changed");
}

/// The files a folder's manifest lists, sorted.
pub fn manifest_files(dir: &Path) -> Vec<String> {
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap()).unwrap();
    let mut files: Vec<String> = m["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["path"].as_str().unwrap().to_owned())
        .collect();
    files.sort();
    files
}

/// The study `study` of a run in `run` holds, in `run/STUDY/`, exactly the files the
/// study's own command wrote into `alone` (its manifest's), byte for byte.
pub fn assert_nested_study(run: &Path, alone: &Path, study: &str) {
    let run_files = manifest_files(run);
    let files = manifest_files(alone);
    let prefix = format!("{study}/");
    let nested: Vec<&str> = run_files
        .iter()
        .filter_map(|f| f.strip_prefix(&prefix))
        .collect();
    assert_eq!(nested, files, "{study}: the run's files differ in name");
    for f in &files {
        let (a, b) = (
            std::fs::read(alone.join(f)).unwrap(),
            std::fs::read(run.join(study).join(f)).unwrap(),
        );
        assert!(
            a == b,
            "{study}/{f}: the run's bytes differ from `gearwear {study}`"
        );
    }
}

/// The published files of a folder (its manifest's) and its checkpoints, as bytes.
pub fn published(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files = manifest_files(dir);
    files.push("manifest.json".into());
    for e in std::fs::read_dir(dir).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        if name.starts_with("checkpoint_") {
            files.push(name);
        }
    }
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let b = std::fs::read(dir.join(&p)).unwrap();
            (p, b)
        })
        .collect()
}

/// A path that passes the pinion's y bearing force unchanged (1 m/s^2 per N, flat): a
/// record through it is the force itself, with no housing resonance of its own.
pub fn flat_path() -> gearwear::signals::transfer::TransferPath {
    use gearwear::signals::frf_table::{Frf, FrfTable};
    use gearwear::signals::transfer::{PathModel, TransferPath};
    use realfft::num_complex::Complex64;
    let mut frf: [Frf; 4] = Default::default();
    frf[1] = Frf {
        frequency_hz: vec![0.0, 1e6],
        value: vec![Complex64::new(1.0, 0.0); 2],
    };
    TransferPath {
        sensors: vec!["force".into()],
        model: PathModel::Table(FrfTable {
            sensors: vec!["force".into()],
            frf: vec![frf],
        }),
        description: "flat".into(),
        placement: "the pinion's y bearing force itself".into(),
    }
}

/// The number after `prefix` in `text` (up to the next space).
pub fn number_after(text: &str, prefix: &str) -> f64 {
    let i = text.find(prefix).unwrap_or_else(|| panic!("no `{prefix}`")) + prefix.len();
    text[i..]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap()
}
