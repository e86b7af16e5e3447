//! What a prediction on a gear train (`[[stage]]`) adds to the pair's outputs: the
//! limiting stage of each sample counted (the mesh whose maximum pinion wear reaches the
//! limit first), each stage's wear band at the horizon, and the cycles stated as input
//! cycles (revolutions of stage 1's pinion; `prognostics::train_forward`).

use crate::prognostics::band::Band;
use crate::prognostics::predict::SampleOutcome;
use crate::prognostics::Quantity;
use serde_json::{json, Value};

/// Samples whose limiting stage is each stage (stage order).
fn limiting_counts(o: &[SampleOutcome], stages: usize) -> Vec<usize> {
    (1..=stages)
        .map(|s| o.iter().filter(|x| x.limiting_stage == Some(s)).count())
        .collect()
}

/// Add the train's entries to a prediction's `summary` (a JSON object): `stages`, the
/// samples per limiting stage, each stage's maximum pinion wear band at the horizon,
/// and the note on cycles.
pub(crate) fn add_train_summary(
    summary: &mut Value,
    o: &[SampleOutcome],
    fans: &[(Quantity, Band)],
    stages: usize,
) {
    let at_horizon = |q: Quantity| {
        fans.iter().find(|b| b.0 == q).map(|(_, b)| {
            let g = b.cycles.len() - 1;
            json!({"p05": b.percentiles[0][g], "median": b.percentiles[2][g], "p95": b.percentiles[4][g], "samples_with_value": b.valid[g]})
        })
    };
    let counts = limiting_counts(o, stages);
    let Some(map) = summary.as_object_mut() else {
        return;
    };
    map.insert("stages".into(), json!(stages));
    map.insert(
        "cycles_are".into(),
        json!("input cycles: revolutions of stage 1's pinion (the motor's shaft); stage k's pinion turns c_k times per input cycle"),
    );
    map.insert(
        "limiting_stage".into(),
        json!({
            "samples": (1..=stages).zip(&counts).map(|(s, n)| json!({"stage": s, "samples": n})).collect::<Vec<_>>(),
            "note": "the life of a train is that of the first mesh whose maximum pinion wear reaches the limit; each sample reaching it within the horizon is counted at that stage",
        }),
    );
    map.insert(
        "stage_wear_at_horizon".into(),
        (1..=stages)
            .filter_map(|s| {
                let q = Quantity::MaxWearPinion.on_stage(s)?;
                Some(json!({"stage": s, "quantity": q.name(), "band": at_horizon(q)}))
            })
            .collect::<Vec<_>>()
            .into(),
    );
}

/// The report's note on a train's prediction: input cycles, and the samples per limiting
/// stage.
pub(crate) fn train_note(o: &[SampleOutcome], stages: usize) -> String {
    let counts = limiting_counts(o, stages);
    let per: Vec<String> = counts
        .iter()
        .enumerate()
        .map(|(s, n)| format!("stage {}: {n}", s + 1))
        .collect();
    format!(
        "Gear train of {stages} stages: cycles are input cycles (revolutions of stage 1's pinion); the life is the first mesh's to reach the limit. Samples per limiting stage: {}.",
        per.join(", ")
    )
}
