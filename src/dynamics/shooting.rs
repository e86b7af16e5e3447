//! The periodic orbit as a fixed point of the one-period map, found by quasi-Newton
//! shooting (Keller's shooting method for periodic boundary value problems; Seydel,
//! *Practical Bifurcation and Stability Analysis*, 3rd ed., Sect. 7.1-7.3).
//!
//! The mesh-periodic steady state y* satisfies P(y*) = y*, with P the map of the state
//! over one mesh period (the integration of [`super::period`]). Newton's method on
//! G(z) = P(z) - z needs the monodromy matrix M = dP/dz; here it starts from the
//! monodromy of the time-invariant average of the linear model, exp(A_mean T), A_mean
//! the state matrix at the mean loaded mesh stiffness without friction
//! ([`GearSystem::mean_state_matrix_at`], [`super::modal::mean_mesh_stiffnesses`]: with
//! corner contact the corners the load closes count, 6.3 % above the table mean on the
//! paper's case, and a warm start after a wear update then converges as fast as on the
//! nominal path). Its slow eigenvalues (the overdamped bearing and
//! coupling modes, ~ -1250 1/s, and the damped mesh pole) are what makes plain period-by-
//! period integration slow, e^(-1250 T) = 0.8 per period at 300 Hz input; the parametric
//! (time-varying stiffness) and friction parts of M are what this start lacks, and good
//! Broyden updates (Dennis & Schnabel, *Numerical Methods for Unconstrained Optimization
//! and Nonlinear Equations*, Sect. 8.3) learn them from the periods integrated. Each
//! iteration costs one period. When contact loss makes P non-smooth and a quasi-Newton
//! step fails to lower the residual, the iteration falls back to plain periods.
//!
//! Coordinates. A speed imposed at one end holds that coordinate and its velocity: they
//! are not unknowns. With the motor-slip boundary nothing is held and the drivetrain's
//! rigid rotation r (`Assembly::rigid_rotation`; for the single pair (phi_m, phi_p, phi_g,
//! phi_b) = (1, 1, r_pb/r_gb, r_pb/r_gb)) is a symmetry (every force depends on angle
//! differences); the slip's speed deficit makes the angles drift along r by a constant
//! amount per period. So the unknowns are the state with its r component removed (the
//! input's angle set to 0 by a rigid shift), and the drift is not part of the residual.

use super::assembly::Dof;
use super::model::{GearSystem, State};
use nalgebra::{DMatrix, DVector, SMatrix};

/// The unknowns of the periodic-orbit problem (see module docs).
#[derive(Debug, Clone)]
pub struct Reduction {
    /// State components that are unknowns.
    idx: Vec<usize>,
    /// The rigid rotation (in the state), when it is a free motion (motor slip).
    rigid: Option<State>,
    /// The input's angle, which the rigid shift sets to 0.
    anchor: usize,
}

impl Reduction {
    /// The reduction of `sys`'s state: without the coordinate held by an imposed speed
    /// (and its velocity), or, when the rigid rotation is free (motor slip), without the
    /// input's angle.
    pub fn new(sys: &GearSystem) -> Self {
        let asm = sys.assembly();
        let (n, n2) = (sys.dofs(), sys.states());
        let anchor = asm
            .index(asm.elements.drive.input, Dof::Rotation)
            .expect("every body rotates");
        match asm.held() {
            Some(held) => Self {
                idx: (0..n2).filter(|i| *i != held && *i != n + held).collect(),
                rigid: None,
                anchor,
            },
            None => {
                let mut r = State::zeros(n2);
                r.rows_mut(0, n).copy_from(&asm.rigid_rotation());
                Self {
                    idx: (0..n2).filter(|i| *i != anchor).collect(),
                    rigid: Some(r),
                    anchor,
                }
            }
        }
    }

    /// Number of unknowns.
    pub fn len(&self) -> usize {
        self.idx.len()
    }

    /// Whether there are no unknowns.
    pub fn is_empty(&self) -> bool {
        self.idx.is_empty()
    }

    /// The unknowns of a state (rigid rotation removed).
    pub fn reduce(&self, y: &[f64]) -> DVector<f64> {
        let at = |i: usize| match &self.rigid {
            Some(r) => y[i] - r[i] * y[self.anchor],
            None => y[i],
        };
        DVector::from_iterator(self.idx.len(), self.idx.iter().map(|i| at(*i)))
    }

    /// The state with unknowns `z` and the held coordinates of `template`.
    pub fn embed(&self, z: &DVector<f64>, template: &[f64]) -> State {
        let mut y = State::from_column_slice(template);
        if self.rigid.is_some() {
            y[self.anchor] = 0.0;
        }
        for (k, i) in self.idx.iter().enumerate() {
            y[*i] = z[k];
        }
        y
    }

    /// The displacements of the rigid rotation that carries the input's angle of `from`
    /// to that of `to` (state slices), when the rigid rotation is a free motion (motor
    /// slip): what two trajectories equal up to it differ by for ever. None otherwise.
    pub fn rigid_offset(&self, from: &[f64], to: &[f64]) -> Option<Vec<f64>> {
        let r = self.rigid.as_ref()?;
        let d = to[self.anchor] - from[self.anchor];
        Some((0..r.len() / 2).map(|i| r[i] * d).collect())
    }

    /// `scales` restricted to the unknowns.
    pub fn scales(&self, scales: &State) -> DVector<f64> {
        DVector::from_iterator(self.idx.len(), self.idx.iter().map(|i| scales[*i]))
    }

    /// The monodromy `m` (states x states) seen in the unknowns: R m E, E embedding a
    /// change of the unknowns into the state, R removing the rigid rotation and the held
    /// entries.
    pub fn reduce_matrix(&self, m: &DMatrix<f64>) -> DMatrix<f64> {
        let n = self.idx.len();
        DMatrix::from_fn(n, n, |a, b| {
            let (i, j) = (self.idx[a], self.idx[b]);
            match &self.rigid {
                Some(r) => m[(i, j)] - r[i] * m[(self.anchor, j)],
                None => m[(i, j)],
            }
        })
    }
}

/// exp(A t) of a state matrix. The single pair's 16 x 16 goes through nalgebra's
/// fixed-size product, as it always has (the dynamic one multiplies in another order:
/// other bits).
pub fn state_matrix_exp(a: &DMatrix<f64>, t: f64) -> DMatrix<f64> {
    if a.nrows() == 16 {
        let s = SMatrix::<f64, 16, 16>::from_fn(|i, j| a[(i, j)]) * t;
        let e = s.exp();
        return DMatrix::from_fn(16, 16, |i, j| e[(i, j)]);
    }
    (a * t).exp()
}

/// Largest component of `v` relative to `scales`.
pub fn scaled_max(v: &DVector<f64>, scales: &DVector<f64>) -> f64 {
    v.iter()
        .zip(scales.iter())
        .fold(0.0_f64, |m, (x, s)| m.max((x / s).abs()))
}

/// Quasi-Newton steps that raised the residual before the iteration gives up on them.
const MAX_FAILED_STEPS: usize = 6;

/// Quasi-Newton iteration for P(z) = z (see module docs).
pub struct Shooting {
    /// Approximate inverse of dG/dz = M - I.
    h_inv: DMatrix<f64>,
    /// The previous start and its residual P(z) - z.
    last: Option<(DVector<f64>, DVector<f64>)>,
    /// The start with the smallest residual so far, and P of it.
    best: Option<(DVector<f64>, f64)>,
    /// Plain periods only, after quasi-Newton steps failed to lower the residual
    /// `MAX_FAILED_STEPS` times.
    pub plain: bool,
    failed: usize,
    /// Largest quasi-Newton step, relative to the state scales (a trust region: halved
    /// after a failed step, doubled after a good one).
    radius: f64,
    scales: DVector<f64>,
}

impl Shooting {
    /// Starts from the monodromy exp(A_mean T) of the averaged linear model over one
    /// period of `period_s` seconds; `scales` are the state scales (see
    /// [`super::state_scales::state_scales`]).
    pub fn new(sys: &GearSystem, red: &Reduction, period_s: f64, scales: &State) -> Self {
        let k = super::modal::mean_mesh_stiffnesses(sys);
        let m = state_matrix_exp(&sys.mean_state_matrix_at(&k), period_s);
        Self::from_monodromy(&red.reduce_matrix(&m), red.scales(scales))
    }

    /// Starts from the approximate monodromy `m` of the unknowns themselves (a model
    /// whose every state is an unknown: no held coordinate, no rigid rotation), `scales`
    /// their scales.
    pub fn from_monodromy(m: &DMatrix<f64>, scales: DVector<f64>) -> Self {
        let n = m.nrows();
        let g = m - DMatrix::identity(n, n);
        // The damped averaged model has no eigenvalue 1 once the held coordinates and
        // the rigid rotation are removed; fall back to plain periods should it be
        // singular to working precision all the same.
        let (h_inv, plain) = match g.try_inverse() {
            Some(inv) if inv.iter().all(|v| v.is_finite()) => (inv, false),
            _ => (DMatrix::zeros(n, n), true),
        };
        Self {
            h_inv,
            last: None,
            best: None,
            plain,
            failed: 0,
            radius: 1.0,
            scales,
        }
    }

    /// Given the unknowns `z` at the start of a period and `f` = P(z) at its end, the
    /// next start and the estimated distance of `z` from the fixed point, relative to
    /// the state scales.
    ///
    /// Every pair of periods updates the inverse Jacobian (good Broyden:
    /// H += (s - H y) s^T H / (s^T H y), s the change of z, y that of the residual).
    /// A quasi-Newton step is limited to a trust region; one that did not lower the
    /// residual below the best so far is undone: the next period starts from P of the
    /// best start (a plain period from there, which contracts).
    pub fn next(&mut self, z: &DVector<f64>, f: &DVector<f64>) -> (DVector<f64>, f64) {
        let r = f - z;
        let res = scaled_max(&r, &self.scales);
        let mut rate = 0.5;
        if let Some((z0, r0)) = &self.last {
            rate = res / scaled_max(r0, &self.scales);
            let s = z - z0;
            let y = &r - r0;
            let hy = &self.h_inv * &y;
            let denom = s.dot(&hy);
            if denom.abs() > 1e-12 * s.norm() * hy.norm() {
                let sth = s.transpose() * &self.h_inv;
                self.h_inv += (&s - &hy) * sth / denom;
            }
        }
        self.last = Some((z.clone(), r.clone()));
        // The change over one period, with the contraction seen, bounds the distance.
        let plain_dist = if rate < 1.0 {
            res / (1.0 - rate)
        } else {
            f64::INFINITY
        };
        let improved = self.best.as_ref().is_none_or(|(_, b)| res < *b);
        if improved {
            self.best = Some((f.clone(), res));
            self.radius = (2.0 * self.radius).min(1e3);
        } else if !self.plain {
            self.failed += 1;
            self.plain = self.failed >= MAX_FAILED_STEPS;
            self.radius *= 0.25;
            // Undo: a plain period from the best start (its P is known).
            let from_best = self.best.as_ref().map_or(f.clone(), |(fb, _)| fb.clone());
            self.best = None;
            return (from_best, plain_dist);
        }
        if self.plain {
            return (f.clone(), plain_dist);
        }
        let mut step = -(&self.h_inv * &r);
        let dist = scaled_max(&step, &self.scales);
        if dist > self.radius {
            step *= self.radius / dist;
        }
        (z + step, dist)
    }
}
