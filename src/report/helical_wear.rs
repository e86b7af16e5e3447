//! The wear map of a helical pair (`study::helical_wear`, docs/MODEL.md 11.3): for each
//! wear run, the last update's depth over the face (slice j at y_j = (j + 1/2) b / N from
//! the face end y = 0) and along the profile, for pinion and gear:
//! - `wear_map_MODE.png`, a heat map per flank (roll angle of the flank's own profile x
//!   position across the face), its data `csv/wear_map_MODE.csv`: the grid's rho1 and both
//!   roll angles, then a column per slice and flank (`pinion_slice{j}_um`, j from 0);
//! - `summary.json` `wear_map.MODE`: the slice count and face width, per flank the deepest
//!   wear with its slice, face position and the flank's own radius of curvature there,
//!   and the volume removed (the sum over
//!   slices of their layers, `helical_wear::slice_volumes_m3`);
//! - a headline line per mode, rounded for people.
//!
//! Where per-tooth inputs wear every tooth's face slices on their own (docs/MODEL.md
//! 11.13), the map is the mean over each gear's teeth of each face slice, and each run
//! adds `teeth_wear_MODE.png` and its data `csv/teeth_wear_MODE.csv` (the spur pair's
//! per-tooth table with the slice axis): rho1 and both roll angles, then a column per
//! tooth and face slice, `{flank}_tooth{t}_slice{j}_um`; its heat map draws each tooth's
//! deepest wear across the face at each profile point.

use super::artifacts::Artifacts;
use super::figures::heat_panel;
use super::plot::Figure;
use crate::format::shown;
use crate::io::Table;
use crate::study::helical::HelicalDynamics;
use crate::study::helical_wear::slice_volumes_m3;
use crate::study::wear_loop::WearRun;
use crate::study::Model;
use crate::wear::{SliceWear, ToothWear};
use serde_json::{json, Map, Value};

/// The deepest entry of a per-slice map: (depth m, slice, grid point).
fn deepest(profiles: &[Vec<f64>]) -> (f64, usize, usize) {
    let mut best = (0.0, 0, 0);
    for (j, p) in profiles.iter().enumerate() {
        for (i, h) in p.iter().enumerate() {
            if *h > best.0 {
                best = (*h, j, i);
            }
        }
    }
    best
}

/// The figure of `map` and its data table (see the module docs).
fn map_figure(model: &Model, y_mm: &[f64], map: &SliceWear, title: String) -> (Figure, Table) {
    let (table, roll_p, roll_g) = super::teeth::map_table(model, map, "slice");
    let max_um = map.max_m() * 1e6;
    let heat = |flank: &str, roll: &[f64], profiles: &[Vec<f64>]| {
        let mut p = heat_panel(roll, y_mm, profiles, max_um);
        p.title = flank.into();
        p.x_label = format!("roll angle of the {flank}'s profile (deg)");
        p.y_label = "position across the face (mm)".into();
        p
    };
    let figure = Figure {
        title,
        panels: vec![
            heat("pinion", &roll_p, &map.pinion_m),
            heat("gear", &roll_g, &map.gear_m),
        ],
    };
    (figure, table)
}

/// `wear_map.MODE` of the summary and the headline line of one run's last map.
fn map_summary(
    model: &Model,
    h: &HelicalDynamics,
    y_mm: &[f64],
    map: &SliceWear,
    label: &str,
) -> (Value, String) {
    let b_mm = h.slice_model.pair().face_width_m * 1e3;
    let (vp, vg) = slice_volumes_m3(model, h, map);
    let g = &model.grid;
    let flank = |profiles: &[Vec<f64>], rho: &[f64], volume: f64| {
        let (d, j, i) = deepest(profiles);
        json!({
            "max_wear_um": d * 1e6,
            "max_wear_slice": j,
            "max_wear_position_mm": y_mm.get(j),
            "max_wear_rho_mm": rho.get(i).map(|r| r * 1e3),
            "volume_mm3": volume * 1e9,
        })
    };
    let v = json!({
        "slices": h.slices,
        "face_width_mm": b_mm,
        "pinion": flank(&map.pinion_m, &g.rho_pinion_m, vp),
        "gear": flank(&map.gear_m, &g.rho_gear_m, vg),
    });
    let (dp, jp, _) = deepest(&map.pinion_m);
    let (dg, jg, _) = deepest(&map.gear_m);
    let at = |j: usize| y_mm.get(j).map_or("-".into(), |y| shown(*y));
    let line = format!(
        "{label}: wear map over {} face slices of the {} mm face: deepest pinion wear {} µm at {} mm, gear {} µm at {} mm",
        h.slices,
        shown(b_mm),
        shown(dp * 1e6),
        at(jp),
        shown(dg * 1e6),
        at(jg)
    );
    (v, line)
}

/// Adds the wear map of every run of a helical pair to `a` (nothing for a spur pair).
pub fn add_wear_map_artifacts(model: &Model, runs: &[&WearRun], a: &mut Artifacts) {
    let Some(h) = &model.helical else {
        return;
    };
    // Each slice's face position, as the slice model places it (mm).
    let y_mm: Vec<f64> = h
        .slice_model
        .positions_m()
        .iter()
        .map(|y| y * 1e3)
        .collect();
    let mut maps = Map::new();
    for r in runs {
        let Some(last) = r.last() else {
            continue;
        };
        let mean_map;
        let map = match (&last.wear.slices, &last.wear.teeth) {
            (Some(m), _) => m,
            (None, Some(t)) => {
                let (table, fig) = tooth_slice_figure(model, h.slices, t, last.wear.cycles, r);
                a.figure_with_data(format!("teeth_wear_{}.png", r.mode.name()), fig, table);
                mean_map = slice_means(t, h.slices);
                &mean_map
            }
            (None, None) => continue,
        };
        let title = format!(
            "Wear over the face after {} cycles ({} study)",
            crate::io::format_number(last.wear.cycles),
            r.mode.label()
        );
        let (figure, table) = map_figure(model, &y_mm, map, title);
        a.figure_with_data(format!("wear_map_{}.png", r.mode.name()), figure, table);
        let (v, line) = map_summary(model, h, &y_mm, map, r.mode.label());
        maps.insert(r.mode.name().into(), v);
        if !a.headline.is_empty() {
            a.headline.push('\n');
        }
        a.headline.push_str(&line);
    }
    if !maps.is_empty() {
        a.summary["wear_map"] = Value::Object(maps);
    }
}

/// Each face slice's mean over a gear's teeth of a per-tooth, per-slice state (profile
/// t N + j: tooth t's face slice j, docs/MODEL.md 11.13) with `n` face slices.
fn slice_means(t: &ToothWear, n: usize) -> SliceWear {
    let means = |profiles: &[Vec<f64>]| -> Vec<Vec<f64>> {
        let z = (profiles.len() / n.max(1)).max(1);
        (0..n)
            .map(|j| {
                let of_slice: Vec<Vec<f64>> = (0..z)
                    .filter_map(|tooth| profiles.get(tooth * n + j).cloned())
                    .collect();
                crate::wear::tooth_wear::mean_profile(&of_slice)
            })
            .collect()
    };
    SliceWear {
        pinion_m: means(&t.pinion_m),
        gear_m: means(&t.gear_m),
    }
}

/// The per-tooth, per-slice wear table of a run's last state `t` at `cycles` (module
/// docs) and its heat map: each tooth's deepest wear across the face against the roll
/// angle of its own profile.
fn tooth_slice_figure(
    model: &Model,
    n: usize,
    t: &ToothWear,
    cycles: f64,
    run: &WearRun,
) -> (Table, Figure) {
    let none = ToothWear::default();
    let (mut table, roll_p, roll_g) = super::teeth::map_table(model, &none, "tooth");
    let deepest = |profiles: &[Vec<f64>]| -> Vec<Vec<f64>> {
        profiles
            .chunks(n.max(1))
            .map(|tooth| {
                let len = tooth.first().map_or(0, Vec::len);
                (0..len)
                    .map(|i| tooth.iter().fold(0.0_f64, |m, p| m.max(p[i])))
                    .collect()
            })
            .collect()
    };
    for (name, profiles) in [("pinion", &t.pinion_m), ("gear", &t.gear_m)] {
        for (k, p) in profiles.iter().enumerate() {
            table = table.col(
                &format!("{name}_tooth{}_slice{}_um", k / n.max(1), k % n.max(1)),
                p.iter().map(|h| h * 1e6).collect(),
            );
        }
    }
    let max = t.max_m() * 1e6;
    let heat = |title: &str, roll: &[f64], profiles: &[Vec<f64>]| {
        let rows: Vec<f64> = (0..profiles.len()).map(|x| x as f64).collect();
        let mut p = heat_panel(roll, &rows, profiles, max);
        p.title = title.into();
        p.x_label = "roll angle of the tooth's own profile (deg)".into();
        p.y_label = "tooth (deepest wear across the face)".into();
        p
    };
    let fig = Figure {
        title: format!(
            "Wear of every tooth after {} cycles ({} study), the deepest of its face slices",
            crate::io::format_number(cycles),
            run.mode.label()
        ),
        panels: vec![
            heat("pinion", &roll_p, &deepest(&t.pinion_m)),
            heat("gear", &roll_g, &deepest(&t.gear_m)),
        ],
    };
    (table, fig)
}
