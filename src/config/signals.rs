//! The `[signals]` section of a case: what a sensor records (acquisition, tachometer,
//! record length, measurement noise, operating variation). Used by `gearwear signals`
//! and datasets; the other studies ignore it. docs/SIGNALS.md describes the chain.

use serde::{Deserialize, Serialize};

/// Standard gravity, m/s^2 (CGPM 1901): 1 g.
pub(crate) const STANDARD_GRAVITY: f64 = 9.80665;

/// Unit of the recorded acceleration channels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum ChannelUnit {
    /// m/s^2.
    #[serde(rename = "m/s^2")]
    MetrePerSecond2,
    /// Standard gravity, 9.80665 m/s^2.
    #[serde(rename = "g")]
    G,
    /// The sensor's output voltage, mV (sensitivity times acceleration in g).
    #[serde(rename = "mV")]
    MilliVolt,
}

impl ChannelUnit {
    /// The unit as written in files.
    pub(crate) fn symbol(&self) -> &'static str {
        match self {
            ChannelUnit::MetrePerSecond2 => "m/s^2",
            ChannelUnit::G => "g",
            ChannelUnit::MilliVolt => "mV",
        }
    }

    /// Suffix of column names: `m_per_s2`, `g`, `mv`.
    pub(crate) fn suffix(&self) -> &'static str {
        match self {
            ChannelUnit::MetrePerSecond2 => "m_per_s2",
            ChannelUnit::G => "g",
            ChannelUnit::MilliVolt => "mv",
        }
    }

    /// Factor from m/s^2 to this unit, for a sensor of `sensitivity_mv_per_g`.
    pub fn factor(&self, sensitivity_mv_per_g: f64) -> f64 {
        match self {
            ChannelUnit::MetrePerSecond2 => 1.0,
            ChannelUnit::G => 1.0 / STANDARD_GRAVITY,
            ChannelUnit::MilliVolt => sensitivity_mv_per_g / STANDARD_GRAVITY,
        }
    }
}

/// A shaft of the pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shaft {
    /// The pinion's (input) shaft.
    Pinion,
    /// The gear's (output) shaft.
    Gear,
}

impl Shaft {
    /// Its name as the case file spells it.
    pub fn name(&self) -> &'static str {
        match self {
            Shaft::Pinion => "pinion",
            Shaft::Gear => "gear",
        }
    }

    /// Teeth of this shaft's gear, for a pair of `z1` / `z2` teeth.
    pub fn teeth(&self, z1: usize, z2: usize) -> usize {
        match self {
            Shaft::Pinion => z1,
            Shaft::Gear => z2,
        }
    }
}

/// Unit of `record_length`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LengthUnit {
    /// Seconds.
    S,
    /// Revolutions of the tachometer's shaft.
    Revolutions,
}

/// `[signals]`: what a sensor records.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SignalsSection {
    /// Sampling rate f_s of a record, Hz; the alias-free band is f_s / 2.56.
    pub sampling_rate_hz: f64,
    /// Record length, s or rev (in `record_length_unit`).
    pub record_length: f64,
    /// Unit of `record_length`: seconds, or revolutions of the tachometer's shaft.
    pub record_length_unit: LengthUnit,
    /// Stopband attenuation of the anti-alias filter at and above f_s / 2, dB.
    pub anti_alias_attenuation_db: f64,
    /// Unit of the accelerometer channels.
    pub channel_unit: ChannelUnit,
    /// Accelerometer sensitivity, mV/g (for channels in mV).
    pub sensitivity_mv_per_g: f64,
    /// Measurement noise as a signal-to-noise ratio (dB); absent: no SNR noise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub snr_db: Option<f64>,
    /// Measurement noise as a one-sided amplitude spectral density, ug/sqrt(Hz), white to
    /// f_s / 2; absent: none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub noise_density_ug_per_sqrt_hz: Option<f64>,
    /// Seed of the measurement noise.
    pub noise_seed: i64,
    /// Shaft the tachometer reads.
    pub tachometer_shaft: Shaft,
    /// Tachometer pulses per revolution of its shaft.
    pub tachometer_pulses_per_revolution: i64,
    /// Mesh harmonics analysed (FM0, spectrum labels); the highest must be recorded.
    pub mesh_harmonics: i64,
    /// RMS of the seeded random load-torque fluctuation, N m (0: none).
    pub torque_fluctuation_rms_nm: f64,
    /// Bandwidth of the torque fluctuation, Hz (flat from 0 to it).
    pub torque_fluctuation_bandwidth_hz: f64,
    /// Seed of the torque fluctuation.
    pub torque_fluctuation_seed: i64,
    /// Input speed at the end of the record for a run-up or coast-down, Hz (from
    /// `operating.input_speed_hz` at its start); absent: steady speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ramp_end_speed_hz: Option<f64>,
    /// The stage (1..N, of a gear train's `[[stage]]` tables) whose bearings the housing's
    /// transfer path takes in, and whose shafts the tachometer and the indicators refer
    /// to; absent: stage 1 (a single pair is stage 1).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sensor_stage: Option<i64>,
    /// Planetary sets: the angle of the sensor on the (fixed) ring from planet 1's position
    /// at the record's start, in the carrier's sense of rotation, deg; absent: 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ring_sensor_angle_deg: Option<f64>,
    /// Planetary sets: the half-width of the Hann window over which the ring sensor hears a
    /// planet's ring mesh, deg; absent: 180 / N (half the planet spacing: each planet heard
    /// alone as it passes).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ring_sensor_half_width_deg: Option<f64>,
}

impl Default for SignalsSection {
    fn default() -> Self {
        Self {
            // 2.56 x 10 kHz, the usual analyser setting for gearbox vibration.
            sampling_rate_hz: 25_600.0,
            record_length: 1.0,
            record_length_unit: LengthUnit::S,
            anti_alias_attenuation_db: 100.0,
            channel_unit: ChannelUnit::MetrePerSecond2,
            // A general-purpose IEPE accelerometer.
            sensitivity_mv_per_g: 100.0,
            snr_db: None,
            noise_density_ug_per_sqrt_hz: None,
            noise_seed: 0,
            tachometer_shaft: Shaft::Pinion,
            tachometer_pulses_per_revolution: 1,
            mesh_harmonics: 4,
            torque_fluctuation_rms_nm: 0.0,
            torque_fluctuation_bandwidth_hz: 20.0,
            torque_fluctuation_seed: 0,
            ramp_end_speed_hz: None,
            sensor_stage: None,
            ring_sensor_angle_deg: None,
            ring_sensor_half_width_deg: None,
        }
    }
}

impl SignalsSection {
    /// Whether the section is all defaults (then a case's serialisation leaves it out,
    /// so cases without signals keep their form and hash).
    pub(crate) fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

/// Checks between keys of the case that involve the `[signals]` section.
pub(crate) fn relation_problems(case: &super::Case) -> Vec<String> {
    let s = &case.signals;
    let mut out = Vec::new();
    if s.snr_db.is_some() && s.noise_density_ug_per_sqrt_hz.is_some() {
        out.push(
            "`signals.snr_db` and `signals.noise_density_ug_per_sqrt_hz` are both given: measurement noise is one or the other, remove one".into(),
        );
    }
    // A Gaussian fluctuation exceeds 3.5 sigma once in ~2000 samples: keep the torque
    // positive with margin.
    let torque = case.operating.load_torque_nm;
    if 3.5 * s.torque_fluctuation_rms_nm >= torque {
        out.push(format!(
            "`signals.torque_fluctuation_rms_nm` = {} is invalid with `operating.load_torque_nm` = {torque}: expected below {} (3.5 standard deviations must stay below the mean torque, or the load would reverse)",
            s.torque_fluctuation_rms_nm,
            torque / 3.5
        ));
    }
    if s.ramp_end_speed_hz.is_some() && s.record_length_unit == LengthUnit::Revolutions {
        out.push(
            "`signals.record_length_unit` = \"revolutions\" is invalid with `signals.ramp_end_speed_hz`: a ramp's record is given in seconds (\"s\")".into(),
        );
    }
    if let Some(k) = s.sensor_stage {
        let stages = case.stage.len().max(1);
        if k > stages as i64 {
            out.push(format!(
                "`signals.sensor_stage` = {k} is invalid: expected 1 to {stages} (the case's stages)"
            ));
        }
    }
    out
}

impl SignalsSection {
    /// The sensor stage, 0-based (`sensor_stage` - 1; stage 1 when absent).
    pub fn sensor_stage_index(&self) -> usize {
        self.sensor_stage.map_or(0, |k| (k.max(1) - 1) as usize)
    }

    /// Speed of the tachometer's shaft at the operating speed, Hz: the pinion's or the
    /// gear's of the sensor's stage (a train's: the input speed through the ratios
    /// z_pinion / z_gear of the stages before it), f z1 / z2 for the gear of one pair.
    pub fn tachometer_shaft_hz(&self, case: &super::Case) -> f64 {
        let ratio = |g: &super::gear::GearSection| {
            g.teeth_pinion.max(1) as f64 / g.teeth_gear.max(1) as f64
        };
        let (before, own) = if case.stage.is_empty() {
            (1.0, ratio(&case.gear))
        } else {
            let k = self.sensor_stage_index().min(case.stage.len() - 1);
            let r = |st: &super::train::StageSpec| ratio(&st.gear_section(&case.gear));
            (case.stage[..k].iter().map(r).product(), r(&case.stage[k]))
        };
        let pinion = case.operating.input_speed_hz * before;
        match self.tachometer_shaft {
            Shaft::Pinion => pinion,
            Shaft::Gear => pinion * own,
        }
    }

    /// The record's length in seconds: `record_length` s, or that many revolutions of the
    /// tachometer's shaft at its operating speed ([`Self::tachometer_shaft_hz`]).
    pub fn record_seconds(&self, case: &super::Case) -> f64 {
        match self.record_length_unit {
            LengthUnit::S => self.record_length,
            LengthUnit::Revolutions => {
                self.record_length / self.tachometer_shaft_hz(case).max(1e-9)
            }
        }
    }

    /// The highest input speed a record of `case` sees, Hz (a ramp's end or the
    /// operating speed).
    pub fn max_input_speed_hz(&self, case: &super::Case) -> f64 {
        let f = case.operating.input_speed_hz;
        self.ramp_end_speed_hz.map_or(f, |e| e.max(f))
    }
}
