//! Figures and report sections of `gearwear calibrate` and `gearwear predict`. Pure:
//! results in, `Figure`s and `Section`s out.

use super::html::{format_value, FigureBlock, Section, TableBlock};
use super::plot::{Figure, LineStyle, Panel, PanelKind, Series};
use crate::prognostics::band::Band;
use crate::prognostics::calibrate::{Calibration, Method};
use crate::prognostics::observations::Observations;
use crate::prognostics::predict::LifeSummary;
use crate::prognostics::prior::Parameter;
use crate::prognostics::quantity::Quantity;

fn series(name: &str, x: Vec<f64>, y: Vec<f64>, style: LineStyle) -> Series {
    Series {
        name: name.into(),
        x,
        y,
        style,
        ..Default::default()
    }
}

/// The plotting coordinate's label of a parameter.
fn axis_label(p: Parameter) -> String {
    match p {
        Parameter::WearCoefficient => "log10 of the wear coefficient k (m^2/N)".into(),
        p => p.label().into(),
    }
}

/// Marginal posterior densities against the (uniform) prior, one panel per parameter.
pub fn posterior_figure(cal: &Calibration) -> Figure {
    let panels = cal
        .densities
        .iter()
        .map(|d| {
            let (x0, x1) = (
                d.x.first().copied().unwrap_or(0.0),
                d.x.last().copied().unwrap_or(1.0),
            );
            Panel {
                x_label: axis_label(d.parameter),
                y_label: "density".into(),
                series: vec![
                    series(
                        "posterior",
                        d.x.clone(),
                        d.density.clone(),
                        LineStyle::Solid,
                    ),
                    series(
                        "prior",
                        vec![x0, x1],
                        vec![d.prior_density; 2],
                        LineStyle::Dashed,
                    ),
                ],
                ..Default::default()
            }
        })
        .collect();
    Figure {
        title: "Posterior of the uncertain parameters".into(),
        panels,
    }
}

/// The outline of a band as one closed line: along the lower edge, back along the upper
/// (one series, so one colour for both edges).
fn outline(x: &[f64], lower: &[f64], upper: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let xs = x.iter().chain(x.iter().rev()).copied().collect();
    let ys = lower.iter().chain(upper.iter().rev()).copied().collect();
    (xs, ys)
}

/// A band panel: the median, and the 50 % (25-75 %) and 90 % (5-95 %) bands as outlines.
pub fn band_panel(q: Quantity, b: &Band, x_scale: f64, x_label: &str) -> Panel {
    let x: Vec<f64> = b.cycles.iter().map(|c| c / x_scale).collect();
    let p = &b.percentiles;
    let (x50, y50) = outline(&x, &p[1], &p[3]);
    let (x90, y90) = outline(&x, &p[0], &p[4]);
    Panel {
        x_label: x_label.into(),
        y_label: q.label(),
        series: vec![
            series("median", x.clone(), p[2].clone(), LineStyle::Solid),
            series("50 % band", x50, y50, LineStyle::Dashed),
            series("90 % band", x90, y90, LineStyle::Dotted),
        ],
        ..Default::default()
    }
}

/// Cycle axis in thousands when the horizon is large.
pub fn cycle_axis(max_cycles: f64) -> (f64, &'static str) {
    if max_cycles >= 1e4 {
        (1e3, "cycles (thousands)")
    } else {
        (1.0, "cycles")
    }
}

/// Observations against the posterior band of the model, one panel per quantity.
pub fn predictive_figure(obs: &Observations, bands: &[(Quantity, Band)]) -> Figure {
    let max = bands
        .iter()
        .flat_map(|b| b.1.cycles.last().copied())
        .fold(0.0, f64::max);
    let (scale, label) = cycle_axis(max);
    let panels = bands
        .iter()
        .map(|(q, b)| {
            let mut p = band_panel(*q, b, scale, label);
            if let Some(s) = obs.series.iter().find(|s| s.quantity == *q) {
                p.series.push(series(
                    "observed",
                    s.cycles.iter().map(|c| c / scale).collect(),
                    s.values.clone(),
                    LineStyle::Points,
                ));
            }
            p
        })
        .collect();
    Figure {
        title: "Observations and the model's posterior band (median, 50 %, 90 %)".into(),
        panels,
    }
}

/// Fan charts of `bands`; a horizontal line at `limit_um` on the wear panel.
pub fn fan_figure(title: &str, bands: &[(Quantity, Band)], limit_um: Option<f64>) -> Figure {
    let max = bands
        .iter()
        .flat_map(|b| b.1.cycles.last().copied())
        .fold(0.0, f64::max);
    let (scale, label) = cycle_axis(max);
    let panels = bands
        .iter()
        .map(|(q, b)| {
            let mut p = band_panel(*q, b, scale, label);
            if let (Some(l), true) = (limit_um, *q == Quantity::MaxWearPinion) {
                p.series.push(series(
                    "wear limit",
                    vec![0.0, max / scale],
                    vec![l, l],
                    LineStyle::Dashed,
                ));
            }
            p
        })
        .collect();
    Figure {
        title: title.into(),
        panels,
    }
}

/// Lives spanning at least this ratio (largest / smallest) are binned on a log scale:
/// equal linear bins would put most samples of a skewed spread into the first bin.
const LOG_LIFE_RATIO: f64 = 10.0;

/// Bins of the histogram of `lives`: 40 equal bins over [smallest, largest] life, on
/// log10(cycles) when the lives span `LOG_LIFE_RATIO` or more. Returns the bin centres
/// in axis units, the count per bin, and whether the axis is log10.
pub fn life_bins(lives: &[f64]) -> (Vec<f64>, Vec<f64>, bool) {
    let bins = 40;
    let ok: Vec<f64> = lives
        .iter()
        .copied()
        .filter(|l| l.is_finite() && *l > 0.0)
        .collect();
    let (lo, hi) = ok
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(a, b), l| (a.min(*l), b.max(*l)));
    if ok.is_empty() {
        return (Vec::new(), Vec::new(), false);
    }
    let log = hi / lo >= LOG_LIFE_RATIO;
    let to_axis = |l: f64| if log { l.log10() } else { l };
    let (a, b) = (to_axis(lo), to_axis(hi));
    // A single value (or all equal): one bin of 1 % of the value around it.
    let w = if b > a {
        (b - a) / bins as f64
    } else {
        0.01 * a.abs().max(1.0)
    };
    let n = if b > a { bins } else { 1 };
    let start = if b > a { a } else { a - 0.5 * w };
    let mut counts = vec![0.0; n];
    for l in &ok {
        counts[(((to_axis(*l) - start) / w) as usize).min(n - 1)] += 1.0;
    }
    let centres = (0..n).map(|k| start + (k as f64 + 0.5) * w).collect();
    (centres, counts, log)
}

/// Histogram of the cycles to the wear limit (samples that reach it), with the 5 %,
/// median and 95 % marked. The axis spans the lives that occur (not from 0): cycles
/// (thousands above 1e4), or log10 of the cycles when they span a decade or more.
pub fn life_figure(lives: &[f64], life: &LifeSummary, horizon: f64) -> Figure {
    let (centres, counts, log) = life_bins(lives);
    let (scale, label) = cycle_axis(horizon);
    let (to_axis, label): (Box<dyn Fn(f64) -> f64>, String) = if log {
        (
            Box::new(f64::log10),
            "log10 of the cycles to the limit".into(),
        )
    } else {
        (Box::new(move |c| c / scale), label.into())
    };
    let x: Vec<f64> = centres
        .iter()
        .map(|c| if log { *c } else { c / scale })
        .collect();
    let n = life.samples.max(1) as f64;
    let mut vlines = Vec::new();
    for (v, name) in [
        (life.p05, "5 %"),
        (life.median, "median"),
        (life.p95, "95 %"),
    ] {
        if let Some(v) = v.filter(|v| *v > 0.0) {
            vlines.push((to_axis(v), name.to_string()));
        }
    }
    Figure {
        title: format!(
            "Cycles to the wear limit ({} of {} samples reach it within the horizon)",
            life.reached, life.samples
        ),
        panels: vec![Panel {
            x_label: label,
            y_label: "fraction of samples per bin".into(),
            series: vec![series(
                "",
                x,
                counts.iter().map(|c| c / n).collect(),
                LineStyle::Solid,
            )],
            vlines,
            kind: PanelKind::Bars,
            ..Default::default()
        }],
    }
}

fn cycles_text(c: Option<f64>, horizon: f64) -> String {
    c.map_or_else(|| format!("> {}", format_value(horizon)), format_value)
}

/// Table of the posterior summary.
pub fn posterior_table(cal: &Calibration) -> TableBlock {
    TableBlock {
        caption: "Posterior: median and 90 % credible interval per parameter".into(),
        header: ["parameter", "median", "5 %", "95 %", "ESS", "R-hat"]
            .map(String::from)
            .to_vec(),
        rows: cal
            .summary
            .iter()
            .map(|s| {
                vec![
                    s.parameter.label().into(),
                    format_value(s.median),
                    format_value(s.ci05),
                    format_value(s.ci95),
                    format!("{:.0}", s.ess),
                    s.rhat.map_or("-".into(), |r| format!("{r:.3}")),
                ]
            })
            .collect(),
        highlight_col: None,
    }
}

/// The report section of a calibration.
pub fn calibration_section(
    cal: &Calibration,
    notes: Vec<String>,
    figures: Vec<FigureBlock>,
) -> Section {
    let method = match cal.method {
        Method::Grid => "exact posterior on a refined grid (independent draws)",
        Method::EnsembleMcmc => "affine-invariant ensemble MCMC (Goodman & Weare 2010)",
    };
    let mut paragraphs = vec![format!(
        "Posterior of {} parameter(s), {method}; {} samples.",
        cal.summary.len(),
        cal.samples.len()
    )];
    paragraphs.extend(notes);
    Section {
        heading: "Calibration".into(),
        paragraphs,
        figures,
        tables: vec![posterior_table(cal)],
    }
}

/// The report section of a prediction.
pub fn prediction_section(
    life: &LifeSummary,
    limit_um: f64,
    horizon: f64,
    notes: Vec<String>,
    figures: Vec<FigureBlock>,
) -> Section {
    let mut paragraphs = vec![format!(
        "Cycles until the maximum pinion wear reaches {limit_um} µm: median {}, 90 % interval {} to {}; probability that it lies beyond {} cycles: {:.3}.",
        cycles_text(life.median, horizon),
        cycles_text(life.p05, horizon),
        cycles_text(life.p95, horizon),
        format_value(horizon),
        life.prob_beyond_horizon
    )];
    paragraphs.extend(notes);
    let row = |k: &str, v: String| vec![k.to_string(), v];
    Section {
        heading: "Wear and remaining-life prediction".into(),
        paragraphs,
        figures,
        tables: vec![TableBlock {
            caption: "Remaining useful life (cycles to the wear limit)".into(),
            header: vec!["quantity".into(), "value".into()],
            rows: vec![
                row("samples", life.samples.to_string()),
                row(
                    "reach the limit within the horizon",
                    life.reached.to_string(),
                ),
                row("stay below it", life.beyond_horizon.to_string()),
                row(
                    "forward run failed first (life unknown)",
                    life.unknown.to_string(),
                ),
                row("5 % (cycles)", cycles_text(life.p05, horizon)),
                row("median (cycles)", cycles_text(life.median, horizon)),
                row("95 % (cycles)", cycles_text(life.p95, horizon)),
                row(
                    "P(life > horizon)",
                    format!("{:.4}", life.prob_beyond_horizon),
                ),
            ],
            highlight_col: None,
        }],
    }
}
