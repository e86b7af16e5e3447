//! Wear of a helical pair's teeth tooth by tooth and slice by slice (docs/MODEL.md 11.13):
//! each face slice of each tooth wears from its own contact history, where per-tooth
//! inputs (`[teeth]`, `[[fault]]`) make the mesh tooth-resolved (`study::teeth::helical`).
//!
//! **Slice loads.** At every sample of the response's last excitation period (P mesh
//! periods; deflection delta along the transverse line of action, mesh force F) each
//! contact line in contact is mesh cycle n's, between pinion tooth a = n mod z1 and gear
//! tooth b = n mod z2, its engagement e = n mod P (the tooth-resolved mesh's,
//! `dynamics::tooth_mesh`). Its slice i at pinion rho1 x = rho + o_i on face slice j is a
//! spring compressed by (all in m along the transverse line of action)
//!   c_i = delta + e_run + p_a + p_b - g_a,j(x) - g_b,j(x) - (h_a,j(x) + h_b,j(x)) / cos(beta_b),
//! e_run the run-out and p_a, p_b the position errors along the line of action (as the
//! tooth-resolved mesh adds them to its pairs), g the teeth's errors and a spall's pit on
//! that slice (`ToothSlices::at`), h their own wear depths on face slice j (normal to the
//! flank); its stiffness is the slice's k(x) with the faults' compliances c_f in series,
//! k_f = 1 / (1/k + c_f) (N/m; c_f in m/N), and a slice a broken tip cuts carries nothing. It carries
//! F_i = k_f c_i+, and the mesh force F is shared over every slice of every line in
//! proportion, F_i F / sum F_i, as the identical teeth's slices are
//! (`study::helical_wear`): with every tooth alike the two are the same loads.
//!
//! **Tribology and Archard per slice.** Each slice load gives the Hertz contact over the
//! slice width b/N in the contact line's normal section, the surface speeds and Xu's
//! coefficient (`helical_wear::slice_sample`). A slice on the path that a broken tip cuts
//! or that is apart (c_i <= 0) is a sample of load 0 (pressure, half-width and friction 0),
//! as the spur pair's path records a tooth pair in reach that does not touch, and a line
//! whose slices are all such is kept: a pass wears nothing where its slice does not touch
//! instead of holding its last loaded sample there. Engagement e's samples on face slice
//! j, sorted by rho1, are one pass of that slice through the path; Archard's law with
//! single-point observation (`wear::per_cycle_wear`) gives the pass's depths along the
//! profile. Per pinion cycle, tooth a's face slice j wears by the mean of its
//! engagements' passes on slice j (the engagements it meets over the hunting period,
//! `wear::per_tooth::engagements_of`, in ascending order, as `wear::per_tooth_wear` takes
//! them), the gear's with z1/z2 (paper eq. 17).

use super::helical::HelicalDynamics;
use super::helical_wear::{load_along_profile, slice_sample, speeds_at, unloaded};
use super::model::Model;
use super::teeth::{LineTeeth, ToothInputs};
use crate::contact::friction::XuConstants;
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::model::{TrainMesh, MAX_PAIRS};
use crate::dynamics::response::{sorted_by_rho1, DynamicResponse, PathSample};
use crate::dynamics::tooth_mesh::lcm;
use crate::wear::per_tooth::engagements_of;
use crate::wear::tooth_wear::mean_profile;
use crate::wear::{per_cycle_wear, ToothWear, WearIncrement, WearState};

/// A line in contact at one sample: the sample's index, the line's mesh cycle and the
/// pinion rho1 of its trailing end on the line pair, m.
#[derive(Clone, Copy)]
struct LineAt {
    sample: usize,
    cycle: i64,
    rho_m: f64,
}

/// What the slice loads of a response need (module docs).
struct SliceLoads<'a> {
    model: &'a Model,
    h: &'a HelicalDynamics,
    lt: &'a LineTeeth,
    teeth: &'a ToothInputs,
    wear: &'a ToothWear,
    r: &'a DynamicResponse,
}

impl SliceLoads<'_> {
    /// The slices of line `l` on the path: (face slice j, pinion rho1 m, spring force
    /// k_f c_i+ N), pushed to `out` in the line's order (module docs); a slice a broken tip
    /// cuts or that is apart (c_i <= 0) with force 0, so that its pass records where it
    /// does not touch.
    fn slices(&self, l: LineAt, out: &mut Vec<(usize, f64, f64)>) {
        let (grid, lt, n) = (&self.model.grid, self.lt, self.lt.slices);
        let [z1, z2] = [self.teeth.pinion.len(), self.teeth.gear.len()];
        let a = l.cycle.rem_euclid(z1 as i64) as usize;
        let b = l.cycle.rem_euclid(z2 as i64) as usize;
        let t = self.r.signals.time_s[l.sample];
        let e_run = self.teeth.runout[0].at(t).0 + self.teeth.runout[1].at(t).0;
        let base = self.r.signals.meshes[0].dte_m[l.sample]
            + e_run
            + self.teeth.pinion[a].position_m
            + self.teeth.gear[b].position_m;
        let (pa, pb) = (&self.wear.pinion_m, &self.wear.gear_m);
        let slice = self.h.slice_model.slice();
        for &(j, o) in &lt.offsets {
            let x = l.rho_m + o;
            if !(lt.path.0..=lt.path.1).contains(&x) {
                continue;
            }
            let (Some((gp, cp)), Some((gg, cg))) =
                (lt.pinion[a].at(grid, j, x), lt.gear[b].at(grid, j, x))
            else {
                out.push((j, x, 0.0));
                continue;
            };
            let worn = (grid.interpolate(&pa[a * n + j], x) + grid.interpolate(&pb[b * n + j], x))
                / lt.cos_base_helix;
            let c = base - gp - gg - worn;
            let k = slice.pair_stiffness_n_per_m(x);
            let compliance = cp + cg;
            let kf = if compliance == 0.0 {
                k
            } else {
                1.0 / (1.0 / k + compliance)
            };
            out.push((j, x, kf * c.max(0.0)));
        }
    }
}

/// The lines in contact over the last excitation period of `r` grouped by engagement
/// (mesh cycle modulo P), and the sum of every line's slice forces at each sample (0 where
/// the mesh force is not positive).
fn lines_by_engagement(
    loads: &SliceLoads,
    mesh: &TrainMesh,
    periods: usize,
) -> (Vec<Vec<LineAt>>, Vec<f64>) {
    let (model, r) = (loads.model, loads.r);
    let sig = &r.signals;
    let ms = &sig.meshes[0];
    let angle = model.pair.mesh_angle_rad();
    let t_end = sig.time_s.last().copied().unwrap_or(0.0);
    let window = r.mesh_period_s * r.excitation_periods.max(1) as f64;
    let from = t_end - window * (1.0 - 1e-9);
    let mut by: Vec<Vec<LineAt>> = vec![Vec::new(); periods];
    let mut totals = vec![0.0; sig.time_s.len()];
    let mut out = Vec::new();
    for i in (0..sig.time_s.len()).filter(|i| sig.time_s[*i] > from || window <= 0.0) {
        let force = ms.mesh_force_n[i];
        if force.is_nan() || force <= 0.0 {
            continue;
        }
        let phase = ms.phase_rad[i];
        // The recorded phase is the absolute one modulo the mesh period: the difference
        // counts the whole mesh cycles (`GearPair::mesh_cycle`).
        let cycle_now = ((mesh.phase_at(sig.time_s[i]) - phase) / angle).round() as i64;
        let lines = model
            .pair
            .pairs_in_reach_decided(model.contact.reach(), phase, phase);
        let mut total = 0.0;
        for (k, rho) in lines.take(MAX_PAIRS) {
            let l = LineAt {
                sample: i,
                cycle: cycle_now - k,
                rho_m: rho,
            };
            out.clear();
            loads.slices(l, &mut out);
            for c in &out {
                total += c.2;
            }
            // A line with a slice on the path is its engagement's even where none of its
            // slices carries load (they record the pass's unloaded stretch).
            if !out.is_empty() {
                by[l.cycle.rem_euclid(periods as i64) as usize].push(l);
            }
        }
        totals[i] = total;
    }
    (by, totals)
}

/// Each face slice's contacts of the lines `lines` of one engagement, sorted by rho1
/// (module docs; index j: face slice j).
fn engagement_paths(
    loads: &SliceLoads,
    mesh: &TrainMesh,
    lines: &[LineAt],
    totals: &[f64],
    xu: &XuConstants,
) -> Vec<Vec<PathSample>> {
    let (model, r, n) = (loads.model, loads.r, loads.lt.slices);
    let s = &loads.h.slice_model;
    let width = s.pair().face_width_m / n as f64;
    let cos_bb = loads.lt.cos_base_helix;
    let mut paths: Vec<Vec<PathSample>> = vec![Vec::new(); n];
    let mut out = Vec::new();
    for l in lines {
        let total = totals[l.sample];
        if total.is_nan() {
            continue;
        }
        let force = r.signals.meshes[0].mesh_force_n[l.sample];
        let (wp, wg) = speeds_at(mesh, r, l.sample);
        out.clear();
        loads.slices(*l, &mut out);
        for &(j, x, f) in &out {
            let share = if total > 0.0 { f * force / total } else { 0.0 };
            paths[j].push(if share > 0.0 {
                slice_sample(model, xu, (x, share), (width, cos_bb), wp, wg)
            } else {
                unloaded(model, x, wp, wg)
            });
        }
    }
    paths.iter().map(|p| sorted_by_rho1(p)).collect()
}

/// Which teeth of a gear of `z` teeth meet each of the `periods` engagements over the
/// hunting period `hunting`, and how many engagements each tooth meets.
fn meetings(z: usize, hunting: usize, periods: usize) -> (Vec<Vec<usize>>, Vec<usize>) {
    let mut by = vec![Vec::new(); periods];
    let mut count = vec![0; z];
    for (t, c) in count.iter_mut().enumerate() {
        let e = engagements_of(t, z, hunting, periods);
        *c = e.len();
        for x in e {
            by[x].push(t);
        }
    }
    (by, count)
}

/// What the wear loop's record of a helical pair's tooth-resolved response `r` on
/// `wear` holds (`study::wear_loop::record`, N >= 2 face slices): every tooth's face
/// slices' Archard increments per pinion cycle (profile t N + j of `teeth`, module docs)
/// with their means over teeth and slices, and the load along the profile (N, at the
/// grid points) summed over the face slices and averaged over the engagements.
pub(crate) fn record_parts(
    model: &Model,
    h: &HelicalDynamics,
    teeth: &ToothInputs,
    lt: &LineTeeth,
    r: &DynamicResponse,
    wear: &WearState,
) -> (WearIncrement, Vec<f64>) {
    let n = lt.slices;
    let (z1, z2) = (teeth.pinion.len(), teeth.gear.len());
    let points = model.grid.len();
    let new = ToothWear::new(points, z1 * n, z2 * n);
    let loads = SliceLoads {
        model,
        h,
        lt,
        teeth,
        wear: wear.teeth.as_ref().unwrap_or(&new),
        r,
    };
    let periods = r.excitation_periods.max(1);
    // The nominal mesh (no gap, no error) for the phases and surface speeds, built once.
    let (no_gap, no_error) = (PairGap::none(), ExternalError::none());
    let sys = model.system(&no_gap, &no_error, 0.0);
    let (by, totals) = lines_by_engagement(&loads, sys.mesh(0), periods);
    let hunting = lcm(lcm(z1, z2), periods);
    let (meet_p, count_p) = meetings(z1, hunting, periods);
    let (meet_g, count_g) = meetings(z2, hunting, periods);
    let mut sum = ToothWear::new(points, z1 * n, z2 * n);
    let mut load = vec![0.0; points];
    let k = model.case.wear.coefficient_m2_per_n;
    let ratio = z1 as f64 / z2 as f64;
    let add = |to: &mut Vec<f64>, from: &[f64]| to.iter_mut().zip(from).for_each(|(s, x)| *s += x);
    let xu = XuConstants::new(model.case.lubricant.viscosity_cp, model.roughness_for(wear));
    for (e, lines) in by.iter().enumerate() {
        let paths = engagement_paths(&loads, sys.mesh(0), lines, &totals, &xu);
        add(&mut load, &load_along_profile(model, &paths));
        for (j, p) in paths.iter().enumerate() {
            let inc = per_cycle_wear(&model.grid, p, k, ratio);
            for a in &meet_p[e] {
                add(&mut sum.pinion_m[a * n + j], &inc.pinion_m);
            }
            for b in &meet_g[e] {
                add(&mut sum.gear_m[b * n + j], &inc.gear_m);
            }
        }
    }
    let mean = |profiles: &mut [Vec<f64>], count: &[usize]| {
        for (i, p) in profiles.iter_mut().enumerate() {
            let m = count[i / n].max(1) as f64;
            p.iter_mut().for_each(|x| *x /= m);
        }
    };
    mean(&mut sum.pinion_m, &count_p);
    mean(&mut sum.gear_m, &count_g);
    load.iter_mut().for_each(|x| *x /= periods as f64);
    let inc = WearIncrement {
        pinion_m: mean_profile(&sum.pinion_m),
        gear_m: mean_profile(&sum.gear_m),
        teeth: Some(sum),
        ..Default::default()
    };
    (inc, load)
}
