//! The time of the dynamic evaluations of the jobs that run one case
//! ([`super::case_jobs`]): each is a search for the periodic orbit
//! (`dynamics::period_search`), cold (from the static equilibrium) or warm (from the
//! previous wear update's periodic state, `study::wear_loop::start_of`), as the
//! run-to-failure jobs count theirs ([`super::chains`]).
//!
//! # Formula
//!
//! An evaluation integrates whole base periods (a mesh period; a train's common period),
//! each costing t_p = [`SECONDS_PER_MESH_PERIOD`] x the speed's scale
//! (`chains::speed_scale`: (T_m / T_30Hz)^(1/3), the error control's steps and their
//! cost in a longer period) x max(S / [`STEPS_PER_MESH_PERIOD`], (1e-5 / tol_i)^(1/3), 1)
//! (a finer grid, a tighter `numerics.integration_tolerance`) x `train_factor` and
//! [`TRAIN_STEP_FACTOR`] for a train x `axial_factor` x the planetary set's step factor
//! x [`TOOTH_RESOLVED_FACTOR`] for a tooth-resolved mesh. With d = max(0, log10(1e-6 /
//! tol)), the decades of `numerics.steady_state_tolerance` below its default:
//! - *cold* (each wear study's first update: each mode, each bin of a spectrum, each run
//!   of a life table; `gearwear dynamics`; the wear states of `run`): K_c =
//!   [`COLD_PERIODS`] + [`PERIODS_PER_DECADE`] d periods of the quasi-Newton search from
//!   rest, its recorded period among them;
//! - *warm* (every later update): K_w = [`WARM_PERIODS`] + [`PERIODS_PER_DECADE`] d
//!   periods, each at [`WORN_STEP_FACTOR`] (the worn profile's gap bends at every point
//!   of the wear grid, and the error control cuts steps there);
//! - a train, cold or warm: 1 + W / c_1 base periods with the splice (W the mesh-1
//!   periods its map takes to forget the start, [`TRAIN_RUN_IN_PERIODS`] at 30 Hz and
//!   1e-6, growing as W does with the mesh frequency and ln(1 / tol); c_1 the mesh-1
//!   periods of a base period), taken where W <= c_1 / 2; else 3 (a period, a second
//!   to confirm, the recorded one); the warm ones at [`WORN_STEP_FACTOR`];
//! - a tooth-resolved case adds its run-in and its excitation period of P periods to every
//!   evaluation, cold or warm ([`super::teeth::budget_term`], at t_p): the pass over P
//!   periods is made whatever the start;
//! - every wear update adds [`SECONDS_PER_WEAR_UPDATE`] (its worn model, record and
//!   increments).
//!
//! The period counts are the searches' measured counts with a margin, not a worst case:
//! a lightly damped case (a mesh near a resonance) or a train whose splice fails its
//! check takes more periods (up to `numerics.max_mesh_periods`, where the search gives
//! up); the rate's [`SLOWER_MACHINE_FACTOR`] is the margin such a case has.
//!
//! Before (issue 29), every evaluation was counted as P_c + P_e = 34 periods of 700 steps
//! at 3 us: a cold search of 30 periods, the recorded window integrated (one period is
//! recorded and repeated) and the error control's steps of 0.5 Hz at any speed: the
//! two-stage example's wear study at 28 times its CPU time, the paper's pair's at 7 to 13
//! (docs/PERFORMANCE.md, "The wear study's time budget").

use super::chains::speed_scale;
use super::evaluation::{axial_factor, train_factor, SLOWER_MACHINE_FACTOR};
use crate::config::case::Case;

/// CPU seconds of one mesh period of the built-in pair's search at 30 Hz (its error
/// control's ~214 steps, 1 370 right-hand sides and 31 factorisations): measured 0.81
/// ms idle (`evaluation/steady_state_dynamic`, 3.25 ms for 4 periods, 2026-11-30 16:21
/// UTC, docs/PERFORMANCE.md) and 0.98 ms at load 4 (3.93 ms, 2026-11-30 21:08 UTC),
/// counted 1 ms, times [`SLOWER_MACHINE_FACTOR`].
pub const SECONDS_PER_MESH_PERIOD: f64 = 1e-3 * SLOWER_MACHINE_FACTOR;
/// Steps per mesh period at 30 Hz, new or worn teeth, where
/// [`SECONDS_PER_MESH_PERIOD`] was measured: 214-228 on the paper's pair (to 308 worn
/// 4e5 cycles deep, which [`WORN_STEP_FACTOR`] covers), 256 on
/// `examples/helical_pair.toml`; counted 260. A grid of more nodes
/// (`numerics.steps_per_mesh_period`) costs its share more.
pub const STEPS_PER_MESH_PERIOD: f64 = 260.0;
/// Periods of a cold search at the default tolerance 1e-6, its recorded period among
/// them: measured 4 on the paper's pair (and on its tooth-resolved search), 3 at 0.2 Hz
/// and on the helical example (2026-11-30); counted 5.
pub const COLD_PERIODS: f64 = 5.0;
/// Periods of a warm update at the default tolerance: measured 3 on the paper's pair at
/// 30 Hz (every update to 4e5 cycles), 2 at 0.2 Hz (2026-11-30); counted 3.
pub const WARM_PERIODS: f64 = 3.0;
/// Periods a search adds per decade of `numerics.steady_state_tolerance` below 1e-6:
/// measured at 1e-10 on the paper's pair, cold 5 (against 4) and warm 5 (against 3);
/// counted 0.5, the warm's.
pub const PERIODS_PER_DECADE: f64 = 0.5;
/// Steps (and their cost) of a worn flank's period over new teeth's: measured 1.07 on
/// the paper's pair at 4e4 cycles, 1.44 at 4e5, 1.47 on the two-stage example at 4e4
/// (its last update, docs/PERFORMANCE.md "The splice"), 1.71 at 0.2 Hz (where the speed's
/// scale, 5.2 against the 3.0 measured on new teeth, leaves room); counted 1.5.
pub const WORN_STEP_FACTOR: f64 = 1.5;
/// Mesh-1 periods a train's map takes to forget its start (the splice's W) at 30 Hz and
/// the default tolerance: 8 on the two-stage example (docs/PERFORMANCE.md, "The splice");
/// counted 10.
pub const TRAIN_RUN_IN_PERIODS: f64 = 10.0;
/// A train's base period over `train_factor` single-pair periods: its step costs more than
/// its states' share (a 14 x 14 Schur complement per factorisation, 108 k instructions
/// against 29 k, 3.7 x for 1.75 x the states) and its fast modes ring after every event
/// of either mesh: measured 162 single-pair periods of CPU time per base period of the
/// two-stage example (166 ms for 1.26 base periods idle, against 0.81 ms a pair's
/// period, 2026-11-30) against `train_factor` 94.5: 1.7.
pub const TRAIN_STEP_FACTOR: f64 = 1.7;
/// A tooth-resolved mesh's period over the single pair's (each engaged tooth pair's own
/// stiffness, errors and faults at every right-hand side, and the update's per-tooth
/// wear over the excitation period): measured on `examples/teeth/grade6_runout_spall.toml`
/// (589 mesh periods, 2026-11-30, load 8): the same 226 steps a period at 2.6 ms (the
/// pair's 1.0 ms at that load), 3.3 ms with the per-tooth wear of the update; counted 3.5.
pub const TOOTH_RESOLVED_FACTOR: f64 = 3.5;
/// CPU seconds of a wear update besides its evaluation (the worn model's gap and mesh,
/// the record, its increments along the path): measured 4.6-5.2 ms on the paper's pair
/// (a study's CPU time less its evaluations', 11 and 49 updates, 2026-11-30), counted 5
/// ms, times [`SLOWER_MACHINE_FACTOR`].
pub const SECONDS_PER_WEAR_UPDATE: f64 = 5e-3 * SLOWER_MACHINE_FACTOR;

/// Steps of a recorded period of `case` at most, worn teeth included: its samples (a
/// helical pair's update spreads each over its slices, `super::helical`).
pub fn samples_per_period(case: &Case) -> f64 {
    STEPS_PER_MESH_PERIOD * WORN_STEP_FACTOR * speed_scale(case) * grid_scale(case)
}

/// How much more a period of `case` costs for its grid and integration tolerance,
/// max(S / [`STEPS_PER_MESH_PERIOD`], (1e-5 / tol_i)^(1/3), 1).
fn grid_scale(case: &Case) -> f64 {
    let nm = &case.numerics;
    let grid = nm.steps_per_mesh_period as f64 / STEPS_PER_MESH_PERIOD;
    let tolerance = (1e-5 / nm.integration_tolerance).cbrt();
    grid.max(tolerance).max(1.0)
}

/// CPU seconds of one base period of a dynamic evaluation of `case` on new teeth, t_p
/// (module docs).
pub fn period_seconds(case: &Case) -> f64 {
    let train = if case.stage.is_empty() {
        1.0
    } else {
        train_factor(case) * TRAIN_STEP_FACTOR
    };
    let teeth = if super::teeth::excitation_periods_of(case) > 1 {
        TOOTH_RESOLVED_FACTOR
    } else {
        1.0
    };
    SECONDS_PER_MESH_PERIOD
        * speed_scale(case)
        * grid_scale(case)
        * train
        * axial_factor(case)
        * super::planetary::step_factor(case)
        * teeth
}

/// Decades of `numerics.steady_state_tolerance` below the default 1e-6, at least 0.
fn decades_below_default(case: &Case) -> f64 {
    (1e-6 / case.numerics.steady_state_tolerance)
        .log10()
        .max(0.0)
}

/// Base periods of a train's search, cold or warm (module docs): 1 + W / c_1 with the
/// splice, 3 without it.
fn train_periods(case: &Case) -> f64 {
    let c1 = super::evaluation::first_mesh_periods(case);
    let mesh_hz = case.operating.input_speed_hz * super::evaluation::input_pinion_teeth(case);
    let speed = (mesh_hz / 570.0).max(1.0);
    let w = TRAIN_RUN_IN_PERIODS * speed * (1.0 + decades_below_default(case) / 6.0);
    if c1 >= 4.0 && 2.0 * w <= c1 {
        1.0 + w / c1
    } else {
        3.0
    }
}

/// Base periods a cold evaluation of `case` integrates (module docs), at most
/// `numerics.max_mesh_periods` and one recorded period.
pub fn cold_periods(case: &Case) -> f64 {
    if !case.stage.is_empty() {
        return train_periods(case);
    }
    let k = COLD_PERIODS + PERIODS_PER_DECADE * decades_below_default(case);
    k.min(case.numerics.max_mesh_periods as f64 + 1.0)
}

/// Base periods a warm update of `case` integrates, counted in periods of new teeth's
/// cost (module docs).
pub fn warm_periods(case: &Case) -> f64 {
    let k = if case.stage.is_empty() {
        (WARM_PERIODS + PERIODS_PER_DECADE * decades_below_default(case))
            .min(case.numerics.max_mesh_periods as f64 + 1.0)
    } else {
        train_periods(case)
    };
    k * WORN_STEP_FACTOR
}

/// CPU seconds of `cold` cold and `warm` warm dynamic evaluations of `case`, `updates` of
/// them wear updates.
pub fn evaluations_seconds(case: &Case, cold: f64, warm: f64, updates: f64) -> f64 {
    (cold * cold_periods(case) + warm * warm_periods(case)) * period_seconds(case)
        + updates * SECONDS_PER_WEAR_UPDATE
}
