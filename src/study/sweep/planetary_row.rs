//! The columns of a planetary set (`[planetary]`) in a sweep row: each sun-planet and
//! ring-planet mesh's mean and largest force and dynamic factor, then each planet's load
//! sharing factor, after the single pair's columns (which, for a set, are its first
//! sun-planet mesh's force columns, the others empty: the set's summary has no DTE or
//! pinion velocity); a wear row then adds every member flank's deepest wear and its wear
//! volume over all its teeth at the end of each mode's run ([`planetary_wear_columns`],
//! `super::planetary_wear_row`).
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
    /// A wear row's: every member flank's deepest wear at the end of the dynamic and the
    /// quasi-static run, µm, then its wear volume over all its teeth at those ends, mm^3
    /// ([`FLANK_WEAR_COLUMNS`] order), in [`flank_stems`] order; empty in a dynamics row.
    pub wear: Vec<[f64; 4]>,
}

impl PlanetaryRow {
    /// The number of planets N.
    pub fn planets(&self) -> usize {
        self.load_sharing.len()
    }

    /// Whether the row is a wear row's (it has the flanks' wear columns).
    pub fn has_wear(&self) -> bool {
        !self.wear.is_empty()
    }

    /// The numbers in [`planetary_columns`] order.
    pub fn values(&self) -> Vec<f64> {
        let mut v: Vec<f64> = self.meshes.iter().flatten().copied().collect();
        v.extend(&self.load_sharing);
        v.extend(self.wear.iter().flatten());
        v
    }

    /// From numbers in [`planetary_columns`] order of `planets` planets (with the flanks'
    /// wear columns when `wear`); `None` when their count is not it.
    pub fn from_values(planets: usize, wear: bool, v: &[f64]) -> Option<Self> {
        let n = PLANETARY_MESH_COLUMNS.len();
        let own = 2 * planets * n + planets;
        let flanks = if wear { flank_stems(planets).len() } else { 0 };
        let per = FLANK_WEAR_COLUMNS.len();
        if planets == 0 || v.len() != own + per * flanks {
            return None;
        }
        Some(Self {
            meshes: v[..2 * planets * n]
                .chunks_exact(n)
                .map(|c| [c[0], c[1], c[2]])
                .collect(),
            load_sharing: v[2 * planets * n..own].to_vec(),
            wear: v[own..]
                .chunks_exact(per)
                .map(|c| [c[0], c[1], c[2], c[3]])
                .collect(),
        })
    }
}

/// Names of a member flank's wear columns after its [`flank_stems`] prefix: its deepest
/// wear at the end of the dynamic and of the quasi-static run, µm, and its wear volume
/// over all its teeth at those ends, mm^3 (as `members[..].final.MODE.flanks.FLANK`'s
/// `max_wear_um` and `volume_mm3` of `gearwear wear`'s summary.json).
pub const FLANK_WEAR_COLUMNS: [&str; 4] = [
    "wear_max_dynamic_um",
    "wear_max_quasi_static_um",
    "wear_volume_dynamic_mm3",
    "wear_volume_quasi_static_mm3",
];

/// The member flanks of a set of `planets` planets as column prefixes, in the order of
/// `study::planetary_wear::member_flanks`: `sun`, then each planet's `planet<N>_sun_side`
/// and `planet<N>_ring_side`, then `ring`.
pub fn flank_stems(planets: usize) -> Vec<String> {
    let mut s = vec!["sun".to_string()];
    for n in 1..=planets {
        s.push(format!("planet{n}_sun_side"));
        s.push(format!("planet{n}_ring_side"));
    }
    s.push("ring".into());
    s
}

/// The flanks' wear columns of a set of `planets` planets: [`FLANK_WEAR_COLUMNS`] of every
/// flank of [`flank_stems`].
pub fn planetary_wear_columns(planets: usize) -> Vec<String> {
    flank_stems(planets)
        .iter()
        .flat_map(|f| FLANK_WEAR_COLUMNS.iter().map(move |c| format!("{f}_{c}")))
        .collect()
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
/// (sun-planet 1..N, then ring-planet 1..N), then `planet<N>_load_sharing_factor`, then
/// (a wear row, `wear`) [`planetary_wear_columns`].
pub fn planetary_columns(planets: usize, wear: bool) -> Vec<String> {
    let mut c: Vec<String> = (0..2 * planets)
        .flat_map(|j| {
            PLANETARY_MESH_COLUMNS
                .iter()
                .map(move |name| format!("{}_{name}", mesh_prefix(j, planets)))
        })
        .collect();
    c.extend((1..=planets).map(|n| format!("planet{n}_{LOAD_SHARING_COLUMN}")));
    if wear {
        c.extend(planetary_wear_columns(planets));
    }
    c
}

/// The number of planets whose columns end `columns` exactly, if any (≥ 1), and whether
/// they are a wear row's.
pub fn planets_of(columns: &[String]) -> Option<(usize, bool)> {
    let per_planet = 2 * PLANETARY_MESH_COLUMNS.len() + 1;
    (1..=columns.len() / per_planet).find_map(|n| {
        [true, false]
            .into_iter()
            .find(|w| columns.ends_with(&planetary_columns(n, *w)))
            .map(|w| (n, w))
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
        wear: Vec::new(),
    };
    Ok((row, d.study.warnings.clone()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_name_each_mesh_and_planet_and_read_back() {
        let c = planetary_columns(3, false);
        // 2 N meshes x 3 columns + N planets.
        assert_eq!(c.len(), 2 * 3 * 3 + 3);
        assert_eq!(c[0], "sun_planet1_mesh_force_mean_n");
        assert_eq!(c[9], "ring_planet1_mesh_force_mean_n");
        assert_eq!(c[17], "ring_planet3_dynamic_factor");
        assert_eq!(c[20], "planet3_load_sharing_factor");
        let mut with_pair = vec!["dte_max_um".to_string()];
        with_pair.extend(c.clone());
        assert_eq!(planets_of(&with_pair), Some((3, false)));
        assert_eq!(planets_of(&with_pair[..with_pair.len() - 1]), None);
        let v: Vec<f64> = (0..c.len()).map(|i| i as f64 + 0.5).collect();
        let row = PlanetaryRow::from_values(3, false, &v).unwrap();
        assert_eq!(row.planets(), 3);
        assert_eq!(row.values(), v);
        assert_eq!(PlanetaryRow::from_values(4, false, &v), None);
        // A wear row: every member names its flanks, depth and volume in two modes
        // each: the sun, each planet's two flanks and the ring, (2 N + 2) x 4 columns more.
        let w = planetary_columns(3, true);
        assert_eq!(w.len(), c.len() + (2 * 3 + 2) * 4);
        assert_eq!(w[c.len()], "sun_wear_max_dynamic_um");
        assert_eq!(w[c.len() + 3], "sun_wear_volume_quasi_static_mm3");
        assert_eq!(w[c.len() + 5], "planet1_sun_side_wear_max_quasi_static_um");
        assert_eq!(w[c.len() + 8], "planet1_ring_side_wear_max_dynamic_um");
        assert_eq!(w[w.len() - 1], "ring_wear_volume_quasi_static_mm3");
        for n in 1..=3 {
            for f in ["sun_side", "ring_side"] {
                assert!(w.contains(&format!("planet{n}_{f}_wear_max_dynamic_um")));
            }
        }
        with_pair.truncate(1);
        with_pair.extend(w.clone());
        assert_eq!(planets_of(&with_pair), Some((3, true)));
        let v: Vec<f64> = (0..w.len()).map(|i| i as f64 + 0.25).collect();
        let row = PlanetaryRow::from_values(3, true, &v).unwrap();
        assert!(row.has_wear() && row.wear.len() == 8);
        assert_eq!(row.values(), v);
        assert_eq!(PlanetaryRow::from_values(3, false, &v), None);
    }
}
