//! The observable quantities of a wear study, named as the columns of the updates CSV that
//! `gearwear wear` writes (display units in the names).

use crate::dynamics::summary::ResponseSummary;
use serde::{Deserialize, Serialize};

/// One observable quantity of a dynamic wear study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Quantity {
    /// Maximum accumulated wear depth of the pinion profile, um (a profile measurement).
    MaxWearPinion,
    /// Maximum accumulated wear depth of the gear profile, um.
    MaxWearGear,
    /// RMS of the pinion's y velocity, mm/s (an accelerometer on the bearing, integrated).
    VelocityRms,
    /// Amplitude of mesh harmonic h (1..=4) of the pinion's y velocity, mm/s.
    MeshHarmonic(usize),
    /// Maximum of the dynamic transmission error, um.
    DteMax,
    /// Peak-to-peak of the DTE over the evaluated window, um (encoder-based measurement).
    DtePeakToPeak,
    /// Amplitude of the first mesh harmonic of the DTE, um.
    DteHarmonic1,
    /// A condition indicator of the recorded housing vibration (`super::indicator`: the
    /// index of its name), in the unit of `signals.channel_unit` or dimensionless.
    Indicator(u16),
    /// A quantity of `ALL` on a later stage of a gear train (`[[stage]]`): the stage
    /// (2..=`config::train::MAX_STAGES`, 1-based) and the quantity's index in `ALL`
    /// (stage 1's is the quantity itself). Observations name it by the `stage` column
    /// (`super::observations`); tables by the name with a `_stage<N>` suffix.
    OnStage(u8, u8),
}

/// Every quantity, in the order tables list them.
pub(crate) const ALL: [Quantity; 10] = [
    Quantity::MaxWearPinion,
    Quantity::MaxWearGear,
    Quantity::VelocityRms,
    Quantity::MeshHarmonic(1),
    Quantity::MeshHarmonic(2),
    Quantity::MeshHarmonic(3),
    Quantity::MeshHarmonic(4),
    Quantity::DteMax,
    Quantity::DtePeakToPeak,
    Quantity::DteHarmonic1,
];

impl Quantity {
    /// Column name (as in `updates_dynamic.csv`).
    pub fn name(&self) -> &'static str {
        match self {
            Quantity::MaxWearPinion => "max_wear_pinion_um",
            Quantity::MaxWearGear => "max_wear_gear_um",
            Quantity::VelocityRms => "velocity_y_pinion_rms_mm_per_s",
            Quantity::MeshHarmonic(1) => "mesh_harmonic1_mm_per_s",
            Quantity::MeshHarmonic(2) => "mesh_harmonic2_mm_per_s",
            Quantity::MeshHarmonic(3) => "mesh_harmonic3_mm_per_s",
            Quantity::MeshHarmonic(_) => "mesh_harmonic4_mm_per_s",
            Quantity::DteMax => "dte_max_um",
            Quantity::DtePeakToPeak => "dte_peak_to_peak_um",
            Quantity::DteHarmonic1 => "dte_harmonic1_um",
            Quantity::Indicator(i) => super::indicator::name(*i),
            Quantity::OnStage(s, i) => staged_name(*s, *i),
        }
    }

    /// Axis label with unit.
    pub fn label(&self) -> String {
        match self {
            Quantity::MaxWearPinion => "max pinion wear (µm)".into(),
            Quantity::MaxWearGear => "max gear wear (µm)".into(),
            Quantity::VelocityRms => "RMS dy_p/dt (mm/s)".into(),
            Quantity::MeshHarmonic(h) => format!("mesh harmonic {h} of dy_p/dt (mm/s)"),
            Quantity::DteMax => "max DTE (µm)".into(),
            Quantity::DtePeakToPeak => "DTE peak-to-peak (µm)".into(),
            Quantity::DteHarmonic1 => "DTE 1st mesh harmonic (µm)".into(),
            Quantity::Indicator(i) => format!("indicator {}", super::indicator::name(*i)),
            Quantity::OnStage(s, _) => format!("{} on stage {s}", self.base().label()),
        }
    }

    /// The quantity of name `name` (as [`Quantity::name`] spells it), if any.
    pub fn parse(name: &str) -> Option<Self> {
        ALL.iter()
            .copied()
            .find(|q| q.name() == name)
            .or_else(|| super::indicator::parse(name).map(Quantity::Indicator))
    }

    /// Names of every quantity, comma separated (for error messages).
    pub(crate) fn valid_names() -> String {
        let names = ALL.iter().map(|q| q.name()).collect::<Vec<_>>().join(", ");
        format!("{names}, and the {}", super::indicator::pattern())
    }

    /// Whether the quantity is a wear depth (known exactly between updates: the wear
    /// grows linearly in cycles within a block) rather than a response (that of the last
    /// update until the next).
    pub(crate) fn is_wear(&self) -> bool {
        matches!(self.base(), Quantity::MaxWearPinion | Quantity::MaxWearGear)
    }

    /// The quantity on stage `stage` (1-based) of a gear train: itself on stage 1; None
    /// for a condition indicator (the housing's record, not a stage's) or a stage beyond
    /// `config::train::MAX_STAGES`.
    pub fn on_stage(self, stage: usize) -> Option<Quantity> {
        if stage == 1 {
            return Some(self);
        }
        let i = ALL.iter().position(|q| *q == self)?;
        (2..=crate::config::train::MAX_STAGES)
            .contains(&stage)
            .then_some(Quantity::OnStage(stage as u8, i as u8))
    }

    /// The stage the quantity is read on (1-based; 1 but for [`Quantity::OnStage`]).
    pub fn stage(&self) -> usize {
        match self {
            Quantity::OnStage(s, _) => *s as usize,
            _ => 1,
        }
    }

    /// The quantity itself, whatever stage it is read on.
    pub fn base(&self) -> Quantity {
        match self {
            Quantity::OnStage(_, i) => ALL[(*i as usize).min(ALL.len() - 1)],
            q => *q,
        }
    }

    /// Value of a response quantity in display units (the updates CSV's conversions:
    /// x 1e6 for um, x 1e3 for mm/s). NaN for the wear depths, which come from the
    /// profile, and for the indicators, which come from a record (`super::indicator`).
    pub(crate) fn of_summary(&self, s: &ResponseSummary) -> f64 {
        match self {
            Quantity::OnStage(..) => self.base().of_summary(s),
            Quantity::MaxWearPinion | Quantity::MaxWearGear | Quantity::Indicator(_) => f64::NAN,
            Quantity::VelocityRms => s.velocity_y_pinion_rms_m_per_s * 1e3,
            Quantity::MeshHarmonic(h) => {
                s.velocity_y_pinion_harmonics_m_per_s[(*h).clamp(1, 4) - 1] * 1e3
            }
            Quantity::DteMax => s.dte_max_m * 1e6,
            Quantity::DtePeakToPeak => (s.dte_max_m - s.dte_min_m) * 1e6,
            Quantity::DteHarmonic1 => s.dte_harmonic1_m * 1e6,
        }
    }
}

/// The name of quantity `ALL[i]` on stage `stage` (2..=MAX_STAGES): its name with a
/// `_stage<N>` suffix (as the dataset's per-stage columns, `cycles_stage2`), from a table
/// made once.
fn staged_name(stage: u8, i: u8) -> &'static str {
    static NAMES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    let names = NAMES.get_or_init(|| {
        (0..=crate::config::train::MAX_STAGES)
            .flat_map(|s| ALL.iter().map(move |q| format!("{}_stage{s}", q.name())))
            .collect()
    });
    let s = (stage as usize).min(crate::config::train::MAX_STAGES);
    &names[s * ALL.len() + (i as usize).min(ALL.len() - 1)]
}

/// The indicators among `qs`.
pub(crate) fn indicators_of(qs: &[Quantity]) -> Vec<u16> {
    let mut v: Vec<u16> = qs
        .iter()
        .filter_map(|q| match q {
            Quantity::Indicator(i) => Some(*i),
            _ => None,
        })
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_are_distinct() {
        for (i, q) in ALL.iter().enumerate() {
            assert_eq!(Quantity::parse(q.name()), Some(*q));
            assert!(ALL[..i].iter().all(|p| p.name() != q.name()));
        }
        assert_eq!(Quantity::parse("velocity"), None);
    }

    #[test]
    fn a_quantity_on_a_later_stage_keeps_its_base_and_names_its_stage() {
        for q in ALL {
            assert_eq!(q.on_stage(1), Some(q));
            let s = q.on_stage(3).unwrap();
            assert_eq!((s.stage(), s.base()), (3, q));
            assert_eq!(s.name(), format!("{}_stage3", q.name()));
            assert_eq!(s.is_wear(), q.is_wear());
        }
        assert_eq!(Quantity::Indicator(0).on_stage(2), None);
        assert_eq!(Quantity::DteMax.on_stage(17), None);
    }

    #[test]
    fn summary_units() {
        let s = ResponseSummary {
            dte_max_m: 20e-6,
            dte_min_m: 5e-6,
            velocity_y_pinion_harmonics_m_per_s: [1e-3, 2e-3, 3e-3, 4e-3],
            ..Default::default()
        };
        // 15e-6 m peak-to-peak is 15 um; 4e-3 m/s is 4 mm/s (to rounding of the factors).
        assert!((Quantity::DtePeakToPeak.of_summary(&s) - 15.0).abs() < 1e-9);
        assert!((Quantity::MeshHarmonic(4).of_summary(&s) - 4.0).abs() < 1e-12);
        assert!(Quantity::MaxWearPinion.of_summary(&s).is_nan());
    }
}
