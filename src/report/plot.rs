//! Plotting layer on `plotters`: a `Figure` of vertically stacked `Panel`s of `Series`,
//! rendered to PNG bytes / files or SVG text. With the `ab_glyph` feature there is no system
//! font and text panics without a registered one (CRATES.md), so DejaVu Sans (`dejavu` crate)
//! is registered once, thread-safely. Bad points are dropped; degenerate ranges get a width.

use std::path::{Path, PathBuf};
use std::sync::{atomic::AtomicU64, atomic::Ordering, OnceLock};

use plotters::coord::{ranged1d::Ranged, ranged1d::ValueFormatter, types::RangedCoordf64, Shift};
use plotters::prelude::*;
use plotters::style::register_font;

/// Largest accepted image side in pixels (keeps the RGB buffer below ~200 MB and `w*h` in u32).
pub const MAX_SIDE_PX: u32 = 8192;

/// Font family name under which DejaVu Sans is registered; plotters' own defaults
/// (tick labels, legend) also ask for "sans-serif".
const FONT: &str = "sans-serif";

/// Smallest panel (w, h) in pixels: the axis label areas (70 px left, 40 px below) plus
/// margins, with room left to plot. Smaller areas make plotters' layout arithmetic overflow.
pub const MIN_PANEL_PX: (u32, u32) = (120, 80);

/// Height reserved for a title (20 px font plus padding) when checking the minimum size.
const TITLE_PX: u32 = 40;

/// Fixed palette (Tableau 10 order), cycled by series index within a panel.
#[rustfmt::skip]
const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180), RGBColor(255, 127, 14), RGBColor(44, 160, 44),
    RGBColor(214, 39, 40), RGBColor(148, 103, 189), RGBColor(140, 86, 75),
    RGBColor(227, 119, 194), RGBColor(127, 127, 127),
];

/// Errors of the plotting layer (never a panic).
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// `got` and `min` are (width, height) in pixels.
    #[error("image size {got:?} px: this figure needs >= {min:?}, <= {MAX_SIDE_PX} a side")]
    Size { got: (u32, u32), min: (u32, u32) },
    #[error("the embedded DejaVu font could not be registered with plotters")]
    Font,
    #[error("drawing failed: {0}")]
    Draw(String),
    #[error("I/O error on {}: {}", .0.display(), .1)]
    Io(PathBuf, #[source] std::io::Error),
}

/// Line style of one series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LineStyle {
    #[default]
    Solid,
    Dashed,
    Dotted,
    /// Markers only, no connecting line.
    Points,
}

/// How the series of a panel are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PanelKind {
    #[default]
    Lines,
    /// Vertical stems from the baseline (0, or the bottom of a log axis) to each point: spectra.
    Bars,
}

/// One named data series; `x` and `y` are paired up to the shorter length.
#[derive(Debug, Clone, Default)]
pub struct Series {
    /// Legend entry; empty = not in the legend.
    pub name: String,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub style: LineStyle,
}

/// One chart: axes, series and labelled vertical markers.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    /// Vertical markers `(x, label)`, drawn dashed grey across the panel.
    pub vlines: Vec<(f64, String)>,
    /// Logarithmic y axis; points with y outside [1e-100, 1e100] (e.g. y <= 0) are skipped.
    pub log_y: bool,
    pub kind: PanelKind,
}

/// A figure: a title over panels stacked vertically with equal heights.
#[derive(Debug, Clone, Default)]
pub struct Figure {
    pub title: String,
    pub panels: Vec<Panel>,
}

/// Render `fig` as PNG bytes in memory (e.g. for base64 embedding in HTML).
///
/// plotters encodes PNG only when saving to a path (its `image` dependency is not ours to
/// name), so this draws to a uniquely named temporary file, reads it back and removes it.
pub fn render_png(fig: &Figure, width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    check_size(fig, width, height)?;
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let name = format!("gearwear-plot-{}-{n}.png", std::process::id());
    let tmp = TempFile(std::env::temp_dir().join(name));
    draw_figure(
        &BitMapBackend::new(&tmp.0, (width, height)).into_drawing_area(),
        fig,
    )?;
    std::fs::read(&tmp.0).map_err(|e| PlotError::Io(tmp.0.clone(), e))
}

/// Render `fig` as PNG and write it to `path` (any extension).
pub fn save_png(fig: &Figure, path: &Path, width: u32, height: u32) -> Result<(), PlotError> {
    write_file(path, &render_png(fig, width, height)?)
}

/// Render `fig` as an SVG document.
pub fn render_svg(fig: &Figure, width: u32, height: u32) -> Result<String, PlotError> {
    check_size(fig, width, height)?;
    let mut svg = String::new();
    draw_figure(
        &SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area(),
        fig,
    )?;
    Ok(svg)
}

/// Render `fig` as SVG and write it to `path`.
pub fn save_svg(fig: &Figure, path: &Path, width: u32, height: u32) -> Result<(), PlotError> {
    write_file(path, render_svg(fig, width, height)?.as_bytes())
}

/// Removes the temporary PNG on every exit path of `render_png`.
struct TempFile(PathBuf);
impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

fn write_file(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    std::fs::write(path, bytes).map_err(|e| PlotError::Io(path.to_path_buf(), e))
}

/// Smallest image (width, height) in pixels that can hold `fig`: a title band plus
/// `MIN_PANEL_PX` per panel.
pub fn min_size(fig: &Figure) -> (u32, u32) {
    let n = u32::try_from(fig.panels.len()).unwrap_or(u32::MAX);
    let title = if fig.title.is_empty() { 0 } else { TITLE_PX };
    let panels_h = n.saturating_mul(MIN_PANEL_PX.1);
    let w = if n > 0 { MIN_PANEL_PX.0 } else { 1 };
    (w, title.saturating_add(panels_h).max(1))
}

fn check_size(fig: &Figure, width: u32, height: u32) -> Result<(), PlotError> {
    let min = min_size(fig);
    let ok = (min.0..=MAX_SIDE_PX).contains(&width) && (min.1..=MAX_SIDE_PX).contains(&height);
    ok.then_some(()).ok_or(PlotError::Size {
        got: (width, height),
        min,
    })
}

/// Registers DejaVu Sans (regular + bold) once per process; safe from any thread.
fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        register_font(FONT, FontStyle::Normal, dejavu::sans::regular()).is_ok()
            && register_font(FONT, FontStyle::Bold, dejavu::sans::bold()).is_ok()
    });
    ok.then_some(()).ok_or(PlotError::Font)
}

fn draw_err(e: impl std::fmt::Display) -> PlotError {
    PlotError::Draw(e.to_string())
}

fn draw_figure<DB>(root: &DrawingArea<DB, Shift>, fig: &Figure) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
{
    ensure_font()?;
    root.fill(&WHITE).map_err(draw_err)?;
    let body = if fig.title.is_empty() {
        root.clone()
    } else {
        root.titled(&fig.title, (FONT, 20)).map_err(draw_err)?
    };
    let areas = body.split_evenly((fig.panels.len(), 1));
    for (panel, area) in fig.panels.iter().zip(&areas) {
        draw_panel(area, panel)?;
    }
    root.present().map_err(draw_err)
}

/// Largest plotted magnitude: keeps spans and margins finite; plotters' pixel mapping
/// overflows (i32 add) for points far outside the axis range.
const LIM: f64 = 1e300;

/// Log-axis data window: plotters' log ticks compute end/start, which overflows (and then
/// loops ~usize::MAX times) beyond ~308 decades; 200 decades plus margins stay clear of it.
const LOG_LIM: f64 = 1e100;

/// Plottable points: |v| <= LIM (so finite), and y in [1/LOG_LIM, LOG_LIM] on a log axis.
fn clean_points(s: &Series, log_y: bool) -> Vec<(f64, f64)> {
    let ok = |v: f64| v.abs() <= LIM; // false for NaN and inf too
    let log_ok = |y: f64| !log_y || (LOG_LIM.recip()..=LOG_LIM).contains(&y);
    let keep = |&(x, y): &(f64, f64)| ok(x) && ok(y) && log_ok(y);
    s.x.iter()
        .zip(&s.y)
        .map(|(&x, &y)| (x, y))
        .filter(keep)
        .collect()
}

/// Axis range of `values` with a 5 % margin each side; empty input gives a unit range and
/// (near-)constant input is widened, so plotters always gets a finite range of positive width.
/// With `log`, the values are log10 of the data and the constant case widens by half a decade.
fn padded_range(values: impl IntoIterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.into_iter().filter(|v| v.is_finite()) {
        (lo, hi) = (lo.min(v), hi.max(v));
    }
    if lo > hi {
        (lo, hi) = (0.0, 1.0);
    }
    // Clamp so that spans and margins below cannot overflow to infinity.
    (lo, hi) = (lo.clamp(-LIM, LIM), hi.clamp(-LIM, LIM));
    // Spans below 1e-6 of the magnitude would need ticks finer than 9-digit labels resolve.
    if !(hi - lo > 1e-6 * lo.abs().max(hi.abs()) && hi - lo > 1e-300) {
        let half = 0.5 * if log || lo == 0.0 { 1.0 } else { lo.abs() };
        (lo, hi) = (lo - half, hi + half);
    }
    let margin = 0.05 * (hi - lo);
    (lo - margin, hi + margin)
}

/// Tick text: rounded to 9 significant digits (hides float noise such as 0.30000000000000004
/// and "-0.0"), "0" for |v| <= `zero_below` (plotters' ticks at zero can come out as
/// ~1e-16), shortest form, exponent notation outside [1e-3, 1e5).
fn tick_label(v: f64, zero_below: f64) -> String {
    let r: f64 = format!("{v:.8e}").parse().unwrap_or(v);
    match r.abs() {
        a if a <= zero_below => "0".to_string(),
        a if (1e-3..1e5).contains(&a) => format!("{r}"),
        _ => format!("{r:e}"),
    }
}

fn draw_panel<DB>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
{
    let clean = |s| clean_points(s, panel.log_y);
    let pts: Vec<_> = panel.series.iter().map(clean).collect();
    let xs = pts.iter().flatten().map(|p| p.0);
    let (x0, x1) = padded_range(xs.chain(panel.vlines.iter().map(|v| v.0)), false);
    let ys = pts.iter().flatten().map(|p| p.1);
    let mut b = ChartBuilder::on(area);
    b.margin(8).x_label_area_size(40).y_label_area_size(70);
    if panel.log_y {
        let (l0, l1) = padded_range(ys.map(f64::log10), true);
        let (y0, y1) = (10f64.powf(l0), 10f64.powf(l1));
        let chart = b.build_cartesian_2d(x0..x1, (y0..y1).log_scale());
        fill_chart(chart.map_err(draw_err)?, panel, &pts, y0)
    } else {
        // Stems start at zero, so a bar panel's range must contain it.
        let zero = (panel.kind == PanelKind::Bars).then_some(0.0);
        let (y0, y1) = padded_range(ys.chain(zero), false);
        let base = 0f64.clamp(y0, y1);
        let chart = b.build_cartesian_2d(x0..x1, y0..y1);
        fill_chart(chart.map_err(draw_err)?, panel, &pts, base)
    }
}

/// Draws mesh, series, markers and legend; generic over linear/log y.
fn fill_chart<'a, DB, Y>(
    mut chart: ChartContext<'a, DB, Cartesian2d<RangedCoordf64, Y>>,
    panel: &Panel,
    pts: &[Vec<(f64, f64)>],
    base: f64,
) -> Result<(), PlotError>
where
    DB: DrawingBackend + 'a,
    DB::ErrorType: 'static,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let (xr, yr) = (chart.x_range(), chart.y_range());
    // Snap float-noise ticks to 0 relative to the axis scale (not on log axes: all ticks > 0).
    let scale = |r: &std::ops::Range<f64>| 1e-9 * r.start.abs().max(r.end.abs());
    let (zx, zy) = (scale(&xr), if panel.log_y { 0.0 } else { scale(&yr) });
    let (fx, fy) = (|v: &f64| tick_label(*v, zx), |v: &f64| tick_label(*v, zy));
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 14))
        .draw()
        .map_err(draw_err)?;

    for (i, (s, p)) in panel.series.iter().zip(pts).enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        let line = color.stroke_width(2);
        let dashes = |on, off| DashedLineSeries::new(p.iter().copied(), on, off, line);
        let anno = match (panel.kind, s.style) {
            (PanelKind::Bars, _) => chart.draw_series(
                p.iter()
                    .map(|&(x, y)| PathElement::new(vec![(x, base), (x, y)], line)),
            ),
            (_, LineStyle::Solid) => chart.draw_series(LineSeries::new(p.iter().copied(), line)),
            (_, LineStyle::Dashed) => chart.draw_series(dashes(10, 6)),
            (_, LineStyle::Dotted) => chart.draw_series(dashes(2, 4)),
            (_, LineStyle::Points) => {
                chart.draw_series(p.iter().map(|&xy| Circle::new(xy, 3, color.filled())))
            }
        }
        .map_err(draw_err)?;
        if !s.name.is_empty() {
            anno.label(s.name.as_str());
            if s.style == LineStyle::Points && panel.kind == PanelKind::Lines {
                anno.legend(move |(x, y)| Circle::new((x, y), 3, color.filled()));
            } else {
                anno.legend(move |(x, y)| PathElement::new(vec![(x - 10, y), (x + 10, y)], line));
            }
        }
    }

    let grey = RGBColor(90, 90, 90);
    let marks: Vec<&(f64, String)> = panel.vlines.iter().filter(|v| xr.contains(&v.0)).collect();
    let font = (FONT, 12).into_font().color(&grey);
    let spans: Vec<(i32, i32)> = marks
        .iter()
        .map(|(x, label)| {
            let left = chart.backend_coord(&(*x, yr.end)).0 + 3;
            let width = match label.is_empty() {
                true => 0,
                false => chart
                    .plotting_area()
                    .estimate_text_size(label, &font)
                    .map_or(7 * label.len() as u32, |s| s.0),
            };
            (left, left + i32::try_from(width).unwrap_or(i32::MAX / 2))
        })
        .collect();
    let rows = label_rows(&spans, 4);
    for ((x, label), row) in marks.iter().zip(rows) {
        let ends = [(*x, yr.start), (*x, yr.end)];
        chart
            .draw_series(DashedLineSeries::new(ends, 6, 4, grey.stroke_width(1)))
            .map_err(draw_err)?;
        if !label.is_empty() {
            let dy = 3 + LABEL_ROW_PX * i32::try_from(row).unwrap_or(0);
            let text =
                EmptyElement::at((*x, yr.end)) + Text::new(label.clone(), (3, dy), font.clone());
            chart.draw_series(std::iter::once(text)).map_err(draw_err)?;
        }
    }

    if panel.series.iter().filter(|s| !s.name.is_empty()).count() > 1 {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .label_font((FONT, 12))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.5))
            .draw()
            .map_err(draw_err)?;
    }
    Ok(())
}

/// Line height of the marker labels, px (12 px text plus 2 px).
const LABEL_ROW_PX: i32 = 14;

/// Row of each marker label (0 = top) so that no two labels in a row overlap: labels are
/// placed left to right, each in the first row whose last label ends at least `gap_px`
/// before it starts. `spans` are the labels' pixel extents (left, right); empty labels
/// (left == right) take row 0 and block nothing.
fn label_rows(spans: &[(i32, i32)], gap_px: i32) -> Vec<usize> {
    let mut order: Vec<usize> = (0..spans.len()).collect();
    order.sort_by_key(|&i| spans[i].0);
    let mut row_end: Vec<i32> = Vec::new();
    let mut rows = vec![0; spans.len()];
    for i in order {
        let (l, r) = spans[i];
        if r <= l {
            continue;
        }
        let row = match row_end.iter().position(|&end| end + gap_px <= l) {
            Some(k) => k,
            None => {
                row_end.push(i32::MIN / 2);
                row_end.len() - 1
            }
        };
        row_end[row] = r;
        rows[i] = row;
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marker_labels_never_overlap_in_a_row() {
        // Three labels 40 px wide at 0, 20 and 100 px, and one at 30: the first and the
        // one at 100 share the top row; 20 and 30 overlap it and each other.
        let spans = [(0, 40), (20, 60), (100, 140), (30, 70)];
        let rows = label_rows(&spans, 4);
        assert_eq!(rows, vec![0, 1, 0, 2]);
        for i in 0..spans.len() {
            for j in 0..i {
                if rows[i] == rows[j] {
                    let (a, b) = (spans[i], spans[j]);
                    assert!(a.1 + 4 <= b.0 || b.1 + 4 <= a.0, "{a:?} {b:?}");
                }
            }
        }
        // A label that starts 4 px after the previous one ends shares its row.
        assert_eq!(label_rows(&[(0, 40), (44, 80)], 4), vec![0, 0]);
    }

    /// Asserts `padded_range(v, log) == want`; 1e-12 is far above the rounding (~1e-15) of
    /// these few operations on O(1) decimals and far below the checked 0.05 differences.
    fn check(v: &[f64], log: bool, want: (f64, f64)) {
        let (lo, hi) = padded_range(v.iter().copied(), log);
        assert!(
            (lo - want.0).abs() < 1e-12 && (hi - want.1).abs() < 1e-12,
            "{lo} {hi}"
        );
    }

    #[test]
    fn padded_range_is_finite_and_wide() {
        check(&[], false, (-0.05, 1.05)); // empty: [0, 1] plus 5 % margins
        check(&[0.0, 2.0], false, (-0.1, 2.1)); // 5 % of the span each side
        check(&[3.0, 3.0], false, (1.35, 4.65)); // constant: +-50 % to [1.5, 4.5], then margins
        check(&[0.0], false, (-0.55, 0.55)); // constant 0: +-0.5, then margins
        check(&[-2.0], true, (-2.55, -1.45)); // log axis (log10 values): +-half a decade
        let (lo, hi) = padded_range([1.0, 1.0 + 1e-8], false); // span 1e-8 < 1e-6 relative:
        assert!(hi - lo > 1.0); // widened by +-0.5 like a constant
        let inf = f64::INFINITY;
        let (lo, hi) = padded_range([f64::NAN, inf, -f64::MAX, f64::MAX], false);
        assert!(lo.is_finite() && hi.is_finite() && hi > lo);
    }

    #[test]
    fn tick_labels_hide_float_noise() {
        assert_eq!(tick_label(0.1 + 0.2, 0.0), "0.3");
        assert_eq!(tick_label(-0.0, 0.0), "0");
        assert_eq!(tick_label(500.0, 0.0), "500");
        assert_eq!(tick_label(2.5e-6, 0.0), "2.5e-6");
        assert_eq!(tick_label(2.220446049250313e-16, 1e-9), "0"); // noise on a unit-scale axis
    }
}
