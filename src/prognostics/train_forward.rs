//! The forward run of a gear train (`[[stage]]`): its dynamic wear loop
//! (`study::train_wear`, each mesh worn at its own cycle count by one response of the
//! whole train) kept as a `Trajectory` whose `records` are stage 1's and whose
//! `later_stages` hold every other mesh's, one per update.
//!
//! **Cycles.** A train's trajectory counts input cycles (revolutions of stage 1's
//! pinion, the motor's shaft): its `records`' cycles are the input cycles (c_1 = 1), and
//! mesh k's pinion turns c_k times per input cycle (`TrainModel::cycle_factors`), so
//! stage k's wear at N input cycles is its record's profile advanced by c_k (N - N_j)
//! of its own cycles (`Trajectory::value`), exactly as the loop advances it
//! (`train_wear::next_block`). Observations and predictions on a train are in input
//! cycles.
//!
//! **The k x N invariance** (`super::surrogate`) holds for a train as for a pair: every
//! mesh's wear per cycle is proportional to k (paper eq. 14), the response depends on the
//! wear states only, and the block is cut by the per-mesh threshold (a wear depth) of
//! the fastest mesh, at the same wear states for every k. So the surrogate's reference
//! runs stand for every k of a train unchanged.
//!
//! A one-stage train is the single pair's loop, number for number (`study::train_wear`):
//! its trajectory equals the pair's.

use crate::config::Case;
use crate::study::model::{Model, ModelError};
use crate::study::train::TrainModel;
use crate::study::train_wear::{run_train_wear, TrainUpdate, TrainWearRun};
use crate::study::wear_loop::{UpdateRecord, WearMode};

/// A train's dynamic wear run as the forward model keeps it (`forward::Trajectory`
/// takes it whole).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TrainRun {
    /// Stage 1's records, one per update (their cycles are the input cycles).
    pub records: Vec<UpdateRecord>,
    /// Every later stage's records (stage 2 first), one per update.
    pub later_stages: Vec<Vec<UpdateRecord>>,
    /// c_k of every stage (stage order); empty for a one-stage train (c_1 = 1).
    pub cycle_factors: Vec<f64>,
    /// Why the run stopped before its total, if it did.
    pub failure: Option<String>,
}

/// Run the dynamic wear study of the train of `case` (its `wear.total_cycles` the input
/// cycles to reach). A solver failure or an early stop is kept in the run, not returned.
/// A load spectrum on a train is refused (`app` refuses it before any run: a train's
/// prognostics follow one operating point).
pub(crate) fn run_train(case: &Case) -> Result<TrainRun, ModelError> {
    if case.load_spectrum.is_some() {
        return Err(ModelError(vec![TRAIN_DUTY.to_owned()]));
    }
    let model = Model::from_case(case)?;
    let Some(train) = model.train.as_ref() else {
        return Err(ModelError(vec![
            "this case has no [[stage]] tables".to_owned()
        ]));
    };
    Ok(continued(&model, train, Vec::new()))
}

/// Continue the train run of `case` whose updates are stage 1's `records` and the later
/// stages' `later` to `total` input cycles (the loop resumes from its updates, as
/// `surrogate::extend` resumes a pair's run, so the blocks it made stay as they were).
pub(crate) fn extend_train(
    case: &Case,
    (records, later): (&[UpdateRecord], &[Vec<UpdateRecord>]),
    total: f64,
) -> Result<TrainRun, ModelError> {
    let mut c = case.clone();
    c.wear.total_cycles = total;
    let model = Model::from_case(&c)?;
    let Some(train) = model.train.as_ref() else {
        return Err(ModelError(vec![
            "this case has no [[stage]] tables".to_owned()
        ]));
    };
    let updates = (0..records.len())
        .map(|j| TrainUpdate {
            input_cycles: records[j].wear.cycles,
            meshes: std::iter::once(records)
                .chain(later.iter().map(Vec::as_slice))
                .map(|r| r[j].clone())
                .collect(),
            // Which mesh cut the block is a report's, not the loop's (`next_block`).
            limited_by: None,
        })
        .collect();
    Ok(continued(&model, train, updates))
}

/// The train's dynamic wear loop from `updates` (none: new teeth) to the model's total
/// input cycles.
fn continued(model: &Model, train: &TrainModel, updates: Vec<TrainUpdate>) -> TrainRun {
    let mut kept = updates.clone();
    let run = TrainWearRun {
        updates,
        ..TrainWearRun::new(WearMode::Dynamic)
    };
    let result = run_train_wear(model, train, run, &mut |run| {
        kept.extend(
            run.updates[kept.len().min(run.updates.len())..]
                .iter()
                .cloned(),
        );
        Ok(())
    });
    let failure = match result {
        Err(e) => Some(format!("{e:#}")),
        Ok(run) => run.stopped.map(|s| s.reason),
    };
    let stages = train.stages.len();
    let mut meshes: Vec<Vec<UpdateRecord>> = (0..stages)
        .map(|m| kept.iter().map(|u| u.meshes[m].clone()).collect())
        .collect();
    let first = meshes.remove(0);
    TrainRun {
        records: first,
        failure,
        later_stages: meshes,
        cycle_factors: if stages > 1 {
            train.cycle_factors()
        } else {
            Vec::new()
        },
    }
}

/// What a train's prognostics say of a load spectrum or a change of duty.
pub const TRAIN_DUTY: &str = "`gearwear calibrate` and `gearwear predict` on a gear train ([[stage]] tables) follow its operating point: a [load_spectrum] or a future duty on a train is not taken yet (`gearwear wear` and `gearwear duty` run a train under a spectrum)";

/// What a train's prognostics say of a condition indicator.
pub const TRAIN_INDICATORS: &str = "condition indicators of the housing's record are not observed on a gear train yet: give wear, vibration or transmission-error columns (with a `stage` column naming the mesh)";
