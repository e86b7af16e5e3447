//! Modes of a case's drivetrain (new teeth, linearised at the mean mesh stiffness): the
//! undamped natural frequencies and the damped poles, with the mesh poles that govern
//! the dynamic response (docs/MODEL.md, "Modes").

use super::model::Model;
use crate::dynamics::damped_modes::{damped_modes, DampedModes};
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::modal::{modes, Modes};

/// Undamped and damped modes of one case.
#[derive(Debug, Clone, Default)]
pub struct ModalAnalysis {
    /// Undamped natural frequencies and mass-normalised shapes (K phi = omega^2 M phi).
    pub undamped: Modes,
    /// Poles of the damped system (all damping included).
    pub damped: DampedModes,
    /// Name and unit of each coordinate of the shapes (`Assembly::coordinate_names`).
    pub coordinates: Vec<(String, &'static str)>,
}

impl ModalAnalysis {
    /// Modes of `model` with new teeth (the gap does not enter the linearisation).
    pub fn of(model: &Model) -> Self {
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = model.system(&gap, &ext, model.roughness.rms_um(0.0));
        Self {
            undamped: modes(&sys),
            damped: damped_modes(&sys),
            coordinates: sys.assembly().coordinate_names(),
        }
    }

    /// Damped frequencies |Im lambda| / 2 pi of the mesh poles, Hz, ascending: where the
    /// dynamic response to the mesh excitation peaks.
    pub fn mesh_pole_frequencies_hz(&self) -> Vec<f64> {
        self.damped
            .mesh_poles()
            .iter()
            .map(|m| m.damped_frequency_hz)
            .collect()
    }
}
