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
use super::stiffness_helical::helical_stiffness_artifacts;
use crate::study::train_stages::StageStiffness;
use crate::study::Model;
use serde_json::{json, Value};

/// The artifacts of the train `train` from its stages' single-pair models `stages`
/// (`study::train_stages::stage_models`, spur stages).
pub fn train_stiffness_artifacts(train: &Model, stages: &[Model]) -> Artifacts {
    let parts = stages
        .iter()
        .map(|m| {
            (
                stiffness_artifacts(m),
                [m.pair.pinion.teeth, m.pair.gear.teeth],
            )
        })
        .collect();
    train_artifacts_of(train, parts)
}

/// As [`train_stiffness_artifacts`] from every stage's stiffness study
/// (`study::train_stages::stage_stiffness_models`): a helical stage's is the helical
/// pair's (`report::stiffness_helical`: the slice model, its `helical` block and ISO
/// 6336-1's helical values).
pub fn train_stiffness_artifacts_of(train: &Model, stages: &[StageStiffness]) -> Artifacts {
    let parts = stages
        .iter()
        .map(|stage| match stage {
            StageStiffness::Spur(m) => (
                stiffness_artifacts(m),
                [m.pair.pinion.teeth, m.pair.gear.teeth],
            ),
            StageStiffness::Helical(h) => {
                let t = &h.pair().transverse;
                (
                    helical_stiffness_artifacts(h),
                    [t.pinion.teeth, t.gear.teeth],
                )
            }
        })
        .collect();
    train_artifacts_of(train, parts)
}

/// The train's files and summary from each stage's artifacts and teeth (stage order).
fn train_artifacts_of(train: &Model, stages: Vec<(Artifacts, [usize; 2])>) -> Artifacts {
    let mut out = Artifacts::default();
    let mut meshes = Vec::with_capacity(stages.len());
    let mut lines = Vec::with_capacity(stages.len());
    let count = stages.len();
    for (k, (a, teeth)) in stages.into_iter().enumerate() {
        let n = k + 1;
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
            "teeth": teeth,
        });
        if let (Some(o), Value::Object(s)) = (v.as_object_mut(), a.summary) {
            o.extend(s.into_iter().filter(|(key, _)| key != "warnings"));
        }
        meshes.push(v);
        lines.push(format!(
            "stage {n} ({}/{}): {}",
            teeth[0], teeth[1], a.headline
        ));
    }
    out.summary = json!({
        "meshes": meshes,
        "train": {"stages": count},
        "warnings": train.warnings,
    });
    out.headline = lines.join("\n");
    out
}
