//! The indicator-trend figure of a dataset (`indicator_trends.png`): the deepest pinion
//! wear and the followed condition indicators (`study::dataset::trends`) against the
//! pinion load cycles, one curve per condition at each speed and load.

use super::figures::{points_panel, Curve};
use super::plot::Figure;
use crate::study::dataset::trends::{TrendLine, Trends};

/// Axis label of an index column (`unit`: the channel unit of the dataset).
fn label(column: &str, channel: &str, unit: &str) -> String {
    let short = column
        .strip_prefix(&format!("{channel}_"))
        .unwrap_or(column);
    match short {
        "max_wear_pinion_um" => "max. pinion wear (µm)".into(),
        "max_wear_gear_um" => "max. gear wear (µm)".into(),
        "rms" => format!("RMS ({unit})"),
        "kurtosis" => "kurtosis".into(),
        "pinion_fm0" => "FM0, pinion TSA".into(),
        "pinion_fm4" => "FM4, pinion TSA".into(),
        "pinion_na4" => "NA4, pinion TSA".into(),
        "pinion_sideband_level_factor" => "SLF, pinion TSA".into(),
        other => other.into(),
    }
}

/// The figure of `t` (every column of its lines except the gear's wear).
pub fn trend_figure(t: &Trends, unit: &str) -> Figure {
    let many_points = |f: fn(&TrendLine) -> u64| {
        t.lines
            .iter()
            .map(f)
            .collect::<std::collections::BTreeSet<_>>()
            .len()
            > 1
    };
    let speeds = many_points(|l| l.input_speed_hz.to_bits());
    let loads = many_points(|l| l.load_torque_nm.to_bits());
    let name = |l: &TrendLine| {
        let mut s = l.condition.clone();
        if speeds {
            s.push_str(&format!(", {} Hz", crate::format::shown(l.input_speed_hz)));
        }
        if loads {
            s.push_str(&format!(", {} N m", crate::format::shown(l.load_torque_nm)));
        }
        s
    };
    let columns: Vec<String> = t.lines.first().map_or(Vec::new(), |l| {
        l.values.iter().map(|(n, _)| n.clone()).collect()
    });
    let panels = columns
        .iter()
        .enumerate()
        .filter(|(_, c)| c.as_str() != "max_wear_gear_um")
        .map(|(k, c)| {
            let curves = t
                .lines
                .iter()
                .map(|l| Curve::new(name(l), l.cycles.clone(), l.values[k].1.clone()))
                .collect();
            points_panel("pinion load cycles", &label(c, &t.channel, unit), curves)
        })
        .collect();
    Figure {
        title: format!(
            "Indicator trends to failure: channel {}, mean over the noise realisations",
            t.channel
        ),
        panels,
    }
}
