//! A sweep of helical pairs (`gear.helix_angle_deg` > 0): each case is built through the
//! planar model of `gearwear dynamics` and `gearwear wear` (`Model::dynamics_from_case`),
//! and the table holds a helical pair's columns (`study::sweep::helical_row`) when the
//! base case is helical or an axis gives the helix angle a value other than 0, decided
//! from the plan so that every shard writes the same columns.

use crate::config::load::case_with;
use crate::config::Case;
use crate::study::sweep::helical_row::HELIX_KEY;
use crate::study::sweep::{SweepPlan, SweepRun};
use crate::study::Model;

/// Whether the sweep's table holds a helical pair's columns (module docs). A value that
/// does not load is named by `cases::check_values`, before this is asked.
pub fn helical_table(base: &Case, plan: &SweepPlan) -> bool {
    // A planetary set's row has the set's columns (its model refuses a helix angle).
    if base.planetary.is_some() {
        return false;
    }
    base.gear.helix_angle_deg != 0.0
        || plan
            .axes
            .iter()
            .filter(|a| a.key == HELIX_KEY)
            .flat_map(|a| &a.values)
            .any(|v| {
                case_with(base, &[(HELIX_KEY, v.value.clone())])
                    .is_ok_and(|c| c.gear.helix_angle_deg != 0.0)
            })
}

/// The first reason a helical or planetary case of a sweep cannot be run (a dynamics or a
/// wear sweep alike),
/// if any: what its model refuses (a planetary set has no sweep model yet; a helical
/// pair's planar model refuses per-tooth errors, profile modifications, faults, ...). A
/// helical pair's wear under a `[load_spectrum]` runs (`duty::study::run_sweep_case`,
/// docs/MODEL.md 11.7).
///
/// A wear sweep (`run`) also refuses what the wear studies do not take on a helical pair
/// (`study::helical_teeth::wear_refusals`: per-tooth inputs, the tilting keys).
pub fn refusal(case: &Case, run: SweepRun) -> Option<String> {
    if run == SweepRun::Wear && case.stage.is_empty() {
        if let Some(r) = crate::study::helical_teeth::wear_refusals(case, "a wear sweep") {
            return Some(r);
        }
    }
    let e = Model::dynamics_from_case(case).err()?;
    e.0.into_iter().next()
}
