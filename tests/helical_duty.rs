//! A helical pair's wear under a `[load_spectrum]` (docs/MODEL.md 11.7) against
//! independent facts: a spectrum of one bin at the operating point is `gearwear wear` at
//! that point (the same bytes of the wear map), the update is linear in the shares (a bin
//! split in two wears as the whole bin), cut and torn logs resume to the bytes of an
//! uninterrupted run while an edited one is refused, `gearwear run`'s wear study is
//! `gearwear wear`'s, a wear sweep's row is the wear study of its case, bad bins exit 2
//! naming the bin, and a helical pair on a soft axial bearing is warned of its axial
//! shift under the spectrum, a stiff one not.

mod common;

use common::resume::{cut_log, cut_then_resumed_is_unchanged, edit_update, refused, run};
use common::{gearwear, read_csv, rejected, stderr};
use gearwear::config::load_case;
use gearwear::duty::{run_spectrum_wear, SpectrumModel, SpectrumRun};
use gearwear::study::wear_loop::WearMode;
use gearwear::wear::WearState;
use std::path::Path;

/// A small helical pair: 15 deg, 6 face slices, 2e4 cycles (five updates or so).
const HELICAL: [&str; 4] = [
    "gear.helix_angle_deg=15",
    "stiffness.slices=6",
    "wear.total_cycles=2e4",
    "wear.threshold_um=0.5",
];

/// Three bins, the heavy one in the middle (shares of cycles 0.3, 0.5, 0.2).
const THREE_BINS: &str = "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.3}, {torque_nm = 90, input_speed_hz = 40, share = 0.5}, {torque_nm = 70, input_speed_hz = 35, share = 0.2}]\n";

fn sets(more: &[&str]) -> Vec<String> {
    HELICAL.iter().chain(more).map(|s| s.to_string()).collect()
}

/// `gearwear -q command` with `config` (written to `dir/name.toml`) and the helical
/// keys plus `more`, into `dir/name`; requires success and returns the folder.
fn cli(dir: &Path, name: &str, command: &str, config: &str, more: &[&str]) -> std::path::PathBuf {
    let case = dir.join(format!("{name}.toml"));
    std::fs::write(&case, config).unwrap();
    let out = dir.join(name);
    let mut a: Vec<String> = ["-q", command, "--config", case.to_str().unwrap()]
        .iter()
        .map(|s| s.to_string())
        .collect();
    for s in sets(more) {
        a.extend(["--set".into(), s]);
    }
    a.extend(["--out".into(), out.to_str().unwrap().into()]);
    let o = run(&a);
    assert!(o.status.success(), "{command} {name}: {}", stderr(&o));
    out
}

#[test]
fn a_one_bin_spectrum_is_the_helical_wear_at_its_operating_point() {
    // One bin of share 1 at the case's own torque and speed: every product with s = 1 is
    // exact, so the wear map, the profiles and the updates are `gearwear wear`'s at that
    // point, byte for byte, in both modes.
    let d = tempfile::tempdir().unwrap();
    let point = ["operating.load_torque_nm=60", "operating.input_speed_hz=30"];
    let single = cli(d.path(), "single", "wear", "", &point);
    let one = "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 1}]\n";
    let spectrum = cli(d.path(), "spectrum", "wear", one, &point);
    for f in [
        "csv/wear_map_dynamic.csv",
        "csv/wear_map_quasi_static.csv",
        "wear_profiles_dynamic.csv",
        "wear_profiles_quasi_static.csv",
        "updates_dynamic.csv",
        "updates_quasi_static.csv",
    ] {
        let (a, b) = (
            std::fs::read(single.join(f)).unwrap(),
            std::fs::read(spectrum.join(f)).unwrap(),
        );
        assert!(
            a == b,
            "{f} differs between the point and its one-bin spectrum"
        );
    }
    // The map is a real one: every face slice worn.
    let (head, rows) = read_csv(&spectrum.join("csv/wear_map_dynamic.csv"));
    let i = head.iter().position(|h| h == "pinion_slice0_um").unwrap();
    assert!(rows.iter().any(|r| r[i].parse::<f64>().unwrap() > 0.0));
}

/// The last wear state of the spectrum `bins` in `mode` (library, no files).
fn last_wear(bins: &str, mode: WearMode) -> (WearState, usize) {
    let case = load_case(&format!("[load_spectrum]\nbins = [{bins}]\n"), &sets(&[])).unwrap();
    let sm = SpectrumModel::dynamics_from_case(&case).unwrap();
    let start = SpectrumRun::new(mode, sm.shares.clone());
    let r = run_spectrum_wear(&sm, start, &mut |_| Ok(())).unwrap();
    assert!(r.stopped.is_none());
    (r.last().unwrap().wear.clone(), r.records.len())
}

/// Largest |a - b| over the largest |b| of two wear maps (both flanks, every slice), and
/// of their mean profiles.
fn map_gap(a: &WearState, b: &WearState) -> (f64, f64) {
    let (sa, sb) = (a.slices.as_ref().unwrap(), b.slices.as_ref().unwrap());
    let gap = |x: &[Vec<f64>], y: &[Vec<f64>]| {
        let flat = |v: &[Vec<f64>]| v.iter().flatten().copied().collect::<Vec<f64>>();
        let (x, y) = (flat(x), flat(y));
        let top = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(top > 0.0, "a map that has not worn");
        x.iter()
            .zip(&y)
            .map(|(p, q)| (p - q).abs())
            .fold(0.0, f64::max)
            / top
    };
    let slices = gap(&sa.pinion_m, &sb.pinion_m).max(gap(&sa.gear_m, &sb.gear_m));
    let one = std::slice::from_ref;
    let means = gap(one(&a.pinion_m), one(&b.pinion_m)).max(gap(one(&a.gear_m), one(&b.gear_m)));
    (slices, means)
}

#[test]
fn a_bin_split_in_two_wears_as_the_whole_bin() {
    // Linearity of the update in the shares (paper eq. 17 per bin): bins A 0.3, B 0.5,
    // A 0.2 add 0.3 n inc_A + 0.5 n inc_B + 0.2 n inc_A per block, A 0.5 + B 0.5 add
    // 0.5 n inc_A + 0.5 n inc_B: the same up to the rounding of the sums, and the two A
    // bins respond alike. Quasi-static (no warm start): the rounding, ~1e-16, is all that
    // differs (measured 4e-16); 1e-12 of the deepest wear leaves it room over the
    // updates' feedback.
    // Dynamic: each A bin warm-starts its periodic search from its own previous state, and
    // starts that differ by rounding give the same periodic orbit to a few ulps of the
    // state (measured 7e-14 of the deepest wear); 1e-9 leaves that four orders and is far
    // below what a wrong share does (a bin's s_i off by 0.1 moves the map by ~5 %).
    let a = |s: f64| format!("{{torque_nm = 60, input_speed_hz = 30, share = {s}}}");
    let b = "{torque_nm = 90, input_speed_hz = 40, share = 0.5}";
    let split = format!("{}, {b}, {}", a(0.3), a(0.2));
    let whole = format!("{}, {b}", a(0.5));
    for (mode, tol) in [(WearMode::QuasiStatic, 1e-12), (WearMode::Dynamic, 1e-9)] {
        let (x, nx) = last_wear(&split, mode);
        let (y, ny) = last_wear(&whole, mode);
        assert_eq!(nx, ny, "{mode:?}: the same updates");
        assert_eq!(x.cycles, y.cycles);
        let (slices, means) = map_gap(&x, &y);
        eprintln!("{mode:?}: split against whole: map {slices:.2e}, mean profiles {means:.2e}");
        assert!(
            slices <= tol && means <= tol,
            "{mode:?}: {slices:e} {means:e}"
        );
    }
}

/// `wear` of the three-bin helical spectrum into `out` in `mode` (its arguments).
fn spectrum_args(dir: &Path, mode: &str, out: &Path) -> Vec<String> {
    let case = dir.join("three.toml");
    std::fs::write(&case, THREE_BINS).unwrap();
    let mut a: Vec<String> = ["-q", "wear", "--mode", mode, "--config"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    a.push(case.to_str().unwrap().into());
    for s in sets(&["wear.threshold_um=0.2"]) {
        a.extend(["--set".into(), s]);
    }
    a.extend(["--out".into(), out.to_str().unwrap().into()]);
    a
}

#[test]
fn cut_and_torn_logs_resume_to_the_bytes_of_an_uninterrupted_run() {
    // A kill between two appends leaves the bins' logs of unequal length, one in the
    // middle of an append a torn line: the resume replays every face slice of every
    // record bit for bit and continues as the uninterrupted run did.
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let cut = |out: &Path| {
        cut_log(&out.join("checkpoint_dynamic_bin1.jsonl"), 4, false);
        cut_log(&out.join("checkpoint_dynamic_bin2.jsonl"), 3, true);
        cut_log(&out.join("checkpoint_quasi_static_bin3.jsonl"), 2, true);
    };
    cut_then_resumed_is_unchanged(&spectrum_args(d.path(), "both", &out), &out, &cut);
}

#[test]
fn an_edited_slice_of_a_middle_update_is_refused() {
    // Every bin's log edited alike at a middle update (1 nm on face slice 2's deepest
    // pinion point, the lines' checksums recomputed: what a forger does, so that the
    // logs agree with each other): the replay of the spectrum's chain refuses it, though
    // the resume recomputes only the first and last updates.
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let a = spectrum_args(d.path(), "quasi-static", &out);
    let o = run(&a);
    assert!(o.status.success(), "{}", stderr(&o));
    let log = |i: usize| out.join(format!("checkpoint_quasi_static_bin{i}.jsonl"));
    let updates = std::fs::read_to_string(log(1)).unwrap().lines().count() - 1;
    assert!(updates >= 5, "{updates} updates");
    let at = updates / 2;
    for i in 1..=3 {
        edit_update(&log(i), at, true, &|v| {
            let p = v
                .pointer_mut("/wear/slices/pinion_m/2")
                .expect("per-slice wear in the log")
                .as_array_mut()
                .unwrap();
            let k = (0..p.len())
                .max_by(|x, y| p[*x].as_f64().unwrap().total_cmp(&p[*y].as_f64().unwrap()))
                .unwrap();
            let y = p[k].as_f64().unwrap();
            assert!(y > 0.0);
            p[k] = serde_json::json!(y + 1e-9);
        });
    }
    refused(
        &a,
        "an edited slice",
        &[&format!("update {at}"), "not the previous wear advanced"],
    );
}

#[test]
fn run_under_a_spectrum_holds_wear_under_it_and_the_duty_section() {
    // `gearwear run`'s wear study is `gearwear wear`'s under the same spectrum (another
    // command's output): the same wear map bytes; its report has the duty-cycle section
    // and its summary the spectrum.
    let d = tempfile::tempdir().unwrap();
    let w = cli(d.path(), "w", "wear", THREE_BINS, &[]);
    let r = cli(d.path(), "r", "run", THREE_BINS, &[]);
    for f in ["csv/wear_map_dynamic.csv", "csv/wear_map_quasi_static.csv"] {
        let (a, b) = (
            std::fs::read(w.join(f)).unwrap(),
            std::fs::read(r.join("wear").join(f)).unwrap(),
        );
        assert!(a == b, "{f}: run's wear study differs from wear's");
    }
    assert!(r.join("wear/duty/bins_dynamic.csv").exists());
    let html = std::fs::read_to_string(r.join("report.html")).unwrap();
    assert!(html.contains("Duty cycle: wear and life under the load spectrum"));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(r.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["load_spectrum"]["bins"].as_array().map(Vec::len), Some(3));
    assert!(s["load_spectrum"]["life"]["spectrum"]["status"].is_string());
}

#[test]
fn a_wear_sweep_over_a_helical_spectrum_is_the_wear_study_of_each_case() {
    // The sweep's row at torque_scale 1.2 is `gearwear wear` of that case: its deepest
    // pinion wear bit for bit, and the face position of the wear map's deepest entry.
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("three.toml");
    std::fs::write(&case, THREE_BINS).unwrap();
    let out = d.path().join("s");
    let mut a = vec!["-q", "sweep", "--config", case.to_str().unwrap()];
    let s = sets(&[]);
    for x in &s {
        a.extend(["--set", x.as_str()]);
    }
    a.extend(["--run", "wear", "--vary", "load_spectrum.torque_scale=1.2"]);
    a.extend(["--out", out.to_str().unwrap()]);
    let o = gearwear(&a);
    assert!(o.status.success(), "{}", stderr(&o));
    let (head, rows) = read_csv(&out.join("sweep.csv"));
    let col = |n: &str| -> f64 {
        let i = head
            .iter()
            .position(|h| h == n)
            .unwrap_or_else(|| panic!("{n}"));
        rows[0][i].parse().unwrap()
    };
    let w = cli(
        d.path(),
        "w",
        "wear",
        THREE_BINS,
        &["load_spectrum.torque_scale=1.2"],
    );
    let (uh, ur) = read_csv(&w.join("updates_dynamic.csv"));
    let i = uh.iter().position(|h| h == "max_wear_pinion_um").unwrap();
    let max: f64 = ur.last().unwrap()[i].parse().unwrap();
    assert_eq!(max.to_bits(), col("wear_max_pinion_dynamic_um").to_bits());
    let sw: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(w.join("summary.json")).unwrap()).unwrap();
    let y = sw["wear_map"]["dynamic"]["pinion"]["max_wear_position_mm"]
        .as_f64()
        .unwrap();
    let at = col("wear_map_deepest_pinion_position_dynamic_mm");
    assert!((at - y).abs() <= 1e-9 * y, "{at} {y}");
}

#[test]
fn bad_bins_of_a_helical_spectrum_exit_2_naming_the_bin_or_the_key() {
    let d = tempfile::tempdir().unwrap();
    let heavy = d.path().join("heavy.toml");
    std::fs::write(
        &heavy,
        "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.5}, {torque_nm = 1e6, input_speed_hz = 30, share = 0.5}]\n",
    )
    .unwrap();
    let three = d.path().join("three.toml");
    std::fs::write(&three, THREE_BINS).unwrap();
    let helix = "gear.helix_angle_deg=15";
    for command in ["wear", "run"] {
        // A bin the flanks cannot carry: named (the budget builds the bins' models
        // rather than price a meaningless wear rate), not priced.
        let e = rejected(
            &[command, "--config", heavy.to_str().unwrap(), "--set", helix],
            &["load_spectrum bin 2", "torque_nm", "1000000"],
        );
        assert!(!e.contains("budget") && !e.contains("panicked"), "{e}");
        // What the planar model refuses, under a spectrum as without one.
        rejected(
            &[
                command,
                "--config",
                three.to_str().unwrap(),
                "--set",
                helix,
                "--set",
                "teeth.accuracy_grade=6",
            ],
            &["`[teeth]`", "gear.helix_angle_deg"],
        );
    }
}

/// `gearwear wear --mode quasi-static` of the three-bin helical spectrum with `more`,
/// into `dir/name`: its output (success required).
fn quasi_static_wear(dir: &Path, name: &str, more: &[&str]) -> String {
    let case = dir.join("three.toml");
    std::fs::write(&case, THREE_BINS).unwrap();
    let out = dir.join(name);
    let mut a = vec!["wear", "--mode", "quasi-static", "--config"];
    a.push(case.to_str().unwrap());
    let s = sets(more);
    for x in &s {
        a.extend(["--set", x.as_str()]);
    }
    a.extend(["--out", out.to_str().unwrap()]);
    let o = gearwear(&a);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    e
}

#[test]
fn an_axial_shift_under_the_spectrum_is_warned_naming_the_bin() {
    // Statics: the pinion on an axial spring of 1e4 N/m under F_t tan(beta) (~0.8 kN at
    // 60 N m, more at 90) shifts by tens of mm, beyond 5 % of the 20 mm face at every
    // bin: warned, naming the bin; at 5e8 N/m it shifts by microns: not warned.
    let d = tempfile::tempdir().unwrap();
    let soft = ["dynamics.bearing_axial_stiffness_pinion_n_per_m=1e4"];
    let e = quasi_static_wear(d.path(), "soft", &soft);
    for bin in 1..=3 {
        assert!(
            e.contains(&format!("load_spectrum bin {bin} (")) && e.contains("move axially"),
            "bin {bin}: {e}"
        );
    }
    let stiff = [
        "dynamics.bearing_axial_stiffness_pinion_n_per_m=5e8",
        "dynamics.bearing_axial_stiffness_gear_n_per_m=7e8",
    ];
    let e = quasi_static_wear(d.path(), "stiff", &stiff);
    assert!(!e.contains("move axially"), "{e}");
}

#[test]
fn run_under_the_spectrum_warns_each_bin_s_axial_shift_once() {
    // `run` solves the monitoring bin's new teeth again for its dynamics folder; its
    // axial shift was warned with the bins', so each of the three bins is warned once.
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("three.toml");
    std::fs::write(&case, THREE_BINS).unwrap();
    let out = d.path().join("run");
    let s = sets(&["dynamics.bearing_axial_stiffness_pinion_n_per_m=1e4"]);
    let mut a = vec!["run", "--config", case.to_str().unwrap()];
    for x in &s {
        a.extend(["--set", x.as_str()]);
    }
    a.extend(["--out", out.to_str().unwrap()]);
    let o = gearwear(&a);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert_eq!(e.matches("move axially").count(), 3, "{e}");
}
