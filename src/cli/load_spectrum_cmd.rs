//! `gearwear load-spectrum`: the load spectrum of a measured torque / speed history.

use super::args::{InterpolationArg, LevelArg, LoadSpectrumArgs, ShaftArg};
use super::error::CliError;
use super::output::execute;
use crate::app::{LoadSpectrumJob, TableSource};
use crate::config::case::TorqueShaft;
use crate::duty::ldd::{Interpolation, LddSettings, Level};
use crate::study::budget::Budget;

pub(crate) fn run(a: &LoadSpectrumArgs, budget: Option<Budget>) -> Result<(), CliError> {
    execute(&LoadSpectrumJob {
        history: TableSource::File(a.history.clone()),
        settings: LddSettings {
            torque_classes: a.torque_classes,
            speed_classes: a.speed_classes,
            interpolation: match a.interpolation {
                InterpolationArg::Linear => Interpolation::Linear,
                InterpolationArg::Hold => Interpolation::Hold,
            },
            level: match a.level {
                LevelArg::Mean => Level::Mean,
                LevelArg::Upper => Level::Upper,
            },
        },
        torque_shaft: match a.torque_shaft {
            ShaftArg::Pinion => TorqueShaft::Pinion,
            ShaftArg::Gear => TorqueShaft::Gear,
        },
        gap_factor: a.gap_factor,
        merge_below_share: a.merge_below_share,
        out: Some(a.out.clone()),
        replace: super::output::replace(),
        budget,
        figures: a.figures.request(),
    })
}
