//! What every estimate is built from: the rates of the reference machine (2-core AMD
//! EPYC, docs/PERFORMANCE.md) for an integrator step, a quasi-static step and a point of
//! the mesh-stiffness table; the steps a dynamic evaluation takes per mesh period and the
//! periods it needs to settle; the largest wear per cycle at the nominal load and the
//! updates of a wear study that follow from it.

use crate::config::case::{Case, NumericsSection};
use crate::geometry::GearPair;
use crate::study::domain::nominal_contacts;

/// How much slower than the machine a rate was measured on a run may be (another
/// processor, or a core shared under load): the rates measured for issue 33 (per record
/// sample, per channel) are multiplied by it, a stated factor rather than a rounding.
pub const SLOWER_MACHINE_FACTOR: f64 = 2.0;
/// Integrator step on the reference machine, s.
pub const SECONDS_PER_STEP: f64 = 3e-6;
/// Quasi-static equilibria for one step of the grid (two per step), s.
pub const SECONDS_PER_QUASI_STATIC_STEP: f64 = 2.4e-6;
/// One point of the mesh-stiffness table, s.
pub const SECONDS_PER_TABLE_POINT: f64 = 2e-6;
/// Periods to settle per decade of `numerics.steady_state_tolerance`.
pub const PERIODS_TO_SETTLE_PER_DECADE: f64 = 5.0;
/// Recorded samples per mesh period of the dynamic solver at the default integration
/// tolerance 1e-5, bounding its step count from above: measured 662 at 0.5 Hz input
/// (the most: the slow mesh leaves the fast modes to the error control), 230 at 30 Hz,
/// 200 at 300 Hz (the grid nodes). At 1e-7, 1e-8 and 1e-9 the measured counts (2733,
/// 5761, 12412 at 0.5 Hz) stay below this bound's 3250, 7000 and 15080.
pub const ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE: f64 = 700.0;
/// Dynamic wear per cycle over the quasi-static estimate (dynamic factor margin).
pub const DYNAMIC_WEAR_FACTOR: f64 = 1.5;

/// Steps per mesh period the error control of the dynamic solver takes, at most, at the
/// local error tolerance `tol` (dimensionless): [`ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE`]
/// x (1e-5 / tol)^(1/3), the step of a third-order method scaling as tol^(1/3).
pub fn adaptive_steps_per_period(tol: f64) -> f64 {
    ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE * (1e-5 / tol).cbrt()
}

/// Steps of a dynamic evaluation per mesh period, S_d = max(S, the error control's bound
/// [`adaptive_steps_per_period`]): the error control may add steps to the S grid nodes.
pub fn dynamic_steps_per_period(nm: &NumericsSection) -> f64 {
    (nm.steps_per_mesh_period as f64).max(adaptive_steps_per_period(nm.integration_tolerance))
}

/// Largest Archard wear per pinion cycle on either profile at the nominal load and speeds,
/// m (quasi-static): the larger of [`nominal_member_wear_per_cycle_m`]'s two.
pub fn nominal_wear_per_cycle_m(case: &Case, pair: &GearPair) -> f64 {
    let (pinion, gear) = nominal_member_wear_per_cycle_m(case, pair);
    pinion.max(gear)
}

/// Largest Archard wear per pinion cycle of the pinion's and of the gear's profile at the
/// nominal load and speeds, m (quasi-static): Archard's k p0 s at the nominal load shared
/// by paper eq. (7), Hertz pressure p0 and sliding distance s at nominal speeds along the
/// path of contact, per contact of the pinion tooth (k p0 s / u_p) and, z_p / z_g contacts
/// of a gear tooth a pinion cycle, of the gear tooth (z_p / z_g k p0 s / u_g).
pub fn nominal_member_wear_per_cycle_m(case: &Case, pair: &GearPair) -> (f64, f64) {
    let ratio = pair.pinion.teeth as f64 / pair.gear.teeth as f64;
    let k = case.wear.coefficient_m2_per_n;
    nominal_contacts(case, pair, 64)
        .iter()
        .map(|c| {
            let (up, ug) = (
                c.kinematics.pinion_velocity_m_per_s,
                c.kinematics.gear_velocity_m_per_s,
            );
            if !(up > 0.0 && ug > 0.0) {
                return (0.0, 0.0);
            }
            let slide = 2.0 * c.hertz.half_width_m * (up - ug).abs();
            let p0 = c.hertz.max_pressure_pa;
            (k * p0 * slide / up, ratio * k * p0 * slide / ug)
        })
        .fold((0.0, 0.0), |(a, b), (p, g)| (a.max(p), b.max(g)))
}

/// Teeth of the input pinion, the one whose mesh frequency the input speed sets: stage
/// 1's pinion of a gear train (its `[[stage]]` table may give its own teeth), the pair's
/// otherwise; at least 1.
pub(crate) fn input_pinion_teeth(case: &Case) -> f64 {
    let z = match case.stage.first() {
        Some(s) => s.gear_section(&case.gear).teeth_pinion,
        None => case.gear.teeth_pinion,
    };
    z.max(1) as f64
}

/// Updates (records) of a wear study whose largest wear per cycle is `rate_m`: U = 1 +
/// ceil(C / n), the block n being `wear.block_cycles` cut to `wear.threshold_um` /
/// `rate_m`, at least one cycle (`study::wear_loop::block_length`).
pub fn wear_updates(case: &Case, rate_m: f64) -> f64 {
    let w = &case.wear;
    let threshold = w.threshold_um * 1e-6;
    let mut block = w.block_cycles;
    if rate_m > 0.0 && block * rate_m > threshold {
        block = (threshold / rate_m).floor().max(1.0);
    }
    1.0 + (w.total_cycles / block).ceil()
}

/// How much more a dynamic evaluation of a gear train costs than one of a single pair
/// (1 for a case without `[[stage]]`): its base period (`dynamics::grid::base_period`)
/// holds sum_k N_k mesh periods of its meshes, each with its events and steps, and each
/// step costs about (states / 16) times the single pair's (a right-hand side per mesh,
/// linear algebra on the larger state). A train whose base period cannot be counted is
/// infinitely dear (refused).
pub fn train_factor(case: &Case) -> f64 {
    if case.stage.is_empty() {
        return 1.0;
    }
    base_mesh_periods(case) * state_factor(case)
}

/// A train's state over the single pair's 16, at least 1: what a step and a recorded
/// sample cost more.
fn state_factor(case: &Case) -> f64 {
    // Each helical stage with axial bearings adds its two bodies' axial coordinates
    // (docs/MODEL.md 4.3): 4 states.
    let axial = case
        .stage
        .iter()
        .filter(|s| {
            s.gear_section(&case.gear).helix_angle_deg != 0.0
                && s.dynamics_section(&case.dynamics)
                    .axial_bearings()
                    .iter()
                    .any(Option::is_some)
        })
        .count();
    let states = 4.0 + 12.0 * case.stage.len() as f64 + 4.0 * axial as f64;
    (states / 16.0).max(1.0)
}

/// Time factor of a dynamic evaluation of a helical pair with axial degrees of freedom
/// (docs/MODEL.md 11.6: any `dynamics.bearing_axial_stiffness_*` given), 1 otherwise: its
/// state leaves the fixed 8-coordinate path for the general one, measured 7.3 ms against
/// 4.6 ms for a cold steady state (beta 15 deg, 400 slices; 1.6), counted as 2. A train
/// takes the general path whatever its stages, its axial coordinates counted by
/// [`train_factor`]: 1. Tilting coordinates (docs/MODEL.md 11.8: any
/// `dynamics.bearing_tilt_stiffness_*`) take the general path too, with up to 24 states
/// against 16: 2 x 24 / 16 = 3 (measured 0.29 s against 0.19 s without them on the
/// built-in helical pair at 2000 steps per mesh period, 1.5, inside it).
pub fn axial_factor(case: &Case) -> f64 {
    let helical = case.stage.is_empty() && case.gear.helix_angle_deg != 0.0;
    let given = |b: [Option<(f64, f64)>; 2]| b.iter().any(Option::is_some);
    if helical && given(case.dynamics.tilt_bearings()) {
        3.0
    } else if helical && given(case.dynamics.axial_bearings()) {
        2.0
    } else {
        1.0
    }
}

/// Mesh periods of all meshes in a train's base period, sum_k N_k
/// (`dynamics::grid::chain_mesh_counts`, each stage's teeth at least 1); infinite when it
/// cannot be counted (refused).
pub fn base_mesh_periods(case: &Case) -> f64 {
    mesh_counts(case).map_or(f64::INFINITY, |c| c.iter().sum())
}

/// How many more samples a recorded base period of a train holds than a single pair's
/// mesh period, each sample of a larger state: max_k N_k (`dynamics::grid::train_nodes`
/// steps the base period at the shortest mesh period over the steps, so its samples follow
/// the mesh of most periods, not their sum) x states / 16. 1 for a single pair; infinite
/// when the train's base period cannot be counted.
pub fn train_record_factor(case: &Case) -> f64 {
    if case.stage.is_empty() {
        return 1.0;
    }
    let most = mesh_counts(case).map_or(f64::INFINITY, |c| c.iter().fold(0.0, |a, b| a.max(*b)));
    most * state_factor(case)
}

/// Periods a steady response records for `evaluated_periods` evaluated mesh periods
/// (`numerics.evaluated_mesh_periods`): those periods for a single pair; for a train,
/// whole base periods, ceil(P_e / N_1) with N_1 the first mesh's periods in a base period
/// (`dynamics::period_search::window_repeats`): a base period of 31 mesh periods holds
/// the default 4. Each recorded base period holds [`train_record_factor`] single-pair
/// periods' samples.
pub fn recorded_periods(case: &Case, evaluated_periods: f64) -> f64 {
    if case.stage.is_empty() {
        return evaluated_periods;
    }
    let first = mesh_counts(case).map_or(1.0, |c| c.first().copied().unwrap_or(1.0).max(1.0));
    (evaluated_periods / first).ceil().max(1.0)
}

/// c_1, the first mesh's periods in a train's base period (1 for a single pair or a
/// train whose base period cannot be counted).
pub fn first_mesh_periods(case: &Case) -> f64 {
    mesh_counts(case).map_or(1.0, |c| c.first().copied().unwrap_or(1.0).max(1.0))
}

/// N_k of each mesh of a train's base period (`dynamics::grid::chain_mesh_counts`), or
/// None when it overflows.
fn mesh_counts(case: &Case) -> Option<Vec<f64>> {
    let teeth: Vec<[usize; 2]> = case
        .stage
        .iter()
        .map(|s| {
            let g = s.gear_section(&case.gear);
            [g.teeth_pinion.max(1) as usize, g.teeth_gear.max(1) as usize]
        })
        .collect();
    crate::dynamics::grid::chain_mesh_counts(&teeth)
        .map(|counts| counts.iter().map(|c| *c as f64).collect())
}
