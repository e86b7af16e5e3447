//! Plotting layer on `plotters`: a `Figure` of vertically stacked `Panel`s of `Series`,
//! rendered to PNG bytes / files or SVG text. With plotters' `ab_glyph` feature there is no
//! system font lookup, and drawing text panics unless a font has been registered, so
//! DejaVu Sans (`dejavu` crate) is registered once, thread-safely. Bad points are dropped;
//! degenerate ranges get a width.
//!
//! Legends never cover data: a legend goes into a corner of the plot area that the data
//! leave free, or else into a band right of it (`draw.rs`); [`layout()`] returns where the
//! renderer put every legend and which pixels the data cover, so tests check what is drawn.

mod dash;
mod draw;
pub mod layout;
mod legend;
mod ticks;

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use plotters::prelude::*;
use plotters::style::register_font;

use draw::draw_figure;
pub use layout::{sequential_color, PanelLayout, Rect};

/// Largest accepted image side in pixels (keeps the RGB buffer below ~200 MB and `w*h` in u32).
pub const MAX_SIDE_PX: u32 = 8192;

/// Font family name under which DejaVu Sans is registered; plotters' own defaults
/// (tick labels) also ask for "sans-serif".
const FONT: &str = "sans-serif";

/// Smallest panel (w, h) in pixels: the axis label areas (70 px left, 40 px below) plus
/// margins, with room left to plot. Smaller areas make plotters' layout arithmetic overflow.
pub const MIN_PANEL_PX: (u32, u32) = (120, 80);

/// Height reserved for a title (20 px font plus padding) when checking the minimum size.
const TITLE_PX: u32 = 40;

/// Height added to a panel with its own title (14 px font plus padding).
const PANEL_TITLE_PX: u32 = 24;

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
    /// The image size is outside what the figure can be drawn in.
    #[error("image size {got:?} px: this figure needs >= {min:?}, <= {MAX_SIDE_PX} a side")]
    Size {
        /// The size asked, (width, height) px.
        got: (u32, u32),
        /// The smallest size the figure needs, (width, height) px.
        min: (u32, u32),
    },
    /// The embedded font could not be registered.
    #[error("the embedded DejaVu font could not be registered with plotters")]
    Font,
    /// The drawing backend failed (its message).
    #[error("drawing failed: {0}")]
    Draw(String),
    /// Reading or writing a file failed (the path and the error).
    #[error("I/O error on {}: {}", .0.display(), .1)]
    Io(PathBuf, #[source] std::io::Error),
}

/// A drawing backend's error as a [`PlotError`].
fn draw_err(e: impl std::fmt::Display) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// Line style of one series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LineStyle {
    /// A solid line.
    #[default]
    Solid,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
    /// Markers only, no connecting line (circles unless the series names a marker).
    Points,
}

/// Marker drawn at every point of a series (with or without its line).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Marker {
    /// No marker.
    #[default]
    None,
    /// A circle.
    Circle,
    /// A square.
    Square,
    /// A triangle.
    Triangle,
    /// A cross.
    Cross,
}

/// How the series of a panel are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PanelKind {
    /// Each series drawn by its line style and marker.
    #[default]
    Lines,
    /// Vertical stems from the baseline (0, or the bottom of a log axis) to each point: spectra.
    Bars,
    /// A filled cell of [`Panel::cell_size`] centred on each point: heat maps (each
    /// series one colour, with a [`ColorBar`]).
    Cells,
}

/// One named data series; `x` and `y` are paired up to the shorter length.
#[derive(Debug, Clone, Default)]
pub struct Series {
    /// Legend entry; empty = not in the legend.
    pub name: String,
    /// Abscissae, in the x axis' unit.
    pub x: Vec<f64>,
    /// Ordinates, in the y axis' unit.
    pub y: Vec<f64>,
    /// How the points are joined.
    pub style: LineStyle,
    /// Marker drawn at every point.
    pub marker: Marker,
    /// Colour (r, g, b); `None` takes the palette colour of the series' index.
    pub color: Option<[u8; 3]>,
}

/// A colour scale for series coloured by a value (see [`sequential_color`]): drawn as a
/// bar with its range and label right of the plot area.
#[derive(Debug, Clone, Default)]
pub struct ColorBar {
    /// What the colour stands for, with unit (e.g. "load cycles").
    pub label: String,
    /// Values at the bottom (t = 0) and top (t = 1) of the scale.
    pub min: f64,
    /// Value at the top (t = 1) of the scale.
    pub max: f64,
}

/// One chart: axes, series and labelled vertical markers.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    /// Small heading above the chart; empty = none.
    pub title: String,
    /// Label of the x axis, with unit.
    pub x_label: String,
    /// Label of the y axis, with unit.
    pub y_label: String,
    /// The data series, drawn in order.
    pub series: Vec<Series>,
    /// Vertical markers `(x, label)`, drawn dashed grey across the panel.
    pub vlines: Vec<(f64, String)>,
    /// Logarithmic y axis; points with y outside [1e-100, 1e100] (e.g. y <= 0) are skipped.
    pub log_y: bool,
    /// How the series are drawn.
    pub kind: PanelKind,
    /// Colour scale drawn right of the plot area, if any.
    pub color_bar: Option<ColorBar>,
    /// Width and height of a cell in data units (`PanelKind::Cells`).
    pub cell_size: (f64, f64),
}

impl Panel {
    /// The pairs of legend entries (series with a name) that the renderer draws alike:
    /// the same colour (the palette's colour of the series' index when none is given),
    /// line style and marker, so that a reader cannot tell them apart. Empty for a
    /// readable panel.
    pub fn indistinct_entries(&self) -> Vec<(String, String)> {
        let look = |i: usize, s: &Series| {
            let c = legend::series_color(i, s);
            ((c.0, c.1, c.2), s.style, legend::marker_of(self.kind, s))
        };
        let named: Vec<(&str, _)> = self
            .series
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.name.is_empty())
            .map(|(i, s)| (s.name.as_str(), look(i, s)))
            .collect();
        let mut pairs = Vec::new();
        for (k, (a, la)) in named.iter().enumerate() {
            for (b, lb) in &named[k + 1..] {
                if la == lb {
                    pairs.push((a.to_string(), b.to_string()));
                }
            }
        }
        pairs
    }
}

/// A figure: a title over panels stacked vertically with equal heights.
#[derive(Debug, Clone, Default)]
pub struct Figure {
    /// Title over the panels; empty = none.
    pub title: String,
    /// The panels, top to bottom.
    pub panels: Vec<Panel>,
}

/// Render `fig` as PNG bytes in memory (e.g. for base64 embedding in HTML): drawn into
/// an RGB buffer and encoded by the `png` crate, with no file anywhere (a temporary file
/// at a predictable name could be redirected by a planted link).
pub fn render_png(fig: &Figure, width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    check_size(fig, width, height)?;
    let mut rgb = vec![0u8; width as usize * height as usize * 3];
    draw_figure(
        &BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area(),
        fig,
    )?;
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Default);
    let encode = |e: png::EncodingError| PlotError::Draw(format!("PNG encoding: {e}"));
    let mut w = enc.write_header().map_err(encode)?;
    w.write_image_data(&rgb).map_err(encode)?;
    w.finish().map_err(encode)?;
    Ok(out)
}

/// Render `fig` as PNG and write it to `path` (any extension).
pub fn save_png(fig: &Figure, path: &Path, width: u32, height: u32) -> Result<(), PlotError> {
    write_file(path, &render_png(fig, width, height)?)
}

/// Where the renderer puts each panel's plot area, legend, colour bar and marker labels,
/// and the pixels its data cover, for an image of `width` x `height` (the same as
/// [`render_png`] and [`render_svg`] draw: the layout comes from drawing the figure).
pub fn layout(fig: &Figure, width: u32, height: u32) -> Result<Vec<PanelLayout>, PlotError> {
    check_size(fig, width, height)?;
    let mut svg = String::new();
    let layouts = draw_figure(
        &SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area(),
        fig,
    );
    layouts
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

fn write_file(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    std::fs::write(path, bytes).map_err(|e| PlotError::Io(path.to_path_buf(), e))
}

/// Smallest image (width, height) in pixels that can hold `fig`: a title band plus
/// `MIN_PANEL_PX` per panel (and `PANEL_TITLE_PX` per panel title). Panels share the
/// height equally, so the tallest need counts for each.
pub fn min_size(fig: &Figure) -> (u32, u32) {
    let n = u32::try_from(fig.panels.len()).unwrap_or(u32::MAX);
    let title = if fig.title.is_empty() { 0 } else { TITLE_PX };
    let titled = fig.panels.iter().any(|p| !p.title.is_empty());
    let panel_h = MIN_PANEL_PX.1 + if titled { PANEL_TITLE_PX } else { 0 };
    let panels_h = n.saturating_mul(panel_h);
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

#[cfg(test)]
mod tests {
    use super::*;

    fn named(name: &str, style: LineStyle, color: Option<[u8; 3]>) -> Series {
        Series {
            name: name.into(),
            style,
            color,
            ..Default::default()
        }
    }

    /// A bar panel (`log_y`: on a log axis), 900 x 420 px, as PNG bytes: `pts` in one
    /// series, or with `apart`
    /// each point a series of its own (one colour: the series are drawn in order, each
    /// stem as it is, with nothing to thin).
    fn bars_png(pts: &[(f64, f64)], apart: bool, log_y: bool) -> Vec<u8> {
        let series = |p: &[(f64, f64)]| Series {
            x: p.iter().map(|p| p.0).collect(),
            y: p.iter().map(|p| p.1).collect(),
            color: Some([31, 119, 180]),
            ..Default::default()
        };
        let fig = Figure {
            panels: vec![Panel {
                kind: PanelKind::Bars,
                log_y,
                series: if apart {
                    pts.chunks(1).map(series).collect()
                } else {
                    vec![series(pts)]
                },
                ..Default::default()
            }],
            ..Default::default()
        };
        render_png(&fig, 900, 420).unwrap()
    }

    /// Stems are thinned to those of each pixel column that the image shows before they
    /// are drawn (`draw::thin_bars`): the image must be that of every stem drawn, here
    /// each stem a series of its own (nothing to thin). Stems at 300 x positions (2.7 px
    /// apart), three or four a column, up and down from zero, the longest neither first
    /// nor last of its run, some of no length or a few pixels long (plotters fills
    /// those across: a short stem need not lie inside a longer one); and six random
    /// stems a column on a linear and on a log axis.
    #[test]
    fn thinned_stems_draw_the_image_of_every_stem() {
        let (mut a, mut b, mut c, mut l) = (vec![], vec![], vec![], vec![]);
        let mut rng = crate::rng::stream(7, 0);
        for i in 0..300 {
            let (x, y) = (i as f64, ((i * 37) % 101) as f64 - 50.0);
            let other = if i % 3 == 0 { 0.0 } else { -0.5 * y };
            a.extend([(x, 0.25 * y), (x, y), (x, other)]);
            b.extend([(x, 0.25 * y), (x, y)]);
            if i % 3 == 0 {
                b.push((x, 0.0));
            }
            b.push((x, -0.5 * y));
            for _ in 0..6 {
                let v = crate::rng::uniform(&mut rng) * 20.0 - 10.0;
                c.push((x, v * v.abs()));
                l.push((x, 10f64.powf(v / 2.0)));
            }
        }
        for (pts, log) in [(&a, false), (&b, false), (&c, false), (&l, true)] {
            assert!(bars_png(pts, false, log) == bars_png(pts, true, log));
        }
    }

    #[test]
    fn entries_drawn_alike_are_found_and_unnamed_series_ignored() {
        let mut p = Panel::default();
        // Series 0 and 8 take the same palette colour (8 colours); solid both: alike.
        for i in 0..9 {
            let style = if i == 8 {
                LineStyle::Solid
            } else {
                LineStyle::Dashed
            };
            let s = named(&format!("s{i}"), style, None);
            p.series.push(if i == 0 {
                named("s0", LineStyle::Solid, None)
            } else {
                s
            });
        }
        assert_eq!(p.indistinct_entries(), vec![("s0".into(), "s8".into())]);
        // A given colour counts as drawn: the palette's first, given to series 3.
        p.series[3] = named("s3", LineStyle::Solid, Some([31, 119, 180]));
        assert_eq!(p.indistinct_entries().len(), 3);
        // Without names they are not in the legend and cannot be confused there.
        for s in &mut p.series[3..] {
            s.name.clear();
        }
        assert!(p.indistinct_entries().is_empty());
        // Another marker sets a series apart (points panels).
        p.series[8].name = "s8".into();
        p.series[8].marker = Marker::Square;
        assert!(p.indistinct_entries().is_empty());
    }
}
