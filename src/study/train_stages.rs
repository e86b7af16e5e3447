//! Each stage of a gear train as a single-pair model: the pair, its bodies and its
//! pinion's operating point from the train's (`TrainOperatingPoint`), for the studies
//! that describe one mesh at a time (`gearwear stiffness` on a train, a helical stage by
//! its slice model).

use super::helical::HelicalModel;
use super::model::{Model, ModelError};
use super::train::stage_case;
use crate::config::case::Case;

/// The single-pair model of every stage of the train `model` (in stage order). A
/// one-stage train's stage is the case itself (its `[operating]` is the pair's own, not
/// carried through the train's operating point and back), so that its numbers are the
/// single pair's bit for bit; a longer train's stage k runs at its pinion's speed and
/// torque. Every problem names its stage.
pub fn stage_models(model: &Model) -> Result<Vec<Model>, ModelError> {
    stage_cases(model)
        .iter()
        .enumerate()
        .map(|(k, case)| Model::from_case(case).map_err(|e| named(model, k, e)))
        .collect()
}

/// Each stage's single-pair case, as [`stage_models`] builds them.
fn stage_cases(model: &Model) -> Vec<Case> {
    let Some(train) = &model.train else {
        return Vec::new();
    };
    let one = train.stages.len() == 1;
    train
        .stages
        .iter()
        .zip(&model.case.stage)
        .map(|(stage, spec)| {
            if one {
                stage_case(&model.case, spec, None)
            } else {
                stage.case.clone()
            }
        })
        .collect()
}

/// A stage model's problems named by stage `k` (0-based) and its own keys.
fn named(model: &Model, k: usize, e: ModelError) -> ModelError {
    let spec = &model.case.stage[k];
    ModelError(
        e.0.iter()
            .map(|p| format!("stage {}: {}", k + 1, spec.name_own_keys(p)))
            .collect(),
    )
}

/// A stage's stiffness study: a spur stage's single-pair model, a helical stage's slice
/// model (`study::helical::HelicalModel`, as `gearwear stiffness` on a helical pair).
pub enum StageStiffness {
    /// A spur stage.
    Spur(Box<Model>),
    /// A helical stage (`stage.helix_angle_deg` > 0).
    Helical(Box<HelicalModel>),
}

/// The stiffness study of every stage of the train `model` (in stage order), each at the
/// operating point [`stage_models`] gives it. Every problem names its stage.
pub fn stage_stiffness_models(model: &Model) -> Result<Vec<StageStiffness>, ModelError> {
    stage_cases(model)
        .iter()
        .enumerate()
        .map(|(k, case)| {
            if case.gear.helix_angle_deg == 0.0 {
                Model::from_case(case).map(|m| StageStiffness::Spur(Box::new(m)))
            } else {
                HelicalModel::from_case(case).map(|m| StageStiffness::Helical(Box::new(m)))
            }
            .map_err(|e| named(model, k, e))
        })
        .collect()
}
