//! A long dynamics run (a hunting period: ISO grade 8 gives every tooth its own errors) writes
//! its long tables as Parquet and draws its figures from a decimated series. Checked across
//! files: the Parquet table holds every sample with the columns a short run's CSV has, and the
//! decimated figure data keep the full series' extremes and ends exactly.
mod common;

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;

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

#[test]
fn a_hunting_period_goes_to_parquet_and_its_figures_keep_the_extremes() {
    let dir = tempfile::tempdir().unwrap();
    let (short, long) = (dir.path().join("short"), dir.path().join("long"));
    common::ok(&["-q", "dynamics", "--out", short.to_str().unwrap()]);
    common::ok(&[
        "-q",
        "dynamics",
        "--set",
        "teeth.accuracy_grade=8",
        "--out",
        long.to_str().unwrap(),
    ]);
    // The paper's case is short: CSV as ever.
    assert!(short.join("timeseries.csv").is_file());
    assert!(!short.join("timeseries.parquet").exists());
    // The hunting period: Parquet, no CSV, and the manifest names the file it wrote.
    assert!(!long.join("timeseries.csv").exists());
    let (names, cols) = read_parquet(&long.join("timeseries.parquet"));
    let (short_names, _) = read_csv(&short.join("timeseries.csv"));
    assert_eq!(names, short_names, "same columns in either form");
    let manifest = std::fs::read_to_string(long.join("manifest.json")).unwrap();
    assert!(manifest.contains("\"timeseries.parquet\""));
    // Above the CSV limit (1e6 values), or it would have stayed CSV.
    let rows = cols[0].len();
    assert!(rows * names.len() > 1_000_000, "{rows} rows");
    let time = &cols[names.iter().position(|n| n == "time_s").unwrap()];
    assert!(time.windows(2).all(|w| w[1] > w[0]), "time increases");
    // The DTE figure's data: far fewer rows, the same extremes and ends, to the last bit
    // (decimation keeps original samples only; the figure's time is in ms, DTE in um both).
    let dte = &cols[names.iter().position(|n| n == "dte_um").unwrap()];
    let (fig_names, fig) = read_csv(&long.join("csv/dte.csv"));
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
