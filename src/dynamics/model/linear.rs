//! The model's linear parts: the Jacobian of the right-hand side (for the implicit
//! integrator) and the static equilibrium (the cold start of a steady-state search).

use super::{dof, ContactFrame, GearSystem, State, NDOF, NSTATE};
use crate::config::case::SpeedBoundary;
use nalgebra::{SMatrix, SVector};

impl GearSystem<'_> {
    /// Jacobian of the right-hand side: exact for the linear parts and the mesh spring
    /// and damper of the pairs in contact; the friction's dependence on the state is
    /// left out (a modified-Newton approximation: friction is < 10 % of the mesh force
    /// and not stiff). The contact is decided as `frame` says.
    pub fn jacobian(
        &self,
        frame: ContactFrame,
        t_s: f64,
        y: &State,
    ) -> SMatrix<f64, NSTATE, NSTATE> {
        let q = y.fixed_rows::<NDOF>(0).into_owned();
        let v = y.fixed_rows::<NDOF>(NDOF).into_owned();
        let sp = self.springs(frame, t_s, q.as_slice(), v.as_slice());
        let (k_mesh, c_mesh) = if sp.pushing {
            (sp.stiffness_touching_n_per_m, self.mesh_damping_n_s_per_m)
        } else {
            (0.0, 0.0)
        };
        self.state_matrix(k_mesh, c_mesh)
    }

    /// The state matrix with every pair in contact at the mean mesh stiffness and the
    /// mesh damper on, friction left out: the time-invariant average of the model's
    /// linear part, 1/s.
    pub fn mean_state_matrix(&self) -> SMatrix<f64, NSTATE, NSTATE> {
        self.state_matrix(
            self.parts.mesh.mean_stiffness_n_per_m(),
            self.mesh_damping_n_s_per_m,
        )
    }

    /// `[[0, I], [-M^-1 K, -M^-1 C]]` with the mesh spring `k_mesh` (N/m) and damper
    /// `c_mesh` (N s/m) along the line of action added to the bearings and couplings.
    fn state_matrix(&self, k_mesh: f64, c_mesh: f64) -> SMatrix<f64, NSTATE, NSTATE> {
        let gg = self.grad * self.grad.transpose();
        let k = self.k_lin + gg * k_mesh;
        let c = self.c_lin + gg * c_mesh;
        let mut j = SMatrix::<f64, NSTATE, NSTATE>::zeros();
        for i in 0..NDOF {
            j[(i, NDOF + i)] = 1.0;
            for l in 0..NDOF {
                j[(NDOF + i, l)] = -k[(i, l)] * self.inv_mass[i];
                j[(NDOF + i, NDOF + l)] = -c[(i, l)] * self.inv_mass[i];
            }
        }
        j
    }

    /// Static equilibrium at the mean mesh stiffness, friction-free: the starting state
    /// of a run (it removes most of the transient). A free drivetrain (motor slip) is
    /// held at the motor for this solve only.
    pub fn static_equilibrium(&self) -> State {
        use dof::*;
        let k_mean = self.parts.mesh.mean_stiffness_n_per_m();
        let mut k = self.k_lin + self.grad * self.grad.transpose() * k_mean;
        let mut f = self.q_ext;
        let fixed = match self.parts.params.speed_boundary {
            SpeedBoundary::BrakeSpeedImposed => PHI_B,
            _ => PHI_M,
        };
        if self.parts.params.speed_boundary == SpeedBoundary::MotorSlip {
            f[PHI_M] = 0.0;
        }
        for l in 0..NDOF {
            k[(fixed, l)] = 0.0;
            k[(l, fixed)] = 0.0;
        }
        k[(fixed, fixed)] = 1.0;
        f[fixed] = 0.0;
        let q = k.lu().solve(&f).unwrap_or_else(SVector::zeros);
        let mut y = State::zeros();
        y.fixed_rows_mut::<NDOF>(0).copy_from(&q);
        y
    }
}
