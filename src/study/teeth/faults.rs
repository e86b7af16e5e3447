//! A `[[fault]]` of the case applied to its tooth's flank: a crack's or a spall's added
//! compliance, a spall's gap and lost width, a broken tip's limit of contact.

use crate::config::case::{Fault, ToothFault};
use crate::dynamics::tooth_mesh::ToothFlank;
use crate::geometry::flank_shape::{ActiveFlank, Side};
use crate::geometry::GearPair;
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::tooth_faults::{
    crack_compliance_m_per_n, spall_compliance_m_per_n, spall_gap_m, Crack, Spall,
};

/// Adds one fault to a tooth's flank (`own` the tooth's own rho at the grid points).
pub(crate) fn apply_fault(
    f: &mut ToothFlank,
    fault: &ToothFault,
    pair: &GearPair,
    mesh: &MeshStiffness,
    s: Side,
    own: &[f64],
) {
    let flank = ActiveFlank::of(pair, s);
    let beam = &mesh.tooth_beams()[match s {
        Side::Pinion => 0,
        Side::Gear => 1,
    }];
    let n = own.len();
    let add_compliance = |c: Vec<f64>, f: &mut ToothFlank| {
        let table = f.compliance_m_per_n.get_or_insert_with(|| vec![0.0; n]);
        for (a, b) in table.iter_mut().zip(c) {
            *a += b;
        }
    };
    match fault.fault {
        Fault::Crack {
            depth_m,
            angle_rad,
            width_fraction,
        } => {
            let crack = Crack {
                depth_m,
                angle_rad,
                width_fraction,
            };
            let c = own
                .iter()
                .map(|rho| crack_compliance_m_per_n(beam, flank.tip_rho_m, &crack, *rho))
                .collect();
            add_compliance(c, f);
        }
        Fault::Spall {
            position_m,
            length_m,
            depth_m,
            width_fraction,
        } => {
            let spall = spall_of(&flank, position_m, length_m, depth_m, width_fraction);
            let c = own
                .iter()
                .map(|rho| {
                    spall_compliance_m_per_n(beam, &spall, mesh.hertz_compliance_m_per_n(), *rho)
                })
                .collect();
            add_compliance(c, f);
            if spall.width_fraction < 1.0 {
                let loss = f.width_loss.get_or_insert_with(|| vec![0.0; n]);
                for (l, rho) in loss.iter_mut().zip(own) {
                    if spall.contains(*rho) {
                        *l += spall.width_fraction;
                    }
                }
            }
            for (i, rho) in own.iter().enumerate() {
                let (r1, r2) = match s {
                    Side::Pinion => (*rho, pair.rho_gear(*rho)),
                    Side::Gear => (pair.loa_length_m - rho, *rho),
                };
                let radius = r1 * r2 / (r1 + r2);
                f.removed_m[i] += spall_gap_m(&spall, flank.base_radius_m, radius, *rho);
            }
        }
        Fault::BrokenTip { removed_height_m } => {
            let g = match s {
                Side::Pinion => &pair.pinion,
                Side::Gear => &pair.gear,
            };
            let r_cut = g.tip_radius_m - removed_height_m;
            let rho_cut = (r_cut.powi(2) - g.base_radius_m.powi(2)).max(0.0).sqrt();
            let limit = match s {
                Side::Pinion => rho_cut,
                Side::Gear => pair.loa_length_m - rho_cut,
            };
            f.contact_limit_rho1_m = Some(match (s, f.contact_limit_rho1_m) {
                (Side::Pinion, Some(l)) => l.min(limit),
                (Side::Gear, Some(l)) => l.max(limit),
                (_, None) => limit,
            });
        }
    }
}

/// A spall on its flank (own rho, m): its centre `position_m` of roll length from the
/// pitch point, `length_m` long (the fields of [`Fault::Spall`]).
pub(crate) fn spall_of(
    flank: &ActiveFlank,
    position_m: f64,
    length_m: f64,
    depth_m: f64,
    width_fraction: f64,
) -> Spall {
    let centre = flank.pitch_rho_m + position_m;
    let half = 0.5 * length_m;
    Spall {
        rho_lo_m: centre - half,
        rho_hi_m: centre + half,
        depth_m,
        width_fraction,
    }
}
