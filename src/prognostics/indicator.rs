//! Condition indicators as observed quantities: the indicators a monitoring system
//! computes from its accelerometers (docs/SIGNALS.md, section 2), named as the columns of
//! a dataset's index (`input_rms`, `input_pinion_fm0`, ...), and where each one's value is
//! in a record's analysis. Their forward value along a wear run is
//! `super::forward::attach`'s.
//!
//! NA4 and NB4 are not offered: their denominator is the mean residual variance of the
//! monitoring history so far, a property of the whole run, not of one wear state.

use crate::signals::analysis::ChannelAnalysis;
use crate::signals::chain::Shaft;
use crate::signals::transfer::TransferPath;
use std::sync::OnceLock;

/// Indicators of a whole channel (`<sensor>_<name>`).
const SIGNAL_KINDS: [&str; 3] = ["rms", "crest_factor", "kurtosis"];
/// Indicators of one shaft's time-synchronous average (`<sensor>_<shaft>_<name>`).
const SHAFT_KINDS: [&str; 8] = [
    "tsa_rms",
    "fm0",
    "fm4",
    "m6a",
    "m8a",
    "energy_ratio",
    "sideband_level_factor",
    "sideband_index",
];
const SHAFTS: [(&str, Shaft); 2] = [("pinion", Shaft::Pinion), ("gear", Shaft::Gear)];

/// One indicator: (sensor index, shaft index or None for a channel indicator, kind).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Spec {
    sensor: usize,
    shaft: Option<usize>,
    kind: usize,
}

/// Every indicator name and its spec, sensors of the built-in housing.
fn table() -> &'static [(String, Spec)] {
    static T: OnceLock<Vec<(String, Spec)>> = OnceLock::new();
    T.get_or_init(|| {
        let mut t = Vec::new();
        for (sensor, s) in TransferPath::generic_housing().sensors.iter().enumerate() {
            for (kind, k) in SIGNAL_KINDS.iter().enumerate() {
                let spec = Spec {
                    sensor,
                    shaft: None,
                    kind,
                };
                t.push((format!("{s}_{k}"), spec));
            }
            for (shaft, (sh, _)) in SHAFTS.iter().enumerate() {
                for (kind, k) in SHAFT_KINDS.iter().enumerate() {
                    let spec = Spec {
                        sensor,
                        shaft: Some(shaft),
                        kind,
                    };
                    t.push((format!("{s}_{sh}_{k}"), spec));
                }
            }
        }
        t
    })
}

/// Column name of indicator `i`.
pub fn name(i: u16) -> &'static str {
    table()
        .get(i as usize)
        .map_or("indicator", |x| x.0.as_str())
}

/// The indicator named `name`.
pub fn parse(name: &str) -> Option<u16> {
    table().iter().position(|x| x.0 == name).map(|i| i as u16)
}

/// How indicator names are formed (for messages).
pub fn pattern() -> String {
    let sensors = TransferPath::generic_housing().sensors.join(", ");
    format!(
        "condition indicators <sensor>_{{{}}} or <sensor>_<pinion|gear>_{{{}}} with <sensor> one of {sensors}",
        SIGNAL_KINDS.join(", "),
        SHAFT_KINDS.join(", ")
    )
}

/// Value of indicator `i` in the analysis of a record.
pub fn value(analysis: &[ChannelAnalysis], i: u16) -> Option<f64> {
    let spec = table().get(i as usize)?.1;
    let ch = analysis.get(spec.sensor)?;
    let Some(shaft) = spec.shaft else {
        let s = &ch.signal;
        return Some([s.rms, s.crest_factor, s.kurtosis][spec.kind]);
    };
    let s = &ch
        .shafts
        .iter()
        .find(|a| a.shaft == SHAFTS[shaft].1)?
        .indicators;
    Some(
        [
            s.tsa_rms,
            s.fm0,
            s.fm4,
            s.m6a,
            s.m8a,
            s.energy_ratio,
            s.sideband_level_factor,
            s.sideband_index,
        ][spec.kind],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_follow_the_dataset_index() {
        for i in 0..table().len() as u16 {
            assert_eq!(parse(name(i)), Some(i));
        }
        // The dataset index's spelling (docs/SIGNALS.md, Layout).
        assert!(parse("input_rms").is_some() && parse("output_gear_fm0").is_some());
        assert!(parse("input_pinion_na4").is_none() && parse("input_fm0").is_none());
    }
}
