//! Wear of a helical pair slice by slice (docs/MODEL.md 11.3): each face slice of the slice
//! model (`stiffness::helical`) is a thin spur pair of width b/N in the transverse section,
//! staggered along the path of contact by its axial position times tan(beta_b) (Flodin &
//! Andersson, Wear 249 (2001) 285: a helical gear's wear as thin spur slices), and wears by
//! the spur pair's law (paper eq. 14-17, `wear::archard`) under its own share of the load.
//!
//! **Slice loads.** At every sample of the last excitation period of a response (mesh
//! phase phi, deflection delta along the transverse line of action, mesh force F) the
//! contact lines in contact at phi (the planar model's, `SliceMeshStiffness::line_model`)
//! place their slices on the transverse path: line slice i at rho + o_i, on face slice j.
//! Slice j's spring (N/m, `stiffness::helical`) compressed by
//!   c_j = delta - G_j - g_j(rho),  G_j its lead gap (docs/MODEL.md 11.2), g_j(rho) its own
//!   wear gap along the transverse line of action (pinion plus gear wear depth at the
//!   conjugate points, normal to the flank, over cos(beta_b): `study::helical::slice_gap_m`),
//! carries F_j = k_j c_j+ (no coupling between slices, as in the slice model); the mesh
//! force F (springs and damper) is shared in proportion, F_j F / sum F_j, so the slice loads
//! add to the recorded force (as `study::face_load_dynamic` shares it).
//!
//! **Tribology per slice.** Each slice load gives the Hertz contact of a line of width b/N
//! at the slice's transverse radii of curvature (paper eq. 15: p0 = sqrt(w E* / (pi R)),
//! w = F_j / (b/N) N/m), the surface speeds omega_p rho and omega_g (N1N2 - rho) of the
//! response (actual speeds in dynamic mode, nominal in the quasi-static one), and Xu's
//! friction coefficient (paper eq. 8) at that contact (recorded with the slice's samples;
//! Archard's law does not use it, as in the spur loop, where friction acts through the
//! dynamics: per contact line there, docs/MODEL.md 11.1). The samples of slice j sorted by
//! rho are the history of one tooth pair's slice through its engagement; Archard's law with
//! single-point observation (`wear::per_cycle_wear`) then gives slice j's wear per pinion
//! cycle along the profile.
//!
//! **The worn slices in the mesh.** The planar model follows each contact line as one
//! spring (`SliceMeshStiffness::line_model`); the wear enters it as the line's gap, the
//! stiffness-weighted mean of its slices' wear gaps at the line's position,
//!   e_l(rho) = sum_i k_i g_j(i)(rho + o_i) / sum_i k_i,
//! the single gap that gives the line the slices' force when they all touch (as
//! `wear::wear_transmission_error` does for a spur pair's pairs). Both modes take it: the
//! dynamic steady state and the quasi-static solve of the same line model.

use super::helical::{slice_gap_m, HelicalDynamics};
use super::model::Model;
use crate::contact::friction::XuConstants;
use crate::contact::hertz::{effective_radius_m, HertzContact};
use crate::contact::kinematics::SurfaceKinematics;
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::model::{TrainMesh, MAX_PAIRS};
use crate::dynamics::response::{interpolate_path, sorted_by_rho1, DynamicResponse, PathSample};
use crate::wear::tooth_wear::mean_profile;
use crate::wear::{per_cycle_wear, SliceWear, WearIncrement, WearState};

/// The lead gap G_j of each face slice, m (zeros without lead keys).
fn lead_gaps_m(h: &HelicalDynamics) -> Vec<f64> {
    h.lead
        .as_ref()
        .map_or_else(|| vec![0.0; h.slices], |l| l.static_load.gaps_m.clone())
}

/// Pinion and gear speeds (rad/s) at sample `i` of `r`: the nominal ones of `mesh` plus
/// the response's rotational velocities (dynamic), or the nominal ones (quasi-static: no
/// velocities recorded).
pub(crate) fn speeds_at(mesh: &TrainMesh, r: &DynamicResponse, i: usize) -> (f64, f64) {
    let v = &r.signals.velocity;
    if v.len() <= i {
        let [wp, wg] = mesh.operating.speeds_rad_s;
        return (wp, wg);
    }
    let (wp, wg) = mesh.nominal_speeds(r.signals.time_s[i]);
    let [rp, rg] = mesh.geometry.rotation;
    (wp + v[i][rp], wg + v[i][rg])
}

/// Each face slice's contacts over the last excitation period of `r` on the wear state
/// `wear`, sorted by rho1 (module docs): load, Hertz pressure and half-width over the
/// slice width b/N, friction coefficient, surface speeds. Index j: face slice j
/// (`SliceMeshStiffness::positions_m`). One slice is its own contact line: its contacts
/// are the response's path itself (the solver's loads, Hertz contacts over the face width
/// b and speeds, exactly the spur pair's record).
pub fn slice_paths(
    model: &Model,
    h: &HelicalDynamics,
    r: &DynamicResponse,
    wear: &WearState,
) -> Vec<Vec<PathSample>> {
    let s = &h.slice_model;
    let n = s.slices();
    if n == 1 {
        return vec![r.meshes[0].path.clone()];
    }
    let t = &s.pair().transverse;
    let grid = s.line_grid();
    let width = s.pair().face_width_m / n as f64;
    let lead = lead_gaps_m(h);
    let cos_bb = h.cos_base_helix();
    let sig = &r.signals;
    let ms = &sig.meshes[0];
    let xu = XuConstants::new(model.case.lubricant.viscosity_cp, model.roughness_for(wear));
    let t_end = sig.time_s.last().copied().unwrap_or(0.0);
    let window = r.mesh_period_s * r.excitation_periods.max(1) as f64;
    let from = t_end - window * (1.0 - 1e-9);
    let (no_gap, no_error) = (PairGap::none(), ExternalError::none());
    let sys = model.system(&no_gap, &no_error, 0.0);
    let mut paths: Vec<Vec<PathSample>> = vec![Vec::new(); n];
    let mut contacts: Vec<(usize, f64, f64)> = Vec::new();
    for i in (0..sig.time_s.len()).filter(|i| sig.time_s[*i] > from || window <= 0.0) {
        let force = ms.mesh_force_n[i];
        if force.is_nan() || force <= 0.0 {
            continue;
        }
        let phase = ms.phase_rad[i];
        contacts.clear();
        let lines = model
            .pair
            .pairs_in_reach_decided(model.contact.reach(), phase, phase);
        for (_, rho) in lines.take(MAX_PAIRS) {
            for (li, o) in grid.offsets.iter().enumerate() {
                let x = rho + o;
                if !(t.rho_start_m..=t.rho_end_m).contains(&x) {
                    continue;
                }
                let j = s.face_slice_of_line_slice(li);
                let c = ms.dte_m[i] - lead[j] - slice_gap_m(&model.grid, wear, j, x, cos_bb);
                // Every slice on the path is recorded, a separated one (c <= 0) with no
                // load ([`unloaded`]): its pass then wears nothing where it does not touch,
                // rather than holding its last loaded sample to the path's end.
                contacts.push((j, x, s.slice().pair_stiffness_n_per_m(x) * c.max(0.0)));
            }
        }
        let total: f64 = contacts.iter().map(|c| c.2).sum();
        if total.is_nan() || total <= 0.0 {
            continue;
        }
        let (wp, wg) = speeds_at(sys.mesh(0), r, i);
        for &(j, x, f) in &contacts {
            paths[j].push(if f > 0.0 {
                slice_sample(model, &xu, (x, f * force / total), (width, cos_bb), wp, wg)
            } else {
                unloaded(model, x, wp, wg)
            });
        }
    }
    paths.iter().map(|p| sorted_by_rho1(p)).collect()
}

/// One slice contact at transverse position `x.0` (m) under load `x.1` (N) over the slice
/// width `w.0` (m), pinion and gear speeds `wp`, `wg` (rad/s): Hertz (paper eq. 15) with
/// the radii of the contact line's normal section, the transverse ones over
/// `w.1` = cos(beta_b) (docs/MODEL.md 11.3), Xu's coefficient (eq. 8), the surface speeds.
pub(crate) fn slice_sample(
    model: &Model,
    xu: &XuConstants,
    (rho1, load): (f64, f64),
    (width_m, cos_base_helix): (f64, f64),
    wp: f64,
    wg: f64,
) -> PathSample {
    let pair = &model.pair;
    let rho2 = pair.rho_gear(rho1);
    let radius_m = effective_radius_m(rho1, rho2) / cos_base_helix;
    let hz = HertzContact::with_radius(load, width_m, radius_m, model.effective_modulus_pa);
    let kin = SurfaceKinematics::new(wp, wg, rho1, rho2);
    let mu = model.friction.coefficient_with(&hz, &kin, xu);
    PathSample {
        rho1_m: rho1,
        load_n: load,
        pressure_pa: hz.max_pressure_pa,
        half_width_m: hz.half_width_m,
        friction_coefficient: mu,
        friction_n: mu * load * model.friction.direction(kin.sliding_velocity_m_per_s()),
        pinion_surface_speed_m_per_s: wp * rho1,
        gear_surface_speed_m_per_s: wg * (pair.loa_length_m - rho1),
        cycle: 0,
    }
}

/// A slice contact at pinion rho1 `x` (m) that carries nothing: load, Hertz pressure and
/// half-width, friction 0, the surface speeds of pinion and gear speeds `wp`, `wg` (rad/s),
/// as the spur pair's path records a tooth pair in reach that does not touch
/// (`PathSample::push_contacts`); Archard's law (`wear::per_cycle_wear`) wears nothing
/// there. Xu's coefficient is not evaluated at zero pressure.
pub(crate) fn unloaded(model: &Model, x: f64, wp: f64, wg: f64) -> PathSample {
    PathSample {
        rho1_m: x,
        load_n: 0.0,
        pressure_pa: 0.0,
        half_width_m: 0.0,
        friction_coefficient: 0.0,
        friction_n: 0.0,
        pinion_surface_speed_m_per_s: wp * x,
        gear_surface_speed_m_per_s: wg * (model.pair.loa_length_m - x),
        cycle: 0,
    }
}

/// The Archard increments per pinion cycle of every face slice (paper eq. 14-17 on each
/// slice's contacts, `wear::per_cycle_wear`), with their means over the face in
/// `pinion_m` and `gear_m`.
pub fn slice_increment(model: &Model, paths: &[Vec<PathSample>]) -> WearIncrement {
    let ratio = model.pair.pinion.teeth as f64 / model.pair.gear.teeth as f64;
    let k = model.case.wear.coefficient_m2_per_n;
    let each: Vec<WearIncrement> = paths
        .iter()
        .map(|p| per_cycle_wear(&model.grid, p, k, ratio))
        .collect();
    let slices = SliceWear {
        pinion_m: each.iter().map(|w| w.pinion_m.clone()).collect(),
        gear_m: each.iter().map(|w| w.gear_m.clone()).collect(),
    };
    WearIncrement {
        pinion_m: mean_profile(&slices.pinion_m),
        gear_m: mean_profile(&slices.gear_m),
        slices: Some(slices),
        ..Default::default()
    }
}

/// What the wear loop's record of a helical pair's response `r` on `wear` holds
/// (`study::wear_loop::record`): the slices' increments, and the load along the profile
/// (at the grid points, N) summed over the face slices, each slice's at its own instant of
/// passing that profile point.
pub(crate) fn record_parts(
    model: &Model,
    h: &HelicalDynamics,
    r: &DynamicResponse,
    wear: &WearState,
) -> (WearIncrement, Vec<f64>) {
    let paths = slice_paths(model, h, r, wear);
    let inc = slice_increment(model, &paths);
    let load = load_along_profile(model, &paths);
    (inc, load)
}

/// The load along the profile (at the grid points, N) of slice paths (one engagement's):
/// the sum over the face slices of each one's load where it passes the point.
pub(crate) fn load_along_profile(model: &Model, paths: &[Vec<PathSample>]) -> Vec<f64> {
    (model.grid.rho_pinion_m.iter())
        .map(|x| {
            let on = |p: &Vec<PathSample>| {
                let inside = p.first().is_some_and(|a| a.rho1_m <= *x)
                    && p.last().is_some_and(|b| b.rho1_m >= *x);
                if inside {
                    interpolate_path(p, *x).load_n
                } else {
                    0.0
                }
            };
            paths.iter().map(on).sum()
        })
        .collect()
}

/// Volume of a layer of depth `depth_m[i]` (m) at the grid points of rho `rho_m[i]` (m) on
/// an involute of base radius `base_radius_m` (m), over the width `width_m` (m), m^3: the
/// trapezoid rule in the involute's arc length from the base circle, s = rho^2 / (2 r_b)
/// (ds = rho drho / r_b; ISO 21771: the radius of curvature of an involute is its roll
/// length).
pub fn layer_volume_m3(rho_m: &[f64], depth_m: &[f64], base_radius_m: f64, width_m: f64) -> f64 {
    let s = |r: f64| r * r / (2.0 * base_radius_m);
    let area: f64 = rho_m
        .windows(2)
        .zip(depth_m.windows(2))
        .map(|(r, h)| 0.5 * (h[0] + h[1]) * (s(r[1]) - s(r[0])).abs())
        .sum();
    width_m * area
}

/// Volume of a per-slice wear map on one pinion flank and one gear flank (pinion, gear),
/// m^3: the sum over face slices of each slice's layer ([`layer_volume_m3`]), its depth
/// Archard's normal to the flank, over the slice's flank width (b/N) / cos(beta_b): the
/// involute helicoid's area element is the transverse arc length's ds times dy /
/// cos(beta_b) (docs/MODEL.md 11.3; the contact line of a slice is b/(N cos(beta_b))
/// long). Of an increment: the volume per pinion cycle (the gear's with the z1/z2 of
/// eq. 17 in it).
pub fn slice_volumes_m3(model: &Model, h: &HelicalDynamics, map: &SliceWear) -> (f64, f64) {
    let b = h.slice_model.pair().face_width_m;
    let width = b / h.slices as f64 / h.cos_base_helix();
    let g = &model.grid;
    let (rb1, rb2) = (
        model.pair.pinion.base_radius_m,
        model.pair.gear.base_radius_m,
    );
    let sum = |profiles: &[Vec<f64>], rho: &[f64], rb: f64| -> f64 {
        profiles
            .iter()
            .map(|p| layer_volume_m3(rho, p, rb, width))
            .sum()
    };
    (
        sum(&map.pinion_m, &g.rho_pinion_m, rb1),
        sum(&map.gear_m, &g.rho_gear_m, rb2),
    )
}
