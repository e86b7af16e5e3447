//! What a train's run under a spectrum gives per mesh: the share of its wear each bin
//! added, its life to the spectrum's wear limit (`load_spectrum.life_wear_limit_um`, the
//! maximum pinion wear depth) in input cycles and hours, and the mesh that limits the
//! train's life.
//!
//! The life is read from the run itself (between updates the wear grows linearly in
//! cycles, paper eq. 17, so the crossing within a block is exact: `life::first_crossing`);
//! a mesh whose limit is not reached by the end of the run is given as "beyond" at the
//! run's end. Hours are input cycles x sum_i s_i / f_i / 3600 (f_i: bin i's input speed,
//! Hz; `LoadSpectrumSection::seconds_per_cycle`).

use super::contribution::{area, share};
use super::life::{first_crossing, Life};
use super::train::{combined_train_run, TrainSpectrum, TrainSpectrumRun};
use serde::Serialize;

/// One mesh's results under the spectrum.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeshUnderSpectrum {
    /// 1-based.
    pub stage: usize,
    /// Pinion cycles of this mesh at the end of the run.
    pub pinion_cycles: f64,
    /// Maximum wear depth at the end, um.
    pub max_wear_pinion_um: f64,
    /// Maximum gear wear depth at the end, um.
    pub max_wear_gear_um: f64,
    /// Share of the worn area of the pinion's profile each bin added (bin order).
    pub share_of_pinion_wear_by_bin: Vec<f64>,
    /// Life to the wear limit, in input cycles.
    pub life: Life,
    /// The life in hours under the spectrum, when reached.
    pub life_hours: Option<f64>,
}

/// A run's results per mesh and the mesh that limits the life.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrainUnderSpectrum {
    /// Input cycles at the end of the run.
    pub input_cycles: f64,
    /// Hours those cycles take under the spectrum.
    pub hours: f64,
    /// The wear limit of the lives, um.
    pub life_wear_limit_um: f64,
    /// Per mesh (stage order).
    pub meshes: Vec<MeshUnderSpectrum>,
    /// The mesh (1-based) whose life is shortest; when no mesh reaches the limit, the
    /// one with the deepest wear at the end.
    pub limiting_stage: Option<usize>,
}

/// Seconds per input cycle under the spectrum: sum_i s_i / f_i, s.
pub fn seconds_per_input_cycle(ts: &TrainSpectrum) -> f64 {
    ts.sm.spectrum().seconds_per_cycle()
}

/// The results of `run` per mesh (see the module docs).
pub fn under_spectrum(ts: &TrainSpectrum, run: &TrainSpectrumRun) -> Option<TrainUnderSpectrum> {
    let last = run.records.last()?;
    let spc = seconds_per_input_cycle(ts);
    let limit_um = ts.sm.spectrum().life_wear_limit_um;
    let combined = combined_train_run(run, ts.sm.monitoring);
    let c = ts.cycle_factors();
    let meshes: Vec<MeshUnderSpectrum> = (0..ts.meshes())
        .map(|k| {
            let wear = &last.bins[0].meshes[k].wear;
            let total = area(&wear.pinion_m);
            let records = combined.mesh_records(k);
            let life = match first_crossing(&records, wear.cycles, limit_um * 1e-6) {
                Some(n) => Life::Reached { cycles: n / c[k] },
                None => Life::Beyond {
                    cycles: last.input_cycles,
                    reason: format!(
                        "the maximum pinion wear of stage {} is {:.3} µm at the end of the run, below the limit of {limit_um} µm",
                        k + 1,
                        wear.max_pinion_m() * 1e6
                    ),
                },
            };
            MeshUnderSpectrum {
                stage: k + 1,
                pinion_cycles: wear.cycles,
                max_wear_pinion_um: wear.max_pinion_m() * 1e6,
                max_wear_gear_um: wear.max_gear_m() * 1e6,
                share_of_pinion_wear_by_bin: last
                    .by_bin_pinion_m
                    .iter()
                    .map(|b| share(area(&b[k]), total))
                    .collect(),
                life_hours: life.cycles().map(|n| n * spc / 3600.0),
                life,
            }
        })
        .collect();
    let limiting_stage = meshes
        .iter()
        .filter_map(|m| m.life.cycles().map(|n| (m.stage, n)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(s, _)| s)
        // No stage reached the limit: the deepest pinion wear, the life's own measure
        // (as the single pair's life, docs/MODEL.md 10.1).
        .or_else(|| {
            meshes
                .iter()
                .max_by(|a, b| a.max_wear_pinion_um.total_cmp(&b.max_wear_pinion_um))
                .map(|m| m.stage)
        });
    Some(TrainUnderSpectrum {
        input_cycles: last.input_cycles,
        hours: last.input_cycles * spc / 3600.0,
        life_wear_limit_um: limit_um,
        meshes,
        limiting_stage,
    })
}
