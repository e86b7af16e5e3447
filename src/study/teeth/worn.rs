//! What severe wear (`wear.worn_geometry = "worn"`) does to a flank besides removing
//! material: the worn tooth's added compliance and the change of its curvature, tabled on
//! the wear grid for each worn profile.

use crate::config::case::Case;
use crate::contact::worn_curvature::curvature_change_per_m;
use crate::dynamics::tooth_mesh::ToothFlank;
use crate::geometry::{GearPair, ProfileGrid};
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::potential_energy::ToothBeam;
use crate::stiffness::worn_tooth::worn_compliance_m_per_n;

/// What the worn flanks of severe wear are computed from (see [`super::ToothInputs`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WornFlanks {
    beams: [ToothBeam; 2],
    /// Own rho of the grid points, ascending, and the grid index of each.
    rho_m: [Vec<f64>; 2],
    half_width_m: f64,
}

/// The added compliance and the curvature change of one worn flank on the grid.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WornTables {
    compliance_m_per_n: Vec<f64>,
    curvature_change_per_m: Vec<f64>,
}

impl WornTables {
    pub(crate) fn apply(self, f: &mut ToothFlank) {
        if self.compliance_m_per_n.iter().all(|c| *c == 0.0) {
            return;
        }
        let table = f
            .compliance_m_per_n
            .get_or_insert_with(|| vec![0.0; self.compliance_m_per_n.len()]);
        for (a, b) in table.iter_mut().zip(&self.compliance_m_per_n) {
            *a += b;
        }
        f.curvature_change_per_m = Some(self.curvature_change_per_m);
    }
}

impl WornFlanks {
    /// The worn flanks' beams, grid points and nominal Hertz half-width under
    /// `static_force_n` at the pitch point.
    pub(crate) fn of(
        case: &Case,
        pair: &GearPair,
        mesh: &MeshStiffness,
        grid: &ProfileGrid,
        static_force_n: f64,
    ) -> Self {
        let r = crate::contact::hertz::effective_radius_m(
            pair.rho_pitch_m,
            pair.rho_gear(pair.rho_pitch_m),
        );
        WornFlanks {
            beams: mesh.tooth_beams().clone(),
            rho_m: [
                grid.rho_pinion_m.clone(),
                grid.rho_gear_m.iter().rev().copied().collect(),
            ],
            half_width_m: crate::contact::hertz::HertzContact::with_radius(
                static_force_n,
                pair.face_width_m,
                r,
                crate::contact::hertz::effective_modulus_of(&case.materials),
            )
            .half_width_m,
        }
    }

    /// The tables of a flank of gear `side` worn by `wear_m` (grid order: the pinion's
    /// ascending rho1, the gear's conjugate points).
    pub(crate) fn tables(&self, side: usize, wear_m: &[f64]) -> WornTables {
        let rho = &self.rho_m[side];
        // The wear in ascending own rho (the gear's grid runs the other way).
        let w: Vec<f64> = match side {
            0 => wear_m.to_vec(),
            _ => wear_m.iter().rev().copied().collect(),
        };
        let beam = &self.beams[side];
        let compliance: Vec<f64> = rho
            .iter()
            .map(|r| worn_compliance_m_per_n(beam, rho, &w, *r))
            .collect();
        let curvature = curvature_change_per_m(rho, &w, beam.base_radius_m, self.half_width_m);
        let grid_order = |v: Vec<f64>| match side {
            0 => v,
            _ => v.into_iter().rev().collect(),
        };
        WornTables {
            compliance_m_per_n: grid_order(compliance),
            curvature_change_per_m: grid_order(curvature),
        }
    }
}
