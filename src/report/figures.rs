//! Builders of the paper's figures (2, 4-13) from results. Pure: data in, `Figure` out.

use super::plot::{
    sequential_color, ColorBar, Figure, LineStyle, Marker, Panel, PanelKind, Series,
};
use crate::io::Table;

/// A figure with the table behind it.
pub struct Fig {
    /// File stem, e.g. "fig04_dte".
    pub file: String,
    /// The paper's figure this one reproduces; 0: a figure beyond the paper.
    pub paper_figure: u32,
    /// Caption in the report (plain text).
    pub caption: String,
    /// The figure.
    pub figure: Figure,
    /// Exactly the plotted numbers.
    pub table: Table,
}

/// A labelled curve (x, y), already in display units.
pub struct Curve {
    /// Legend entry.
    pub name: String,
    /// Abscissae, in display units.
    pub x: Vec<f64>,
    /// Ordinates, in display units.
    pub y: Vec<f64>,
}

impl Curve {
    /// A curve named `name` through the points (x, y).
    pub fn new(name: impl Into<String>, x: Vec<f64>, y: Vec<f64>) -> Self {
        Self {
            name: name.into(),
            x,
            y,
        }
    }
}

const STYLES: [LineStyle; 3] = [LineStyle::Solid, LineStyle::Dashed, LineStyle::Dotted];
const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Cross,
];

/// One panel of curves, cycling line styles (and palette colours).
pub fn panel(x_label: &str, y_label: &str, curves: Vec<Curve>) -> Panel {
    Panel {
        x_label: x_label.into(),
        y_label: y_label.into(),
        series: curves
            .into_iter()
            .enumerate()
            .map(|(i, c)| Series {
                name: c.name,
                x: c.x,
                y: c.y,
                style: STYLES[i % STYLES.len()],
                ..Default::default()
            })
            .collect(),
        ..Default::default()
    }
}

/// A panel of curves through a few points each: every point drawn as a marker (a
/// different shape per curve) on the curve's line.
pub fn points_panel(x_label: &str, y_label: &str, curves: Vec<Curve>) -> Panel {
    let mut p = panel(x_label, y_label, curves);
    for (i, s) in p.series.iter_mut().enumerate() {
        s.marker = MARKERS[i % MARKERS.len()];
    }
    p
}

/// A panel of many curves, each coloured by a value on a sequential scale shown as a
/// colour bar; `scale` is (what the value is, with unit; value at the bottom; at the top).
/// The curves have no legend entries.
pub fn scale_panel(
    title: &str,
    x_label: &str,
    y_label: &str,
    curves: Vec<(f64, Curve)>,
    scale: (&str, f64, f64),
) -> Panel {
    let (label, min, max) = scale;
    let span = if max > min { max - min } else { 1.0 };
    Panel {
        title: title.into(),
        x_label: x_label.into(),
        y_label: y_label.into(),
        series: curves
            .into_iter()
            .map(|(v, c)| Series {
                x: c.x,
                y: c.y,
                color: Some(sequential_color((v - min) / span)),
                ..Default::default()
            })
            .collect(),
        color_bar: (min.is_finite() && max.is_finite()).then(|| ColorBar {
            label: label.into(),
            min,
            max,
        }),
        ..Default::default()
    }
}

/// A figure with one panel.
pub fn single(title: &str, p: Panel) -> Figure {
    Figure {
        title: title.into(),
        panels: vec![p],
    }
}

/// Relative tolerance on a frequency limit: a bin computed as k / T lands on h f_mesh
/// only up to round-off (~1e-15 relative), far below this.
const FREQ_TOL: f64 = 1e-9;

/// The rows of a spectrum up to `f_max_hz` (what [`spectrum_panel`] shows).
pub fn spectrum_rows(freq_hz: &[f64], amp: &[f64], f_max_hz: f64) -> (Vec<f64>, Vec<f64>) {
    freq_hz
        .iter()
        .zip(amp)
        .filter(|(f, _)| **f <= f_max_hz * (1.0 + FREQ_TOL))
        .map(|(f, a)| (*f, *a))
        .unzip()
}

/// A one-sided amplitude spectrum as stems, with the mesh harmonics in its range marked.
pub fn spectrum_panel(y_label: &str, freq_hz: &[f64], amp: &[f64], mesh_hz: f64) -> Panel {
    spectrum_panel_meshes(y_label, freq_hz, amp, &[mesh_hz])
}

/// [`spectrum_panel`] of a gear train: every mesh's harmonics (up to the 8th) in the
/// range marked, "h × mesh k" for mesh k (1-based, the stage's number); a single mesh
/// keeps the pair's labels ("mesh frequency", "2 × mesh frequency", ...).
pub fn spectrum_panel_meshes(
    y_label: &str,
    freq_hz: &[f64],
    amp: &[f64],
    mesh_hz: &[f64],
) -> Panel {
    let f_max_hz = freq_hz.iter().fold(0.0_f64, |a, b| a.max(*b)) * (1.0 + FREQ_TOL);
    let vlines = mesh_harmonic_lines(mesh_hz, f_max_hz, 8);
    Panel {
        x_label: "frequency (Hz)".into(),
        y_label: y_label.into(),
        series: vec![Series {
            x: freq_hz.to_vec(),
            y: amp.to_vec(),
            ..Default::default()
        }],
        vlines,
        kind: PanelKind::Bars,
        ..Default::default()
    }
}

/// The marker lines of every mesh's harmonics 1..=`max_harmonic` at or below `f_max_hz`
/// (Hz), mesh order: "mesh frequency", "2 × mesh frequency", ... for a single mesh,
/// "mesh k", "h × mesh k" for mesh k (1-based: a train's stage number) of several.
pub fn mesh_harmonic_lines(
    mesh_hz: &[f64],
    f_max_hz: f64,
    max_harmonic: usize,
) -> Vec<(f64, String)> {
    let mut lines = Vec::new();
    for (k, &f) in mesh_hz.iter().enumerate() {
        for h in (1..=max_harmonic).take_while(|h| f > 0.0 && *h as f64 * f <= f_max_hz) {
            let label = match (mesh_hz.len(), h) {
                (1, _) => harmonic_label(h),
                (_, 1) => format!("mesh {}", k + 1),
                _ => format!("{h} × mesh {}", k + 1),
            };
            lines.push((h as f64 * f, label));
        }
    }
    lines
}

/// Colour levels of a [`heat_panel`].
const HEAT_LEVELS: usize = 32;

/// A heat map of wear depth: row r's profile `rows_m[r]` (m) drawn as cells at the
/// abscissae `xs` and the ordinate `ys[r]` (evenly spaced in both), coloured on the
/// sequential scale from 0 to `max_um` (µm) in 32 levels, with its colour bar. The
/// caller sets the title and axis labels.
pub fn heat_panel(xs: &[f64], ys: &[f64], rows_m: &[Vec<f64>], max_um: f64) -> Panel {
    let mut series: Vec<Series> = (0..HEAT_LEVELS)
        .map(|l| Series {
            color: Some(sequential_color((l as f64 + 0.5) / HEAT_LEVELS as f64)),
            ..Default::default()
        })
        .collect();
    for (y, p) in ys.iter().zip(rows_m) {
        for (x, h) in xs.iter().zip(p) {
            let level = if max_um > 0.0 {
                ((h * 1e6 / max_um * HEAT_LEVELS as f64) as usize).min(HEAT_LEVELS - 1)
            } else {
                0
            };
            series[level].x.push(*x);
            series[level].y.push(*y);
        }
    }
    let step = |v: &[f64]| match v {
        [a, .., b] => (b - a).abs() / (v.len() - 1) as f64,
        _ => 1.0,
    };
    Panel {
        series,
        kind: PanelKind::Cells,
        cell_size: (step(xs), step(ys)),
        color_bar: Some(ColorBar {
            label: "wear depth (µm)".into(),
            min: 0.0,
            max: max_um,
        }),
        ..Default::default()
    }
}

/// "mesh frequency", "2 x mesh frequency", ... for harmonic `h` (1-based).
pub fn harmonic_label(h: usize) -> String {
    match h {
        1 => "mesh frequency".into(),
        _ => format!("{h} × mesh frequency"),
    }
}
