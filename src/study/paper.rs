//! The paper's section 4 as one study: the wear study of 4.2 (dynamic and quasi-static),
//! and the dynamic response at the wear states of 4.1.
//!
//! A wear state "maximum wear depth X um" is the dynamic wear study's own profile (pinion
//! and gear, from the first update whose maximum pinion wear reaches X, or the last one)
//! scaled so that the maximum pinion wear is exactly X; its roughness is the case's
//! roughness-versus-wear law at X (docs/MODEL.md).

use super::model::Model;
use super::wear_loop::{run_wear_modes, WearMode, WearRun};
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::summary::ResponseSummary;
use crate::wear::WearState;
use rayon::prelude::*;

/// The wear states of the paper's section 4.1, um.
pub const PAPER_WEAR_STATES_UM: [f64; 3] = [0.1, 0.5, 1.0];

/// The dynamic response at one wear state.
pub struct WearStateResult {
    /// The wear state: the deepest pinion wear, µm (one of [`PAPER_WEAR_STATES_UM`]; the
    /// profile is scaled to it).
    pub max_wear_um: f64,
    /// Composite RMS roughness at that wear, µm.
    pub roughness_um: f64,
    /// The wear profiles at the state.
    pub wear: WearState,
    /// The steady-state dynamic response on them.
    pub response: DynamicResponse,
    /// Its headline numbers.
    pub summary: ResponseSummary,
}

/// Everything of the paper's section 4.
pub struct PaperStudy {
    /// The wear study with the dynamic solver.
    pub dynamic: WearRun,
    /// The wear study with the quasi-static solver.
    pub quasi_static: WearRun,
    /// The dynamic response at each of the paper's wear states.
    pub wear_states: Vec<WearStateResult>,
}

/// The wear profile of a state: the dynamic run's first record reaching `target_m` (or its
/// last), scaled to `target_m`.
pub fn wear_state_from_run(run: &WearRun, target_m: f64) -> WearState {
    let rec = run
        .records
        .iter()
        .find(|r| r.wear.max_pinion_m() >= target_m)
        .or_else(|| run.records.last())
        .expect("a run has records");
    rec.wear.scaled_to_max_pinion(target_m)
}

/// The dynamic response at the wear states of section 4.1, taken from the dynamic run, in
/// parallel.
pub fn paper_wear_states(model: &Model, dynamic: &WearRun) -> anyhow::Result<Vec<WearStateResult>> {
    PAPER_WEAR_STATES_UM
        .par_iter()
        .map(|um| -> anyhow::Result<WearStateResult> {
            let wear = wear_state_from_run(dynamic, um * 1e-6);
            let response = model.dynamic(&wear, &ExternalError::none())?;
            Ok(WearStateResult {
                max_wear_um: *um,
                roughness_um: model.roughness_for(&wear),
                summary: ResponseSummary::of(&response),
                wear,
                response,
            })
        })
        .collect()
}

/// Run the whole study; `on_update(mode, run)` after every wear update (progress,
/// checkpoints). The two wear runs go in parallel, then the wear states.
pub fn run_paper_study(
    model: &Model,
    start_dynamic: WearRun,
    start_quasi_static: WearRun,
    on_update: &(dyn Fn(WearMode, &WearRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<PaperStudy> {
    let mut runs = run_wear_modes(model, vec![start_dynamic, start_quasi_static], on_update)?;
    let (Some(quasi_static), Some(dynamic)) = (runs.pop(), runs.pop()) else {
        anyhow::bail!("the wear runs returned no result");
    };
    let wear_states = paper_wear_states(model, &dynamic)?;
    Ok(PaperStudy {
        dynamic,
        quasi_static,
        wear_states,
    })
}
