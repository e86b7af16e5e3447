//! Results of `gearwear stiffness` on a helical case: the slice mesh stiffness over a mesh
//! period beside the transverse section's spur pair, the centre of pressure across the
//! face, the contact ratios, the base helix angle, the virtual numbers of teeth and the
//! ISO 6336-1 Method B stiffness (docs/MODEL.md section 11).

use super::artifacts::Artifacts;
use super::figures::{panel, Curve};
use super::plot::Figure;
use super::stiffness::geometry_of_pair;
use crate::format::shown;
use crate::io::Table;
use crate::stiffness::helical::iso6336_input;
use crate::study::helical::HelicalModel;
use serde_json::json;

/// Samples over one mesh period in the CSV and plot (as the spur study's).
const SAMPLES: usize = 720;

/// Names of the columns of `mesh_stiffness.csv` for a helical pair.
const COLUMNS: [&str; 6] = [
    "pinion_angle_deg",
    "stiffness_total_n_per_m",
    "stiffness_spur_transverse_n_per_m",
    "centre_of_pressure_mm",
    "slice_contacts",
    "contact_length_mm",
];

/// The curve over one mesh period (pinion rotation from the instant pair 0 enters contact
/// at the face y = 0) and the transverse spur pair at the same phase.
fn helical_table(model: &HelicalModel) -> Table {
    let mut cols: Vec<Vec<f64>> = (0..COLUMNS.len())
        .map(|_| Vec::with_capacity(SAMPLES))
        .collect();
    for p in model.slices.table(SAMPLES) {
        let row = [
            p.phase_rad.to_degrees(),
            p.stiffness_n_per_m,
            model.spur_transverse.total_stiffness_n_per_m(p.phase_rad),
            p.centre_of_pressure_m * 1e3,
            p.slice_contacts as f64,
            p.contact_length_m * 1e3,
        ];
        for (c, v) in cols.iter_mut().zip(row) {
            c.push(v);
        }
    }
    let mut t = Table::new();
    for (n, c) in COLUMNS.iter().zip(cols) {
        t = t.col(n, c);
    }
    t
}

/// Smallest and largest value of a column.
fn extrema(c: &[f64]) -> (f64, f64) {
    c.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        })
}

/// The figure: the slice mesh stiffness and the spur transverse pair's; the centre of
/// pressure across the face.
fn helical_figure(model: &HelicalModel, t: &Table) -> Figure {
    let col = |i: usize| t.columns[i].clone();
    let x = col(0);
    let angle = "pinion angle within a mesh period (deg)";
    let pair = model.pair();
    Figure {
        title: format!(
            "Helical mesh stiffness, {} slices (beta {} deg, epsilon_beta {})",
            model.slices.slices(),
            shown(pair.helix_angle_rad.to_degrees()),
            shown(pair.overlap_ratio)
        ),
        panels: vec![
            panel(
                angle,
                "mesh stiffness (N/m)",
                vec![
                    Curve::new("helical pair (slices)", x.clone(), col(1)),
                    Curve::new("transverse section as a spur pair", x.clone(), col(2)),
                ],
            ),
            panel(
                angle,
                "centre of pressure across the face (mm)",
                vec![Curve::new("", x, col(3))],
            ),
        ],
    }
}

/// The helix numbers of `summary.json`.
fn helix_json(model: &HelicalModel) -> serde_json::Value {
    let p = model.pair();
    json!({
        "helix_angle_deg": p.helix_angle_rad.to_degrees(),
        "hand_pinion": model.case.gear.helix_hand_pinion,
        "base_helix_angle_deg": p.base_helix_angle_rad.to_degrees(),
        "transverse_module_mm": p.transverse_module_m * 1e3,
        "transverse_pressure_angle_deg": p.transverse_pressure_angle_rad.to_degrees(),
        "epsilon_alpha": p.transverse_contact_ratio,
        "epsilon_beta": p.overlap_ratio,
        "epsilon_gamma": p.total_contact_ratio,
        "virtual_teeth": p.virtual_teeth,
        "slices": model.slices.slices(),
    })
}

/// ISO 6336-1 Method B for the helical pair beside the slice model's mean.
fn iso_json(model: &HelicalModel) -> serde_json::Value {
    match iso6336_input(model.pair(), 1.0, None).evaluate() {
        Ok(iso) => {
            let b_mm = model.pair().face_width_m * 1e3;
            let c_n_per_m = iso.mesh_alpha_n_per_mm_um * b_mm * 1e6;
            json!({
                "c_prime_th_n_per_mm_um": iso.theoretical_single_n_per_mm_um,
                "c_prime_n_per_mm_um": iso.single_n_per_mm_um,
                "c_gamma_alpha_n_per_mm_um": iso.mesh_alpha_n_per_mm_um,
                "c_gamma_beta_n_per_mm_um": iso.mesh_beta_n_per_mm_um,
                "c_gamma_alpha_n_per_m": c_n_per_m,
                "virtual_teeth": iso.virtual_teeth,
                "ratio_potential_energy_mean_to_c_gamma_alpha": model.slices.mean_stiffness_n_per_m() / c_n_per_m,
                "warnings": iso.warnings,
            })
        }
        Err(e) => json!({ "error": e.to_string() }),
    }
}

/// The headline: the contact ratios, the slice stiffness and ISO's c' and c_gamma_alpha.
fn headline(model: &HelicalModel, min: f64, max: f64, iso: &serde_json::Value) -> String {
    let p = model.pair();
    let iso_text = match (
        iso["c_prime_n_per_mm_um"].as_f64(),
        iso["c_gamma_alpha_n_per_mm_um"].as_f64(),
    ) {
        (Some(c), Some(cg)) => format!(
            "; ISO 6336-1 c' {}, c_gamma_alpha {} N/(mm µm)",
            shown(c),
            shown(cg)
        ),
        _ => String::new(),
    };
    format!(
        "helical pair, beta {} deg (beta_b {} deg): epsilon_alpha {}, epsilon_beta {}, epsilon_gamma {}; mesh stiffness ({} slices) min {}, mean {}, max {} N/m{iso_text}",
        shown(p.helix_angle_rad.to_degrees()),
        shown(p.base_helix_angle_rad.to_degrees()),
        shown(p.transverse_contact_ratio),
        shown(p.overlap_ratio),
        shown(p.total_contact_ratio),
        model.slices.slices(),
        shown(min),
        shown(model.slices.mean_stiffness_n_per_m()),
        shown(max),
    )
}

/// Everything `gearwear stiffness` writes for a helical case: `summary.json` content,
/// `mesh_stiffness.csv`, `mesh_stiffness.png`.
pub fn helical_stiffness_artifacts(model: &HelicalModel) -> Artifacts {
    let table = helical_table(model);
    let (min, max) = extrema(&table.columns[1]);
    let (cop_lo, cop_hi) = extrema(&table.columns[3]);
    let spur = &model.spur_transverse;
    let iso = iso_json(model);
    let v = json!({
        "contact_ratio": model.pair().transverse_contact_ratio,
        "helical": helix_json(model),
        "mesh_stiffness": {
            "min_n_per_m": min,
            "max_n_per_m": max,
            "mean_n_per_m": model.slices.mean_stiffness_n_per_m(),
            "fillet_foundation": model.case.stiffness.fillet_foundation,
            "sampled_at": SAMPLES,
        },
        "mesh_stiffness_spur_transverse": {
            "min_n_per_m": spur.min_stiffness_n_per_m(),
            "max_n_per_m": spur.max_stiffness_n_per_m(),
            "mean_n_per_m": spur.mean_stiffness_n_per_m(),
        },
        "centre_of_pressure_mm": {
            "min": cop_lo,
            "max": cop_hi,
            "face_width": model.pair().face_width_m * 1e3,
        },
        "iso6336": iso,
        "geometry": geometry_of_pair(&model.pair().transverse),
        "warnings": model.warnings,
    });
    let mut a = Artifacts {
        headline: headline(model, min, max, &v["iso6336"]),
        summary: v,
        ..Default::default()
    };
    a.figure("mesh_stiffness.png", helical_figure(model, &table));
    if let Some(f) = a.figures.last_mut() {
        f.data = Some("mesh_stiffness.csv".into());
    }
    a.table("mesh_stiffness.csv", table);
    a
}
