//! Every kept record's labels recomputed (issue 33, "every record verified"): a resume
//! and a merge recompute the signals of at most eight physical states (a steady-state
//! solve each), but the labels of every kept record from the verified wear trajectory
//! and the design. A label forged in records no sample can reach is refused all the
//! same: with 20 states and 18 forged records, at least 12 are outside any sample, and
//! every one of the 18 must be named (by the sample's recomputation or by the labels'
//! check), on a single pair, on a merge's shard and on a gear train. A record's indicators
//! are recomputed from its own signal file (they are computed from the samples as stored),
//! so an indicator forged in any record is named too; and each equals the indicator the
//! test computes itself from the Parquet file's samples.

mod common;

use common::{gearwear, stderr};
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;
use serde_json::Value;
use std::path::Path;

/// States recomputed whole by a resume or a merge (`MAX_RECOMPUTED_STATES`).
const SAMPLED: usize = 8;

/// One condition, `states` states, one speed, one noise realisation: a record per state.
fn pair_design(states: usize) -> String {
    format!(
        "seed = 3\n[run_to_failure]\nstates = {states}\nmax_cycles = 1e4\nwear_limit_um = 10\n\
         [operating]\ninput_speed_hz = [30]\n[records]\nnoise_realisations = 1\n"
    )
}

fn dataset(dir: &Path, out: &str, extra: &[&str]) -> std::process::Output {
    let p = |s: &str| dir.join(s).to_str().unwrap().to_owned();
    let mut a = vec![
        "dataset".to_owned(),
        "-q".to_owned(),
        "--design".to_owned(),
        p("design.toml"),
        "--out".to_owned(),
        p(out),
    ];
    a.extend(extra.iter().map(|s| s.to_string()));
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    gearwear(&a)
}

/// Require success of a run.
fn ok(r: &std::process::Output) {
    assert!(r.status.success(), "{}", stderr(r));
}

/// Apply `edit` to the labels of record `id`'s sidecar in `ds` (the signal and its
/// checksum untouched: only the index would carry the forgery).
fn forge(ds: &Path, id: usize, edit: &dyn Fn(&mut Value)) {
    let p = ds.join(format!("records/{id:07}.json"));
    let mut v: Value = serde_json::from_slice(&std::fs::read(&p).unwrap()).unwrap();
    edit(&mut v["labels"]);
    std::fs::write(&p, serde_json::to_vec_pretty(&v).unwrap()).unwrap();
}

fn scale(v: &mut Value, f: f64) {
    *v = (v.as_f64().unwrap() * f).into();
}

/// The dataset's own files (records, signals, trajectories, index and metadata), by
/// path, for "no record changed" (a refused run may mark the folder incomplete).
fn files(ds: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for sub in ["records", "signals", "state"] {
        for e in std::fs::read_dir(ds.join(sub)).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(ds).unwrap().to_string_lossy().into_owned();
            out.push((rel, std::fs::read(&p).unwrap()));
        }
    }
    for f in ["index.csv", "metadata.json"] {
        out.push((f.into(), std::fs::read(ds.join(f)).unwrap()));
    }
    out.sort();
    out
}

/// The refusal names every forged record's sidecar, and at least `forged - SAMPLED` of
/// them through the labels' check (those no sample recomputed).
fn assert_all_named(err: &str, ds: &Path, forged: &[usize], field: &str) {
    for id in forged {
        let name = ds.join(format!("records/{id:07}.json"));
        assert!(
            err.contains(&format!("{}: record {id}", name.display())),
            "record {id} not named:\n{err}"
        );
    }
    let by_labels = err
        .lines()
        .filter(|l| l.contains("from the design, its verified wear trajectory"))
        .filter(|l| l.contains(&format!("`{field}`")))
        .count();
    assert!(
        by_labels >= forged.len() - SAMPLED,
        "{by_labels} of {} forged records found by the labels' check:\n{err}",
        forged.len()
    );
}

/// A 20-record dataset whose records 1-18 had their labels edited, then resumed.
struct Forged {
    dir: tempfile::TempDir,
    ds: std::path::PathBuf,
    forged: Vec<usize>,
    /// The folder's files before the resume.
    before: Vec<(String, Vec<u8>)>,
    resume: std::process::Output,
}

/// [`Forged`] with the labels of records 1-18 edited by `edit`.
fn resume_forged(edit: &dyn Fn(&mut Value)) -> Forged {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), pair_design(20)).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    let ds = dir.path().join("ds");
    let forged: Vec<usize> = (1..19).collect();
    for &id in &forged {
        forge(&ds, id, edit);
    }
    let before = files(&ds);
    let resume = dataset(dir.path(), "ds", &[]);
    Forged {
        dir,
        ds,
        forged,
        before,
        resume,
    }
}

#[test]
fn a_resume_refuses_a_label_forged_in_any_record() {
    let f = resume_forged(&|l| scale(&mut l["max_wear_pinion_um"], 1.5));
    let (dir, ds, forged, r) = (&f.dir, &f.ds, &f.forged, &f.resume);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(r));
    assert_all_named(&stderr(r), ds, forged, "max_wear_pinion_um");
    assert!(files(ds) == f.before, "a refused resume changed a record");

    // The library's verification of the folder finds every one of them as well.
    let v = gearwear::app::dataset::jobs::verify_folder(
        &gearwear::app::dataset::DesignSource::file(&dir.path().join("design.toml")).unwrap(),
        ds,
        SAMPLED,
        11,
        gearwear::app::budget::DEFAULT.as_ref(),
    )
    .unwrap();
    assert_all_named(&v.problems.join("\n"), ds, forged, "max_wear_pinion_um");
}

#[test]
fn a_merge_refuses_a_label_forged_in_any_record_of_a_shard() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), pair_design(40)).unwrap();
    ok(&dataset(dir.path(), "s1", &["--shard", "1/2"]));
    ok(&dataset(dir.path(), "s2", &["--shard", "2/2"]));
    // Shard 2 holds the odd states (records 1, 3, ..., 39): forge 18 of its 20.
    let s2 = dir.path().join("s2");
    let forged: Vec<usize> = (3..39).step_by(2).collect();
    for &id in &forged {
        forge(&s2, id, &|l| scale(&mut l["remaining_cycles"], 0.5));
    }
    let p = |s: &str| dir.path().join(s).to_str().unwrap().to_owned();
    let r = gearwear(&[
        "dataset-merge",
        "-q",
        &p("s1"),
        &p("s2"),
        "--out",
        &p("merged"),
    ]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert_all_named(&stderr(&r), &s2, &forged, "remaining_cycles");
    assert!(!dir.path().join("merged/index.csv").exists());
}

#[test]
fn a_resume_refuses_a_stage_label_forged_in_any_record_of_a_train() {
    let dir = tempfile::tempdir().unwrap();
    let case = format!(
        "{}/examples/two_stage_reducer.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    // Coarse grids keep the 20 train states cheap (the labels do not depend on them).
    let design = format!(
        "case = {case:?}\nseed = 5\nset = [\"numerics.steps_per_mesh_period=60\", \
         \"numerics.evaluated_mesh_periods=2\", \"stiffness.table_points_per_mesh_period=60\", \
         \"signals.record_length=0.05\"]\n[run_to_failure]\nstates = 20\nmax_cycles = 2e4\n\
         wear_limit_um = 50\n[records]\nnoise_realisations = 1\n"
    );
    std::fs::write(dir.path().join("design.toml"), design).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    let ds = dir.path().join("ds");
    let forged: Vec<usize> = (1..19).collect();
    for &id in &forged {
        forge(&ds, id, &|l| {
            scale(&mut l["stages"][1]["max_wear_gear_um"], 1.25)
        });
    }
    let r = dataset(dir.path(), "ds", &[]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert_all_named(&stderr(&r), &ds, &forged, "stages.1.max_wear_gear_um");
}

#[test]
fn a_resume_refuses_an_indicator_forged_in_any_record() {
    // Recomputed from each record's own signal file: no solve, no sample.
    let f = resume_forged(&|l| scale(&mut l["indicators"][0]["kurtosis"], 1.01));
    assert_eq!(f.resume.status.code(), Some(2), "{}", stderr(&f.resume));
    assert_all_named(
        &stderr(&f.resume),
        &f.ds,
        &f.forged,
        "indicators.0.kurtosis",
    );
    assert!(
        files(&f.ds) == f.before,
        "a refused resume changed a record"
    );
}

/// The float32 columns of a record's Parquet file, by name, read row by row (the
/// reference reader's record API, not the column reader gearwear uses).
fn parquet_columns(path: &Path) -> Vec<(String, Vec<f64>)> {
    let r = SerializedFileReader::new(std::fs::File::open(path).unwrap()).unwrap();
    let names: Vec<String> = (r.metadata().file_metadata().schema_descr().columns())
        .iter()
        .map(|c| c.name().to_owned())
        .collect();
    let mut cols = vec![Vec::new(); names.len()];
    for row in r.get_row_iter(None).unwrap() {
        for (j, (_, f)) in row.unwrap().get_column_iter().enumerate() {
            match f {
                Field::Float(v) => cols[j].push(f64::from(*v)),
                other => panic!("column {} holds {other:?}, not a float", names[j]),
            }
        }
    }
    names.into_iter().zip(cols).collect()
}

#[test]
fn every_record_s_signal_indicators_are_those_of_its_stored_samples() {
    // What a PHM engineer checks first: load a record's file, compute the RMS, crest
    // factor and kurtosis, compare with the label. Computed here from the file's float32
    // samples by the textbook formulas; summed in sample order as gearwear does, so the
    // only difference is the order of the kurtosis' moments (bound: N eps ~ 3e-12 for the
    // 25 600 samples of a second at 25.6 kHz). A label computed from the samples before
    // their rounding to float32 differs by ~1e-10 (RMS) and ~3e-8 (crest factor).
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), pair_design(3)).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    let ds = dir.path().join("ds");
    for id in 0..3 {
        let car: Value = serde_json::from_slice(
            &std::fs::read(ds.join(format!("records/{id:07}.json"))).unwrap(),
        )
        .unwrap();
        let labels = &car["labels"];
        let columns = parquet_columns(&ds.join(labels["file"].as_str().unwrap()));
        let indicators = labels["indicators"].as_array().unwrap();
        assert_eq!(
            indicators.len() + 1,
            columns.len(),
            "a column per channel and the tachometer"
        );
        for (ind, (name, x)) in indicators.iter().zip(&columns) {
            assert!(name.starts_with(ind["channel"].as_str().unwrap()), "{name}");
            let n = x.len() as f64;
            let ms = x.iter().map(|v| v * v).sum::<f64>() / n;
            let rms = ms.sqrt();
            let peak = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let mean = x.iter().sum::<f64>() / n;
            let m2 = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n;
            let m4 = x.iter().map(|v| (v - mean).powi(4)).sum::<f64>() / n;
            let close = |label: &str, want: f64| {
                let got = ind[label].as_f64().unwrap();
                assert!(
                    (got - want).abs() <= 4e-12 * want.abs(),
                    "record {id} {name} {label}: label {got}, from the file {want}"
                );
            };
            close("rms", rms);
            close("crest_factor", peak / rms);
            close("kurtosis", m4 / (m2 * m2));
        }
    }
}

/// A design asking for every record's CSV twin (PHM 2009-style text beside the Parquet
/// file): 12 states, one record each.
fn csv_design() -> String {
    pair_design(12).replace(
        "noise_realisations = 1\n",
        "noise_realisations = 1\ncsv = true\n",
    )
}

#[test]
fn every_record_s_csv_twin_holds_the_samples_of_its_parquet_file() {
    // The CSV a user loads in MATLAB must be the record: each column's values, parsed
    // from the text, equal the Parquet file's float32 samples read by the reference row
    // reader (exactly: float32 values printed and parsed back round trip), and the time
    // column is n / f_s.
    let dir = tempfile::tempdir().unwrap();
    let design = pair_design(2).replace(
        "noise_realisations = 1\n",
        "noise_realisations = 1\ncsv = true\n",
    );
    std::fs::write(dir.path().join("design.toml"), design).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    let ds = dir.path().join("ds");
    for id in 0..2 {
        let car: Value = serde_json::from_slice(
            &std::fs::read(ds.join(format!("records/{id:07}.json"))).unwrap(),
        )
        .unwrap();
        let columns = parquet_columns(&ds.join(car["labels"]["file"].as_str().unwrap()));
        let mut csv = csv::Reader::from_path(ds.join(format!("csv/{id:07}.csv"))).unwrap();
        let header: Vec<String> = csv.headers().unwrap().iter().map(str::to_owned).collect();
        assert_eq!(header[0], "time_s");
        let rows: Vec<Vec<f64>> = csv
            .records()
            .map(|r| r.unwrap().iter().map(|c| c.parse().unwrap()).collect())
            .collect();
        assert_eq!(
            header.len(),
            columns.len() + 1,
            "time and every Parquet column"
        );
        let meta: Value =
            serde_json::from_slice(&std::fs::read(ds.join("metadata.json")).unwrap()).unwrap();
        let fs = meta["record"]["sampling_rate_hz"].as_f64().unwrap();
        for (j, (name, x)) in columns.iter().enumerate() {
            assert_eq!(&header[j + 1], name);
            assert_eq!(rows.len(), x.len(), "{name}: sample count");
            for (n, row) in rows.iter().enumerate() {
                assert_eq!(
                    row[j + 1] as f32,
                    x[n] as f32,
                    "record {id} {name} sample {n}"
                );
                assert!((row[0] - n as f64 / fs).abs() <= 1e-12 * (1.0 + row[0]));
            }
        }
    }
}

#[test]
fn a_resume_or_merge_refuses_an_edited_or_missing_csv_twin_in_any_record() {
    // The CSV twin is not in the sidecar's checksum: it is rendered again from the
    // verified signal file for every kept record. 12 states, one record each: records
    // 1-9 edited (one sample changed in the last digit shown) and record 10's removed;
    // at least 2 of them are beyond the 8 sampled states, so the labels' check must name
    // them.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("design.toml"), csv_design()).unwrap();
    ok(&dataset(dir.path(), "ds", &[]));
    ok(&dataset(dir.path(), "shard", &["--shard", "1/1"]));
    let edit = |ds: &Path| {
        for id in 1..10 {
            let p = ds.join(format!("csv/{id:07}.csv"));
            let text = std::fs::read_to_string(&p).unwrap();
            let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
            let mut cells: Vec<String> = lines[5].split(',').map(str::to_owned).collect();
            let v: f32 = cells[1].parse().unwrap();
            cells[1] = format!("{}", v * 1.001 + 1e-3);
            lines[5] = cells.join(",");
            std::fs::write(&p, lines.join("\n") + "\n").unwrap();
        }
        std::fs::remove_file(ds.join("csv/0000010.csv")).unwrap();
    };
    let ds = dir.path().join("ds");
    edit(&ds);
    let before = files(&ds);
    let resume = dataset(dir.path(), "ds", &[]);
    assert_eq!(resume.status.code(), Some(2), "{}", stderr(&resume));
    let err = stderr(&resume);
    for id in 1..11 {
        assert!(
            err.contains(&format!("csv/{id:07}.csv")),
            "record {id}'s CSV not named:\n{err}"
        );
    }
    assert!(files(&ds) == before, "a refused resume changed a record");
    assert!(
        !err.contains("csv/0000011.csv"),
        "an intact CSV named:\n{err}"
    );

    // The same edits in a shard: its merge is refused and writes no index.
    let shard = dir.path().join("shard");
    edit(&shard);
    let merged = dir.path().join("merged");
    let m = gearwear(&[
        "dataset-merge",
        "-q",
        "--out",
        merged.to_str().unwrap(),
        shard.to_str().unwrap(),
    ]);
    assert_eq!(m.status.code(), Some(2), "{}", stderr(&m));
    assert!(stderr(&m).contains("csv/0000010.csv"), "{}", stderr(&m));
    assert!(!merged.join("index.csv").exists());
}
