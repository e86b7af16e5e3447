//! Helpers shared by the tests that run the binary.
#![allow(dead_code)]

pub mod linear;
pub mod paper;

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
