//! The face load distribution in `gearwear stiffness` (docs/MODEL.md 11.2):
//! `face_load.csv` (per slice: its position, gap, and the load per unit face width
//! averaged over a mesh period, its largest and smallest value), `face_load.png` and the
//! summary's `face_load` (K_Hbeta, the centre of pressure).

use super::artifacts::Artifacts;
use super::figures::{panel, Curve};
use super::plot::Figure;
use crate::format::shown;
use crate::io::Table;
use crate::study::face_load::CaseFaceLoad;
use serde_json::json;

/// Names of the columns of `face_load.csv`.
const COLUMNS: [&str; 5] = [
    "face_position_mm",
    "gap_um",
    "load_per_width_mean_n_per_mm",
    "load_per_width_max_n_per_mm",
    "load_per_width_min_n_per_mm",
];

/// Smallest load per unit face width at each slice over the mesh positions, N/m.
fn lowest(c: &CaseFaceLoad) -> Vec<f64> {
    let mut lo = vec![f64::INFINITY; c.load.positions_m.len()];
    for p in &c.load.positions {
        for (a, w) in lo.iter_mut().zip(&p.load_per_width_n_per_m) {
            *a = a.min(*w);
        }
    }
    lo
}

/// The table: one row per slice; loads per unit face width in N/mm.
pub fn face_load_table(c: &CaseFaceLoad) -> Table {
    let per_mm = |v: Vec<f64>| v.iter().map(|w| w * 1e-3).collect::<Vec<f64>>();
    let cols = [
        c.load.positions_m.iter().map(|y| y * 1e3).collect(),
        c.load.gaps_m.iter().map(|g| g * 1e6).collect(),
        per_mm(c.load.period_mean_n_per_m()),
        per_mm(c.load.envelope_n_per_m()),
        per_mm(lowest(c)),
    ];
    let mut t = Table::new();
    for (n, col) in COLUMNS.iter().zip(cols) {
        t = t.col(n, col);
    }
    t
}

/// The summary's `face_load`.
pub fn face_load_json(c: &CaseFaceLoad) -> serde_json::Value {
    let f = &c.load;
    let centres: Vec<f64> = f
        .positions
        .iter()
        .map(|p| f.centre_of(&p.load_per_width_n_per_m) * 1e3)
        .collect();
    let range = |v: &[f64]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            })
    };
    let (c_lo, c_hi) = range(&centres);
    let approach: Vec<f64> = f.positions.iter().map(|p| p.approach_m * 1e6).collect();
    let (a_lo, a_hi) = range(&approach);
    json!({
        "k_h_beta": f.k_h_beta(),
        "k_h_beta_of": "the load per unit face width averaged over a mesh period (ISO 6336-1: peak over mean)",
        "k_h_beta_instantaneous_max": f.k_h_beta_instantaneous_max(),
        "centre_of_pressure_mm": f.centre_of_pressure_m() * 1e3,
        "centre_of_pressure_over_period_mm": { "min": c_lo, "max": c_hi },
        "face_width_mm": f.face_width_m * 1e3,
        "mean_load_per_width_n_per_mm": f.mean_load_per_width_n_per_m() * 1e-3,
        "mesh_force_n": f.force_n,
        "approach_um": { "min": a_lo, "max": a_hi },
        "gap_max_um": f.gaps_m.iter().fold(0.0_f64, |a, g| a.max(*g)) * 1e6,
        "fewest_loaded_slices": f.fewest_loaded_slices(),
        "slices": f.positions_m.len(),
        "mesh_positions": f.positions.len(),
    })
}

/// The figure: the load per unit face width across the face (period mean, largest,
/// smallest) and the gap.
pub fn face_load_figure(c: &CaseFaceLoad, t: &Table) -> Figure {
    let col = |i: usize| t.columns[i].clone();
    let x = col(0);
    let face = "position across the face (mm)";
    Figure {
        title: format!(
            "Face load distribution: K_Hbeta {}, centre of pressure {} mm of {} mm",
            shown(c.load.k_h_beta()),
            shown(c.load.centre_of_pressure_m() * 1e3),
            shown(c.load.face_width_m * 1e3)
        ),
        panels: vec![
            panel(
                face,
                "load per unit face width (N/mm)",
                vec![
                    Curve::new("mean over a mesh period", x.clone(), col(2)),
                    Curve::new("largest", x.clone(), col(3)),
                    Curve::new("smallest", x.clone(), col(4)),
                ],
            ),
            panel(face, "gap (µm)", vec![Curve::new("", x, col(1))]),
        ],
    }
}

/// Add `face_load.csv`, `face_load.png`, the summary's `face_load` and the warnings.
pub fn add_face_load_artifacts(c: &CaseFaceLoad, a: &mut Artifacts) {
    let t = face_load_table(c);
    a.summary["face_load"] = face_load_json(c);
    if !c.warnings.is_empty() {
        if let Some(w) = a.summary["warnings"].as_array_mut() {
            w.extend(c.warnings.iter().map(|s| json!(s)));
        }
    }
    a.headline.push_str(&format!(
        "; face load K_Hbeta {} (centre of pressure {} mm)",
        shown(c.load.k_h_beta()),
        shown(c.load.centre_of_pressure_m() * 1e3)
    ));
    a.figure("face_load.png", face_load_figure(c, &t));
    if let Some(f) = a.figures.last_mut() {
        f.data = Some("face_load.csv".into());
    }
    a.table("face_load.csv", t);
}
