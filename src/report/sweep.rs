//! Figures of a sweep: max DTE and dynamic factor against input speed, with the speeds
//! where a mesh harmonic meets a mode marked.

use super::figures::{panel, Curve};
use super::plot::Figure;
use crate::study::sweep::{Crossing, SweepTable, SPEED_KEY};
use std::collections::BTreeMap;

/// Size of the two-panel sweep figure, px.
pub const SWEEP_FIGURE_PX: (u32, u32) = (900, 640);

/// Max DTE and dynamic factor against input speed, one curve per combination of the other
/// varied keys, with the crossing speeds marked.
pub fn speed_figure(t: &SweepTable, marks: &[Crossing]) -> Option<Figure> {
    let ks = t.keys.iter().position(|k| k == SPEED_KEY)?;
    let (dte, df) = (t.column("dte_max_um")?, t.column("dynamic_factor")?);
    let mut groups: BTreeMap<String, Vec<(f64, f64, f64)>> = BTreeMap::new();
    for r in &t.rows {
        let Ok(speed) = r.values[ks].parse::<f64>() else {
            continue;
        };
        let others: Vec<String> = (0..t.keys.len())
            .filter(|i| *i != ks)
            .map(|i| format!("{}={}", t.keys[i], r.values[i]))
            .collect();
        groups
            .entry(others.join(", "))
            .or_default()
            .push((speed, r.results[dte], r.results[df]));
    }
    let (mut c_dte, mut c_df) = (Vec::new(), Vec::new());
    for (name, mut pts) in groups {
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let x: Vec<f64> = pts.iter().map(|p| p.0).collect();
        c_dte.push(Curve::new(
            name.clone(),
            x.clone(),
            pts.iter().map(|p| p.1).collect(),
        ));
        c_df.push(Curve::new(name, x, pts.iter().map(|p| p.2).collect()));
    }
    let vlines: Vec<(f64, String)> = marks
        .iter()
        .map(|c| (c.input_speed_hz, c.label()))
        .collect();
    let x = "input speed (Hz)";
    let mut p1 = panel(x, "max DTE (um)", c_dte);
    let mut p2 = panel(x, "dynamic factor (-)", c_df);
    p1.vlines = vlines.clone();
    p2.vlines = vlines;
    Some(Figure {
        title: "Speed sweep (markers: h x z1 x f_in = natural frequency f_n, h = 1..3)".into(),
        panels: vec![p1, p2],
    })
}
