//! What a monitoring system computes from a record: per accelerometer channel, the
//! indicators of the whole signal and, per shaft, the TSA by tachometer angle with its
//! derived signals and indicators.

use super::chain::{Shaft, TachometerSpec};
use super::components::{components, ComponentSettings, Components};
use super::indicators::{ShaftIndicators, SignalIndicators};
use super::record::{Kinematics, Record};
use super::tachometer::rising_edges;
use super::tsa::{synchronous_averages, Tsa};
use serde::{Deserialize, Serialize};

/// The TSA of one shaft on one channel, its derived signals and indicators.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftAnalysis {
    /// The shaft the average is synchronous with.
    pub shaft: Shaft,
    /// The time-synchronous average of the channel over that shaft's revolutions.
    pub tsa: Tsa,
    /// The regular, difference, residual, band-pass and envelope signals of the TSA.
    pub components: Components,
    /// The condition indicators of the TSA.
    pub indicators: ShaftIndicators,
}

/// One channel's analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct ChannelAnalysis {
    /// Sensor name of the channel.
    pub name: String,
    /// Indicators of the whole recorded signal.
    pub signal: SignalIndicators,
    /// Pinion and gear shafts, where the record holds a complete revolution.
    pub shafts: Vec<ShaftAnalysis>,
}

/// The indicators of a channel, as written to summaries and index tables.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ChannelIndicators {
    /// Sensor name of the channel.
    pub channel: String,
    /// Indicators of the whole recorded signal.
    #[serde(flatten)]
    pub signal: SignalIndicators,
    /// Indicators of the pinion shaft's TSA, where the record holds a complete revolution.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pinion: Option<ShaftIndicators>,
    /// Indicators of the gear shaft's TSA, where the record holds a complete revolution.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gear: Option<ShaftIndicators>,
}

impl ChannelAnalysis {
    /// The channel's indicators as written to summaries and index tables.
    pub fn indicators(&self) -> ChannelIndicators {
        let of = |s: Shaft| {
            self.shafts
                .iter()
                .find(|a| a.shaft == s)
                .map(|a| a.indicators)
        };
        ChannelIndicators {
            channel: self.name.clone(),
            signal: self.signal,
            pinion: of(Shaft::Pinion),
            gear: of(Shaft::Gear),
        }
    }
}

/// Analyse every channel of `record`: the tachometer's pulse times, then per channel
/// the signal indicators and the TSA of each shaft (mesh order = that shaft's teeth); the
/// channels' TSAs of one shaft computed together (`tsa::synchronous_averages`).
pub fn analyse(
    record: &Record,
    kin: &Kinematics,
    tach: &TachometerSpec,
    settings: ComponentSettings,
) -> Vec<ChannelAnalysis> {
    let fs = record.sampling_rate_hz;
    let edges = rising_edges(&record.tachometer_v, fs);
    let xs: Vec<&[f64]> = record.channels.iter().map(|(_, x)| x.as_slice()).collect();
    let mut tsas: Vec<Vec<(Shaft, Tsa)>> = vec![Vec::new(); xs.len()];
    for shaft in [Shaft::Pinion, Shaft::Gear] {
        let ratio = kin.ratio(shaft, tach.shaft);
        let by_channel = synchronous_averages(&xs, fs, &edges, tach.pulses_per_revolution, ratio);
        for (c, tsa) in by_channel.into_iter().flatten().enumerate() {
            tsas[c].push((shaft, tsa));
        }
    }
    record
        .channels
        .iter()
        .zip(tsas)
        .map(|((name, x), tsas)| ChannelAnalysis {
            name: name.clone(),
            signal: SignalIndicators::of(x),
            shafts: tsas
                .into_iter()
                .map(|(shaft, tsa)| shaft_analysis(shaft, tsa, kin, fs, settings))
                .collect(),
        })
        .collect()
}

/// The analysis of one channel's TSA `tsa` of `shaft` (the record sampled at `fs` Hz).
fn shaft_analysis(
    shaft: Shaft,
    tsa: Tsa,
    kin: &Kinematics,
    fs: f64,
    settings: ComponentSettings,
) -> ShaftAnalysis {
    let z = shaft.teeth(kin.teeth_pinion, kin.teeth_gear);
    // The TSA's passband: orders below the resampling's flat band.
    let top = (super::interp::PASSBAND_OVER_FS * fs * tsa.revolution_s).floor();
    let settings = ComponentSettings {
        top_order: Some(top as usize),
        ..settings
    };
    let c = components(&tsa.values, z, settings);
    let indicators = ShaftIndicators::of(&tsa.values, &c, tsa.revolutions);
    ShaftAnalysis {
        shaft,
        tsa,
        components: c,
        indicators,
    }
}
