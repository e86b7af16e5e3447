//! Per-tooth inputs through the command line: the outputs of a wear study name each
//! tooth's inputs and wear, and a sweep varies a `[teeth]` key like any other key (its
//! rows equal single runs of the same cases).

mod common;

use common::{ok, read_csv, sweep, CHEAP};

fn json(path: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn a_wear_study_writes_each_tooths_inputs_and_wear() {
    // Pinion tooth 3 stands 5 um proud; nothing else differs, so the excitation repeats
    // every pinion revolution (19 mesh periods) and the hunting period is lcm(19, 31).
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let mut pitch = vec!["0"; 19];
    pitch[3] = "5";
    let set = format!("teeth.pitch_error_pinion_um=[{}]", pitch.join(","));
    let mut a = vec!["wear", "--mode", "dynamic"];
    a.extend(CHEAP);
    a.extend([
        "--set",
        &set,
        "--set",
        "wear.total_cycles=1e4",
        "--out",
        out.to_str().unwrap(),
    ]);
    ok(&a);
    let s = json(&out.join("summary.json"));
    assert_eq!(s["teeth"]["excitation_mesh_periods"], 19);
    assert_eq!(s["teeth"]["hunting_mesh_periods"], 589);
    // The inputs, and the single pitch deviations as the differences of neighbouring
    // positions (ISO 1328-1): +5 um entering tooth 3, -5 um leaving it.
    let (h, rows) = read_csv(&out.join("teeth_pinion.csv"));
    let col = |n: &str| h.iter().position(|x| x == n).unwrap();
    assert_eq!(rows.len(), 19);
    for (t, r) in rows.iter().enumerate() {
        let num = |n: &str| r[col(n)].parse::<f64>().unwrap();
        assert_eq!(num("position_error_um"), if t == 3 { 5.0 } else { 0.0 });
        let fpt = match t {
            3 => 5.0,
            4 => -5.0,
            _ => 0.0,
        };
        assert_eq!(num("single_pitch_deviation_um"), fpt);
    }
    assert_eq!(read_csv(&out.join("teeth_gear.csv")).1.len(), 31);
    // A column per tooth of both gears; the proud tooth, which takes the load first and
    // carries it alone longer, wears deepest of the pinion teeth.
    let (h, rows) = read_csv(&out.join("csv/teeth_wear_dynamic.csv"));
    let pinion: Vec<usize> = (0..19)
        .map(|t| {
            h.iter()
                .position(|x| *x == format!("pinion_tooth{t}_um"))
                .unwrap()
        })
        .collect();
    assert!((0..31).all(|t| h.contains(&format!("gear_tooth{t}_um"))));
    let deepest = |c: usize| {
        rows.iter()
            .map(|r| r[c].parse::<f64>().unwrap())
            .fold(0.0_f64, f64::max)
    };
    let depths: Vec<f64> = pinion.iter().map(|c| deepest(*c)).collect();
    let max = depths.iter().fold(0.0_f64, |m, x| m.max(*x));
    assert_eq!(depths[3], max, "{depths:?}");
    assert!(depths[0] < max, "{depths:?}");
    // The maximum wear reported per update is over every tooth (to the CSV's digits).
    let (h, rows) = read_csv(&out.join("updates_dynamic.csv"));
    let c = h.iter().position(|x| x == "max_wear_pinion_um").unwrap();
    let reported: f64 = rows.last().unwrap()[c].parse().unwrap();
    assert!((reported - max).abs() <= 1e-12 * max, "{reported} vs {max}");
    for f in ["teeth_wear_dynamic.png", "teeth_mesh_stiffness.png"] {
        assert!(out.join(f).exists(), "{f} missing");
    }
}

#[test]
fn a_sweep_varies_a_per_tooth_key_and_its_rows_equal_single_runs() {
    // The rows of a sweep that varies a per-tooth key share one load-sharing law
    // (compression): a single run of a row's values under that law must give the row
    // exactly, and a vanishing run-out (1e-9 µm) must give the row of none to 1e-7 of
    // the DTE (the run-out moves it by 5e-16 m of ~1e-5 m; the rest is round-off), which
    // under two laws it would miss by per cent.
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("sw");
    sweep(&["--vary", "teeth.runout_gear_um=0,1e-9,4"], &out);
    let (h, rows) = read_csv(&out.join("sweep.csv"));
    let col = |n: &str| h.iter().position(|x| x == n).unwrap();
    assert_eq!(rows.len(), 3);
    let dte: Vec<f64> = rows
        .iter()
        .map(|r| r[col("dte_max_um")].parse().unwrap())
        .collect();
    for (i, runout) in [(0, "0"), (2, "4")] {
        let single = d.path().join(format!("single{i}"));
        let set = format!("teeth.runout_gear_um={runout}");
        let mut a = vec!["dynamics"];
        a.extend(CHEAP);
        a.extend([
            "--set",
            &set,
            "--set",
            "contact.load_sharing=stiffness",
            "--out",
            single.to_str().unwrap(),
        ]);
        ok(&a);
        let s = json(&single.join("summary.json"));
        let want = s["dte"]["max_um"].as_f64().unwrap();
        // Same case, same deterministic computation, round-trip formats: equal up to a
        // differently ordered unit conversion.
        assert!(
            (dte[i] - want).abs() <= 1e-12 * want.abs(),
            "run-out {runout}: sweep {} vs single {want}",
            dte[i]
        );
    }
    assert!(
        (dte[1] - dte[0]).abs() <= 1e-7 * dte[0].abs(),
        "a vanishing run-out jumps: {dte:?}"
    );
    // A 4 µm run-out (2 µm eccentricity) raises the maximum DTE.
    assert!(dte[2] > dte[0], "{dte:?}");
}

#[test]
fn healthy_teeth_list_their_faults_as_plain_zeros() {
    // A healthy tooth has no crack, spall or broken tip: its fault cells are exactly 0,
    // written "0" (an empty f64 sum is -0.0, which was written "-0").
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    ok(&[
        "stiffness",
        "-q",
        "--set",
        "fault.kind=crack",
        "--set",
        "fault.gear=gear",
        "--set",
        "fault.tooth=7",
        "--set",
        "fault.crack_depth_mm=1",
        "--out",
        out.to_str().unwrap(),
    ]);
    for (file, teeth) in [("teeth_pinion.csv", 19), ("teeth_gear.csv", 31)] {
        let (h, rows) = read_csv(&out.join(file));
        assert_eq!(rows.len(), teeth);
        for (t, row) in rows.iter().enumerate() {
            for (name, cell) in h.iter().zip(row) {
                assert!(!cell.starts_with("-0"), "{file} tooth {t} {name} = {cell}");
                let cracked = file == "teeth_gear.csv" && t == 7 && name == "crack_depth_mm";
                if name.ends_with("_mm") || name.ends_with("depth_um") {
                    assert_eq!(
                        cell,
                        if cracked { "1" } else { "0" },
                        "{file} tooth {t} {name}"
                    );
                }
            }
        }
    }
}
