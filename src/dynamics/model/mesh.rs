//! One mesh of the train: its pairs in contact, their springs and damper, the contact
//! and friction of each pair, and the generalised forces the mesh puts on its two gears
//! (paper eq. 2-7).

use super::{MeshFrame, MeshOperating, MeshParts, MeshSprings, MeshState, MAX_PAIRS};
use crate::config::case::LoadSharingModel;
use crate::contact::friction::XuConstants;
use crate::contact::hertz::{effective_radius_m, HertzContact};
use crate::contact::kinematics::SurfaceKinematics;
use crate::contact::load_sharing::pedrero_shares;
use crate::dynamics::assembly::MeshGeometry;
use crate::dynamics::drive::Drive;
use crate::dynamics::tooth_mesh::ToothMesh;
use crate::stiffness::helical_lead::LineGapTable;

/// One mesh of a [`super::GearSystem`]: what it is made of, where it acts and its
/// operating point.
pub struct TrainMesh<'a> {
    /// What the mesh was assembled from.
    pub parts: MeshParts<'a>,
    /// Mesh damping c_m, N s/m.
    pub mesh_damping_n_s_per_m: f64,
    /// Where the mesh acts in the assembled coordinates.
    pub geometry: MeshGeometry,
    /// The mesh's operating point (nominal speeds, torques, static force, damping ratio).
    pub operating: MeshOperating,
    /// Nominal speed of the drive's input, rad/s (the reference of a [`Drive`]).
    pub(super) input_speed_rad_s: f64,
    /// The friction law's terms of the viscosity and roughness (constant here).
    pub(super) xu: XuConstants,
    pub(super) drive: Option<&'a Drive>,
}

/// Effective radius (m) of a contact whose flanks' curvature changed by `dk` (1/m) from
/// the involutes' 1/rho1 + 1/rho2 (severe wear, `contact::worn_curvature`). A worn flank
/// that turns conformal has no Hertz line contact: 1/R is kept at least a tenth of the
/// involutes' (the radius at most ten times theirs; docs/MODEL.md, section 9).
fn worn_radius(rho1: f64, rho2: f64, dk: f64) -> f64 {
    let k0 = 1.0 / rho1 + 1.0 / rho2;
    1.0 / (k0 + dk).max(0.1 * k0)
}

impl TrainMesh<'_> {
    /// Nominal pinion speed over the drive's, when they differ (a later stage).
    fn drive_angle(&self, d: &Drive, t_s: f64) -> f64 {
        let (ws, w_in) = (self.operating.speeds_rad_s[0], self.input_speed_rad_s);
        if ws == w_in {
            d.angle(t_s)
        } else {
            d.angle(t_s) * ws / w_in
        }
    }

    /// Mesh phase (rad of pinion rotation) at time t: the nominal rotation Omega_p t.
    ///
    /// The stiffness and contact positions follow the nominal angle; the vibratory part
    /// phi_p (~1e-5 rad against a 0.33 rad mesh period) is neglected there, the standard
    /// time-varying-stiffness approximation (docs/MODEL.md).
    #[inline]
    pub fn phase_at(&self, t_s: f64) -> f64 {
        match self.drive {
            Some(d) => self.drive_angle(d, t_s),
            None => self.operating.speeds_rad_s[0] * t_s,
        }
    }

    /// Nominal pinion and gear speeds at time t, rad/s.
    #[inline]
    pub fn nominal_speeds(&self, t_s: f64) -> (f64, f64) {
        let [ws, wg] = self.operating.speeds_rad_s;
        match self.drive {
            Some(d) => {
                let w = if ws == self.input_speed_rad_s {
                    d.speed(t_s)
                } else {
                    d.speed(t_s) * ws / self.input_speed_rad_s
                };
                (w, w * wg / ws)
            }
            None => (ws, wg),
        }
    }

    /// Run-out of a tooth-resolved mesh at time t (`ToothMesh::runout_at`, which follows
    /// the constant operating speed): under a drive, at the time the constant speed
    /// reaches the drive's angle, its rate scaled by the drive's speed.
    fn runout_at(&self, tm: &ToothMesh, t_s: f64) -> (f64, f64) {
        match self.drive {
            None => tm.runout_at(t_s),
            Some(_) => {
                let w = self.operating.speeds_rad_s[0];
                let (e, de) = tm.runout_at(self.phase_at(t_s) / w);
                (e, de * self.nominal_speeds(t_s).0 / w)
            }
        }
    }

    /// The pairs in contact at time t and the force of their springs and damper, for
    /// generalised displacements q and velocities v (paper eq. 2 with the wear gaps and
    /// the external error): what decides the contact mode and the mesh force. The pairs
    /// and the mode are decided as `frame` says.
    pub fn springs(&self, frame: MeshFrame, t_s: f64, q: &[f64], v: &[f64]) -> MeshSprings {
        let mut sp = MeshSprings::default();
        for (i, g) in &self.geometry.gradient {
            sp.deflection_m += g * q[*i];
            sp.deflection_rate_m_per_s += g * v[*i];
        }
        if let Some(tm) = self.parts.teeth {
            return self.springs_resolved(tm, frame, t_s, sp);
        }
        if let Some(table) = self.parts.contact.lead_gaps() {
            return self.springs_lead(table, frame, t_s, sp);
        }
        let phase = self.phase_at(t_s);
        let omega_nom = self.nominal_speeds(t_s).0;
        let rb1 = self.parts.pair.pinion.base_radius_m;
        let (e_ext, de_ext) = self.parts.external.at(phase);
        let frozen = frame.mode;
        let decide = frame.decision_time_s.map_or(phase, |t| self.phase_at(t));
        let mut gap_rate_weighted = 0.0;
        let contact = self.parts.contact;
        let pairs = self
            .parts
            .pair
            .pairs_in_reach_decided(contact.reach(), phase, decide);
        for (_, rho1) in pairs {
            let n = sp.n_pairs;
            if n == MAX_PAIRS {
                break;
            }
            let pp = contact.plain_pair(self.parts.mesh, self.parts.gap, rho1);
            let (k, g_wear, dg_drho) = (pp.stiffness_n_per_m, pp.gap_m, pp.gap_slope);
            // Effective gap of this pair: wear gap minus the external error (eq. 2 sign).
            let gap = g_wear - e_ext;
            let c = sp.deflection_m - gap;
            sp.rho1_m[n] = pp.contact_rho1_m;
            sp.corner[n] = pp.corner;
            sp.width_loss[n] = pp.width_loss;
            sp.stiffness_n_per_m[n] = k;
            sp.compression_m[n] = c;
            if frozen.map_or(c > 0.0, |m| m.touches(n)) {
                sp.touching[n] = true;
                sp.elastic_n += k * c;
                sp.stiffness_touching_n_per_m += k;
                gap_rate_weighted += k * (dg_drho * rb1 * omega_nom - de_ext * omega_nom);
            }
            sp.n_pairs += 1;
        }
        self.close_springs(sp, gap_rate_weighted, frame)
    }

    /// The force of the touching pairs' springs and damper and whether the mesh pushes,
    /// given their stiffness-weighted gap rate (N/s).
    fn close_springs(
        &self,
        mut sp: MeshSprings,
        gap_rate_weighted: f64,
        frame: MeshFrame,
    ) -> MeshSprings {
        // Mesh damping acts on the closing rate of the touching pairs (eq. 2, c_m term
        // with de_t/dt); the mesh cannot pull: F >= 0 (contact loss). Within a step of
        // frozen mode the laws continue smoothly past their switches (F may go slightly
        // negative) until the step is cut at the switch (docs/MODEL.md, section 4).
        let k_touch = sp.stiffness_touching_n_per_m;
        if k_touch > 0.0 {
            let closing = sp.deflection_rate_m_per_s - gap_rate_weighted / k_touch;
            sp.force_unclipped_n = sp.elastic_n + self.mesh_damping_n_s_per_m * closing;
        }
        sp.pushing = k_touch > 0.0 && frame.mode.map_or(sp.force_unclipped_n > 0.0, |m| m.pushing);
        sp
    }

    /// [`TrainMesh::springs`] of a helical pair's contact lines with lead gaps across the
    /// face (docs/MODEL.md 11.1): each line's force is its slices',
    /// F_l = sum_j k_j (c - G_j)+ (`LineGapTable::force`), so slices open one by one; a
    /// line touches while its compression c = delta - (g - e) is above the smallest gap of
    /// the face (0). The touching stiffness (the Jacobian's) is the tangent dF_l/dc; the
    /// pair's stiffness the secant F_l / c (the tangent where c <= 0), so that the load
    /// shares k_i c_i / sum of the forces are the lines' forces'. Kept out of line (cold):
    /// the unmodified meshes' `springs` stays as small as it was.
    #[cold]
    #[inline(never)]
    fn springs_lead(
        &self,
        table: &LineGapTable,
        frame: MeshFrame,
        t_s: f64,
        mut sp: MeshSprings,
    ) -> MeshSprings {
        let phase = self.phase_at(t_s);
        let (e_ext, de_ext) = self.parts.external.at(phase);
        let frozen = frame.mode;
        let decide = frame.decision_time_s.map_or(phase, |t| self.phase_at(t));
        let contact = self.parts.contact;
        let omega_nom = self.nominal_speeds(t_s).0;
        let rb1 = self.parts.pair.pinion.base_radius_m;
        let mut gap_rate_weighted = 0.0;
        for (_, rho1) in self
            .parts
            .pair
            .pairs_in_reach_decided(contact.reach(), phase, decide)
            .take(MAX_PAIRS)
        {
            let n = sp.n_pairs;
            let pp = contact.plain_pair(self.parts.mesh, self.parts.gap, rho1);
            let c = sp.deflection_m - (pp.gap_m - e_ext);
            let touching = frozen.map_or(c > 0.0, |m| m.touches(n));
            let (f, k) = table.force(rho1, c, touching);
            sp.rho1_m[n] = pp.contact_rho1_m;
            sp.width_loss[n] = pp.width_loss;
            sp.stiffness_n_per_m[n] = if c > 0.0 { f / c } else { k };
            sp.compression_m[n] = c;
            if touching {
                sp.touching[n] = true;
                sp.elastic_n += f;
                sp.stiffness_touching_n_per_m += k;
                gap_rate_weighted += k * (pp.gap_slope * rb1 * omega_nom - de_ext * omega_nom);
            }
            sp.n_pairs += 1;
        }
        self.close_springs(sp, gap_rate_weighted, frame)
    }

    /// [`TrainMesh::springs`] of a tooth-resolved mesh: each pair's teeth from its mesh
    /// cycle (`dynamics::tooth_mesh`), the run-out common to all pairs.
    fn springs_resolved(
        &self,
        tm: &ToothMesh,
        frame: MeshFrame,
        t_s: f64,
        mut sp: MeshSprings,
    ) -> MeshSprings {
        let phase = self.phase_at(t_s);
        let omega_nom = self.nominal_speeds(t_s).0;
        let rb1 = self.parts.pair.pinion.base_radius_m;
        let (e_ext, de_ext) = self.parts.external.at(phase);
        let (e_run, de_run) = self.runout_at(tm, t_s);
        let frozen = frame.mode;
        let decide = frame.decision_time_s.map_or(phase, |t| self.phase_at(t));
        let cycle_now = self.parts.pair.mesh_cycle(decide);
        let mut gap_rate_weighted = 0.0;
        let contact = self.parts.contact;
        let pairs = self
            .parts
            .pair
            .pairs_in_reach_decided(contact.reach(), phase, decide);
        for (k, rho1) in pairs {
            let n = sp.n_pairs;
            if n == MAX_PAIRS {
                break;
            }
            let cycle = cycle_now - k;
            let pp = tm.pair_in(self.parts.mesh, contact, cycle, rho1);
            let gap = pp.gap_m - e_ext - e_run;
            let c = sp.deflection_m - gap;
            sp.rho1_m[n] = contact.contact_rho1_m(rho1);
            sp.corner[n] = pp.corner;
            sp.stiffness_n_per_m[n] = pp.stiffness_n_per_m;
            sp.compression_m[n] = c;
            sp.cycle[n] = cycle;
            sp.width_loss[n] = pp.width_loss;
            sp.curvature_change[n] = pp.curvature_change_per_m;
            if frozen.map_or(c > 0.0, |m| m.touches(n)) {
                let k = pp.stiffness_n_per_m;
                sp.touching[n] = true;
                sp.elastic_n += k * c;
                sp.stiffness_touching_n_per_m += k;
                gap_rate_weighted +=
                    k * (pp.gap_slope * rb1 * omega_nom - de_ext * omega_nom - de_run);
            }
            sp.n_pairs += 1;
        }
        self.close_springs(sp, gap_rate_weighted, frame)
    }

    /// Mesh state at time t for generalised displacements q and velocities v, the
    /// contact decided as `frame` says.
    pub fn mesh_state(&self, frame: MeshFrame, t_s: f64, q: &[f64], v: &[f64]) -> MeshState {
        let mut ms = MeshState::default();
        self.mesh_state_into(frame, t_s, q, v, &mut ms);
        ms
    }

    /// [`TrainMesh::mesh_state`] written over `ms` field by field (no copy of the whole
    /// state: this runs in every right-hand side). Entries of the pairs past `n_pairs` are
    /// zero, as in a new state.
    pub fn mesh_state_into(
        &self,
        frame: MeshFrame,
        t_s: f64,
        q: &[f64],
        v: &[f64],
        ms: &mut MeshState,
    ) {
        let sp = self.springs(frame, t_s, q, v);
        let n = sp.n_pairs;
        ms.n_pairs = n;
        ms.rho1_m = sp.rho1_m;
        ms.stiffness_n_per_m = sp.stiffness_n_per_m;
        ms.deflection_m = sp.deflection_m;
        // The pairs on the path, and the corners beyond it that touch.
        ms.stiffness_total_n_per_m = (0..n)
            .filter(|i| !sp.corner[*i] || sp.touching[*i])
            .map(|i| sp.stiffness_n_per_m[i])
            .sum();
        ms.stiffness_touching_n_per_m = sp.stiffness_touching_n_per_m;
        ms.compression_m = sp.compression_m;
        ms.force_unclipped_n = sp.force_unclipped_n;
        ms.pushing = sp.pushing;
        ms.force_n = if sp.pushing {
            sp.force_unclipped_n
        } else {
            0.0
        };
        ms.cycle = sp.cycle;
        ms.width_loss = sp.width_loss;
        ms.curvature_change = sp.curvature_change;
        ms.corner = sp.corner;
        // One loop over the few pairs past n (a fill per array would call memset).
        for i in n..MAX_PAIRS {
            ms.share[i] = 0.0;
            ms.load_n[i] = 0.0;
            ms.pressure_pa[i] = 0.0;
            ms.half_width_m[i] = 0.0;
            ms.friction_coefficient[i] = 0.0;
            ms.friction_n[i] = 0.0;
            ms.sliding_m_per_s[i] = 0.0;
        }
        let (nominal_p, nominal_g) = self.nominal_speeds(t_s);
        let [rp, rg] = self.geometry.rotation;
        let omega_p = nominal_p + v[rp];
        let omega_g = nominal_g + v[rg];
        let stiffness_shares = (sp.elastic_n > 0.0).then(|| {
            let mut sh = [0.0; MAX_PAIRS];
            for i in (0..n).filter(|i| sp.touching[*i]) {
                sh[i] = sp.stiffness_n_per_m[i] * sp.compression_m[i] / sp.elastic_n;
            }
            sh
        });
        self.fill_contacts(ms, stiffness_shares, omega_p, omega_g);
    }

    /// Per-pair shares, loads, Hertz contact and friction for a mesh state whose pairs
    /// (`rho1_m`, `n_pairs`) and force are set. `stiffness_shares` are the shares by
    /// pair compression (used by `LoadSharingModel::Stiffness`); `omega_*` the actual
    /// pinion and gear speeds, rad/s (eq. 5).
    pub fn fill_contacts(
        &self,
        ms: &mut MeshState,
        stiffness_shares: Option<[f64; MAX_PAIRS]>,
        omega_p: f64,
        omega_g: f64,
    ) {
        let n = ms.n_pairs;
        match self.parts.load_sharing {
            // By the contact set decided (pairs ordered from the last to enter).
            LoadSharingModel::Pedrero => {
                pedrero_shares(self.parts.pair, &ms.rho1_m[..n], &mut ms.share[..n])
            }
            // `Auto` was resolved when the system was assembled and never reaches here.
            LoadSharingModel::Stiffness | LoadSharingModel::Auto => {
                ms.share[..n].copy_from_slice(&stiffness_shares.unwrap_or_default()[..n])
            }
        }
        // The normal section's radius over the transverse one (helical lines,
        // docs/MODEL.md 11.1; exactly 1 on a spur pair, so 1 x R there), read once.
        let normal = self.parts.contact.normal_radius_factor();
        for i in 0..n {
            // A pair load below zero exists only inside a step whose frozen contact mode
            // is about to switch; the contact and friction see no load then.
            let w = (ms.share[i] * ms.force_n).max(0.0);
            ms.load_n[i] = w;
            let rho1 = ms.rho1_m[i];
            let rho2 = self.parts.pair.rho_gear(rho1);
            let width = self.parts.pair.face_width_m * (1.0 - ms.width_loss[i]);
            let e_star = self.parts.effective_modulus_pa;
            let radius = match ms.curvature_change[i] {
                0.0 => effective_radius_m(rho1, rho2),
                dk => worn_radius(rho1, rho2, dk),
            };
            let hz = HertzContact::with_radius(w, width, normal * radius, e_star);
            ms.pressure_pa[i] = hz.max_pressure_pa;
            ms.half_width_m[i] = hz.half_width_m;
            let kin = SurfaceKinematics::new(omega_p, omega_g, rho1, rho2);
            let u_s = kin.sliding_velocity_m_per_s();
            ms.sliding_m_per_s[i] = u_s;
            let mu = self.parts.friction.coefficient_with(&hz, &kin, &self.xu);
            ms.friction_coefficient[i] = mu;
            // Positive when the pinion surface is faster; acts on the pinion along +e.
            ms.friction_n[i] = mu * w * self.parts.friction.direction(u_s);
        }
    }

    /// The resultant of the pairs' friction forces: their sum F_f (N, on the pinion along
    /// +e) and its moments about the pinion's and the gear's centres, sum(rho1_i F_f,i) and
    /// sum(rho2_i F_f,i) (N m; paper eq. (1), the friction terms of the rotations). Summed
    /// pair by pair in one order, so both force paths give the same bits.
    #[inline]
    pub(crate) fn friction_resultant(&self, ms: &MeshState) -> [f64; 3] {
        let (mut f_sum, mut m_p, mut m_g) = (0.0, 0.0, 0.0);
        for i in 0..ms.n_pairs {
            let f = ms.friction_n[i];
            f_sum += f;
            m_p += ms.rho1_m[i] * f;
            m_g += self.parts.pair.rho_gear(ms.rho1_m[i]) * f;
        }
        [f_sum, m_p, m_g]
    }

    /// Adds the generalised forces of the mesh (normal force and friction) for a mesh
    /// state to `forces` (one entry per coordinate).
    #[inline]
    pub fn add_forces(&self, ms: &MeshState, forces: &mut [f64]) {
        let g = &self.geometry;
        for (i, gi) in &g.gradient {
            forces[*i] += -ms.force_n * gi;
        }
        let [f_sum, m_p, m_g] = self.friction_resultant(ms);
        // Friction along e on the pinion, opposite on the gear.
        let [ex, ey] = g.tangent;
        if let Some(x) = g.lateral[0] {
            forces[x] += f_sum * ex;
            forces[x + 1] += f_sum * ey;
        }
        if let Some(x) = g.lateral[1] {
            forces[x] -= f_sum * ex;
            forces[x + 1] -= f_sum * ey;
        }
        forces[g.rotation[0]] -= m_p;
        forces[g.rotation[1]] += m_g;
    }
}
