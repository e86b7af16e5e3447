//! The columns a helical pair adds to a sweep row (`gear.helix_angle_deg` > 0, its planar
//! model `study::helical_dynamics`, docs/MODEL.md 11), after the pair's own columns:
//!
//! - both runs: the total contact ratio epsilon_gamma (ISO 21771, `geometry::helical`),
//!   the mean axial force on the pinion (N, + along its angular velocity: the
//!   `axial_force_pinion.mean_n` of `gearwear dynamics`' summary.json, s F_m tan(beta_b),
//!   `HelicalDynamics::axial_per_transverse`), and with lead gaps the dynamic face load's
//!   K_Hbeta and centre of pressure (mm from the face end y = 0; `face_load.k_h_beta` and
//!   `face_load.centre_of_pressure_mm` there, `study::face_load_dynamic`; empty without lead
//!   keys, where `gearwear dynamics` has no `face_load` either);
//! - a wear sweep: per mode where across the face the wear map is deepest at the run's
//!   end, pinion and gear, mm from the face end y = 0 (the slice's centre,
//!   `wear_map.MODE.pinion.max_wear_position_mm` of `gearwear wear`'s summary.json). The
//!   depth itself is the pair's `wear_max_*` columns: on a helical pair they are the
//!   deepest entry of the wear map (`WearState::max_pinion_m`, every face slice), its
//!   `wear_map.MODE.pinion.max_wear_um`.
//!
//! The numbers are computed as those summaries compute them (same operations, same order),
//! so a row equals them bit for bit. A table holds these columns when its base case is
//! helical or an axis varies `gear.helix_angle_deg` ([`HELIX_KEY`]); its spur cases leave
//! them empty (a spur pair has no slice model): their other columns are a spur sweep's.

use crate::dynamics::response::DynamicResponse;
use crate::study::face_load_dynamic::DynamicFaceLoad;
use crate::study::helical::HelicalDynamics;
use crate::study::wear_loop::WearRun;
use crate::study::Model;

/// The key that makes a sweep's table helical when an axis varies it.
pub const HELIX_KEY: &str = "gear.helix_angle_deg";

/// The helical columns of both runs.
pub const HELICAL_COLUMNS: [&str; 4] = [
    "total_contact_ratio",
    "axial_force_pinion_mean_n",
    "k_h_beta",
    "centre_of_pressure_mm",
];

/// The helical columns a wear sweep adds: where the wear map is deepest across the face,
/// per mode and flank.
pub const HELICAL_WEAR_COLUMNS: [&str; 4] = [
    "wear_map_deepest_pinion_position_dynamic_mm",
    "wear_map_deepest_gear_position_dynamic_mm",
    "wear_map_deepest_pinion_position_quasi_static_mm",
    "wear_map_deepest_gear_position_quasi_static_mm",
];

/// The helical columns of a sweep's run (`wear`: a wear sweep's), in row order.
pub fn helical_columns(wear: bool) -> Vec<String> {
    let mut c: Vec<String> = HELICAL_COLUMNS.iter().map(|s| s.to_string()).collect();
    if wear {
        c.extend(HELICAL_WEAR_COLUMNS.iter().map(|s| s.to_string()));
    }
    c
}

/// What a helical case adds to its row (module docs); NaN where a number does not exist.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HelicalRow {
    /// Total contact ratio epsilon_gamma = epsilon_alpha + epsilon_beta.
    pub total_contact_ratio: f64,
    /// Time mean of the axial force on the pinion, N (+ along its angular velocity).
    pub axial_force_pinion_mean_n: f64,
    /// Dynamic face load factor K_Hbeta (NaN without lead gaps).
    pub k_h_beta: f64,
    /// Dynamic centre of pressure across the face, mm (NaN without lead gaps).
    pub centre_of_pressure_mm: f64,
    /// A wear sweep: the face position of the wear map's deepest entry at the end of the
    /// dynamic run (pinion, gear), then of the quasi-static run, mm.
    pub wear_map_deepest_mm: Option<[f64; 4]>,
}

impl HelicalRow {
    /// The row of a spur case in a helical table (of a wear sweep when `wear`): every
    /// number empty.
    pub fn empty(wear: bool) -> Self {
        Self {
            total_contact_ratio: f64::NAN,
            axial_force_pinion_mean_n: f64::NAN,
            k_h_beta: f64::NAN,
            centre_of_pressure_mm: f64::NAN,
            wear_map_deepest_mm: wear.then_some([f64::NAN; 4]),
        }
    }

    /// The dynamics columns of a helical model `model` (None for a spur model) whose new
    /// teeth's mean mesh force is `mean_force_n` (N), with the dynamic face load `face` of
    /// its steady state (None without lead gaps).
    pub fn of_dynamics(
        model: &Model,
        mean_force_n: f64,
        face: Option<&DynamicFaceLoad>,
    ) -> Option<Self> {
        let h: &HelicalDynamics = model.helical.as_ref()?;
        Some(Self {
            total_contact_ratio: h.pair.total_contact_ratio,
            // As `report::dynamics_helical::helical_summary`: s tan(beta_b) F_m.
            axial_force_pinion_mean_n: h.pinion_axial_sign()
                * h.axial_per_transverse()
                * mean_force_n,
            k_h_beta: face.map_or(f64::NAN, DynamicFaceLoad::k_h_beta),
            centre_of_pressure_mm: face.map_or(f64::NAN, |d| d.centre_of_pressure_m() * 1e3),
            wear_map_deepest_mm: None,
        })
    }

    /// [`HelicalRow::of_dynamics`] of a steady state `r` of new teeth (no external error,
    /// as a sweep case runs it).
    pub fn of_response(model: &Model, r: &DynamicResponse) -> Option<Self> {
        let none = crate::dynamics::excitation::ExternalError::none();
        let face = DynamicFaceLoad::of(model, r, &none);
        Self::of_dynamics(model, r.meshes[0].mean_mesh_force_n, face.as_ref())
    }

    /// The same row with where the wear maps of `model` are deepest at the ends of the
    /// dynamic run `d` and the quasi-static run `q`.
    pub fn with_wear_maps(self, model: &Model, d: &WearRun, q: &WearRun) -> Self {
        let [pd, gd] = deepest_position_mm(model, d);
        let [pq, gq] = deepest_position_mm(model, q);
        Self {
            wear_map_deepest_mm: Some([pd, gd, pq, gq]),
            ..self
        }
    }

    /// The numbers in [`helical_columns`] order.
    pub fn values(&self) -> Vec<f64> {
        let mut v = vec![
            self.total_contact_ratio,
            self.axial_force_pinion_mean_n,
            self.k_h_beta,
            self.centre_of_pressure_mm,
        ];
        v.extend(self.wear_map_deepest_mm.iter().flatten());
        v
    }

    /// From numbers in [`helical_columns`] order (of a wear sweep when `wear`); None when
    /// their count is not it.
    pub fn from_values(wear: bool, v: &[f64]) -> Option<Self> {
        if v.len() != helical_columns(wear).len() {
            return None;
        }
        Some(Self {
            total_contact_ratio: v[0],
            axial_force_pinion_mean_n: v[1],
            k_h_beta: v[2],
            centre_of_pressure_mm: v[3],
            wear_map_deepest_mm: wear.then(|| [v[4], v[5], v[6], v[7]]),
        })
    }
}

/// Where the wear map at the end of `run` is deepest across the face, pinion and gear, mm:
/// the centre of the first slice holding the largest entry (from 0, as
/// `report::helical_wear` finds it; slice 0 when nothing wore); NaN without a map.
fn deepest_position_mm(model: &Model, run: &WearRun) -> [f64; 2] {
    let (Some(h), Some(map)) = (
        &model.helical,
        run.last().and_then(|r| r.wear.slices.as_ref()),
    ) else {
        return [f64::NAN; 2];
    };
    let y = h.slice_model.positions_m();
    let slice = |p: &[Vec<f64>]| {
        let mut best = (0.0, 0);
        for (j, profile) in p.iter().enumerate() {
            for d in profile {
                if *d > best.0 {
                    best = (*d, j);
                }
            }
        }
        y.get(best.1).map_or(f64::NAN, |y| y * 1e3)
    };
    [slice(&map.pinion_m), slice(&map.gear_m)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_in_column_order() {
        for wear in [false, true] {
            let mut r = HelicalRow::empty(wear);
            r.total_contact_ratio = 2.5;
            r.k_h_beta = 1.25;
            if let Some(w) = r.wear_map_deepest_mm.as_mut() {
                w[3] = 7.0;
            }
            let v = r.values();
            assert_eq!(v.len(), helical_columns(wear).len());
            let back = HelicalRow::from_values(wear, &v).unwrap();
            assert_eq!(back.total_contact_ratio, 2.5);
            assert_eq!(back.k_h_beta, 1.25);
            assert_eq!(
                back.wear_map_deepest_mm.map(|w| w[3]),
                r.wear_map_deepest_mm.map(|w| w[3])
            );
            assert!(HelicalRow::from_values(wear, &v[1..]).is_none());
        }
    }
}
