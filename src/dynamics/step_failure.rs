//! Why an integration over a period failed, and what helps.

/// Why an integration over a mesh period failed.
#[derive(Debug, Clone, thiserror::Error)]
#[error(
    "the integrator failed at t = {time_s:.6e} s (mesh phase {phase_deg:.3} deg of the \
     mesh period; DTE {dte_um:.4} µm, mesh force {force_n:.1} N): {reason}; {}",
    advice(*.intervals, *.tolerance)
)]
pub struct StepFailure {
    /// Time at which the step failed, s.
    pub time_s: f64,
    /// The first mesh's phase at the failure, degrees of its mesh period.
    pub phase_deg: f64,
    /// The first mesh's dynamic transmission error at the failure, µm.
    pub dte_um: f64,
    /// The first mesh's force at the failure, N.
    pub force_n: f64,
    /// What failed (the integrator's message).
    pub reason: String,
    /// Node intervals of the period grid of the stepper.
    pub intervals: usize,
    /// Local error tolerance of the stepper, relative to the state's scales.
    pub tolerance: f64,
}

/// Tolerance below which round-off in the error estimate, not the grid, can be what
/// fails (the `numerics.integration_tolerance` range's note: 1e-8 fails at 0.5 Hz on 20
/// nodes, 1e-10 at the first step).
const TIGHT_TOLERANCE: f64 = 1e-7;

/// What helps after a failed step: more grid nodes (a step never crosses a node, so the
/// error control restarts from shorter steps at every node, and the floor
/// (`H_MIN_FLOOR_S` of [`super::period`]) is at most a fixed fraction of the node spacing). A smaller
/// tolerance asks for smaller steps still.
fn advice(intervals: usize, tolerance: f64) -> String {
    let tight = if tolerance < TIGHT_TOLERANCE {
        format!(
            "; with numerics.integration_tolerance = {tolerance:e}, near the floor where round-off reaches the error estimate, a larger value may help too"
        )
    } else {
        String::new()
    };
    format!(
        "raise numerics.steps_per_mesh_period (the period has {intervals} node intervals; more nodes let the error control restart from shorter steps at each of them); a smaller numerics.integration_tolerance asks for smaller steps still and does not help{tight}"
    )
}
