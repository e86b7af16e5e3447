//! Issue 33's hostile designs, each refused before any work (exit 2, a message naming the
//! key or file, no output folder), under a limited address space so that an input which
//! slipped through to a huge allocation fails the test instead of the machine: a record
//! count that overflows, records longer or denser than the budget allows, more sensors
//! than the budget allows, fault labels the case does not model, settings a dataset
//! cannot honour, a chain that changes between conditions, sensor names that collide.

mod common;

use common::{assert_refused_touching_nothing, gearwear_within_address_space, snapshot};
use std::path::Path;

/// 1 GiB of address space: far below what any of these designs would take if run.
const ADDRESS_SPACE: u64 = 1 << 30;

/// Write `design` (and `extra` files beside it) in a fresh folder, run `dataset` on it
/// into `out` (not created), and require a refusal naming every needle that touched
/// nothing.
fn refused(design: &str, extra: &[(&str, &str)], args: &[&str], needles: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), design).unwrap();
    for (name, text) in extra {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    let before = snapshot(dir.path());
    let out = dir.path().join("out");
    let design_path = dir.path().join("design.toml");
    let mut a = vec![
        "dataset",
        "--design",
        design_path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "-q",
    ];
    a.extend(args);
    let r = gearwear_within_address_space(&a, ADDRESS_SPACE);
    assert_refused_touching_nothing(&r, needles, dir.path(), &out, &before);
}

fn list(n: usize, first: f64, step: f64) -> String {
    (0..n)
        .map(|i| format!("{}", first + step * i as f64))
        .collect::<Vec<_>>()
        .join(", ")
}

#[test]
fn a_record_count_that_overflows_is_refused_naming_the_axes() {
    // 8192 states x 65536 speeds x 65536 loads x 524288 realisations = 2^64 records,
    // which wrapped to 0, passed the disk budget and aborted on a 256 TiB allocation.
    let design = format!(
        "[run_to_failure]\nstates = 8192\n[operating]\ninput_speed_hz = [{}]\nload_torque_nm = [{}]\n[records]\nnoise_realisations = 524288\n",
        list(65536, 10.0, 1e-3),
        list(65536, 10.0, 1e-3)
    );
    refused(
        &design,
        &[],
        &[],
        &["records", "2^53", "noise realisations"],
    );
    // Under 2^64 but over 2^53: refused too (ids must stay exact as numbers).
    let design = format!(
        "[run_to_failure]\nstates = 8192\n[operating]\ninput_speed_hz = [{}]\nload_torque_nm = [{}]\n[records]\nnoise_realisations = 1000000\n",
        list(4096, 10.0, 1e-3),
        list(1024, 10.0, 1e-3)
    );
    refused(&design, &[], &["--no-budget"], &["2^53"]);
}

#[test]
fn the_run_budget_counts_each_record_length_and_sampling_rate() {
    // One 10 s record at 10 MHz (refused at once by `signals`) ran 54 s in a design and
    // aborted at 4 GiB: the budget now counts its 1e8 samples.
    let design = "set = [\"signals.sampling_rate_hz=1e7\", \"signals.record_length=10\"]\n[records]\ndisk_budget_gib = 1000\n";
    refused(
        design,
        &[],
        &[],
        &["over its budget", "signals.sampling_rate_hz"],
    );
    // 100 s at the default rate, 1000 realisations: time, not memory (each further
    // realisation of 2.56e6 samples counted at about 2.6 s: 2600 s against 600 s).
    let design = "set = [\"signals.record_length=100\"]\n[records]\nnoise_realisations = 1000\ndisk_budget_gib = 1000\n";
    refused(design, &[], &[], &["over its budget", "records"]);
}

#[test]
fn the_run_budget_counts_the_sensors() {
    // 5000 sensors of a modal path: 5000 channels a sample.
    let n = 5000;
    let sensors = (0..n)
        .map(|i| format!("\"s{i}\""))
        .collect::<Vec<_>>()
        .join(", ");
    let gains = vec!["[0.0075, 0.025, 0.005, 0.02]"; n].join(", ");
    let path = format!(
        "sensors = [{sensors}]\n[[mode]]\nfrequency_hz = 2100.0\ndamping_ratio = 0.02\ngains_per_kg = [{gains}]\n"
    );
    let design = "transfer_path = \"path.toml\"\nset = [\"signals.record_length=4\"]\n[records]\ndisk_budget_gib = 1000\nnoise_realisations = 4\n";
    refused(
        design,
        &[("path.toml", &path)],
        &[],
        &["over its budget", "sensors"],
    );
}

#[test]
fn fault_labels_must_be_what_the_case_models() {
    // "crack" with no crack in the case: its records equalled the healthy ones.
    let crack_without_crack = "[[condition]]\nname = \"healthy\"\n[[condition]]\nname = \"c\"\nfault = \"crack\"\nseverity = 2.0\n";
    refused(
        crack_without_crack,
        &[],
        &[],
        &["condition 2", "`fault` = \"crack\"", "\"none\""],
    );
    // A misspelt label beside a real crack.
    let typo = "[[condition]]\nname = \"c\"\nfault = \"crak\"\nseverity = 1\n[[condition.case.fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 0\ncrack_depth_mm = 1.0\n";
    refused(typo, &[], &[], &["`fault` = \"crak\"", "\"crack\""]);
    // A severity with no fault, and a negative one.
    let severity = "[[condition]]\nname = \"h\"\nseverity = 2.0\n";
    refused(severity, &[], &[], &["`severity` = 2", "no fault"]);
    let negative = "[[condition]]\nname = \"c\"\nseverity = -1\n[[condition.case.fault]]\nkind = \"spall\"\ngear = \"gear\"\ntooth = 3\nspall_position_mm = 0.0\nspall_length_mm = 1.0\nspall_depth_um = 20\n";
    refused(negative, &[], &[], &["`severity` = -1", "\"spall\""]);
}

#[test]
fn settings_a_dataset_cannot_honour_are_refused_naming_the_key() {
    // A run-up gave steady 30 Hz records; a torque fluctuation gave records identical to
    // none; the metadata listed both as used.
    refused(
        "set = [\"signals.ramp_end_speed_hz=60\", \"signals.record_length=1\"]\n",
        &[],
        &[],
        &["`signals.ramp_end_speed_hz` = 60", "steady"],
    );
    refused(
        "set = [\"signals.torque_fluctuation_rms_nm=10\"]\n",
        &[],
        &[],
        &["`signals.torque_fluctuation_rms_nm` = 10"],
    );
}

#[test]
fn one_chain_for_every_condition() {
    // A condition in g beside one in m/s^2 wrote 9.18 beside 90.06 in one column; a
    // condition with another sampling rate was not in the metadata.
    let unit = "[[condition]]\nname = \"a\"\n[[condition]]\nname = \"b\"\n[condition.case.signals]\nchannel_unit = \"g\"\n";
    refused(unit, &[], &[], &["condition `b`", "`signals.channel_unit`"]);
    let rate = "[[condition]]\nname = \"a\"\n[[condition]]\nname = \"b\"\n[condition.case.signals]\nsampling_rate_hz = 51200\n";
    refused(rate, &[], &[], &["`signals.sampling_rate_hz`"]);
}

#[test]
fn sensor_names_that_collide_are_refused() {
    let modal = |sensors: &str, rows: usize| {
        format!(
            "sensors = {sensors}\n[[mode]]\nfrequency_hz = 2100\ndamping_ratio = 0.02\ngains_per_kg = [{}]\n",
            vec!["[0.0075, 0.025, 0.005, 0.02]"; rows].join(", ")
        )
    };
    let design = "transfer_path = \"path.toml\"\n";
    for (sensors, rows, needle) in [
        ("[\"a\", \"a\"]", 2, "\"a\" is named twice"),
        ("[\"\"]", 1, "empty name"),
        ("[\"x\", \"x_pinion_tsa\"]", 2, "`x_pinion_tsa_rms`"),
        ("[\"a\", \"a_gear_tsa\"]", 2, "`a_gear_tsa_rms`"),
    ] {
        refused(
            design,
            &[("path.toml", &modal(sensors, rows))],
            &[],
            &[needle],
        );
    }
}

#[test]
fn a_refusal_leaves_an_existing_folder_as_it_was() {
    // The refusals above run before the folder is touched: a folder that exists is left
    // as it was (its files byte for byte).
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("keep.txt"), "mine").unwrap();
    std::fs::write(
        dir.path().join("design.toml"),
        "[[condition]]\nname = \"c\"\nfault = \"crack\"\nseverity = 1\n",
    )
    .unwrap();
    let before = snapshot(dir.path());
    let d = dir.path().join("design.toml");
    let r = gearwear_within_address_space(
        &[
            "dataset",
            "--design",
            d.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "-q",
        ],
        ADDRESS_SPACE,
    );
    assert_eq!(r.status.code(), Some(2));
    assert_eq!(snapshot(dir.path()), before);
    assert!(Path::new(&out.join("keep.txt")).exists());
}

#[test]
fn a_trajectory_longer_than_a_dataset_folder_keeps_is_refused_before_any_work() {
    // 1e11 cycles in blocks of 10: about 1e10 updates of ~1 kB, far over the 1 GiB a
    // trajectory file may hold; refused even without a run budget, naming the key.
    refused(
        "set = [\"wear.block_cycles=10\"]\n[run_to_failure]\nmax_cycles = 1e11\nstates = 2\n",
        &[],
        &["--no-budget"],
        &["run_to_failure.max_cycles", "trajectory", "GiB"],
    );
}

#[test]
fn non_finite_values_of_every_numeric_design_field_are_refused_naming_it() {
    // Each numeric key of a design (its whole numbers too) at nan, inf and -inf.
    for v in ["nan", "inf", "-inf", "+inf"] {
        for (text, key) in [
            (format!("seed = {v}\n"), "seed"),
            (format!("[run_to_failure]\nstates = {v}\n"), "run_to_failure.states"),
            (format!("[run_to_failure]\ncycles = [0, {v}]\n"), "run_to_failure.cycles"),
            (format!("[run_to_failure]\nmax_cycles = {v}\n"), "run_to_failure.max_cycles"),
            (format!("[run_to_failure]\nwear_limit_um = {v}\n"), "run_to_failure.wear_limit_um"),
            (format!("[operating]\ninput_speed_hz = [30, {v}]\n"), "operating.input_speed_hz"),
            (format!("[operating]\nload_torque_nm = [{v}]\n"), "operating.load_torque_nm"),
            (format!("[records]\nnoise_realisations = {v}\n"), "records.noise_realisations"),
            (format!("[records]\ndisk_budget_gib = {v}\n"), "records.disk_budget_gib"),
            (format!("[[condition]]\nname = \"a\"\nseverity = {v}\n"), "severity"),
            (
                format!("[[condition]]\nname = \"a\"\n[condition.case.operating]\nload_torque_nm = {v}\n"),
                "operating.load_torque_nm",
            ),
        ] {
            refused(&text, &[], &[], &[key]);
        }
    }
}
