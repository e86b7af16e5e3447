//! Numbers printed for people: every number on standard output carries at most four
//! significant digits unless it is a whole number (a count, an exact input), the file
//! behind it keeps every digit, exact values print exactly, and the results line says
//! what was written (`gearwear::format`, the rule).

mod common;

use common::{gearwear, CHEAP};
use std::path::Path;

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Run and require success; returns (stdout, stderr).
fn run(args: &[&str]) -> (String, String) {
    let o = gearwear(args);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert!(o.status.success(), "gearwear {args:?} failed: {err}");
    (out, err)
}

/// The numbers of a line of text: tokens that parse as f64 once the punctuation around
/// them is cut ("(+33.3", "1.602;", "[1.2e-3,").
fn numbers(text: &str) -> Vec<String> {
    text.split_whitespace()
        .map(|t| {
            t.trim_matches(|c: char| "()[],;:".contains(c))
                .trim_start_matches('+')
                .to_owned()
        })
        .filter(|t| t.parse::<f64>().is_ok() && t.chars().any(|c| c.is_ascii_digit()))
        .collect()
}

/// Significant digits written in `t`: the mantissa's digits without leading zeros.
fn significant_digits(t: &str) -> usize {
    let mantissa = t.split(['e', 'E']).next().unwrap_or(t);
    mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .skip_while(|&c| c == '0')
        .count()
}

/// Every number of `stdout` that is not whole has at most four significant digits.
fn assert_for_people(stdout: &str) {
    assert!(!stdout.trim().is_empty(), "no headline");
    for t in numbers(stdout) {
        let whole = !t.contains(['.', 'e', 'E']);
        assert!(
            whole || significant_digits(&t) <= 4,
            "{t} has more than four significant digits in:\n{stdout}"
        );
    }
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The number after `label` in `line`.
fn after(line: &str, label: &str) -> f64 {
    let rest = &line[line
        .find(label)
        .unwrap_or_else(|| panic!("{label} in {line}"))
        + label.len()..];
    numbers(rest)[0].parse().unwrap()
}

/// The shown value is the file's value to four significant digits: within half a unit
/// of the fourth digit, and the file holds more digits than the screen.
fn assert_rounded(shown: f64, full: f64) {
    assert!(
        (shown - full).abs() <= 0.5e-3 * full.abs() * (1.0 + 1e-12),
        "shown {shown} is not {full} to four digits"
    );
}

#[test]
fn dynamics_headline_is_rounded_and_the_summary_keeps_every_digit() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("dyn");
    let (stdout, stderr) = run(&["dynamics", "--out", out.to_str().unwrap()]);
    assert_for_people(&stdout);
    let v = json(&out.join("summary.json"));
    let full = v["dte"]["max_um"].as_f64().unwrap();
    let shown = after(&stdout, "max DTE");
    assert_rounded(shown, full);
    assert_ne!(
        shown, full,
        "the summary keeps the digits the headline drops"
    );
    assert_rounded(
        after(&stdout, "mean mesh force"),
        v["mesh_force"]["mean_n"].as_f64().unwrap(),
    );
    // 19 teeth x 30 Hz is 570 Hz exactly, in the file too.
    assert_eq!(v["mesh_frequency_hz"].as_f64(), Some(570.0));
    // The results line counts what the folder holds.
    let tree = common::figures::tree(&out);
    let count = |ext: &str| tree.keys().filter(|k| k.ends_with(ext)).count();
    let (pngs, csvs) = (count(".png"), count(".csv"));
    let line = stderr
        .lines()
        .find(|l| l.starts_with("dynamics: "))
        .unwrap_or_else(|| panic!("no results line in {stderr}"));
    assert!(
        line.contains(&format!("summary, {pngs} figures, {csvs} tables -> ")),
        "{line}: {pngs} PNG, {csvs} CSV"
    );
    assert!(line.ends_with(std::path::MAIN_SEPARATOR), "{line}");
}

#[test]
fn run_comparison_and_stiffness_headlines_are_for_people() {
    let d = tempfile::tempdir().unwrap();
    let (stdout, stderr) = run(&["run", "--out", d.path().join("r").to_str().unwrap()]);
    assert_for_people(&stdout);
    assert_eq!(stdout.lines().count(), 11, "{stdout}");
    assert!(
        stderr.contains("run: report, summary, "),
        "the results line names the report: {stderr}"
    );
    let (stdout, _) = run(&["stiffness", "--out", d.path().join("s").to_str().unwrap()]);
    assert_for_people(&stdout);
    // Contact ratio 1.6022 of the paper's pair (docs/MODEL.md) to four digits.
    assert!(stdout.contains("contact ratio 1.602;"), "{stdout}");
}

#[test]
fn signals_headline_has_every_channel_and_exact_shaft_speeds() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sig");
    let mut args = vec!["signals", "--out", out.to_str().unwrap()];
    args.extend(CHEAP);
    let (stdout, _) = run(&args);
    assert_for_people(&stdout);
    let v = json(&out.join("summary.json"));
    let channels = v["indicators"].as_array().unwrap();
    assert_eq!(stdout.lines().count(), channels.len(), "{stdout}");
    for c in channels {
        let name = c["channel"].as_str().unwrap();
        assert!(
            stdout.contains(&format!("{name}: RMS ")),
            "{name}: {stdout}"
        );
    }
    let k = &v["kinematics"];
    assert_eq!(k["mesh_hz"].as_f64(), Some(570.0), "{k}");
    assert_eq!(k["pinion_shaft_hz"].as_f64(), Some(30.0), "{k}");
}

#[test]
fn load_spectrum_and_duty_wear_headlines_are_for_people() {
    let d = tempfile::tempdir().unwrap();
    let root = env!("CARGO_MANIFEST_DIR");
    let history = format!("{root}/examples/duty_cycle/history.csv");
    let (stdout, _) = run(&[
        "load-spectrum",
        "--history",
        &history,
        "--out",
        d.path().join("ls").to_str().unwrap(),
    ]);
    assert_for_people(&stdout);
    let config = format!("{root}/examples/duty_cycle/three_bins.toml");
    let mut args = vec![
        "wear",
        "--config",
        &config,
        "--mode",
        "dynamic",
        "--set",
        "wear.total_cycles=2e4",
        "--out",
    ];
    let out = d.path().join("w");
    args.push(out.to_str().unwrap());
    args.extend(CHEAP);
    let (stdout, _) = run(&args);
    assert_for_people(&stdout);
    assert!(stdout.contains("of the pinion's wear"), "{stdout}");
    // `wear` gives the life under the spectrum, printed in cycles and hours and recorded.
    let line = stdout
        .lines()
        .find(|l| l.starts_with("life to 10 µm (dynamic): "))
        .unwrap_or_else(|| panic!("no life line in {stdout}"));
    let v = json(&out.join("summary.json"));
    let life = &v["load_spectrum"]["life"];
    let cycles = life["spectrum"]["cycles"].as_f64().unwrap();
    let hours = life["spectrum_hours"].as_f64().unwrap();
    assert_rounded(after(line, "(dynamic):"), cycles);
    assert_rounded(after(line, "cycles ("), hours);
    // Hours from the bins alone: 0.5 / 20 Hz + 0.3 / 30 Hz + 0.2 / 45 Hz seconds per
    // pinion revolution (examples/duty_cycle/three_bins.toml).
    let s_per_cycle = 0.5 / 20.0 + 0.3 / 30.0 + 0.2 / 45.0;
    assert!(
        (hours - cycles * s_per_cycle / 3600.0).abs() <= 1e-12 * hours,
        "{hours} h for {cycles} cycles"
    );
    assert!(out.join("csv/duty_life.csv").exists());
}
