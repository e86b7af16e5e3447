//! Records of a transient: a run-up or coast-down (`signals.ramp_end_speed_hz`) or a
//! fluctuating load (`signals.torque_fluctuation_rms_nm`), simulated as one trajectory
//! from the periodic steady state at the starting speed (`dynamics::transient`), then
//! recorded (`signals::transient_record`).

use super::model::Model;
use crate::config::case::{Case, LoadPoint, SpeedBoundary, TorqueShaft};
use crate::dynamics::drive::{Drive, Tabulated};
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::params::OperatingPoint;
use crate::dynamics::period_search::DynamicsError;
use crate::dynamics::transient::integrate_transient;
use crate::signals::antialias::OVERSAMPLING;
use crate::signals::bearing::bearing_forces;
use crate::signals::chain::{RecordLength, Shaft};
use crate::signals::noise::band_limited;
use crate::signals::record::Record;
use crate::signals::setup::ChainSetup;
use crate::signals::transient_record::{transient_record, ForceSampler, TAIL_S};
use crate::wear::WearState;
use std::f64::consts::PI;

/// Whether the case's `[signals]` asks for a transient.
pub fn is_transient(case: &Case) -> bool {
    case.signals.ramp_end_speed_hz.is_some() || case.signals.torque_fluctuation_rms_nm > 0.0
}

/// Duration of the record, s (a ramp's record is given in seconds: checked with the case).
pub fn duration_s(case: &Case, setup: &ChainSetup) -> f64 {
    match setup.chain.length {
        RecordLength::Seconds(s) => s,
        RecordLength::Revolutions(r) => {
            let f = case.operating.input_speed_hz;
            let shaft_hz = match setup.chain.tachometer.shaft {
                Shaft::Pinion => f,
                Shaft::Gear => f * case.gear.teeth_pinion as f64 / case.gear.teeth_gear as f64,
            };
            r / shaft_hz
        }
    }
}

/// The drive of the model's case over `duration` s (`dynamics::drive`): the ramp from the
/// operating speed to `signals.ramp_end_speed_hz`, and the load fluctuation moved to the
/// shaft where the load acts (through the base radii, as the mean load is). Both ends'
/// speeds are the `OperatingPoint`'s of the case at each.
pub fn drive_of(model: &Model, duration: f64) -> Drive {
    let case = &model.case;
    let s = &case.signals;
    let w0 = model.params.operating.pinion_speed_rad_s;
    let w1 = s.ramp_end_speed_hz.map_or(w0, |f| {
        let mut end = case.clone();
        end.set_load_point(LoadPoint {
            input_speed_hz: f,
            ..case.load_point()
        });
        OperatingPoint::of(&end.operating, &model.pair).pinion_speed_rad_s
    });
    let torque = (s.torque_fluctuation_rms_nm > 0.0).then(|| {
        let p = &model.params;
        // Torque on the shaft it is given on -> on the shaft where the load acts.
        let on_gear_side = p.speed_boundary != SpeedBoundary::BrakeSpeedImposed;
        let per_given = match (case.operating.load_torque_shaft, on_gear_side) {
            (TorqueShaft::Pinion, true) => {
                p.operating.brake_torque_nm / p.operating.motor_torque_nm
            }
            (TorqueShaft::Gear, false) => p.operating.motor_torque_nm / p.operating.brake_torque_nm,
            _ => 1.0,
        };
        let rate = (20.0 * s.torque_fluctuation_bandwidth_hz).max(1000.0);
        let n = ((duration + 2.0 * TAIL_S) * rate).ceil() as usize + 4;
        let seed = s.torque_fluctuation_seed.max(0) as u64;
        let values = band_limited(
            seed,
            0,
            n,
            rate,
            s.torque_fluctuation_bandwidth_hz,
            s.torque_fluctuation_rms_nm * per_given,
        );
        Tabulated {
            rate_hz: rate,
            values,
        }
    });
    Drive {
        start_rad_s: w0,
        accel_rad_s2: (w1 - w0) / duration,
        ramp_s: duration,
        torque_nm: torque,
    }
}

/// The transient's local error tolerance over the case's `numerics.integration_tolerance`
/// (dimensionless). A steady state replays a step plan that keeps every refinement the
/// error test asked for in any period of its search, so at one tolerance it is more
/// accurate than a transient, whose steps the error control chooses afresh once. Measured
/// on the paper's case at 30 Hz against a reference at 1e-8 and 800 steps a period (bearing
/// force channel, RMS of the difference over the RMS): steady state 2.6e-4; transient
/// 2.7e-3 at the case's 1e-5, 1.1e-3 at half of it, 6.9e-4 at a fifth (2e-6), 5.9e-4 at a
/// tenth. A fifth brings the transient within three times the steady state's error, for
/// about 30 % more time (0.17 -> 0.22 s for this 0.2 s record with its starting steady
/// state).
pub const TRANSIENT_TOLERANCE_FACTOR: f64 = 0.2;

/// The tightest transient tolerance: the lower end of `numerics.integration_tolerance`'s
/// range, below which the error estimate's round-off can fail the first step.
const MIN_TRANSIENT_TOLERANCE: f64 = 1e-9;

/// The noise-free record of the case's transient for `wear`, with the nominal input
/// speed at each record sample (Hz).
pub fn transient_clean_record(
    model: &Model,
    setup: &ChainSetup,
    wear: &WearState,
) -> Result<(Record, Vec<f64>), DynamicsError> {
    let case = &model.case;
    let duration = duration_s(case, setup);
    let drive = drive_of(model, duration);
    // The steady state at the starting speed: the start state and the lead-in.
    let r0 = model.dynamic(wear, &ExternalError::none())?;
    let lead = bearing_forces(&r0, &model.params);
    let start = r0.end_state.clone();
    // The transient's system: the case at its fastest speed, so that the error control's
    // velocity scale (`dynamics::state_scales`) suits the whole ramp.
    let fastest = drive.speed(0.0).max(drive.speed(duration)) / (2.0 * PI);
    let mut fast_case = case.clone();
    fast_case.set_load_point(LoadPoint {
        input_speed_hz: fastest,
        ..case.load_point()
    });
    // The model as `model` was built (a helical pair's planar model on its slices,
    // docs/MODEL.md 11.11), and the gap of its wear state (a helical pair's per slice).
    let fast = model
        .rebuilt_like(&fast_case)
        .map_err(|e| DynamicsError::Setting(e.to_string()))?;
    let gap = fast.wear_gap(wear);
    let none = ExternalError::none();
    // Per-tooth errors and faults as the steady state has them (a run-out under the
    // drive follows the drive's angle, `TrainMesh::runout_at`).
    let teeth = fast.tooth_mesh(wear);
    let sys = fast
        .system_for(&gap, &none, fast.roughness_for(wear), teeth.as_ref())
        .with_drive(&drive);
    let chain = &setup.chain;
    let rate = chain.acquisition.sampling_rate_hz * OVERSAMPLING as f64;
    let mut sampler = ForceSampler::new(rate, &fast.params);
    let settings = &model.settings;
    integrate_transient(
        &sys,
        &drive,
        &start,
        duration + TAIL_S,
        settings.steps_per_mesh_period,
        (settings.integration_tolerance * TRANSIENT_TOLERANCE_FACTOR).max(MIN_TRANSIENT_TOLERANCE),
        &mut sampler,
    )?;
    let ratio = match chain.tachometer.shaft {
        Shaft::Pinion => 1.0,
        Shaft::Gear => {
            model.params.operating.gear_speed_rad_s / model.params.operating.pinion_speed_rad_s
        }
    };
    let samples = (duration * chain.acquisition.sampling_rate_hz).ceil() as usize;
    let record = transient_record(&sampler, &lead, chain, &|t| ratio * drive.angle(t), samples);
    let speeds = (0..samples)
        .map(|i| drive.speed(i as f64 / chain.acquisition.sampling_rate_hz) / (2.0 * PI))
        .collect();
    Ok((record, speeds))
}
