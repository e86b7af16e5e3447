//! A wear sweep's row of a planetary set (`[planetary]`, docs/MODEL.md 12.17): the set's
//! wear study in both modes, the very loop `gearwear wear` runs on the set
//! (`study::planetary_wear_loop`; under a `[load_spectrum]` the spectrum's loop,
//! `duty::planetary`, read as one run), reduced to a row:
//!
//! - the pair's columns: the first sun-planet mesh's mean and largest force and its
//!   dynamic factor (largest over the nominal mesh force, docs/MODEL.md 12.6) from the
//!   dynamic run's first update (the new set), the others empty (the set has no DTE or
//!   pinion velocity); per mode, the first sun-planet mesh's members' deepest wear at the
//!   run's end (pinion: the sun's flank, all its meshes' wear; gear: planet 1's sun-side
//!   flank), the updates after the first and the input cycles reached;
//! - the set's columns (`super::planetary_row`): every mesh's forces and dynamic factor and
//!   every planet's load sharing of the dynamic run's first update, then every member
//!   flank's deepest wear, µm, and wear volume over its teeth, mm^3, at the end of each
//!   mode's run (as `members[..].final.MODE.flanks` of `gearwear wear`'s summary.json).

use super::planetary_row::{PlanetaryRow, PlanetaryRunError};
use super::row::{DynamicsRow, WearEnd};
use crate::config::Case;
use crate::study::model::ModelError;
use crate::study::planetary_dynamics::shares;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use crate::study::wear_loop::WearMode;

/// The pieces of a planetary set's wear row (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetaryWearRow {
    /// The pair's dynamics columns (the first sun-planet mesh's forces; the rest NaN).
    pub dynamics: DynamicsRow,
    /// The end of the dynamic and of the quasi-static run.
    pub wear: [WearEnd; 2],
    /// The set's columns, with the flanks' wear.
    pub set: PlanetaryRow,
}

/// Largest entry, 0 for none (a flank's deepest wear, as `gearwear wear` reports it).
fn deepest(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |a, b| a.max(*b))
}

/// The row of the set `model`'s dynamic run `d` and quasi-static run `q` (see the module
/// docs; NaN where a run has no update).
pub fn planetary_wear_row(
    model: &PlanetaryWearModel,
    d: &PlanetaryWearRun,
    q: &PlanetaryWearRun,
) -> PlanetaryWearRow {
    let planets = model.planets();
    let nominal = model.dynamics.nominal_mesh_force_n();
    let (meshes, load_sharing): (Vec<[f64; 3]>, Vec<f64>) = match d.updates.first() {
        Some(u) => {
            let mean: Vec<f64> = u
                .meshes
                .iter()
                .map(|m| m.summary.mesh_force_mean_n)
                .collect();
            let meshes = u
                .meshes
                .iter()
                .map(|m| {
                    let s = &m.summary;
                    [
                        s.mesh_force_mean_n,
                        s.mesh_force_max_n,
                        s.mesh_force_max_n / nominal,
                    ]
                })
                .collect();
            (meshes, shares(&mean[..planets]))
        }
        None => (vec![[f64::NAN; 3]; 2 * planets], vec![f64::NAN; planets]),
    };
    // Every flank's deepest wear, µm, and wear volume over its teeth, mm^3, at each
    // run's end (NaN without an update).
    let finals: Vec<Vec<[f64; 2]>> = [d, q]
        .iter()
        .map(|r| match r.updates.last() {
            Some(u) => u
                .flanks(model)
                .iter()
                .map(|f| [deepest(&f.depth_m) * 1e6, f.volume_m3 * 1e9])
                .collect(),
            None => vec![[f64::NAN; 2]; 2 * planets + 2],
        })
        .collect();
    let end = |r: &PlanetaryWearRun, f: &[[f64; 2]]| WearEnd {
        max_wear_pinion_um: f[0][0],
        max_wear_gear_um: f[1][0],
        updates: r.updates.len().saturating_sub(1) as f64,
        cycles: r.updates.last().map_or(f64::NAN, |u| u.input_cycles),
    };
    let mut pair = [f64::NAN; 9];
    pair[2..5].copy_from_slice(&meshes[0]);
    PlanetaryWearRow {
        dynamics: DynamicsRow::from_values(&pair),
        wear: [end(d, &finals[0]), end(q, &finals[1])],
        set: PlanetaryRow {
            meshes,
            load_sharing,
            wear: finals[0]
                .iter()
                .zip(&finals[1])
                .map(|(a, b)| [a[0], b[0], a[1], b[1]])
                .collect(),
        },
    }
}

/// The set's wear model of `case`, refused (naming the fault's keys) when its
/// quasi-static run cannot run (`PlanetaryWearModel::quasi_static_problem`): a sweep runs
/// both modes.
pub fn sweep_wear_model(model: PlanetaryWearModel) -> Result<PlanetaryWearModel, ModelError> {
    match model.quasi_static_problem() {
        Some(p) => Err(ModelError(vec![p])),
        None => Ok(model),
    }
}

/// The set's wear study of `case` in both modes, side by side (as `gearwear wear` on it):
/// its model and the dynamic and quasi-static runs.
pub fn run_planetary_wear_modes(
    case: &Case,
) -> Result<(PlanetaryWearModel, [PlanetaryWearRun; 2]), PlanetaryRunError> {
    let model = PlanetaryWearModel::from_case(case)
        .and_then(sweep_wear_model)
        .map_err(PlanetaryRunError::Model)?;
    let one = |mode| {
        run_planetary_wear(&model, &case.wear, PlanetaryWearRun::new(mode), &mut |_| {
            Ok(())
        })
    };
    let (d, q) = rayon::join(|| one(WearMode::Dynamic), || one(WearMode::QuasiStatic));
    let (d, q) = (
        d.map_err(PlanetaryRunError::Solve)?,
        q.map_err(PlanetaryRunError::Solve)?,
    );
    Ok((model, [d, q]))
}
