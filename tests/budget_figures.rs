//! The figures the run budget counts for a job (`study::budget::figures`, counted in time
//! one by one at a requested `--figure-size`) against the image files the job really
//! writes: for stiffness, dynamics, signals, wear and run on the paper's pair, a
//! tooth-resolved case, a load spectrum and a helical pair. The count must never be
//! below the files written (a figure not counted is time not counted, issue 33), nor
//! taller figures below the tall files; and it may exceed them by at most
//! [`SLACK`] (the bound counts figures the case cannot rule out before the run).

use std::path::{Path, PathBuf};
use std::process::Command;

use gearwear::config::load::load_case;
use gearwear::study::budget::figures::{
    dynamics_figures, run_figures, signals_figures, stiffness_figures, wear_figures,
};
use gearwear::study::budget::FigureCount;

/// Figures a count may hold beyond the files written: two (a tooth-resolved case's
/// tooth-pair stiffness in `stiffness`; a spectrum's load-duration figures counted per
/// mode), so that a figure dropped from a job, or one added to the count by mistake,
/// shows.
const SLACK: f64 = 2.0;

/// Height of a one-panel figure at the default size, px (`--figure-size` 900x420).
const ONE_PANEL_PX: u32 = 420;

/// Wear cycles of the wear and run jobs here: short runs (the figures do not depend on
/// the length).
const CYCLES: &str = "wear.total_cycles=1e4";

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("examples")
}

/// Every PNG under `dir`, with its height (the IHDR chunk: bytes 20-23, big-endian).
fn pngs(dir: &Path, into: &mut Vec<u32>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            pngs(&p, into);
        } else if p.extension().is_some_and(|x| x == "png") {
            let b = std::fs::read(&p).unwrap();
            into.push(u32::from_be_bytes([b[20], b[21], b[22], b[23]]));
        }
    }
}

/// Runs `command` on `config` (None: the built-in case) with `sets`; its PNG heights.
fn written(command: &str, config: Option<&str>, sets: &[&str]) -> Vec<u32> {
    let out = tempfile::tempdir().unwrap();
    let mut c = Command::new(env!("CARGO_BIN_EXE_gearwear"));
    c.args([command, "-q", "--no-budget", "--out"])
        .arg(out.path());
    if let Some(f) = config {
        c.arg("--config").arg(examples().join(f));
    }
    for s in sets {
        c.args(["--set", s]);
    }
    let o = c.output().unwrap();
    assert!(
        o.status.success(),
        "{command} {config:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let mut h = Vec::new();
    pngs(out.path(), &mut h);
    h
}

fn case(config: Option<&str>, sets: &[&str]) -> gearwear::config::case::Case {
    let text = config.map_or(String::new(), |f| {
        std::fs::read_to_string(examples().join(f)).unwrap()
    });
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    load_case(&text, &sets).unwrap()
}

/// The count against the files: never below in all or in tall figures, at most
/// [`SLACK`] above.
fn check(what: &str, counted: FigureCount, heights: &[u32]) {
    let files = heights.len() as f64;
    let tall = heights.iter().filter(|h| **h > ONE_PANEL_PX).count() as f64;
    assert!(files > 0.0, "{what}: no figure written");
    assert!(
        counted.total() >= files && counted.taller >= tall,
        "{what}: {files} figures written ({tall} tall), counted {counted:?}"
    );
    assert!(
        counted.total() <= files + SLACK,
        "{what}: {files} figures written, counted {counted:?}"
    );
}

fn all_jobs(config: Option<&str>, with_run: bool) {
    let c = case(config, &[CYCLES]);
    let name = config.unwrap_or("built-in case");
    check(
        &format!("stiffness, {name}"),
        stiffness_figures(&c),
        &written("stiffness", config, &[]),
    );
    check(
        &format!("dynamics, {name}"),
        dynamics_figures(&c),
        &written("dynamics", config, &[]),
    );
    check(
        &format!("signals, {name}"),
        signals_figures(&c),
        &written("signals", config, &[]),
    );
    check(
        &format!("wear, {name}"),
        wear_figures(&c, 2),
        &written("wear", config, &[CYCLES]),
    );
    if with_run {
        check(
            &format!("run, {name}"),
            run_figures(&c),
            &written("run", config, &[CYCLES]),
        );
    }
}

#[test]
fn the_papers_pair() {
    all_jobs(None, true);
}

#[test]
fn a_helical_pair() {
    all_jobs(Some("helical_pair.toml"), true);
}

#[test]
fn a_load_spectrum() {
    all_jobs(Some("duty_cycle/three_bins.toml"), true);
}

/// A tooth-resolved case (its `run` takes two minutes: its figures are the paper's and
/// the teeth's of `wear` and `dynamics`, checked here).
#[test]
fn a_tooth_resolved_case() {
    all_jobs(Some("teeth/grade6_runout_spall.toml"), false);
}

/// A run-up record draws its order tracks and Campbell diagram besides.
#[test]
fn a_run_up_record() {
    let sets = ["signals.ramp_end_speed_hz=40", "signals.record_length=0.5"];
    let c = case(None, &sets);
    check(
        "signals, run-up",
        signals_figures(&c),
        &written("signals", None, &sets),
    );
}

/// The widest figure the cost model counts with (the study layer cannot import the
/// report's raster bound) is the raster's bound.
#[test]
fn the_widest_figure_counted_is_the_rasters_bound() {
    assert_eq!(
        gearwear::study::budget::figures::WIDEST_FIGURE_PX,
        f64::from(gearwear::report::plot::MAX_SIDE_PX)
    );
}
