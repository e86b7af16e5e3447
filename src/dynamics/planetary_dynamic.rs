//! The dynamic model of a planetary set (docs/MODEL.md section 12.5): the degrees of
//! freedom of Lin & Parker's lumped model (`planetary_lumped`, 3 (N + 3) coordinates in
//! the carrier frame) with every mesh's time-varying stiffness and phase
//! (`stiffness::planetary_mesh`), mesh contact loss, viscous damping and a torque on the
//! input member, as a first-order system for the implicit integrator
//! (`integrator::OdeSystem` on a `Dyn` state [q, dq/dt], m and m/s).
//!
//! Equations (Lin & Parker 1999 eqs. 1-3 for the deflections; Parker, Agashe & Vijayakar
//! 2000 and Parker & Lin 2004 for the time-varying, phased mesh stiffness):
//!   M q'' + sum_j (k_j d_j + c_j d_j') g_j = f,   d_j = g_j . q,
//! with g_j the gradient of deflection j (sun mesh, ring mesh, planet pin radial and
//! tangential, and the lateral and torsional supports of carrier, ring and sun). A mesh
//! carries k_jn(t) d + c_j d' while its compression d is positive and nothing otherwise
//! (contact loss; no backlash, so the back flanks never touch). The sun mesh's deflection
//! uses the sun mesh's operating pressure angle alpha_s, the ring mesh's alpha_r
//! (psi_sn = psi_n - alpha_s, psi_rn = psi_n + alpha_r).
//!
//! Rotating frame: the carrier turns at a constant mean speed; the centripetal and
//! gyroscopic terms of its frame (of order Omega_c^2 m and 2 Omega_c m) are left out, as in
//! Lin & Parker's modal model and Parker et al.'s (2000) dynamic one: valid while the
//! carrier's speed is small beside the lowest natural frequency (docs/MODEL.md 12.5).
//!
//! Damping (the sources are silent; gearwear's choice): every spring j has a viscous
//! damper c_j = 2 zeta sqrt(k_j m_j), zeta the case's `dynamics.mesh_damping_ratio`, k_j
//! the spring's (mean) stiffness, m_j for a mesh the equivalent mass 1 / (1/m_a + 1/m_b)
//! of the two gears' I / r_b^2, for a support the supported coordinate's mass, for a
//! planet pin the planet's mass.

use super::excitation::PairGap;
use super::integrator::{Matrix, OdeSystem, Vector};
use super::planetary_lumped::PlanetaryLumped;
use crate::stiffness::planetary_mesh::PlanetaryMeshes;
use nalgebra::allocator::Allocator;
use nalgebra::{DMatrix, DVector, DefaultAllocator, Dim, U1};

/// Indices of a member's three coordinates, as in `planetary_lumped`: carrier 0, ring 3,
/// sun 6, planet n 9 + 3n.
const CARRIER: usize = 0;
const RING: usize = 3;
const SUN: usize = 6;
const PLANETS: usize = 9;

/// Where the meshes' stiffness comes from.
#[derive(Debug, Clone)]
pub enum MeshStiffnessSource {
    /// The potential-energy tables with every mesh's phase.
    Tables(Box<PlanetaryMeshes>),
    /// Constant stiffness of the sun-planet and ring-planet meshes, N/m (the time-invariant
    /// model, for checks against `planetary_lumped`).
    Constant([f64; 2]),
}

impl MeshStiffnessSource {
    /// Mesh stiffness of planet `p`'s sun (`ring` false) or ring mesh at `cycles`, N/m,
    /// the pairs in contact decided at `decide` cycles (`PlanetaryMeshes`).
    fn at(&self, p: usize, ring: bool, cycles: f64, decide: f64) -> f64 {
        match (self, ring) {
            (Self::Tables(m), false) => m.sun_n_per_m_decided(p, cycles, decide),
            (Self::Tables(m), true) => m.ring_n_per_m_decided(p, cycles, decide),
            (Self::Constant(k), r) => k[r as usize],
        }
    }

    /// Mesh periods over which the stiffness repeats (`PlanetaryMeshes::periods`; 1 for
    /// constant stiffness).
    pub fn periods(&self) -> usize {
        match self {
            Self::Tables(m) => m.periods(),
            Self::Constant(_) => 1,
        }
    }

    /// The same source with every tooth alike (a tooth fault left out).
    pub fn without_fault(&self) -> Self {
        match self {
            Self::Tables(m) => Self::Tables(Box::new(m.without_fault())),
            Self::Constant(k) => Self::Constant(*k),
        }
    }

    /// The mesh cycles in [0, 1) where a mesh's stiffness jumps
    /// (`PlanetaryMeshes::jump_cycles`); none for constant stiffness.
    pub fn jump_cycles(&self) -> Vec<f64> {
        match self {
            Self::Tables(m) => m.jump_cycles(),
            Self::Constant(_) => Vec::new(),
        }
    }
}

/// A linear spring-damper along deflection d = g . q (sparse g).
#[derive(Debug, Clone)]
struct Element {
    /// Stiffness (constant springs) or mean stiffness (meshes), N/m.
    k: f64,
    /// Damping, N s/m.
    c: f64,
    g: Vec<(usize, f64)>,
    /// For a mesh: (planet, ring mesh?).
    mesh: Option<(usize, bool)>,
    /// For a mesh: the gap a planet pin's position error opens along its line of action
    /// ([`pin_error_gaps`]), m; its compression is g . q - gap.
    gap_m: f64,
}

impl Element {
    /// g . v: the deflection of `v` = q (m), or its rate of `v` = q' (m/s).
    fn deflection(&self, v: &[f64]) -> f64 {
        self.g.iter().map(|(i, x)| x * v[*i]).sum()
    }

    /// The compression g . q - gap, m (a spring's deflection: its gap is 0).
    fn compression(&self, q: &[f64]) -> f64 {
        self.deflection(q) - self.gap_m
    }
}

/// The gaps that a planet pin's position error opens on the planet's sun and ring meshes,
/// m: [sun, ring] from the error (e_t tangential along eta, e_r radial along zeta, m) and
/// the meshes' operating pressure angles `alpha_rad` [sun, ring].
///
/// A pin displaced by (e_r, e_t) holds the planet, at rest on its pin, at zeta = e_r,
/// eta = e_t; in the deflections of Lin & Parker (1999, eqs. 1-3) zeta and eta enter the
/// sun mesh as -zeta sin alpha_s - eta cos alpha_s and the ring mesh as
/// +zeta sin alpha_r - eta cos alpha_r. Measuring the planet's coordinates from its
/// displaced pin (so the pin's springs keep their form) leaves on each mesh a gap
///   sun:  e_r sin alpha_s + e_t cos alpha_s,    ring: e_t cos alpha_r - e_r sin alpha_r,
/// positive opening the mesh. The error is a displacement of the planet's centre on the
/// carrier as Kahraman (1994, "Load sharing characteristics of planetary transmissions",
/// Mech. Mach. Theory 29, 1151) and Bodas & Kahraman (2004, "Influence of carrier and gear
/// manufacturing errors on the static load sharing behavior of planetary gear sets", JSME
/// Int. J. C 47, 908) state it; its projection on each line of action is derived here from
/// Lin & Parker's deflections. A tangential error (e_t) opens or closes both meshes
/// alike; a radial one (e_r) opens one and closes the other (with alpha_s = alpha_r the
/// two cancel along the planet's path from sun to ring).
pub fn pin_error_gaps(e_t_m: f64, e_r_m: f64, alpha_rad: [f64; 2]) -> [f64; 2] {
    let (ss, cs) = alpha_rad[0].sin_cos();
    let (sr, cr) = alpha_rad[1].sin_cos();
    [e_r_m * ss + e_t_m * cs, e_t_m * cr - e_r_m * sr]
}

/// A pivot of K's LU below this share of the largest is a singular K (a member with no
/// path to ground): K's real spread of stiffness (supports of 1e16 N/m against planet
/// pins of 1e8 in the tests) keeps its pivots above ~1e-9 of the largest, round-off of a
/// singular matrix leaves them near 1e-16.
const SINGULAR_PIVOT: f64 = 1e-13;

/// The solution of K q = f (m) when K is grounded: None when a pivot of its LU is below
/// [`SINGULAR_PIVOT`] of the largest (a member with no path to ground) or q is not finite.
fn solve_grounded(k: DMatrix<f64>, f: &DVector<f64>) -> Option<DVector<f64>> {
    let lu = k.lu();
    let pivots = lu.u().diagonal().map(f64::abs);
    if pivots.min() <= SINGULAR_PIVOT * pivots.max() {
        return None;
    }
    lu.solve(f).filter(|x| x.iter().all(|v| v.is_finite()))
}

/// The planetary set's dynamic model (see module docs).
#[derive(Debug, Clone)]
pub struct PlanetaryDynamic {
    /// Masses, radii, supports and planet angles (its mesh stiffness: the meshes' means).
    pub params: PlanetaryLumped,
    /// Operating pressure angles of the sun and ring meshes, rad.
    pub alpha_rad: [f64; 2],
    /// The meshes' stiffness over time.
    pub source: MeshStiffnessSource,
    /// Mesh frequency f_m, Hz: time t is f_m t mesh cycles.
    pub mesh_frequency_hz: f64,
    /// External generalised forces (a torque T on member j as T / r_j on its u), N.
    pub force_n: DVector<f64>,
    mass: Vec<f64>,
    elements: Vec<Element>,
    /// When set, the time (s) at which `rhs` and `jacobian` decide which tooth pairs
    /// touch (the middle of the integration step, [`Self::decide_contact_at`]).
    decide_s: Option<f64>,
    /// Each mesh's wear gap over its path (sun meshes 1..N, then ring meshes; empty: no
    /// wear), [`Self::set_wear_gaps`].
    wear_gaps: Vec<PairGap>,
}

impl PlanetaryDynamic {
    /// The model of `params` (its mesh stiffness the mean of `source`'s) with operating
    /// pressure angles `alpha_rad` [sun, ring], damping ratio `zeta` and no load.
    pub fn new(
        params: PlanetaryLumped,
        alpha_rad: [f64; 2],
        source: MeshStiffnessSource,
        mesh_frequency_hz: f64,
        zeta: f64,
    ) -> Self {
        let mass = params.mass_diagonal();
        let elements = elements_of(&params, alpha_rad, &mass, zeta);
        Self {
            force_n: DVector::zeros(mass.len()),
            params,
            alpha_rad,
            source,
            mesh_frequency_hz,
            mass,
            elements,
            decide_s: None,
            wear_gaps: Vec::new(),
        }
    }

    /// Set every mesh's wear gap (sun meshes 1..N, then ring meshes; each on its path's
    /// rho1, the sun's or the planet's flank; an empty list: no wear). A mesh's compression
    /// is then g . q - gap - e_w(t), e_w the stiffness-weighted gap of its pairs in contact
    /// ([`Self::wear_gap_m`]).
    pub fn set_wear_gaps(&mut self, gaps: Vec<PairGap>) {
        self.wear_gaps = gaps;
    }

    /// The wear gap of mesh (`p`, `ring`) at `cycles`, pairs decided at `decide` cycles, m:
    /// e_w = sum k_i g(rho_i) / sum k_i over its pairs in contact, the single transmission
    /// error of paper eq. 2 that gives the mesh the per-pair gaps' force while every pair
    /// touches (as `wear::profile_wear::wear_transmission_error`; docs/MODEL.md 12.9).
    /// Exactly 0 without wear gaps or with constant stiffness.
    pub fn wear_gap_m(&self, p: usize, ring: bool, cycles: f64, decide: f64) -> f64 {
        let planets = self.params.planet_angles_rad.len();
        let (Some(gap), MeshStiffnessSource::Tables(m)) = (
            self.wear_gaps.get(p + ring as usize * planets),
            &self.source,
        ) else {
            return 0.0;
        };
        let (mut kg, mut k) = (0.0, 0.0);
        let mut add = |(rho, ki): (f64, f64)| {
            kg += ki * gap.at(rho).0;
            k += ki;
        };
        if ring {
            m.ring_pairs_decided(p, cycles, decide).for_each(&mut add);
        } else {
            m.sun_pairs_decided(p, cycles, decide).for_each(&mut add);
        }
        if k > 0.0 {
            kg / k
        } else {
            0.0
        }
    }

    /// Element `e`'s wear gap at `cycles` (0 for a spring), pairs decided as `mesh_k`.
    fn worn(&self, e: &Element, cycles: f64) -> f64 {
        match e.mesh {
            Some((p, ring)) if !self.wear_gaps.is_empty() => {
                let decide = self.decide_s.map_or(cycles, |t| self.mesh_frequency_hz * t);
                self.wear_gap_m(p, ring, cycles, decide)
            }
            _ => 0.0,
        }
    }

    /// Decide the tooth pairs in contact of every mesh at time `t_s` (s) in `rhs` and
    /// `jacobian` (the middle of a step that crosses no stiffness jump, so that a step
    /// ending on a jump sees one contact set on all its stages); `None`: at each call's
    /// own time.
    pub fn decide_contact_at(&mut self, t_s: Option<f64>) {
        self.decide_s = t_s;
    }

    /// Stiffness of mesh (`p`, `ring`) at `cycles`, decided at `decide_s` when set, N/m.
    fn mesh_k(&self, p: usize, ring: bool, cycles: f64) -> f64 {
        let decide = self.decide_s.map_or(cycles, |t| self.mesh_frequency_hz * t);
        self.source.at(p, ring, cycles, decide)
    }

    /// Coordinates 3 (N + 3).
    pub fn dofs(&self) -> usize {
        self.mass.len()
    }

    /// Index of the u coordinate of member `m` (0 carrier, 1 ring, 2 sun).
    pub fn rotation_index(member: usize) -> usize {
        3 * member + 2
    }

    /// Every mesh's force at time `t_s` in state `y` ([q, q']), N: the sun meshes of planets
    /// 1..N, then their ring meshes; 0 for a mesh out of contact.
    pub fn mesh_forces(&self, t_s: f64, y: &[f64]) -> Vec<f64> {
        let n = self.dofs();
        let (q, v) = y.split_at(n);
        let cycles = self.mesh_frequency_hz * t_s;
        let planets = self.params.planet_angles_rad.len();
        let mut f = vec![0.0; 2 * planets];
        for e in &self.elements {
            if let Some((p, ring)) = e.mesh {
                let d = e.compression(q) - self.wear_gap_m(p, ring, cycles, cycles);
                if d > 0.0 {
                    let k = self.source.at(p, ring, cycles, cycles);
                    f[p + ring as usize * planets] = k * d + e.c * e.deflection(v);
                }
            }
        }
        f
    }

    /// The stiffness (or damping, `damping` true) matrix of the springs and of the
    /// meshes in contact in `q` at `cycles`, N/m (N s/m); every mesh in contact when `q`
    /// is `None`, at its mean stiffness when `cycles` is `None`; the tooth pairs in
    /// contact decided as set by [`Self::decide_contact_at`].
    pub fn matrix(&self, q: Option<&[f64]>, cycles: Option<f64>, damping: bool) -> DMatrix<f64> {
        let n = self.dofs();
        let mut k = DMatrix::zeros(n, n);
        for e in &self.elements {
            let kv = match (e.mesh, damping) {
                (_, true) => e.c,
                (None, false) => e.k,
                (Some((p, ring)), false) => cycles.map_or(e.k, |c| self.mesh_k(p, ring, c)),
            };
            let worn = cycles.map_or(0.0, |c| self.worn(e, c));
            if e.mesh.is_some() && q.is_some_and(|q| e.compression(q) - worn <= 0.0) {
                continue;
            }
            for (i, gi) in &e.g {
                for (j, gj) in &e.g {
                    k[(*i, *j)] += kv * gi * gj;
                }
            }
        }
        k
    }

    /// The state matrix of the time-invariant model (every mesh in contact at its mean
    /// stiffness), [[0, I], [-M^-1 K_mean, -M^-1 C]], 1/s and 1/s^2: the linear model the
    /// steady-state search starts its Jacobian from.
    pub fn mean_state_matrix(&self) -> DMatrix<f64> {
        let n = self.dofs();
        let k = self.matrix(None, None, false);
        let c = self.matrix(None, None, true);
        DMatrix::from_fn(2 * n, 2 * n, |r, col| match (r < n, col < n) {
            (true, true) => 0.0,
            (true, false) => f64::from(u8::from(col - n == r)),
            (false, true) => -k[(r - n, col)] / self.mass[r - n],
            (false, false) => -c[(r - n, col - n)] / self.mass[r - n],
        })
    }

    /// The static deflection under `force_n` with every mesh in contact at its mean
    /// stiffness and preloaded by its gap, K q = f + sum_meshes k gap g, m; `None` when a
    /// member has no path to ground (K singular). Whether every mesh is then compressed
    /// is [`Self::static_mesh_forces`]'s question.
    pub fn static_deflection(&self) -> Option<DVector<f64>> {
        let (k, f, _) = self.assemble(&|e| (e.k, e.gap_m));
        solve_grounded(k, &f)
    }

    /// The stiffness matrix K = sum_j k_j g_j g_j^T (N/m) and the load
    /// f = force_n + sum_j k_j gap_j g_j (N) of every element at the stiffness and gap (m)
    /// `spring` gives it, with those (stiffness, gap) pairs in element order.
    fn assemble(
        &self,
        spring: &dyn Fn(&Element) -> (f64, f64),
    ) -> (DMatrix<f64>, DVector<f64>, Vec<(f64, f64)>) {
        let n = self.dofs();
        let mut k = DMatrix::zeros(n, n);
        let mut f = self.force_n.clone();
        let mut springs = Vec::with_capacity(self.elements.len());
        for e in &self.elements {
            let (kv, gap) = spring(e);
            springs.push((kv, gap));
            for (i, gi) in &e.g {
                f[*i] += kv * gap * gi;
                for (j, gj) in &e.g {
                    k[(*i, *j)] += kv * gi * gj;
                }
            }
        }
        (k, f, springs)
    }

    /// Every mesh's static force k (g . q - gap) at its mean stiffness in the static
    /// deflection (sun meshes 1..N, then ring meshes), N: negative for a mesh the static
    /// load would open (a planet whose pin error keeps it off the load: the model has no
    /// back flanks, so such a planet is unheld); `None` as [`Self::static_deflection`].
    pub fn static_mesh_forces(&self) -> Option<Vec<f64>> {
        let q = self.static_deflection()?;
        let planets = self.params.planet_angles_rad.len();
        let mut f = vec![0.0; 2 * planets];
        for e in &self.elements {
            if let Some((p, ring)) = e.mesh {
                f[p + ring as usize * planets] = e.k * e.compression(q.as_slice());
            }
        }
        Some(f)
    }

    /// The quasi-static mesh forces at `cycles` mesh cycles (sun meshes 1..N, then ring
    /// meshes), N: the static equilibrium K(t) q = f + sum_meshes k_j(t) (gap_j + e_w,j(t)) g_j
    /// with every mesh's stiffness and wear gap at that instant (no inertia, no damping),
    /// a mesh the solution puts in tension taken out and the equilibrium solved again
    /// (contact loss, at most one pass per mesh). The planetary twin of the pair's
    /// `dynamics::quasi_static` (docs/MODEL.md 12.9); `None` when K is singular (the same
    /// assembly and pivot check as [`Self::static_deflection`]: a planet that lost both
    /// its meshes has no path to ground).
    pub fn quasi_static_mesh_forces(&self, cycles: f64) -> Option<Vec<f64>> {
        let planets = self.params.planet_angles_rad.len();
        let mut open = vec![false; 2 * planets];
        for _ in 0..=2 * planets {
            let (k, f, springs) = self.assemble(&|e| match e.mesh {
                None => (e.k, 0.0),
                Some((p, ring)) if open[p + ring as usize * planets] => (0.0, 0.0),
                Some((p, ring)) => (
                    self.source.at(p, ring, cycles, cycles),
                    e.gap_m + self.wear_gap_m(p, ring, cycles, cycles),
                ),
            });
            let q = solve_grounded(k, &f)?;
            let mut forces = vec![0.0; 2 * planets];
            let mut newly_open = false;
            for (e, (kv, gap)) in self.elements.iter().zip(&springs) {
                if let Some((p, ring)) = e.mesh {
                    let j = p + ring as usize * planets;
                    if open[j] {
                        continue;
                    }
                    let fj = kv * (e.deflection(q.as_slice()) - gap);
                    if fj < 0.0 {
                        open[j] = true;
                        newly_open = true;
                    }
                    forces[j] = fj.max(0.0);
                }
            }
            if !newly_open {
                return Some(forces);
            }
        }
        None
    }

    /// Set the planets' pin position errors, (tangential e_t, radial e_r) per planet, m:
    /// the gaps of [`pin_error_gaps`] on each planet's sun and ring mesh.
    pub fn set_pin_errors(&mut self, errors_m: &[(f64, f64)]) {
        for e in &mut self.elements {
            if let Some((p, ring)) = e.mesh {
                let (et, er) = errors_m.get(p).copied().unwrap_or((0.0, 0.0));
                e.gap_m = pin_error_gaps(et, er, self.alpha_rad)[ring as usize];
            }
        }
    }
}

impl<D: Dim> OdeSystem<D> for PlanetaryDynamic
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// [q', M^-1 (f - sum (k d + c d') g)], m/s and m/s^2.
    fn rhs(&mut self, t: f64, y: &Vector<D>) -> Vector<D> {
        let n = self.dofs();
        let (q, v) = y.as_slice().split_at(n);
        let cycles = self.mesh_frequency_hz * t;
        // The generalised forces accumulate in the acceleration half of the output (no
        // scratch vector per call).
        let (dim, _) = y.shape_generic();
        let mut out = Vector::<D>::zeros_generic(dim, U1);
        out.rows_mut(n, n).copy_from(&self.force_n);
        for e in &self.elements {
            let d = e.compression(q) - self.worn(e, cycles);
            let k = match e.mesh {
                None => e.k,
                Some(_) if d <= 0.0 => continue,
                Some((p, ring)) => self.mesh_k(p, ring, cycles),
            };
            let fe = k * d + e.c * e.deflection(v);
            for (i, gi) in &e.g {
                out[n + *i] -= fe * gi;
            }
        }
        for i in 0..n {
            out[i] = v[i];
            out[n + i] /= self.mass[i];
        }
        out
    }

    /// [[0, I], [-M^-1 K(t), -M^-1 C]] with the meshes in contact in `y`, 1/s and 1/s^2.
    fn jacobian(&mut self, t: f64, y: &Vector<D>) -> Option<Matrix<D>> {
        let n = self.dofs();
        let q = &y.as_slice()[..n];
        let cycles = self.mesh_frequency_hz * t;
        let k = self.matrix(Some(q), Some(cycles), false);
        let c = self.matrix(Some(q), Some(cycles), true);
        let (dim, _) = y.shape_generic();
        let mut j = Matrix::<D>::zeros_generic(dim, dim);
        for r in 0..n {
            j[(r, n + r)] = 1.0;
            for col in 0..n {
                j[(n + r, col)] = -k[(r, col)] / self.mass[r];
                j[(n + r, n + col)] = -c[(r, col)] / self.mass[r];
            }
        }
        Some(j)
    }
}

/// The model's springs and meshes with their dampers (module docs): per planet its sun
/// mesh, ring mesh and the pin's radial and tangential springs, then the supports.
fn elements_of(p: &PlanetaryLumped, alpha: [f64; 2], mass: &[f64], zeta: f64) -> Vec<Element> {
    let (ssa, csa) = alpha[0].sin_cos();
    let (sra, cra) = alpha[1].sin_cos();
    let [k_sun, k_ring] = p.mesh_stiffness_n_per_m;
    let k_pin = p.bearing_n_per_m[3];
    let damper = |k: f64, m: f64| 2.0 * zeta * (k * m).sqrt();
    let reduced = |a: f64, b: f64| 1.0 / (1.0 / a + 1.0 / b);
    let mut out = Vec::new();
    for (n, psi) in p.planet_angles_rad.iter().enumerate() {
        let q = PLANETS + 3 * n;
        let (s_sn, c_sn) = (psi - alpha[0]).sin_cos();
        let (s_rn, c_rn) = (psi + alpha[1]).sin_cos();
        let (sp, cp) = psi.sin_cos();
        let m_planet_u = mass[q + 2];
        out.push(Element {
            k: k_sun,
            c: damper(k_sun, reduced(mass[SUN + 2], m_planet_u)),
            g: vec![
                (SUN, -s_sn),
                (SUN + 1, c_sn),
                (q, -ssa),
                (q + 1, -csa),
                (SUN + 2, 1.0),
                (q + 2, 1.0),
            ],
            mesh: Some((n, false)),
            gap_m: 0.0,
        });
        out.push(Element {
            k: k_ring,
            c: damper(k_ring, reduced(mass[RING + 2], m_planet_u)),
            g: vec![
                (RING, -s_rn),
                (RING + 1, c_rn),
                (q, sra),
                (q + 1, -cra),
                (RING + 2, 1.0),
                (q + 2, -1.0),
            ],
            mesh: Some((n, true)),
            gap_m: 0.0,
        });
        for g in [
            vec![(CARRIER, cp), (CARRIER + 1, sp), (q, -1.0)],
            vec![
                (CARRIER, -sp),
                (CARRIER + 1, cp),
                (CARRIER + 2, 1.0),
                (q + 1, -1.0),
            ],
        ] {
            let c = damper(k_pin, mass[q]);
            out.push(Element {
                k: k_pin,
                c,
                g,
                mesh: None,
                gap_m: 0.0,
            });
        }
    }
    for (j, base) in [CARRIER, RING, SUN].into_iter().enumerate() {
        for (i, k) in [
            (base, p.bearing_n_per_m[j]),
            (base + 1, p.bearing_n_per_m[j]),
            (base + 2, p.torsional_n_per_m[j]),
        ] {
            if k > 0.0 {
                let c = damper(k, mass[i]);
                out.push(Element {
                    k,
                    c,
                    g: vec![(i, 1.0)],
                    mesh: None,
                    gap_m: 0.0,
                });
            }
        }
    }
    out
}
