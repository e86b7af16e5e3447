//! Steady-state evaluation: find the mesh-periodic solution, then record whole periods.
//!
//! Steady state is found, not assumed: quasi-Newton shooting on the one-period map
//! ([`super::shooting`]) from the static equilibrium or from a given periodic state
//! (warm start), each iteration one mesh period of the error-controlled integration of
//! [`super::period`]. It stops when the estimated distance of the start state from the
//! periodic orbit, relative to the state's scales, is below the case's tolerance. One
//! period of the orbit is recorded (the last search period when it started close enough,
//! else one more) and repeated over the evaluated window; its periodicity (the change of
//! the state over that period) is reported. The search itself is [`super::period_search`].

use super::grid::excitation_periods;
use super::model::GearSystem;
use super::period_search::{window_repeats, DynamicsError, MeshPeriodSearch, SteadyStateSettings};
use super::recorder::Recorder;
use super::response::DynamicResponse;

/// Integrate `sys` to its mesh-periodic steady state and record the evaluated window,
/// starting from the static equilibrium.
pub fn solve_steady_state(
    sys: &GearSystem,
    settings: &SteadyStateSettings,
) -> Result<DynamicResponse, DynamicsError> {
    solve_steady_state_from(sys, settings, None)
}

/// As [`solve_steady_state`], starting at mesh phase 0 from `start` (a state at a
/// mesh-period boundary, e.g. [`DynamicResponse::end_state`] of a neighbouring case)
/// instead of the static equilibrium. A tooth-resolved mesh whose teeth differ repeats
/// only over several mesh periods: its steady state is found over those
/// ([`super::hunting`]).
pub fn solve_steady_state_from(
    sys: &GearSystem,
    settings: &SteadyStateSettings,
    start: Option<&[f64]>,
) -> Result<DynamicResponse, DynamicsError> {
    let periods = excitation_periods(sys).ok_or(DynamicsError::PeriodTooLong)?;
    if periods > 1 {
        return super::hunting::solve_hunting(sys, settings, start, periods);
    }
    let mut search = MeshPeriodSearch::new(sys, settings, start)?;
    let recorded = search.run(settings, start.is_some(), true)?;
    let (rec, y_start, y_end) = match recorded {
        Some(r) => r,
        None => {
            search.replay();
            let y0 = search.start_state();
            let mut y = y0.clone();
            let mut rec = Recorder::new(sys, 1);
            search.ps.integrate(0.0, y.as_mut_slice(), &mut rec)?;
            (rec, y0, y)
        }
    };
    let periodicity = search.distance_between(&y_start, &y_end);
    let period = search.ps.period();
    let (signals, paths) = rec.window(
        period,
        window_repeats(sys, settings, 1),
        y_start.as_slice(),
        y_end.as_slice(),
    );
    Ok(search.response(signals, paths, &rec, period, 1, periodicity, &y_end))
}
