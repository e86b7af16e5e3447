//! Figures of `gearwear wear` on a planetary set (`study::planetary_wear_loop`), each with
//! the table of exactly its data (under `csv/`):
//! - `wear_history_MODE.png`: the largest wear depth of every member flank (sun, each
//!   planet's sun-side and ring-side flank, ring) against the input member's revolutions;
//! - `wear_profiles_MODE.png`: the last update's depth along each mesh's path of contact,
//!   one panel per mesh: the sun mesh (the sun and every planet's sun-side flank against
//!   the sun's radius of curvature) and the ring mesh (every planet's ring-side flank and
//!   the ring against the planet's radius of curvature).

use super::artifacts::Artifacts;
use super::figures::{panel, points_panel, Curve};
use super::plot::Figure;
use crate::io::Table;
use crate::study::planetary_wear::{MemberFlank, PlanetaryWearModel};
use crate::study::planetary_wear_loop::PlanetaryWearRun;

/// A flank in words for a legend: "sun", "ring", "planet 2, sun side".
fn flank_words(f: &MemberFlank) -> String {
    if f.member == f.flank {
        f.member.clone()
    } else {
        format!("{}, {}", f.member, f.flank).replace('_', " ")
    }
}

/// A flank's column stem, e.g. `planet_2_ring_side`.
pub(crate) fn flank_stem(f: &MemberFlank) -> String {
    if f.member == f.flank {
        f.member.clone()
    } else {
        format!("{}_{}", f.member, f.flank)
    }
}

/// Largest entry, 0 for none.
pub(crate) fn max_of(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |a, b| a.max(*b))
}

/// The largest depth of every member flank at every update, µm, against the input
/// member's revolutions; None for a run without an update.
pub fn history_figure(
    model: &PlanetaryWearModel,
    run: &PlanetaryWearRun,
) -> Option<(Figure, Table)> {
    let flanks: Vec<Vec<MemberFlank>> = run.updates.iter().map(|u| u.flanks(model)).collect();
    let first = flanks.first()?;
    let cycles: Vec<f64> = run.updates.iter().map(|u| u.input_cycles).collect();
    let mut table = Table::new().col("input_cycles", cycles.clone());
    let mut curves = Vec::new();
    for (k, f) in first.iter().enumerate() {
        let depth: Vec<f64> = flanks.iter().map(|u| max_of(&u[k].depth_m) * 1e6).collect();
        table = table.col(&format!("max_wear_{}_um", flank_stem(f)), depth.clone());
        curves.push(Curve::new(flank_words(f), cycles.clone(), depth));
    }
    let p = points_panel(
        "revolutions of the input member",
        "largest wear depth (µm)",
        curves,
    );
    let title = format!(
        "Wear of every member flank of the planetary set ({})",
        run.mode.label()
    );
    Some((super::figures::single(&title, p), table))
}

/// The last update's wear depth along each mesh's path of contact, µm: the sun mesh's
/// flanks against the sun's radius of curvature, the ring mesh's against the planet's;
/// None for a run without an update.
pub fn profiles_figure(
    model: &PlanetaryWearModel,
    run: &PlanetaryWearRun,
) -> Option<(Figure, Table)> {
    let last = run.updates.last()?;
    let [gs, gr] = &model.grids;
    let mm = |v: &[f64]| v.iter().map(|r| r * 1e3).collect::<Vec<f64>>();
    let (rho_s, rho_r) = (mm(&gs.rho_pinion_m), mm(&gr.rho_pinion_m));
    let mut table = Table::new()
        .col("rho_sun_mesh_mm", rho_s.clone())
        .col("rho_ring_mesh_mm", rho_r.clone());
    let (mut sun_mesh, mut ring_mesh) = (Vec::new(), Vec::new());
    for f in last.flanks(model) {
        let depth: Vec<f64> = f.depth_m.iter().map(|h| h * 1e6).collect();
        table = table.col(&format!("{}_um", flank_stem(&f)), depth.clone());
        // The sun and the planets' sun-side flanks lie on the sun mesh's grid.
        if f.member == "sun" || f.flank == "sun_side" {
            sun_mesh.push(Curve::new(flank_words(&f), rho_s.clone(), depth));
        } else {
            ring_mesh.push(Curve::new(flank_words(&f), rho_r.clone(), depth));
        }
    }
    let mut p1 = panel(
        "sun's radius of curvature along the sun-planet path of contact (mm)",
        "wear depth (µm)",
        sun_mesh,
    );
    p1.title = "sun-planet meshes".into();
    let mut p2 = panel(
        "planet's radius of curvature along the ring-planet path of contact (mm)",
        "wear depth (µm)",
        ring_mesh,
    );
    p2.title = "ring-planet meshes".into();
    let figure = Figure {
        title: format!(
            "Wear profiles of the planetary set at {} input revolutions ({})",
            crate::io::format_number(last.input_cycles),
            run.mode.label()
        ),
        panels: vec![p1, p2],
    };
    Some((figure, table))
}

/// Adds both figures of `run` (with their tables) to `a`.
pub(crate) fn add_figures(model: &PlanetaryWearModel, run: &PlanetaryWearRun, a: &mut Artifacts) {
    let mode = run.mode.name();
    if let Some((f, t)) = history_figure(model, run) {
        a.figure_with_data(format!("wear_history_{mode}.png"), f, t);
    }
    if let Some((f, t)) = profiles_figure(model, run) {
        a.figure_with_data(format!("wear_profiles_{mode}.png"), f, t);
    }
}
