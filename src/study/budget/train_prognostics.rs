//! The cost of a gear train's (`[[stage]]`) forward run in `calibrate` and `predict`
//! (`prognostics::train_forward`): the train's wear loop, whose blocks the fastest mesh
//! cuts (per input cycle) and whose updates keep every mesh's record.
//!
//! - **Wear per input cycle.** Mesh k's pinion turns c_k = prod_(j<k) z_p,j / z_g,j
//!   times per input cycle and carries T_in / c_k (a lossless train, torque on the input
//!   shaft); its largest wear per pinion cycle at that torque is
//!   `nominal_wear_per_cycle_m` of its own pair (Archard's k p0 s, paper eq. 14). The
//!   train's blocks follow the largest c_k rate_k over the meshes (`train_wear::next_block`),
//!   so the updates of a run follow it.
//! - **Records.** N meshes' records per update, each mesh's load along its path sampled
//!   over the train's base period (sum_k N_k mesh periods, as `super::dataset` counts a
//!   train's trajectory), plus the train's periodic state 2 (4 + 12 N).
//!
//! The time per evaluation is the train's already (`super::chains::run_to_failure_scale`
//! holds `super::evaluation::train_factor`).

use super::evaluation::{base_mesh_periods, nominal_wear_per_cycle_m};
use crate::config::case::Case;
use crate::geometry::GearPair;

/// Largest wear per input cycle over the meshes of the train of `case` at its nominal
/// load, m (see the module docs); None for a single pair or a stage without a pair.
pub fn train_wear_per_input_cycle_m(case: &Case) -> Option<f64> {
    if case.stage.is_empty() {
        return None;
    }
    let mut c_k = 1.0;
    let mut rate: f64 = 0.0;
    for s in &case.stage {
        let gear = s.gear_section(&case.gear);
        let pair = GearPair::from_case(&gear).ok()?;
        let mut c = case.clone();
        c.gear = gear.clone();
        c.operating.load_torque_nm = case.operating.load_torque_nm / c_k;
        rate = rate.max(c_k * nominal_wear_per_cycle_m(&c, &pair));
        c_k *= gear.teeth_pinion.max(1) as f64 / gear.teeth_gear.max(1) as f64;
    }
    Some(rate)
}

/// Numbers one update of a train's forward run keeps (see the module docs), with `g`
/// points per profile and `s_dyn` steps per mesh period; None for a single pair.
pub fn train_record_numbers(case: &Case, g: f64, s_dyn: f64) -> Option<f64> {
    if case.stage.is_empty() {
        return None;
    }
    let n = case.stage.len() as f64;
    let periods = base_mesh_periods(case);
    Some(n * (4.0 * g + 2.0 * s_dyn * periods + 48.0) + 2.0 * (4.0 + 12.0 * n))
}
