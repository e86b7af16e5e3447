//! A sweep of planetary sets (`[planetary]`): the checks before any case runs. A dynamics
//! sweep (`--run dynamics`) takes a set: its row holds each sun-planet and ring-planet
//! mesh's force and dynamic factor and each planet's load sharing factor
//! (`study::sweep::planetary_row`); a wear sweep (`--run wear`) runs the set's wear study
//! in both modes and adds every member flank's wear (`study::sweep::planetary_wear_row`).
//! Every case must have the base case's number of planets (refused otherwise, naming
//! both). A continuation is not built for a set yet: refused before any case runs.

use super::super::JobError;
use crate::config::Case;
use crate::remedy::{Arg, Problem, Words};
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::sweep::planetary_wear_row::sweep_wear_model;
use crate::study::sweep::SweepRun;
use crate::study::Model;

/// The number of planets of `case` (0: not a planetary set).
pub fn planets_of(case: &Case) -> usize {
    case.planetary
        .as_ref()
        .map_or(0, |p| usize::try_from(p.planets).unwrap_or(0))
}

/// Refuse a case whose number of planets is not the base case's (naming both), before
/// any case runs. `cases`: each planned case with its name in messages
/// (`case ID (KEY=VALUE, ...)`).
pub fn check_planetary(base: &Case, cases: &[(String, &Case)]) -> Result<(), JobError> {
    let n = planets_of(base);
    if n == 0 && cases.iter().all(|(_, c)| c.planetary.is_none()) {
        return Ok(());
    }
    let Some((name, c)) = cases.iter().find(|(_, c)| planets_of(c) != n) else {
        return Ok(());
    };
    Err(JobError::input(Problem::new(format!(
        "{name} has {} planet(s) and the base case {n}: a sweep's columns are those of one planetary set (each mesh's and each planet's), so every case must keep the base case's `planetary.planets`",
        planets_of(c),
    ))))
}

/// Refuse a continuation on a planetary set: a branch is followed from each point's
/// periodic state, which the set's steady state does not take yet.
pub fn refuse_continuation(base: &Case) -> Result<(), JobError> {
    if base.planetary.is_none() {
        return Ok(());
    }
    Err(Problem::of(
        Arg::Continuation,
        Words::new().text(
            "a planetary set ([planetary]) is not followed along a branch yet (its steady state starts from the static equilibrium); sweep it without it",
        ),
    )
    .into())
}

/// Why the model of `case` cannot be built for `run` (the set's dynamic model for a
/// planetary case, its wear model with both modes for a wear sweep; else the pair's or
/// train's), or `None`.
pub fn model_error(case: &Case, run: SweepRun) -> Option<String> {
    if case.planetary.is_some() {
        return match run {
            SweepRun::Dynamics => PlanetaryDynamics::from_case(case).err(),
            SweepRun::Wear => PlanetaryWearModel::from_case(case)
                .and_then(sweep_wear_model)
                .err(),
        }
        .map(|e| e.to_string());
    }
    Model::dynamics_from_case(case).err().map(|e| e.to_string())
}
