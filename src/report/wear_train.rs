//! Results of `gearwear wear` on a gear train (`[[stage]]`, `study::train_wear`).
//!
//! Files, for each mode MODE (`dynamic`, `quasi_static`):
//! - `wear_history_MODE.csv`: a row per update and mesh (long form, a `stage` column):
//!   input cycles, the stage's pinion and gear cycles, its maximum wear on either flank,
//!   and which stage's threshold cut the block before the update (0: none).
//! - `updates_MODE_stageK.csv`, `wear_profiles_MODE_stageK.csv`: stage K's rows and
//!   profiles exactly as a single pair's `updates_MODE.csv` and `wear_profiles_MODE.csv`
//!   (its `cycles` being its own pinion's revolutions).
//!
//! A stage with a tooth fault (`fault.stage`, docs/MODEL.md 9.10) wears tooth by tooth:
//! `teeth_wear_MODE_stageK.png` and its data `csv/teeth_wear_MODE_stageK.csv` hold every
//! tooth's wear at the end of the run, exactly as a single pair's `teeth_wear_MODE.png`
//! and `csv/teeth_wear_MODE.csv` (`report::teeth`); its `updates_MODE_stageK.csv` and
//! maxima are over every tooth, its `wear_profiles_MODE_stageK.csv` the mean profiles.
//!
//! `summary.json`: a `meshes` list (per mesh: stage, teeth, pinion revolutions per input
//! revolution, whether its teeth wear one by one, and per mode its final pinion and gear
//! cycles and maximum wear), `faults` (the tooth faults modelled, with a fault), the
//! input cycles and updates per mode, `limiting_mesh` per mode (the mesh with the
//! deepest wear at the end: the train's wear life is that of its weakest mesh), the
//! early stops and the warnings.

use super::artifacts::Artifacts;
use super::teeth::tooth_wear_figure_of;
use super::wear::{profiles_table, updates_table};
use crate::format::shown;
use crate::io::Table;
use crate::study::train::TrainModel;
use crate::study::train_wear::TrainWearRun;
use crate::study::Model;
use serde_json::{json, Map, Value};

/// `wear_history_MODE.csv` of a run (see the module docs).
pub fn history_table(train: &TrainModel, run: &TrainWearRun) -> Table {
    let mut cols: [Vec<f64>; 8] = Default::default();
    for (i, u) in run.updates.iter().enumerate() {
        for (m, r) in u.meshes.iter().enumerate() {
            let p = &train.stages[m].pair;
            let ratio = p.pinion.teeth as f64 / p.gear.teeth as f64;
            let row = [
                i as f64,
                u.input_cycles,
                (m + 1) as f64,
                r.wear.cycles,
                r.wear.cycles * ratio,
                r.wear.max_pinion_m() * 1e6,
                r.wear.max_gear_m() * 1e6,
                u.limited_by.map_or(0.0, |k| (k + 1) as f64),
            ];
            for (c, v) in cols.iter_mut().zip(row) {
                c.push(v);
            }
        }
    }
    let names = [
        "update",
        "input_cycles",
        "stage",
        "pinion_cycles",
        "gear_cycles",
        "max_wear_pinion_um",
        "max_wear_gear_um",
        "block_limited_by_stage",
    ];
    names
        .iter()
        .zip(cols)
        .fold(Table::new(), |t, (n, c)| t.col(n, c))
}

/// Each mesh's entry of `meshes` in `summary.json`.
fn meshes_json(train: &TrainModel, runs: &[&TrainWearRun]) -> Vec<Value> {
    let c = train.cycle_factors();
    train
        .stages
        .iter()
        .enumerate()
        .map(|(m, s)| {
            let (z1, z2) = (s.pair.pinion.teeth, s.pair.gear.teeth);
            let mut by_mode = Map::new();
            for run in runs {
                let Some(r) = run.updates.last().map(|u| &u.meshes[m]) else {
                    continue;
                };
                by_mode.insert(
                    run.mode.name().into(),
                    json!({
                        "pinion_cycles": r.wear.cycles,
                        "gear_cycles": r.wear.cycles * z1 as f64 / z2 as f64,
                        "max_wear_pinion_um": r.wear.max_pinion_m() * 1e6,
                        "max_wear_gear_um": r.wear.max_gear_m() * 1e6,
                        "max_wear_rate_pinion_um_per_kcycle": r.max_increment_pinion_m() * 1e9,
                    }),
                );
            }
            json!({
                "stage": m + 1,
                "teeth": [z1, z2],
                "pinion_cycles_per_input_cycle": c[m],
                "per_tooth_wear": s.tooth_inputs.is_some(),
                "final": by_mode,
            })
        })
        .collect()
}

/// The summary, tables and headline of a train's wear runs.
pub fn train_wear_artifacts(
    model: &Model,
    train: &TrainModel,
    runs: &[&TrainWearRun],
) -> Artifacts {
    let mut a = Artifacts::default();
    let (mut input, mut updates, mut stopped, mut limiting) =
        (Map::new(), Map::new(), Map::new(), Map::new());
    let mut lines = Vec::new();
    for run in runs {
        let mode = run.mode.name();
        a.table(
            format!("wear_history_{mode}.csv"),
            history_table(train, run),
        );
        for (m, s) in train.stages.iter().enumerate() {
            let rec = run.mesh_records(m);
            a.table(
                format!("updates_{mode}_stage{}.csv", m + 1),
                updates_table(&rec),
            );
            a.table(
                format!("wear_profiles_{mode}_stage{}.csv", m + 1),
                profiles_table(&s.grid, &rec),
            );
            let last = rec.last();
            if let Some((fig, table)) =
                last.and_then(|r| tooth_wear_figure_of(&s.grid, &s.pair, r, run.mode))
            {
                let name = format!("teeth_wear_{mode}_stage{}.png", m + 1);
                a.figure_with_data(name, fig, table);
            }
        }
        let last = run.updates.last();
        input.insert(mode.into(), json!(last.map(|u| u.input_cycles)));
        updates.insert(mode.into(), json!(run.updates.len().saturating_sub(1)));
        if let Some(s) = &run.stopped {
            stopped.insert(
                mode.into(),
                json!({"input_cycles": s.cycles, "reason": s.reason}),
            );
        }
        lines.extend(headline_lines(run));
        if let Some((m, depth)) = run.limiting_mesh() {
            limiting.insert(
                mode.into(),
                json!({"stage": m + 1, "max_wear_um": depth * 1e6}),
            );
        }
    }
    a.summary = json!({
        "meshes": meshes_json(train, runs),
        "input_cycles": input,
        "updates": updates,
        "limiting_mesh": limiting,
        "limiting_mesh_notes": "the mesh with the deepest wear (either flank) at the end of each run: the train's wear life is that of its weakest mesh",
        "stopped": stopped,
        "warnings": model.warnings,
    });
    if let Some(f) = super::teeth::train_faults_json(train) {
        a.summary["faults"] = f;
    }
    a.headline = lines.join("\n");
    a
}

/// The headline of a run: a line per mesh and the mesh that limits the life.
fn headline_lines(run: &TrainWearRun) -> Vec<String> {
    let Some(last) = run.updates.last() else {
        return Vec::new();
    };
    let mode = run.mode.label();
    let mut lines: Vec<String> = last
        .meshes
        .iter()
        .enumerate()
        .map(|(m, r)| {
            format!(
                "{mode}, stage {}: {} pinion cycles, maximum wear pinion {} µm, gear {} µm",
                m + 1,
                shown(r.wear.cycles),
                shown(r.wear.max_pinion_m() * 1e6),
                shown(r.wear.max_gear_m() * 1e6)
            )
        })
        .collect();
    if let Some((m, depth)) = run.limiting_mesh() {
        lines.push(format!(
            "{mode}: {} updates to {} input cycles; stage {} limits the life (deepest wear {} µm)",
            run.updates.len() - 1,
            shown(last.input_cycles),
            m + 1,
            shown(depth * 1e6)
        ));
    }
    lines
}
