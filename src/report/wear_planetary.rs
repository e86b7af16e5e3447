//! Results of `gearwear wear` on a planetary set (`study::planetary_wear_loop`).
//!
//! Files, for each mode MODE (`dynamic`, `quasi_static`):
//! - `wear_history_MODE.csv`: a row per update: input cycles, then for every member flank
//!   (`sun`, `planet_N_sun_side`, `planet_N_ring_side`, `ring`) its largest wear depth
//!   (µm) and wear volume over all its teeth (mm^3), and the flank whose threshold cut the
//!   block before the update (1-based in that order; 0: none).
//! - `mesh_history_MODE.csv`: a row per update: for every mesh (`sun_planet_N`,
//!   `ring_planet_N`) its pinion's revolutions relative to the carrier, its largest pinion
//!   and gear wear from its own contacts (µm) and its mean force (N).
//! - `wear_profiles_MODE.csv`: the last update's wear profiles along each mesh's path of
//!   contact: the sun mesh's rho1 (the sun's radius of curvature, mm) with the sun's and
//!   every planet's sun-side depth, the ring mesh's rho1 (the planet's, mm) with every
//!   planet's ring-side depth and the ring's (µm).
//!
//! - `teeth_wear_MODE.csv` (a set with a tooth fault): every tooth of the faulty member's
//!   depth at the end of the run along each of its flanks ([`teeth_table`]).
//!
//! Figures (`super::wear_planetary_figures`): `wear_history_MODE.png` and
//! `wear_profiles_MODE.png`, each with its data under `csv/`.
//!
//! `summary.json`: `members` (per member its teeth, tooth contacts per input revolution
//! and per mode its final largest depth, volume and each flank's), the meshes' pinion
//! revolutions per input revolution, the input cycles and updates per mode,
//! `limiting_member` per mode (the member with the deepest wear at the end), with a tooth
//! fault `faulty_tooth` (the fault's member, planet, tooth and kind, and per mode and flank
//! the faulty tooth's deepest wear beside the deepest of the member's other teeth), the
//! early stops and the warnings.

use super::artifacts::Artifacts;
use super::teeth::own_and_others_line;
use super::wear_planetary_figures::{flank_stem as stem, max_of};
use crate::format::shown;
use crate::io::Table;
use crate::study::planetary_teeth::FaultyTeeth;
use crate::study::planetary_wear::{contacts_per_input, MemberFlank, PlanetaryWearModel};
use crate::study::planetary_wear_check::planetary_mesh_name;
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use crate::wear::tooth_wear::deepest_own_and_others;
use serde_json::{json, Map, Value};

/// `wear_history_MODE.csv` of a run (see the module docs).
pub fn history_table(model: &PlanetaryWearModel, run: &PlanetaryWearRun) -> Table {
    let flanks: Vec<Vec<MemberFlank>> = run.updates.iter().map(|u| u.flanks(model)).collect();
    let mut t = Table::new()
        .col("update", (0..run.updates.len()).map(|i| i as f64).collect())
        .col(
            "input_cycles",
            run.updates.iter().map(|u| u.input_cycles).collect(),
        );
    let Some(first) = flanks.first() else {
        return t;
    };
    for (k, f) in first.iter().enumerate() {
        let s = stem(f);
        t = t
            .col(
                &format!("max_wear_{s}_um"),
                flanks.iter().map(|u| max_of(&u[k].depth_m) * 1e6).collect(),
            )
            .col(
                &format!("volume_{s}_mm3"),
                flanks.iter().map(|u| u[k].volume_m3 * 1e9).collect(),
            );
    }
    t.col(
        "block_limited_by_flank",
        run.updates
            .iter()
            .map(|u| u.limited_by.map_or(0.0, |k| (k + 1) as f64))
            .collect(),
    )
}

/// `mesh_history_MODE.csv` of a run (see the module docs).
pub fn mesh_table(model: &PlanetaryWearModel, run: &PlanetaryWearRun) -> Table {
    let mut t = Table::new().col(
        "input_cycles",
        run.updates.iter().map(|u| u.input_cycles).collect(),
    );
    for j in 0..2 * model.planets() {
        let name = planetary_mesh_name(model, j);
        let col = |f: &dyn Fn(&crate::study::wear_loop::UpdateRecord) -> f64| {
            run.updates.iter().map(|u| f(&u.meshes[j])).collect()
        };
        t = t
            .col(&format!("pinion_cycles_{name}"), col(&|r| r.wear.cycles))
            .col(
                &format!("max_wear_pinion_{name}_um"),
                col(&|r| r.wear.max_pinion_m() * 1e6),
            )
            .col(
                &format!("max_wear_gear_{name}_um"),
                col(&|r| r.wear.max_gear_m() * 1e6),
            )
            .col(
                &format!("mean_force_{name}_n"),
                col(&|r| r.summary.mesh_force_mean_n),
            );
    }
    t
}

/// `wear_profiles_MODE.csv`: the last update's profiles (see the module docs).
pub fn profiles_table(model: &PlanetaryWearModel, run: &PlanetaryWearRun) -> Table {
    let [gs, gr] = &model.grids;
    let mut t = Table::new()
        .col(
            "rho_sun_mesh_mm",
            gs.rho_pinion_m.iter().map(|r| r * 1e3).collect(),
        )
        .col(
            "rho_ring_mesh_mm",
            gr.rho_pinion_m.iter().map(|r| r * 1e3).collect(),
        );
    if let Some(u) = run.updates.last() {
        for f in u.flanks(model) {
            t = t.col(
                &format!("{}_um", stem(&f)),
                f.depth_m.iter().map(|h| h * 1e6).collect(),
            );
        }
    }
    t
}

/// The members' final wear per mode: (member, largest depth m, volume m^3, flanks json).
fn members_of(flanks: &[MemberFlank]) -> Vec<(String, f64, f64, Map<String, Value>)> {
    let mut out: Vec<(String, f64, f64, Map<String, Value>)> = Vec::new();
    for f in flanks {
        let depth = max_of(&f.depth_m);
        let entry = json!({"max_wear_um": depth * 1e6, "volume_mm3": f.volume_m3 * 1e9});
        match out.iter_mut().find(|m| m.0 == f.member) {
            Some(m) => {
                m.1 = m.1.max(depth);
                m.2 += f.volume_m3;
                m.3.insert(f.flank.into(), entry);
            }
            None => {
                let mut fl = Map::new();
                fl.insert(f.flank.into(), entry);
                out.push((f.member.clone(), depth, f.volume_m3, fl));
            }
        }
    }
    out
}

/// A run's history, mesh and profile tables and its figures, added to `a`.
fn add_run_files(model: &PlanetaryWearModel, run: &PlanetaryWearRun, a: &mut Artifacts) {
    let mode = run.mode.name();
    a.table(
        format!("wear_history_{mode}.csv"),
        history_table(model, run),
    );
    a.table(format!("mesh_history_{mode}.csv"), mesh_table(model, run));
    a.table(
        format!("wear_profiles_{mode}.csv"),
        profiles_table(model, run),
    );
    super::wear_planetary_figures::add_figures(model, run, a);
}

/// The summary, tables and headline of a planetary set's wear runs.
pub fn planetary_wear_artifacts(
    model: &PlanetaryWearModel,
    runs: &[&PlanetaryWearRun],
) -> Artifacts {
    let mut a = Artifacts::default();
    let set = &model.dynamics.study.set;
    let contacts = contacts_per_input(model);
    let mut members: Vec<Value> = Vec::new();
    let (mut input, mut updates, mut stopped, mut limiting) =
        (Map::new(), Map::new(), Map::new(), Map::new());
    let mut lines = Vec::new();
    let mut finals: Vec<(String, Map<String, Value>)> = Vec::new();
    let mut faulty = Map::new();
    for run in runs {
        let mode = run.mode.name();
        add_run_files(model, run, &mut a);
        if let Some(teeth) = run.faulty_teeth(model) {
            a.table(format!("teeth_wear_{mode}.csv"), teeth_table(model, &teeth));
            let entry = faulty_tooth_final(&teeth, run.mode.label(), &mut lines);
            faulty.insert(mode.into(), entry);
        }
        let Some(last) = run.updates.last() else {
            continue;
        };
        input.insert(mode.into(), json!(last.input_cycles));
        updates.insert(mode.into(), json!(run.updates.len() - 1));
        if let Some(s) = &run.stopped {
            stopped.insert(
                mode.into(),
                json!({"input_cycles": s.cycles, "reason": s.reason}),
            );
        }
        let ms = members_of(&last.flanks(model));
        if let Some(worst) = ms.iter().max_by(|x, y| x.1.total_cmp(&y.1)) {
            limiting.insert(
                mode.into(),
                json!({"member": worst.0, "max_wear_um": worst.1 * 1e6}),
            );
            lines.push(format!(
                "{}: {} updates to {} input cycles; the {} limits the life (deepest wear {} µm); sun {} µm, ring {} µm",
                run.mode.label(),
                run.updates.len() - 1,
                shown(last.input_cycles),
                worst.0.replace('_', " "),
                shown(worst.1 * 1e6),
                shown(ms.first().map_or(0.0, |m| m.1) * 1e6),
                shown(ms.last().map_or(0.0, |m| m.1) * 1e6),
            ));
        }
        for (name, depth, volume, flanks) in ms {
            let v =
                json!({"max_wear_um": depth * 1e6, "volume_mm3": volume * 1e9, "flanks": flanks});
            match finals.iter_mut().find(|f| f.0 == name) {
                Some(f) => {
                    f.1.insert(mode.into(), v);
                }
                None => {
                    let mut m = Map::new();
                    m.insert(mode.into(), v);
                    finals.push((name, m));
                }
            }
        }
    }
    for (name, by_mode) in finals {
        let (teeth, per_input) = match name.as_str() {
            "sun" => (set.teeth_sun(), contacts[0]),
            "ring" => (set.teeth_ring(), contacts[2]),
            _ => (set.teeth_planet(), contacts[1]),
        };
        members.push(json!({
            "member": name,
            "teeth": teeth,
            "tooth_contacts_per_input_cycle": per_input,
            "final": by_mode,
        }));
    }
    let [cs, cp] = model.pinion_cycles_per_input;
    a.summary = json!({
        "planetary_wear": {
            "members": members,
            "pinion_cycles_per_input_cycle": {"sun_planet_mesh_sun": cs, "ring_planet_mesh_planet": cp},
            "input_cycles": input,
            "updates": updates,
            "limiting_member": limiting,
            "limiting_member_notes": "the member with the deepest wear (any flank) at the end of each run; a planet's sun-side and ring-side flanks wear apart (docs/MODEL.md 12.9)",
            "stopped": stopped,
        },
        "warnings": model.dynamics.study.warnings,
    });
    if let Some(f) = faulty_tooth_summary(model, faulty) {
        a.summary["planetary_wear"]["faulty_tooth"] = f;
    }
    a.headline = lines.join("\n");
    a
}

/// `teeth_wear_MODE.csv`: every tooth of the faulty member's depth at the end of a run
/// (µm) along each of its flanks, against each mesh's rho1 (mm) as `wear_profiles_MODE.csv`
/// gives them: a column per flank and tooth, `STEM_toothT_um` (`STEM` as the profiles'
/// flank columns, e.g. `sun`, `planet_2_ring_side`).
pub fn teeth_table(model: &PlanetaryWearModel, teeth: &FaultyTeeth) -> Table {
    let [gs, gr] = &model.grids;
    let mm = |v: &[f64]| v.iter().map(|r| r * 1e3).collect::<Vec<f64>>();
    let mut t = Table::new()
        .col("rho_sun_mesh_mm", mm(&gs.rho_pinion_m))
        .col("rho_ring_mesh_mm", mm(&gr.rho_pinion_m));
    for (flank, profiles) in &teeth.flanks {
        let stem = if teeth.member == *flank {
            teeth.member.clone()
        } else {
            format!("{}_{flank}", teeth.member)
        };
        for (k, p) in profiles.iter().enumerate() {
            t = t.col(
                &format!("{stem}_tooth{k}_um"),
                p.iter().map(|h| h * 1e6).collect(),
            );
        }
    }
    t
}

/// A run's `faulty_tooth.final` entry (per flank the faulty tooth's deepest wear and the
/// deepest of the member's other teeth, µm), the headline's lines on it added to `lines`
/// (`label`: the run's mode in words).
fn faulty_tooth_final(teeth: &FaultyTeeth, label: &str, lines: &mut Vec<String>) -> Value {
    let mut entry = Map::new();
    let member = teeth.member.replace('_', " ");
    for (flank, profiles) in &teeth.flanks {
        let Some((own, others)) = deepest_own_and_others(profiles, teeth.tooth) else {
            continue;
        };
        entry.insert(
            (*flank).into(),
            json!({"tooth_max_wear_um": own * 1e6, "other_teeth_max_wear_um": others * 1e6}),
        );
        let who = if teeth.member == *flank {
            format!("{member} tooth {}", teeth.tooth)
        } else {
            format!(
                "{member} tooth {} ({})",
                teeth.tooth,
                flank.replace('_', " ")
            )
        };
        lines.push(own_and_others_line(
            label,
            &who,
            &member,
            (&shown(own * 1e6), &shown(others * 1e6)),
        ));
    }
    Value::Object(entry)
}

/// The summary's `faulty_tooth` of a set with a tooth fault (its member, planet, tooth and
/// kind, `final`: each run's [`faulty_tooth_final`] entry by mode); None without a fault.
fn faulty_tooth_summary(
    model: &PlanetaryWearModel,
    final_by_mode: Map<String, Value>,
) -> Option<Value> {
    let f = model.dynamics.study.section.active_fault()?;
    Some(json!({
        "member": f.gear.name(),
        "planet": f.planet,
        "tooth": f.tooth,
        "kind": f.kind.name(),
        "final": final_by_mode,
        "notes": "the faulty tooth's deepest wear and the deepest of its member's other teeth, each tooth worn by its own contacts over the fault's period and accumulated over the run's blocks (docs/MODEL.md 12.16); teeth_wear_MODE.csv holds every tooth's profile",
    }))
}
