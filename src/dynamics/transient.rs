//! Transient integration under a drive (`dynamics::drive`): a run-up, a coast-down or a
//! fluctuating load, integrated as one long trajectory rather than a sequence of steady
//! states.
//!
//! The steps are those of the steady-state solver (`dynamics::period`): grid nodes at the
//! mesh events bound the steps, the ESDIRK3(2) error control chooses them in between,
//! contact-mode switches are located inside steps. The mesh events lie at fixed angles of
//! the pinion's nominal rotation, so under a drive the nodes are the times at which the
//! drive's angle reaches them (`Drive::time_at_angle`): a ramp packs them closer as it
//! speeds up. The trajectory starts from a given state at mesh phase 0 (e.g. the periodic
//! steady state at the starting speed, so no start transient is recorded).

use super::drive::Drive;
use super::grid::period_nodes_in;
use super::model::{GearSystem, State};
use super::period::{period_stepper, PeriodObserver, StepFailure};
use super::period_search::DynamicsError;

/// Node times over [0, `duration_s`] of `sys` under its drive: the mesh-event nodes of
/// every mesh period (of the first mesh: transients are of the single pair), mapped
/// through the drive's angle, `duration_s` the last.
pub fn transient_nodes(
    sys: &GearSystem,
    drive: &Drive,
    duration_s: f64,
    steps_per_mesh_period: usize,
) -> Vec<f64> {
    let parts = &sys.mesh(0).parts;
    let pair = parts.pair;
    // At unit speed the node "times" are the node angles within one mesh period.
    let angles = period_nodes_in(pair, parts.contact.reach(), 1.0, steps_per_mesh_period);
    let period = pair.mesh_angle_rad();
    let end_angle = drive.angle(duration_s);
    let mut nodes = Vec::with_capacity(((end_angle / period).ceil() as usize + 1) * angles.len());
    let mut k = 0usize;
    'periods: loop {
        let base = k as f64 * period;
        for a in &angles[..angles.len() - 1] {
            let theta = base + a;
            if theta >= end_angle {
                break 'periods;
            }
            nodes.push(drive.time_at_angle(theta));
        }
        k += 1;
    }
    // Close on the end without a sliver of a last interval (< 1/4 of a typical one).
    let typical = duration_s / nodes.len().max(1) as f64;
    while nodes.len() > 1 && duration_s - nodes[nodes.len() - 1] < 0.25 * typical {
        nodes.pop();
    }
    nodes.push(duration_s);
    nodes
}

/// Integrate `sys` (a system with `drive`) from `start` at t = 0 to `duration_s`,
/// showing every step to `obs`; returns the end state.
pub fn integrate_transient(
    sys: &GearSystem,
    drive: &Drive,
    start: &[f64],
    duration_s: f64,
    steps_per_mesh_period: usize,
    tolerance: f64,
    obs: &mut dyn PeriodObserver,
) -> Result<State, DynamicsError> {
    let nodes = transient_nodes(sys, drive, duration_s, steps_per_mesh_period);
    let mut ps =
        period_stepper(sys, nodes, tolerance).map_err(|e| DynamicsError::Setting(e.to_string()))?;
    let mut y = State::from_column_slice(start);
    ps.integrate(0.0, y.as_mut_slice(), obs)
        .map_err(|e: StepFailure| DynamicsError::Integrator(e))?;
    Ok(y)
}
