//! Exact Fourier coefficients of the integrator's solution over one period.
//!
//! The steady-state solver accepts steps t_j -> t_j+1 and knows, at both ends of each,
//! the state and its derivative (for a velocity: the acceleration, evaluated with the
//! step's own contact set, so the limit from inside the step where a mesh event or a
//! contact switch makes the force jump). The cubic Hermite interpolant of those values
//! and derivatives is the solution between the points to the order of the solver (the
//! third-order SDIRK's dense output is of this order; Hairer & Wanner, Solving ODE II,
//! Sect. IV.6). Its Fourier coefficients
//!
//!   C_0 = (1/T) int_0^T x dt,  C_k = (2/T) int_0^T x(t) e^(-i w_k (t - t_o)) dt,
//!   w_k = 2 pi k / T,
//!
//! so that x(t) = Re sum_k C_k e^(i w_k (t - t_o)), are computed here exactly (to
//! round-off) for k = 0..=K, whatever the spacing of the points: no resampling. A linear
//! resampling onto a uniform grid (the former spectra) under-resolves what happens between
//! the grid points (the fast decay of the bearing dampers after each mesh event) and
//! takes 1.2 % off the run-out sidebands.
//!
//! Method (moments on a uniform cell grid, then FFTs). Cut [t_0, t_0 + T) into N cells of
//! width D = T / N (N a power of two, N >= 2 (K + 1)), centres tau_m. On cell m,
//! e^(-i w_k t) = e^(-i w_k tau_m) e^(-i w_k (t - tau_m)), and with s = (t - tau_m) / (D/2)
//! in [-1, 1] and theta_k = w_k D / 2 = pi k / N <= pi / 2,
//!
//!   int_cell x e^(-i w_k t) dt = e^(-i w_k tau_m) (D/2) sum_p (-i theta_k)^p / p! M_mp,
//!   M_mp = int_-1^1 x s^p ds,
//!
//! and sum_m e^(-i w_k tau_m) M_mp is one FFT over m per power p. The series is cut after
//! p = `POWERS` - 1: (pi/2)^23 / 23! = 1.3e-18 of the moment. Each M_mp is exact by
//! Gauss-Legendre quadrature on each piece of a step inside a cell (the integrand is a
//! polynomial of degree <= 3 + 22: 13 points), the cubic evaluated in its Hermite form
//! (no expansion about a distant centre, so no cancellation).

use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;
use std::sync::OnceLock;

/// Powers p = 0..POWERS-1 of the Taylor series of e^(-i theta s) (module docs).
const POWERS: usize = 23;
/// Gauss-Legendre points on each piece: exact for degree 2 * 13 - 1 = 25 >= 3 + 22.
const GAUSS_POINTS: usize = 13;

/// One period of a signal as the integrator's points: on step j from `t[j]` to `t[j + 1]`
/// (the last step to `t[0] + period`) the cubic Hermite interpolant of `x[j]`, `x[j + 1]`
/// (the last to `x[0]`) with slope `slope_start[j]` at its start and `slope_end[j]` at its
/// end.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HermitePeriod {
    /// Step start times, s.
    pub t: Vec<f64>,
    /// Signal values at the step starts.
    pub x: Vec<f64>,
    /// Slope dx/dt at each step's start (per s).
    pub slope_start: Vec<f64>,
    /// Slope dx/dt at each step's end (per s).
    pub slope_end: Vec<f64>,
    /// The period, s.
    pub period_s: f64,
}

impl HermitePeriod {
    /// The piecewise-linear interpolant of samples (the slopes are the chords): for a
    /// solution known only at its points (the quasi-static twin).
    pub fn linear(t: Vec<f64>, x: Vec<f64>, period_s: f64) -> Self {
        let n = t.len();
        let chord: Vec<f64> = (0..n)
            .map(|j| {
                let (t1, x1) = if j + 1 < n {
                    (t[j + 1], x[j + 1])
                } else {
                    (t[0] + period_s, x[0])
                };
                let h = t1 - t[j];
                if h > 0.0 {
                    (x1 - x[j]) / h
                } else {
                    0.0
                }
            })
            .collect();
        Self {
            t,
            x,
            slope_start: chord.clone(),
            slope_end: chord,
            period_s,
        }
    }

    /// The interpolant at `t` in `[t[0], t[0] + period)` (for tests and checks).
    pub fn at(&self, t: f64) -> f64 {
        let j = self.t.partition_point(|v| *v <= t).saturating_sub(1);
        let s = self.step(j);
        s.at(t - s.t0)
    }

    fn step(&self, j: usize) -> Step {
        let n = self.t.len();
        let (t1, x1) = if j + 1 < n {
            (self.t[j + 1], self.x[j + 1])
        } else {
            (self.t[0] + self.period_s, self.x[0])
        };
        Step {
            t0: self.t[j],
            h: t1 - self.t[j],
            x0: self.x[j],
            x1,
            d0: self.slope_start[j],
            d1: self.slope_end[j],
        }
    }

    /// C_0..=C_K (module docs) with phases referred to time `origin_s`.
    pub fn coefficients(&self, origin_s: f64, harmonics: usize) -> Vec<Complex64> {
        let n_pts = self.t.len();
        let period = self.period_s;
        if n_pts == 0 || period <= 0.0 {
            return vec![Complex64::new(0.0, 0.0); harmonics + 1];
        }
        let cells = (2 * (harmonics + 1)).next_power_of_two().max(16);
        let moments = self.moments(cells);
        let half = 0.5 * period / cells as f64;
        let mut planner = RealFftPlanner::<f64>::new();
        let fft = planner.plan_fft_forward(cells);
        let mut sums = vec![Complex64::new(0.0, 0.0); harmonics + 1];
        let mut spec = fft.make_output_vec();
        let factorial = factorials();
        let mut input = fft.make_input_vec();
        for p in 0..POWERS {
            for (v, cell) in input.iter_mut().zip(&moments) {
                *v = cell[p];
            }
            fft.process(&mut input, &mut spec)
                .expect("FFT buffers sized by the plan");
            for (k, sum) in sums.iter_mut().enumerate() {
                let theta = std::f64::consts::PI * k as f64 / cells as f64;
                // (-i theta)^p / p!
                let w = Complex64::new(0.0, -theta).powu(p as u32) / factorial[p];
                *sum += w * spec[k];
            }
        }
        let t0 = self.t[0];
        sums.iter()
            .enumerate()
            .map(|(k, s)| {
                let wk = 2.0 * std::f64::consts::PI * k as f64 / period;
                // Cell m is centred on t0 + (m + 1/2) D: the FFT's phase e^(-i w_k m D)
                // times e^(-i w_k (D/2 + t0 - origin)).
                let shift = Complex64::from_polar(1.0, -wk * (half + t0 - origin_s));
                let scale = if k == 0 { 1.0 } else { 2.0 } * half / period;
                s * shift * scale
            })
            .collect()
    }

    /// M_mp of every cell m (index m, then p; module docs): each cell's powers side by
    /// side, so a quadrature point adds to one cache line, not to 23 rows far apart
    /// (the sums and their order are the same either way).
    fn moments(&self, cells: usize) -> Vec<[f64; POWERS]> {
        let mut m = vec![[0.0; POWERS]; cells];
        let (nodes, weights) = gauss_legendre();
        let t0 = self.t[0];
        let width = self.period_s / cells as f64;
        let half = 0.5 * width;
        for j in 0..self.t.len() {
            let step = self.step(j);
            if step.h <= 0.0 {
                continue;
            }
            let end = step.t0 + step.h;
            let mut a = step.t0;
            while a < end {
                let mut c = (((a - t0) / width).floor().max(0.0) as usize).min(cells - 1);
                let mut boundary = t0 + (c + 1) as f64 * width;
                if boundary <= a && c + 1 < cells {
                    c += 1;
                    boundary = t0 + (c + 1) as f64 * width;
                }
                let b = if c + 1 == cells {
                    end
                } else {
                    end.min(boundary)
                };
                let centre = t0 + (c as f64 + 0.5) * width;
                // Gauss-Legendre on [a, b] in s = (t - centre) / half.
                let (sa, sb) = ((a - centre) / half, (b - centre) / half);
                let (mid, rad) = (0.5 * (sa + sb), 0.5 * (sb - sa));
                for (g, wg) in nodes.iter().zip(weights) {
                    let s = mid + rad * g;
                    let v = step.at(centre + half * s - step.t0) * wg * rad;
                    let mut pw = 1.0;
                    for moment in m[c].iter_mut() {
                        *moment += v * pw;
                        pw *= s;
                    }
                }
                a = b;
            }
        }
        m
    }
}

/// One step's cubic Hermite interpolant.
struct Step {
    t0: f64,
    h: f64,
    x0: f64,
    x1: f64,
    d0: f64,
    d1: f64,
}

impl Step {
    /// The cubic at `u` = t - t0 in [0, h] (Hermite basis).
    #[inline]
    fn at(&self, u: f64) -> f64 {
        let s = u / self.h;
        let s2 = s * s;
        let s3 = s2 * s;
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        self.x0 * h00 + self.h * self.d0 * h10 + self.x1 * h01 + self.h * self.d1 * h11
    }
}

fn factorials() -> [f64; POWERS] {
    let mut f = [1.0; POWERS];
    for p in 1..POWERS {
        f[p] = f[p - 1] * p as f64;
    }
    f
}

/// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from Chebyshev guesses;
/// Press et al., Numerical Recipes, 3rd ed., Sect. 4.6.1).
fn gauss_legendre() -> &'static ([f64; GAUSS_POINTS], [f64; GAUSS_POINTS]) {
    static RULE: OnceLock<([f64; GAUSS_POINTS], [f64; GAUSS_POINTS])> = OnceLock::new();
    RULE.get_or_init(|| {
        let n = GAUSS_POINTS;
        let mut x = [0.0; GAUSS_POINTS];
        let mut w = [0.0; GAUSS_POINTS];
        for i in 0..n {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                // P_n(z) and P_n'(z) by the three-term recurrence.
                let (mut p0, mut p1) = (1.0, z);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                let dz = p1 / dp;
                z -= dz;
                if dz.abs() < 1e-16 {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
        (x, w)
    })
}

#[cfg(test)]
#[path = "tests_fourier.rs"]
mod tests;
