//! What the spectrum of a measured history writes: the spectrum for a case (as a CSV a
//! case's `load_spectrum.file` reads, and as a `[load_spectrum]` section to paste), the
//! load duration distribution per torque x speed cell, and the time-at-level histogram.

use super::artifacts::Artifacts;
use super::duty_figures::spectrum_figure;
use super::plot::{sequential_color, ColorBar, Figure, Panel, PanelKind, Series};
use crate::config::case::TorqueShaft;
use crate::config::spectrum_merge::Merged;
use crate::config::LoadSpectrumSection;
use crate::duty::ldd::{Interpolation, Ldd, Level};
use crate::format::{shown, shown_percent};
use crate::io::Table;
use serde_json::json;

/// Seconds per hour: the figure and headline give time in hours, as duty cycles are stated.
const S_PER_H: f64 = 3600.0;

/// Midpoints of consecutive class edges.
fn mids(edges: &[f64]) -> Vec<f64> {
    edges.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect()
}

/// The cells of `ldd` as a table: class edges, time, revolutions and mean torque of
/// each cell (row-major: torque class slowest), every cell including the empty ones.
pub fn ldd_table(ldd: &Ldd) -> Table {
    let ns = ldd.settings.speed_classes;
    let n = ldd.time_s.len();
    let col = |f: &dyn Fn(usize) -> f64| (0..n).map(f).collect::<Vec<f64>>();
    Table::new()
        .col("torque_from_nm", col(&|i| ldd.torque_edges_nm[i / ns]))
        .col("torque_to_nm", col(&|i| ldd.torque_edges_nm[i / ns + 1]))
        .col("speed_from_hz", col(&|i| ldd.speed_edges_hz[i % ns]))
        .col("speed_to_hz", col(&|i| ldd.speed_edges_hz[i % ns + 1]))
        .col("time_s", ldd.time_s.clone())
        .col("cycles", ldd.cycles.clone())
        .col(
            "mean_torque_nm",
            col(&|i| {
                if ldd.cycles[i] > 0.0 {
                    ldd.torque_cycles_nm[i] / ldd.cycles[i]
                } else {
                    f64::NAN
                }
            }),
        )
}

/// The spectrum as the CSV a case reads (`torque_nm,input_speed_hz,share`).
pub fn spectrum_table(s: &LoadSpectrumSection) -> Table {
    let col = |f: &dyn Fn(usize) -> f64| (0..s.bins.len()).map(f).collect::<Vec<f64>>();
    Table::new()
        .col("torque_nm", col(&|i| s.bins[i].torque_nm))
        .col("input_speed_hz", col(&|i| s.bins[i].input_speed_hz))
        .col("share", col(&|i| s.bins[i].share))
}

/// The spectrum as a `[load_spectrum]` section of a case file, bins inline, every number
/// in its shortest form that reads back exactly.
pub fn spectrum_toml(s: &LoadSpectrumSection, shaft: TorqueShaft) -> String {
    let shaft = match shaft {
        TorqueShaft::Pinion => "pinion",
        TorqueShaft::Gear => "gear",
    };
    let mut t = format!(
        "# The load spectrum of a measured history (gearwear load-spectrum): paste into a case.\n[load_spectrum]\ntorque_shaft = \"{shaft}\"\nbins = [\n"
    );
    for b in &s.bins {
        t.push_str(&format!(
            "    {{ torque_nm = {:?}, input_speed_hz = {:?}, share = {:?} }},\n",
            b.torque_nm, b.input_speed_hz, b.share
        ));
    }
    t.push_str("]\n");
    t
}

/// Time at level: the torque x speed cells coloured by their time, and the time at each
/// torque class and each speed class (all in hours), with the table of exactly its data.
pub fn time_at_level_figure(ldd: &Ldd) -> (Figure, Table) {
    let (tm, fm) = (mids(&ldd.torque_edges_nm), mids(&ldd.speed_edges_hz));
    let ns = ldd.settings.speed_classes;
    let hours: Vec<f64> = ldd.time_s.iter().map(|t| t / S_PER_H).collect();
    let top = hours.iter().fold(0.0_f64, |a, b| a.max(*b)).max(1e-300);
    let cells: Vec<Series> = (0..hours.len())
        .filter(|i| hours[*i] > 0.0)
        .map(|i| Series {
            x: vec![fm[i % ns]],
            y: vec![tm[i / ns]],
            color: Some(sequential_color(hours[i] / top)),
            ..Default::default()
        })
        .collect();
    let width = |e: &[f64]| e.get(1).copied().unwrap_or(1.0) - e[0];
    let at_torque: Vec<f64> = ldd.time_at_torque_s().iter().map(|t| t / S_PER_H).collect();
    let at_speed: Vec<f64> = ldd.time_at_speed_s().iter().map(|t| t / S_PER_H).collect();
    let bars = |x: &[f64], y: &[f64], x_label: &str, name: &str| Panel {
        x_label: x_label.into(),
        y_label: "time (h)".into(),
        series: vec![Series {
            name: name.into(),
            x: x.to_vec(),
            y: y.to_vec(),
            ..Default::default()
        }],
        kind: PanelKind::Bars,
        ..Default::default()
    };
    let figure = Figure {
        title: format!(
            "Time at level ({:.4} h under load, {:.4} h idle)",
            ldd.loaded_time_s() / S_PER_H,
            ldd.idle_time_s / S_PER_H
        ),
        panels: vec![
            Panel {
                title: "time in each torque x speed cell (colour)".into(),
                x_label: "input speed (Hz)".into(),
                y_label: "torque (N m)".into(),
                series: cells,
                kind: PanelKind::Cells,
                cell_size: (width(&ldd.speed_edges_hz), width(&ldd.torque_edges_nm)),
                color_bar: Some(ColorBar {
                    label: "time (h)".into(),
                    min: 0.0,
                    max: top,
                }),
                ..Default::default()
            },
            bars(
                &tm,
                &at_torque,
                "torque class midpoint (N m)",
                "time at torque",
            ),
            bars(&fm, &at_speed, "speed class midpoint (Hz)", "time at speed"),
        ],
    };
    // Columns of unequal length: the torque classes, then the speed classes.
    let table = Table::new()
        .col("torque_class_mid_nm", tm)
        .col("time_at_torque_h", at_torque)
        .col("speed_class_mid_hz", fm)
        .col("time_at_speed_h", at_speed);
    (figure, table)
}

fn interpolation_name(i: Interpolation) -> &'static str {
    match i {
        Interpolation::Linear => "linear",
        Interpolation::Hold => "hold",
    }
}

fn level_name(l: Level) -> &'static str {
    match l {
        Level::Mean => "mean",
        Level::Upper => "upper",
    }
}

/// What the merge of dust bins did, for the headline: empty when nothing was merged.
fn merged_note(m: &Merged) -> String {
    match m.merged {
        0 => String::new(),
        n => format!(
            "; {n} bin{} holding {} of the revolutions merged into their nearest",
            if n == 1 { "" } else { "s" },
            shown_percent(m.merged_share)
        ),
    }
}

/// Everything the spectrum of a history writes; `source`: the history's name.
pub fn ldd_artifacts(
    source: &str,
    samples: usize,
    ldd: &Ldd,
    spectrum: &LoadSpectrumSection,
    merged: &Merged,
    shaft: TorqueShaft,
) -> Artifacts {
    let mut a = Artifacts::default();
    let cycles: f64 = ldd.cycles.iter().sum();
    let counted = ldd.loaded_time_s() + ldd.idle_time_s;
    a.summary = json!({
        "history": { "source": source, "samples": samples, "span_s": ldd.span_s },
        "method": {
            "count": "time at level (ISO 6336-6 load spectrum; the IEC 61400-4 load duration distribution)",
            "interpolation": interpolation_name(ldd.settings.interpolation),
            "bin_torque": level_name(ldd.settings.level),
            "torque_classes": ldd.settings.torque_classes,
            "speed_classes": ldd.settings.speed_classes,
        },
        "time": {
            "under_load_s": ldd.loaded_time_s(),
            "idle_s": ldd.idle_time_s,
            "reversed_torque_s": ldd.reversed_torque_time_s,
            "counted_s": counted,
            "span_s": ldd.span_s,
        },
        "pinion_revolutions_under_load": cycles,
        "bins": spectrum.bins.len(),
        "merged_bins": merged,
        "load_spectrum": {
            "torque_shaft": shaft,
            "bins": spectrum.bins,
        },
    });
    a.table("spectrum.csv", spectrum_table(spectrum));
    a.table("ldd.csv", ldd_table(ldd));
    let (fig, data) = time_at_level_figure(ldd);
    a.figure_with_data("ldd_time_at_level.png", fig, data);
    let f = spectrum_figure(spectrum, None);
    a.figure_with_data(format!("{}.png", f.stem), f.figure, f.table);
    a.documents.push((
        "load_spectrum.toml".into(),
        spectrum_toml(spectrum, shaft).into_bytes(),
    ));
    a.headline = format!(
        "{} samples over {} h: {} h under load in {} bins ({} torque x {} speed classes{}), {} h idle; {} pinion revolutions",
        samples,
        shown(ldd.span_s / S_PER_H),
        shown(ldd.loaded_time_s() / S_PER_H),
        spectrum.bins.len(),
        ldd.settings.torque_classes,
        ldd.settings.speed_classes,
        merged_note(merged),
        shown(ldd.idle_time_s / S_PER_H),
        shown(cycles)
    );
    a
}
