//! Result of a steady-state dynamic (or quasi-static) evaluation.

use serde::Serialize;

/// One contact along the path of contact: what a tooth pair sees when it is at rho1.
///
/// Over one steady mesh period every position of the path is visited by some pair, so
/// these samples sorted by rho1 are the history of one tooth pair through its whole
/// engagement (all teeth alike, as the paper assumes).
#[derive(Debug, Clone, Copy, Serialize, Default)]
pub struct PathSample {
    /// Pinion radius of curvature rho1 at the contact (its position on the line of action,
    /// measured from the pinion's base-circle tangent point), m.
    pub rho1_m: f64,
    /// Load W carried by the pair, N.
    pub load_n: f64,
    /// Maximum Hertz contact pressure p_0, Pa.
    pub pressure_pa: f64,
    /// Hertz contact half-width a, m.
    pub half_width_m: f64,
    /// Friction coefficient mu (the case's law: Xu et al., paper eq. 8, by default).
    pub friction_coefficient: f64,
    /// Signed friction force, N (positive when the pinion surface is faster).
    pub friction_n: f64,
    /// Pinion and gear surface speeds perpendicular to the line of action, m/s.
    pub pinion_surface_speed_m_per_s: f64,
    /// Gear surface speed perpendicular to the line of action, m/s.
    pub gear_surface_speed_m_per_s: f64,
    /// Mesh cycle of the pair modulo the excitation period P (tooth-resolved mesh; 0
    /// otherwise): its engagement within the period, in [0, P), from the dynamic recorder
    /// and the quasi-static solver alike. Its teeth are cycle mod z1 and cycle mod z2 (a
    /// gear whose teeth are all alike is the same tooth whichever).
    pub cycle: i64,
}

impl PathSample {
    /// The contacts of a mesh state on the path of contact, with the pinion and gear
    /// speeds (rad/s) that made them.
    pub fn push_contacts(
        path: &mut Vec<PathSample>,
        ms: &super::model::MeshState,
        loa_length_m: f64,
        omega_pinion_rad_s: f64,
        omega_gear_rad_s: f64,
    ) {
        // Corner contacts touch the tip edge and, off the line of action, the mate's
        // flank: no Hertz line contact of the path (docs/MODEL.md, section 4).
        for i in (0..ms.n_pairs).filter(|i| !ms.corner[*i]) {
            let rho1 = ms.rho1_m[i];
            path.push(PathSample {
                rho1_m: rho1,
                load_n: ms.load_n[i],
                pressure_pa: ms.pressure_pa[i],
                half_width_m: ms.half_width_m[i],
                friction_coefficient: ms.friction_coefficient[i],
                friction_n: ms.friction_n[i],
                pinion_surface_speed_m_per_s: omega_pinion_rad_s * rho1,
                gear_surface_speed_m_per_s: omega_gear_rad_s * (loa_length_m - rho1),
                cycle: ms.cycle[i],
            });
        }
    }
}

/// Generalised coordinates (displacements, velocities or accelerations) at every sample,
/// `dofs` per sample, stored flat: `c[k]` is sample k's slice.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Coordinates {
    dofs: usize,
    values: Vec<f64>,
}

impl Coordinates {
    /// No samples of `dofs` coordinates.
    pub fn new(dofs: usize) -> Self {
        Self {
            dofs,
            values: Vec::new(),
        }
    }

    /// Coordinates per sample.
    pub fn dofs(&self) -> usize {
        self.dofs
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.values.len().checked_div(self.dofs).unwrap_or(0)
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// Appends a sample (its `dofs` coordinates).
    pub fn push(&mut self, sample: &[f64]) {
        debug_assert_eq!(sample.len(), self.dofs);
        self.values.extend_from_slice(sample);
    }

    /// The samples in order.
    pub fn iter(&self) -> std::slice::ChunksExact<'_, f64> {
        self.values.chunks_exact(self.dofs.max(1))
    }

    /// Appends every sample of `other` (of the same `dofs`).
    pub(crate) fn append(&mut self, other: &Coordinates) {
        debug_assert_eq!(other.dofs, self.dofs);
        self.values.extend_from_slice(&other.values);
    }

    /// Adds `shift` (one value per coordinate) to every sample.
    pub(crate) fn shift_each(&mut self, shift: &[f64]) {
        for sample in self.values.chunks_exact_mut(self.dofs.max(1)) {
            for (v, d) in sample.iter_mut().zip(shift) {
                *v += d;
            }
        }
    }

    /// Coordinate `i` of every sample.
    pub fn column(&self, i: usize) -> Vec<f64> {
        self.iter().map(|s| s[i]).collect()
    }
}

impl std::ops::Index<usize> for Coordinates {
    type Output = [f64];

    fn index(&self, k: usize) -> &[f64] {
        &self.values[k * self.dofs..(k + 1) * self.dofs]
    }
}

/// One mesh's time series over the evaluated window, sampled with [`Signals::time_s`].
#[derive(Debug, Clone, Default)]
pub struct MeshSignals {
    /// Mesh phase, rad of the mesh's pinion rotation (reduced to one mesh period).
    pub phase_rad: Vec<f64>,
    /// Dynamic transmission error: relative displacement along the line of action, m.
    pub dte_m: Vec<f64>,
    /// Mesh force F, N.
    pub mesh_force_n: Vec<f64>,
    /// Sum of the stiffnesses of the pairs in contact, N/m.
    pub mesh_stiffness_n_per_m: Vec<f64>,
    /// Rate of the DTE, m/s: the mesh gradient times the velocities (the DTE is linear in
    /// the displacements), the DTE's slope for its interpolant. Empty when quasi-static.
    pub dte_rate_m_per_s: Vec<f64>,
    /// Friction coefficient and signed friction force of the pair that entered contact
    /// last (pair 0) and of the one ahead of it (pair 1; 0 when out of contact).
    pub friction_coefficient: [Vec<f64>; 2],
    /// Signed friction force of pair 0 and pair 1, N (positive when the pinion surface is
    /// faster).
    pub friction_n: [Vec<f64>; 2],
    /// Load of pair 0 and pair 1, N.
    pub pair_load_n: [Vec<f64>; 2],
}

impl MeshSignals {
    /// Per-pair friction and load of the first two pairs (0 when a pair is out of contact).
    ///
    /// The pairs are those on the path of contact, in order (a corner beyond the path is
    /// not one of them: `MeshState::corner`).
    pub fn push_pairs(&mut self, ms: &super::model::MeshState) {
        let mut on_path = (0..ms.n_pairs).filter(|i| !ms.corner[*i]);
        for j in 0..2 {
            let at = on_path.next();
            let pick = |a: &[f64; super::model::MAX_PAIRS]| at.map_or(0.0, |i| a[i]);
            self.friction_coefficient[j].push(pick(&ms.friction_coefficient));
            self.friction_n[j].push(pick(&ms.friction_n));
            self.pair_load_n[j].push(pick(&ms.load_n));
        }
    }

    /// Appends a sample of a mesh state at mesh phase `phase_rad`.
    pub fn push(&mut self, phase_rad: f64, ms: &super::model::MeshState) {
        self.phase_rad.push(phase_rad);
        self.dte_m.push(ms.deflection_m);
        self.mesh_force_n.push(ms.force_n);
        self.mesh_stiffness_n_per_m.push(ms.stiffness_total_n_per_m);
        self.push_pairs(ms);
    }

    /// Appends the samples of `later` (the series that follows).
    fn append(&mut self, later: &MeshSignals) {
        // Destructured in full: a new signal must be appended here too.
        let Self {
            phase_rad,
            dte_m,
            mesh_force_n,
            mesh_stiffness_n_per_m,
            dte_rate_m_per_s,
            friction_coefficient,
            friction_n,
            pair_load_n,
        } = later;
        self.phase_rad.extend_from_slice(phase_rad);
        self.dte_m.extend_from_slice(dte_m);
        self.mesh_force_n.extend_from_slice(mesh_force_n);
        self.mesh_stiffness_n_per_m
            .extend_from_slice(mesh_stiffness_n_per_m);
        self.dte_rate_m_per_s.extend_from_slice(dte_rate_m_per_s);
        for j in 0..2 {
            self.friction_coefficient[j].extend_from_slice(&friction_coefficient[j]);
            self.friction_n[j].extend_from_slice(&friction_n[j]);
            self.pair_load_n[j].extend_from_slice(&pair_load_n[j]);
        }
    }

    /// The series repeated: every sample appended again `times` more times.
    fn repeat(&mut self, times: usize) {
        // Destructured in full: a new signal must be repeated here too.
        let Self {
            phase_rad,
            dte_m,
            mesh_force_n,
            mesh_stiffness_n_per_m,
            dte_rate_m_per_s,
            friction_coefficient,
            friction_n,
            pair_load_n,
        } = self;
        let series = [
            phase_rad,
            dte_m,
            mesh_force_n,
            mesh_stiffness_n_per_m,
            dte_rate_m_per_s,
        ];
        let pairs = friction_coefficient
            .iter_mut()
            .chain(friction_n.iter_mut())
            .chain(pair_load_n.iter_mut());
        for v in series.into_iter().chain(pairs) {
            let one = v.clone();
            for _ in 0..times {
                v.extend_from_slice(&one);
            }
        }
    }
}

/// Time series over the evaluated window (whole periods). A sample at every grid
/// node (right limit at a mesh event) and at every integration step between nodes, so
/// the spacing is not uniform: it is short where the error control shortened the steps
/// (after each mesh event, near contact switches). The dynamic solver integrates one
/// period of the periodic solution and repeats it over the window.
#[derive(Debug, Clone, Default)]
pub struct Signals {
    /// Sample times, s (not uniformly spaced).
    pub time_s: Vec<f64>,
    /// Generalised displacements q (the assembly's coordinates: 8 for the single pair),
    /// velocities and accelerations.
    pub displacement: Coordinates,
    /// Generalised velocities dq/dt at every sample (m/s, rad/s).
    pub velocity: Coordinates,
    /// Generalised accelerations at every sample (m/s^2, rad/s^2; the limit from the right).
    pub acceleration: Coordinates,
    /// Accelerations at the start (`[0]`) and the end (`[1]`) of the integration step that
    /// leaves each sample, evaluated with that step's own pairs and contact mode: where a
    /// mesh event or a contact switch makes the force jump, the end one is the limit from
    /// the left at the next sample, which `acceleration` (the limit from the right) is not.
    /// With the displacements and velocities they give the solution between the samples,
    /// the cubic Hermite interpolant of the solver's steps (`super::fourier`). Empty for a
    /// quasi-static response, whose samples are all there is.
    pub step_acceleration: [Coordinates; 2],
    /// Each mesh's series, in the train's mesh order.
    pub meshes: Vec<MeshSignals>,
}

impl Signals {
    /// No samples, for `dofs` coordinates and `meshes` meshes.
    pub fn new(dofs: usize, meshes: usize) -> Self {
        Self {
            time_s: Vec::new(),
            displacement: Coordinates::new(dofs),
            velocity: Coordinates::new(dofs),
            acceleration: Coordinates::new(dofs),
            step_acceleration: [Coordinates::new(dofs), Coordinates::new(dofs)],
            meshes: vec![MeshSignals::default(); meshes],
        }
    }

    /// Appends the samples of `later` (the stretch of the solution that follows).
    pub(crate) fn append(&mut self, later: &Signals) {
        // Destructured in full: a new signal must be appended here too.
        let Self {
            time_s,
            displacement,
            velocity,
            acceleration,
            step_acceleration,
            meshes,
        } = later;
        self.time_s.extend_from_slice(time_s);
        self.displacement.append(displacement);
        self.velocity.append(velocity);
        self.acceleration.append(acceleration);
        for (out, more) in self.step_acceleration.iter_mut().zip(step_acceleration) {
            out.append(more);
        }
        for (out, more) in self.meshes.iter_mut().zip(meshes) {
            out.append(more);
        }
    }

    /// The recorded period repeated `periods` times, each repeat `period` s later and its
    /// displacements moved by `drift` more (the rigid rotation's drift per period).
    pub fn repeated(&self, period: f64, periods: usize, drift: &[f64]) -> Self {
        // Destructured in full: a new signal must be repeated here too.
        let Self {
            time_s,
            displacement,
            velocity,
            acceleration,
            step_acceleration,
            meshes,
        } = self;
        let mut sig = self.clone();
        let mut moved = vec![0.0; displacement.dofs()];
        for p in 1..periods {
            let shift = p as f64 * period;
            sig.time_s.extend(time_s.iter().map(|t| t + shift));
            for q in displacement.iter() {
                for (m, (qi, di)) in moved.iter_mut().zip(q.iter().zip(drift)) {
                    *m = qi + p as f64 * di;
                }
                sig.displacement.push(&moved);
            }
            for v in velocity.iter() {
                sig.velocity.push(v);
            }
            for a in acceleration.iter() {
                sig.acceleration.push(a);
            }
            for (out, one) in sig.step_acceleration.iter_mut().zip(step_acceleration) {
                for a in one.iter() {
                    out.push(a);
                }
            }
        }
        for (out, _) in sig.meshes.iter_mut().zip(meshes) {
            out.repeat(periods.saturating_sub(1));
        }
        sig
    }
}

/// One mesh's share of a steady-state response.
#[derive(Debug, Clone, Default)]
pub struct MeshResponse {
    /// Samples along the path of contact over the last period, sorted by rho1.
    pub path: Vec<PathSample>,
    /// Time means over the evaluated window by Simpson's rule on the steps (the mesh force
    /// jumps at mesh events, which lie on grid nodes, so a trapezoid on the nodes would
    /// split each jump and be first order only).
    pub mean_mesh_force_n: f64,
    /// Time mean of the dynamic transmission error, m.
    pub mean_dte_m: f64,
}

impl MeshResponse {
    /// Load a pair carries at LOA position rho1 (linear interpolation along the path).
    pub fn path_at(&self, rho1_m: f64) -> PathSample {
        interpolate_path(&self.path, rho1_m)
    }
}

/// A steady-state response.
#[derive(Debug, Clone, Default)]
pub struct DynamicResponse {
    /// Time series over the evaluated window.
    pub signals: Signals,
    /// Each mesh's path of contact and means, in the train's mesh order.
    pub meshes: Vec<MeshResponse>,
    /// Periods integrated before the periodic state was found (the recorded window not
    /// included).
    pub periods_to_converge: usize,
    /// Largest change of the state over one recorded period, relative to the state's
    /// scales (`state_scales::state_scales`): how periodic the recorded window is.
    pub periodicity_error: f64,
    /// The base period: the mesh period of a single pair, the smallest common period of
    /// a train's meshes, s.
    pub mesh_period_s: f64,
    /// Base periods after which the response repeats: 1 when every tooth is alike, else
    /// the tooth-resolved meshes' period (`ToothMesh::periods`, lcm(z1, z2) at most for a
    /// single pair).
    pub excitation_periods: usize,
    /// State y = [q; dq/dt] (SI, `dynamics::model` coordinates) at the end of the
    /// evaluated window, a period boundary (mesh phase 0). Passing it as the start of
    /// another evaluation (`steady::solve_steady_state_from`) warm-starts that one from
    /// this periodic state: wear updates, continuation along a parameter.
    pub end_state: Vec<f64>,
    /// Integrator work (for benchmarks and the performance notes): accepted steps over
    /// all periods integrated, rhs calls, LU factorisations, and the step counts in
    /// detail (rejections, contact switches).
    pub steps: usize,
    /// Right-hand side evaluations.
    pub rhs_evaluations: usize,
    /// LU factorisations of the iteration matrix.
    pub factorizations: usize,
    /// Step counts in detail (rejections, contact switches).
    pub step_counts: super::period::StepCounts,
}

impl DynamicResponse {
    /// Fraction of the evaluated window during which mesh `m` transmits no force
    /// (contact loss), from the samples: the intervals whose both ends carry none.
    pub fn contact_loss_fraction_of(&self, m: usize) -> f64 {
        let s = &self.signals;
        let f = &s.meshes[m].mesh_force_n;
        let (mut off, mut total) = (0.0, 0.0);
        for k in 1..s.time_s.len() {
            let dt = s.time_s[k] - s.time_s[k - 1];
            total += dt;
            if f[k] <= 0.0 && f[k - 1] <= 0.0 {
                off += dt;
            }
        }
        if total > 0.0 {
            off / total
        } else {
            0.0
        }
    }

    /// [`DynamicResponse::contact_loss_fraction_of`] the first mesh (the single pair's).
    pub fn contact_loss_fraction(&self) -> f64 {
        self.contact_loss_fraction_of(0)
    }

    /// Load a pair of the first mesh carries at LOA position rho1 (linear interpolation
    /// along the path).
    pub fn path_at(&self, rho1_m: f64) -> PathSample {
        self.meshes[0].path_at(rho1_m)
    }
}

/// Linear interpolation of path samples (sorted by rho1) at rho1; clamped at the ends.
pub fn interpolate_path(path: &[PathSample], rho1_m: f64) -> PathSample {
    if path.is_empty() {
        return PathSample::default();
    }
    let j = path.partition_point(|s| s.rho1_m < rho1_m);
    if j == 0 {
        return path[0];
    }
    if j == path.len() {
        return path[path.len() - 1];
    }
    let (a, b) = (&path[j - 1], &path[j]);
    let span = b.rho1_m - a.rho1_m;
    let t = if span > 0.0 {
        (rho1_m - a.rho1_m) / span
    } else {
        0.0
    };
    let l = |x: f64, y: f64| x + (y - x) * t;
    PathSample {
        rho1_m,
        load_n: l(a.load_n, b.load_n),
        pressure_pa: l(a.pressure_pa, b.pressure_pa),
        half_width_m: l(a.half_width_m, b.half_width_m),
        friction_coefficient: l(a.friction_coefficient, b.friction_coefficient),
        friction_n: l(a.friction_n, b.friction_n),
        pinion_surface_speed_m_per_s: l(
            a.pinion_surface_speed_m_per_s,
            b.pinion_surface_speed_m_per_s,
        ),
        gear_surface_speed_m_per_s: l(a.gear_surface_speed_m_per_s, b.gear_surface_speed_m_per_s),
        cycle: a.cycle,
    }
}

/// The path of contact in order of rho1, equal rho1 in their recorded order: exactly what
/// a stable sort by `f64::total_cmp` gives. Sorts (key, index) pairs of 16 bytes instead
/// of moving the 72-byte samples: a hunting period's path holds ~10^5 of them
/// (docs/PERFORMANCE.md).
pub fn sorted_by_rho1(path: &[PathSample]) -> Vec<PathSample> {
    // `total_cmp`'s order as an integer: the same bit flip it performs.
    let key = |x: f64| {
        let b = x.to_bits() as i64;
        b ^ (((b >> 63) as u64) >> 1) as i64
    };
    let mut order: Vec<(i64, usize)> = path
        .iter()
        .enumerate()
        .map(|(i, s)| (key(s.rho1_m), i))
        .collect();
    // The index breaks ties, so the unstable sort yields the stable order.
    order.sort_unstable();
    order.iter().map(|&(_, i)| path[i]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_key_sort_is_the_stable_total_order_sort() {
        // Interleaved runs with repeated values (the engagements of a hunting period meet
        // the same rho1 at the grid nodes), signed zeros and a wide range: the order, and
        // among equal rho1 the recorded order (told apart by `cycle`), must be the stable
        // sort's.
        let mut path = Vec::new();
        for i in 0..2000_i64 {
            let rho1_m = match i % 7 {
                0 => 0.0,
                1 => -0.0,
                2 => 1e-3 * ((i * 37) % 11) as f64,
                3 => -1e-3 * ((i * 13) % 5) as f64,
                _ => 1e-3 * (i as f64).sin() + 1e-300 * (i % 3) as f64,
            };
            path.push(PathSample {
                rho1_m,
                cycle: i,
                ..PathSample::default()
            });
        }
        let mut stable = path.clone();
        stable.sort_by(|a, b| a.rho1_m.total_cmp(&b.rho1_m));
        let fast = sorted_by_rho1(&path);
        assert_eq!(fast.len(), stable.len());
        for (a, b) in fast.iter().zip(&stable) {
            assert_eq!((a.rho1_m.to_bits(), a.cycle), (b.rho1_m.to_bits(), b.cycle));
        }
    }
}
