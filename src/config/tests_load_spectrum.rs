//! Tests of reading `[load_spectrum]`: inline bins, a CSV file, rpm and hours, bad spectra.

use super::case::{Case, SpectrumBin, TorqueShaft};
use super::load::{check_all_ranges, load_case, load_case_in};

fn err(text: &str) -> String {
    load_case(text, &[]).unwrap_err().to_string()
}

const TWO: &str = "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 80, input_speed_hz = 45, share = 0.3}]\n";

#[test]
fn inline_bins_load_and_a_case_without_the_section_is_unchanged() {
    let c = load_case(TWO, &[]).unwrap();
    let s = c.load_spectrum.as_ref().unwrap();
    assert_eq!(s.bins.len(), 2);
    assert_eq!(
        s.bins[1],
        SpectrumBin {
            torque_nm: 80.0,
            input_speed_hz: 45.0,
            share: 0.3
        }
    );
    // The largest share is observed by default.
    assert_eq!(s.monitoring_index(), 0);
    // No section: the default case, and its serialised form has no trace of it.
    assert_eq!(load_case("", &[]).unwrap(), Case::default());
    assert!(!toml::to_string(&Case::default())
        .unwrap()
        .contains("load_spectrum"));
    // An empty section (as the commented template prints it) is no spectrum.
    assert_eq!(
        load_case("[load_spectrum]\n", &[]).unwrap(),
        Case::default()
    );
    // A resolved case reloads to itself.
    let text = toml::to_string(&c).unwrap();
    assert_eq!(load_case(&text, &[]).unwrap(), c);
    assert!(check_all_ranges(&c).is_empty());
}

#[test]
fn bin_cases_carry_the_operating_point() {
    let c = load_case(
        &format!("{TWO}torque_shaft = \"gear\"\ntorque_scale = 1.5\n"),
        &["load_spectrum.speed_scale=2".into()],
    )
    .unwrap();
    let b = c.at_bin(1);
    assert_eq!(b.operating.load_torque_nm, 120.0);
    assert_eq!(b.operating.input_speed_hz, 90.0);
    assert_eq!(b.operating.load_torque_shaft, TorqueShaft::Gear);
    assert!(b.load_spectrum.is_none());
    // Everything else is the case's.
    assert_eq!(b.wear, c.wear);
    // A bin at the operating point is the case without its spectrum.
    let one = load_case(
        "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 1}]\n",
        &[],
    )
    .unwrap();
    assert_eq!(one.at_bin(0), Case::default());
}

#[test]
fn rpm_and_hours_convert_as_stated() {
    let c = load_case(
        "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_rpm = 1800, hours = 2}, {torque_nm = 80, input_speed_rpm = 900, hours = 1}]\n",
        &[],
    )
    .unwrap();
    let s = c.load_spectrum.unwrap();
    // 1800 rpm = 30 Hz; cycles 2 h x 30 Hz : 1 h x 15 Hz = 60 : 15 = 0.8 : 0.2.
    assert_eq!(s.bins[0].input_speed_hz, 30.0);
    assert_eq!(s.bins[1].input_speed_hz, 15.0);
    assert!((s.bins[0].share - 0.8).abs() < 1e-15 && (s.bins[1].share - 0.2).abs() < 1e-15);
    // Mean time per cycle: 0.8 / 30 + 0.2 / 15 s.
    assert!((s.seconds_per_cycle() - (0.8 / 30.0 + 0.2 / 15.0)).abs() < 1e-15);
}

#[test]
fn a_csv_file_is_read_from_the_case_folder() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("s.csv"),
        "torque_nm,input_speed_hz,share\n60,30,0.25\n70,35,0.75\n",
    )
    .unwrap();
    let c = load_case_in("[load_spectrum]\nfile = \"s.csv\"\n", &[], dir.path()).unwrap();
    assert_eq!(c.load_spectrum.as_ref().unwrap().bins[1].share, 0.75);
    std::fs::write(
        dir.path().join("bad.csv"),
        "torque_nm,input_speed_hz,share\n60,30,0.25\n-70,35,0.75\n",
    )
    .unwrap();
    let e = load_case_in("[load_spectrum]\nfile = \"bad.csv\"\n", &[], dir.path())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bin 2") && e.contains("line 3") && e.contains("torque_nm"),
        "{e}"
    );
    let e = load_case_in("[load_spectrum]\nfile = \"none.csv\"\n", &[], dir.path())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("load_spectrum.file") && e.contains("cannot read"),
        "{e}"
    );
}

#[test]
fn bad_spectra_name_the_bin_the_key_and_the_range() {
    // Shares not summing to 1.
    let e = err("[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 80, input_speed_hz = 45, share = 0.2}]\n");
    assert!(e.contains("sum to 0.9") && e.contains("hours"), "{e}");
    // Hours totalling zero.
    let e = err("[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, hours = 0}]\n");
    assert!(e.contains("hours total 0"), "{e}");
    // Negative, non-finite, outside the range (with the scale that put it there).
    for (bin, want) in [
        (
            "{torque_nm = -60, input_speed_hz = 30, share = 1}",
            "`torque_nm` = -60",
        ),
        (
            "{torque_nm = 60, input_speed_hz = nan, share = 1}",
            "`input_speed_hz` = NaN",
        ),
        (
            "{torque_nm = inf, input_speed_hz = 30, share = 1}",
            "`torque_nm` = inf",
        ),
        (
            "{torque_nm = 60, input_speed_hz = 2000, share = 1}",
            "outside [1e-6, 1000]",
        ),
        (
            "{torque_nm = 60, input_speed_hz = 30, share = 1.5}",
            "`share` = 1.5",
        ),
        ("{torque_nm = 60, input_speed_hz = 30}", "missing `share`"),
        (
            "{torque_nm = 60, input_speed_hz = 30, input_speed_rpm = 1800, share = 1}",
            "not both",
        ),
        (
            "{torque_nm = 60, speed_hz = 30, share = 1}",
            "unknown key `speed_hz`",
        ),
    ] {
        let e = err(&format!("[load_spectrum]\nbins = [{bin}]\n"));
        assert!(
            e.contains("load_spectrum bin 1") && e.contains(want),
            "{bin}: {e}"
        );
    }
    // A subnormal share or time (the shares still sum to 1 exactly): refused as
    // subnormal values are for every key of a case; the smallest normal share is not.
    for (w, want) in [("share", "`share` = "), ("hours", "`hours` = ")] {
        let bins = |tiny: &str| {
            format!("[load_spectrum]\nbins = [{{torque_nm = 60, input_speed_hz = 30, {w} = 1}}, {{torque_nm = 80, input_speed_hz = 30, {w} = {tiny}}}]\n")
        };
        let e = err(&bins("5e-324"));
        assert!(
            e.contains("bin 2") && e.contains(want) && e.contains("subnormal"),
            "{e}"
        );
        assert!(load_case(&bins("2.2250738585072014e-308"), &[]).is_ok());
    }
    // 45 Hz x 30 = 1350 Hz is out of range; 30 x 30 = 900 Hz is not.
    let e = err(&format!("{TWO}speed_scale = 30\n"));
    assert!(
        e.contains("bin 2")
            && !e.contains("bin 1")
            && e.contains("speed_scale")
            && e.contains("operating.input_speed_hz"),
        "{e}"
    );
    let e = err(&format!("{TWO}monitoring_bin = 3\n"));
    assert!(e.contains("monitoring_bin") && e.contains("[1, 2]"), "{e}");
    let e = err("[load_spectrum]\ntorque_scale = 2\n");
    assert!(e.contains("has no bins"), "{e}");
    let e = err(&format!("{TWO}file = \"x.csv\"\n"));
    assert!(e.contains("not both"), "{e}");
}
