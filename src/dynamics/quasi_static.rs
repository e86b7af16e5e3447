//! Quasi-static twin of the dynamic model: the same mesh, friction and gaps without
//! inertia or damping, in equilibrium at each mesh position (the baseline of the paper's
//! section 4.2 and the static transmission error of the stiffness command).
//!
//! At equilibrium the loaded shaft balances the mesh force and the friction moments
//! (paper eq. 1 with the time derivatives removed):
//!   gear side (load at the brake):  r_gb F + sum rho2_i f_i = T_brk
//!   pinion side (brake imposed):    r_pb F + sum rho1_i f_i = T_mor
//! with f_i = mu_i kappa_i F tanh(u_s/v_s) at the nominal speeds; mu_i depends on the pair
//! load through the Hertz pressure, so F is found by fixed-point iteration (friction is a
//! few per cent of F, the iteration contracts by that factor). The mesh deflection then
//! solves sum_i k_i max(delta - g_i, 0) = F exactly (pairs closing their gaps in order);
//! a helical pair's contact lines with lead gaps across the face carry the dynamic
//! model's line force instead, sum_l F_l(delta - g_l) = F with
//! F_l(c) = sum_j k_j (c - G_j)+ (`LineGapTable::force`, docs/MODEL.md 11.1 and 11.3),
//! solved exactly by `lead_deflection_for_force`.

use super::grid::{excitation_periods, period_nodes_in, train_nodes};
use super::model::{GearSystem, MeshState, TrainMesh, MAX_PAIRS};
use super::response::{DynamicResponse, MeshResponse, PathSample, Signals};
use crate::config::case::SpeedBoundary;
use crate::stiffness::helical_lead::LineGapTable;

/// Mesh deflection delta (m) with sum k_i max(delta - g_i, 0) = force (N), k_i >= 0
/// (a pair of zero stiffness, a contact a broken tip removed, carries nothing). Returns
/// the smallest gap when no pair can carry the force.
pub fn deflection_for_force(k: &[f64], gap: &[f64], force_n: f64) -> f64 {
    let n = k.len();
    let mut order: [usize; MAX_PAIRS] = [0, 1, 2, 3];
    order[..n].sort_by(|a, b| gap[*a].total_cmp(&gap[*b]));
    if k.iter().all(|k| *k <= 0.0) {
        return gap.iter().fold(f64::INFINITY, |m, g| m.min(*g)).min(1.0);
    }
    let (mut ksum, mut kg) = (0.0, 0.0);
    for j in 0..n {
        let i = order[j];
        ksum += k[i];
        kg += k[i] * gap[i];
        if ksum <= 0.0 {
            continue;
        }
        let delta = (force_n + kg) / ksum;
        if j + 1 == n || delta <= gap[order[j + 1]] {
            return delta;
        }
    }
    0.0
}

/// Mesh deflection delta (m) of a helical pair's contact lines with lead gaps: the root of
///   f(delta) = sum_l F_l(rho_l, delta - g_l) = force (N),
/// F_l the line's force at trailing end `rho_m[l]` and compression c (`LineGapTable::
/// force`: sum_j k_j (c - G_j)+, the dynamic model's law; docs/MODEL.md 11.1), g_l the
/// line's gap `gap[l]` (m). f is continuous, piecewise linear, increasing and convex in
/// delta (each slice adds its stiffness as its gap closes), so Newton's steps from a point
/// right of the root (every slice compressed) stay right of it, fall monotonically and end
/// exactly on the root's linear piece: no tolerance (at most one step per kink). Without
/// a line that can carry load, or without load, the smallest gap (first touch).
pub(crate) fn lead_deflection_for_force(
    table: &LineGapTable,
    rho_m: &[f64],
    gap: &[f64],
    force_n: f64,
) -> f64 {
    let first_touch = gap.iter().fold(f64::INFINITY, |m, g| m.min(*g)).min(1.0);
    let lines = || rho_m.iter().zip(gap);
    let all: f64 = lines()
        .map(|(r, _)| table.force(*r, f64::MAX, false).1)
        .sum();
    if force_n <= 0.0 || all <= 0.0 {
        return first_touch;
    }
    let highest = gap.iter().fold(f64::NEG_INFINITY, |m, g| m.max(*g));
    // Every slice of every line compressed: f(delta) >= sum_l K_l (delta - g_l - G_max).
    let mut delta = highest + table.largest_gap_m() + force_n / all;
    // One step per kink passed (the lines' slices), a few more for the round-off.
    for _ in 0..table.slices() * rho_m.len() + 8 {
        let (mut f, mut k) = (0.0, 0.0);
        for (r, g) in lines() {
            let (fl, kl) = table.force(*r, delta - g, false);
            f += fl;
            k += kl;
        }
        let next = delta - (f - force_n) / k;
        if k <= 0.0 || next >= delta || next.is_nan() {
            break;
        }
        delta = next;
    }
    delta
}

/// Phases per mesh period over which [`loaded_mean_stiffnesses`] averages.
const LOADED_MEAN_PHASES: usize = 64;

/// Each mesh's mean loaded stiffness, N/m: the stiffness of the pairs that carry load in
/// the quasi-static equilibrium (the tangent stiffness dF/d delta of the loaded mesh)
/// averaged over `LOADED_MEAN_PHASES` phases
/// of one mesh period. With corner contact it counts the corners the load closes (6.3 %
/// above the nominal mean on the paper's case), which the table mean
/// (`MeshStiffness::mean_stiffness_n_per_m`) leaves out; a mesh on the nominal path keeps
/// the table mean, so the paper's model is unchanged.
pub fn loaded_mean_stiffnesses(sys: &GearSystem) -> Vec<f64> {
    (0..sys.meshes.len())
        .map(|m| {
            let mesh = sys.mesh(m);
            let table_mean = mesh.parts.mesh.mean_stiffness_n_per_m();
            if !mesh.parts.contact.is_extended() {
                return table_mean;
            }
            let period = mesh.parts.pair.mesh_angle_rad();
            let sum: f64 = (0..LOADED_MEAN_PHASES)
                .map(|i| {
                    let phase = period * i as f64 / LOADED_MEAN_PHASES as f64;
                    let eq = equilibrium(sys, m, phase);
                    (0..eq.n_pairs)
                        .filter(|j| eq.load_n[*j] > 0.0)
                        .map(|j| eq.stiffness_n_per_m[j])
                        .sum::<f64>()
                })
                .sum();
            let mean = sum / LOADED_MEAN_PHASES as f64;
            // A mesh that carries nothing anywhere (no load) keeps the table mean.
            if mean > 0.0 && mean.is_finite() {
                mean
            } else {
                table_mean
            }
        })
        .collect()
}

/// Equilibrium state of mesh `m` at its mesh phase `phase_rad` (pinion rotation since
/// t = 0: with a tooth-resolved mesh it also says which teeth meet, and the time the
/// run-out has).
pub fn equilibrium(sys: &GearSystem, m: usize, phase_rad: f64) -> MeshState {
    let mesh = sys.mesh(m);
    let omega_p = mesh.operating.speeds_rad_s[0];
    let cycle = mesh.parts.pair.mesh_cycle(phase_rad);
    equilibrium_in_cycle(sys, m, phase_rad, cycle, phase_rad / omega_p)
}

/// As [`equilibrium`] at phase `phase_rad` of mesh cycle `cycle_now` (given, so that a
/// node on a period boundary belongs to the cycle it opens whatever the round-off of
/// the absolute phase), time `t_s` for the run-out. Each mesh of a train stands alone at
/// its own shafts' torque (the statics of a chain of meshes: each carries its shaft's
/// torque whatever the others do).
pub fn equilibrium_in_cycle(
    sys: &GearSystem,
    m: usize,
    phase_rad: f64,
    cycle_now: i64,
    t_s: f64,
) -> MeshState {
    let boundary = sys.assembly().elements.drive.boundary;
    mesh_equilibrium(sys.mesh(m), boundary, phase_rad, cycle_now, t_s)
}

fn mesh_equilibrium(
    mesh: &TrainMesh,
    boundary: SpeedBoundary,
    phase_rad: f64,
    cycle_now: i64,
    t_s: f64,
) -> MeshState {
    let (mut ms, k, gap, ends) = pairs_at(mesh, phase_rad, cycle_now, t_s);
    let n = ms.n_pairs;
    if k[..n].iter().all(|k| *k <= 0.0) {
        // No pair can carry the load (a broken tip's removed contact in single contact):
        // the quasi-static mesh has lost contact there.
        ms.deflection_m = deflection_for_force(&k[..n], &gap[..n], 0.0);
        return ms;
    }
    let law = PairLaw {
        k: &k[..n],
        gap: &gap[..n],
        lead: mesh.parts.contact.lead_gaps().map(|t| (t, &ends[..n])),
    };
    carry_the_torque(mesh, boundary, &mut ms, &law);
    if ms.corner[..n].contains(&true) {
        // The mesh's stiffness counts the corners beyond the path only where they touch.
        ms.stiffness_total_n_per_m = (0..n)
            .filter(|i| !ms.corner[*i] || ms.deflection_m > gap[*i])
            .map(|i| k[i])
            .sum();
    }
    ms
}

/// How the pairs of a mesh carry its force: springs k_i (delta - g_i)+ (N/m, m), or a
/// helical pair's contact lines with lead gaps, the line table's force at each line's
/// trailing end (m) and compression delta - g_i (the dynamic model's law,
/// `TrainMesh::springs`).
struct PairLaw<'a> {
    k: &'a [f64],
    gap: &'a [f64],
    lead: Option<(&'a LineGapTable, &'a [f64])>,
}

impl PairLaw<'_> {
    /// The deflection (m) at which the pairs carry `force_n` (N).
    fn deflection(&self, force_n: f64) -> f64 {
        match self.lead {
            None => deflection_for_force(self.k, self.gap, force_n),
            Some((t, ends)) => lead_deflection_for_force(t, ends, self.gap, force_n),
        }
    }

    /// Each pair's share of the mesh force `force_n` (N) at deflection `delta_m` (m): its
    /// force over the mesh force.
    fn shares(&self, delta_m: f64, force_n: f64) -> [f64; MAX_PAIRS] {
        let Some((t, ends)) = self.lead else {
            return compression_shares(self.k, self.gap, delta_m, force_n);
        };
        let mut sh = [0.0; MAX_PAIRS];
        for (i, (r, g)) in ends.iter().zip(self.gap).enumerate() {
            sh[i] = t.force(*r, delta_m - g, false).0 / force_n;
        }
        sh
    }
}

/// The pairs of `mesh` in reach at `phase_rad` (tooth cycle `cycle_now`, time `t_s` for
/// the run-out): a mesh state with their positions, stiffnesses (N/m) and flags, each
/// pair's stiffness and gap (m, the external and run-out errors taken off), and its place
/// on the line pair (m: a helical contact line's trailing end).
fn pairs_at(
    mesh: &TrainMesh,
    phase_rad: f64,
    cycle_now: i64,
    t_s: f64,
) -> (
    MeshState,
    [f64; MAX_PAIRS],
    [f64; MAX_PAIRS],
    [f64; MAX_PAIRS],
) {
    let parts = &mesh.parts;
    let (e_ext, _) = parts.external.at(phase_rad);
    let mut ms = MeshState::default();
    let mut k = [0.0; MAX_PAIRS];
    let mut gap = [0.0; MAX_PAIRS];
    let mut ends = [0.0; MAX_PAIRS];
    let mut n = 0;
    let e_run = parts.teeth.map_or(0.0, |tm| tm.runout_at(t_s).0);
    let contact = parts.contact;
    let pairs = parts
        .pair
        .pairs_in_reach_decided(contact.reach(), phase_rad, phase_rad);
    for (pair_k, rho1) in pairs {
        if n == MAX_PAIRS {
            break;
        }
        ms.rho1_m[n] = contact.contact_rho1_m(rho1);
        ends[n] = rho1;
        match parts.teeth {
            None => {
                let pp = contact.plain_pair(parts.mesh, parts.gap, rho1);
                k[n] = pp.stiffness_n_per_m;
                gap[n] = pp.gap_m - e_ext;
                ms.corner[n] = pp.corner;
                ms.width_loss[n] = pp.width_loss;
            }
            Some(tm) => {
                let cycle = cycle_now - pair_k;
                let pp = tm.pair_in(parts.mesh, contact, cycle, rho1);
                k[n] = pp.stiffness_n_per_m;
                gap[n] = pp.gap_m - e_ext - e_run;
                ms.cycle[n] = cycle;
                ms.width_loss[n] = pp.width_loss;
                ms.curvature_change[n] = pp.curvature_change_per_m;
                ms.corner[n] = pp.corner;
            }
        }
        ms.stiffness_n_per_m[n] = k[n];
        ms.stiffness_total_n_per_m += k[n];
        n += 1;
    }
    ms.n_pairs = n;
    (ms, k, gap, ends)
}

/// The mesh force that carries the loaded shaft's torque with the friction moment of
/// the pairs it loads (N; a fixed point, at most 8 passes, to 1e-12), set in `ms` with
/// its deflection and contacts. The pairs carry it by `law`.
fn carry_the_torque(mesh: &TrainMesh, boundary: SpeedBoundary, ms: &mut MeshState, law: &PairLaw) {
    let parts = &mesh.parts;
    let [omega_p, omega_g] = mesh.operating.speeds_rad_s;
    let (torque, on_gear) = match boundary {
        SpeedBoundary::BrakeSpeedImposed => (mesh.operating.torques_nm[0], false),
        _ => (mesh.operating.torques_nm[1], true),
    };
    let arm = if on_gear {
        parts.pair.gear.base_radius_m
    } else {
        parts.pair.pinion.base_radius_m
    };
    let n = law.k.len();
    let mut force = torque / arm;
    for _ in 0..8 {
        ms.force_n = force;
        let delta = law.deflection(force);
        ms.deflection_m = delta;
        let sh = law.shares(delta, force.max(1e-300));
        mesh.fill_contacts(ms, Some(sh), omega_p, omega_g);
        // Friction moment per unit mesh force on the loaded shaft.
        let mut moment_per_n = 0.0;
        for i in 0..n {
            let lever = if on_gear {
                parts.pair.rho_gear(ms.rho1_m[i])
            } else {
                ms.rho1_m[i]
            };
            moment_per_n += lever * ms.friction_n[i] / force.max(1e-300);
        }
        let next = torque / (arm + moment_per_n);
        let done = (next - force).abs() <= 1e-12 * force;
        force = next;
        if done {
            break;
        }
    }
    ms.force_n = force;
    ms.deflection_m = law.deflection(force);
    let sh = law.shares(ms.deflection_m, force);
    mesh.fill_contacts(ms, Some(sh), omega_p, omega_g);
}

/// Each pair's share of the mesh force `force_n` at deflection `delta_m`: its spring
/// force k_i max(delta - g_i, 0) over the force (pairs of stiffness `k`, N/m, gaps `gap`, m).
fn compression_shares(k: &[f64], gap: &[f64], delta_m: f64, force_n: f64) -> [f64; MAX_PAIRS] {
    let mut sh = [0.0; MAX_PAIRS];
    for i in 0..k.len() {
        sh[i] = k[i] * (delta_m - gap[i]).max(0.0) / force_n;
    }
    sh
}

/// Quasi-static response over one mesh period on the same grid as the dynamic solver,
/// or over the tooth-resolved mesh's period of several (`ToothMesh::periods`). A train:
/// every mesh at the nodes of its base period ([`train_nodes`]) repeated over the
/// excitation period.
pub fn solve_quasi_static(sys: &GearSystem, steps_per_mesh_period: usize) -> DynamicResponse {
    if sys.meshes.len() > 1 {
        return solve_train(sys, steps_per_mesh_period);
    }
    let mesh = sys.mesh(0);
    let [omega, omega_g] = mesh.operating.speeds_rad_s;
    let reach = mesh.parts.contact.reach();
    let one = period_nodes_in(mesh.parts.pair, reach, omega, steps_per_mesh_period);
    let periods = mesh.parts.teeth.map_or(1, |tm| tm.periods());
    let t_mesh = *one.last().unwrap_or(&0.0);
    // Nodes as (cycle, time within it): each period's nodes but its last, then the end.
    let mut nodes: Vec<(i64, f64)> = (0..periods as i64)
        .flat_map(|c| one[..one.len() - 1].iter().map(move |t| (c, *t)))
        .collect();
    nodes.push((periods as i64 - 1, t_mesh));
    let abs = |(c, t): (i64, f64)| c as f64 * t_mesh + t;
    let at =
        |node: (i64, f64)| equilibrium_in_cycle(sys, 0, mesh.phase_at(node.1), node.0, abs(node));
    let mut sig = Signals::new(0, 1);
    let mut path = Vec::with_capacity(2 * nodes.len());
    for node in &nodes[..nodes.len() - 1] {
        let (t, phase) = (abs(*node), mesh.phase_at(node.1));
        let ms = at(*node);
        sig.time_s.push(t);
        sig.meshes[0].push(phase, &ms);
        PathSample::push_contacts(&mut path, &ms, mesh.parts.pair.loa_length_m, omega, omega_g);
    }
    // The engagement within the excitation period, as the dynamic recorder gives it
    // (`PathSample::cycle`): the leaving pair of cycle 0 is engagement P - 1, not -1.
    for s in &mut path {
        s.cycle = s.cycle.rem_euclid(periods as i64);
    }
    let path = super::response::sorted_by_rho1(&path);
    // Midpoint-rule means (the force jumps at mesh events, which are grid nodes).
    let (mut fi, mut di) = (0.0, 0.0);
    for w in nodes.windows(2) {
        let (a, b) = (w[0], (w[0].0, w[1].1 + (w[1].0 - w[0].0) as f64 * t_mesh));
        let ms = at((a.0, 0.5 * (a.1 + b.1)));
        fi += ms.force_n * (b.1 - a.1);
        di += ms.deflection_m * (b.1 - a.1);
    }
    let period = abs(*nodes.last().unwrap_or(&(0, 1.0)));
    DynamicResponse {
        meshes: vec![MeshResponse {
            path,
            mean_mesh_force_n: fi / period,
            mean_dte_m: di / period,
        }],
        signals: sig,
        periods_to_converge: 0,
        periodicity_error: 0.0,
        mesh_period_s: t_mesh,
        excitation_periods: periods,
        ..Default::default()
    }
}

/// [`solve_quasi_static`] of a train: the nodes of the base period repeated over the
/// excitation period, each mesh's cycle decided just after each node (a node on a mesh
/// period's boundary opens the next cycle), midpoint-rule means.
fn solve_train(sys: &GearSystem, steps_per_mesh_period: usize) -> DynamicResponse {
    let (Some(one), Some(periods)) = (
        train_nodes(sys, steps_per_mesh_period),
        excitation_periods(sys),
    ) else {
        return DynamicResponse::default();
    };
    let t_base = *one.last().unwrap_or(&0.0);
    let eps = 0.25
        * one
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min);
    let mut times: Vec<f64> = (0..periods)
        .flat_map(|c| {
            one[..one.len() - 1]
                .iter()
                .map(move |t| c as f64 * t_base + t)
        })
        .collect();
    times.push(periods as f64 * t_base);
    let at = |m: usize, t: f64, decide: f64| {
        let mesh = sys.mesh(m);
        let cycle = mesh.parts.pair.mesh_cycle(mesh.phase_at(decide));
        equilibrium_in_cycle(sys, m, mesh.phase_at(t), cycle, t)
    };
    let n_meshes = sys.meshes.len();
    let mut sig = Signals::new(0, n_meshes);
    let mut paths = vec![Vec::new(); n_meshes];
    let mut means = vec![(0.0, 0.0); n_meshes];
    for (k, t) in times[..times.len() - 1].iter().enumerate() {
        sig.time_s.push(*t);
        let mid = 0.5 * (t + times[k + 1]);
        let dt = times[k + 1] - t;
        for m in 0..n_meshes {
            let mesh = sys.mesh(m);
            let ms = at(m, *t, t + eps);
            let phase = mesh.phase_at(*t) % mesh.parts.pair.mesh_angle_rad();
            sig.meshes[m].push(phase, &ms);
            let [wp, wg] = mesh.operating.speeds_rad_s;
            PathSample::push_contacts(&mut paths[m], &ms, mesh.parts.pair.loa_length_m, wp, wg);
            let ms_mid = at(m, mid, mid);
            means[m].0 += ms_mid.force_n * dt;
            means[m].1 += ms_mid.deflection_m * dt;
        }
    }
    let period = periods as f64 * t_base;
    let meshes = paths
        .into_iter()
        .zip(means)
        .map(|(path, (fi, di))| MeshResponse {
            path: super::response::sorted_by_rho1(&path),
            mean_mesh_force_n: fi / period,
            mean_dte_m: di / period,
        })
        .collect();
    DynamicResponse {
        meshes,
        signals: sig,
        mesh_period_s: t_base,
        excitation_periods: periods,
        ..Default::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deflection_closes_gaps_in_order() {
        // Two equal springs, second gap 1 um: below 1e8*1e-6 = 100 N only one touches.
        let k = [1e8, 1e8];
        let g = [0.0, 1e-6];
        assert!((deflection_for_force(&k, &g, 50.0) - 5e-7).abs() < 1e-18);
        // Above: both, delta = (F + k g2) / 2k.
        let d = deflection_for_force(&k, &g, 300.0);
        assert!((d - (300.0 + 100.0) / 2e8).abs() < 1e-18);
        // The force is reproduced.
        let f: f64 = k.iter().zip(&g).map(|(k, g)| k * (d - g).max(0.0)).sum();
        assert!((f - 300.0).abs() < 1e-9);
    }
}
