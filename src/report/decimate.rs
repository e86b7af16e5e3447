//! Long series drawn and tabled at a size people can use: a figure of a hunting period or a
//! run-up has 1e5-1e6 points where its plot is 900 pixels wide, and its data CSV took tens
//! of megabytes of text nobody reads.
//!
//! **Rule (min-max decimation).** Above [`MAX_FIGURE_POINTS`] points the index range is cut
//! into [`BUCKETS`] equal runs of consecutive points; of each run the first and last point
//! and the points of its smallest and largest value are kept, in their order. Every kept
//! point is an original point; each run's extremes survive, so the drawn envelope (what a
//! line through 1e5 points at 900 pixels shows) and every series' global minimum and
//! maximum are those of the full series. The full-resolution values stay in the command's
//! time-series table (`timeseries.csv`, or `.parquet` when long: [`long_table_path`]).
//!
//! A figure's data table is decimated on one set of rows for all its columns (the union of
//! every column's kept points), so its rows stay rows of the original table.

use super::plot::{Figure, PanelKind};
use crate::io::table::Table;

/// Figures and their data tables with up to this many points are kept whole (a 1 s record
/// at 25.6 kHz stays whole; a 589-mesh-period run or a 10 s run-up does not).
pub(crate) const MAX_FIGURE_POINTS: usize = 50_000;

/// Runs of consecutive points a long series is cut into: four times a wide figure's
/// 1000 pixels, so each pixel column holds whole runs.
pub(crate) const BUCKETS: usize = 4_000;

/// Tables with more cells than this are written as Parquet (exact binary doubles, no text
/// formatting) instead of CSV: about 20 MB of CSV text.
pub(crate) const MAX_CSV_CELLS: usize = 1_000_000;

/// The indices kept of a series of `n` points whose values are `ys` (one or more columns of
/// length `n`): per run of consecutive points, its first, last, and each column's smallest
/// and largest (non-finite values are never chosen as extremes). All indices when `n` is
/// at most [`MAX_FIGURE_POINTS`].
pub(crate) fn kept_indices(n: usize, ys: &[&[f64]]) -> Vec<usize> {
    if n <= MAX_FIGURE_POINTS {
        return (0..n).collect();
    }
    let mut keep = Vec::with_capacity(BUCKETS * (2 + 2 * ys.len()));
    for b in 0..BUCKETS {
        let (lo, hi) = (b * n / BUCKETS, (b + 1) * n / BUCKETS);
        if lo >= hi {
            continue;
        }
        let start = keep.len();
        keep.push(lo);
        keep.push(hi - 1);
        for y in ys {
            let run = &y[lo..hi.min(y.len())];
            let finite = || run.iter().enumerate().filter(|(_, v)| v.is_finite());
            if let Some((i, _)) = finite().min_by(|a, b| a.1.total_cmp(b.1)) {
                keep.push(lo + i);
            }
            if let Some((i, _)) = finite().max_by(|a, b| a.1.total_cmp(b.1)) {
                keep.push(lo + i);
            }
        }
        keep[start..].sort_unstable();
    }
    keep.dedup();
    keep
}

fn pick(v: &[f64], keep: &[usize]) -> Vec<f64> {
    keep.iter().filter_map(|&i| v.get(i).copied()).collect()
}

/// `fig` with every line or stem series longer than [`MAX_FIGURE_POINTS`] decimated on
/// its own extremes (module docs). Heat-map cells are kept whole (each cell is drawn).
pub(crate) fn decimate_figure(mut fig: Figure) -> Figure {
    for p in &mut fig.panels {
        if p.kind == PanelKind::Cells {
            continue;
        }
        for s in &mut p.series {
            let n = s.x.len().min(s.y.len());
            if n <= MAX_FIGURE_POINTS {
                continue;
            }
            let keep = kept_indices(n, &[&s.y[..n]]);
            s.x = pick(&s.x, &keep);
            s.y = pick(&s.y, &keep);
        }
    }
    fig
}

/// A figure's data table with its rows decimated on one set (module docs): the first
/// column is the abscissa, the others the plotted values.
pub(crate) fn decimate_table(t: Table) -> Table {
    let n = t.rows();
    if n <= MAX_FIGURE_POINTS || t.columns.iter().any(|c| c.len() != n) {
        return t;
    }
    let ys: Vec<&[f64]> = t.columns.iter().skip(1).map(Vec::as_slice).collect();
    let keep = kept_indices(n, &ys);
    Table {
        columns: t.columns.iter().map(|c| pick(c, &keep)).collect(),
        names: t.names,
    }
}

/// The path a table is written at: `STEM.csv`, or `STEM.parquet` when it has more than
/// [`MAX_CSV_CELLS`] cells (and equal, finite columns, which Parquet's required columns
/// need; anything else stays CSV, whose empty cells stand for non-finite values).
pub(crate) fn long_table_path(stem: &str, t: &Table) -> String {
    let n = t.rows();
    let cells = n.saturating_mul(t.columns.len());
    let parquet_ready = t
        .columns
        .iter()
        .all(|c| c.len() == n && c.iter().all(|v| v.is_finite()));
    if cells > MAX_CSV_CELLS && parquet_ready {
        format!("{stem}.parquet")
    } else {
        format!("{stem}.csv")
    }
}

/// A long per-point table (over [`MAX_CSV_CELLS`] values) is thinned to at most this many
/// values unless the case asks for full tables (`output.full_tables`): 5e5 doubles, 4 MB
/// of Parquet, so that a hunting period's time series and path of contact together stay
/// under 10 MB.
pub(crate) const MAX_THINNED_CELLS: usize = 500_000;

/// The stride a per-point table is written at: 1 (every row) up to [`MAX_CSV_CELLS`]
/// values, otherwise the smallest k whose rows 0, k, 2k, ... (ceil(n / k) of them) hold at
/// most [`MAX_THINNED_CELLS`] values.
pub(crate) fn thinning_stride(t: &Table) -> usize {
    let (n, c) = (t.rows(), t.columns.len().max(1));
    if n.saturating_mul(c) <= MAX_CSV_CELLS {
        return 1;
    }
    let mut k = n.saturating_mul(c).div_ceil(MAX_THINNED_CELLS).max(1);
    while n.div_ceil(k) * c > MAX_THINNED_CELLS {
        k += 1;
    }
    k
}

/// Rows 0, k, 2k, ... of `t` (every column; `t` itself for k <= 1). Every kept value is
/// an original one, at full precision.
pub(crate) fn thin_table(t: Table, k: usize) -> Table {
    if k <= 1 {
        return t;
    }
    Table {
        columns: t
            .columns
            .iter()
            .map(|c| c.iter().copied().step_by(k).collect())
            .collect(),
        names: t.names,
    }
}

#[cfg(test)]
#[path = "tests_decimate.rs"]
mod tests;
