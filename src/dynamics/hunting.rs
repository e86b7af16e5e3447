//! The steady state of a tooth-resolved mesh over its excitation period: P mesh periods
//! (`ToothMesh::periods`; lcm(z1, z2) = 589 for the paper's 19/31 pair with both gears'
//! teeth differing).
//!
//! The excitation repeats only every P mesh periods, so the orbit sought is P-periodic.
//! The map over P periods contracts by e^(-sigma P T) (sigma the slowest decay rate of the
//! damped model, T the mesh period): for the paper's case ~1e-560, so one pass from a
//! state close to the orbit is already periodic, and a quasi-Newton search over it would
//! waste passes. The solution is found in three steps:
//! 1. a settled mesh-period state: the mesh-periodic orbit of the teeth of mesh cycle 0
//!    meeting again and again, found by the one-period shooting of [`super::steady`]
//!    (a few periods; its step plan is kept);
//! 2. a run-in over the last W mesh periods of the excitation period, ending at its start,
//!    W = 1.2 ln(1 / tolerance) / (sigma T) with sigma from the averaged linear model
//!    (a 20 % margin for the uneven decay under time-varying stiffness; at least 2, at
//!    most P): what the orbit of cycle 0 differs from the true one decays to the
//!    tolerance;
//! 3. one pass over the P periods, recorded, whose periodicity (the change of the state
//!    over it, relative to the state scales) is checked against the tolerance; a pass
//!    that is not periodic enough is followed by another from its end state.
//!
//! The steps follow the plan of step 1 in every period, refined where the error test
//! fails (without keeping the refinements). A mesh whose teeth are all alike (P = 1) never
//! comes here (`steady` takes P > 1 only), but if it does (a test forces it), the run-in is
//! one period (W is capped at P) and every period replays the plan from the periodic state,
//! repeating the one-period solution.

pub use super::modal::{run_in_periods, slowest_decay_rate};
use super::model::{GearSystem, State};
use super::period::PlanMode;
use super::period_search::{DynamicsError, MeshPeriodSearch, SteadyStateSettings};
use super::recorder::Recorder;
use super::response::DynamicResponse;

/// Steady state over `periods` mesh periods (see the module docs), from the static
/// equilibrium or `start` (a state at the start of the excitation period, e.g. the
/// [`DynamicResponse::end_state`] of an earlier evaluation).
pub fn solve_hunting(
    sys: &GearSystem,
    settings: &SteadyStateSettings,
    start: Option<&[f64]>,
    periods: usize,
) -> Result<DynamicResponse, DynamicsError> {
    let mut search = MeshPeriodSearch::new(sys, settings, start)?;
    search.run(settings, start.is_some(), false)?;
    let mode = match search.ps.plan_mode() {
        PlanMode::Free => PlanMode::Free,
        _ => PlanMode::ReplayFixed,
    };
    search.ps.set_plan_mode(mode);
    let t_mesh = search.ps.period();
    let mut y: State = search.start_state();
    // Run-in over the last W periods of the excitation period.
    let w = run_in_periods(sys, t_mesh, settings.tolerance, periods);
    for c in periods - w..periods {
        search
            .ps
            .integrate(c as f64 * t_mesh, y.as_mut_slice(), &mut ())?;
    }
    search.periods += w;
    let budget = settings.max_mesh_periods.max(2 * periods + w);
    loop {
        let y_start = y.clone();
        let mut rec = Recorder::new(sys, periods);
        for c in 0..periods {
            search
                .ps
                .integrate(c as f64 * t_mesh, y.as_mut_slice(), &mut rec)?;
        }
        search.periods += periods;
        let periodicity = search.distance_between(&y_start, &y);
        if periodicity < settings.tolerance || search.periods + periods > budget {
            if periodicity >= settings.tolerance {
                return Err(DynamicsError::NotPeriodic {
                    periods: search.periods,
                    change: periodicity,
                    tolerance: settings.tolerance,
                });
            }
            let recorded_s = periods as f64 * t_mesh;
            let repeats = super::period_search::window_repeats(sys, settings, periods);
            let (signals, paths) =
                rec.window(recorded_s, repeats, y_start.as_slice(), y.as_slice());
            return Ok(search.response(signals, paths, &rec, recorded_s, periods, periodicity, &y));
        }
    }
}
