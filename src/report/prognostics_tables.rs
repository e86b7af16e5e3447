//! Tables, JSON lists and embedded figures of `gearwear calibrate` and `gearwear predict`,
//! shared by both commands. Pure: results in, `Table`s, JSON and PNG bytes out.

use super::artifacts::Artifacts;
use super::html::FigureBlock;
use super::plot::{render_png, Figure};
use crate::io::Table;
use crate::prognostics::band::Band;
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

/// Parameter sets as JSON objects (at most [`LISTED_FAILURES`] of them).
pub fn thetas_json(t: &[Theta]) -> Value {
    json!(t
        .iter()
        .take(LISTED_FAILURES)
        .map(|x| json!({"wear_coefficient_m2_per_n": x[0], "roughness_scale": x[1], "load_torque_nm": x[2]}))
        .collect::<Vec<_>>())
}

/// A multi-panel figure as PNG bytes (260 px per panel).
fn png(fig: &Figure) -> anyhow::Result<Vec<u8>> {
    let h = (60 + 260 * fig.panels.len().max(1)) as u32;
    Ok(render_png(fig, 900, h)?)
}

/// The PNG staged as `name` in `art` and returned as a report figure (the same bytes).
pub fn figure(
    art: &mut Artifacts,
    name: &str,
    fig: &Figure,
    caption: &str,
    csv: Option<&str>,
) -> anyhow::Result<FigureBlock> {
    let bytes = png(fig)?;
    art.documents.push((name.to_string(), bytes.clone()));
    Ok(FigureBlock {
        caption: caption.into(),
        png: bytes,
        csv_name: csv.map(String::from),
    })
}
