//! The model's linear parts: the Jacobian of the right-hand side (for the implicit
//! integrator) and the static equilibrium (the cold start of a steady-state search).

use super::rhs::LinearParts;
use super::{ContactFrame, GearSystem, State};
use crate::config::case::SpeedBoundary;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};

impl GearSystem<'_> {
    /// Jacobian of the right-hand side, written column by column into `out`
    /// ([`GearSystem::states`] squared entries): exact for the linear parts and the mesh
    /// springs and dampers of the pairs in contact; the friction's dependence on the state
    /// is left out (a modified-Newton approximation: friction is < 10 % of the mesh force
    /// and not stiff). The contact is decided as `frame` says.
    pub fn jacobian_into(&self, frame: ContactFrame, t_s: f64, y: &[f64], out: &mut [f64]) {
        let (q, v) = y.split_at(self.dofs());
        let mesh_terms = |m: usize| {
            let mesh = &self.meshes[m];
            let sp = mesh.springs(frame.mesh(m), t_s, q, v);
            if sp.pushing {
                (sp.stiffness_touching_n_per_m, mesh.mesh_damping_n_s_per_m)
            } else {
                (0.0, 0.0)
            }
        };
        if let LinearParts::Fixed8(p) = &self.linear {
            // The single pair on the stack (no allocation): its one mesh's terms added to
            // the constant parts as `Assembly::stiffness_with_meshes` adds them.
            let (k_m, c_m) = mesh_terms(0);
            let (mut k, mut c) = (p.k, p.c);
            let g = &self.meshes[0].geometry.gradient;
            for (i, gi) in g {
                for (j, gj) in g {
                    k[(*i, *j)] += gi * gj * k_m;
                    c[(*i, *j)] += gi * gj * c_m;
                }
            }
            return state_matrix_into(8, |i, l| k[(i, l)], |i, l| c[(i, l)], &p.inv_mass, out);
        }
        let (k_mesh, c_mesh): (Vec<f64>, Vec<f64>) = (0..self.meshes.len()).map(mesh_terms).unzip();
        self.state_matrix_into(&k_mesh, &c_mesh, out);
    }

    /// [`GearSystem::jacobian_into`] as a new matrix, 1/s.
    pub fn jacobian(&self, frame: ContactFrame, t_s: f64, y: &[f64]) -> DMatrix<f64> {
        let n2 = self.states();
        let mut j = DMatrix::zeros(n2, n2);
        self.jacobian_into(frame, t_s, y, j.as_mut_slice());
        j
    }

    /// The state matrix with every pair in contact at the mean mesh stiffness and the
    /// mesh dampers on, friction left out: the time-invariant average of the model's
    /// linear part, 1/s.
    pub fn mean_state_matrix(&self) -> DMatrix<f64> {
        let k: Vec<f64> = self
            .meshes
            .iter()
            .map(|m| m.parts.mesh.mean_stiffness_n_per_m())
            .collect();
        self.mean_state_matrix_at(&k)
    }

    /// As [`GearSystem::mean_state_matrix`] with mesh m's spring `k_mesh[m]` (N/m), 1/s.
    pub fn mean_state_matrix_at(&self, k: &[f64]) -> DMatrix<f64> {
        let c: Vec<f64> = self
            .meshes
            .iter()
            .map(|m| m.mesh_damping_n_s_per_m)
            .collect();
        let n2 = self.states();
        let mut a = DMatrix::zeros(n2, n2);
        self.state_matrix_into(k, &c, a.as_mut_slice());
        a
    }

    /// `[[0, I], [-M^-1 K, -M^-1 C]]` with mesh m's spring `k_mesh[m]` (N/m) and damper
    /// `c_mesh[m]` (N s/m) along its line of action added to the bearings, shafts and
    /// couplings; column-major into `out`.
    fn state_matrix_into(&self, k_mesh: &[f64], c_mesh: &[f64], out: &mut [f64]) {
        let asm = self.assembly();
        let k = asm.stiffness_with_meshes(k_mesh);
        let c = asm.damping_with_meshes(c_mesh);
        let n = self.dofs();
        state_matrix_into(
            n,
            |i, l| k[(i, l)],
            |i, l| c[(i, l)],
            asm.inverse_masses(),
            out,
        );
    }

    /// Static equilibrium at the mean mesh stiffness, friction-free: the starting state
    /// of a run (it removes most of the transient). A free drivetrain (motor slip) is
    /// held at the input for this solve only.
    pub fn static_equilibrium(&self) -> State {
        let asm = self.assembly();
        let k_mean: Vec<f64> = self
            .meshes
            .iter()
            .map(|m| m.parts.mesh.mean_stiffness_n_per_m())
            .collect();
        let mut k = asm.stiffness_with_meshes(&k_mean);
        let mut f = asm.external_forces().clone();
        let drive = asm.elements.drive;
        let rotation = |b| {
            asm.index(b, crate::dynamics::assembly::Dof::Rotation)
                .expect("every body rotates")
        };
        let fixed = match drive.boundary {
            SpeedBoundary::BrakeSpeedImposed => rotation(drive.output),
            _ => rotation(drive.input),
        };
        if drive.boundary == SpeedBoundary::MotorSlip {
            f[fixed] = 0.0;
        }
        let n = self.dofs();
        for l in 0..n {
            k[(fixed, l)] = 0.0;
            k[(l, fixed)] = 0.0;
        }
        k[(fixed, fixed)] = 1.0;
        f[fixed] = 0.0;
        let q = solve_or_zero(k, f);
        let mut y = State::zeros(2 * n);
        y.rows_mut(0, n).copy_from(&q);
        y
    }
}

/// `[[0, I], [-M^-1 K, -M^-1 C]]` of `n` coordinates, column-major into `out`.
fn state_matrix_into(
    n: usize,
    k: impl Fn(usize, usize) -> f64,
    c: impl Fn(usize, usize) -> f64,
    inv_mass: &[f64],
    out: &mut [f64],
) {
    let n2 = 2 * n;
    out.fill(0.0);
    for i in 0..n {
        out[(n + i) * n2 + i] = 1.0;
        for l in 0..n {
            out[l * n2 + n + i] = -k(i, l) * inv_mass[i];
            out[(n + l) * n2 + n + i] = -c(i, l) * inv_mass[i];
        }
    }
}

/// K q = f by LU, zeros if K is singular. The single pair's 8 x 8 system goes through
/// nalgebra's fixed-size LU, as it always has (same arithmetic, same bits).
fn solve_or_zero(k: DMatrix<f64>, f: DVector<f64>) -> DVector<f64> {
    let n = f.len();
    if n == 8 {
        let ks = SMatrix::<f64, 8, 8>::from_fn(|i, j| k[(i, j)]);
        let fs = SVector::<f64, 8>::from_fn(|i, _| f[i]);
        let q = ks.lu().solve(&fs).unwrap_or_else(SVector::zeros);
        return DVector::from_column_slice(q.as_slice());
    }
    k.lu().solve(&f).unwrap_or_else(|| DVector::zeros(n))
}
