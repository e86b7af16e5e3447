use super::*;
use crate::report::plot::{Panel, Series};

/// A noisy oscillation with isolated spikes: extremes that a stride would miss.
fn spiky(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut s: u64 = 99;
    let x: Vec<f64> = (0..n).map(|i| i as f64 * 1e-3).collect();
    let y = (0..n)
        .map(|i| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let noise = (s >> 40) as f64 / (1u64 << 24) as f64 - 0.5;
            let spike = if i % 7919 == 0 { 50.0 } else { 0.0 };
            (i as f64 * 0.01).sin() + 0.1 * noise + spike
        })
        .collect();
    (x, y)
}

#[test]
fn short_series_are_kept_whole() {
    let (x, y) = spiky(MAX_FIGURE_POINTS);
    let t = Table::new().col("x", x.clone()).col("y", y.clone());
    let d = decimate_table(t);
    assert_eq!((d.columns[0].clone(), d.columns[1].clone()), (x, y));
}

#[test]
fn every_run_keeps_its_own_extremes_and_ends_and_only_original_points() {
    // The rule as documented: run b holds indices [b n / B, (b + 1) n / B). Checked by
    // brute force against the full series: per run, the largest and smallest kept value
    // equal the run's, its first and last points are kept, and every kept row is a row
    // of the original (x and y together).
    let n = 589 * 233 + 17;
    let (x, y) = spiky(n);
    let y2: Vec<f64> = y.iter().map(|v| -2.0 * v * v).collect();
    let t = Table::new()
        .col("x", x.clone())
        .col("y", y.clone())
        .col("y2", y2.clone());
    let d = decimate_table(t);
    let (kx, ky, ky2) = (&d.columns[0], &d.columns[1], &d.columns[2]);
    assert!(
        kx.len() <= BUCKETS * 6 && kx.len() >= 2 * BUCKETS,
        "{}",
        kx.len()
    );
    // Original rows: x is i * 1e-3 exactly as built, so the row index is recoverable.
    let rows: Vec<usize> = kx.iter().map(|v| (v / 1e-3).round() as usize).collect();
    assert!(rows.windows(2).all(|w| w[0] < w[1]), "in order, no repeats");
    for (k, &i) in rows.iter().enumerate() {
        assert_eq!((kx[k], ky[k], ky2[k]), (x[i], y[i], y2[i]));
    }
    for b in 0..BUCKETS {
        let (lo, hi) = (b * n / BUCKETS, (b + 1) * n / BUCKETS);
        let kept: Vec<usize> = rows
            .iter()
            .copied()
            .filter(|&i| i >= lo && i < hi)
            .collect();
        assert!(kept.contains(&lo) && kept.contains(&(hi - 1)), "run {b}");
        for col in [&y, &y2] {
            let full = |f: fn(f64, f64) -> f64, from: &mut dyn Iterator<Item = usize>| {
                from.map(|i| col[i]).fold(col[lo], f)
            };
            assert_eq!(
                full(f64::max, &mut (lo..hi)),
                full(f64::max, &mut kept.iter().copied())
            );
            assert_eq!(
                full(f64::min, &mut (lo..hi)),
                full(f64::min, &mut kept.iter().copied())
            );
        }
    }
}

#[test]
fn a_long_figure_series_keeps_its_spikes_and_global_extremes() {
    let (x, y) = spiky(300_000);
    let fig = Figure {
        title: String::new(),
        panels: vec![Panel {
            series: vec![Series {
                x: x.clone(),
                y: y.clone(),
                ..Default::default()
            }],
            ..Default::default()
        }],
    };
    let d = decimate_figure(fig);
    let s = &d.panels[0].series[0];
    assert!(s.x.len() <= 4 * BUCKETS, "{}", s.x.len());
    // Every spike (every 7919th point, 50 above the rest) survives.
    let spikes = y.iter().filter(|v| **v > 10.0).count();
    assert_eq!(s.y.iter().filter(|v| **v > 10.0).count(), spikes);
    let max = |v: &[f64]| v.iter().copied().fold(f64::MIN, f64::max);
    let min = |v: &[f64]| v.iter().copied().fold(f64::MAX, f64::min);
    assert_eq!((max(&s.y), min(&s.y)), (max(&y), min(&y)));
}

#[test]
fn tables_above_the_cell_limit_go_to_parquet_and_read_back_exactly() {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::Field;
    let rows = MAX_CSV_CELLS / 2 + 1;
    let (x, y) = spiky(rows);
    let long = Table::new().col("time_s", x.clone()).col("y", y.clone());
    assert_eq!(long_table_path("timeseries", &long), "timeseries.parquet");
    let short = Table::new()
        .col("time_s", x[..rows - 2].to_vec())
        .col("y", y[..rows - 2].to_vec());
    assert_eq!(long_table_path("timeseries", &short), "timeseries.csv");
    // Non-finite values have no place in Parquet's required columns: CSV keeps them empty.
    let mut with_nan = y.clone();
    with_nan[5] = f64::NAN;
    let t = Table::new().col("time_s", x.clone()).col("y", with_nan);
    assert_eq!(long_table_path("timeseries", &t), "timeseries.csv");
    // Read back by the reference reader: every double bit for bit.
    let bytes = long.to_parquet().unwrap();
    let mut f = tempfile::tempfile().unwrap();
    std::io::Write::write_all(&mut f, &bytes).unwrap();
    let r = SerializedFileReader::new(f).unwrap();
    assert_eq!(r.metadata().file_metadata().num_rows() as usize, rows);
    for (i, row) in r.get_row_iter(None).unwrap().enumerate().step_by(9973) {
        let v: Vec<Field> = row
            .unwrap()
            .get_column_iter()
            .map(|(_, f)| f.clone())
            .collect();
        assert_eq!(v, vec![Field::Double(x[i]), Field::Double(y[i])]);
    }
}
