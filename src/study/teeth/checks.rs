//! The checks of the per-tooth inputs that need the geometry: a crack deeper than the
//! tooth, a spall off the active profile, a relief longer than the addendum or dedendum, a
//! broken tip below the root circle; each names the key, the tooth and the valid range.

use super::faults::spall_of;
use super::sides::{member_gear, side};
use crate::config::case::{Case, Fault, ModificationSection, ToothFault};
use crate::geometry::flank_shape::{ActiveFlank, Side};
use crate::geometry::GearPair;
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::tooth_faults::{Crack, Spall};

/// An upper limit shown to 4 decimals, rounded down, so that every value up to the shown
/// limit is accepted (a limit rounded to nearest could show 4.5000 for 4.49999).
pub(crate) fn upper_mm(x: f64) -> String {
    format!("{:.4}", (x * 1e4).floor() / 1e4)
}

/// A lower limit shown to 4 decimals, rounded up (see [`upper_mm`]).
pub(crate) fn lower_mm(x: f64) -> String {
    format!("{:.4}", (x * 1e4).ceil() / 1e4)
}

/// The checks of the module docs, every problem at once.
pub(crate) fn geometry_problems(case: &Case, pair: &GearPair, mesh: &MeshStiffness) -> Vec<String> {
    let flanks = [Side::Pinion, Side::Gear].map(|s| ActiveFlank::of(pair, s));
    let mut p = relief_problems(&case.modification, &flanks);
    for (i, f) in case.fault.iter().enumerate() {
        p.extend(fault_problem(i, f, pair, mesh, &flanks));
    }
    p
}

/// The index of a side's entry in the `[pinion, gear]` arrays.
fn index_of(s: Side) -> usize {
    match s {
        Side::Pinion => 0,
        Side::Gear => 1,
    }
}

/// The profile modification's problems: a tip relief longer than the addendum, a root
/// relief longer than the active dedendum (roll lengths in m of the shorter of the two
/// flanks, shown in mm), an amount without its length or the reverse.
fn relief_problems(m: &ModificationSection, flanks: &[ActiveFlank; 2]) -> Vec<String> {
    let mut p = Vec::new();
    let mm = 1e3;
    let addendum = flanks[0].addendum_roll_m().min(flanks[1].addendum_roll_m());
    if let Some(l) = m.tip_relief_length_mm {
        if l * 1e-3 > addendum {
            p.push(format!(
                "`modification.tip_relief_length_mm` = {l} is longer than the addendum: a tip relief runs from the tip at most to the pitch point, valid (0, {}] mm on this pair (the shorter of the pinion's {:.4} and the gear's {:.4} mm roll length)",
                upper_mm(addendum * mm),
                flanks[0].addendum_roll_m() * mm,
                flanks[1].addendum_roll_m() * mm
            ));
        }
    }
    let dedendum = flanks[0].dedendum_roll_m().min(flanks[1].dedendum_roll_m());
    if let Some(l) = m.root_relief_length_mm {
        if l * 1e-3 > dedendum {
            p.push(format!(
                "`modification.root_relief_length_mm` = {l} is longer than the active dedendum: a root relief runs from the start of active profile at most to the pitch point, valid (0, {}] mm on this pair",
                upper_mm(dedendum * mm)
            ));
        }
    }
    for (key_amount, key_len, amount, len) in [
        (
            "tip_relief_um",
            "tip_relief_length_mm",
            m.tip_relief_um,
            m.tip_relief_length_mm,
        ),
        (
            "root_relief_um",
            "root_relief_length_mm",
            m.root_relief_um,
            m.root_relief_length_mm,
        ),
    ] {
        if amount.is_some() != len.is_some() {
            p.push(format!(
                "`modification.{key_amount}` and `modification.{key_len}` go together: give both or neither"
            ));
        }
    }
    p
}

/// The problem of fault `i` (`f`) against its tooth's geometry, if any: a crack deeper
/// than the root's thickness, a spall longer than or off the active profile or deeper than
/// the tooth holds, a broken tip below the root circle (SI inside, mm and µm shown).
pub(crate) fn fault_problem(
    i: usize,
    f: &ToothFault,
    pair: &GearPair,
    mesh: &MeshStiffness,
    flanks: &[ActiveFlank; 2],
) -> Option<String> {
    let mm = 1e3;
    let s = side(f.gear);
    let g = member_gear(pair, f.gear);
    let flank = flanks[index_of(s)];
    let beam = &mesh.tooth_beams()[index_of(s)];
    let who = format!("fault {i}, {} tooth {}", f.gear.name(), f.tooth);
    let mut problem = None;
    match f.fault {
        Fault::Crack {
            depth_m, angle_rad, ..
        } => {
            let q_max = Crack::max_depth_m(beam, angle_rad);
            if depth_m >= q_max {
                problem = Some(format!(
                    "`fault.crack_depth_mm` = {} ({who}) is deeper than the tooth: at {} deg its reach across the root must stay below the root's thickness {:.4} mm, valid [0, {}) mm",
                    f.written("crack_depth_mm"),
                    f.written("crack_angle_deg"),
                    2.0 * beam.root_section().0 * mm,
                    upper_mm(q_max * mm)
                ));
            }
        }
        Fault::Spall {
            position_m,
            length_m,
            depth_m,
            width_fraction,
        } => {
            let spall = spall_of(&flank, position_m, length_m, depth_m, width_fraction);
            let profile = flank.tip_rho_m - flank.sap_rho_m;
            let len = spall.rho_hi_m - spall.rho_lo_m;
            if len > profile {
                problem = Some(format!(
                    "`fault.spall_length_mm` = {} ({who}) is longer than the active profile: valid (0, {}] mm",
                    f.written("spall_length_mm"),
                    upper_mm(profile * mm)
                ));
            } else if spall.rho_lo_m < flank.sap_rho_m - 1e-12
                || spall.rho_hi_m > flank.tip_rho_m + 1e-12
            {
                problem = Some(format!(
                    "`fault.spall_position_mm` = {} ({who}) puts the spall off the active profile: with length {} mm its centre must lie within [{}, {}] mm of the pitch point",
                    f.written("spall_position_mm"),
                    f.written("spall_length_mm"),
                    lower_mm((flank.sap_rho_m - flank.pitch_rho_m + 0.5 * len) * mm),
                    upper_mm((flank.tip_rho_m - flank.pitch_rho_m - 0.5 * len) * mm)
                ));
            } else {
                let d_max = spall.max_depth_m(beam);
                if spall.depth_m > d_max {
                    problem = Some(format!(
                        "`fault.spall_depth_um` = {} ({who}) is deeper than the tooth holds: a pit may take at most {:.0} % of the tooth's thickness at its upper edge ({:.4} mm), valid (0, {:.1}] µm",
                        f.written("spall_depth_um"),
                        Spall::MAX_THICKNESS_SHARE * 100.0,
                        d_max / Spall::MAX_THICKNESS_SHARE * mm,
                        (d_max * 1e7).floor() / 10.0
                    ));
                }
            }
        }
        Fault::BrokenTip { removed_height_m } => {
            let height = g.tip_radius_m - g.root_radius_m;
            if removed_height_m > height {
                problem = Some(format!(
                    "`fault.removed_height_mm` = {} ({who}) is more than the tooth: valid (0, {}] mm (tip to root circle)",
                    f.written("removed_height_mm"),
                    upper_mm(height * mm)
                ));
            }
        }
    }
    problem
}
