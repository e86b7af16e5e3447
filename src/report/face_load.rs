//! The face load distribution in `gearwear stiffness` (docs/MODEL.md 11.2):
//! `face_load.csv` (per slice: its position, gap, and the load per unit face width
//! averaged over a mesh period, its largest and smallest value), `face_load.png` and the
//! summary's `face_load` (K_Hbeta, the centre of pressure); and in `gearwear dynamics` on a
//! helical pair with lead gaps the same over the steady state (`study::face_load_dynamic`)
//! with the tilting moment and the static solve beside it.

use super::artifacts::Artifacts;
use super::figures::{panel, Curve};
use super::plot::Figure;
use crate::format::shown;
use crate::io::Table;
use crate::stiffness::face_load::FaceLoad;
use crate::study::face_load::CaseFaceLoad;
use crate::study::face_load_dynamic::DynamicFaceLoad;
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
    static_face_load_json(&c.load)
}

/// [`face_load_json`] of a solved distribution.
fn static_face_load_json(f: &FaceLoad) -> serde_json::Value {
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

/// Names of the columns of `face_load.csv` in `gearwear dynamics`.
const DYNAMIC_COLUMNS: [&str; 5] = [
    "face_position_mm",
    "gap_um",
    "load_per_width_mean_n_per_mm",
    "load_per_width_max_n_per_mm",
    "load_per_width_static_mean_n_per_mm",
];

/// The dynamic face load table: one row per slice, the time mean and largest load per
/// unit face width over the steady state beside the static solve's period mean, N/mm.
pub fn dynamic_face_load_table(d: &DynamicFaceLoad, s: &FaceLoad) -> Table {
    let per_mm = |v: &[f64]| v.iter().map(|w| w * 1e-3).collect::<Vec<f64>>();
    let cols = [
        d.positions_m.iter().map(|y| y * 1e3).collect(),
        d.gaps_m.iter().map(|g| g * 1e6).collect(),
        per_mm(&d.mean_n_per_m),
        per_mm(&d.max_n_per_m),
        per_mm(&s.period_mean_n_per_m()),
    ];
    let mut t = Table::new();
    for (n, col) in DYNAMIC_COLUMNS.iter().zip(cols) {
        t = t.col(n, col);
    }
    t
}

/// The dynamics summary's `face_load`: the dynamic K_Hbeta, centre of pressure and tilting
/// moment beside the static solve's (docs/MODEL.md 11.1).
pub fn dynamic_face_load_json(d: &DynamicFaceLoad, s: &FaceLoad) -> serde_json::Value {
    let (m_mean, m_lo, m_hi) = d.tilting_moment_nm();
    json!({
        "k_h_beta": d.k_h_beta(),
        "k_h_beta_of": "the load per unit face width averaged over the steady state (ISO 6336-1: peak over mean)",
        "k_h_beta_instantaneous_max": d.k_h_beta_instantaneous_max(),
        "centre_of_pressure_mm": d.centre_of_pressure_m() * 1e3,
        "face_width_mm": d.face_width_m * 1e3,
        "mean_load_per_width_n_per_mm": d.mean_load_per_width_n_per_m() * 1e-3,
        "tilting_moment_nm": {
            "mean": m_mean,
            "min": m_lo,
            "max": m_hi,
            "definition": "sum over slices of F_j (y_j - b/2) about the face centre, y along the pinion's angular velocity (+: load towards y = b); it tilts the gear about z x d (d the transverse line of action, z the pinion's axis), the pinion the opposite way",
        },
        "gap_max_um": d.gaps_m.iter().fold(0.0_f64, |a, g| a.max(*g)) * 1e6,
        "slices": d.positions_m.len(),
        "static": static_face_load_json(s),
    })
}

/// The figure of the dynamic face load: time mean and largest load per unit face width
/// over the steady state, the static period mean, and the gap.
fn dynamic_face_load_figure(d: &DynamicFaceLoad, t: &Table) -> Figure {
    let col = |i: usize| t.columns[i].clone();
    let x = col(0);
    let face = "position across the face (mm)";
    Figure {
        title: format!(
            "Dynamic face load: K_Hbeta {}, centre of pressure {} mm of {} mm",
            shown(d.k_h_beta()),
            shown(d.centre_of_pressure_m() * 1e3),
            shown(d.face_width_m * 1e3)
        ),
        panels: vec![
            panel(
                face,
                "load per unit face width (N/mm)",
                vec![
                    Curve::new("time mean, dynamic", x.clone(), col(2)),
                    Curve::new("largest, dynamic", x.clone(), col(3)),
                    Curve::new("period mean, static", x.clone(), col(4)),
                ],
            ),
            panel(face, "gap (µm)", vec![Curve::new("", x, col(1))]),
        ],
    }
}

/// Add the dynamic face load to `gearwear dynamics`' artifacts: `face_load.csv`,
/// `face_load.png` and the summary's `face_load`.
pub fn add_dynamic_face_load_artifacts(d: &DynamicFaceLoad, s: &FaceLoad, a: &mut Artifacts) {
    let t = dynamic_face_load_table(d, s);
    a.summary["face_load"] = dynamic_face_load_json(d, s);
    a.headline.push_str(&format!(
        "; dynamic face load K_Hbeta {} (centre of pressure {} mm)",
        shown(d.k_h_beta()),
        shown(d.centre_of_pressure_m() * 1e3)
    ));
    a.figure("face_load.png", dynamic_face_load_figure(d, &t));
    if let Some(f) = a.figures.last_mut() {
        f.data = Some("face_load.csv".into());
    }
    a.table("face_load.csv", t);
}
