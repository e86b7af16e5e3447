//! The duty cycle from the command line: wear and run under a spectrum, resuming from the
//! bins' checkpoints, the single-point outputs of a one-bin spectrum, and bad spectra
//! refused with exit code 2 before anything is computed.

mod common;
use common::gearwear;
use std::path::Path;

const THREE: &str = "[load_spectrum]\nbins = [{torque_nm = 40, input_speed_hz = 20, share = 0.5}, {torque_nm = 60, input_speed_hz = 30, share = 0.3}, {torque_nm = 80, input_speed_hz = 70, share = 0.2}]\n";

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

#[test]
fn a_one_bin_spectrum_writes_the_single_point_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let one = write(
        dir.path(),
        "one.toml",
        "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 1}]\n",
    );
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    for (args, out) in [(vec!["--config", one.as_str()], &a), (vec![], &b)] {
        let mut all = vec![
            "wear",
            "--set",
            "wear.total_cycles=1.5e4",
            "--out",
            out.to_str().unwrap(),
        ];
        all.extend(args);
        let o = gearwear(&all);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    for f in [
        "updates_dynamic.csv",
        "wear_profiles_quasi_static.csv",
        "csv/fig13_max_accumulated_wear.csv",
    ] {
        assert_eq!(
            std::fs::read(a.join(f)).unwrap(),
            std::fs::read(b.join(f)).unwrap(),
            "{f}"
        );
    }
}

#[test]
fn a_spectrum_run_resumes_from_uneven_bin_logs_to_the_same_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let case = write(dir.path(), "three.toml", THREE);
    let out = dir.path().join("w");
    let args = [
        "wear",
        "--mode",
        "dynamic",
        "--config",
        case.as_str(),
        "--out",
        out.to_str().unwrap(),
    ];
    let o = gearwear(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let full = std::fs::read(out.join("updates_dynamic.csv")).unwrap();
    let profiles = std::fs::read(out.join("csv/duty_wear_by_bin_dynamic.csv")).unwrap();
    // A kill between the appends of one update: bin 1's log holds 3 updates, bin 2's 4
    // and bin 3's 4 and half a line.
    for (bin, keep, torn) in [(1, 4, false), (2, 5, false), (3, 5, true)] {
        let p = out.join(format!("checkpoint_dynamic_bin{bin}.jsonl"));
        let text = std::fs::read_to_string(&p).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let mut cut = lines[..keep].join("\n") + "\n";
        if torn {
            cut.push_str(&lines[keep][..lines[keep].len() / 2]);
        }
        std::fs::write(&p, cut).unwrap();
    }
    let mut resumed = args.to_vec();
    resumed.push("--resume");
    let o = gearwear(&resumed);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        std::fs::read(out.join("updates_dynamic.csv")).unwrap(),
        full
    );
    assert_eq!(
        std::fs::read(out.join("csv/duty_wear_by_bin_dynamic.csv")).unwrap(),
        profiles
    );
    // An edited log is refused, naming the bin's file.
    let p = out.join("checkpoint_dynamic_bin2.jsonl");
    let text = std::fs::read_to_string(&p).unwrap();
    std::fs::write(&p, text.replacen("\"cycles\":0.0", "\"cycles\":1.0", 1)).unwrap();
    let o = gearwear(&resumed);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn bad_spectra_exit_2_naming_bin_key_and_range_and_nothing_is_computed() {
    let dir = tempfile::tempdir().unwrap();
    for (bins, want) in [
        ("{torque_nm = 60, input_speed_hz = 30, share = 0.6}, {torque_nm = 80, input_speed_hz = 30, share = 0.3}", "shares sum to 0.9"),
        ("{torque_nm = 60, input_speed_hz = 30, hours = 0}", "hours total 0"),
        ("{torque_nm = 60, input_speed_hz = 30, share = 0.5}, {torque_nm = -1, input_speed_hz = 30, share = 0.5}", "load_spectrum bin 2"),
        ("{torque_nm = 60, input_speed_hz = nan, share = 1}", "`input_speed_hz` = NaN"),
        ("{torque_nm = 60, input_speed_hz = 3000, share = 1}", "outside [1e-6, 1000]"),
        // In the key's range, beyond what the flanks carry (Hertz pressure > 10 GPa).
        ("{torque_nm = 60, input_speed_hz = 30, share = 0.5}, {torque_nm = 5e6, input_speed_hz = 30, share = 0.5}", "load_spectrum bin 2 (5000000 N m, 30 Hz): the bin's `torque_nm` = 5000000 is more"),
    ] {
        let case = write(dir.path(), "bad.toml", &format!("[load_spectrum]\nbins = [{bins}]\n"));
        let out = dir.path().join("never");
        // Without the budget check, so the model's own checks speak.
        let o = gearwear(&["--no-budget", "wear", "--config", &case, "--out", out.to_str().unwrap()]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{bins}: {err}");
        assert!(err.contains(want), "{bins}: {err}");
        assert!(!out.join("summary.json").exists(), "{bins}");
    }
}
