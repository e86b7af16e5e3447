//! Drawing a figure with plotters. Each panel is laid out first (plot area, the pixels its
//! data cover, marker labels, then a place for the legend that covers none of them), then
//! drawn exactly there; the layout is returned so that [`super::layout`] can show it.

use std::ops::Range;

use plotters::coord::ranged1d::{AsRangedCoord, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::dash::dash_pieces;
use super::layout::{free_corner, sample_polyline, stack_labels, PanelLayout, Rect};
use super::legend::{
    draw_bar, draw_legend, marker_of, measure_bar, measure_legend, series_color, GAP,
};
use super::ticks::tick_label;
use super::{
    draw_err, ensure_font, Figure, LineStyle, Marker, Panel, PanelKind, PlotError, Series, FONT,
};

/// Narrowest plot area left beside a legend or colour-bar band, px; below it the band is
/// left out (a legend is dropped rather than drawn over the data).
const MIN_PLOT_BESIDE_BAND_PX: u32 = 300;

/// Font size of marker labels, px.
const LABEL_FONT_PX: u32 = 12;

pub fn draw_figure<DB>(
    root: &DrawingArea<DB, Shift>,
    fig: &Figure,
) -> Result<Vec<PanelLayout>, PlotError>
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
    let mut layouts = Vec::with_capacity(fig.panels.len());
    for (panel, area) in fig.panels.iter().zip(&areas) {
        layouts.push(draw_panel(area, panel)?);
    }
    root.present().map_err(draw_err)?;
    Ok(layouts)
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

/// Points of a line with more than [`DECIMATE_PER_PIXEL`] points per pixel column of
/// `width_px` over `x0..x1` are thinned to its envelope: per column, the first, lowest,
/// highest and last points, in their order. The line drawn is the same to the pixel, at a
/// cost bounded by the image rather than the data (a wear profile of 1e5 points at each
/// of hundreds of updates).
const DECIMATE_PER_PIXEL: usize = 4;

fn decimate(p: Vec<(f64, f64)>, x0: f64, x1: f64, width_px: u32) -> Vec<(f64, f64)> {
    let cols = width_px.max(1) as usize;
    if p.len() <= DECIMATE_PER_PIXEL * cols || x1 <= x0 {
        return p;
    }
    let col = |x: f64| (((x - x0) / (x1 - x0) * cols as f64) as usize).min(cols - 1);
    let mut out = Vec::with_capacity(4 * cols);
    let mut i = 0;
    while i < p.len() {
        let c = col(p[i].0);
        let start = i;
        while i < p.len() && col(p[i].0) == c {
            i += 1;
        }
        let run = &p[start..i];
        let lo = (0..run.len())
            .min_by(|a, b| run[*a].1.total_cmp(&run[*b].1))
            .unwrap_or(0);
        let hi = (0..run.len())
            .max_by(|a, b| run[*a].1.total_cmp(&run[*b].1))
            .unwrap_or(0);
        let mut keep = [0, lo, hi, run.len() - 1];
        keep.sort_unstable();
        let mut last = usize::MAX;
        for k in keep {
            if k != last {
                out.push(run[k]);
                last = k;
            }
        }
    }
    out
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

fn draw_panel<DB>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> Result<PanelLayout, PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
{
    let clean = |s| clean_points(s, panel.log_y);
    let pts: Vec<_> = panel.series.iter().map(clean).collect();
    let xs = pts.iter().flatten().map(|p| p.0);
    let (x0, x1) = padded_range(xs.chain(panel.vlines.iter().map(|v| v.0)), false);
    let width = area.dim_in_pixel().0;
    let pts: Vec<_> = panel
        .series
        .iter()
        .zip(pts)
        .map(|(s, p)| match (panel.kind, s.style) {
            (PanelKind::Lines, LineStyle::Solid | LineStyle::Dashed | LineStyle::Dotted)
                if s.marker == Marker::None =>
            {
                decimate(p, x0, x1, width)
            }
            _ => p,
        })
        .collect();
    let ys = pts.iter().flatten().map(|p| p.1);
    if panel.log_y {
        let (l0, l1) = padded_range(ys.map(f64::log10), true);
        let (y0, y1) = (10f64.powf(l0), 10f64.powf(l1));
        laid_out_panel(area, panel, &pts, x0..x1, (y0..y1).log_scale(), y0)
    } else {
        // Stems start at zero, so a bar panel's range must contain it.
        let zero = (panel.kind == PanelKind::Bars).then_some(0.0);
        let (y0, y1) = padded_range(ys.chain(zero), false);
        laid_out_panel(area, panel, &pts, x0..x1, y0..y1, 0f64.clamp(y0, y1))
    }
}

type Chart<'a, DB, Y> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, Y>>;

fn build_chart<'a, DB, YS>(
    area: &'a DrawingArea<DB, Shift>,
    panel: &Panel,
    xr: Range<f64>,
    ys: YS,
) -> Result<Chart<'a, DB, YS::CoordDescType>, PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    YS: AsRangedCoord<Value = f64>,
{
    let mut b = ChartBuilder::on(area);
    b.margin(8).x_label_area_size(40).y_label_area_size(70);
    if !panel.title.is_empty() {
        b.caption(&panel.title, (FONT, 14));
    }
    b.build_cartesian_2d(xr, ys).map_err(draw_err)
}

/// Lay the panel out (plot area, data pixels, marker labels, legend place), then draw it.
/// The legend takes the first corner of the plot area the data leave free; if none is, the
/// plot area narrows to leave a band for it on the right (with the colour bar, if any).
fn laid_out_panel<DB, YS>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    pts: &[Vec<(f64, f64)>],
    xr: Range<f64>,
    ys: YS,
    base: f64,
) -> Result<PanelLayout, PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    YS: AsRangedCoord<Value = f64> + Clone,
    YS::CoordDescType: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let screen = area.use_screen_coord();
    let legend = measure_legend(&screen, panel)?;
    let w = area.dim_in_pixel().0;
    let fits = |band: u32| w >= band.saturating_add(MIN_PLOT_BESIDE_BAND_PX);
    let bar = measure_bar(&screen, panel)?.filter(|b| fits(b.band_w));
    let bar_band = bar.as_ref().map_or(0, |b| b.band_w);
    let legend_band = legend
        .as_ref()
        .map_or(0, |l| l.size().0 + 2 * GAP as u32)
        .max(bar_band);
    let narrowed = |band: u32| match band {
        0 => area.clone(),
        _ => area.split_horizontally(w - band).0,
    };
    let (with_bar, with_legend) = (narrowed(bar_band), narrowed(legend_band));

    let mut chart = build_chart(&with_bar, panel, xr.clone(), ys.clone())?;
    let mut shown = thin_bars(&chart, panel, pts, base);
    let mut lay = data_layout(&chart, &screen, panel, &shown, base)?;
    let mut legend_in_band = false;
    if let Some(l) = &legend {
        let blocked = blocked_by_markers(&chart, panel, &lay);
        lay.legend = free_corner(lay.plot, l.size(), &lay.marks, &blocked);
        if lay.legend.is_none() && fits(legend_band) {
            chart = build_chart(&with_legend, panel, xr, ys)?;
            shown = thin_bars(&chart, panel, pts, base);
            lay = data_layout(&chart, &screen, panel, &shown, base)?;
            let (lw, lh) = l.size();
            lay.legend = Some(Rect::at(lay.plot.x1 + GAP, lay.plot.y0, lw, lh));
            legend_in_band = true;
        }
    }
    if let Some(b) = &bar {
        let top = match lay.legend {
            Some(r) if legend_in_band => r.y1 + GAP,
            _ => lay.plot.y0,
        };
        let h = u32::try_from(lay.plot.y1 - top).unwrap_or(0);
        lay.color_bar = Some(Rect::at(
            lay.plot.x1 + GAP,
            top,
            b.band_w - 2 * GAP as u32,
            h,
        ));
    }

    draw_chart(&mut chart, &screen, panel, &shown, base, &lay)?;
    if let (Some(l), Some(r)) = (&legend, lay.legend) {
        draw_legend(&screen, l, r)?;
    }
    if let (Some(b), Some(r)) = (&bar, lay.color_bar) {
        draw_bar(&screen, b, r)?;
    }
    Ok(lay)
}

/// Stems at most this long (px; the stem's 2 px width and some) are kept by
/// [`thin_bars`], one of each length a column.
const SHORT_STEM_PX: i32 = 4;

/// The stems of a bar panel that the image shows: of each run of consecutive stems in one
/// pixel column of `chart` (their x mapped as plotters maps it), the two reaching highest
/// and lowest and one of each length up to [`SHORT_STEM_PX`] from the baseline `base`, in
/// their order. Every stem runs from the baseline, so the others in the column lie inside
/// those and the image is the same to the pixel, while drawing costs two long stems a
/// column rather than one a point (a 40 s record's spectrum has 4e5 lines: 17 s of CPU
/// and 1.5 GB of stem samples at 8192 x 4096 px, issue 33). Other panels are returned as
/// they are.
fn thin_bars<'p, DB, Y>(
    chart: &Chart<'_, DB, Y>,
    panel: &Panel,
    pts: &'p [Vec<(f64, f64)>],
    base: f64,
) -> std::borrow::Cow<'p, [Vec<(f64, f64)>]>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64>,
{
    if panel.kind != PanelKind::Bars {
        return std::borrow::Cow::Borrowed(pts);
    }
    let thin = |p: &Vec<(f64, f64)>| {
        let px: Vec<(i32, i32)> = p.iter().map(|xy| chart.backend_coord(xy)).collect();
        let mut out = Vec::new();
        let mut i = 0;
        while i < p.len() {
            let (start, column) = (i, px[i].0);
            while i < p.len() && px[i].0 == column {
                i += 1;
            }
            let run = start..i;
            let by_y = |a: &usize, b: &usize| px[*a].1.cmp(&px[*b].1);
            let top = run.clone().min_by(by_y).unwrap_or(start);
            let bottom = run.clone().max_by(by_y).unwrap_or(start);
            let mut keep = vec![top, bottom];
            // Short stems are kept, one of each length: plotters fills a stem's polygon
            // along its longer side and leaves the last row out, so a stem about as
            // short as it is wide need not lie inside a longer one.
            let pbase = chart.backend_coord(&(p[start].0, base)).1;
            let mut seen = [false; 2 * SHORT_STEM_PX as usize + 1];
            for k in run {
                let d = px[k].1 - pbase;
                if d.abs() <= SHORT_STEM_PX
                    && !std::mem::replace(&mut seen[(d + SHORT_STEM_PX) as usize], true)
                {
                    keep.push(k);
                }
            }
            keep.sort_unstable();
            keep.dedup();
            out.extend(keep.into_iter().map(|k| p[k]));
        }
        out
    };
    std::borrow::Cow::Owned(pts.iter().map(thin).collect())
}

/// The plot area, the pixels the data cover and the marker-label boxes of `chart`.
fn data_layout<DB, Y>(
    chart: &Chart<'_, DB, Y>,
    screen: &DrawingArea<DB, Shift>,
    panel: &Panel,
    pts: &[Vec<(f64, f64)>],
    base: f64,
) -> Result<PanelLayout, PlotError>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64>,
{
    let (px, py) = chart.plotting_area().get_pixel_range();
    let plot = Rect {
        x0: px.start,
        y0: py.start,
        x1: px.end,
        y1: py.end,
    };
    let to_px = |p: &(f64, f64)| chart.backend_coord(p);
    let mut marks = Vec::new();
    for (s, p) in panel.series.iter().zip(pts) {
        match (panel.kind, s.style) {
            (PanelKind::Bars, _) => {
                for &(x, y) in p {
                    sample_polyline(&[to_px(&(x, base)), to_px(&(x, y))], &mut marks);
                }
            }
            (PanelKind::Cells, _) | (_, LineStyle::Points) => marks.extend(p.iter().map(to_px)),
            _ => sample_polyline(&p.iter().map(to_px).collect::<Vec<_>>(), &mut marks),
        }
    }
    let xr = chart.x_range();
    let font = TextStyle::from((FONT, LABEL_FONT_PX).into_font());
    let (mut xs, mut sizes, mut lines) = (Vec::new(), Vec::new(), Vec::new());
    for (x, label) in shown_vlines(panel, &xr) {
        let px = to_px(&(*x, chart.y_range().end)).0;
        lines.push(px);
        if !label.is_empty() {
            xs.push(px);
            // The box is the font's full line (ascenders to descenders), not the ink the
            // estimate measures (9 px of a 12 px font): the white back below must hide a
            // crossing line over the whole text, descenders included.
            let (w, h) = screen.estimate_text_size(label, &font).map_err(draw_err)?;
            sizes.push((w, h.max(LABEL_FONT_PX + 1)));
        }
    }
    Ok(PanelLayout {
        plot,
        labels: stack_labels(&xs, &sizes, &lines, plot),
        marks,
        ..Default::default()
    })
}

/// The vertical markers inside the x range.
fn shown_vlines<'p>(
    panel: &'p Panel,
    xr: &'p Range<f64>,
) -> impl Iterator<Item = &'p (f64, String)> + 'p {
    panel.vlines.iter().filter(|v| xr.contains(&v.0))
}

/// What a legend must also keep clear of: the marker labels and the marker lines.
fn blocked_by_markers<DB, Y>(
    chart: &Chart<'_, DB, Y>,
    panel: &Panel,
    lay: &PanelLayout,
) -> Vec<Rect>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64>,
{
    let xr = chart.x_range();
    let lines = shown_vlines(panel, &xr).map(|(x, _)| {
        let px = chart.backend_coord(&(*x, chart.y_range().end)).0;
        Rect {
            x0: px - 1,
            x1: px + 2,
            ..lay.plot
        }
    });
    lay.labels.iter().copied().chain(lines).collect()
}

/// Grid, axes, series and vertical markers (the legend and colour bar come after).
fn draw_chart<DB, Y>(
    chart: &mut Chart<'_, DB, Y>,
    screen: &DrawingArea<DB, Shift>,
    panel: &Panel,
    pts: &[Vec<(f64, f64)>],
    base: f64,
    lay: &PanelLayout,
) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let (xr, yr) = (chart.x_range(), chart.y_range());
    // Snap float-noise ticks to 0 relative to the axis scale (not on log axes: all ticks > 0).
    let scale = |r: &Range<f64>| 1e-9 * r.start.abs().max(r.end.abs());
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
        .bold_line_style(BLACK.mix(0.12))
        .light_line_style(TRANSPARENT)
        .draw()
        .map_err(draw_err)?;

    for (i, (s, p)) in panel.series.iter().zip(pts).enumerate() {
        let color = series_color(i, s);
        let line = color.stroke_width(2);
        let drawn = match (panel.kind, s.style) {
            (PanelKind::Bars, _) => chart
                .draw_series(
                    p.iter()
                        .map(|&(x, y)| PathElement::new(vec![(x, base), (x, y)], line)),
                )
                .map(|_| ()),
            (PanelKind::Cells, _) => {
                let (w, h) = (0.5 * panel.cell_size.0, 0.5 * panel.cell_size.1);
                chart
                    .draw_series(p.iter().map(|&(x, y)| {
                        Rectangle::new([(x - w, y - h), (x + w, y + h)], color.filled())
                    }))
                    .map(|_| ())
            }
            // Segment by segment: a wide polyline's miter joins spike far beyond the data
            // where the line turns back on itself (a force jump), as plotters draws them.
            (_, LineStyle::Solid) => chart
                .draw_series(
                    p.windows(2)
                        .map(|w| PathElement::new(vec![w[0], w[1]], line)),
                )
                .map(|_| ()),
            // Dashes cut at every vertex, for the same reason (`dash.rs`).
            (_, LineStyle::Dashed) => draw_dashes(chart, screen, p, (10.0, 6.0), line),
            (_, LineStyle::Dotted) => draw_dashes(chart, screen, p, (2.0, 4.0), line),
            (_, LineStyle::Points) => Ok(()), // markers only, below
        };
        drawn.map_err(draw_err)?;
        draw_markers(chart, marker_of(panel.kind, s), p, color)?;
    }

    let grey = RGBColor(90, 90, 90);
    for (x, _) in shown_vlines(panel, &xr) {
        let ends = [(*x, yr.start), (*x, yr.end)];
        chart
            .draw_series(DashedLineSeries::new(ends, 6, 4, grey.stroke_width(1)))
            .map_err(draw_err)?;
    }
    let labels = shown_vlines(panel, &xr).filter(|v| !v.1.is_empty());
    for ((_, label), r) in labels.zip(&lay.labels) {
        // On white: a line that still passes (no side was free of lines) goes behind it.
        let back = Rectangle::new([(r.x0 - 1, r.y0 - 1), (r.x1 + 1, r.y1)], WHITE.filled());
        screen.draw(&back).map_err(draw_err)?;
        let font = (FONT, LABEL_FONT_PX).into_font().color(&grey);
        let text = Text::new(label.clone(), (r.x0, r.y0), font);
        screen.draw(&text).map_err(draw_err)?;
    }
    Ok(())
}

/// The dashed line through `p` as straight pieces (`on`, `off` in px), none across a
/// vertex (see [`dash_pieces`]).
fn draw_dashes<DB, Y>(
    chart: &Chart<'_, DB, Y>,
    screen: &DrawingArea<DB, Shift>,
    p: &[(f64, f64)],
    (on, off): (f64, f64),
    line: ShapeStyle,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64>,
{
    let px: Vec<_> = p.iter().map(|xy| chart.backend_coord(xy)).collect();
    for [a, b] in dash_pieces(&px, on, off) {
        screen.draw(&PathElement::new(vec![a, b], line))?;
    }
    Ok(())
}

/// The series' markers, shaped as [`super::legend::marker_element`] draws them in the legend.
fn draw_markers<DB, Y>(
    chart: &mut Chart<'_, DB, Y>,
    marker: Marker,
    p: &[(f64, f64)],
    color: RGBColor,
) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    Y: Ranged<ValueType = f64>,
{
    let (fill, at) = (color.filled(), |xy| EmptyElement::at(xy));
    let pts = p.iter().copied();
    match marker {
        Marker::None => Ok(()),
        Marker::Circle => chart
            .draw_series(pts.map(|xy| at(xy) + Circle::new((0, 0), 4, fill)))
            .map(|_| ()),
        Marker::Square => chart
            .draw_series(pts.map(|xy| at(xy) + Rectangle::new([(-3, -3), (3, 3)], fill)))
            .map(|_| ()),
        Marker::Triangle => chart
            .draw_series(pts.map(|xy| at(xy) + TriangleMarker::new((0, 0), 5, fill)))
            .map(|_| ()),
        Marker::Cross => chart
            .draw_series(pts.map(|xy| at(xy) + Cross::new((0, 0), 4, color.stroke_width(2))))
            .map(|_| ()),
    }
    .map_err(draw_err)
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
