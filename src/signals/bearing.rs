//! The forces the shafts exert on the housing through their bearings: what drives the
//! transfer path to the sensors.
//!
//! The bearings of paper eq. (1) are springs and dampers between each gear's centre and
//! the housing, in x and y: the force on the housing is +k_b q + c_b dq/dt for q = x_p,
//! y_p (pinion bearing) and x_g, y_g (gear bearing), the reaction of the restoring force
//! -k_b q - c_b dq/dt on the gear body.

use crate::dynamics::assembly::train::{gear_body, pinion_body};
use crate::dynamics::assembly::{Assembly, Dof};
use crate::dynamics::fourier::HermitePeriod;
use crate::dynamics::model::dof;
use crate::dynamics::params::DynamicParams;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::summary::evaluated_periods;

/// The bearing forces on the housing, the inputs of a transfer path, in the order of
/// [`BearingForces::force_n`]: pinion x, pinion y, gear x, gear y (the model's frame).
pub(crate) const INPUTS: [&str; 4] = ["pinion_x", "pinion_y", "gear_x", "gear_y"];

/// Bearing forces on the housing over one period of a periodic response, N, in
/// `INPUTS` order, at the solver's samples, with their rates at both ends of the step
/// leaving each sample (N/s: k_b dq/dt + c_b d2q/dt2 with the step's own accelerations),
/// which make the solution between the samples (`signal`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BearingForces {
    /// Time of each sample from the start of the period, s.
    pub time_s: Vec<f64>,
    /// Force of each input at each sample, N (`INPUTS` order).
    pub force_n: [Vec<f64>; 4],
    /// Rates at the start and the end of each step; empty for a response without steps
    /// (quasi-static), whose forces are then the chords of the samples.
    pub rate_start_n_per_s: [Vec<f64>; 4],
    /// Rate of each input's force at the end of each step, N/s (`INPUTS` order; empty as
    /// above).
    pub rate_end_n_per_s: [Vec<f64>; 4],
    /// Length of the period, s.
    pub period_s: f64,
}

impl BearingForces {
    /// Input j over the period as the solver's solution: the cubic Hermite interpolant of
    /// the forces and their rates (`dynamics::fourier`), or the chords without rates.
    pub fn signal(&self, j: usize) -> HermitePeriod {
        let n = self.time_s.len();
        if self.rate_start_n_per_s[j].len() != n || self.rate_end_n_per_s[j].len() != n {
            return HermitePeriod::linear(
                self.time_s.clone(),
                self.force_n[j].clone(),
                self.period_s,
            );
        }
        HermitePeriod {
            t: self.time_s.clone(),
            x: self.force_n[j].clone(),
            slope_start: self.rate_start_n_per_s[j].clone(),
            slope_end: self.rate_end_n_per_s[j].clone(),
            period_s: self.period_s,
        }
    }
}

/// Period of a periodic steady-state response, s: the period its recorded window
/// repeats (one mesh period for identical teeth, the tooth-resolved mesh's period, up to
/// the hunting period lcm(z1, z2) mesh periods, otherwise).
pub(crate) fn response_period_s(r: &DynamicResponse) -> f64 {
    r.mesh_period_s * r.excitation_periods.max(1) as f64
}

/// One bearing-force input: the response coordinate it reads, the bearing's stiffness
/// k_b (N/m) and damping c_b (N s/m) in that direction.
pub(crate) type Spring = (usize, f64, f64);

/// The bearing forces over the first period of the response's recorded window: the
/// pinion's and the gear's bearings of the single pair (paper eq. 1).
pub(crate) fn bearing_forces(r: &DynamicResponse, params: &DynamicParams) -> BearingForces {
    let l = &params.lumped;
    let (kp, cp) = (
        l.bearing_stiffness_pinion_n_per_m,
        l.bearing_damping_pinion_n_s_per_m,
    );
    let (kg, cg) = (
        l.bearing_stiffness_gear_n_per_m,
        l.bearing_damping_gear_n_s_per_m,
    );
    let spring = [
        (dof::XP, kp, cp),
        (dof::YP, kp, cp),
        (dof::XG, kg, cg),
        (dof::YG, kg, cg),
    ];
    forces_of(r, spring)
}

/// The bearing forces of stage `stage` (0-based) of an assembled train over the first
/// period of the response's recorded window, `INPUTS` order: its pinion's bearing in x
/// and y, its gear's in x and y (each body's own bearing, `assembly::Bearing`: +k_b q +
/// c_b dq/dt on the housing, as in paper eq. 1). None when a body of the stage has no
/// lateral coordinates or no bearing.
pub(crate) fn stage_bearing_forces(
    r: &DynamicResponse,
    asm: &Assembly,
    stage: usize,
) -> Option<BearingForces> {
    let spring = |body: usize, d: Dof, j: usize| -> Option<Spring> {
        let b = asm.elements.bearings.iter().find(|b| b.body == body)?;
        Some((
            asm.index(body, d)?,
            b.stiffness_n_per_m[j],
            b.damping_n_s_per_m[j],
        ))
    };
    let (p, g) = (pinion_body(stage), gear_body(stage));
    let spring = [
        spring(p, Dof::X, 0)?,
        spring(p, Dof::Y, 1)?,
        spring(g, Dof::X, 0)?,
        spring(g, Dof::Y, 1)?,
    ];
    Some(forces_of(r, spring))
}

/// The forces +k_b q + c_b dq/dt of the four `spring` inputs over the first period of
/// the response's recorded window, with their rates (see [`BearingForces`]).
fn forces_of(r: &DynamicResponse, spring: [Spring; 4]) -> BearingForces {
    let s = &r.signals;
    let period = response_period_s(r);
    let t0 = s.time_s.first().copied().unwrap_or(0.0);
    // The window holds whole periods; keep the samples of the first (a sample within
    // 1e-9 of a period of the next period's start belongs to the next).
    let n = if evaluated_periods(r) > r.excitation_periods.max(1) {
        s.time_s
            .partition_point(|t| *t < t0 + period * (1.0 - 1e-9))
    } else {
        s.time_s.len()
    };
    let force_n = spring.map(|(i, k, c)| {
        (0..n)
            .map(|m| k * s.displacement[m][i] + c * s.velocity[m][i])
            .collect()
    });
    let stepped = s.step_acceleration.iter().all(|a| a.len() >= n);
    let rate = |which: usize| {
        spring.map(|(i, k, c)| -> Vec<f64> {
            if !stepped {
                return Vec::new();
            }
            (0..n)
                .map(|m| k * s.velocity[m][i] + c * s.step_acceleration[which][m][i])
                .collect()
        })
    };
    BearingForces {
        time_s: s.time_s[..n].to_vec(),
        force_n,
        rate_start_n_per_s: rate(0),
        rate_end_n_per_s: rate(1),
        period_s: period,
    }
}
