//! The columns of each mesh of a gear train (`[[stage]]`) in a sweep row: one column set
//! per mesh, `stage<K>_<name>` (K = 1, 2, ... as the `[[stage]]` tables), after the
//! single-pair columns (which, for a train, are its first mesh's, as the top level of
//! `gearwear dynamics`' summary.json).
//!
//! The numbers are those of the `meshes` entries of `gearwear dynamics`' summary.json
//! (`study::train::TrainModel::mesh_summaries`), with the same unit conversions
//! (x 1e6 for um), so a one-point sweep equals the single run bit for bit.

use crate::dynamics::summary::ResponseSummary;

/// Names of a mesh's columns after its `stage<K>_` prefix, display units in the names.
pub const MESH_COLUMNS: [&str; 5] = [
    "mesh_frequency_hz",
    "dte_max_um",
    "mesh_force_mean_n",
    "mesh_force_max_n",
    "dynamic_factor",
];

/// One mesh of a train in a sweep row (display units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MeshRow {
    /// The mesh frequency of the case's operating point, Hz.
    pub mesh_frequency_hz: f64,
    /// Maximum dynamic transmission error of the mesh, um.
    pub dte_max_um: f64,
    /// Mean mesh force over the evaluated window, N.
    pub mesh_force_mean_n: f64,
    /// Maximum mesh force over the evaluated window, N.
    pub mesh_force_max_n: f64,
    /// Maximum over mean mesh force (-).
    pub dynamic_factor: f64,
}

impl MeshRow {
    /// The row of a mesh whose summary is `s` and mesh frequency `mesh_frequency_hz` (Hz).
    pub fn of(s: &ResponseSummary, mesh_frequency_hz: f64) -> Self {
        Self {
            mesh_frequency_hz,
            dte_max_um: s.dte_max_m * 1e6,
            mesh_force_mean_n: s.mesh_force_mean_n,
            mesh_force_max_n: s.mesh_force_max_n,
            dynamic_factor: s.dynamic_factor,
        }
    }

    /// The numbers in [`MESH_COLUMNS`] order.
    pub fn values(&self) -> [f64; 5] {
        [
            self.mesh_frequency_hz,
            self.dte_max_um,
            self.mesh_force_mean_n,
            self.mesh_force_max_n,
            self.dynamic_factor,
        ]
    }

    /// From numbers in [`MESH_COLUMNS`] order (at least five).
    pub fn from_values(v: &[f64]) -> Self {
        Self {
            mesh_frequency_hz: v[0],
            dte_max_um: v[1],
            mesh_force_mean_n: v[2],
            mesh_force_max_n: v[3],
            dynamic_factor: v[4],
        }
    }
}

/// Names of a mesh's wear columns in a wear sweep of a train, after its `stage<K>_`
/// prefix: the deepest wear of each flank at the end of each mode's run, µm (as the
/// `meshes[K-1].final.MODE` entries of `gearwear wear`'s summary.json).
pub const MESH_WEAR_COLUMNS: [&str; 4] = [
    "wear_max_pinion_dynamic_um",
    "wear_max_gear_dynamic_um",
    "wear_max_pinion_quasi_static_um",
    "wear_max_gear_quasi_static_um",
];

/// The last columns of a wear sweep of a train: the stage (1-based) whose mesh limits
/// the life in each mode (the deepest wear of either flank at the run's end, as
/// `limiting_mesh.MODE.stage` of `gearwear wear`'s summary.json).
pub const LIMITING_STAGE_COLUMNS: [&str; 2] = [
    "wear_limiting_stage_dynamic",
    "wear_limiting_stage_quasi_static",
];

/// One mesh of a train at the end of a wear sweep case's runs (display units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MeshWear {
    /// Deepest pinion and gear wear at the end of the dynamic run, µm (NaN without a
    /// record).
    pub dynamic_um: [f64; 2],
    /// Deepest pinion and gear wear at the end of the quasi-static run, µm.
    pub quasi_static_um: [f64; 2],
}

impl MeshWear {
    /// The numbers in [`MESH_WEAR_COLUMNS`] order.
    pub fn values(&self) -> [f64; 4] {
        let (d, q) = (self.dynamic_um, self.quasi_static_um);
        [d[0], d[1], q[0], q[1]]
    }

    /// From numbers in [`MESH_WEAR_COLUMNS`] order (at least four).
    pub fn from_values(v: &[f64]) -> Self {
        Self {
            dynamic_um: [v[0], v[1]],
            quasi_static_um: [v[2], v[3]],
        }
    }
}

/// The wear of every mesh of a train at the end of a wear sweep case's runs, and the
/// stage that limits each mode's life.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TrainWearEnd {
    /// Each mesh, stage by stage.
    pub meshes: Vec<MeshWear>,
    /// The limiting stage (1-based) of the dynamic and the quasi-static run (NaN without
    /// a record).
    pub limiting_stage: [f64; 2],
}

impl TrainWearEnd {
    /// The numbers in [`mesh_wear_columns`] order.
    pub fn values(&self) -> Vec<f64> {
        let mut v: Vec<f64> = self.meshes.iter().flat_map(MeshWear::values).collect();
        v.extend(self.limiting_stage);
        v
    }

    /// From numbers in [`mesh_wear_columns`] order of `stages` meshes; `None` when their
    /// count is not it.
    pub fn from_values(stages: usize, v: &[f64]) -> Option<Self> {
        let n = MESH_WEAR_COLUMNS.len();
        if stages == 0 || v.len() != stages * n + LIMITING_STAGE_COLUMNS.len() {
            return None;
        }
        Some(Self {
            meshes: v[..stages * n]
                .chunks_exact(n)
                .map(MeshWear::from_values)
                .collect(),
            limiting_stage: [v[stages * n], v[stages * n + 1]],
        })
    }
}

/// The wear columns of `stages` meshes, stage by stage, then [`LIMITING_STAGE_COLUMNS`]
/// (none for a single pair, `stages` = 0).
pub fn mesh_wear_columns(stages: usize) -> Vec<String> {
    if stages == 0 {
        return Vec::new();
    }
    (1..=stages)
        .flat_map(|k| MESH_WEAR_COLUMNS.iter().map(move |c| mesh_column(k, c)))
        .chain(LIMITING_STAGE_COLUMNS.iter().map(|c| c.to_string()))
        .collect()
}

/// The column of `name` (one of [`MESH_COLUMNS`]) of stage `k` (1-based).
pub fn mesh_column(k: usize, name: &str) -> String {
    format!("stage{k}_{name}")
}

/// The columns of `stages` meshes, stage by stage.
pub fn mesh_columns(stages: usize) -> Vec<String> {
    (1..=stages)
        .flat_map(|k| MESH_COLUMNS.iter().map(move |c| mesh_column(k, c)))
        .collect()
}

/// The number of meshes whose columns `columns` are exactly ([`mesh_columns`]); `None`
/// when they are not mesh columns.
pub fn stages_of(columns: &[String]) -> Option<usize> {
    let n = columns.len() / MESH_COLUMNS.len();
    (columns.len().is_multiple_of(MESH_COLUMNS.len()) && columns == mesh_columns(n).as_slice())
        .then_some(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_name_each_stage_and_read_back() {
        let c = mesh_columns(2);
        assert_eq!(c.len(), 10);
        assert_eq!(c[0], "stage1_mesh_frequency_hz");
        assert_eq!(c[9], "stage2_dynamic_factor");
        assert_eq!(stages_of(&c), Some(2));
        assert_eq!(stages_of(&[]), Some(0));
        assert_eq!(stages_of(&c[..9]), None);
        let mut swapped = c.clone();
        swapped.swap(0, 5);
        assert_eq!(stages_of(&swapped), None);
        let s = ResponseSummary {
            dte_max_m: 3e-6,
            dynamic_factor: 1.25,
            ..Default::default()
        };
        let r = MeshRow::of(&s, 570.0);
        // 3e-6 m is 3 um (to the rounding of the unit factor).
        assert!((r.dte_max_um - 3.0).abs() < 1e-12);
        assert_eq!(MeshRow::from_values(&r.values()), r);
    }
}
