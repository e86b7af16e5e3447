//! `gearwear dataset` on a planetary set whose condition carries a tooth fault
//! (`[[planetary.fault]]` in `[condition.case]`, docs/MODEL.md 5.x and 12.15), checked
//! against independent facts:
//! - the sun-crack condition's new-set record is the faulty set's ring sensor record
//!   (solved here from the faulty case: its steady state over the fault's period, heard
//!   by the case's sensor) and differs from the healthy condition's;
//! - the labels `fault`, `severity` and the sidecar's `planetary_faults` (member, tooth,
//!   kind, size), and the index's fault columns per row, are what the design and the
//!   condition's case say;
//! - a `fault` label that contradicts the case, or a severity on a healthy condition, is
//!   refused (exit 2) naming the key, before the folder exists;
//! - a forged fault table in a kept sidecar is named on resume (the labels recomputed
//!   from the case).

mod common;

use common::{gearwear, stderr};
use gearwear::study::planetary_signals::{ring_sensor_record, RingSensor};
use gearwear::study::planetary_wear::PlanetaryWearModel;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn case_path() -> String {
    format!("{}/examples/planetary_set.toml", env!("CARGO_MANIFEST_DIR"))
}

const CRACK: &str = "kind = \"crack\"\ngear = \"sun\"\ntooth = 3\ncrack_depth_mm = 1.5\n";

/// A design on the example set: a healthy condition and a sun-crack one (its `fault`
/// line `label`, severity `severity`), recording new teeth only.
fn design(dir: &Path, name: &str, label: &str, healthy_extra: &str) -> PathBuf {
    let text = format!(
        "case = {:?}\nseed = 5\nset = [\"signals.record_length=0.05\"]\n[run_to_failure]\ncycles = [0]\nmax_cycles = 2e4\nwear_limit_um = 50\n[records]\nnoise_realisations = 1\n[[condition]]\nname = \"healthy\"\n{healthy_extra}[[condition]]\nname = \"sun_crack\"\n{label}severity = 2.5\n[[condition.case.planetary.fault]]\n{CRACK}",
        case_path()
    );
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn dataset(design: &Path, out: &Path) -> std::process::Output {
    gearwear(&[
        "-q",
        "dataset",
        "--design",
        design.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

fn json(p: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap()
}

fn ring_column(p: &Path, samples: usize) -> Vec<f32> {
    let names = ["ring_sensor_n".to_owned(), "tachometer_v".to_owned()];
    let cols = gearwear::io::parquet::read_f32_columns(std::fs::read(p).unwrap(), &names, samples)
        .unwrap();
    cols[0].clone()
}

#[test]
fn a_sun_crack_conditions_records_are_the_faulty_sets_and_labelled_by_its_case() {
    let dir = tempfile::tempdir().unwrap();
    let d = design(dir.path(), "d.toml", "fault = \"crack\"\n", "");
    let out = dir.path().join("out");
    let r = dataset(&d, &out);
    assert!(r.status.success(), "{}", stderr(&r));
    // Record 0: the healthy condition's new set; record 1: the cracked set's.
    let cars: Vec<Value> = (0..2)
        .map(|i| json(&out.join(format!("records/{i:07}.json")))["labels"].clone())
        .collect();
    assert_eq!(cars[0]["condition"], "healthy");
    assert_eq!(cars[1]["condition"], "sun_crack");
    assert_eq!(cars[0]["fault"], "none");
    assert_eq!(cars[0]["severity"].as_f64(), Some(0.0));
    assert!(cars[0].get("planetary_faults").is_none());
    assert_eq!(cars[1]["fault"], "crack");
    assert_eq!(cars[1]["severity"].as_f64(), Some(2.5));
    let f = &cars[1]["planetary_faults"][0];
    assert_eq!(f["gear"], "sun");
    assert_eq!(f["tooth"].as_i64(), Some(3));
    assert_eq!(f["kind"], "crack");
    assert_eq!(f["crack_depth_mm"].as_f64(), Some(1.5));
    // The index's fault columns, row by row, against the design written above (the
    // healthy condition: none; the sun-crack one: sun tooth 3, a 1.5 mm crack).
    let (names, rows) = common::read_csv(&out.join("index.csv"));
    let col = |row: &[String], name: &str| {
        row[names
            .iter()
            .position(|n| n == name)
            .unwrap_or_else(|| panic!("{name}"))]
        .clone()
    };
    assert_eq!(rows.len(), 2);
    for row in &rows {
        let want: [&str; 7] = match col(row, "condition").as_str() {
            "healthy" => ["", "0", "-1", "", "0", "0", "0"],
            _ => ["sun", "0", "3", "crack", "1.5", "0", "0"],
        };
        for (name, w) in [
            "fault_member",
            "fault_planet",
            "fault_tooth",
            "fault_kind",
            "fault_crack_depth_mm",
            "fault_spall_depth_um",
            "fault_removed_height_mm",
        ]
        .iter()
        .zip(want)
        {
            let got = col(row, name);
            let same = match (got.parse::<f64>(), w.parse::<f64>()) {
                (Ok(a), Ok(b)) => a == b,
                _ => got == w,
            };
            assert!(same, "{name}: {got:?}, the design says {w:?}");
        }
    }

    // The faulty set's ring sensor record, solved here from its case (angle 0,
    // half-width 180 / N deg, 0.05 s at 25.6 kHz, as the example's signals give it).
    let text = std::fs::read_to_string(case_path()).unwrap();
    let faulty = format!("{text}\n[[planetary.fault]]\n{CRACK}");
    let case =
        gearwear::config::load_case(&faulty, &["signals.record_length=0.05".to_owned()]).unwrap();
    let mut dynamics = PlanetaryWearModel::from_case(&case).unwrap().dynamics;
    let response = dynamics.solve().unwrap();
    assert_eq!(
        response.mesh_periods, 23,
        "the sun's teeth: the fault's period"
    );
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
    let healthy = ring_column(&out.join("signals/0000000.parquet"), want.len());
    for (k, (a, b)) in want.iter().zip(&got).enumerate() {
        assert_eq!(*a as f32, *b, "sample {k} of the cracked set's record");
    }
    // The crack's dip: the records differ by more than float32 rounding (1e-6 of the
    // signal's scale).
    let scale = healthy.iter().fold(0.0_f32, |a, b| a.max(b.abs()));
    let diff = healthy
        .iter()
        .zip(&got)
        .fold(0.0_f32, |a, (x, y)| a.max((x - y).abs()));
    assert!(
        diff > 1e-3 * scale,
        "the cracked record differs by {diff} of {scale}"
    );

    // A forged fault table (another tooth) in the kept sidecar is named on resume.
    let p = out.join("records/0000001.json");
    let mut car = json(&p);
    car["labels"]["planetary_faults"][0]["tooth"] = serde_json::json!(4);
    std::fs::write(&p, serde_json::to_vec_pretty(&car).unwrap()).unwrap();
    let r = dataset(&d, &out);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    let e = stderr(&r);
    assert!(
        e.contains("0000001.json") && e.contains("planetary_faults"),
        "{e}"
    );
}

#[test]
fn a_label_that_contradicts_the_sets_case_is_refused_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    for (label, healthy, needles) in [
        (
            "fault = \"spall\"\n",
            "",
            &["`fault` = \"spall\"", "models (\"crack\")", "sun_crack"][..],
        ),
        (
            "",
            "severity = 1.0\n",
            &["`severity` = 1", "models no fault", "healthy"][..],
        ),
    ] {
        let d = design(dir.path(), "bad.toml", label, healthy);
        let out = dir.path().join("bad");
        let r = dataset(&d, &out);
        assert_eq!(r.status.code(), Some(2), "{label}{healthy}: {}", stderr(&r));
        let e = stderr(&r);
        for n in needles {
            assert!(e.contains(n), "{label}{healthy}: {e} lacks {n}");
        }
        assert!(!out.exists(), "the refusal made the folder");
    }
}
