//! Tables, JSON lists and embedded figures of `gearwear calibrate` and `gearwear predict`,
//! shared by both commands. Pure: results in, `Table`s, JSON and rendered figures out.

use super::artifacts::{embed_figure, Artifacts};
use super::html::{FigureBlock, TableBlock};
use super::plot::Figure;
use crate::io::Table;
use crate::prognostics::band::Band;
use crate::prognostics::fit_check::FitCheck;
use crate::prognostics::prior::Theta;
use crate::prognostics::quantity::Quantity;
use serde_json::{json, Value};

/// Failed parameter sets listed in summary.json (all are counted).
pub const LISTED_FAILURES: usize = 100;

/// The posterior samples CSV: `sample` and every parameter (fixed ones included), the
/// format `prognostics::samples::read_samples` reads.
pub fn samples_table(samples: &[Theta]) -> Table {
    let mut t = Table::new().col("sample", (0..samples.len()).map(|i| i as f64).collect());
    for (i, p) in crate::prognostics::prior::PARAMETERS.iter().enumerate() {
        t = t.col(p.column(), samples.iter().map(|s| s[i]).collect());
    }
    t
}

/// Bands as one CSV: cycles, then `<quantity>_p05` ... `_p95` per quantity.
pub fn bands_table(bands: &[(Quantity, Band)]) -> Table {
    let mut t = Table::new().col(
        "cycles",
        bands.first().map_or_else(Vec::new, |b| b.1.cycles.clone()),
    );
    for (q, b) in bands {
        for (i, p) in ["p05", "p25", "p50", "p75", "p95"].iter().enumerate() {
            t = t.col(&format!("{}_{p}", q.name()), b.percentiles[i].clone());
        }
        t = t.col(
            &format!("{}_members_with_value", q.name()),
            b.valid.iter().map(|v| *v as f64).collect(),
        );
    }
    t
}

/// The fit check as a report paragraph (its verdict and rule) and table (a row per
/// observed quantity).
pub fn fit_check_block(c: &FitCheck) -> (String, TableBlock) {
    let verdict = match &c.warning {
        Some(w) => format!("Warning: {w}."),
        None => "The observations are consistent with the calibrated model.".into(),
    };
    let text = format!(
        "Fit check: {} of {} observations lie outside the central {:.0} % posterior predictive band (model over the posterior samples plus the noise), {:.1} expected; the furthest lies {:.2} noise sigma beyond it. The check warns above {} outside or beyond {:.2} sigma (each rule a false alarm with probability < {} for data the model generated; docs/PROGNOSTICS.md). {verdict}",
        c.outside,
        c.observations,
        100.0 * c.coverage,
        c.expected_outside,
        c.largest_excess_sigma,
        c.max_outside_without_warning,
        c.excess_limit_sigma,
        c.false_alarm_probability_per_rule,
    );
    let rows = c
        .quantities
        .iter()
        .map(|q| {
            let (at, band, ex) = match &q.worst {
                Some(w) => (
                    format!(
                        "{} at {:e} cycles",
                        crate::io::format_number(w.observed),
                        w.cycles
                    ),
                    format!("[{:.4}, {:.4}]", w.band[0], w.band[1]),
                    format!("{:.2} sigma ({:.4})", w.excess_sigma, w.excess),
                ),
                None => ("-".into(), "-".into(), "0".into()),
            };
            vec![
                q.quantity.clone(),
                q.noise.to_string(),
                q.observations.to_string(),
                q.outside.to_string(),
                at,
                band,
                ex,
            ]
        })
        .collect();
    let table = TableBlock {
        caption: "Fit check: observations against the central posterior predictive band, per quantity (the furthest outside, its band, and how far beyond it)".into(),
        header: [
            "quantity",
            "noise",
            "observations",
            "outside",
            "furthest outside",
            "band there",
            "beyond the band",
        ]
        .map(String::from)
        .to_vec(),
        rows,
        highlight_col: Some(3),
    };
    (text, table)
}

/// Parameter sets as JSON objects (at most [`LISTED_FAILURES`] of them).
pub fn thetas_json(t: &[Theta]) -> Value {
    json!(t
        .iter()
        .take(LISTED_FAILURES)
        .map(|x| json!({"wear_coefficient_m2_per_n": x[0], "roughness_scale": x[1], "load_torque_nm": x[2]}))
        .collect::<Vec<_>>())
}

/// The figure `fig` added to `art` as `name` (`NAME.png`, and/or `NAME.svg` as the job
/// asks) and returned as a report figure (the same bytes). Default size: 900 px wide,
/// 260 px a panel plus a 60 px title band.
pub fn figure(
    art: &mut Artifacts,
    name: &str,
    fig: &Figure,
    caption: &str,
    csv: Option<&str>,
) -> anyhow::Result<FigureBlock> {
    let h = (60 + 260 * fig.panels.len().max(1)) as u32;
    Ok(embed_figure(
        art,
        name,
        fig.clone(),
        (900, h),
        caption,
        csv,
    )?)
}
