//! Natural frequencies and mode shapes of the model linearised at the mean loaded mesh
//! stiffness ([`mean_mesh_stiffnesses`]): K phi = omega^2 M phi on the free coordinates (an imposed speed removes
//! its coordinate), with K = K_bearings+couplings + k_mean g g^T (g = d delta/dq).
//! Solved as the symmetric problem M^-1/2 K M^-1/2 (M is diagonal).

use super::model::GearSystem;
use nalgebra::{DMatrix, SymmetricEigen};

/// Undamped modes, ascending in frequency.
#[derive(Debug, Clone, Default)]
pub struct Modes {
    /// Natural frequencies, Hz, ascending.
    pub frequency_hz: Vec<f64>,
    /// Mass-normalised shapes in the assembled coordinates (0 on an imposed coordinate).
    pub shapes: Vec<Vec<f64>>,
}

/// Each mesh's mean stiffness under the load, N/m: the table mean on the nominal path,
/// with corner contact the mean of the pairs that carry load in the quasi-static
/// equilibrium, corners included (`quasi_static::loaded_mean_stiffnesses`): the modes are
/// those of the loaded gearbox.
pub fn mean_mesh_stiffnesses(sys: &GearSystem) -> Vec<f64> {
    super::quasi_static::loaded_mean_stiffnesses(sys)
}

/// Linearised mass (diagonal) and stiffness matrices of the free coordinates, and the
/// indices of those coordinates: K = K_lin + sum_m k_mean,m g_m g_m^T.
pub fn linearised_matrices(sys: &GearSystem) -> (Vec<f64>, DMatrix<f64>, Vec<usize>) {
    let (k_lin, _, inv_mass) = sys.linear_parts();
    let k_mean = mean_mesh_stiffnesses(sys);
    let grads: Vec<_> = (0..sys.meshes.len())
        .map(|m| sys.mesh_gradient(m))
        .collect();
    let free: Vec<usize> = (0..sys.dofs()).filter(|i| inv_mass[*i] > 0.0).collect();
    let n = free.len();
    let mut k = DMatrix::zeros(n, n);
    for (a, &i) in free.iter().enumerate() {
        for (b, &j) in free.iter().enumerate() {
            let mut v = k_lin[(i, j)];
            for (g, km) in grads.iter().zip(&k_mean) {
                v += km * g[i] * g[j];
            }
            k[(a, b)] = v;
        }
    }
    let m = free.iter().map(|&i| 1.0 / inv_mass[i]).collect();
    (m, k, free)
}

/// The undamped modes of the linearised system (each mesh at its mean loaded stiffness,
/// [`linearised_matrices`]), from the mass-normalised symmetric eigenproblem.
pub fn modes(sys: &GearSystem) -> Modes {
    let (m, k, free) = linearised_matrices(sys);
    let n = m.len();
    let s: Vec<f64> = m.iter().map(|x| 1.0 / x.sqrt()).collect();
    let a = DMatrix::from_fn(n, n, |i, j| s[i] * k[(i, j)] * s[j]);
    let eig = SymmetricEigen::new(a);
    let mut idx: Vec<usize> = (0..n).collect();
    idx.sort_by(|x, y| eig.eigenvalues[*x].total_cmp(&eig.eigenvalues[*y]));
    let mut out = Modes::default();
    for i in idx {
        let lam = eig.eigenvalues[i].max(0.0);
        out.frequency_hz
            .push(lam.sqrt() / (2.0 * std::f64::consts::PI));
        let mut shape = vec![0.0; sys.dofs()];
        for (a, &dof) in free.iter().enumerate() {
            shape[dof] = eig.eigenvectors[(a, i)] * s[a];
        }
        out.shapes.push(shape);
    }
    out
}

/// Slowest decay rate of the averaged linear model, 1/s: the smallest -Re(lambda) over
/// its eigenvalues, leaving out the zero ones of a held coordinate or of the motor-slip
/// drivetrain's free rotation.
pub fn slowest_decay_rate(sys: &GearSystem) -> f64 {
    let a = sys.mean_state_matrix();
    // The single pair's 16 x 16 through the fixed-size solver, as it always has.
    let eig: Vec<nalgebra::Complex<f64>> = if a.nrows() == 16 {
        let s = nalgebra::SMatrix::<f64, 16, 16>::from_fn(|i, j| a[(i, j)]);
        s.complex_eigenvalues().iter().copied().collect()
    } else {
        a.complex_eigenvalues().iter().copied().collect()
    };
    let scale = eig.iter().fold(0.0_f64, |m, l| m.max(l.norm()));
    eig.iter()
        .map(|l| -l.re)
        .filter(|d| *d > 1e-9 * scale)
        .fold(f64::INFINITY, f64::min)
}

/// Mesh periods of run-in for an excitation of `periods` mesh periods of `mesh_period_s`
/// (see the module docs), at least 2 and at most `periods` (so 1 when P = 1: `Ord::clamp`
/// would panic there, its lower bound above its upper).
pub fn run_in_periods(
    sys: &GearSystem,
    mesh_period_s: f64,
    tolerance: f64,
    periods: usize,
) -> usize {
    let sigma = slowest_decay_rate(sys);
    if !(sigma.is_finite() && sigma > 0.0) {
        return periods;
    }
    // The orbit of cycle 0 differs from the true one by up to the state scales (1), and
    // the time-varying stiffness makes the decay somewhat uneven: 20 % margin.
    let w = 1.2 * (1.0 / tolerance).ln() / (sigma * mesh_period_s);
    (w.ceil() as usize).max(2).min(periods)
}
