//! Results of `gearwear stiffness` on a gear train (`[[stage]]`): every mesh's stiffness
//! study as the single pair's (`report::stiffness`), one file set per stage.
//!
//! Files: `mesh_stiffness_stageK.csv` and `mesh_stiffness_stageK.png` for stage K
//! (1-based), each the single pair's `mesh_stiffness.csv` / `.png` of that stage at its
//! pinion's torque; `summary.json` holds a `meshes` list (one entry per mesh: its stage
//! and teeth, then exactly the keys of a single pair's summary: contact ratio, mean,
//! minimum and maximum stiffness, the quasi-static transmission error, ISO 6336, the
//! geometry) and the train's warnings.

use super::artifacts::Artifacts;
use super::stiffness::stiffness_artifacts;
use crate::study::Model;
use serde_json::{json, Value};

/// The artifacts of the train `train` from its stages' single-pair models `stages`
/// (`study::train_stages::stage_models`).
pub fn train_stiffness_artifacts(train: &Model, stages: &[Model]) -> Artifacts {
    let mut out = Artifacts::default();
    let mut meshes = Vec::with_capacity(stages.len());
    let mut lines = Vec::with_capacity(stages.len());
    for (k, stage) in stages.iter().enumerate() {
        let n = k + 1;
        let a = stiffness_artifacts(stage);
        let rename = |p: &str| p.replace("mesh_stiffness.", &format!("mesh_stiffness_stage{n}."));
        for (path, t) in a.tables {
            out.tables.push((rename(&path), t));
        }
        for mut f in a.figures {
            f.path = rename(&f.path);
            f.data = f.data.as_deref().map(rename);
            out.figures.push(f);
        }
        let mut v = json!({
            "stage": n,
            "teeth": [stage.pair.pinion.teeth, stage.pair.gear.teeth],
        });
        if let (Some(o), Value::Object(s)) = (v.as_object_mut(), a.summary) {
            o.extend(s.into_iter().filter(|(key, _)| key != "warnings"));
        }
        meshes.push(v);
        lines.push(format!(
            "stage {n} ({}/{}): {}",
            stage.pair.pinion.teeth, stage.pair.gear.teeth, a.headline
        ));
    }
    out.summary = json!({
        "meshes": meshes,
        "train": {"stages": stages.len()},
        "warnings": train.warnings,
    });
    out.headline = lines.join("\n");
    out
}
