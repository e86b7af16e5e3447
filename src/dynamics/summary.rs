//! Headline numbers of a response (the quantities of the paper's section 4.1).

use super::fourier::HermitePeriod;
use super::model::dof;
use super::response::DynamicResponse;
use super::spectrum::{amplitude_spectrum, mesh_harmonics, time_rms, Spectrum};
use serde::{Deserialize, Serialize};

/// Scalar results of one steady-state (or quasi-static) evaluation, SI units.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct ResponseSummary {
    /// Largest dynamic transmission error over the window, m.
    pub dte_max_m: f64,
    /// Smallest dynamic transmission error over the window, m.
    pub dte_min_m: f64,
    /// Time mean of the dynamic transmission error, m.
    pub dte_mean_m: f64,
    /// Time mean of the mesh force, N.
    pub mesh_force_mean_n: f64,
    /// Largest mesh force over the window, N.
    pub mesh_force_max_n: f64,
    /// Smallest mesh force over the window, N.
    pub mesh_force_min_n: f64,
    /// max / mean mesh force.
    pub dynamic_factor: f64,
    /// RMS over the window of the pinion's lateral velocity dy_p/dt, m/s.
    pub velocity_y_pinion_rms_m_per_s: f64,
    /// Amplitudes of the first four mesh harmonics of dy_p/dt, m/s: the exact Fourier
    /// coefficients of the solution over the window (`super::fourier`).
    pub velocity_y_pinion_harmonics_m_per_s: [f64; 4],
    /// Amplitude of the first mesh harmonic of the DTE, m (what a pair of encoders gives;
    /// absent in checkpoints written before it existed, hence the serde default).
    #[serde(default)]
    pub dte_harmonic1_m: f64,
    /// Largest friction coefficient along the path of contact.
    pub friction_coefficient_max: f64,
    /// Mean friction coefficient over the path samples that carry load.
    pub friction_coefficient_mean_in_contact: f64,
    /// Largest magnitude of a pair's friction force along the path of contact, N.
    pub friction_force_max_n: f64,
}

fn max(x: &[f64]) -> f64 {
    x.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v))
}

fn min(x: &[f64]) -> f64 {
    x.iter().fold(f64::INFINITY, |m, v| m.min(*v))
}

/// Velocity of coordinate `i` (the assembly's numbering; `model::dof` for the pair) over the evaluated window as the solver's
/// solution: the cubic Hermite interpolant of the velocities and the steps'
/// accelerations (`super::fourier`); the chords of the samples for a quasi-static
/// response, which has no steps.
pub fn velocity_signal(r: &DynamicResponse, i: usize) -> HermitePeriod {
    let s = &r.signals;
    let window = r.mesh_period_s * evaluated_periods(r) as f64;
    let x: Vec<f64> = s.velocity.iter().map(|v| v[i]).collect();
    let [start, end] = &s.step_acceleration;
    if start.len() != x.len() || end.len() != x.len() {
        return HermitePeriod::linear(s.time_s.clone(), x, window);
    }
    HermitePeriod {
        t: s.time_s.clone(),
        x,
        slope_start: start.iter().map(|a| a[i]).collect(),
        slope_end: end.iter().map(|a| a[i]).collect(),
        period_s: window,
    }
}

/// The DTE of mesh `m` over the evaluated window as the solver's solution (its rate is
/// continuous: the same slope at both ends of a step); the chords when quasi-static.
pub fn dte_signal(r: &DynamicResponse, m: usize) -> HermitePeriod {
    let s = &r.signals;
    let ms = &s.meshes[m];
    let window = r.mesh_period_s * evaluated_periods(r) as f64;
    if ms.dte_rate_m_per_s.len() != ms.dte_m.len() {
        return HermitePeriod::linear(s.time_s.clone(), ms.dte_m.clone(), window);
    }
    HermitePeriod {
        t: s.time_s.clone(),
        x: ms.dte_m.clone(),
        slope_start: ms.dte_rate_m_per_s.clone(),
        slope_end: ms.dte_rate_m_per_s.clone(),
        period_s: window,
    }
}

/// Spectrum of the pinion's y velocity over the evaluated window (exact lines).
pub fn velocity_y_spectrum(r: &DynamicResponse) -> Spectrum {
    amplitude_spectrum(&velocity_signal(r, dof::YP), evaluated_periods(r))
}

/// Whole mesh periods in the evaluated window.
pub fn evaluated_periods(r: &DynamicResponse) -> usize {
    let s = &r.signals;
    if s.time_s.len() < 2 || r.mesh_period_s <= 0.0 {
        return 1;
    }
    // Samples start at a period boundary and stop one node short of the last one.
    let span = s.time_s[s.time_s.len() - 1] - s.time_s[0];
    ((span / r.mesh_period_s).ceil() as usize).max(1)
}

impl ResponseSummary {
    /// The summary of the single pair (of a train's first mesh, its harmonics those of
    /// the base period: use [`ResponseSummary::of_mesh`]).
    pub fn of(r: &DynamicResponse) -> Self {
        Self::of_mesh(r, 0, r.mesh_period_s, dof::YP)
    }

    /// The summary of mesh `m` of a response, its harmonics those of its mesh period
    /// `mesh_period_s` (s), the velocity that of coordinate `pinion_y` (its pinion's y).
    pub fn of_mesh(r: &DynamicResponse, m: usize, mesh_period_s: f64, pinion_y: usize) -> Self {
        let s = &r.signals;
        if s.time_s.is_empty() {
            return Self::default();
        }
        let window = r.mesh_period_s * evaluated_periods(r) as f64;
        // Whole mesh periods of this mesh in the window (the base period holds a whole
        // number of them).
        let periods = ((window / mesh_period_s).round() as usize).max(1);
        let mean_f = r.meshes[m].mean_mesh_force_n;
        let vy: Vec<f64> = s.velocity.iter().map(|v| v[pinion_y]).collect();
        let has_velocity = vy.iter().any(|v| *v != 0.0);
        let mut harm = [0.0; 4];
        if has_velocity {
            let lines = mesh_harmonics(&velocity_signal(r, pinion_y), periods, 4);
            for (a, c) in harm.iter_mut().zip(&lines) {
                *a = c.norm();
            }
        }
        let dte_h1 = mesh_harmonics(&dte_signal(r, m), periods, 1)[0].norm();
        let mu_all: Vec<f64> = r.meshes[m]
            .path
            .iter()
            .map(|p| p.friction_coefficient)
            .collect();
        let mu_in: Vec<f64> = r.meshes[m]
            .path
            .iter()
            .filter(|p| p.load_n > 0.0)
            .map(|p| p.friction_coefficient)
            .collect();
        let fr: Vec<f64> = r.meshes[m]
            .path
            .iter()
            .map(|p| p.friction_n.abs())
            .collect();
        let f_max = max(&s.meshes[m].mesh_force_n);
        Self {
            dte_max_m: max(&s.meshes[m].dte_m),
            dte_min_m: min(&s.meshes[m].dte_m),
            dte_mean_m: r.meshes[m].mean_dte_m,
            mesh_force_mean_n: mean_f,
            mesh_force_max_n: f_max,
            mesh_force_min_n: min(&s.meshes[m].mesh_force_n),
            dynamic_factor: if mean_f > 0.0 { f_max / mean_f } else { 0.0 },
            velocity_y_pinion_rms_m_per_s: if has_velocity {
                time_rms(&s.time_s, &vy, window)
            } else {
                0.0
            },
            velocity_y_pinion_harmonics_m_per_s: harm,
            dte_harmonic1_m: dte_h1,
            friction_coefficient_max: if mu_all.is_empty() { 0.0 } else { max(&mu_all) },
            friction_coefficient_mean_in_contact: if mu_in.is_empty() {
                0.0
            } else {
                mu_in.iter().sum::<f64>() / mu_in.len() as f64
            },
            friction_force_max_n: if fr.is_empty() { 0.0 } else { max(&fr) },
        }
    }
}
