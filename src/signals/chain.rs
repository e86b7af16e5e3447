//! The signal chain of a record: transfer path, acquisition, tachometer, record length.

use super::transfer::TransferPath;
pub use crate::config::signals::{ChannelUnit, Shaft};
use serde::{Deserialize, Serialize};

pub(crate) use crate::config::signals::STANDARD_GRAVITY;
/// Additive measurement noise.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NoiseSpec {
    /// No noise.
    None,
    /// Signal-to-noise ratio of each channel, dB (powers).
    SnrDb(f64),
    /// One-sided amplitude spectral density, ug/sqrt(Hz) (accelerometer data sheets).
    DensityUgPerSqrtHz(f64),
}

/// Sampling and conversion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Acquisition {
    /// Sampling rate of the recorded channels f_s, Hz.
    pub sampling_rate_hz: f64,
    /// Stopband attenuation of the anti-alias filter at and above f_s / 2, dB.
    pub anti_alias_attenuation_db: f64,
    /// Unit the channels are recorded in.
    pub unit: ChannelUnit,
    /// Accelerometer sensitivity, mV/g (for a channel recorded in volts).
    pub sensitivity_mv_per_g: f64,
    /// Measurement noise added to each channel.
    pub noise: NoiseSpec,
    /// Seed of the noise's random stream.
    pub noise_seed: u64,
}

/// The tachometer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct TachometerSpec {
    /// The shaft the tachometer is on.
    pub shaft: Shaft,
    /// Pulses per revolution of that shaft.
    pub pulses_per_revolution: usize,
}

/// How long a record is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RecordLength {
    /// Duration, s.
    Seconds(f64),
    /// Revolutions of the tachometer's shaft.
    Revolutions(f64),
}

/// Everything between the gear pair and a recorded file.
#[derive(Debug, Clone, PartialEq)]
pub struct SignalChain {
    /// From bearing forces to the sensors' accelerations.
    pub path: TransferPath,
    /// Sampling and conversion.
    pub acquisition: Acquisition,
    /// The tachometer.
    pub tachometer: TachometerSpec,
    /// How long a record is.
    pub length: RecordLength,
}

impl SignalChain {
    /// The default chain: generic housing, 25.6 kHz, 100 dB anti-alias filter, m/s^2,
    /// 100 mV/g, no noise, one pulse per pinion revolution, 1 s.
    #[cfg(test)]
    pub(crate) fn default_chain() -> Self {
        Self {
            path: TransferPath::generic_housing(),
            acquisition: Acquisition {
                sampling_rate_hz: 25_600.0,
                anti_alias_attenuation_db: 100.0,
                unit: ChannelUnit::MetrePerSecond2,
                sensitivity_mv_per_g: 100.0,
                noise: NoiseSpec::None,
                noise_seed: 0,
            },
            tachometer: TachometerSpec {
                shaft: Shaft::Pinion,
                pulses_per_revolution: 1,
            },
            length: RecordLength::Seconds(1.0),
        }
    }

    /// Samples of a record for a tachometer shaft turning at `shaft_hz`.
    pub fn samples(&self, shaft_hz: f64) -> usize {
        let fs = self.acquisition.sampling_rate_hz;
        let seconds = match self.length {
            RecordLength::Seconds(s) => s,
            RecordLength::Revolutions(r) => r / shaft_hz,
        };
        (seconds * fs).ceil().max(1.0) as usize
    }
}
