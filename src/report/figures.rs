//! Builders of the paper's figures (2, 4-13) from results. Pure: data in, `Figure` out.

use super::plot::{Figure, LineStyle, Panel, PanelKind, Series};

/// A labelled curve (x, y), already in display units.
pub struct Curve {
    pub name: String,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

impl Curve {
    pub fn new(name: impl Into<String>, x: Vec<f64>, y: Vec<f64>) -> Self {
        Self {
            name: name.into(),
            x,
            y,
        }
    }
}

const STYLES: [LineStyle; 3] = [LineStyle::Solid, LineStyle::Dashed, LineStyle::Dotted];

/// One panel of curves, cycling line styles.
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
            })
            .collect(),
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

/// A one-sided amplitude spectrum as stems, with mesh-harmonic markers.
pub fn spectrum_panel(
    y_label: &str,
    freq_hz: &[f64],
    amp: &[f64],
    f_max_hz: f64,
    mesh_hz: f64,
) -> Panel {
    let keep: Vec<usize> = (0..freq_hz.len())
        .filter(|i| freq_hz[*i] <= f_max_hz)
        .collect();
    let mut vlines = Vec::new();
    let mut h = 1;
    while mesh_hz > 0.0 && h as f64 * mesh_hz <= f_max_hz && h <= 8 {
        vlines.push((h as f64 * mesh_hz, format!("{h} MF")));
        h += 1;
    }
    Panel {
        x_label: "frequency (Hz)".into(),
        y_label: y_label.into(),
        series: vec![Series {
            name: String::new(),
            x: keep.iter().map(|i| freq_hz[*i]).collect(),
            y: keep.iter().map(|i| amp[*i]).collect(),
            style: LineStyle::Solid,
        }],
        vlines,
        log_y: false,
        kind: PanelKind::Bars,
    }
}
