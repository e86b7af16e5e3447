//! The right-hand side of the assembled equations of motion:
//! M q'' = f_ext + sum over meshes f_mesh - K q - C q' (docs/MODEL.md, section 4.1).

use super::{ContactFrame, GearSystem, MeshState, State};
use crate::config::case::SpeedBoundary;
use crate::dynamics::drive::Drive;
use nalgebra::{DMatrix, SMatrix, SVector};

/// The nonzero entries of a matrix row by row, each row's in ascending column order:
/// `sum_j a_ij x_j` over them adds the terms in the order nalgebra's dense
/// matrix-vector product does (column by column from the first), and the zero terms it
/// leaves out change no sum, so the two agree bit for bit.
#[derive(Debug, Clone, Default)]
pub(crate) struct SparseRows {
    /// Row i's entries are `entries[start[i]..start[i + 1]]`.
    start: Vec<usize>,
    entries: Vec<(usize, f64)>,
}

impl SparseRows {
    pub(crate) fn of(a: &DMatrix<f64>) -> Self {
        let mut start = vec![0];
        let mut entries = Vec::new();
        for i in 0..a.nrows() {
            for j in 0..a.ncols() {
                if a[(i, j)] != 0.0 {
                    entries.push((j, a[(i, j)]));
                }
            }
            start.push(entries.len());
        }
        Self { start, entries }
    }

    /// `sum_j a_ij x_j`.
    #[inline]
    fn row_times(&self, i: usize, x: &[f64]) -> f64 {
        let mut s = 0.0;
        for (j, a) in &self.entries[self.start[i]..self.start[i + 1]] {
            s += a * x[*j];
        }
        s
    }
}

/// The single pair's constant parts as fixed-size arrays (8 coordinates): its
/// right-hand side and Jacobian run on the stack, unrolled, with no slice iteration
/// (the paper's case's speed; `docs/PERFORMANCE.md`).
#[derive(Debug, Clone)]
pub(crate) struct PairParts {
    /// Constant stiffness and damping (bearings, shafts, couplings).
    pub(crate) k: SMatrix<f64, 8, 8>,
    pub(crate) c: SMatrix<f64, 8, 8>,
    /// 1/M per coordinate (0 for a held one).
    pub(crate) inv_mass: [f64; 8],
    /// Constant external forces and torques.
    pub(crate) f_ext: [f64; 8],
    /// The mesh's gradient d delta / d q, dense, and where its friction acts: the
    /// tangent e, the pinion's and gear's x and rotation coordinates.
    pub(crate) gradient: SVector<f64, 8>,
    pub(crate) tangent: [f64; 2],
    pub(crate) lateral: [usize; 2],
    pub(crate) rotation: [usize; 2],
}

/// The assembly's stiffness and damping as the right-hand side multiplies them: the
/// single pair's as [`PairParts`], any other train's by rows. One lives in each system,
/// built once and never moved in a loop: the fixed variant stays inline (a box would add
/// an indirection to every right-hand side of the paper's pair).
#[allow(clippy::large_enum_variant)]
pub(crate) enum LinearParts {
    Fixed8(PairParts),
    Sparse(SparseRows, SparseRows),
}

impl PairParts {
    /// [`super::TrainMesh::add_forces`] of the pair's one mesh, on fixed-size arrays: the
    /// normal force -F g on every coordinate (0 where g is), the friction on the laterals
    /// along e and its moments on the rotations.
    #[inline]
    fn mesh_forces(&self, mesh: &super::TrainMesh, ms: &MeshState) -> SVector<f64, 8> {
        let mut f = -ms.force_n * self.gradient;
        let [f_sum, m_p, m_g] = mesh.friction_resultant(ms);
        let [ex, ey] = self.tangent;
        let [xp, xg] = self.lateral;
        f[xp] += f_sum * ex;
        f[xp + 1] += f_sum * ey;
        f[xg] -= f_sum * ex;
        f[xg + 1] -= f_sum * ey;
        f[self.rotation[0]] -= m_p;
        f[self.rotation[1]] += m_g;
        f
    }
}

impl LinearParts {
    pub(crate) fn of(asm: &crate::dynamics::assembly::Assembly) -> Self {
        let (k, c) = (asm.stiffness(), asm.damping());
        let single_pair =
            asm.meshes().len() == 1 && asm.meshes()[0].lateral.iter().all(|x| x.is_some());
        if k.nrows() == 8 && single_pair {
            let geo = &asm.meshes()[0];
            let mut gradient = SVector::<f64, 8>::zeros();
            for (i, g) in &geo.gradient {
                gradient[*i] = *g;
            }
            let fixed = |a: &DMatrix<f64>| SMatrix::<f64, 8, 8>::from_fn(|i, j| a[(i, j)]);
            Self::Fixed8(PairParts {
                k: fixed(k),
                c: fixed(c),
                inv_mass: std::array::from_fn(|i| asm.inverse_masses()[i]),
                f_ext: std::array::from_fn(|i| asm.external_forces()[i]),
                gradient,
                tangent: geo.tangent,
                lateral: geo.lateral.map(|x| x.unwrap_or(0)),
                rotation: geo.rotation,
            })
        } else {
            Self::Sparse(SparseRows::of(k), SparseRows::of(c))
        }
    }
}

impl GearSystem<'_> {
    /// Right-hand side dy/dt into `dy` and the state of every mesh into `meshes`, the
    /// contact decided as `frame` says. `y`, `dy`: [`GearSystem::states`] entries;
    /// `meshes`: one per mesh.
    pub fn derivative_into(
        &self,
        frame: ContactFrame,
        t_s: f64,
        y: &[f64],
        dy: &mut [f64],
        meshes: &mut [MeshState],
    ) {
        let (k, c) = match &self.linear {
            LinearParts::Fixed8(p) => return self.derivative_pair(p, frame, t_s, y, dy, meshes),
            LinearParts::Sparse(k, c) => (k, c),
        };
        let n = self.dofs();
        let (q, v) = y.split_at(n);
        let (dq, dv) = dy.split_at_mut(n);
        // The mesh forces gather in dv first.
        dv.fill(0.0);
        for (m, mesh) in self.meshes.iter().enumerate() {
            mesh.mesh_state_into(frame.mesh(m), t_s, q, v, &mut meshes[m]);
            mesh.add_forces(&meshes[m], dv);
        }
        let inv_mass = self.assembly().inverse_masses();
        let f_ext = self.external_forces();
        for i in 0..n {
            let rhs = f_ext[i] + dv[i] - k.row_times(i, q) - c.row_times(i, v);
            dv[i] = rhs * inv_mass[i];
        }
        dq.copy_from_slice(v);
        if let Some(d) = self.drive {
            self.add_drive(d, t_s, dv);
        }
    }

    /// [`GearSystem::derivative_into`] of the single pair: the same terms in the same
    /// order (so the same bits), on fixed-size arrays.
    #[inline]
    fn derivative_pair(
        &self,
        p: &PairParts,
        frame: ContactFrame,
        t_s: f64,
        y: &[f64],
        dy: &mut [f64],
        meshes: &mut [MeshState],
    ) {
        let q = SVector::<f64, 8>::from_column_slice(&y[..8]);
        let v = SVector::<f64, 8>::from_column_slice(&y[8..16]);
        let (mesh, ms) = (&self.meshes[0], &mut meshes[0]);
        mesh.mesh_state_into(frame.mesh(0), t_s, q.as_slice(), v.as_slice(), ms);
        let f = p.mesh_forces(mesh, ms);
        let kq = p.k * q;
        let cv = p.c * v;
        let dy: &mut [f64; 16] = (&mut dy[..16]).try_into().expect("16 states");
        for i in 0..8 {
            dy[i] = v[i];
            dy[8 + i] = (p.f_ext[i] + f[i] - kq[i] - cv[i]) * p.inv_mass[i];
        }
        if let Some(d) = self.drive {
            self.add_drive(d, t_s, &mut dy[8..]);
        }
    }

    /// [`GearSystem::derivative_into`] into new vectors: dy/dt and the state of every
    /// mesh.
    pub fn derivative(&self, frame: ContactFrame, t_s: f64, y: &[f64]) -> (State, Vec<MeshState>) {
        let mut dy = State::zeros(self.states());
        let mut meshes = vec![MeshState::default(); self.meshes.len()];
        self.derivative_into(frame, t_s, y, dy.as_mut_slice(), &mut meshes);
        (dy, meshes)
    }

    /// The drive's terms in the accelerations `dv` (`dynamics::drive`): the nominal
    /// acceleration -d^2 Theta/dt^2 on every free angle (each body's at its own nominal
    /// speed's share of the input's), and the load fluctuation on the body where the load
    /// acts (the input when the output's speed is imposed).
    fn add_drive(&self, d: &Drive, t_s: f64, dv: &mut [f64]) {
        let asm = self.assembly();
        let inv_mass = asm.inverse_masses();
        let speeds = self.body_speeds_rad_s();
        let drive = asm.elements.drive;
        let w_in = speeds[drive.input];
        let a = d.accel(t_s);
        for (b, w) in speeds.iter().enumerate() {
            let i = asm
                .index(b, crate::dynamics::assembly::Dof::Rotation)
                .unwrap_or(0);
            // A body at the input's speed takes the acceleration itself (ratio 1 exactly).
            let r = if *w == w_in { 1.0 } else { w / w_in };
            if inv_mass[i] > 0.0 {
                dv[i] -= a * r;
            }
        }
        let dt = d.torque_at(t_s);
        if dt != 0.0 {
            let rotation = |b| {
                asm.index(b, crate::dynamics::assembly::Dof::Rotation)
                    .unwrap_or(0)
            };
            if drive.boundary == SpeedBoundary::BrakeSpeedImposed {
                let i = rotation(drive.input);
                dv[i] += dt * inv_mass[i];
            } else {
                let i = rotation(drive.output);
                dv[i] -= dt * inv_mass[i];
            }
        }
    }
}
