//! Each stage of a gear train as a single-pair model: the pair, its bodies and its
//! pinion's operating point from the train's (`TrainOperatingPoint`), for the studies
//! that describe one mesh at a time (`gearwear stiffness` on a train).

use super::model::{Model, ModelError};
use super::train::stage_case;

/// The single-pair model of every stage of the train `model` (in stage order). A
/// one-stage train's stage is the case itself (its `[operating]` is the pair's own, not
/// carried through the train's operating point and back), so that its numbers are the
/// single pair's bit for bit; a longer train's stage k runs at its pinion's speed and
/// torque. Every problem names its stage.
pub fn stage_models(model: &Model) -> Result<Vec<Model>, ModelError> {
    let Some(train) = &model.train else {
        return Ok(Vec::new());
    };
    let one = train.stages.len() == 1;
    let mut out = Vec::with_capacity(train.stages.len());
    for (k, (stage, spec)) in train.stages.iter().zip(&model.case.stage).enumerate() {
        let case = if one {
            stage_case(&model.case, spec, None)
        } else {
            stage.case.clone()
        };
        let m = Model::from_case(&case).map_err(|e| {
            ModelError(
                e.0.iter()
                    .map(|p| format!("stage {}: {}", k + 1, spec.name_own_keys(p)))
                    .collect(),
            )
        })?;
        out.push(m);
    }
    Ok(out)
}
