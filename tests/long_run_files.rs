//! A long dynamics run (a hunting period: ISO grades 6 and 8 give every tooth its own
//! errors) writes its long tables as Parquet, thinned to every k-th row unless the case asks
//! for full tables, and draws its figures from a decimated series. Checked across files and
//! against a second run with `output.full_tables = true`: the thinned table is exactly rows
//! 0, k, 2k, ... of the full one, with the columns a short run's CSV has; summary.json says
//! so; the decimated figure data keep the full series' extremes and ends exactly; the whole
//! output of a grade-6 run stays under the 20 MB of issue 34.
mod common;

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;
use std::path::Path;

/// Every column of a Parquet file as f64 (gearwear writes required doubles only).
fn read_parquet(path: &std::path::Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let r = SerializedFileReader::new(std::fs::File::open(path).unwrap()).unwrap();
    let schema = r.metadata().file_metadata().schema_descr();
    let names: Vec<String> = schema
        .columns()
        .iter()
        .map(|c| c.name().to_string())
        .collect();
    let mut cols = vec![Vec::new(); names.len()];
    for row in r.get_row_iter(None).unwrap() {
        for (j, (_, f)) in row.unwrap().get_column_iter().enumerate() {
            match f {
                Field::Double(v) => cols[j].push(*v),
                other => panic!("column {} holds {other:?}, not a double", names[j]),
            }
        }
    }
    (names, cols)
}

fn read_csv(path: &std::path::Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut r = csv::Reader::from_path(path).unwrap();
    let names: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    let mut cols = vec![Vec::new(); names.len()];
    for rec in r.records() {
        for (j, v) in rec.unwrap().iter().enumerate() {
            cols[j].push(v.parse::<f64>().unwrap());
        }
    }
    (names, cols)
}

fn extremes(v: &[f64]) -> (f64, f64) {
    let max = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let min = v.iter().copied().fold(f64::INFINITY, f64::min);
    (min, max)
}

/// Bytes of every file under `dir`.
fn folder_bytes(dir: &Path) -> u64 {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            if e.file_type().unwrap().is_dir() {
                folder_bytes(&e.path())
            } else {
                e.metadata().unwrap().len()
            }
        })
        .sum()
}

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

fn dynamics(grade: &str, extra: &[&str], out: &Path) {
    let set = format!("teeth.accuracy_grade={grade}");
    let mut args = vec!["-q", "dynamics", "--set", &set];
    args.extend_from_slice(extra);
    args.extend_from_slice(&["--out", out.to_str().unwrap()]);
    common::ok(&args);
}

#[test]
fn a_hunting_period_is_written_thinned_under_the_size_bound_and_whole_on_request() {
    let dir = tempfile::tempdir().unwrap();
    let (short, thin, full) = (
        dir.path().join("short"),
        dir.path().join("thin"),
        dir.path().join("full"),
    );
    common::ok(&["-q", "dynamics", "--out", short.to_str().unwrap()]);
    dynamics("6", &[], &thin);
    dynamics("6", &["--set", "output.full_tables=true"], &full);
    // The paper's case is short: CSV as ever, whole, and nothing said of thinning.
    assert!(short.join("timeseries.csv").is_file());
    assert!(!short.join("timeseries.parquet").exists());
    assert!(summary(&short).get("output").is_none());
    // Issue 34's bound on what a grade-6 hunting period writes by default.
    let bytes = folder_bytes(&thin);
    assert!(bytes < 20_000_000, "{bytes} bytes written");
    // The full tables: every recorded step (more than 1e6 values, hence Parquet), and
    // no `output` note; the same columns as the short run's CSV.
    assert!(summary(&full).get("output").is_none());
    let (names, whole) = read_parquet(&full.join("timeseries.parquet"));
    let (short_names, _) = read_csv(&short.join("timeseries.csv"));
    assert_eq!(names, short_names, "same columns in either form");
    let rows = whole[0].len();
    assert!(rows * names.len() > 1_000_000, "{rows} rows");
    // The thinned tables: what summary.json states, exactly rows 0, k, 2k, ... of the
    // full ones (the solve is deterministic, so both runs recorded the same steps).
    let notes = summary(&thin)["output"]["thinned_tables"].clone();
    let notes = notes.as_array().expect("thinned tables listed");
    assert_eq!(notes.len(), 2, "{notes:?}");
    for note in notes {
        let file = note["file"].as_str().unwrap();
        let k = note["every_kth_row"].as_u64().unwrap() as usize;
        let (thin_names, thinned) = read_parquet(&thin.join(file));
        let (full_names, all) = read_parquet(&full.join(file));
        assert_eq!(thin_names, full_names, "{file}");
        let n = all[0].len();
        assert_eq!(note["rows_computed"].as_u64(), Some(n as u64), "{file}");
        assert_eq!(note["rows_written"].as_u64(), Some(thinned[0].len() as u64));
        assert!(
            k > 1 && thinned[0].len() == n.div_ceil(k),
            "{file}: k = {k}"
        );
        // At most 5e5 values, and k the smallest stride that gets there.
        let c = thin_names.len();
        assert!(thinned[0].len() * c <= 500_000, "{file}");
        assert!(
            n.div_ceil(k - 1) * c > 500_000,
            "{file}: k = {k} not the smallest"
        );
        for (t, a) in thinned.iter().zip(&all) {
            let every_kth: Vec<f64> = a.iter().copied().step_by(k).collect();
            assert_eq!(t, &every_kth, "{file}");
        }
        assert!(thin.join(file).is_file() && !thin.join(file.replace(".parquet", ".csv")).exists());
    }
    // The DTE figure's data: far fewer rows, the full series' extremes and ends, to the
    // last bit (decimation keeps original samples only; the figure's time is in ms, DTE in
    // um both), and the same file whether the tables are thinned or not.
    let time = &whole[names.iter().position(|n| n == "time_s").unwrap()];
    assert!(time.windows(2).all(|w| w[1] > w[0]), "time increases");
    let dte = &whole[names.iter().position(|n| n == "dte_um").unwrap()];
    let (fig_names, fig) = read_csv(&thin.join("csv/dte.csv"));
    assert_eq!(
        std::fs::read(thin.join("csv/dte.csv")).unwrap(),
        std::fs::read(full.join("csv/dte.csv")).unwrap()
    );
    assert_eq!(fig_names, ["time_ms", "dte_um"]);
    assert!(fig[1].len() < rows / 5, "{} of {rows} rows", fig[1].len());
    assert_eq!(extremes(&fig[1]), extremes(dte));
    assert_eq!(fig[1].first(), dte.first());
    assert_eq!(fig[1].last(), dte.last());
    // Every kept point is a sample of the full series at its time.
    for (t_ms, v) in fig[0].iter().zip(&fig[1]).step_by(97) {
        let i = time
            .iter()
            .position(|t| (t * 1e3 - t_ms).abs() <= 1e-9 * t_ms.abs().max(1.0))
            .unwrap_or_else(|| panic!("no sample at {t_ms} ms"));
        assert_eq!(dte[i], *v, "at {t_ms} ms");
    }
}

/// A CSV's columns as f64, an empty cell (a pair not in contact) as NaN.
fn read_csv_gaps(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut r = csv::Reader::from_path(path).unwrap();
    let names: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    let mut cols = vec![Vec::new(); names.len()];
    for rec in r.records() {
        for (j, v) in rec.unwrap().iter().enumerate() {
            cols[j].push(if v.is_empty() {
                f64::NAN
            } else {
                v.parse().unwrap()
            });
        }
    }
    (names, cols)
}

#[test]
fn the_tooth_stiffness_figure_table_holds_its_window_and_the_period_its_own_file() {
    // Grade 6 draws every tooth: the excitation period is the hunting period,
    // lcm(19, 31) = 589 mesh cycles. Without a fault the figure shows the first pinion
    // revolution (19 mesh cycles); its table must hold exactly those rows (issue 34: it
    // held all 589 cycles while the figure drew 19), and the period's table all of them.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s");
    common::ok(&[
        "-q",
        "stiffness",
        "--set",
        "teeth.accuracy_grade=6",
        "--out",
        out.to_str().unwrap(),
    ]);
    let (names, period) = read_csv_gaps(&out.join("teeth_mesh_stiffness_period.csv"));
    let (wnames, window) = read_csv_gaps(&out.join("csv/teeth_mesh_stiffness.csv"));
    assert_eq!(names, wnames);
    let cycle = names.iter().position(|n| n == "mesh_cycle").unwrap();
    let per_cycle = period[cycle].iter().filter(|c| **c == 0.0).count();
    assert!(per_cycle > 1);
    assert_eq!(period[cycle].len(), 589 * per_cycle);
    assert_eq!(period[cycle].last(), Some(&588.0));
    assert_eq!(window[cycle].len(), 19 * per_cycle);
    for (j, n) in names.iter().enumerate() {
        let same = window[j]
            .iter()
            .zip(&period[j])
            .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()));
        assert!(same, "{n}: the window is not the period's first rows");
    }
}
