//! Legends and colour bars, drawn in pixel coordinates by our own code rather than by
//! plotters' series labels, so that their boxes are known before they are drawn (to keep
//! them off the data) and their swatches show each series' own line style and marker.

use plotters::coord::Shift;
use plotters::element::DynElement;
use plotters::prelude::*;

use super::layout::{sequential_color, Rect};
use super::ticks::tick_label;
use super::{draw_err, ColorBar, LineStyle, Marker, Panel, PanelKind, PlotError, Series, FONT};

/// Padding inside a legend and gap between a band and the plot area, px.
pub const PAD: i32 = 6;
pub const GAP: i32 = 10;
/// Length of a legend swatch, px: fits two dashes (10 on, 6 off) or five dots.
const SWATCH_PX: i32 = 28;
const LEGEND_FONT_PX: u32 = 12;
/// Width of the colour bar itself, px.
const BAR_PX: i32 = 14;

fn text_style() -> TextStyle<'static> {
    TextStyle::from((FONT, LEGEND_FONT_PX).into_font())
}

fn text_size<DB: DrawingBackend>(
    screen: &DrawingArea<DB, Shift>,
    text: &str,
) -> Result<(u32, u32), PlotError> {
    screen
        .estimate_text_size(text, &text_style())
        .map_err(draw_err)
}

/// Colour of series `i`: its own, or the palette's.
pub fn series_color(i: usize, s: &Series) -> RGBColor {
    match s.color {
        Some([r, g, b]) => RGBColor(r, g, b),
        None => super::PALETTE[i % super::PALETTE.len()],
    }
}

/// The marker a series draws at its points, if any (a `Points` series without one gets
/// circles; spectra draw stems only).
pub fn marker_of(kind: PanelKind, s: &Series) -> Marker {
    match (kind, s.style, s.marker) {
        (PanelKind::Bars | PanelKind::Cells, _, _) => Marker::None,
        (_, LineStyle::Points, Marker::None) => Marker::Circle,
        (_, _, m) => m,
    }
}

/// A marker centred on `at` (data or pixel coordinates), about 8 px across.
pub fn marker_element<'a, DB: DrawingBackend + 'a, C: Clone + 'a>(
    m: Marker,
    at: C,
    color: RGBColor,
) -> DynElement<'a, DB, C> {
    let (fill, e) = (color.filled(), EmptyElement::at(at));
    match m {
        Marker::None | Marker::Circle => (e + Circle::new((0, 0), 4, fill)).into_dyn(),
        Marker::Square => (e + Rectangle::new([(-3, -3), (3, 3)], fill)).into_dyn(),
        Marker::Triangle => (e + TriangleMarker::new((0, 0), 5, fill)).into_dyn(),
        Marker::Cross => (e + Cross::new((0, 0), 4, color.stroke_width(2))).into_dyn(),
    }
}

/// The legend of a panel with two or more named series, measured.
pub struct Legend<'p> {
    entries: Vec<(&'p Series, RGBColor, Marker)>,
    text_w: u32,
    text_h: u32,
    kind: PanelKind,
}

impl Legend<'_> {
    fn row_px(&self) -> i32 {
        self.text_h.max(10) as i32 + 4
    }

    /// Width and height of the box, px.
    pub fn size(&self) -> (u32, u32) {
        let w = 2 * PAD + SWATCH_PX + 6 + self.text_w as i32;
        let h = 2 * PAD + self.entries.len() as i32 * self.row_px();
        (w as u32, h as u32)
    }
}

pub fn measure_legend<'p, DB: DrawingBackend>(
    screen: &DrawingArea<DB, Shift>,
    panel: &'p Panel,
) -> Result<Option<Legend<'p>>, PlotError> {
    let mut entries = Vec::new();
    let (mut text_w, mut text_h) = (0, 0);
    for (i, s) in panel.series.iter().enumerate() {
        if !s.name.is_empty() {
            let (w, h) = text_size(screen, &s.name)?;
            (text_w, text_h) = (text_w.max(w), text_h.max(h));
            entries.push((s, series_color(i, s), marker_of(panel.kind, s)));
        }
    }
    Ok((entries.len() > 1).then_some(Legend {
        entries,
        text_w,
        text_h,
        kind: panel.kind,
    }))
}

/// Draw the legend into `r` (from [`Legend::size`]).
pub fn draw_legend<DB: DrawingBackend>(
    screen: &DrawingArea<DB, Shift>,
    l: &Legend,
    r: Rect,
) -> Result<(), PlotError> {
    let corners = [(r.x0, r.y0), (r.x1 - 1, r.y1 - 1)];
    screen
        .draw(&Rectangle::new(corners, WHITE.filled()))
        .map_err(draw_err)?;
    screen
        .draw(&Rectangle::new(corners, BLACK.mix(0.5).stroke_width(1)))
        .map_err(draw_err)?;
    let row = l.row_px();
    for (k, (s, color, marker)) in l.entries.iter().enumerate() {
        let y = r.y0 + PAD + k as i32 * row + row / 2;
        let x = r.x0 + PAD;
        let style = if l.kind == PanelKind::Bars {
            LineStyle::Solid
        } else {
            s.style
        };
        draw_swatch(screen, style, x, y, *color)?;
        if *marker != Marker::None {
            let m = marker_element(*marker, (x + SWATCH_PX / 2, y), *color);
            screen.draw(&m).map_err(draw_err)?;
        }
        let text = Text::new(
            s.name.clone(),
            (x + SWATCH_PX + 6, y - l.text_h as i32 / 2),
            text_style(),
        );
        screen.draw(&text).map_err(draw_err)?;
    }
    Ok(())
}

/// A short piece of line in the series' own style: solid, two dashes or five dots.
fn draw_swatch<DB: DrawingBackend>(
    screen: &DrawingArea<DB, Shift>,
    style: LineStyle,
    x: i32,
    y: i32,
    color: RGBColor,
) -> Result<(), PlotError> {
    // (on, off) lengths as the data lines are drawn (draw.rs).
    let pieces: &[(i32, i32)] = match style {
        LineStyle::Solid => &[(0, SWATCH_PX)],
        LineStyle::Dashed => &[(0, 10), (16, 26)],
        LineStyle::Dotted => &[(0, 2), (6, 8), (12, 14), (18, 20), (24, 26)],
        LineStyle::Points => &[],
    };
    for (a, b) in pieces {
        let seg = PathElement::new(vec![(x + a, y), (x + b, y)], color.stroke_width(2));
        screen.draw(&seg).map_err(draw_err)?;
    }
    Ok(())
}

/// A colour bar, measured: `band_w` is the width it needs right of the plot area.
pub struct BarSpec<'p> {
    bar: &'p ColorBar,
    ticks: [(f64, String); 3],
    label_h: u32,
    tick_h: u32,
    pub band_w: u32,
}

pub fn measure_bar<'p, DB: DrawingBackend>(
    screen: &DrawingArea<DB, Shift>,
    panel: &'p Panel,
) -> Result<Option<BarSpec<'p>>, PlotError> {
    let Some(bar) = &panel.color_bar else {
        return Ok(None);
    };
    let mid = 0.5 * (bar.min + bar.max);
    // Three significant digits: a colour is read to a few per cent at best.
    let three = |v: f64| format!("{v:.2e}").parse().unwrap_or(v);
    let ticks =
        [(0.0, bar.min), (0.5, mid), (1.0, bar.max)].map(|(t, v)| (t, tick_label(three(v), 0.0)));
    let (label_w, label_h) = text_size(screen, &bar.label)?;
    let (mut tick_w, mut tick_h) = (0, 0);
    for (_, s) in &ticks {
        let (w, h) = text_size(screen, s)?;
        (tick_w, tick_h) = (tick_w.max(w), tick_h.max(h));
    }
    let inner = label_w.max(BAR_PX as u32 + 4 + tick_w);
    Ok(Some(BarSpec {
        bar,
        ticks,
        label_h,
        tick_h,
        band_w: inner + 2 * GAP as u32,
    }))
}

/// Draw the colour bar into `r`: its label on top, then the scale (t = 1 at the top) with
/// the values at both ends and the middle.
pub fn draw_bar<DB: DrawingBackend>(
    screen: &DrawingArea<DB, Shift>,
    b: &BarSpec,
    r: Rect,
) -> Result<(), PlotError> {
    let label = Text::new(b.bar.label.clone(), (r.x0, r.y0), text_style());
    screen.draw(&label).map_err(draw_err)?;
    let (top, bottom) = (r.y0 + b.label_h as i32 + 6, r.y1 - 1);
    let span = f64::from((bottom - top).max(1));
    for y in top..=bottom {
        let [cr, cg, cb] = sequential_color(f64::from(bottom - y) / span);
        let px = Rectangle::new(
            [(r.x0, y), (r.x0 + BAR_PX, y + 1)],
            RGBColor(cr, cg, cb).filled(),
        );
        screen.draw(&px).map_err(draw_err)?;
    }
    let frame = Rectangle::new(
        [(r.x0, top), (r.x0 + BAR_PX, bottom)],
        BLACK.mix(0.5).stroke_width(1),
    );
    screen.draw(&frame).map_err(draw_err)?;
    for (t, text) in &b.ticks {
        let y = bottom - (t * span).round() as i32;
        let tick = PathElement::new(
            vec![(r.x0 + BAR_PX, y), (r.x0 + BAR_PX + 3, y)],
            BLACK.stroke_width(1),
        );
        screen.draw(&tick).map_err(draw_err)?;
        let at = (r.x0 + BAR_PX + 5, y - b.tick_h as i32 / 2);
        screen
            .draw(&Text::new(text.clone(), at, text_style()))
            .map_err(draw_err)?;
    }
    Ok(())
}
