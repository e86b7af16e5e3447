//! Results of the mesh-stiffness study (`gearwear stiffness`, Fig. 2 of `run`): the mesh
//! stiffness over a mesh period, load sharing, the quasi-static transmission error, the
//! ISO 6336 cross-check, the pair's geometry.

use super::artifacts::Artifacts;
use super::figures::{panel, Curve};
use super::plot::{Figure, Panel};
use crate::contact::load_sharing::pedrero_shares;
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::quasi_static::equilibrium;
use crate::format::shown;
use crate::io::Table;
use crate::stiffness::iso6336::Iso6336Input;
use crate::stiffness::mesh::MeshStiffness;
use crate::study::Model;
use serde_json::json;

/// Samples over one mesh period in the CSV and plot.
const SAMPLES: usize = 720;

/// Columns of `mesh_stiffness.csv` over one mesh period and the summary numbers. The
/// pairs are those on the path of contact (pair 0 the one that entered last); with
/// `contact.path` = "extended" two columns more give the stiffness of the pairs that
/// touch in the quasi-static equilibrium under the case's load (corners beyond the path
/// included) and the corners' share of the load.
pub fn stiffness_table(model: &Model) -> (Table, serde_json::Value) {
    let pair = &model.pair;
    let gap = PairGap::none();
    let ext = ExternalError::none();
    let sys = model.system(&gap, &ext, model.roughness.rms_um(0.0));
    let extended = model.contact.is_extended();
    let n_cols = if extended { 14 } else { 12 };
    let mut cols: Vec<Vec<f64>> = (0..n_cols).map(|_| Vec::with_capacity(SAMPLES)).collect();
    for i in 0..SAMPLES {
        let phase = pair.mesh_angle_rad() * i as f64 / SAMPLES as f64;
        let eq = equilibrium(&sys, 0, phase);
        let mut on_path = (0..eq.n_pairs).filter(|j| !eq.corner[*j]);
        let idx: [Option<usize>; 4] = std::array::from_fn(|_| on_path.next());
        let n = idx.iter().flatten().count();
        let pick = |a: &[f64; 4]| -> [f64; 4] { idx.map(|i| i.map_or(0.0, |i| a[i])) };
        let (rho, k) = (pick(&eq.rho1_m), pick(&eq.stiffness_n_per_m));
        let total: f64 = k[..n].iter().sum();
        let get = |a: &[f64; 4], j: usize| if j < n { a[j] } else { f64::NAN };
        let mut shares = [0.0; 4];
        pedrero_shares(pair, &rho[..n], &mut shares[..n]);
        let by_k = |j: usize| if j < n { k[j] / total } else { 0.0 };
        let row = [
            phase.to_degrees(),
            get(&rho, 0) * 1e3,
            get(&rho, 1) * 1e3,
            get(&k, 0),
            get(&k, 1),
            total,
            shares[0],
            shares[1],
            by_k(0),
            by_k(1),
            eq.deflection_m * 1e6,
            eq.force_n,
            eq.stiffness_total_n_per_m,
            (0..eq.n_pairs)
                .filter(|j| eq.corner[*j])
                .map(|j| eq.load_n[j])
                .sum::<f64>()
                / eq.force_n,
        ];
        for (c, v) in cols.iter_mut().zip(row) {
            c.push(v);
        }
    }
    let names = [
        "pinion_angle_deg",
        "rho1_pair0_mm",
        "rho1_pair1_mm",
        "stiffness_pair0_n_per_m",
        "stiffness_pair1_n_per_m",
        "stiffness_total_n_per_m",
        "load_share_pedrero_pair0",
        "load_share_pedrero_pair1",
        "load_share_stiffness_pair0",
        "load_share_stiffness_pair1",
        "quasi_static_te_um",
        "quasi_static_mesh_force_n",
        "stiffness_loaded_n_per_m",
        "load_share_corners",
    ];
    let mut t = Table::new();
    for (n, c) in names.iter().zip(cols.iter()) {
        t = t.col(n, c.clone());
    }
    let mesh = &model.mesh;
    let range = |c: &[f64]| {
        (
            c.iter().fold(f64::INFINITY, |a, b| a.min(*b)),
            c.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b)),
        )
    };
    let (te_min, te_max) = range(&cols[10]);
    let mut v = json!({
        "contact_ratio": pair.contact_ratio,
        "mesh_stiffness": {
            "min_n_per_m": mesh.min_stiffness_n_per_m(),
            "max_n_per_m": mesh.max_stiffness_n_per_m(),
            "mean_n_per_m": mesh.mean_stiffness_n_per_m(),
            "fillet_foundation": model.case.stiffness.fillet_foundation,
        },
        "quasi_static_te": {
            "min_um": te_min,
            "max_um": te_max,
        },
    });
    if extended {
        let (lo, hi) = range(&cols[12]);
        v["mesh_stiffness"]["loaded_min_n_per_m"] = json!(lo);
        v["mesh_stiffness"]["loaded_max_n_per_m"] = json!(hi);
        v["corner_load_share_max"] = json!(range(&cols[13]).1);
        // The mean the modes and the period search's start take (docs/MODEL.md 4.2).
        v["mesh_stiffness"]["loaded_mean_n_per_m"] =
            json!(crate::dynamics::quasi_static::loaded_mean_stiffnesses(&sys)[0]);
    }
    (t, v)
}

/// The paper's Figure 2: single-pair and total mesh stiffness over one mesh period, and
/// the quasi-static transmission error, drawn from the columns of `t` (`stiffness_table`).
pub fn figure2(model: &Model, t: &Table) -> Figure {
    let col = |name: &str| {
        t.index_of(name)
            .map(|i| t.columns[i].clone())
            .unwrap_or_default()
    };
    let x = col("pinion_angle_deg");
    let angle = "pinion angle within a mesh period (deg)";
    let source = if model.case.stiffness.fillet_foundation {
        "potential energy method with fillet foundation"
    } else {
        "potential energy method"
    };
    Figure {
        title: format!("Time-varying mesh stiffness ({source})"),
        panels: vec![
            panel(
                angle,
                "mesh stiffness (N/m)",
                vec![
                    Curve::new(
                        "all pairs in contact",
                        x.clone(),
                        col("stiffness_total_n_per_m"),
                    ),
                    Curve::new("first pair", x.clone(), col("stiffness_pair0_n_per_m")),
                    Curve::new("second pair", x.clone(), col("stiffness_pair1_n_per_m")),
                ],
            ),
            Panel {
                title: format!(
                    "quasi-static transmission error at a mean mesh force of {:.0} N",
                    model.params.operating.static_mesh_force_n
                ),
                ..panel(
                    angle,
                    "transmission error (µm)",
                    vec![Curve::new("", x, col("quasi_static_te_um"))],
                )
            },
        ],
    }
}

/// ISO 6336-1 Method B beside the potential-energy result (or why it cannot be evaluated).
pub fn iso6336_json(model: &Model) -> serde_json::Value {
    match Iso6336Input::from_pair(&model.pair, 1.0, None).evaluate() {
        Ok(iso) => {
            let b_mm = model.pair.face_width_m * 1e3;
            let c_n_per_m = iso.mesh_alpha_n_per_mm_um * b_mm * 1e6;
            json!({
                "c_prime_th_n_per_mm_um": iso.theoretical_single_n_per_mm_um,
                "c_prime_n_per_mm_um": iso.single_n_per_mm_um,
                "c_gamma_alpha_n_per_mm_um": iso.mesh_alpha_n_per_mm_um,
                "c_gamma_alpha_n_per_m": c_n_per_m,
                "ratio_potential_energy_mean_to_c_gamma_alpha": model.mesh.mean_stiffness_n_per_m() / c_n_per_m,
                "warnings": iso.warnings,
            })
        }
        Err(e) => json!({ "error": e.to_string() }),
    }
}

/// The pair's geometry, mm and deg.
pub fn geometry_json(model: &Model) -> serde_json::Value {
    geometry_of_pair(&model.pair)
}

/// A pair's geometry (for a helical pair its transverse section), mm and deg.
pub fn geometry_of_pair(p: &crate::geometry::GearPair) -> serde_json::Value {
    json!({
        "base_radius_mm": [p.pinion.base_radius_m * 1e3, p.gear.base_radius_m * 1e3],
        "tip_radius_mm": [p.pinion.tip_radius_m * 1e3, p.gear.tip_radius_m * 1e3],
        "root_radius_mm": [p.pinion.root_radius_m * 1e3, p.gear.root_radius_m * 1e3],
        "centre_distance_mm": p.centre_distance_m * 1e3,
        "operating_pressure_angle_deg": p.operating_pressure_angle_rad.to_degrees(),
        "path_of_contact_mm": [p.rho_start_m * 1e3, p.rho_end_m * 1e3],
        "pitch_point_rho1_mm": p.rho_pitch_m * 1e3,
        "base_pitch_mm": p.base_pitch_m * 1e3,
    })
}

/// Everything `gearwear stiffness` writes: `summary.json` content, `mesh_stiffness.csv`,
/// `mesh_stiffness.png`.
pub fn stiffness_artifacts(model: &Model) -> Artifacts {
    let (table, mut v) = stiffness_table(model);
    v["iso6336"] = iso6336_json(model);
    // The same pair with the other fillet-foundation setting, for comparison.
    let fillet = !model.case.stiffness.fillet_foundation;
    v["mesh_stiffness_other_fillet_setting"] = match MeshStiffness::new(
        &model.pair,
        &model.elastic,
        model.case.stiffness.table_points_per_mesh_period.max(16) as usize,
        fillet,
    ) {
        Ok(other) => json!({
            "fillet_foundation": fillet,
            "min_n_per_m": other.min_stiffness_n_per_m(),
            "max_n_per_m": other.max_stiffness_n_per_m(),
            "mean_n_per_m": other.mean_stiffness_n_per_m(),
        }),
        Err(e) => json!({ "fillet_foundation": fillet, "error": e.to_string() }),
    };
    v["geometry"] = geometry_json(model);
    v["warnings"] = json!(model.warnings);
    let mut a = Artifacts {
        headline: format!(
            "contact ratio {}; mesh stiffness min {}, mean {}, max {} N/m",
            shown(model.pair.contact_ratio),
            shown(model.mesh.min_stiffness_n_per_m()),
            shown(model.mesh.mean_stiffness_n_per_m()),
            shown(model.mesh.max_stiffness_n_per_m()),
        ),
        summary: v,
        ..Default::default()
    };
    a.figure("mesh_stiffness.png", figure2(model, &table));
    if let Some(f) = a.figures.last_mut() {
        f.data = Some("mesh_stiffness.csv".into());
    }
    a.table("mesh_stiffness.csv", table);
    super::pair_load::add_pair_load_artifacts(model, &mut a);
    super::teeth::add_teeth_artifacts(model, &mut a);
    super::teeth::add_teeth_static_te(model, &mut a);
    a
}
