//! The run budget's estimate of a transient record (`gearwear signals` with a run-up or
//! a load fluctuation) against what the run really uses: its peak resident memory and
//! CPU time (user + system) measured by the kernel in a child process. The record's
//! memory is its internal grid at the record's peak (`study::budget::signals::
//! transient_grid_bytes`, 160 bytes a cell at eight cells a sample), its time the steps
//! of the mesh periods the drive spans (`transient_steps`). Issue 33: a 19 s run-up was
//! counted 1.52 GB (3000 bytes a record sample) against 0.50 GB measured, and refused at
//! 8192 x 4096 px though it peaks at 0.71 GB.

mod common;

use gearwear::config::load_case;
use gearwear::study::budget::estimate_signals;

/// Memory is the same on every machine and load (the allocations are the run's): the
/// count holds the 127 bytes a cell it can name and the allocator's retained transforms
/// (160), where 125-146 are measured: 1.15-1.45 times the peak of 1-19 s run-ups with the
/// base and the steady state's evaluation; twice the peak leaves no more than that, and
/// the old count (3000 bytes a sample) was 2.8-3.1 times it.
const MEMORY_FACTOR: f64 = 2.0;

/// Time, a run-up: counted on the reference machine's rates, an upper bound on the steps
/// per mesh period (the error control's at 0.5 Hz, ~1.5-3 times those taken at 30-60 Hz)
/// and twice the rates per record sample (`SLOWER_MACHINE_FACTOR`): measured 2.6-2.7
/// times the CPU time of 5-19 s run-ups on a shared 2-core machine (load 1-3); the CPU
/// time of one run varies 1.5-2 times with the machine's load (longer on a busy one:
/// shared caches and cores); 4 leaves that noise, and never under.
const RUN_UP_TIME_FACTOR: f64 = 4.0;

/// Time, a load fluctuation at steady speed: counted at its measured rates per mesh
/// period and its fixed part times `SLOWER_MACHINE_FACTOR` (2,
/// `study::budget::signals::steady_speed_transient_seconds`): 1.5-2.0 times the CPU time
/// of 1-10 s records at load 2 (2026-12-01), about 3 times on the quieter machine of
/// 2026-11-30 (2 and 5 s: 1.58 and 3.49 s). The target, 3 times; the CPU time
/// of one run varies about 1.5 times with the load of the shared machine (cache and
/// cores), which the factor 2 is for. (The count before, the run-up's bound of steps and
/// no fixed part, was 1.41 times a 2 s record's CPU time on the CI machine and 3.1 times
/// a 5 s one's.) The test allows 4: the counts stand 1.5-3 times over depending on the
/// machine's load, and a quiet run at 3 must not fail it (docs/RELIABILITY.md holds the
/// measured ratios against the 3).
const FLUCTUATION_TIME_FACTOR: f64 = 4.0;

/// Runs `gearwear signals` with `sets` measured, and checks the estimate against it:
/// memory never under and at most [`MEMORY_FACTOR`] x; time never under and at most
/// `time_factor` x.
fn check(sets: &[&str], time_factor: f64) {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let mut args = vec![
        "signals",
        "-q",
        "--no-budget",
        "--out",
        out.to_str().unwrap(),
    ];
    for s in sets {
        args.extend(["--set", s]);
    }
    let used = common::rusage::run(&args);
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    let case = load_case("", &sets).unwrap();
    // Two channels: the generic housing's sensors.
    let e = estimate_signals(&case, 2);
    let (bytes, secs) = (e.memory_bytes(), e.seconds());
    common::rusage::print_counted(&format!("{sets:?}"), bytes, secs, &used);
    assert!(
        bytes >= used.peak_bytes && bytes <= MEMORY_FACTOR * used.peak_bytes,
        "{sets:?}: {:.3e} B counted, {:.3e} B used",
        bytes,
        used.peak_bytes
    );
    assert!(
        secs >= used.cpu_s && secs <= time_factor * used.cpu_s,
        "{sets:?}: {secs:.2} s counted, {:.2} s of CPU used",
        used.cpu_s
    );
}

#[test]
#[cfg(target_os = "linux")]
fn a_run_up_is_counted_within_a_few_times_what_it_uses() {
    // A run-up to twice the speed.
    check(
        &["signals.record_length=3", "signals.ramp_end_speed_hz=60"],
        RUN_UP_TIME_FACTOR,
    );
}

#[test]
#[cfg(target_os = "linux")]
fn a_load_fluctuation_is_counted_within_a_few_times_at_every_length() {
    // 1, 2, 5 and 10 s at steady speed: the count's fixed part and its part per second
    // both measured (22 s of CPU in all at load 2).
    for length in ["1", "2", "5", "10"] {
        let l = format!("signals.record_length={length}");
        check(
            &[&l, "signals.torque_fluctuation_rms_nm=10"],
            FLUCTUATION_TIME_FACTOR,
        );
    }
}
