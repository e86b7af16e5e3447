//! Quasi-static load distribution across the face of a sliced pair with lead gaps
//! (docs/MODEL.md 11.2): lead modifications and a mesh misalignment as a gap g_j at each
//! slice, the slices of the slice model (`stiffness::helical`) as independent springs, and
//! the face load factor K_Hbeta.
//!
//! At a mesh position phi the slice j (all its tooth pairs in contact, every tooth carrying
//! the same lead gap) has stiffness K_j(phi) along the transverse line of action, N/m, and
//! carries F_j = K_j (delta - g_j)+ at the common rigid-body approach delta (no coupling
//! between slices, as in the slice model). The pair's transmitted force F (along the
//! transverse line of action, the case's static mesh force) fixes delta:
//!   sum_j K_j (delta - g_j)+ = F,
//! a continuous, piecewise-linear, increasing function of delta, solved exactly: with the
//! slices sorted by gap, the first m in contact give delta = (F + sum K_j g_j) / sum K_j,
//! valid once delta lies below the next gap. The load per unit face width is
//! w_j = F_j / (b/N), N/m; the centre of pressure sum y_j w_j / sum w_j.
//!
//! K_Hbeta (ISO 6336-1:2019, 3.1 and 7: the maximum over the mean load per unit face width,
//! w_max / w_m with w_m = F / b) is reported of the load distribution averaged over a
//! mesh period, w_bar(y_j) = mean over positions of w_j: the variation along the path of
//! contact that the meshing itself brings (ISO's K_Halpha and the contact lines' travel
//! across a helical face) averages out and what stays is the lead direction's, ISO's
//! K_Hbeta. The largest instantaneous ratio max_j w_j / w_m over the positions is
//! reported beside it.

use super::helical::SliceMeshStiffness;

/// Lead modifications and misalignment of a pair as one gap across the face, in SI
/// units; each is the pair's (both gears' together), measured along the transverse line
/// of action (ISO 1328-1 measures helix deviations in the transverse plane along the base
/// tangent).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LeadGap {
    /// Crowning C_beta: the gap at each face end over the middle, parabolic, m.
    pub crowning_m: f64,
    /// End relief at each face end, m.
    pub end_relief_m: f64,
    /// Length of each end relief across the face, m.
    pub end_relief_length_m: f64,
    /// Whether the end relief falls with the square of the distance (else linearly).
    pub end_relief_parabolic: bool,
    /// Linear part: the gap's difference across the face (helix slope deviation f_Hbeta
    /// plus the misalignment in the plane of action), m, positive opening towards y = b.
    pub slope_m: f64,
}

impl LeadGap {
    /// Whether the gap is zero everywhere.
    pub fn is_zero(&self) -> bool {
        self.crowning_m == 0.0 && self.end_relief_m == 0.0 && self.slope_m == 0.0
    }

    /// The gap at y across the face of width `b_m`, m, before its shift (all parts 0 at
    /// mid-face but the slope, 0 at y = 0):
    ///   g(y) = C_beta u^2 + C_e t^p + f y / b,  u = 2 y / b - 1,
    /// with t = 1 - d / L_e inside an end relief (d the distance to the nearer face end,
    /// L_e its length; p = 1 linear, 2 parabolic) and 0 elsewhere.
    pub fn raw_m(&self, y_m: f64, b_m: f64) -> f64 {
        let u = 2.0 * y_m / b_m - 1.0;
        let mut g = self.crowning_m * u * u + self.slope_m * y_m / b_m;
        let d = y_m.min(b_m - y_m);
        if self.end_relief_m != 0.0 && d < self.end_relief_length_m {
            let t = 1.0 - d / self.end_relief_length_m;
            g += self.end_relief_m * if self.end_relief_parabolic { t * t } else { t };
        }
        g
    }

    /// The gaps at the slice positions, shifted so that the smallest is 0 (the approach is
    /// measured from the first touch), m.
    pub fn gaps_m(&self, positions_m: &[f64], b_m: f64) -> Vec<f64> {
        let raw: Vec<f64> = positions_m.iter().map(|&y| self.raw_m(y, b_m)).collect();
        let lo = raw.iter().fold(f64::INFINITY, |a, &g| a.min(g));
        raw.iter().map(|g| g - lo).collect()
    }
}

/// The load across the face at one mesh position.
#[derive(Debug, Clone, PartialEq)]
pub struct FacePosition {
    /// Pinion rotation (the slice model's phase), rad.
    pub phase_rad: f64,
    /// Rigid-body approach delta along the transverse line of action from the first
    /// touch, m.
    pub approach_m: f64,
    /// Load per unit face width w_j at each slice, N/m.
    pub load_per_width_n_per_m: Vec<f64>,
}

impl FacePosition {
    /// Number of slices carrying load.
    pub fn loaded_slices(&self) -> usize {
        self.load_per_width_n_per_m
            .iter()
            .filter(|w| **w > 0.0)
            .count()
    }
}

/// The face load distribution over a mesh period. See the module docs.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceLoad {
    /// Slice positions y_j across the face, m.
    pub positions_m: Vec<f64>,
    /// Face width b, m.
    pub face_width_m: f64,
    /// The gap g_j at each slice, m (smallest 0).
    pub gaps_m: Vec<f64>,
    /// The transmitted force F along the transverse line of action, N.
    pub force_n: f64,
    /// The mesh positions, uniform over one mesh period.
    pub positions: Vec<FacePosition>,
}

/// Why a face load cannot be solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct FaceLoadError(pub String);

/// The common approach delta with sum_j K_j (delta - g_j)+ = `force_n` (module docs);
/// `order` sorts the slices by gap. `None` if no slice has stiffness.
fn approach_m(k: &[f64], gaps: &[f64], order: &[usize], force_n: f64) -> Option<f64> {
    let (mut sk, mut skg) = (0.0, 0.0);
    for (m, &j) in order.iter().enumerate() {
        sk += k[j];
        skg += k[j] * gaps[j];
        if sk <= 0.0 {
            continue;
        }
        let delta = (force_n + skg) / sk;
        if m + 1 == order.len() || delta <= gaps[order[m + 1]] {
            return Some(delta);
        }
    }
    None
}

impl FaceLoad {
    /// Solve the slice springs of `model` with the gap `gap` under the transmitted force
    /// `force_n` (N, > 0) at `positions` uniform mesh positions over one mesh period.
    pub fn solve(
        model: &SliceMeshStiffness,
        gap: &LeadGap,
        force_n: f64,
        positions: usize,
    ) -> Result<Self, FaceLoadError> {
        let b = model.pair().face_width_m;
        let y = model.positions_m().to_vec();
        let n = y.len();
        let gaps = gap.gaps_m(&y, b);
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&i, &j| gaps[i].total_cmp(&gaps[j]));
        let width = b / n as f64;
        let period = model.pair().transverse.mesh_angle_rad();
        let mut k = vec![0.0; n];
        let mut out = Vec::with_capacity(positions);
        for i in 0..positions {
            let phase_rad = period * i as f64 / positions as f64;
            model.slice_stiffnesses(phase_rad, &mut k);
            let delta = approach_m(&k, &gaps, &order, force_n).ok_or_else(|| {
                FaceLoadError(format!(
                    "no slice is in contact at pinion angle {} deg",
                    phase_rad.to_degrees()
                ))
            })?;
            let w = k
                .iter()
                .zip(&gaps)
                .map(|(kj, g)| kj * (delta - g).max(0.0) / width)
                .collect();
            out.push(FacePosition {
                phase_rad,
                approach_m: delta,
                load_per_width_n_per_m: w,
            });
        }
        Ok(Self {
            positions_m: y,
            face_width_m: b,
            gaps_m: gaps,
            force_n,
            positions: out,
        })
    }

    /// Mean load per unit face width w_m = F / b, N/m.
    pub fn mean_load_per_width_n_per_m(&self) -> f64 {
        self.force_n / self.face_width_m
    }

    /// The load per unit face width at each slice averaged over the mesh positions, N/m.
    pub fn period_mean_n_per_m(&self) -> Vec<f64> {
        let m = self.positions.len() as f64;
        let mut mean = vec![0.0; self.positions_m.len()];
        for p in &self.positions {
            for (a, w) in mean.iter_mut().zip(&p.load_per_width_n_per_m) {
                *a += w / m;
            }
        }
        mean
    }

    /// Largest load per unit face width at each slice over the mesh positions, N/m.
    pub fn envelope_n_per_m(&self) -> Vec<f64> {
        let mut hi = vec![0.0_f64; self.positions_m.len()];
        for p in &self.positions {
            for (a, w) in hi.iter_mut().zip(&p.load_per_width_n_per_m) {
                *a = a.max(*w);
            }
        }
        hi
    }

    /// Largest value of a distribution `w` over the mean load per unit face width w_m.
    fn peak_over_mean(&self, w: &[f64]) -> f64 {
        peak_of(w) / self.mean_load_per_width_n_per_m()
    }

    /// K_Hbeta = w_max / w_m of the period-mean distribution (module docs).
    pub fn k_h_beta(&self) -> f64 {
        self.peak_over_mean(&self.period_mean_n_per_m())
    }

    /// The largest instantaneous max_j w_j / w_m over the mesh positions.
    pub fn k_h_beta_instantaneous_max(&self) -> f64 {
        self.peak_over_mean(&self.envelope_n_per_m())
    }

    /// Centre of pressure of a distribution `w` over the slices, m from y = 0.
    pub fn centre_of(&self, w: &[f64]) -> f64 {
        centre_of_pressure(w, &self.positions_m)
    }

    /// Centre of pressure of the period-mean distribution, m from y = 0.
    pub fn centre_of_pressure_m(&self) -> f64 {
        self.centre_of(&self.period_mean_n_per_m())
    }

    /// Fewest slices carrying load at any mesh position.
    pub fn fewest_loaded_slices(&self) -> usize {
        self.positions
            .iter()
            .map(FacePosition::loaded_slices)
            .min()
            .unwrap_or(0)
    }
}

/// Largest load per unit face width of a distribution `w` over the slices (0 for none),
/// N/m: the peak of ISO 6336-1's K_Hbeta = w_max / w_m.
pub fn peak_of(w: &[f64]) -> f64 {
    w.iter().fold(0.0_f64, |a, w| a.max(*w))
}

/// Centre of pressure sum_j y_j w_j / sum_j w_j of a distribution `w` (any unit) over the
/// slices at positions `positions_m` (m from y = 0), m: the static face load's and the
/// dynamic one's (`study::face_load_dynamic`).
pub fn centre_of_pressure(w: &[f64], positions_m: &[f64]) -> f64 {
    let total: f64 = w.iter().sum();
    w.iter().zip(positions_m).map(|(w, y)| w * y).sum::<f64>() / total
}

#[cfg(test)]
#[path = "tests_face_load.rs"]
mod tests;
