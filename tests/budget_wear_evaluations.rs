//! The run budget's time of a dynamic wear study (`gearwear wear --mode dynamic`: one
//! cold steady-state search, then warm updates from the previous update's periodic
//! state, `study::budget::steady_states`) against the CPU time the command takes (user +
//! system, measured by the kernel in a child process, `common::rusage`). The estimate is
//! read from the command's own refusal under a vanishing budget, so that it is the one the
//! job checks (every term: the evaluations, the tables, the figures, the checkpoints).
//! Issue 29: every update was counted as a cold search of 30 periods and the recorded
//! window, at the error control's steps of 0.5 Hz: the two-stage reducer's study at 28
//! times its CPU time, the paper's pair's at 7 times, and a study of 30 s refused as over
//! 10 minutes.

mod common;

/// Counted over measured at most this. The rates are measured on an idle machine and
/// doubled (`SLOWER_MACHINE_FACTOR`: a shared core's cache and clock make the same work
/// up to ~1.5-2 times dearer in CPU time), and the periods and steps are upper bounds at
/// the hard corners (0.2 Hz, tight tolerances), so on an idle machine the count is
/// about 1.5-3 times the CPU time and, under the load of other builds, less. Measured
/// 2026-12-01 on the quiet machine (load 1.4): 2.1-2.9 x, the planetary set 3.75 x (its
/// steady state 29 % cheaper since the stepper keeps its iteration matrix as blocks; its
/// rates were measured before) and the helical pair 4.9 x (its slice contacts counted
/// at the adaptive sample count's bound, `budget::helical::SECONDS_PER_SLICE_CONTACT`);
/// under load 1.4-3.2 x. 6 leaves that spread; never under.
const TIME_FACTOR: f64 = 6.0;

/// The estimated seconds of `gearwear wear --mode dynamic args`, from its refusal.
fn estimated_seconds(args: &[&str]) -> f64 {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let mut all = vec![
        "wear",
        "--mode",
        "dynamic",
        "--budget-scale",
        "1e-9",
        "--out",
        out.to_str().unwrap(),
    ];
    all.extend(args);
    let o = common::gearwear(&all);
    let err = common::stderr(&o);
    assert!(!o.status.success(), "{args:?}: not refused: {err}");
    let at = err
        .find("time ~")
        .unwrap_or_else(|| panic!("{args:?}: {err}"))
        + 6;
    let number: String = err[at..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == 'e' || *c == '-')
        .collect();
    let t: f64 = number.parse().unwrap_or_else(|_| panic!("{args:?}: {err}"));
    // The estimate is shown in s, min or h (`format` of the budget's message).
    let unit: String = err[at + number.len()..]
        .trim_start()
        .chars()
        .take_while(|c| c.is_alphabetic())
        .collect();
    match unit.as_str() {
        "s" => t,
        "min" => 60.0 * t,
        "h" => 3600.0 * t,
        u => panic!("{args:?}: unit `{u}` in {err}"),
    }
}

/// CPU seconds of `gearwear wear --mode dynamic args` without the budget.
fn measured_seconds(args: &[&str]) -> f64 {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let mut all = vec![
        "wear",
        "-q",
        "--mode",
        "dynamic",
        "--no-budget",
        "--out",
        out.to_str().unwrap(),
    ];
    all.extend(args);
    common::rusage::run(&all).cpu_s
}

#[test]
#[cfg(target_os = "linux")]
fn a_dynamic_wear_study_is_counted_within_a_few_times_its_cpu_time() {
    let root = env!("CARGO_MANIFEST_DIR");
    let config = |f: &str| format!("{root}/examples/{f}");
    let train = config("two_stage_reducer.toml");
    let teeth = config("teeth/grade6_runout_spall.toml");
    let planetary = config("planetary_set.toml");
    let helical = config("helical_pair.toml");
    let cases: Vec<(&str, Vec<&str>)> = vec![
        ("the paper's pair", vec![]),
        ("two-stage reducer", vec!["--config", &train]),
        // Slow: the error control's most steps per mesh period.
        (
            "0.2 Hz input",
            vec!["--set", "operating.input_speed_hz=0.2"],
        ),
        // Tight: more shooting periods, cold and warm.
        (
            "steady_state_tolerance 1e-10",
            vec!["--set", "numerics.steady_state_tolerance=1e-10"],
        ),
        // Tooth-resolved: every update, cold or warm, passes over the hunting period of
        // 589 mesh periods.
        (
            "grade 6, run-out, spall (589 periods)",
            vec!["--config", &teeth, "--set", "wear.total_cycles=5e3"],
        ),
        ("helical pair", vec!["--config", &helical]),
        ("planetary set", vec!["--config", &planetary]),
    ];
    let mut failures = Vec::new();
    for (name, args) in &cases {
        let counted = estimated_seconds(args);
        let used = measured_seconds(args);
        let ratio = counted / used;
        eprintln!("{name}: counted {counted:.3} s, used {used:.3} s of CPU ({ratio:.2} x)");
        if !(counted >= used && counted <= TIME_FACTOR * used) {
            failures.push(format!("{name}: {counted:.3} s counted, {used:.3} s used"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
