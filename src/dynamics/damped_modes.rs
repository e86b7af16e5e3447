//! Damped (complex) modes of the model linearised at the mean mesh stiffness.
//!
//! M q'' + C q' + K q = 0 on the free coordinates (an imposed speed removes its
//! coordinate), with K = K_bearings+couplings + k_mean g g^T and
//! C = C_bearings+couplings (+ c_slip on the motor for `motor_slip`) + c_m g g^T
//! (g = d delta / dq, c_m the mesh damping). The poles are the eigenvalues lambda of the
//! first-order state matrix A = [[0, I], [-M^-1 K, -M^-1 C]] (Schur form, in
//! mass-normalised coordinates u = M^1/2 q so that the entries are balanced), each
//! refined by Newton's method on det D(lambda) = 0, D(lambda) = lambda^2 M + lambda C + K
//! (the quadratic pencil); each mode shape phi is the null vector of D(lambda) (its right
//! singular vector of the smallest singular value).
//!
//! Reported per pole (one of each complex-conjugate pair, Im lambda > 0):
//! - damped frequency |Im lambda| / 2 pi, Hz, and pole magnitude |lambda| / 2 pi, Hz (the
//!   undamped natural frequency of a one-degree-of-freedom mode with this pole);
//! - damping ratio zeta = -Re lambda / |lambda| (1 for a real, overdamped pole);
//! - mesh strain-energy share e_mesh = k_mean |g^T phi|^2 / (phi^H K phi) (summed over a
//!   train's meshes): the share of the
//!   mesh spring in the strain energy of the mode. For a complex mode the real motion is
//!   q(t) = Re(phi e^(lambda t)); over one cycle of its oscillation (envelope held), the
//!   mean of (Re(a e^(i w t)))^2 is |a|^2 / 2 for every component, so the cycle-averaged
//!   strain energies are (1/4) phi^H K phi in all springs and (1/4) k_mean |g^T phi|^2 in
//!   the mesh spring. The ratio does not depend on the (complex) scale of phi; for a real
//!   pole phi is real and the ratio is the instantaneous one. In the undamped limit it is
//!   the classical modal strain-energy share of a normal mode.
//!
//! The neutral rotation of a drivetrain that no spring holds (`motor_slip`: K r = 0 for
//! the rigid rotation r, lambda = 0) has no frequency, damping or strain energy and is
//! left out; its velocity decays through the slip damper as a real pole, which is kept.

use super::modal::{linearised_matrices, mean_mesh_stiffnesses};
use super::model::GearSystem;
use nalgebra::{Complex, DMatrix};
use serde::Serialize;
use std::f64::consts::PI;

/// How a pole moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PoleKind {
    /// Complex pole pair: a decaying oscillation.
    Oscillatory,
    /// Real negative pole: a decay without oscillation.
    Overdamped,
}

/// One damped mode (a pole with Im lambda >= 0).
#[derive(Debug, Clone, Serialize)]
pub struct DampedMode {
    /// Real part of lambda, 1/s (negative: decaying).
    pub real_per_s: f64,
    /// Imaginary part of lambda, rad/s (>= 0).
    pub imag_rad_per_s: f64,
    /// |Im lambda| / 2 pi, Hz (0 for an overdamped pole).
    pub damped_frequency_hz: f64,
    /// |lambda| / 2 pi, Hz.
    pub pole_magnitude_hz: f64,
    /// -Re lambda / |lambda|.
    pub damping_ratio: f64,
    /// Share of the mode's strain energy in the mesh spring (0..1).
    pub mesh_energy_share: f64,
    /// Oscillatory or overdamped.
    pub kind: PoleKind,
    /// Mode shape in the assembled coordinates (0 on an imposed coordinate), scaled so
    /// that its largest component (in mass-normalised coordinates) is real and
    /// 1 / sqrt(mass).
    #[serde(skip)]
    pub shape: Vec<Complex<f64>>,
}

/// Smallest mesh-energy share of a "mesh pole".
///
/// The mesh spring is the stiffest element of the drivetrain; a mode in which it stores
/// a tenth of the strain energy or more is driven by the mesh excitation (transmission
/// error, stiffness variation), one in which it stores less is a bearing or shaft mode the
/// mesh hardly excites. Under each speed boundary the default case has one oscillatory
/// pole far above this (0.91-0.97 of the energy, docs/MODEL.md) and the others far below
/// (< 0.06).
pub const MESH_POLE_MIN_SHARE: f64 = 0.1;

/// All damped modes, sorted by pole magnitude.
#[derive(Debug, Clone, Default, Serialize)]
pub struct DampedModes {
    /// The modes, sorted by pole magnitude.
    pub modes: Vec<DampedMode>,
}

impl DampedModes {
    /// The oscillatory poles whose mesh-energy share is at least [`MESH_POLE_MIN_SHARE`]:
    /// the resonances of the mesh.
    pub fn mesh_poles(&self) -> Vec<&DampedMode> {
        self.modes
            .iter()
            .filter(|m| {
                m.kind == PoleKind::Oscillatory && m.mesh_energy_share >= MESH_POLE_MIN_SHARE
            })
            .collect()
    }
}

/// Linearised damping matrix of the free coordinates `free` (as returned by
/// [`linearised_matrices`]): C_lin + sum_m c_m g_m g_m^T, N s/m, N m s/rad and mixed.
pub fn linearised_damping(sys: &GearSystem, free: &[usize]) -> DMatrix<f64> {
    let (_, c_lin, _) = sys.linear_parts();
    let grads: Vec<_> = (0..sys.meshes.len())
        .map(|m| sys.mesh_gradient(m))
        .collect();
    DMatrix::from_fn(free.len(), free.len(), |a, b| {
        let (i, j) = (free[a], free[b]);
        let mut v = c_lin[(i, j)];
        for (g, mesh) in grads.iter().zip(&sys.meshes) {
            v += mesh.mesh_damping_n_s_per_m * g[i] * g[j];
        }
        v
    })
}

/// Damped modes of `sys` linearised at the mean mesh stiffness.
pub fn damped_modes(sys: &GearSystem) -> DampedModes {
    let (mass, k, free) = linearised_matrices(sys);
    let c = linearised_damping(sys, &free);
    let n = mass.len();
    if n == 0 {
        return DampedModes::default();
    }
    // Mass-normalised coordinates u = M^1/2 q: K~ = S K S, C~ = S C S, S = M^-1/2.
    let s: Vec<f64> = mass.iter().map(|m| 1.0 / m.sqrt()).collect();
    let kt = DMatrix::from_fn(n, n, |i, j| s[i] * k[(i, j)] * s[j]);
    let ct = DMatrix::from_fn(n, n, |i, j| s[i] * c[(i, j)] * s[j]);
    // First-order form in (u, v / w), w = |K~|^1/2 (Frobenius): a similarity transform
    // of [[0, I], [-K~, -C~]] that balances its blocks (w ~ 4e5 1/s against |K~| ~ 2e11
    // 1/s^2), so the Schur form's error eps |A| is ~1e-10 of the fastest pole instead of
    // ~1e-5 (the unbalanced form lost 2.6e-5 on the 70 kHz pole, beyond `refine`'s reach).
    let w = kt.norm().sqrt().max(f64::MIN_POSITIVE);
    let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = w;
        for j in 0..n {
            a[(n + i, j)] = -kt[(i, j)] / w;
            a[(n + i, n + j)] = -ct[(i, j)];
        }
    }
    let eig = a.complex_eigenvalues();
    let grads: Vec<_> = (0..sys.meshes.len())
        .map(|m| sys.mesh_gradient(m))
        .collect();
    let k_mean = mean_mesh_stiffnesses(sys);
    let mut out = Vec::new();
    for lam in eig.iter().copied() {
        if lam.im < 0.0 {
            continue;
        }
        let lam = refine(&kt, &ct, lam);
        let mag = lam.norm();
        // A real pole has Im exactly 0 from a 1x1 Schur block, or ~1e-12 |lambda| from a
        // 2x2 block with two real roots.
        let oscillatory = lam.im > 1e-9 * mag;
        let phi_u = null_vector(&kt, &ct, lam);
        if is_rigid_rotation(&kt, &phi_u) {
            continue;
        }
        let mut shape = vec![Complex::new(0.0, 0.0); sys.dofs()];
        for (idx, &dof) in free.iter().enumerate() {
            shape[dof] = phi_u[idx] * s[idx];
        }
        // Strain energy of the mesh springs, sum over meshes of k_m |g_m^T phi|^2.
        let mesh_energy: f64 = grads
            .iter()
            .zip(&k_mean)
            .map(|(g, km)| {
                let g_phi: Complex<f64> = free.iter().map(|&d| shape[d] * g[d]).sum();
                km * g_phi.norm_sqr()
            })
            .sum();
        let mut phk = 0.0;
        for (a_i, &i) in free.iter().enumerate() {
            for (b_i, &j) in free.iter().enumerate() {
                phk += (shape[i].conj() * shape[j]).re * k[(a_i, b_i)];
            }
        }
        let share = if phk > 0.0 {
            (mesh_energy / phk).clamp(0.0, 1.0)
        } else {
            0.0
        };
        out.push(DampedMode {
            real_per_s: lam.re,
            imag_rad_per_s: if oscillatory { lam.im } else { 0.0 },
            damped_frequency_hz: if oscillatory {
                lam.im / (2.0 * PI)
            } else {
                0.0
            },
            pole_magnitude_hz: mag / (2.0 * PI),
            damping_ratio: (-lam.re / mag).clamp(-1.0, 1.0),
            mesh_energy_share: share,
            kind: if oscillatory {
                PoleKind::Oscillatory
            } else {
                PoleKind::Overdamped
            },
            shape,
        });
    }
    out.sort_by(|x, y| x.pole_magnitude_hz.total_cmp(&y.pole_magnitude_hz));
    DampedModes { modes: out }
}

/// lambda^2 I + lambda C~ + K~ (`derivative`: its derivative 2 lambda I + C~).
fn pencil(
    kt: &DMatrix<f64>,
    ct: &DMatrix<f64>,
    lam: Complex<f64>,
    derivative: bool,
) -> DMatrix<Complex<f64>> {
    let n = kt.nrows();
    DMatrix::from_fn(n, n, |i, j| {
        let id = if i == j { 1.0 } else { 0.0 };
        if derivative {
            lam * (2.0 * id) + ct[(i, j)]
        } else {
            lam * lam * id + lam * ct[(i, j)] + Complex::new(kt[(i, j)], 0.0)
        }
    })
}

/// Newton's method on det D(lambda) = 0 from a Schur eigenvalue: lambda -= 1 / tr(D^-1 D').
///
/// Why: the state matrix's norm (~1e8 1/s, from the stiffest bearing and mesh poles) sets
/// the Schur form's absolute error, eps |A|; the slow poles (~1e3 1/s) sit in clusters
/// (bearings and couplings with equal k / c) whose condition numbers reach ~1e5, so they
/// come out to only ~1e-6 relative. The pencil evaluated at the pole has the pole's own
/// scale, and two or three Newton steps bring its backward error to round-off. A step
/// larger than 1e-5 |lambda| would be a jump towards a neighbouring pole, not a
/// correction: the iteration then stops where it is.
fn refine(kt: &DMatrix<f64>, ct: &DMatrix<f64>, lam: Complex<f64>) -> Complex<f64> {
    let n = kt.nrows();
    let real = lam.im == 0.0;
    let mut l = lam;
    for _ in 0..4 {
        let Some(x) = pencil(kt, ct, l, false)
            .lu()
            .solve(&pencil(kt, ct, l, true))
        else {
            break; // exactly singular: l is a pole to round-off
        };
        let tr: Complex<f64> = (0..n).map(|i| x[(i, i)]).sum();
        let step = tr.inv();
        if !(step.re.is_finite() && step.im.is_finite()) || step.norm() > 1e-5 * l.norm() {
            break;
        }
        l -= step;
        if real {
            l.im = 0.0;
        }
        if step.norm() <= 4.0 * f64::EPSILON * l.norm() {
            break;
        }
    }
    l
}

/// Whether the mass-normalised shape `phi` stores no strain energy: its stiffness Rayleigh
/// quotient phi^H K~ phi / phi^H phi is below 1e-12 of |K~| (Frobenius). Only the rigid
/// rotation does that (round-off leaves ~1e-17 there, and the rotation's zero pole comes
/// out as ~1e-8 1/s, or as a pair ~1e-3 i rad/s without slip damping, where the zero is
/// double); every other pole of the default case is above 1e-5.
fn is_rigid_rotation(kt: &DMatrix<f64>, phi: &[Complex<f64>]) -> bool {
    let n = phi.len();
    let den: f64 = phi.iter().map(|x| x.norm_sqr()).sum();
    let mut num = 0.0;
    for i in 0..n {
        for j in 0..n {
            num += (phi[i].conj() * phi[j]).re * kt[(i, j)];
        }
    }
    num.abs() <= 1e-12 * kt.norm() * den
}

/// Null vector of lambda^2 I + lambda C~ + K~ (mass-normalised pencil): the right singular
/// vector of its smallest singular value, scaled so that its largest entry is real and 1.
fn null_vector(kt: &DMatrix<f64>, ct: &DMatrix<f64>, lam: Complex<f64>) -> Vec<Complex<f64>> {
    let n = kt.nrows();
    let d = DMatrix::from_fn(n, n, |i, j| {
        let diag = if i == j {
            lam * lam
        } else {
            Complex::new(0.0, 0.0)
        };
        diag + lam * ct[(i, j)] + Complex::new(kt[(i, j)], 0.0)
    });
    let svd = d.svd(false, true);
    let Some(v_t) = svd.v_t else {
        return vec![Complex::new(0.0, 0.0); n];
    };
    // Singular values descending: the last row of V^H is the conjugated null vector.
    let mut v: Vec<Complex<f64>> = (0..n).map(|j| v_t[(n - 1, j)].conj()).collect();
    let big = v
        .iter()
        .copied()
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(Complex::new(1.0, 0.0));
    if big.norm() > 0.0 {
        for x in &mut v {
            *x /= big;
        }
    }
    v
}
