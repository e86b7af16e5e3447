//! `gearwear load-spectrum`: a measured history to the spectrum a case reads, checked
//! against a history whose time at level is known exactly; bad histories and options exit
//! 2 naming the row, the column or the option, and write nothing.

mod common;
use common::gearwear;
use gearwear::config::load::load_case_in;
use std::path::Path;

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A square wave, 3 s at 20 N m then 1 s at 80 N m, ten periods, at 1500 rpm (25 Hz),
/// sampled every 0.5 s so that the switches fall on samples.
/// `gearwear load-spectrum --history history --out out` with `extra` arguments.
fn load_spectrum(history: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "load-spectrum",
        "--history",
        history.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend(extra);
    gearwear(&args)
}

fn square_wave() -> String {
    sampled(
        "time_s,torque_nm,input_speed_rpm,oil_temp_c",
        80,
        |i| if (0.5 * i as f64) % 4.0 < 3.0 { 20 } else { 80 },
        "1500,40",
    )
}

/// A history sampled every 0.5 s, samples 0 to `last`: time, `torque(i)`, then `rest`.
fn sampled(header: &str, last: usize, torque: impl Fn(usize) -> i32, rest: &str) -> String {
    let mut t = format!("{header}\n");
    for i in 0..=last {
        t.push_str(&format!("{},{},{rest}\n", 0.5 * i as f64, torque(i)));
    }
    t
}

#[test]
fn a_history_becomes_the_spectrum_a_case_reads() {
    let dir = tempfile::tempdir().unwrap();
    let h = dir.path().join("history.csv");
    std::fs::write(&h, square_wave()).unwrap();
    let out = dir.path().join("ls");
    let o = load_spectrum(
        &h,
        &out,
        &["--interpolation", "hold", "--torque-shaft", "gear"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    // Held between samples, the counts are exact (30 s and 10 s at 25 Hz: 750 and 250
    // revolutions), so the shares 0.75 / 0.25 and the torques are exact binary numbers.
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["time"]["under_load_s"], 40.0);
    assert_eq!(s["time"]["idle_s"], 0.0);
    assert_eq!(s["time"]["span_s"], 40.0);
    assert_eq!(s["pinion_revolutions_under_load"], 1000.0);
    for f in [
        "ldd_time_at_level.png",
        "ldd.csv",
        "csv/ldd_time_at_level.csv",
    ] {
        assert!(out.join(f).is_file(), "{f}");
    }
    // The CSV, read as a case's load_spectrum.file (relative to the case's folder), and
    // the TOML section, pasted into a case, give the same bins.
    let by_file = load_case_in(
        "[load_spectrum]\nfile = \"ls/spectrum.csv\"\ntorque_shaft = \"gear\"\n",
        &[],
        dir.path(),
    )
    .unwrap();
    let toml = std::fs::read_to_string(out.join("load_spectrum.toml")).unwrap();
    let pasted = load_case_in(&toml, &[], Path::new(".")).unwrap();
    let (a, b) = (
        by_file.load_spectrum.unwrap(),
        pasted.load_spectrum.unwrap(),
    );
    assert_eq!(a, b);
    assert_eq!(a.bins.len(), 2);
    assert_eq!(
        (
            a.bins[0].torque_nm,
            a.bins[0].input_speed_hz,
            a.bins[0].share
        ),
        (20.0, 25.0, 0.75)
    );
    assert_eq!(
        (
            a.bins[1].torque_nm,
            a.bins[1].input_speed_hz,
            a.bins[1].share
        ),
        (80.0, 25.0, 0.25)
    );
    assert_eq!(
        a.torque_shaft,
        Some(gearwear::config::case::TorqueShaft::Gear)
    );
}

#[test]
fn bad_histories_and_options_exit_2_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("never");
    let header = "time_s,torque_nm,input_speed_hz\n";
    for (body, expect) in [
        (
            "0,10,30\n1,nan,30\n2,10,30\n",
            "row 2 (line 3): `torque_nm`",
        ),
        (
            "0,10,30\n2,10,30\n1,10,30\n",
            "row 3 (line 4): `time_s` = 1",
        ),
        (
            "0,10,30\n1,10,30\n2,10,\n",
            "row 3 (line 4): `input_speed_hz`",
        ),
        ("0,-5,30\n1,-5,30\n", "no time under load"),
        // Issue 33: 1e307 N m and 1e308 Hz were read, giving `inf` in the spectrum and
        // null shares with exit 0; each column now has its range.
        (
            "0,10,30\n1,1e307,30\n2,10,30\n",
            "row 2 (line 3): `torque_nm` = 1e307 is out of range",
        ),
        (
            "0,10,30\n1,10,1e308\n2,10,30\n",
            "row 2 (line 3): `input_speed_hz` = 1e308 is out of range",
        ),
    ] {
        let h = dir.path().join("h.csv");
        std::fs::write(&h, format!("{header}{body}")).unwrap();
        let o = load_spectrum(&h, &out, &[]);
        assert_eq!(o.status.code(), Some(2), "{body}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(e.contains("--history") && e.contains(expect), "{e}");
        assert!(!out.exists());
    }
    // A spreadsheet's CSV in a decimal-comma locale: one column; the separator named.
    let h = dir.path().join("semicolon.csv");
    std::fs::write(
        &h,
        "time_s;torque_nm;input_speed_hz\n0;10,5;30\n1;10,5;30\n",
    )
    .unwrap();
    let o = load_spectrum(&h, &out, &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("separated by `;`"), "{}", stderr(&o));
    assert!(!out.exists());
    // 1 s sampling with a 60 s hole: a gap, named by its rows.
    let mut t = String::from(header);
    for i in (0..20).chain(80..100) {
        t.push_str(&format!("{i},10,30\n"));
    }
    let h = dir.path().join("gap.csv");
    std::fs::write(&h, t).unwrap();
    let o = load_spectrum(&h, &out, &["--speed-classes", "51"]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    // The options are checked first, all of them.
    assert!(
        e.contains("--speed-classes 51") && e.contains("[1, 50]"),
        "{e}"
    );
    let o = load_spectrum(&h, &out, &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("rows 20 and 21"), "{}", stderr(&o));
    assert!(!out.exists());
}

/// 100 s at 20 N m and 25 Hz, sampled every 0.5 s and held, with one held sample at
/// 80 N m and one at 50 N m: 12.5 of the 2500 revolutions (0.5 %) at each transient.
fn history_with_two_transients() -> String {
    let torque = |i| match i {
        20 => 80,
        100 => 50,
        _ => 20,
    };
    sampled("time_s,torque_nm,input_speed_hz", 200, torque, "25")
}

#[test]
fn bins_below_the_merge_share_join_their_nearest_keeping_revolutions_and_torque() {
    let dir = tempfile::tempdir().unwrap();
    let h = dir.path().join("history.csv");
    std::fs::write(&h, history_with_two_transients()).unwrap();
    let spectrum = |share: &str| {
        let out = dir.path().join(format!("ls{share}"));
        let o = load_spectrum(
            &h,
            &out,
            &["--interpolation", "hold", "--merge-below-share", share],
        );
        assert!(o.status.success(), "{}", stderr(&o));
        let s: serde_json::Value =
            serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
        (s, String::from_utf8_lossy(&o.stdout).into_owned())
    };
    // Below 0.5 %: every bin is kept, the two transients each 0.005 of the revolutions.
    let (kept, _) = spectrum("0.001");
    assert_eq!(kept["bins"], 3);
    assert_eq!(kept["merged_bins"]["merged"], 0);
    // Above it: both join the one bin left, whose torque keeps the torque-revolution
    // integral, (20 x 2475 + 80 x 12.5 + 50 x 12.5) / 2500 = 20.45 N m, at 25 Hz.
    let (merged, stdout) = spectrum("0.01");
    assert_eq!(merged["bins"], 1);
    assert_eq!(merged["merged_bins"]["merged"], 2);
    let share = merged["merged_bins"]["merged_share"].as_f64().unwrap();
    assert!((share - 0.01).abs() < 1e-12, "{share}");
    let bin = &merged["load_spectrum"]["bins"][0];
    // Sums of a few exact binary numbers: a rounding or two of 20.45.
    assert!((bin["torque_nm"].as_f64().unwrap() - 20.45).abs() < 1e-12);
    assert!((bin["input_speed_hz"].as_f64().unwrap() - 25.0).abs() < 1e-12);
    assert_eq!(bin["share"], 1.0);
    assert_eq!(
        merged["pinion_revolutions_under_load"],
        kept["pinion_revolutions_under_load"]
    );
    assert!(
        stdout.contains("2 bins holding 1") && stdout.contains("of the revolutions merged"),
        "{stdout}"
    );
    // Out of range: exit 2 naming the option and its range, nothing written.
    for bad in ["0.2", "-0.001", "NaN"] {
        let out = dir.path().join("never");
        let o = load_spectrum(&h, &out, &["--merge-below-share", bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        let e = stderr(&o);
        assert!(
            e.contains("--merge-below-share") && e.contains("[0, 0.1]"),
            "{e}"
        );
        assert!(!out.exists());
    }
}

#[test]
fn reversed_torque_is_counted_as_idle_and_said_so() {
    // 10 s driving at 50 N m, then 10 s braking at -50 N m at the same 25 Hz, held: the
    // spectrum keeps the 10 s under load, the warning names the 10 s of the coast flank
    // (2.8e-3 h, half the span), and the summary records them.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let h = dir.path().join("h.csv");
    let mut t = String::from("time_s,torque_nm,input_speed_hz\n");
    for i in 0..=20 {
        t.push_str(&format!("{i},{},25\n", if i < 10 { 50 } else { -50 }));
    }
    std::fs::write(&h, t).unwrap();
    let o = load_spectrum(&h, &out, &["--interpolation", "hold"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("0.002778 h") && e.contains("50 %") && e.contains("negative torque"),
        "{e}"
    );
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["time"]["reversed_torque_s"], 10.0);
    assert_eq!(s["time"]["under_load_s"], 10.0);
}
