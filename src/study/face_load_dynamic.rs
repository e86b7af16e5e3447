//! The dynamic face load distribution of a helical pair with lead gaps (`gearwear dynamics`,
//! docs/MODEL.md 11.1 and 11.2): the slice loads over the steady state, their time mean and
//! maximum per slice, the dynamic K_Hbeta, the centre of pressure and the tilting moment.
//!
//! At each recorded sample (mesh phase phi, deflection delta, mesh force F) the slices of
//! the contact lines in contact at phi (`SliceMeshStiffness::add_line_slices`, the lines of
//! the dynamic model) give each face slice j its stiffness K_j and force
//! F_j = K_j (c - g_j)+, c = delta + e(phi) the compression (e the external error, the
//! lines' wear gap 0): the dynamic model's law summed slice by slice instead of through the
//! line table. The mesh force F (springs and damper) is then shared in proportion,
//! F_j F / sum F_j, as the contact lines share it (`contact.load_sharing` = "stiffness"),
//! so the slice loads add up to the recorded mesh force at every sample. The load per unit
//! face width is w_j = F_j / (b/N), N/m.
//!
//! Over the window (trapezoid rule on the samples' times): the time mean w_bar_j and the
//! largest w_j; K_Hbeta = max_j w_bar_j / w_m with w_m = the mean of w_bar over the face
//! = (time mean of F) / b (ISO 6336-1's peak over mean, as `gearwear stiffness` reports it
//! of the period mean), and the largest instantaneous max_j w_j / w_m beside it; the centre
//! of pressure sum y_j w_bar_j / sum w_bar_j; the tilting moment about the face centre
//! M = sum_j F_j (y_j - b/2), N m (see [`DynamicFaceLoad::tilting_moment_nm`]).

use super::Model;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::model::MAX_PAIRS;
use crate::dynamics::response::DynamicResponse;
use crate::stiffness::face_load::{centre_of_pressure, peak_of};

/// The face load over the steady state (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicFaceLoad {
    /// Slice positions y_j across the face, m, and the face width b, m.
    pub positions_m: Vec<f64>,
    /// Face width b, m.
    pub face_width_m: f64,
    /// The gap g_j at each slice, m (smallest 0).
    pub gaps_m: Vec<f64>,
    /// Time mean and largest load per unit face width at each slice, N/m.
    pub mean_n_per_m: Vec<f64>,
    /// Largest load per unit face width over the samples at each slice, N/m.
    pub max_n_per_m: Vec<f64>,
    /// The samples' times, s, and the tilting moment at each, N m.
    pub time_s: Vec<f64>,
    /// Tilting moment at each sample, N m.
    pub moment_nm: Vec<f64>,
    /// Largest max_j w_j over the samples, N/m.
    pub peak_n_per_m: f64,
}

/// Trapezoid weights of samples at times `t` (s), normalised to sum to 1.
fn trapezoid_weights(t: &[f64]) -> Vec<f64> {
    let n = t.len();
    let mut w = vec![0.0; n];
    if n < 2 {
        return vec![1.0; n];
    }
    for k in 0..n - 1 {
        let h = 0.5 * (t[k + 1] - t[k]);
        w[k] += h;
        w[k + 1] += h;
    }
    let span = t[n - 1] - t[0];
    w.iter_mut().for_each(|x| *x /= span);
    w
}

impl DynamicFaceLoad {
    /// The face load of `model`'s steady state `r` under the external error `external`;
    /// None when the model has no lead gaps.
    pub fn of(model: &Model, r: &DynamicResponse, external: &ExternalError) -> Option<Self> {
        let lead = model.helical.as_ref()?.lead.as_ref()?;
        let s = &lead.slices;
        let grid = s.line_grid();
        let b = s.pair().face_width_m;
        let n = s.slices();
        let width = b / n as f64;
        let gaps = lead.static_load.gaps_m.clone();
        let y = s.positions_m().to_vec();
        let sig = &r.signals.meshes[0];
        let weights = trapezoid_weights(&r.signals.time_s);
        // With tilting degrees of freedom, each slice's compression gains the relative
        // tilt's linear part across the face, (y_j - b/2) tau (docs/MODEL.md 11.8).
        let tau = super::helical_tilt::relative_tilt_rad(model, r);
        let (mut mean, mut max) = (vec![0.0; n], vec![0.0_f64; n]);
        let mut moment = Vec::with_capacity(weights.len());
        let (mut k, mut f) = (vec![0.0; n], vec![0.0; n]);
        for (i, wt) in weights.iter().enumerate() {
            let phase = sig.phase_rad[i];
            let c = sig.dte_m[i] + external.at(phase).0;
            k.fill(0.0);
            let lines = model
                .pair
                .pairs_in_reach_decided(model.contact.reach(), phase, phase);
            for (_, rho) in lines.take(MAX_PAIRS) {
                s.add_line_slices(&grid, rho, &mut k);
            }
            let tilt = tau.as_ref().map_or(0.0, |t| t[i]);
            for (j, ((fj, kj), g)) in f.iter_mut().zip(&k).zip(&gaps).enumerate() {
                *fj = kj * (c - g + (y[j] - 0.5 * b) * tilt).max(0.0);
            }
            let total: f64 = f.iter().sum();
            let scale = if total > 0.0 {
                sig.mesh_force_n[i] / total
            } else {
                0.0
            };
            let mut m = 0.0;
            for j in 0..n {
                let fj = f[j] * scale;
                m += fj * (y[j] - 0.5 * b);
                let w = fj / width;
                mean[j] += wt * w;
                max[j] = max[j].max(w);
            }
            moment.push(m);
        }
        let peak_n_per_m = peak_of(&max);
        Some(Self {
            positions_m: y,
            face_width_m: b,
            gaps_m: gaps,
            mean_n_per_m: mean,
            max_n_per_m: max,
            time_s: r.signals.time_s.clone(),
            moment_nm: moment,
            peak_n_per_m,
        })
    }

    /// Mean load per unit face width w_m: the mean of the time-mean distribution over the
    /// face, (time mean of the mesh force) / b, N/m.
    pub fn mean_load_per_width_n_per_m(&self) -> f64 {
        self.mean_n_per_m.iter().sum::<f64>() / self.mean_n_per_m.len() as f64
    }

    /// K_Hbeta = max_j w_bar_j / w_m of the time-mean distribution.
    pub fn k_h_beta(&self) -> f64 {
        peak_of(&self.mean_n_per_m) / self.mean_load_per_width_n_per_m()
    }

    /// The largest instantaneous max_j w_j / w_m over the samples.
    pub fn k_h_beta_instantaneous_max(&self) -> f64 {
        self.peak_n_per_m / self.mean_load_per_width_n_per_m()
    }

    /// Centre of pressure of the time-mean distribution, m from y = 0.
    pub fn centre_of_pressure_m(&self) -> f64 {
        centre_of_pressure(&self.mean_n_per_m, &self.positions_m)
    }

    /// The tilting moment's time mean, smallest and largest value, N m: the moment about
    /// the face centre of the slice loads, M = sum_j F_j (y_j - b/2), positive when the
    /// load sits towards y = b (y along the pinion's angular velocity). The slice loads act
    /// on the gear along the transverse line of action d (on the pinion along -d), so the
    /// gear is tilted by the moment M about the axis z x d (z along the pinion's angular
    /// velocity), the pinion by -M; the axial force's own moment (F_a at the pitch radii) is
    /// not in it.
    pub fn tilting_moment_nm(&self) -> (f64, f64, f64) {
        let w = trapezoid_weights(&self.time_s);
        let mean = w.iter().zip(&self.moment_nm).map(|(w, m)| w * m).sum();
        let (lo, hi) = self
            .moment_nm
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), m| {
                (a.min(*m), b.max(*m))
            });
        (mean, lo, hi)
    }
}
