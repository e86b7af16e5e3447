//! `gearwear dataset` on a planetary set (issue 31 with issue 33's rules): run-to-failure
//! records of the set's own wear loop, each the ring sensor's record that `gearwear
//! signals` gives for the set at the state's wear, labelled per member. Checked against
//! independent facts: the new set's record equals `gearwear signals` (as float32), a worn
//! state's equals the set's steady state solved here with the wear gaps the test builds
//! from the kept trajectory, every member's wear and the limiting member are recomputed
//! here from the trajectory's mesh records, the indicators from the Parquet file;
//! kill-and-resume and shards + merge equal one uninterrupted run byte for byte; a forged
//! member label is named on resume; what a set cannot take is refused.

mod common;

use common::{gearwear, kill_when, ok, read_csv, stderr};
use gearwear::study::planetary_signals::{ring_sensor_record, RingSensor};
use gearwear::study::planetary_wear::{wear_gaps, PlanetaryWearModel};
use gearwear::wear::WearState;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn case_path() -> String {
    format!("{}/examples/planetary_set.toml", env!("CARGO_MANIFEST_DIR"))
}

/// A design on the example set recording the states at `cycles` (input cycles) with
/// `extra` lines in its `[records]` table and `sets` in its `set`.
fn design(dir: &Path, name: &str, cycles: &str, sets: &[&str], extra: &str) -> PathBuf {
    let sets: Vec<String> = ["signals.record_length=0.05"]
        .iter()
        .chain(sets)
        .map(|s| format!("{s:?}"))
        .collect();
    let text = format!(
        "case = {:?}\nseed = 5\nset = [{}]\n[run_to_failure]\ncycles = [{cycles}]\nmax_cycles = 2e5\nwear_limit_um = 50\n[records]\ncsv = true\n{extra}",
        case_path(),
        sets.join(", ")
    );
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn dataset(design: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    let mut a = vec![
        "-q",
        "dataset",
        "--design",
        design.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    a.extend(extra);
    gearwear(&a)
}

fn json(p: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap()
}

/// Column `name` of a CSV file, parsed.
fn column(p: &Path, name: &str) -> Vec<f64> {
    let (h, rows) = read_csv(p);
    let i = h
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("{name} in {h:?}"));
    rows.iter().map(|r| r[i].parse().unwrap()).collect()
}

/// The ring sensor's column of a record's Parquet file, as stored (float32).
fn ring_column(p: &Path, samples: usize) -> Vec<f32> {
    let names = ["ring_sensor_n".to_owned(), "tachometer_v".to_owned()];
    let cols = gearwear::io::parquet::read_f32_columns(std::fs::read(p).unwrap(), &names, samples)
        .unwrap();
    cols[0].clone()
}

/// Every mesh's wear state at `cycles` input cycles, built here from the kept trajectory:
/// the last update at or before `cycles`, each mesh's profiles advanced by its increment
/// times its pinion turns per input turn times the input cycles since (the loop holds the
/// update's rate over the block, paper eq. 17).
fn states_at(t: &Value, cycles: f64) -> Vec<WearState> {
    let x: Vec<f64> = serde_json::from_value(t["input_cycles"].clone()).unwrap();
    let c: Vec<f64> = serde_json::from_value(t["cycle_factors"].clone()).unwrap();
    let i = x.iter().rposition(|v| *v <= cycles).unwrap();
    let meshes: Vec<&Value> = std::iter::once(&t["records"])
        .chain(t["later_stages"].as_array().unwrap())
        .map(|m| &m[i])
        .collect();
    meshes
        .iter()
        .enumerate()
        .map(|(j, r)| {
            let mut w: WearState = serde_json::from_value(r["wear"].clone()).unwrap();
            let n = (cycles - x[i]) * c[j];
            let inc = |k: &str| -> Vec<f64> { serde_json::from_value(r[k].clone()).unwrap() };
            if n > 0.0 {
                for (p, d) in w.pinion_m.iter_mut().zip(inc("increment_pinion_m")) {
                    *p += d * n;
                }
                for (p, d) in w.gear_m.iter_mut().zip(inc("increment_gear_m")) {
                    *p += d * n;
                }
            }
            w
        })
        .collect()
}

/// Each member's deepest wear (µm), computed here: the sun's flank sums its N meshes'
/// pinion profiles, the ring's its N ring meshes' gear profiles; planet p's deeper flank
/// of its sun mesh's gear profile and its ring mesh's pinion profile (docs/MODEL.md 12.9).
fn members_um(states: &[WearState]) -> Vec<f64> {
    let n = states.len() / 2;
    let max = |v: &[f64]| v.iter().fold(0.0_f64, |a, b| a.max(*b));
    let sum = |ws: &[WearState], pinion: bool| -> Vec<f64> {
        let len = if pinion {
            ws[0].pinion_m.len()
        } else {
            ws[0].gear_m.len()
        };
        (0..len)
            .map(|k| {
                ws.iter()
                    .map(|w| if pinion { w.pinion_m[k] } else { w.gear_m[k] })
                    .sum()
            })
            .collect()
    };
    let mut m = vec![max(&sum(&states[..n], true))];
    m.extend((0..n).map(|p| max(&states[p].gear_m).max(max(&states[n + p].pinion_m))));
    m.push(max(&sum(&states[n..], false)));
    m.into_iter().map(|v| v * 1e6).collect()
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(1e-300)
}

#[test]
fn a_planetary_record_is_the_sets_signal_and_its_labels_its_trajectory() {
    let dir = tempfile::tempdir().unwrap();
    let d = design(
        dir.path(),
        "d.toml",
        "0, 100000",
        &[],
        "noise_realisations = 1\n",
    );
    let out = dir.path().join("ds");
    let r = dataset(&d, &out, &[]);
    assert!(r.status.success(), "{}", stderr(&r));

    // State 0 (new teeth) against `gearwear signals` on the same set: the same steady
    // state and window, stored as float32, so equal once rounded to float32.
    let sig = dir.path().join("sig");
    ok(&[
        "-q",
        "signals",
        "--config",
        &case_path(),
        "--set",
        "signals.record_length=0.05",
        "--out",
        sig.to_str().unwrap(),
    ]);
    let expected = column(&sig.join("record.csv"), "ring_sensor_n");
    let stored = column(&out.join("csv/0000000.csv"), "ring_sensor_n");
    assert_eq!(expected.len(), stored.len());
    assert!(expected.len() > 1000);
    for (k, (a, b)) in expected.iter().zip(&stored).enumerate() {
        assert_eq!(*a as f32, *b as f32, "sample {k}: signals {a}, dataset {b}");
    }
    assert_eq!(
        ring_column(&out.join("signals/0000000.parquet"), stored.len()).len(),
        stored.len()
    );

    // State 1 (1e5 input cycles): the set's steady state solved here with the wear gaps of
    // the meshes' states the test builds from the kept trajectory, heard by the ring
    // sensor of the case (angle 0, half-width 180 / N deg, 0.05 s at 25.6 kHz).
    let t = json(&out.join("state/trajectory_healthy.json"))["trajectory"].clone();
    let states = states_at(&t, 1e5);
    let text = std::fs::read_to_string(case_path()).unwrap();
    let case =
        gearwear::config::load_case(&text, &["signals.record_length=0.05".to_owned()]).unwrap();
    let model = PlanetaryWearModel::from_case(&case).unwrap();
    let mut dynamics = model.dynamics.clone();
    dynamics.model.set_wear_gaps(wear_gaps(&model, &states));
    let response = dynamics.solve().unwrap();
    let sensor = RingSensor {
        angle_rad: 0.0,
        half_width_rad: (180.0_f64 / 4.0).to_radians(),
        record_s: 0.05,
        sampling_rate_hz: 25_600.0,
    };
    let want = ring_sensor_record(&dynamics, &response, sensor)
        .unwrap()
        .values_n;
    let got = ring_column(&out.join("signals/0000001.parquet"), want.len());
    let new = ring_column(&out.join("signals/0000000.parquet"), want.len());
    assert!(got != new, "the worn state's record equals the new set's");
    for (k, (a, b)) in want.iter().zip(&got).enumerate() {
        assert_eq!(*a as f32, *b, "sample {k} of the worn record");
    }

    // Labels: each member's wear, the limiting member, cycles, tooth contacts, remaining
    // cycles and mesh frequency, recomputed here.
    let car = json(&out.join("records/0000001.json"))["labels"].clone();
    let um = members_um(&states);
    let names = ["sun", "planet1", "planet2", "planet3", "planet4", "ring"];
    let members = car["members"].as_array().unwrap();
    assert_eq!(members.len(), 6);
    for (k, m) in members.iter().enumerate() {
        assert_eq!(m["member"], names[k]);
        // The same sums in the same order but for the advance's grouping: 1e-12.
        let v = m["wear_max_um"].as_f64().unwrap();
        assert!(
            close(v, um[k], 1e-12),
            "{}: {v} against {}",
            names[k],
            um[k]
        );
    }
    assert!(um.iter().all(|v| *v > 0.0));
    let deepest = um
        .iter()
        .enumerate()
        .fold((0, 0.0), |b, (k, v)| if *v >= b.1 { (k, *v) } else { b });
    assert_eq!(car["limiting_member"], names[deepest.0]);
    assert_eq!(car["cycles"].as_f64(), Some(1e5));
    // Tooth contacts: a sun tooth meets every planet once per sun turn relative to the
    // carrier: 4 x (1 - 1 / (1 + 85 / 23)) = 4 x 85 / 108 per sun turn (ring fixed).
    let sun_contacts = members[0]["tooth_contacts"].as_f64().unwrap();
    assert!(
        close(sun_contacts, 1e5 * 4.0 * 85.0 / 108.0, 1e-12),
        "{sun_contacts}"
    );
    // Mesh frequency z_r f_c with f_c = 25 x 23 / 108 Hz.
    assert!(close(
        car["mesh_hz"].as_f64().unwrap(),
        85.0 * 25.0 * 23.0 / 108.0,
        1e-12
    ));
    let end = t["end_cycles"].as_f64().unwrap();
    match t["failure_cycles"].as_f64() {
        Some(f) => assert!(close(
            car["remaining_cycles"].as_f64().unwrap(),
            f - 1e5,
            1e-12
        )),
        None => {
            assert_eq!(car["failure_censored"], true);
            assert!(close(
                car["remaining_cycles"].as_f64().unwrap(),
                end - 1e5,
                1e-12
            ));
        }
    }
    // The index's member columns hold the same labels.
    let wear_ring = column(&out.join("index.csv"), "wear_max_um_ring");
    assert!(close(wear_ring[1], um[5], 1e-12));
    // Indicators from the stored samples: RMS, crest factor, kurtosis (central, 4th).
    let x: Vec<f64> = got.iter().map(|v| f64::from(*v)).collect();
    let n = x.len() as f64;
    let rms = (x.iter().map(|v| v * v).sum::<f64>() / n).sqrt();
    let mean = x.iter().sum::<f64>() / n;
    let m2 = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n;
    let m4 = x.iter().map(|v| (v - mean).powi(4)).sum::<f64>() / n;
    let ind = &car["indicators"][0];
    // Sums of 1280 terms in another order: 1e-9.
    assert!(close(ind["rms"].as_f64().unwrap(), rms, 1e-9));
    assert!(close(
        ind["kurtosis"].as_f64().unwrap(),
        m4 / (m2 * m2),
        1e-9
    ));
    let peak = x.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
    assert!(close(
        ind["crest_factor"].as_f64().unwrap(),
        peak / rms,
        1e-9
    ));
}

/// Every file of a dataset folder that a run publishes (records, signals, CSV, index,
/// metadata, trajectories), as bytes.
fn folder(root: &Path) -> Vec<(String, Vec<u8>)> {
    let mut all = Vec::new();
    for sub in ["signals", "records", "csv", "state"] {
        let mut names: Vec<_> = std::fs::read_dir(root.join(sub))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            // A write's temporary file a kill left (not a published file).
            .filter(|n| !n.starts_with('.'))
            .collect();
        names.sort();
        for n in names {
            all.push((
                format!("{sub}/{n}"),
                std::fs::read(root.join(sub).join(&n)).unwrap(),
            ));
        }
    }
    for f in ["index.csv", "index.parquet", "metadata.json"] {
        all.push((f.to_owned(), std::fs::read(root.join(f)).unwrap()));
    }
    all
}

#[test]
fn planetary_datasets_resume_and_merge_to_one_run_and_name_a_forged_label() {
    let dir = tempfile::tempdir().unwrap();
    let d = design(
        dir.path(),
        "d.toml",
        "0, 50000, 100000, 150000",
        &["signals.snr_db=20"],
        "noise_realisations = 2\n",
    );
    let whole = dir.path().join("whole");
    let r = dataset(&d, &whole, &[]);
    assert!(r.status.success(), "{}", stderr(&r));
    let reference = folder(&whole);

    // Killed once its first record is written, then resumed.
    let killed = dir.path().join("killed");
    let args: Vec<String> = [
        "-q",
        "dataset",
        "--design",
        d.to_str().unwrap(),
        "--out",
        killed.to_str().unwrap(),
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let first = killed.join("records/0000000.json");
    kill_when(&args, &|| first.exists());
    let r = dataset(&d, &killed, &[]);
    assert!(r.status.success(), "{}", stderr(&r));
    assert!(
        folder(&killed) == reference,
        "the resumed folder differs from one run"
    );

    // Two shards merged.
    let shards: Vec<PathBuf> = (1..=2).map(|i| dir.path().join(format!("s{i}"))).collect();
    for (i, s) in shards.iter().enumerate() {
        let r = dataset(&d, s, &["--shard", &format!("{}/2", i + 1)]);
        assert!(r.status.success(), "{}", stderr(&r));
    }
    let merged = dir.path().join("merged");
    let mut a = vec!["-q", "dataset-merge"];
    a.extend(shards.iter().map(|s| s.to_str().unwrap()));
    a.extend(["--out", merged.to_str().unwrap()]);
    ok(&a);
    let m = folder(&merged);
    for name in ["index.csv", "index.parquet"] {
        assert!(
            m.iter().find(|f| f.0 == name) == reference.iter().find(|f| f.0 == name),
            "the merged {name} differs"
        );
    }
    let records = |f: &[(String, Vec<u8>)]| -> Vec<(String, Vec<u8>)> {
        f.iter()
            .filter(|x| x.0.starts_with("signals/") || x.0.starts_with("records/"))
            .cloned()
            .collect()
    };
    assert!(
        records(&m) == records(&reference),
        "the merged records differ"
    );

    // A forged member label (the ring's wear of record 5) is named on resume.
    let p = whole.join("records/0000005.json");
    let mut car = json(&p);
    let v = car["labels"]["members"][5]["wear_max_um"].as_f64().unwrap();
    car["labels"]["members"][5]["wear_max_um"] = serde_json::json!(v + 1.0);
    std::fs::write(&p, serde_json::to_vec_pretty(&car).unwrap()).unwrap();
    let r = dataset(&d, &whole, &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    let e = stderr(&r);
    assert!(e.contains("0000005.json") && e.contains("members"), "{e}");
}

#[test]
fn what_a_set_cannot_take_in_a_dataset_is_refused_by_key() {
    let dir = tempfile::tempdir().unwrap();
    for (set, needles) in [
        (
            "signals.channel_unit=g",
            &["`signals.channel_unit` = \"g\"", "force in N"][..],
        ),
        (
            "signals.noise_density_ug_per_sqrt_hz=50",
            &[
                "`signals.noise_density_ug_per_sqrt_hz` = 50",
                "signals.snr_db",
            ][..],
        ),
        (
            "signals.tachometer_shaft=gear",
            &["`signals.tachometer_shaft` = \"gear\"", "carrier"][..],
        ),
    ] {
        let d = design(
            dir.path(),
            "bad.toml",
            "0",
            &[set],
            "noise_realisations = 1\n",
        );
        let out = dir.path().join("bad");
        let r = dataset(&d, &out, &[]);
        assert_eq!(r.status.code(), Some(2), "{set}: {}", stderr(&r));
        let e = stderr(&r);
        for n in needles {
            assert!(e.contains(n), "{set}: {e}");
        }
        assert!(!out.exists(), "{set}: the refusal made the folder");
    }
}

#[test]
fn every_kept_planetary_record_s_labels_and_csv_are_checked_beyond_the_sample() {
    // A resume recomputes at most 8 physical states whole; the others' labels are
    // recomputed from the set's trajectory and their indicators and CSV twins from their
    // own signal files. 10 states, one record each: a member label forged in records 0-8
    // and the CSV twin of record 9 edited: all 10 are named, at least one forged label by
    // that check (at most 8 of the 9 states are sampled).
    let dir = tempfile::tempdir().unwrap();
    let cycles: Vec<String> = (0..10).map(|i| format!("{}", i * 15_000)).collect();
    let d = design(dir.path(), "d.toml", &cycles.join(", "), &[], "");
    let out = dir.path().join("ds");
    let r = dataset(&d, &out, &[]);
    assert!(r.status.success(), "{}", stderr(&r));
    for id in 0..9 {
        let p = out.join(format!("records/{id:07}.json"));
        let mut car = json(&p);
        let v = car["labels"]["members"][0]["wear_max_um"].as_f64().unwrap();
        car["labels"]["members"][0]["wear_max_um"] = serde_json::json!(v + 0.5);
        std::fs::write(&p, serde_json::to_vec_pretty(&car).unwrap()).unwrap();
    }
    let csv = out.join("csv/0000009.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let mut cells: Vec<String> = lines[3].split(',').map(str::to_owned).collect();
    let v: f64 = cells[1].parse().unwrap();
    cells[1] = format!("{}", v + 1.0);
    lines[3] = cells.join(",");
    std::fs::write(&csv, lines.join("\n") + "\n").unwrap();
    let r = dataset(&d, &out, &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    let e = stderr(&r);
    for id in 0..9 {
        assert!(
            e.contains(&format!("{id:07}.json")),
            "record {id} not named:\n{e}"
        );
    }
    assert!(
        e.contains("csv/0000009.csv"),
        "the edited CSV not named:\n{e}"
    );
    let by_labels = e
        .lines()
        .filter(|l| l.contains("from the design, its verified wear trajectory"))
        .count();
    assert!(by_labels >= 1, "no record named by the labels' check:\n{e}");
}
