//! Figures of a duty cycle, each with the table of exactly its data: the spectrum, the
//! wear each bin added along the profile, the dynamic factor of each bin as the flanks
//! wear, and the lives under the spectrum and at each bin alone.

use super::figures::{panel, points_panel, Curve};
use super::plot::{
    sequential_color, ColorBar, Figure, LineStyle, Marker, Panel, PanelKind, Series,
};
use crate::config::LoadSpectrumSection;
use crate::duty::contribution::{dynamic_factors, BinWear};
use crate::duty::life::LifeTable;
use crate::duty::wear::SpectrumRun;
use crate::geometry::ProfileGrid;
use crate::io::Table;

/// A figure, its file stem and the table of exactly its data.
pub struct DutyFigure {
    /// File stem.
    pub stem: String,
    /// The figure.
    pub figure: Figure,
    /// Exactly the plotted numbers.
    pub table: Table,
}

/// Most bins drawn each with its own line: 7, with the total or the rest one line more,
/// fits the 8 colours of the palette and a legend beside one panel. The table keeps
/// every bin.
pub(crate) const MAX_BIN_CURVES: usize = 7;

/// The indices of the bins drawn each with its own line: all when there are at most
/// [`MAX_BIN_CURVES`], else the [`MAX_BIN_CURVES`] of largest `weight` (the first of
/// equals), in bin order.
pub(crate) fn drawn_bins(weight: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..weight.len()).collect();
    if order.len() > MAX_BIN_CURVES {
        order.sort_by(|a, b| weight[*b].total_cmp(&weight[*a]).then(a.cmp(b)));
        order.truncate(MAX_BIN_CURVES);
        order.sort_unstable();
    }
    order
}

/// Colour of the bins drawn without their own legend entry: a light grey, apart from the
/// palette's grey.
const OTHERS_GREY: [u8; 3] = [190, 190, 190];

/// The legend name of the bins not drawn on their own.
fn others_name(n: usize) -> String {
    format!("the other {n} bins")
}

/// Share of the time of each bin: (s_i / f_i) / sum_j (s_j / f_j).
pub fn time_shares(s: &LoadSpectrumSection) -> Vec<f64> {
    let total = s.seconds_per_cycle();
    (0..s.bins.len())
        .map(|i| s.bins[i].share / s.input_speed_hz(i) / total)
        .collect()
}

/// The spectrum: the bins on the torque x speed plane coloured by their share of the
/// cycles, and the shares of cycles, time and (when a run is given) pinion wear per bin.
pub fn spectrum_figure(s: &LoadSpectrumSection, ranking: Option<&[BinWear]>) -> DutyFigure {
    let n = s.bins.len();
    let bin_no: Vec<f64> = (1..=n).map(|i| i as f64).collect();
    let torque: Vec<f64> = (0..n).map(|i| s.torque_nm(i)).collect();
    let speed: Vec<f64> = (0..n).map(|i| s.input_speed_hz(i)).collect();
    let cycles: Vec<f64> = s.bins.iter().map(|b| 100.0 * b.share).collect();
    let time: Vec<f64> = time_shares(s).iter().map(|x| 100.0 * x).collect();
    let top = cycles.iter().fold(0.0_f64, |a, b| a.max(*b)).max(1e-12);
    let plane = Panel {
        title: "bins (colour: share of the load cycles)".into(),
        x_label: "input speed (Hz)".into(),
        y_label: "torque (N m)".into(),
        series: (0..n)
            .map(|i| Series {
                x: vec![speed[i]],
                y: vec![torque[i]],
                style: LineStyle::Points,
                marker: Marker::Circle,
                color: Some(sequential_color(cycles[i] / top)),
                ..Default::default()
            })
            .collect(),
        color_bar: Some(ColorBar {
            label: "share of cycles (%)".into(),
            min: 0.0,
            max: top,
        }),
        ..Default::default()
    };
    // Stems side by side: cycles at the bin number, time and wear just right of it.
    let mut shares = vec![
        Series {
            name: "share of cycles".into(),
            x: bin_no.clone(),
            y: cycles.clone(),
            ..Default::default()
        },
        Series {
            name: "share of time".into(),
            x: bin_no.iter().map(|b| b + 0.15).collect(),
            y: time.clone(),
            ..Default::default()
        },
    ];
    let mut table = Table::new()
        .col("bin", bin_no.clone())
        .col("torque_nm", torque)
        .col("input_speed_hz", speed)
        .col("share_of_cycles_percent", cycles)
        .col("share_of_time_percent", time);
    if let Some(r) = ranking {
        let mut wear = vec![0.0; n];
        for b in r {
            wear[b.bin - 1] = 100.0 * b.share_of_pinion_wear;
        }
        shares.push(Series {
            name: "share of pinion wear".into(),
            x: bin_no.iter().map(|b| b + 0.3).collect(),
            y: wear.clone(),
            ..Default::default()
        });
        table = table.col("share_of_pinion_wear_percent", wear);
    }
    DutyFigure {
        stem: "duty_spectrum".into(),
        figure: Figure {
            title: "Load spectrum".into(),
            panels: vec![
                plane,
                Panel {
                    x_label: "bin".into(),
                    y_label: "share (%)".into(),
                    series: shares,
                    kind: PanelKind::Bars,
                    ..Default::default()
                },
            ],
        },
        table,
    }
}

/// Pinion and gear wear along the profile at the end of `run`: the total and what each
/// bin added.
pub fn wear_by_bin_figure(grid: &ProfileGrid, run: &SpectrumRun) -> Option<DutyFigure> {
    wear_by_bin_titled(grid, run, &|cycles| {
        format!(
            "Wear added by each bin of the spectrum, {} cycles ({})",
            crate::io::format_number(cycles),
            run.mode.label()
        )
    })
}

/// [`wear_by_bin_figure`] with its title from the pinion cycles of the last update.
pub(crate) fn wear_by_bin_titled(
    grid: &ProfileGrid,
    run: &SpectrumRun,
    title: &dyn Fn(f64) -> String,
) -> Option<DutyFigure> {
    let last = run.records.last()?;
    let m = run.mode.name();
    let rho: Vec<f64> = grid.rho_pinion_m.iter().map(|x| x * 1e3).collect();
    let um = |v: &[f64]| v.iter().map(|x| x * 1e6).collect::<Vec<f64>>();
    let mut table = Table::new()
        .col("rho1_mm", rho.clone())
        .col("wear_pinion_total_um", um(&last.wear.pinion_m))
        .col("wear_gear_total_um", um(&last.wear.gear_m));
    let mut panels = Vec::new();
    for (name, total, parts) in [
        ("pinion", &last.wear.pinion_m, &last.by_bin_pinion_m),
        ("gear", &last.wear.gear_m, &last.by_bin_gear_m),
    ] {
        let mut curves = vec![Curve::new("all bins", rho.clone(), um(total))];
        for (i, p) in parts.iter().enumerate() {
            table = table.col(&format!("wear_{name}_bin{}_um", i + 1), um(p));
        }
        // The bins that added the most wear (deepest), and the rest summed in one line.
        let deepest: Vec<f64> = parts
            .iter()
            .map(|p| p.iter().fold(0.0_f64, |m, x| m.max(*x)))
            .collect();
        let drawn = drawn_bins(&deepest);
        for i in &drawn {
            curves.push(Curve::new(
                format!("bin {}", i + 1),
                rho.clone(),
                um(&parts[*i]),
            ));
        }
        if drawn.len() < parts.len() {
            let mut rest = vec![0.0; rho.len()];
            for (_, p) in parts.iter().enumerate().filter(|(i, _)| !drawn.contains(i)) {
                for (r, x) in rest.iter_mut().zip(p) {
                    *r += x;
                }
            }
            let name = others_name(parts.len() - drawn.len());
            curves.push(Curve::new(name, rho.clone(), um(&rest)));
        }
        panels.push(panel(
            "pinion roll distance along the path of contact (mm)",
            &format!("{name} wear depth (µm)"),
            curves,
        ));
    }
    Some(DutyFigure {
        stem: format!("duty_wear_by_bin_{m}"),
        figure: Figure {
            title: title(last.wear.cycles),
            panels,
        },
        table,
    })
}

/// The dynamic factor (max / mean mesh force) of each bin at every update.
pub fn dynamic_factor_figure(run: &SpectrumRun) -> DutyFigure {
    let cycles = run.cycles();
    let df = dynamic_factors(run);
    let nb = df.first().map_or(0, Vec::len);
    let mut table = Table::new().col("cycles", cycles.clone());
    let mut curves = Vec::new();
    // The bins of largest share on their own; a dynamic factor does not add up, so the
    // rest are drawn thin and grey under one legend entry.
    let drawn = drawn_bins(&run.shares);
    let mut others = Vec::new();
    for i in 0..nb {
        let y: Vec<f64> = df.iter().map(|r| r[i]).collect();
        table = table.col(&format!("dynamic_factor_bin{}", i + 1), y.clone());
        if drawn.contains(&i) {
            curves.push(Curve::new(format!("bin {}", i + 1), cycles.clone(), y));
        } else {
            others.push(y);
        }
    }
    let n_others = others.len();
    let mut p = points_panel(
        "load cycles of the spectrum",
        "dynamic factor (max / mean mesh force)",
        curves,
    );
    for (k, y) in others.into_iter().enumerate() {
        p.series.push(Series {
            name: if k == 0 {
                format!("{} (grey)", others_name(n_others))
            } else {
                String::new()
            },
            x: cycles.clone(),
            y,
            color: Some(OTHERS_GREY),
            ..Default::default()
        });
    }
    DutyFigure {
        stem: format!("duty_dynamic_factor_{}", run.mode.name()),
        figure: Figure {
            title: format!(
                "Dynamic factor of each bin as the flanks wear ({})",
                run.mode.label()
            ),
            panels: vec![p],
        },
        table,
    }
}

/// Lives to the wear limit: under the spectrum, at each bin alone, and the linear mix.
pub fn life_figure(life: &LifeTable) -> DutyFigure {
    let n = life.bins.len();
    let x: Vec<f64> = (1..=n).map(|i| i as f64).collect();
    let bins: Vec<f64> = life
        .bins
        .iter()
        .map(|b| b.life.cycles().unwrap_or(f64::NAN))
        .collect();
    let spectrum = life.spectrum.cycles().unwrap_or(f64::NAN);
    let mix = life.linear_mix_cycles.unwrap_or(f64::NAN);
    let table = Table::new()
        .col("bin", x.clone())
        .col("life_at_bin_alone_cycles", bins.clone())
        .col("life_under_spectrum_cycles", vec![spectrum; n])
        .col("life_linear_mix_cycles", vec![mix; n]);
    let flat = |v: f64, name: &str, style| Series {
        name: name.into(),
        x: vec![0.5, n as f64 + 0.5],
        y: vec![v, v],
        style,
        ..Default::default()
    };
    DutyFigure {
        stem: "duty_life".into(),
        figure: Figure {
            title: format!(
                "Cycles to {} µm of pinion wear ({})",
                life.limit_um,
                life.mode.label()
            ),
            panels: vec![Panel {
                x_label: "bin".into(),
                y_label: "load cycles to the limit".into(),
                series: vec![
                    Series {
                        name: "each bin alone".into(),
                        x,
                        y: bins,
                        style: LineStyle::Points,
                        marker: Marker::Square,
                        ..Default::default()
                    },
                    flat(spectrum, "under the spectrum", LineStyle::Solid),
                    flat(mix, "linear mix of the bins", LineStyle::Dashed),
                ],
                log_y: true,
                ..Default::default()
            }],
        },
        table,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn few_bins_are_all_drawn_many_keep_the_heaviest_in_bin_order() {
        assert_eq!(drawn_bins(&[0.2, 0.5, 0.3]), vec![0, 1, 2]);
        // 25 bins with weights 25 - i, except bin 20 (index 19) the heaviest of all.
        let mut w: Vec<f64> = (0..25).map(|i| 25.0 - i as f64).collect();
        w[19] = 100.0;
        assert_eq!(drawn_bins(&w), vec![0, 1, 2, 3, 4, 5, 19]);
        // Equal weights: the first bins.
        assert_eq!(
            drawn_bins(&[1.0; 10]),
            (0..MAX_BIN_CURVES).collect::<Vec<_>>()
        );
    }

    #[test]
    fn a_25_bin_wear_figure_draws_every_entry_apart() {
        // The built-in case's profile grid, one update of 25 bins whose added wear falls
        // with the bin number: the total, the 7 deepest bins and the other 18 summed.
        let model = crate::study::Model::from_case(&crate::config::Case::default()).unwrap();
        let n = model.grid.len();
        let part = |i: usize| vec![1e-7 / (i + 1) as f64; n];
        let mut rec = crate::duty::wear::SpectrumRecord {
            wear: model.new_wear_state(),
            roughness_um: 0.4,
            bins: Vec::new(),
            by_bin_pinion_m: (0..25).map(part).collect(),
            by_bin_gear_m: (0..25).map(part).collect(),
        };
        rec.wear.cycles = 1e4;
        let mut run = SpectrumRun::new(crate::study::wear_loop::WearMode::Dynamic, vec![0.04; 25]);
        run.records.push(rec);
        let f = wear_by_bin_figure(&model.grid, &run).unwrap();
        for p in &f.figure.panels {
            let names: Vec<&str> = p.series.iter().map(|s| s.name.as_str()).collect();
            assert_eq!(names.len(), 1 + MAX_BIN_CURVES + 1, "{names:?}");
            assert_eq!(names.last(), Some(&"the other 18 bins"));
            assert!(p.indistinct_entries().is_empty(), "{names:?}");
        }
    }
}
