//! Input speeds at which a mesh harmonic meets a damped mesh pole.
//!
//! The mesh frequency of a spur pair is f_m = z1 f_in (z1 pinion teeth, f_in pinion speed
//! in rev/s; `DynamicParams::mesh_frequency_hz`), so harmonic k excites a pole of damped
//! frequency f_p = |Im lambda| / 2 pi at f_in = f_p / (k z1). The poles marked are the
//! mesh poles of the base case (`ModalAnalysis::mesh_pole_frequencies_hz`): the
//! oscillatory poles of the damped system whose strain energy sits mostly in the mesh
//! spring. Near these speeds the dynamic response of a speed sweep peaks (primary
//! resonance for k = 1, super-harmonic for k > 1: the stiffness variation and the
//! transmission error have harmonics at every multiple of f_m). The undamped natural
//! frequencies are the wrong marks: at the mesh pole the bearing and coupling dampers of
//! the default case are stiffer than the springs beside them (c omega >> k), so the
//! bearings and shafts hardly flex and the pole lies far from every undamped mode
//! (docs/MODEL.md, "Modes").
//!
//! A gear train's mesh k turns at its own frequency f_m,k = r_k f_in, r_k = z1 f_m,k / f_m,1
//! (its order: mesh frequency per input rev/s, from the train's operating point), so its
//! harmonic h meets the pole at f_in = f_p / (h r_k). The poles are the train's mesh poles
//! (strain energy mostly in the mesh springs, all meshes together).

use crate::study::sweep::plan::SweepPlan;
use crate::study::sweep::SPEED_KEY;
use crate::study::{ModalAnalysis, Model};
use serde::{Deserialize, Serialize};

/// Mesh harmonics k = 1..=MARKED_HARMONICS whose crossings are marked.
pub const MARKED_HARMONICS: u32 = 4;

/// One crossing of harmonic `harmonic` with pole `pole` (1-based, ascending frequency).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Crossing {
    /// Harmonic k of the mesh frequency (1-based).
    pub harmonic: u32,
    /// Pole number, 1-based in ascending frequency.
    pub pole: usize,
    /// Damped frequency of the pole, Hz.
    pub pole_frequency_hz: f64,
    /// Input speed at which they meet, Hz (f_p / (k z1) for a single pair; module docs).
    pub input_speed_hz: f64,
}

impl Crossing {
    /// Short plot label: `2x` (one pole) or `2x p1` (several poles).
    pub fn label(&self, several_poles: bool) -> String {
        if several_poles {
            format!("{}x p{}", self.harmonic, self.pole)
        } else {
            format!("{}x", self.harmonic)
        }
    }
}

/// Crossings of harmonics 1..=`max_harmonic` with the pole frequencies (Hz) whose input
/// speed lies in [lo_hz, hi_hz], sorted by speed. Non-positive frequencies are skipped.
pub fn crossings(
    pole_hz: &[f64],
    pinion_teeth: usize,
    max_harmonic: u32,
    lo_hz: f64,
    hi_hz: f64,
) -> Vec<Crossing> {
    crossings_of_order(pole_hz, pinion_teeth as f64, max_harmonic, lo_hz, hi_hz)
}

/// As [`crossings`] for a mesh of order `order` (its mesh frequency per input rev/s: the
/// pinion's teeth for a single pair, r_k of a train's mesh k, see the module docs).
pub fn crossings_of_order(
    pole_hz: &[f64],
    order: f64,
    max_harmonic: u32,
    lo_hz: f64,
    hi_hz: f64,
) -> Vec<Crossing> {
    let mut out = Vec::new();
    if !(order.is_finite() && order > 0.0) {
        return out;
    }
    for (i, &f_p) in pole_hz.iter().enumerate() {
        if !(f_p.is_finite() && f_p > 0.0) {
            continue;
        }
        for h in 1..=max_harmonic {
            let f_in = f_p / (h as f64 * order);
            if f_in >= lo_hz && f_in <= hi_hz {
                out.push(Crossing {
                    harmonic: h,
                    pole: i + 1,
                    pole_frequency_hz: f_p,
                    input_speed_hz: f_in,
                });
            }
        }
    }
    out.sort_by(|a, b| a.input_speed_hz.total_cmp(&b.input_speed_hz));
    out
}

/// The modes of a speed sweep's base case and the crossings inside its speed range.
#[derive(Debug, Clone)]
pub struct SpeedMarks {
    /// The modes of the base case.
    pub modal: ModalAnalysis,
    /// The crossings of the pair's (a train's first mesh's) harmonics.
    pub crossings: Vec<Crossing>,
    /// A gear train's meshes, stage by stage: the order r_k (mesh frequency per input
    /// rev/s) and the crossings of its harmonics; empty for a single pair.
    pub stages: Vec<(f64, Vec<Crossing>)>,
}

/// Marks of a sweep that varies the input speed (`None` otherwise): the base case's
/// mesh poles crossed by harmonics 1..=[`MARKED_HARMONICS`] within the swept range.
pub fn speed_marks(base: &Model, plan: &SweepPlan) -> Option<SpeedMarks> {
    let axis = plan.axes.iter().find(|x| x.key == SPEED_KEY)?;
    let speeds: Vec<f64> = axis.values.iter().filter_map(|v| v.as_number()).collect();
    let lo = speeds.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = speeds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let modal = ModalAnalysis::of(base);
    let poles = modal.mesh_pole_frequencies_hz();
    let crossings = crossings(&poles, base.pair.pinion.teeth, MARKED_HARMONICS, lo, hi);
    let stages = match &base.train {
        Some(t) => {
            let f1 = t.operating.meshes[0].mesh_frequency_hz;
            let z1 = base.pair.pinion.teeth as f64;
            t.operating
                .meshes
                .iter()
                .map(|p| {
                    let order = z1 * (p.mesh_frequency_hz / f1);
                    let c = crossings_of_order(&poles, order, MARKED_HARMONICS, lo, hi);
                    (order, c)
                })
                .collect()
        }
        None => Vec::new(),
    };
    Some(SpeedMarks {
        modal,
        crossings,
        stages,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn speeds_solve_k_z1_f_in_equals_f_p() {
        // z1 = 19: f_p = 1900 Hz is met by harmonic 1 at 100 rev/s, 2 at 50, 3 at 33.3,
        // 4 at 25.
        let c = crossings(&[0.0, 1900.0], 19, 4, 40.0, 120.0);
        assert_eq!(c.len(), 2);
        assert_eq!(
            (c[0].harmonic, c[0].pole, c[0].input_speed_hz),
            (2, 2, 50.0)
        );
        assert_eq!((c[1].harmonic, c[1].input_speed_hz), (1, 100.0));
        for x in &c {
            assert!(
                (x.harmonic as f64 * 19.0 * x.input_speed_hz - x.pole_frequency_hz).abs() < 1e-9
            );
        }
        assert_eq!(crossings(&[1900.0], 19, 4, 20.0, 30.0)[0].harmonic, 4);
        assert!(crossings(&[1900.0], 19, 3, 101.0, 200.0).is_empty());
        assert_eq!(c[0].label(false), "2x");
        assert_eq!(c[0].label(true), "2x p2");
    }
}
