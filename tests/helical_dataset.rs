//! Datasets, calibration and prediction of a helical pair (docs/MODEL.md 11.9) against
//! independent facts: a dataset state's wear labels are `gearwear wear`'s own updates
//! advanced within their block by hand (paper eq. 17, slice by slice), its record's mesh
//! frequency is z1 f; at a vanishing helix angle one slice is the spur pair's dataset; a
//! tampered record or trajectory is found on resume; a calibration recovers the wear
//! coefficient that made its observations, and a prediction at that coefficient gives the
//! life that `gearwear wear`'s updates reach the limit at; what is not built is refused.

mod common;

use common::{gearwear, ok, read_csv, rejected, stderr};
use gearwear::study::wear_loop::UpdateRecord;
use std::path::{Path, PathBuf};

/// The example helical pair (15 deg, 400 slices, a 10 um crowning).
fn example() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/helical_pair.toml")
        .to_str()
        .unwrap()
        .to_owned()
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    std::fs::create_dir_all(dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

/// The updates of `gearwear wear`'s dynamic checkpoint in `dir` (each line: its checksum,
/// a space, the JSON of the record; the first line is the header).
fn checkpoint(dir: &Path) -> Vec<UpdateRecord> {
    std::fs::read_to_string(dir.join("checkpoint_dynamic.jsonl"))
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| serde_json::from_str(l.split_once(' ').unwrap().1).unwrap())
        .collect()
}

/// Deepest pinion and gear wear (m) over every face slice and point at `cycles`, from
/// the last update at or before it advanced by its per-slice increment (paper eq. 17: the
/// wear grows linearly within a block, each slice at its own rate), computed here.
fn deepest_at(records: &[UpdateRecord], cycles: f64) -> (f64, f64) {
    let r = records
        .iter()
        .rev()
        .find(|r| r.wear.cycles <= cycles)
        .unwrap();
    let n = cycles - r.wear.cycles;
    let (h, d) = (
        r.wear.slices.as_ref().unwrap(),
        r.increment_slices.as_ref().unwrap(),
    );
    let deepest = |h: &[Vec<f64>], d: &[Vec<f64>]| {
        h.iter().zip(d).fold(0.0_f64, |m, (h, d)| {
            h.iter().zip(d).fold(m, |m, (a, b)| m.max(a + n * b))
        })
    };
    (
        deepest(&h.pinion_m, &d.pinion_m),
        deepest(&h.gear_m, &d.gear_m),
    )
}

/// The index rows of a dataset folder, each as (column, value) pairs.
fn index(dir: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    read_csv(&dir.join("index.csv"))
}

fn column(h: &[String], row: &[String], name: &str) -> f64 {
    let i = h.iter().position(|c| c == name).unwrap();
    row[i].parse().unwrap()
}

/// Amplitude of the DFT of `x` (sampled at `fs` Hz) at `f` Hz, by direct summation.
fn amplitude_at(x: &[f64], fs: f64, f: f64) -> f64 {
    let w = 2.0 * std::f64::consts::PI * f / fs;
    let (mut re, mut im) = (0.0, 0.0);
    for (i, v) in x.iter().enumerate() {
        re += v * (w * i as f64).cos();
        im -= v * (w * i as f64).sin();
    }
    2.0 * (re * re + im * im).sqrt() / x.len() as f64
}

#[test]
fn a_helical_dataset_state_is_the_wear_study_advanced_within_its_block() {
    let dir = tempfile::tempdir().unwrap();
    // 12 345 cycles lies inside a block of the wear loop (its updates fall where 0.5 um
    // of wear is reached, about every 3500 cycles), so the label is a state between two
    // updates, which the dataset advances slice by slice.
    let design = write(
        dir.path(),
        "design.toml",
        &format!(
            "seed = 3\ncase = \"{}\"\nset = [\"signals.record_length=0.12\"]\n\
             [run_to_failure]\ncycles = [0, 12345]\nmax_cycles = 2e4\nwear_limit_um = 50\n\
             [records]\ncsv = true\n[[condition]]\nname = \"helical\"\n",
            example()
        ),
    );
    let ds = dir.path().join("ds");
    ok(&[
        "dataset",
        "--design",
        &design,
        "--out",
        ds.to_str().unwrap(),
    ]);
    let w = dir.path().join("wear");
    ok(&[
        "wear",
        "--config",
        &example(),
        "--set",
        "wear.total_cycles=2e4",
        "--mode",
        "dynamic",
        "--out",
        w.to_str().unwrap(),
    ]);
    let records = checkpoint(&w);
    let (p, g) = deepest_at(&records, 12345.0);
    let car: serde_json::Value =
        serde_json::from_slice(&std::fs::read(ds.join("records/0000001.json")).unwrap()).unwrap();
    let l = &car["labels"];
    // The same loop on the same model, advanced by the same sum h + n dh: equal to
    // round-off (1e-12 relative allows the order of one addition).
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    let (lp, lg) = (
        l["max_wear_pinion_um"].as_f64().unwrap(),
        l["max_wear_gear_um"].as_f64().unwrap(),
    );
    assert!(close(lp, p * 1e6), "{lp} against {}", p * 1e6);
    assert!(close(lg, g * 1e6), "{lg} against {}", g * 1e6);
    // Every tooth alike, each the deepest face slice's wear; under the crowning the
    // middle of the face wears deepest, so the mean profile over the slices is
    // shallower: a label of the mean would be caught.
    let teeth = l["wear_pinion_tooth_um"].as_array().unwrap();
    assert_eq!(teeth.len(), 19);
    assert!(teeth.iter().all(|t| close(t.as_f64().unwrap(), p * 1e6)));
    let r = records
        .iter()
        .rev()
        .find(|r| r.wear.cycles <= 12345.0)
        .unwrap();
    let n = 12345.0 - r.wear.cycles;
    let mean_max = r
        .wear
        .pinion_m
        .iter()
        .zip(&r.increment_pinion_m)
        .fold(0.0_f64, |m, (h, d)| m.max(h + n * d));
    assert!(mean_max < 0.99 * p, "{mean_max} against {p}");
    // The mesh frequency is z1 f = 19 x 30 Hz, and the record has its line there: far
    // above the spectrum's level half-way to the next harmonic (a bin between lines),
    // computed here from the CSV twin.
    let (h, rows) = index(&ds);
    assert_eq!(column(&h, &rows[1], "mesh_hz"), 19.0 * 30.0);
    let (ch, data) = read_csv(&ds.join("csv/0000000.csv"));
    let fs = column(&h, &rows[0], "sampling_rate_hz");
    let x: Vec<f64> = data.iter().map(|r| r[1].parse().unwrap()).collect();
    assert!(ch[0] == "time_s", "{ch:?}");
    let (line, between) = (amplitude_at(&x, fs, 570.0), amplitude_at(&x, fs, 855.0));
    assert!(line > 10.0 * between, "{line} against {between}");
}

/// The index of a dataset of the built-in case on the nominal path, its load shared by
/// compression (as a helical pair's always is), with `extra` keys set.
fn built_in_dataset(dir: &Path, name: &str, extra: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let design = write(
        dir,
        &format!("{name}.toml"),
        &format!(
            "seed = 5\nset = ['signals.record_length=0.12', 'contact.path=\"nominal\"', \
             'contact.load_sharing=\"stiffness\"'{extra}]\n\
             [run_to_failure]\ncycles = [0, 12345]\nmax_cycles = 3e4\nwear_limit_um = 50\n\
             [[condition]]\nname = \"c\"\n"
        ),
    );
    let out = dir.join(name);
    ok(&[
        "dataset",
        "--design",
        &design,
        "--out",
        out.to_str().unwrap(),
    ]);
    index(&out)
}

#[test]
fn at_a_vanishing_helix_angle_one_slice_is_the_spur_dataset() {
    // beta = 1e-6 deg with one slice is the helical model (its line model, its wear per
    // slice, its gap from the slices) of a pair whose helical terms differ from the spur
    // pair's by O(beta) ~ 2e-8 rad, and whose one slice sits at half the lead L = b
    // tan(beta_b) = 3.5e-10 m from the wear grid's points: the wear gap is read
    // L / (2 spacing) = 1.8e-6 of a grid cell away from the spur pair's. The labels and
    // the signal's own indicators (RMS, crest factor, kurtosis, TSA RMS, FM0) equal the
    // spur dataset's to 1e-5 relative (measured at most 1.4e-6); the indicators of the
    // residual signal (FM4, NA4, NB4, M6A, M8A, energy ratio, sidebands) divide by a
    // residual of 1e-5 of the signal and amplify that: to 1e-2 (measured at most
    // 1.8e-3). Before the line gap kept its end cells (`HelicalDynamics::wear_gap`), the
    // helical pair wore 7 % deeper by 12 345 cycles.
    let dir = tempfile::tempdir().unwrap();
    let (hs, spur) = built_in_dataset(dir.path(), "spur", "");
    let (hh, hel) = built_in_dataset(
        dir.path(),
        "helical",
        ", 'gear.helix_angle_deg=1e-6', 'stiffness.slices=1'",
    );
    assert_eq!(hs, hh);
    for (a, b) in spur.iter().zip(&hel) {
        for (k, name) in hs.iter().enumerate() {
            let (Ok(x), Ok(y)) = (a[k].parse::<f64>(), b[k].parse::<f64>()) else {
                assert_eq!(a[k], b[k], "{name}");
                continue;
            };
            let residual = [
                "fm4",
                "na4",
                "nb4",
                "m6a",
                "m8a",
                "energy_ratio",
                "sideband",
            ]
            .iter()
            .any(|s| name.contains(s));
            let tol = if residual { 1e-2 } else { 1e-5 };
            assert!(
                (x - y).abs() <= tol * x.abs().max(y.abs()).max(1e-300),
                "{name}: spur {x}, helical {y}"
            );
        }
    }
    // And the wear did grow: the comparison is not of new teeth alone.
    assert!(column(&hs, &spur[1], "max_wear_pinion_um") > 1.0);
}

#[test]
fn a_tampered_helical_record_or_trajectory_is_found_on_resume() {
    let dir = tempfile::tempdir().unwrap();
    let design = write(
        dir.path(),
        "design.toml",
        &format!(
            "seed = 3\ncase = \"{}\"\nset = [\"signals.record_length=0.12\"]\n\
             [run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 50\n\
             [[condition]]\nname = \"helical\"\n",
            example()
        ),
    );
    let ds = dir.path().join("ds");
    let args = [
        "dataset",
        "--design",
        &design,
        "--out",
        ds.to_str().unwrap(),
    ];
    ok(&args);
    // A resume of the untouched folder recomputes and reuses.
    assert!(ok(&args).contains("2 reused"));
    // One label of the worn state's sidecar moved by 1 %: the recomputation names it.
    let car = ds.join("records/0000001.json");
    let kept = std::fs::read(&car).unwrap();
    let mut v: serde_json::Value = serde_json::from_slice(&kept).unwrap();
    let x = v["labels"]["max_wear_pinion_um"].as_f64().unwrap();
    v["labels"]["max_wear_pinion_um"] = (1.01 * x).into();
    std::fs::write(&car, serde_json::to_vec_pretty(&v).unwrap()).unwrap();
    let o = gearwear(&args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("labels.max_wear_pinion_um"),
        "{}",
        stderr(&o)
    );
    std::fs::write(&car, &kept).unwrap();
    // One face slice's wear at one point of the kept trajectory moved by 1 %: the
    // slice's chain of Archard increments is broken.
    let t = ds.join("state/trajectory_helical.json");
    let mut v: serde_json::Value = serde_json::from_slice(&std::fs::read(&t).unwrap()).unwrap();
    let h = &mut v["trajectory"]["records"][1]["wear"]["slices"]["pinion_m"][200][50];
    *h = (1.01 * h.as_f64().unwrap()).into();
    std::fs::write(&t, serde_json::to_vec(&v).unwrap()).unwrap();
    let o = gearwear(&args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("face slice 200"), "{}", stderr(&o));
}

#[test]
fn what_is_not_built_for_a_helical_pair_is_refused_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let case = example();
    let design = |name: &str, extra: &str| {
        write(
            dir.path(),
            name,
            &format!(
                "case = \"{case}\"\nset = [\"signals.record_length=0.12\"{extra}]\n\
                 [run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 50\n\
                 [[condition]]\nname = \"c\"\n"
            ),
        )
    };
    // Tilting bearings: the slices' wear would ignore the tilt.
    let tilt = ", \"dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e6\"";
    rejected(
        &["dataset", "--design", &design("tilt.toml", tilt)],
        &[
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad",
            "`gearwear dataset`",
        ],
    );
    rejected(
        &[
            "calibrate",
            "--config",
            &case,
            "--set",
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e6",
            "--observations",
            &write(
                dir.path(),
                "obs.csv",
                "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um\n1000,0.1,0.05\n",
            ),
        ],
        &[
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad",
            "`gearwear calibrate`",
        ],
    );
    // Per-tooth errors: each slice would need its own gap.
    rejected(
        &[
            "dataset",
            "--design",
            &design("teeth.toml", ", \"teeth.accuracy_grade=6\""),
        ],
        &["[teeth]", "helical"],
    );
    // ... and in a condition's own case, and as the forward model of a prediction: the
    // wear studies refuse a helical pair's teeth (its slices would have to wear tooth by
    // tooth; they ran before, review finding).
    let condition = write(
        dir.path(),
        "condition_teeth.toml",
        &format!(
            "case = \"{case}\"\nset = [\"signals.record_length=0.12\"]\n\
             [run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 50\n\
             [[condition]]\nname = \"c\"\n[condition.case.teeth]\naccuracy_grade = 6\nerror_seed = 1\n"
        ),
    );
    rejected(
        &["dataset", "--design", &condition],
        &["[teeth]", "gear.helix_angle_deg"],
    );
    rejected(
        &[
            "predict",
            "--config",
            &case,
            "--set",
            "teeth.accuracy_grade=6",
            "--limit-um",
            "10",
            "--cycles",
            "1e5",
            // Past the budget (which counts a toothed pair's long runs) to the model.
            "--no-budget",
        ],
        &["[teeth]", "`gearwear predict`"],
    );
}

/// Observations of the deepest pinion wear at every other update of `gearwear wear` on
/// the example at wear coefficient `k` to 4e4 cycles, sigma 0.05 um; and the updates.
fn observations(dir: &Path, k: f64) -> (PathBuf, Vec<UpdateRecord>) {
    let w = dir.join("truth");
    ok(&[
        "wear",
        "--config",
        &example(),
        "--set",
        &format!("wear.coefficient_m2_per_n={k}"),
        "--set",
        "wear.total_cycles=4e4",
        "--mode",
        "dynamic",
        "--out",
        w.to_str().unwrap(),
    ]);
    let (h, rows) = read_csv(&w.join("updates_dynamic.csv"));
    let mut text = "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um\n".to_owned();
    for r in rows.iter().skip(1).step_by(2) {
        let c = column(&h, r, "cycles");
        let v = column(&h, r, "max_wear_pinion_um");
        text.push_str(&format!("{c},{v},0.05\n"));
    }
    let p = dir.join("obs.csv");
    std::fs::write(&p, text).unwrap();
    (p, checkpoint(&w))
}

#[test]
fn calibration_and_prediction_of_a_helical_pair_recover_the_wear_study() {
    // Observations made by `gearwear wear` at k0 = 1.6e-16 m^2/N (not the case's 2.5e-16),
    // noise-free, sigma 0.05 um: the posterior's 90 % interval holds k0, and its median
    // lies within the interval's width of it.
    let dir = tempfile::tempdir().unwrap();
    let k0 = 1.6e-16;
    let (obs, truth) = observations(dir.path(), k0);
    let cfg = write(
        dir.path(),
        "case.toml",
        &format!(
            "{}\n[calibration]\nwear_coefficient_min_m2_per_n = 2e-17\n\
             wear_coefficient_max_m2_per_n = 6e-16\n",
            std::fs::read_to_string(example()).unwrap()
        ),
    );
    let cal = dir.path().join("cal");
    ok(&[
        "calibrate",
        "--config",
        &cfg,
        "--observations",
        obs.to_str().unwrap(),
        "--samples",
        "400",
        "--out",
        cal.to_str().unwrap(),
    ]);
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(cal.join("summary.json")).unwrap()).unwrap();
    let p = s["parameters"]
        .as_array()
        .and_then(|a| a.first())
        .cloned()
        .unwrap_or_else(|| panic!("{s}"));
    assert_eq!(p["parameter"], "wear_coefficient_m2_per_n");
    let (lo, med, hi) = (
        p["ci90"][0].as_f64().unwrap(),
        p["median"].as_f64().unwrap(),
        p["ci90"][1].as_f64().unwrap(),
    );
    assert!(lo <= k0 && k0 <= hi, "[{lo}, {hi}] misses {k0}");
    assert!(
        (med - k0).abs() <= hi - lo,
        "median {med}, interval [{lo}, {hi}]"
    );
    // At k0 itself (a prior of one point) every sample's life to 2 um is the cycles at
    // which the wear study's deepest slice point reaches 2 um: found here by bisection on
    // its updates advanced within their blocks. The surrogate's reference run at k0 is
    // the same loop to a longer horizon (the same blocks up to there): 1e-6 relative.
    let point = write(
        dir.path(),
        "point.toml",
        &format!(
            "{}\n[calibration]\nwear_coefficient_min_m2_per_n = {k0}\n\
             wear_coefficient_max_m2_per_n = {k0}\n",
            std::fs::read_to_string(example()).unwrap()
        ),
    );
    let pred = dir.path().join("pred");
    ok(&[
        "predict",
        "--config",
        &point,
        "--limit-um",
        "2",
        "--cycles",
        "4e4",
        "--samples",
        "50",
        "--out",
        pred.to_str().unwrap(),
    ]);
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(pred.join("summary.json")).unwrap()).unwrap();
    let life = s["remaining_life_cycles"]["median"].as_f64().unwrap();
    let (mut a, mut b) = (0.0, 4e4);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if deepest_at(&truth, m).0 >= 2e-6 {
            b = m;
        } else {
            a = m;
        }
    }
    assert!(
        (life - b).abs() <= 1e-6 * b,
        "predicted {life}, wear study {b}"
    );
}
