//! The columns of a planetary set (`[planetary]`) in a dynamics sweep row: each sun-planet
//! and ring-planet mesh's mean and largest force and dynamic factor, then each planet's
//! load sharing factor, after the single pair's columns (which, for a set, are its first
//! sun-planet mesh's force columns, the others empty: the set's summary has no DTE or
//! pinion velocity).
//!
//! The numbers are those of `gearwear dynamics`' summary.json on the set
//! (`report::dynamics_planetary`): `meshes[j].mean_force_n`, `meshes[j].max_force_n`,
//! the dynamic factor as max_force_n / `nominal_mesh_force_n` (docs/MODEL.md 12.6) and
//! `load_sharing_factor[n]` (12.8), computed by the same functions, so a one-point sweep
//! equals the single run bit for bit.

use crate::config::Case;
use crate::study::model::ModelError;
use crate::study::planetary_dynamics::{shares, PlanetaryDynamics};

/// Names of a planetary mesh's columns after its `sun_planet<N>_` / `ring_planet<N>_`
/// prefix, display units in the names.
pub const PLANETARY_MESH_COLUMNS: [&str; 3] =
    ["mesh_force_mean_n", "mesh_force_max_n", "dynamic_factor"];

/// Name of a planet's load sharing column after its `planet<N>_` prefix.
pub const LOAD_SHARING_COLUMN: &str = "load_sharing_factor";

/// The set's columns of a row (display units).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PlanetaryRow {
    /// Each mesh (sun-planet 1..N, then ring-planet 1..N): mean force N, largest force N,
    /// dynamic factor (-).
    pub meshes: Vec<[f64; 3]>,
    /// Each planet's load sharing factor (its sun mesh's mean over the planets' mean).
    pub load_sharing: Vec<f64>,
}

impl PlanetaryRow {
    /// The number of planets N.
    pub fn planets(&self) -> usize {
        self.load_sharing.len()
    }

    /// The numbers in [`planetary_columns`] order.
    pub fn values(&self) -> Vec<f64> {
        let mut v: Vec<f64> = self.meshes.iter().flatten().copied().collect();
        v.extend(&self.load_sharing);
        v
    }

    /// From numbers in [`planetary_columns`] order of `planets` planets; `None` when their
    /// count is not it.
    pub fn from_values(planets: usize, v: &[f64]) -> Option<Self> {
        let n = PLANETARY_MESH_COLUMNS.len();
        if planets == 0 || v.len() != 2 * planets * n + planets {
            return None;
        }
        Some(Self {
            meshes: v[..2 * planets * n]
                .chunks_exact(n)
                .map(|c| [c[0], c[1], c[2]])
                .collect(),
            load_sharing: v[2 * planets * n..].to_vec(),
        })
    }
}

/// The mesh named as `gearwear dynamics`' summary names it: `sun_planet_<n>` and
/// `ring_planet_<n>` there, `sun_planet<n>` / `ring_planet<n>` as a column prefix.
fn mesh_prefix(j: usize, planets: usize) -> String {
    if j < planets {
        format!("sun_planet{}", j + 1)
    } else {
        format!("ring_planet{}", j - planets + 1)
    }
}

/// The columns of a set of `planets` planets: every mesh's [`PLANETARY_MESH_COLUMNS`]
/// (sun-planet 1..N, then ring-planet 1..N), then `planet<N>_load_sharing_factor`.
pub fn planetary_columns(planets: usize) -> Vec<String> {
    let mut c: Vec<String> = (0..2 * planets)
        .flat_map(|j| {
            PLANETARY_MESH_COLUMNS
                .iter()
                .map(move |name| format!("{}_{name}", mesh_prefix(j, planets)))
        })
        .collect();
    c.extend((1..=planets).map(|n| format!("planet{n}_{LOAD_SHARING_COLUMN}")));
    c
}

/// The number of planets whose columns end `columns` exactly, if any (≥ 1).
pub fn planets_of(columns: &[String]) -> Option<usize> {
    let per_planet = 2 * PLANETARY_MESH_COLUMNS.len() + 1;
    (1..=columns.len() / per_planet).find(|&n| {
        let own = planetary_columns(n);
        columns.ends_with(&own)
    })
}

/// Why a planetary case's sweep row could not be computed.
#[derive(Debug)]
pub enum PlanetaryRunError {
    /// The set's model cannot be built from the case.
    Model(ModelError),
    /// Its steady state was not found.
    Solve(anyhow::Error),
}

/// One steady state of the set in `case` with new teeth, reduced to a row (as
/// `gearwear dynamics` on it), with the model's warnings.
pub fn run_planetary_dynamics(
    case: &Case,
) -> Result<(PlanetaryRow, Vec<String>), PlanetaryRunError> {
    let mut d = PlanetaryDynamics::from_case(case).map_err(PlanetaryRunError::Model)?;
    let r = d
        .solve()
        .map_err(|e| PlanetaryRunError::Solve(anyhow::Error::new(e)))?;
    let planets = d.study.set.planets();
    let nominal = d.nominal_mesh_force_n();
    let max = r.max_forces_n();
    let mean = &r.mean_forces_n;
    let meshes: Vec<[f64; 3]> = (0..2 * planets)
        .map(|j| [mean[j], max[j], max[j] / nominal])
        .collect();
    let row = PlanetaryRow {
        load_sharing: shares(&mean[..planets]),
        meshes,
    };
    Ok((row, d.study.warnings.clone()))
}

/// The refusal of a planetary set's wear sweep (`--run wear`): not built yet.
pub fn wear_refusal() -> ModelError {
    ModelError(vec!["`[planetary]` in a sweep of wear: a planetary set's wear sweep is not built yet; `gearwear sweep` of dynamics takes a planetary set (each mesh's force and dynamic factor, each planet's load sharing), `gearwear wear` wears one set".into()])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_name_each_mesh_and_planet_and_read_back() {
        let c = planetary_columns(3);
        // 2 N meshes x 3 columns + N planets.
        assert_eq!(c.len(), 2 * 3 * 3 + 3);
        assert_eq!(c[0], "sun_planet1_mesh_force_mean_n");
        assert_eq!(c[9], "ring_planet1_mesh_force_mean_n");
        assert_eq!(c[17], "ring_planet3_dynamic_factor");
        assert_eq!(c[20], "planet3_load_sharing_factor");
        let mut with_pair = vec!["dte_max_um".to_string()];
        with_pair.extend(c.clone());
        assert_eq!(planets_of(&with_pair), Some(3));
        assert_eq!(planets_of(&with_pair[..with_pair.len() - 1]), None);
        let v: Vec<f64> = (0..c.len()).map(|i| i as f64 + 0.5).collect();
        let row = PlanetaryRow::from_values(3, &v).unwrap();
        assert_eq!(row.planets(), 3);
        assert_eq!(row.values(), v);
        assert_eq!(PlanetaryRow::from_values(4, &v), None);
    }
}
