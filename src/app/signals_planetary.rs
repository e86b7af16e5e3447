//! `gearwear signals` on a planetary set: the steady state of its dynamic model and what a
//! sensor fixed on the ring hears of it (`study::planetary_signals`). The run job on a
//! planetary set (`app::run_planetary`) writes the same study through
//! [`ring_signals_artifacts`].

use super::observer::Observer;
use super::signals::SignalsJob;
use super::{publish, JobError};
use crate::config::planetary::Member;
use crate::config::signals::LengthUnit;
use crate::config::Case;
use crate::dynamics::planetary_steady::PlanetaryResponse;
use crate::remedy::{Arg, Problem};
use crate::report::artifacts::Artifacts;
use crate::report::signals_planetary::planetary_signals_artifacts;
use crate::store::RunMetadata;
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::planetary_signals::{
    ring_sensor_record, RingSensor, RingSensorError, RingSensorRecord,
};

/// Why the ring sensor's record of `case` cannot be made (a turning ring, a ramp or a
/// torque fluctuation), or `None` when it can.
pub(super) fn ring_sensor_problem(case: &Case) -> Option<Problem> {
    if let Some(p) = case.planetary.as_ref().filter(|p| p.fixed != Member::Ring) {
        return Some(Problem::new(format!(
            "`planetary.fixed` = \"{}\": a sensor on the ring needs the ring held fixed (a turning ring carries the sensor with it)",
            p.fixed.name()
        )));
    }
    // A fault's record spans lcm(P, z_r) mesh periods: checked here, where a sensor hears
    // it (the dynamics alone records P).
    if let Some(p) = case.planetary.as_ref() {
        let steps = case.numerics.steps_per_mesh_period.max(8) as u64;
        if let Err(e) = crate::study::planetary_fault::fault_periods(p, steps) {
            return Some(Problem::new(e.to_string()));
        }
    }
    let s = &case.signals;
    if s.ramp_end_speed_hz.is_some() || s.torque_fluctuation_rms_nm != 0.0 {
        return Some(Problem::new(
            "`signals.ramp_end_speed_hz` / `signals.torque_fluctuation_rms_nm` on a planetary set: its record is a steady state so far; remove them".to_string(),
        ));
    }
    None
}

/// The ring sensor of `case` on a set of `planets` planets: `signals`' angle, window
/// half-width (180 / N deg when absent), record length and sampling rate.
pub(super) fn ring_sensor_of(case: &Case, planets: usize) -> RingSensor {
    let s = &case.signals;
    RingSensor {
        angle_rad: s.ring_sensor_angle_deg.unwrap_or(0.0).to_radians(),
        half_width_rad: s
            .ring_sensor_half_width_deg
            .unwrap_or(180.0 / planets as f64)
            .to_radians(),
        // Revolutions are the input member's (as the run budget counts them).
        record_s: match s.record_length_unit {
            LengthUnit::S => s.record_length,
            LengthUnit::Revolutions => s.record_length / case.operating.input_speed_hz.max(1e-9),
        },
        sampling_rate_hz: s.sampling_rate_hz,
    }
}

/// What `gearwear signals` writes for the set `d` of `case` (checked by
/// [`ring_sensor_problem`]) from its steady state `r`, with the sensor's record.
pub(super) fn ring_signals_artifacts(
    case: &Case,
    d: &PlanetaryDynamics,
    r: &PlanetaryResponse,
) -> Result<(Artifacts, RingSensorRecord), JobError> {
    let sensor = ring_sensor_of(case, d.study.set.planets());
    // A turning ring is the case's doing (exit 2); a record that overflowed is a failed
    // run (exit 1), as a pair's is.
    let rec = ring_sensor_record(d, r, sensor).map_err(|e| match e {
        RingSensorError::RingNotFixed(_) => JobError::Input(vec![Problem::new(e.to_string())]),
        RingSensorError::Spectrum(_) | RingSensorError::NonFinite { .. } => {
            JobError::Failed(anyhow::Error::msg(e.to_string()))
        }
    })?;
    let harmonics = case.signals.mesh_harmonics.max(1) as usize;
    let a = planetary_signals_artifacts(d, &rec, sensor, harmonics);
    Ok((a, rec))
}

impl SignalsJob {
    /// A planetary case: the ring sensor's steady record.
    pub(super) fn run_planetary(
        &self,
        observer: &dyn Observer,
    ) -> Result<super::Outcome, JobError> {
        if self.transfer_path.is_some() {
            return Err(JobError::input(Problem::of(
                Arg::TransferPath,
                "a planetary set's record is the ring sensor's window model (`signals.ring_sensor_angle_deg`, `signals.ring_sensor_half_width_deg`); a housing transfer path is not taken yet".to_string(),
            )));
        }
        // What the ring sensor cannot hear (a turning ring, a transient, a record beyond
        // the limits) is named before the budget, which cannot count it; then the set's
        // dynamics estimate with the record added (one channel).
        if let Some(p) = ring_sensor_problem(&self.case) {
            return Err(JobError::input(p));
        }
        super::budget::check_estimate(
            &crate::study::budget::estimate_signals(&self.case, 1),
            self.budget.as_ref(),
        )?;
        let mut d = PlanetaryDynamics::from_case(&self.case)?;
        for w in &d.study.warnings {
            observer.warning(w);
        }
        let out = publish::open_if(self.out.as_deref(), None, "signals", self.replace)?;
        let r = d
            .solve()
            .map_err(|e| JobError::Failed(anyhow::anyhow!(e)))?;
        let (artifacts, _) = ring_signals_artifacts(&self.case, &d, &r)?;
        let meta = RunMetadata::new("signals", &self.case);
        publish::publish(out, artifacts, Some(&meta), observer)
    }
}
