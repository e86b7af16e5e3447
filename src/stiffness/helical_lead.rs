//! A helical pair's contact line with lead gaps, for the planar dynamics (docs/MODEL.md
//! 11.1 and 11.2): the line's force as a function of its trailing end's position rho and
//! its compression c = delta - e (m), tabulated once.
//!
//! The line at trailing end rho carries its slices at rho + o_j (`SliceMeshStiffness::
//! line_model`), slice j with the lead gap G_j of the face slice it sits on (every tooth
//! carries the same gap, so G_j does not depend on rho). Each slice is a spring
//! k_j(rho) = k_slice(rho + o_j) (0 off the path [A, E]) compressed by c - G_j (no
//! coupling between slices, as in the slice model), so the line's force, N, is
//!   F(rho, c) = sum_j k_j(rho) (c - G_j)+ = c K_M(rho) - KG_M(rho),
//! with the slices sorted by gap, M the number whose gap lies below c, K_M and KG_M the
//! sums of k_j and k_j G_j over those M: a continuous, piecewise-linear, increasing
//! function of c with a kink at each slice's gap (the slices open one by one), and its
//! tangent stiffness dF/dc = K_M(rho), N/m.
//!
//! *Choice (measured, docs/MODEL.md 11.1):* K_M and KG_M are tabulated for every M at the
//! line model's samples of rho (the slice spacing L / N) and interpolated linearly in rho;
//! an evaluation costs one binary search among the N sorted gaps and two table rows
//! (stored M-major, so the two samples around rho share a cache line). The table holds
//! (N + 1) x points pairs of sums, at most [`MAX_TABLE_ENTRIES`]; a finer slicing samples
//! rho more coarsely to stay within it.

use super::helical::SliceMeshStiffness;

/// Most (N + 1) x points entries of a table (each two f64: 64 MB).
pub const MAX_TABLE_ENTRIES: usize = 4_000_000;

/// The contact line's force with lead gaps, tabulated (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct LineGapTable {
    /// The line pair's path start A - L, m, and the spacing of the samples, m.
    rho_start_m: f64,
    step_m: f64,
    points: usize,
    /// The line's slices' gaps in ascending order, m.
    sorted_gaps_m: Vec<f64>,
    /// Entry M * points + i: (K_M, KG_M) at sample i (N/m, N).
    sums: Vec<[f64; 2]>,
}

impl LineGapTable {
    /// The table of `model`'s contact line (N >= 2 slices) with the gap `gaps_m[j]` (m,
    /// >= 0) at face slice j (`SliceMeshStiffness::positions_m`).
    pub fn new(model: &SliceMeshStiffness, gaps_m: &[f64]) -> Self {
        let grid = model.line_grid();
        let n = model.slices();
        let span = grid.line.path_length_m();
        let points = grid.points.min(MAX_TABLE_ENTRIES / (n + 1)).max(2);
        let h = span / (points - 1) as f64;
        // The line's slice i carries the gap of the face slice it sits on.
        let line_gap = |i: usize| gaps_m[model.face_slice_of_line_slice(i)];
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| line_gap(a).total_cmp(&line_gap(b)));
        let sorted_gaps_m: Vec<f64> = order.iter().map(|&i| line_gap(i)).collect();
        let mut sums = vec![[0.0; 2]; (n + 1) * points];
        let mut k = vec![0.0; n];
        let t = &model.pair().transverse;
        for i in 0..points {
            let rho = grid.line.rho_start_m + i as f64 * h;
            for (kj, o) in k.iter_mut().zip(&grid.offsets) {
                let r = rho + o;
                let on_path = (t.rho_start_m..=t.rho_end_m).contains(&r);
                *kj = if on_path {
                    model.slice().pair_stiffness_n_per_m(r)
                } else {
                    0.0
                };
            }
            let (mut sk, mut skg) = (0.0, 0.0);
            for (m, &j) in order.iter().enumerate() {
                sk += k[j];
                skg += k[j] * sorted_gaps_m[m];
                sums[(m + 1) * points + i] = [sk, skg];
            }
        }
        Self {
            rho_start_m: grid.line.rho_start_m,
            step_m: h,
            points,
            sorted_gaps_m,
            sums,
        }
    }

    /// The line's force F (N) and tangent stiffness dF/dc (N/m) at trailing end `rho_m`
    /// and compression `compression_m` = delta - e (m). `touching`: the contact mode holds
    /// the line in contact, so below the first gap the law continues with the first
    /// slice's spring (F < 0; the integrator cuts the step at the switch, docs/MODEL.md 4).
    #[inline]
    pub fn force(&self, rho_m: f64, compression_m: f64, touching: bool) -> (f64, f64) {
        let last = (self.points - 1) as f64;
        let x = ((rho_m - self.rho_start_m) / self.step_m).clamp(0.0, last);
        let i = (x as usize).min(self.points - 2);
        let t = x - i as f64;
        let mut m = self.sorted_gaps_m.partition_point(|g| *g < compression_m);
        if touching {
            m = m.max(1);
        }
        let at = m * self.points + i;
        let (a, b) = (self.sums[at], self.sums[at + 1]);
        let k = a[0] + t * (b[0] - a[0]);
        let kg = a[1] + t * (b[1] - a[1]);
        (compression_m * k - kg, k)
    }

    /// Number of samples of rho.
    pub fn points(&self) -> usize {
        self.points
    }

    /// The largest gap of the line's slices, m (every slice touches beyond it).
    pub(crate) fn largest_gap_m(&self) -> f64 {
        self.sorted_gaps_m.last().copied().unwrap_or(0.0)
    }

    /// Number of slices N of the line.
    pub(crate) fn slices(&self) -> usize {
        self.sorted_gaps_m.len()
    }
}

#[cfg(test)]
#[path = "tests_helical_lead.rs"]
mod tests;
