//! Figures and tables of a run-up or coast-down record: the Campbell diagram (frequency
//! against speed, the mesh orders and the damped mesh poles drawn over it) and the order
//! tracks of the mesh harmonics with the speeds where they cross a mesh pole.

use super::artifacts::Artifacts;
use super::figures::{panel, Curve};
use super::plot::{sequential_color, ColorBar, Figure, LineStyle, Marker, Panel, Series};
use crate::io::Table;
use crate::signals::antialias::SAMPLING_OVER_PASSBAND;
use crate::signals::chain::{Shaft, SignalChain};
use crate::signals::order::{campbell_map, order_map};
use crate::signals::tachometer::rising_edges;
use crate::study::signal_record::SignalRecord;
use serde_json::{json, Value};

/// Revolutions of the pinion per order-spectrum block.
const BLOCK_REVOLUTIONS: usize = 4;
/// Levels of the Campbell diagram's colour scale, 6 dB each.
const LEVELS: usize = 8;

/// Add the run-up figures and tables of `rec` to `a`; returns the summary's `runup` part.
pub fn runup_artifacts(
    a: &mut Artifacts,
    rec: &SignalRecord,
    chain: &SignalChain,
    harmonics: usize,
    unit: &str,
) -> Value {
    let r = &rec.record;
    let Some((name, x)) = r.channels.first() else {
        return Value::Null;
    };
    let fs = r.sampling_rate_hz;
    let k = &rec.kinematics;
    let edges = rising_edges(&r.tachometer_v, fs);
    let n = chain.tachometer.pulses_per_revolution;
    // Pinion revolutions per tachometer revolution.
    let ratio = match chain.tachometer.shaft {
        Shaft::Pinion => 1.0,
        Shaft::Gear => k.pinion_hz / k.gear_hz,
    };
    let z1 = k.teeth_pinion as f64;
    let harmonics = harmonics.clamp(1, 4);
    let orders = order_map(x, fs, &edges, n, ratio, BLOCK_REVOLUTIONS);
    let mut table = Table::new().col("input_speed_hz", orders.speed_hz.clone());
    let mut tracks = Vec::new();
    let mut peaks = Vec::new();
    for h in 1..=harmonics {
        let t = orders.track(h as f64 * z1);
        if let Some((i, v)) = t.iter().enumerate().max_by(|p, q| p.1.total_cmp(q.1)) {
            peaks.push(json!({"harmonic": h, "order": h as f64 * z1, "peak_input_speed_hz": orders.speed_hz[i], "peak_amplitude": v}));
        }
        table = table.col(&format!("order_{}_amplitude", h as f64 * z1), t.clone());
        tracks.push(Curve::new(
            format!("{h}× mesh (order {})", h as f64 * z1),
            orders.speed_hz.clone(),
            t,
        ));
    }
    let (lo, hi) = (
        rec.input_speed_hz.0.min(rec.input_speed_hz.1),
        rec.input_speed_hz.0.max(rec.input_speed_hz.1),
    );
    let mut crossings = Vec::new();
    for &fp in &rec.mesh_poles_hz {
        for h in 1..=harmonics {
            let v = fp / (h as f64 * z1);
            if (lo..=hi).contains(&v) {
                crossings.push((v, h, fp));
            }
        }
    }
    let mut p = panel(
        "input speed (Hz)",
        &format!("order amplitude ({unit})"),
        tracks,
    );
    p.log_y = true;
    p.vlines = crossings
        .iter()
        .map(|(v, h, fp)| (*v, format!("{h}× mesh at the {fp:.0} Hz mesh pole")))
        .collect();
    a.figure_with_data(
        "order_tracks.png",
        Figure {
            title: format!(
                "{name}: mesh orders along the ramp ({BLOCK_REVOLUTIONS}-revolution blocks)"
            ),
            panels: vec![p],
        },
        table,
    );
    let block = ((fs / 8.0) as usize).next_power_of_two().max(256);
    let camp = campbell_map(x, fs, &edges, n, ratio, block);
    a.figure_sized(
        "campbell.png",
        campbell_figure(&camp, fs, z1, harmonics, &rec.mesh_poles_hz, name, unit),
        900,
        600,
    );
    json!({
        "input_speed_hz": [rec.input_speed_hz.0, rec.input_speed_hz.1],
        "order_block_revolutions": BLOCK_REVOLUTIONS,
        "order_peaks": peaks,
        "pole_crossings": crossings.iter().map(|(v, h, fp)| json!({"harmonic": h, "mesh_pole_hz": fp, "input_speed_hz": v})).collect::<Vec<_>>(),
    })
}

/// Frequency against speed, coloured by level; the mesh orders and the mesh poles drawn.
fn campbell_figure(
    c: &crate::signals::order::CampbellMap,
    fs: f64,
    z1: f64,
    harmonics: usize,
    poles: &[f64],
    name: &str,
    unit: &str,
) -> Figure {
    let top = fs / SAMPLING_OVER_PASSBAND;
    let peak = c
        .amplitude
        .iter()
        .flat_map(|a| a.iter())
        .fold(0.0_f64, |m, v| m.max(*v));
    let rows = 200usize;
    let bins_per_row = (c.frequency_hz.iter().filter(|f| **f <= top).count() / rows).max(1);
    let mut levels: Vec<(Vec<f64>, Vec<f64>)> = vec![(Vec::new(), Vec::new()); LEVELS];
    for (a, v) in c.amplitude.iter().zip(&c.speed_hz) {
        for (row, chunk) in a.chunks(bins_per_row).enumerate() {
            let f = c.frequency_hz[row * bins_per_row];
            if f > top {
                break;
            }
            let m = chunk.iter().fold(0.0_f64, |x, y| x.max(*y));
            if m <= 0.0 || peak <= 0.0 {
                continue;
            }
            let db = 20.0 * (m / peak).log10();
            let level = ((-db / 6.0).floor() as isize).clamp(0, LEVELS as isize);
            if (level as usize) < LEVELS {
                let l = LEVELS - 1 - level as usize;
                levels[l].0.push(*v);
                levels[l].1.push(f);
            }
        }
    }
    let mut series: Vec<Series> = levels
        .into_iter()
        .enumerate()
        .map(|(l, (x, y))| Series {
            x,
            y,
            style: LineStyle::Points,
            marker: Marker::Square,
            color: Some(sequential_color(l as f64 / (LEVELS - 1) as f64)),
            ..Default::default()
        })
        .collect();
    let (vmin, vmax) = c
        .speed_hz
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    for h in 1..=harmonics {
        series.push(Series {
            name: format!("{h}× mesh"),
            x: vec![vmin, vmax],
            y: vec![h as f64 * z1 * vmin, h as f64 * z1 * vmax],
            style: LineStyle::Dashed,
            color: Some([60, 60, 60]),
            ..Default::default()
        });
    }
    for fp in poles {
        series.push(Series {
            name: format!("mesh pole {fp:.0} Hz"),
            x: vec![vmin, vmax],
            y: vec![*fp, *fp],
            style: LineStyle::Dotted,
            color: Some([200, 30, 30]),
            ..Default::default()
        });
    }
    Figure {
        title: format!("Campbell diagram of {name}: spectrum along the ramp"),
        panels: vec![Panel {
            x_label: "input speed (Hz)".into(),
            y_label: "frequency (Hz)".into(),
            series,
            color_bar: Some(ColorBar {
                label: format!("level (dB re peak {peak:.3} {unit})"),
                min: -6.0 * LEVELS as f64,
                max: 0.0,
            }),
            ..Default::default()
        }],
    }
}
