//! What a sweep case runs ([`SweepRun`]) and the headline numbers of its row: the
//! dynamics columns of one evaluation ([`DynamicsRow`]) and where each wear run ended
//! ([`WearEnd`]); [`super::case_run`] runs the case and assembles the row.

use super::helical_row::helical_columns;
use super::mesh_row::{mesh_columns, mesh_wear_columns, MESH_COLUMNS};
use super::planetary_row::{planetary_columns, planets_of};
use crate::dynamics::summary::ResponseSummary;
use crate::study::wear_loop::WearRun;
use serde::{Deserialize, Serialize};
/// What each case runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepRun {
    /// One steady-state evaluation of the new teeth (as `gearwear dynamics`).
    Dynamics,
    /// The wear study in both modes (as `gearwear wear --mode both`); the dynamics
    /// columns are those of its first update, which is the new-teeth evaluation.
    Wear,
}

/// Result columns of a dynamics row, display units in the names.
pub(super) const DYNAMICS_COLUMNS: [&str; 9] = [
    "dte_max_um",
    "velocity_y_pinion_rms_mm_per_s",
    "mesh_force_mean_n",
    "mesh_force_max_n",
    "dynamic_factor",
    "mesh_harmonic1_mm_per_s",
    "mesh_harmonic2_mm_per_s",
    "mesh_harmonic3_mm_per_s",
    "mesh_harmonic4_mm_per_s",
];

/// Extra columns of a wear row, per mode: final maximum wear depths, update count, and
/// the cycles reached (below the case's total when the run stopped at the edge of the
/// model's domain, [`crate::study::wear_loop::WearStop`]).
pub(super) const WEAR_COLUMNS: [&str; 8] = [
    "wear_max_pinion_dynamic_um",
    "wear_max_gear_dynamic_um",
    "wear_updates_dynamic",
    "wear_cycles_dynamic",
    "wear_max_pinion_quasi_static_um",
    "wear_max_gear_quasi_static_um",
    "wear_updates_quasi_static",
    "wear_cycles_quasi_static",
];

impl SweepRun {
    /// The run's name (`dynamics`, `wear`).
    pub fn name(&self) -> &'static str {
        match self {
            SweepRun::Dynamics => "dynamics",
            SweepRun::Wear => "wear",
        }
    }

    /// Names of the result columns, in row order.
    pub fn columns(&self) -> Vec<String> {
        let mut c: Vec<String> = DYNAMICS_COLUMNS.iter().map(|s| s.to_string()).collect();
        if *self == SweepRun::Wear {
            c.extend(WEAR_COLUMNS.iter().map(|s| s.to_string()));
        }
        c
    }

    /// The run and the number of train meshes (0: a single pair) whose result columns
    /// are `columns` (`CaseResults::columns`), if any.
    pub fn of_columns(columns: &[String]) -> Option<(Self, usize)> {
        Self::layout_of(columns).map(|(r, n, _)| (r, n))
    }

    /// As [`SweepRun::of_columns`], and whether the columns end with a helical pair's
    /// (`super::helical_row`; a single pair's only).
    pub fn layout_of(columns: &[String]) -> Option<(Self, usize, bool)> {
        // A mesh adds at least MESH_COLUMNS' five columns, so no more meshes can fit.
        let most = columns.len() / MESH_COLUMNS.len();
        [SweepRun::Wear, SweepRun::Dynamics]
            .into_iter()
            .find_map(|r| {
                let helical = [r.columns_for(0), helical_columns(r == SweepRun::Wear)].concat();
                if helical == columns {
                    return Some((r, 0, true));
                }
                (0..=most)
                    .find(|n| r.columns_for(*n) == columns)
                    .map(|n| (r, n, false))
            })
    }

    /// The run, train meshes and planets (0: none) whose result columns are `columns`
    /// (`CaseResults::columns`), if any.
    pub fn shape_of(columns: &[String]) -> Option<(Self, usize, usize)> {
        match planets_of(columns) {
            Some((n, wear)) => {
                let head = &columns[..columns.len() - planetary_columns(n, wear).len()];
                let run = if wear {
                    SweepRun::Wear
                } else {
                    SweepRun::Dynamics
                };
                (head == run.columns().as_slice()).then_some((run, 0, n))
            }
            None => Self::of_columns(columns).map(|(r, s)| (r, s, 0)),
        }
    }

    /// The result columns of a case of `stages` train meshes (0: a single pair): this
    /// run's, then each mesh's, then (a wear sweep of a train) each mesh's wear and the
    /// limiting stages ([`super::mesh_row`]).
    pub fn columns_for(&self, stages: usize) -> Vec<String> {
        let mut c = self.columns();
        c.extend(mesh_columns(stages));
        if *self == SweepRun::Wear {
            c.extend(mesh_wear_columns(stages));
        }
        c
    }
}

/// The headline numbers of one dynamic evaluation, as a sweep row holds them (display
/// units; NaN where a number is not finite). Unit conversions are written as in
/// `gearwear dynamics`' summary.json (x 1e6 for um, x 1e3 for mm/s), so the numbers are
/// bit-identical to it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DynamicsRow {
    /// Largest dynamic transmission error, µm.
    pub dte_max_um: f64,
    /// RMS of the pinion's lateral velocity dy_p/dt, mm/s.
    pub velocity_y_pinion_rms_mm_per_s: f64,
    /// Mean mesh force, N.
    pub mesh_force_mean_n: f64,
    /// Largest mesh force, N.
    pub mesh_force_max_n: f64,
    /// Dynamic factor: largest over mean mesh force.
    pub dynamic_factor: f64,
    /// First to fourth mesh harmonic of dy_p/dt, mm/s.
    pub mesh_harmonics_mm_per_s: [f64; 4],
}

impl DynamicsRow {
    /// The row of a response summary (SI) in display units.
    pub fn of(s: &ResponseSummary) -> Self {
        let h = s.velocity_y_pinion_harmonics_m_per_s;
        Self {
            dte_max_um: s.dte_max_m * 1e6,
            velocity_y_pinion_rms_mm_per_s: s.velocity_y_pinion_rms_m_per_s * 1e3,
            mesh_force_mean_n: s.mesh_force_mean_n,
            mesh_force_max_n: s.mesh_force_max_n,
            dynamic_factor: s.dynamic_factor,
            mesh_harmonics_mm_per_s: [h[0] * 1e3, h[1] * 1e3, h[2] * 1e3, h[3] * 1e3],
        }
    }

    pub(super) fn values(&self) -> [f64; 9] {
        let h = self.mesh_harmonics_mm_per_s;
        [
            self.dte_max_um,
            self.velocity_y_pinion_rms_mm_per_s,
            self.mesh_force_mean_n,
            self.mesh_force_max_n,
            self.dynamic_factor,
            h[0],
            h[1],
            h[2],
            h[3],
        ]
    }

    /// From numbers in the dynamics columns' order (at least nine).
    pub(crate) fn from_values(v: &[f64]) -> Self {
        Self {
            dte_max_um: v[0],
            velocity_y_pinion_rms_mm_per_s: v[1],
            mesh_force_mean_n: v[2],
            mesh_force_max_n: v[3],
            dynamic_factor: v[4],
            mesh_harmonics_mm_per_s: [v[5], v[6], v[7], v[8]],
        }
    }
}

/// Where one wear run of a sweep case ended.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WearEnd {
    /// Deepest pinion wear at the run's end, µm (NaN without a record).
    pub max_wear_pinion_um: f64,
    /// Deepest gear wear at the run's end, µm (NaN without a record).
    pub max_wear_gear_um: f64,
    /// Updates after the first (new-teeth) record.
    pub updates: f64,
    /// Cycles reached.
    pub cycles: f64,
}

impl WearEnd {
    /// Where `run` ended.
    pub fn of(run: &WearRun) -> Self {
        let last = run.last();
        Self {
            max_wear_pinion_um: last.map_or(f64::NAN, |r| r.wear.max_pinion_m() * 1e6),
            max_wear_gear_um: last.map_or(f64::NAN, |r| r.wear.max_gear_m() * 1e6),
            updates: run.records.len().saturating_sub(1) as f64,
            cycles: last.map_or(f64::NAN, |r| r.wear.cycles),
        }
    }

    pub(super) fn values(&self) -> [f64; 4] {
        [
            self.max_wear_pinion_um,
            self.max_wear_gear_um,
            self.updates,
            self.cycles,
        ]
    }

    pub(super) fn from_values(v: &[f64]) -> Self {
        Self {
            max_wear_pinion_um: v[0],
            max_wear_gear_um: v[1],
            updates: v[2],
            cycles: v[3],
        }
    }
}
