//! The time-varying stiffness of every mesh of a planetary set in the carrier's frame:
//! each sun-planet mesh k_sn(t) and ring-planet mesh k_rn(t) from the potential-energy
//! tables (`mesh::MeshStiffness` for the external sun-planet pair, `internal` for the
//! ring-planet pair), shifted by the relative mesh phases of Parker & Lin (2004, "Mesh
//! phasing relationships in planetary and epicyclic gears", J. Mech. Des. 126, 365),
//! docs/MODEL.md section 12.4:
//!   k_sn(t) = k_s(t - gamma_sn T_m),   k_rn(t) = k_r(t - gamma_rn T_m - gamma_rs T_m),
//! with T_m the mesh period, gamma_sn = frac(z_s psi_n / 2 pi), gamma_rn = frac(-z_r
//! psi_n / 2 pi) and gamma_rs the ring-to-sun phase of one planet (`geometry::planetary`).
//!
//! Time is counted in mesh cycles c = f_m t (f_m the mesh frequency, the same for every
//! mesh of the set). The reference event c = 0 is planet 1's sun mesh at its pitch point:
//! a pair of the sun mesh entered contact (a_s = (rho_pitch - rho_start) / p_b) cycles
//! earlier, so the sun table's phase (sun rotation relative to the carrier since a pair
//! entered contact) is 2 pi / z_s (c - gamma_sn + a_s); the ring table's (planet rotation
//! relative to the carrier since a pair entered) 2 pi / z_p (c - gamma_rn - gamma_rs + a_r).

use super::internal::InternalMeshStiffness;
use super::mesh::MeshStiffness;
use crate::geometry::planetary::PlanetarySet;
use std::f64::consts::PI;

/// Points of the ring pair's stiffness table along its path of contact: k_pair is smooth
/// there (its curvature over the path is a few per cent of its value), so linear
/// interpolation on 256 intervals errs by ~1e-6 relative, far below the method's own error.
const RING_TABLE_POINTS: usize = 257;

/// The member a [`MeshFault`] is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaultMember {
    /// The sun: every planet's sun mesh meets the tooth.
    Sun,
    /// Planet n (0-based): its sun and ring meshes meet the tooth.
    Planet(usize),
    /// The ring: every planet's ring mesh meets the tooth.
    Ring,
}

impl FaultMember {
    /// Its name in the outputs: `sun`, `planet 2` (counted from 1), `ring`.
    pub fn name(self) -> String {
        match self {
            FaultMember::Sun => "sun".to_string(),
            FaultMember::Planet(n) => format!("planet {}", n + 1),
            FaultMember::Ring => "ring".to_string(),
        }
    }
}

/// A tooth fault on one member: the compliance it adds to a pair holding the tooth, m/N,
/// at `RING_TABLE_POINTS` equally spaced rho1 along each mesh's path of contact (the
/// sun's flank for the sun mesh, the planet's for the ring mesh; `None`: that mesh never
/// meets the tooth), and where on each path such a pair touches at all (a broken tip's
/// cut; outside it the pair carries nothing, as a pair's broken tip, docs/MODEL.md 9.5),
/// built by `study::planetary_fault`.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshFault {
    /// The member with the faulty tooth.
    pub member: FaultMember,
    /// The faulty tooth's index on its member.
    pub tooth: usize,
    /// Added compliance on the sun mesh's path, m/N.
    pub sun_m_per_n: Option<Vec<f64>>,
    /// Added compliance on the ring mesh's path, m/N.
    pub ring_m_per_n: Option<Vec<f64>>,
    /// The rho1 interval [lo, hi] of the sun mesh's path (m) where a pair holding the
    /// tooth touches; None: all of it.
    pub sun_contact_rho1_m: Option<[f64; 2]>,
    /// As `sun_contact_rho1_m` on the ring mesh's path (rho1 on the planet's flank), m.
    pub ring_contact_rho1_m: Option<[f64; 2]>,
}

/// Which tooth of each member a pair holds (module docs): per planet the whole parts of
/// z_s psi_n / 2 pi and of -z_r psi_n / 2 pi and R_n, and the teeth of sun, planet, ring.
#[derive(Debug, Clone, PartialEq)]
pub struct FaultTeeth {
    /// round(z_s psi_n / 2 pi - gamma_sn) per planet (its whole part, rounding-safe): sun tooth i meets planet n at the pitch point
    /// at c = i + z_s psi_n / 2 pi (+ multiples of z_s), when the sun has turned by
    /// psi_n relative to the carrier.
    pub sun_whole: Vec<i64>,
    /// R_n per planet: a planet tooth that passes the sun mesh's pitch point at c passes
    /// the ring mesh's at c + R_n + (gamma_rn + gamma_rs - gamma_sn), the loaded flanks
    /// half a planet turn apart less the teeth's half angles (`ring_sun_phase`).
    pub ring_to_planet: Vec<i64>,
    /// round(-z_r psi_n / 2 pi - gamma_rn) per planet (its whole part, rounding-safe):
    /// ring tooth j passes planet n's ring-mesh pitch point at c = gamma_rs + j - z_r
    /// psi_n / 2 pi (+ multiples of z_r), the ring turning against the sun relative to the
    /// carrier (docs/MODEL.md 12.14), so the ring pair of planet n that entered contact at
    /// the table's cycle M holds ring tooth (M - ring_whole_n) mod z_r.
    pub ring_whole: Vec<i64>,
    /// Teeth z_s, z_p and z_r.
    pub teeth: [i64; 3],
}

impl FaultTeeth {
    /// The teeth of `set` (module docs).
    pub fn of(set: &PlanetarySet) -> Self {
        let zs = set.teeth_sun() as f64;
        let zr = set.teeth_ring() as f64;
        let gs = set.sun_planet_phases();
        let gr = set.ring_planet_phases();
        let gamma_rs = set.ring_sun_phase();
        let g_whole = set.ring_sun_cycles();
        Self {
            sun_whole: set
                .planet_angles_rad
                .iter()
                .zip(&gs)
                .map(|(psi, g)| (zs * psi / (2.0 * PI) - g).round() as i64)
                .collect(),
            ring_to_planet: gs
                .iter()
                .zip(&gr)
                .map(|(s, r)| -(s + g_whole - r - gamma_rs).round() as i64)
                .collect(),
            ring_whole: set
                .planet_angles_rad
                .iter()
                .zip(&gr)
                .map(|(psi, g)| (-zr * psi / (2.0 * PI) - g).round() as i64)
                .collect(),
            teeth: [
                set.teeth_sun() as i64,
                set.teeth_planet() as i64,
                set.teeth_ring() as i64,
            ],
        }
    }
}

impl FaultTeeth {
    /// Whether the pair of planet `planet`'s sun (`ring` false) or ring mesh that entered
    /// contact at the table's cycle `entered` holds tooth `tooth` of `member` (module
    /// docs: a sun tooth meets every planet's sun mesh, a ring tooth every ring mesh, a
    /// planet's tooth its own two meshes).
    pub fn holds(
        &self,
        member: FaultMember,
        tooth: usize,
        planet: usize,
        ring: bool,
        entered: i64,
    ) -> bool {
        self.tooth_of(member, planet, ring, entered) == Some(tooth)
    }

    /// The tooth of `member` that the pair of [`Self::holds`] holds (0-based); None when
    /// that mesh never meets `member`'s teeth.
    pub fn tooth_of(
        &self,
        member: FaultMember,
        planet: usize,
        ring: bool,
        entered: i64,
    ) -> Option<usize> {
        let t = match (member, ring) {
            (FaultMember::Sun, false) => {
                (entered - self.sun_whole[planet]).rem_euclid(self.teeth[0])
            }
            (FaultMember::Ring, true) => {
                (entered - self.ring_whole[planet]).rem_euclid(self.teeth[2])
            }
            (FaultMember::Planet(n), false) if n == planet => entered.rem_euclid(self.teeth[1]),
            (FaultMember::Planet(n), true) if n == planet => {
                (entered + self.ring_to_planet[planet]).rem_euclid(self.teeth[1])
            }
            _ => return None,
        };
        Some(t as usize)
    }
}

/// Every mesh's stiffness over time in the carrier frame (see module docs).
#[derive(Debug, Clone)]
pub struct PlanetaryMeshes {
    sun: MeshStiffness,
    /// k_pair of the ring mesh at RING_TABLE_POINTS equally spaced rho1 (planet side), N/m.
    ring_pair_n_per_m: Vec<f64>,
    ring_rho_start_m: f64,
    ring_rho_end_m: f64,
    ring_base_pitch_m: f64,
    ring_mean_n_per_m: f64,
    /// Phase offsets (mesh cycles) added to c for each planet's sun and ring mesh.
    sun_offset: Vec<f64>,
    ring_offset: Vec<f64>,
    teeth_sun: f64,
    /// Where a pair of the sun mesh and of the ring mesh leaves contact, mesh cycles after
    /// a pair entered: frac(epsilon) of each (0 for an integer contact ratio).
    leave_cycles: [f64; 2],
    /// The sun path's first rho1 and its length, m (the fault tables' abscissa).
    sun_path_m: [f64; 2],
    /// A tooth fault and the teeth each pair holds (None: every tooth alike).
    fault: Option<(MeshFault, FaultTeeth)>,
}

impl PlanetaryMeshes {
    /// The meshes of `set` from its sun-planet table and ring-planet model.
    pub fn new(set: &PlanetarySet, sun: &MeshStiffness, ring: &InternalMeshStiffness) -> Self {
        let rp = &set.ring_planet;
        let (r0, r1) = (rp.rho_start_m, rp.rho_end_m);
        let n = RING_TABLE_POINTS - 1;
        let ring_pair_n_per_m = (0..=n)
            .map(|i| ring.pair_stiffness_n_per_m(r0 + (r1 - r0) * i as f64 / n as f64))
            .collect();
        let sp = &set.sun_planet;
        let a_s = (sp.rho_pitch_m - sp.rho_start_m) / sp.base_pitch_m;
        let a_r = (rp.rho_pitch_m - rp.rho_start_m) / rp.base_pitch_m;
        let gamma_rs = set.ring_sun_phase();
        Self {
            sun: sun.clone(),
            ring_pair_n_per_m,
            ring_rho_start_m: r0,
            ring_rho_end_m: r1,
            ring_base_pitch_m: rp.base_pitch_m,
            ring_mean_n_per_m: ring.mean_stiffness_n_per_m(),
            sun_offset: set.sun_planet_phases().iter().map(|g| a_s - g).collect(),
            ring_offset: set
                .ring_planet_phases()
                .iter()
                .map(|g| a_r - g - gamma_rs)
                .collect(),
            teeth_sun: set.teeth_sun() as f64,
            leave_cycles: [sp.contact_ratio, (r1 - r0) / rp.base_pitch_m].map(|e| e - e.floor()),
            sun_path_m: [sp.rho_start_m, sp.rho_end_m - sp.rho_start_m],
            fault: None,
        }
    }

    /// The same meshes with the tooth fault `fault` of `set` (module docs).
    pub fn with_fault(mut self, set: &PlanetarySet, fault: MeshFault) -> Self {
        self.fault = Some((fault, FaultTeeth::of(set)));
        self
    }

    /// The same meshes with every tooth alike (the fault left out).
    pub fn without_fault(&self) -> Self {
        Self {
            fault: None,
            ..self.clone()
        }
    }

    /// The tooth fault, if any.
    pub fn fault(&self) -> Option<&MeshFault> {
        self.fault.as_ref().map(|(f, _)| f)
    }

    /// Whether pair `k` (counted from the newest, as [`Self::sun_pairs_decided`] and
    /// [`Self::ring_pairs_decided`] yield them, decided at `cycles`) of planet `planet`'s
    /// sun (`ring` false) or ring mesh at `cycles` holds tooth `tooth` of `member`; None
    /// for a set without a tooth fault (its teeth are not told apart).
    pub fn pair_holds(
        &self,
        at: (usize, bool),
        cycles: f64,
        k: usize,
        (member, tooth): (FaultMember, usize),
    ) -> Option<bool> {
        self.fault.as_ref()?;
        Some(self.pair_tooth(at, cycles, k, member) == Some(tooth))
    }

    /// The tooth of `member` that pair `k` of [`Self::pair_holds`] holds; None without a
    /// tooth fault or when that mesh never meets `member`'s teeth.
    pub fn pair_tooth(
        &self,
        (planet, ring): (usize, bool),
        cycles: f64,
        k: usize,
        member: FaultMember,
    ) -> Option<usize> {
        let (_, t) = self.fault.as_ref()?;
        let off = if ring {
            self.ring_offset[planet]
        } else {
            self.sun_offset[planet]
        };
        let entered = (cycles + off).floor() as i64 - k as i64;
        t.tooth_of(member, planet, ring, entered)
    }

    /// Mesh cycles over which every mesh's stiffness repeats: 1 with every tooth alike,
    /// z_s with a faulty sun tooth (it meets each planet once per sun revolution relative
    /// to the carrier), z_p with a faulty planet tooth (once per planet revolution), z_r
    /// with a faulty ring tooth (once per ring revolution relative to the carrier).
    pub fn periods(&self) -> usize {
        match &self.fault {
            None => 1,
            Some((f, t)) => match f.member {
                FaultMember::Sun => t.teeth[0] as usize,
                FaultMember::Planet(_) => t.teeth[1] as usize,
                FaultMember::Ring => t.teeth[2] as usize,
            },
        }
    }

    /// The fault's compliance (m/N) added to the pair of planet `planet`'s sun
    /// (`ring` false) or ring mesh that entered contact at the table's cycle `entered`,
    /// at rho1 (m); 0 when the pair does not hold the faulty tooth; infinite where the
    /// faulty tooth does not touch (a broken tip's removed part: the pair's stiffness in
    /// series, [`in_series`], is then exactly 0).
    fn fault_compliance(&self, planet: usize, ring: bool, entered: i64, rho_m: f64) -> f64 {
        let Some((f, t)) = &self.fault else {
            return 0.0;
        };
        if !t.holds(f.member, f.tooth, planet, ring, entered) {
            return 0.0;
        }
        let (table, contact, start, len) = if ring {
            (
                &f.ring_m_per_n,
                f.ring_contact_rho1_m,
                self.ring_rho_start_m,
                self.ring_rho_end_m - self.ring_rho_start_m,
            )
        } else {
            (
                &f.sun_m_per_n,
                f.sun_contact_rho1_m,
                self.sun_path_m[0],
                self.sun_path_m[1],
            )
        };
        if contact.is_some_and(|[lo, hi]| rho_m < lo || rho_m > hi) {
            return f64::INFINITY;
        }
        table
            .as_ref()
            .map_or(0.0, |c| path_table_at(c, (rho_m - start) / len))
    }

    /// Number of planets.
    pub fn planets(&self) -> usize {
        self.sun_offset.len()
    }

    /// Mean stiffness of the sun-planet and the ring-planet mesh over a mesh period, N/m.
    pub fn mean_n_per_m(&self) -> [f64; 2] {
        [self.sun.mean_stiffness_n_per_m(), self.ring_mean_n_per_m]
    }

    /// k_sn at `cycles` mesh cycles since the reference event, N/m.
    pub fn sun_n_per_m(&self, planet: usize, cycles: f64) -> f64 {
        self.sun_n_per_m_decided(planet, cycles, cycles)
    }

    /// k_rn at `cycles` mesh cycles since the reference event, N/m: the ring pairs in
    /// contact (one base pitch apart on the path) in parallel.
    pub fn ring_n_per_m(&self, planet: usize, cycles: f64) -> f64 {
        self.ring_n_per_m_decided(planet, cycles, cycles)
    }

    /// As [`Self::sun_n_per_m`], but which pairs touch is decided at `decide_cycles` (e.g.
    /// the middle of an integration step) while their positions follow `cycles`, as
    /// `GearPair::pairs_in_contact_decided`: a step that ends on a pair entering or
    /// leaving sees one contact set on all its stages.
    pub fn sun_n_per_m_decided(&self, planet: usize, cycles: f64, decide_cycles: f64) -> f64 {
        self.sun_pairs_decided(planet, cycles, decide_cycles)
            .fold(0.0, |k, (_, kp)| k + kp)
    }

    /// As [`Self::ring_n_per_m`] with the pairs in contact decided at `decide_cycles`
    /// (see [`Self::sun_n_per_m_decided`]).
    pub fn ring_n_per_m_decided(&self, planet: usize, cycles: f64, decide_cycles: f64) -> f64 {
        self.ring_pairs_decided(planet, cycles, decide_cycles)
            .fold(0.0, |k, (_, kp)| k + kp)
    }

    /// The tooth pairs of planet `planet`'s sun mesh at `cycles` mesh cycles, the pairs in
    /// contact decided at `decide_cycles` (as [`Self::sun_n_per_m_decided`], whose sum this
    /// splits): each pair's position rho1 on the sun's flank (m) and stiffness (N/m).
    pub fn sun_pairs_decided(
        &self,
        planet: usize,
        cycles: f64,
        decide_cycles: f64,
    ) -> impl Iterator<Item = (f64, f64)> + '_ {
        let off = self.sun_offset[planet];
        let (c, d) = (cycles + off, decide_cycles + off);
        let base = d.floor();
        let rad_per_cycle = 2.0 * PI / self.teeth_sun;
        let newest = base as i64;
        self.sun
            .pair()
            .pairs_in_contact_decided(rad_per_cycle * (c - base), rad_per_cycle * (d - base))
            .map(move |(k, rho)| {
                let k0 = self.sun.pair_stiffness_n_per_m(rho);
                let extra = self.fault_compliance(planet, false, newest - k as i64, rho);
                (rho, in_series(k0, extra))
            })
    }

    /// The tooth pairs of planet `planet`'s ring mesh at `cycles`, decided at
    /// `decide_cycles` (as [`Self::ring_n_per_m_decided`], whose sum this splits): each
    /// pair's position rho1 on the planet's flank (m) and stiffness (N/m).
    pub fn ring_pairs_decided(
        &self,
        planet: usize,
        cycles: f64,
        decide_cycles: f64,
    ) -> impl Iterator<Item = (f64, f64)> + '_ {
        let off = self.ring_offset[planet];
        let (c, d) = (cycles + off, decide_cycles + off);
        let base = d.floor();
        let pb = self.ring_base_pitch_m;
        let rho = self.ring_rho_start_m + pb * (c - base);
        let rho_decide = self.ring_rho_start_m + pb * (d - base);
        let newest = base as i64;
        // Each pair one base pitch on from the last (the sums of `ring_n_per_m_decided`),
        // pair k the one that entered k cycles before the newest.
        std::iter::successors(Some((rho, rho_decide)), move |(r, d)| {
            Some((r + pb, d + pb))
        })
        .take_while(move |(_, d)| *d <= self.ring_rho_end_m + 1e-15)
        .enumerate()
        .map(move |(k, (r, _))| {
            let extra = self.fault_compliance(planet, true, newest - k as i64, r);
            (r, in_series(self.ring_pair_at(r), extra))
        })
    }

    /// The mesh cycles in [0, 1) where some mesh's stiffness jumps (a pair enters or
    /// leaves contact), sorted, those closer than 1e-9 cycles merged: for each planet's
    /// sun (ring) mesh where its table's phase passes 0 (a pair enters at the path's
    /// start) and frac(epsilon) (a pair leaves at its end), c = frac(event - offset); with
    /// a broken tip also where a pair passes its cut ((rho_cut - rho_start) / p_b, every
    /// mesh period: a pair of the faulty tooth passes it in one of them).
    pub fn jump_cycles(&self) -> Vec<f64> {
        let mut v: Vec<f64> = Vec::new();
        let cuts = |contact: Option<[f64; 2]>, start: f64, pitch: f64| -> Vec<f64> {
            contact.map_or(Vec::new(), |c| {
                c.iter()
                    .filter(|r| r.is_finite())
                    .map(|r| (r - start) / pitch)
                    .collect()
            })
        };
        let f = self.fault.as_ref().map(|(f, _)| f);
        let sun_pitch = self.sun.pair().base_pitch_m;
        let sun_cuts = cuts(
            f.and_then(|f| f.sun_contact_rho1_m),
            self.sun_path_m[0],
            sun_pitch,
        );
        let ring_cuts = cuts(
            f.and_then(|f| f.ring_contact_rho1_m),
            self.ring_rho_start_m,
            self.ring_base_pitch_m,
        );
        for (offsets, leave, cut) in [
            (&self.sun_offset, self.leave_cycles[0], &sun_cuts),
            (&self.ring_offset, self.leave_cycles[1], &ring_cuts),
        ] {
            for off in offsets {
                for event in [0.0, leave].iter().chain(cut.iter()).copied() {
                    let c = event - off;
                    let c = c - c.floor();
                    v.push(if c > 1.0 - 1e-9 { 0.0 } else { c });
                }
            }
        }
        v.sort_by(f64::total_cmp);
        v.dedup_by(|b, a| *b - *a < 1e-9);
        v
    }

    /// The ring pair's stiffness at rho1 (m), linear in the table.
    fn ring_pair_at(&self, rho_m: f64) -> f64 {
        let n = (RING_TABLE_POINTS - 1) as f64;
        let x = ((rho_m - self.ring_rho_start_m) / (self.ring_rho_end_m - self.ring_rho_start_m)
            * n)
            .clamp(0.0, n);
        let i = (x as usize).min(RING_TABLE_POINTS - 2);
        let t = x - i as f64;
        self.ring_pair_n_per_m[i] * (1.0 - t) + self.ring_pair_n_per_m[i + 1] * t
    }
}

/// A pair's stiffness k0 (N/m) with a fault's compliance `extra` (m/N) in series: k0
/// itself, bit for bit, when `extra` is 0 (a healthy tooth, a crack of zero depth).
#[inline]
fn in_series(k0: f64, extra: f64) -> f64 {
    if extra == 0.0 {
        k0
    } else {
        1.0 / (1.0 / k0 + extra)
    }
}

/// A fault table's value at the fraction `u` of the path (linear between its equally
/// spaced points, clamped to the path).
fn path_table_at(table: &[f64], u: f64) -> f64 {
    let n = (table.len() - 1) as f64;
    let x = (u * n).clamp(0.0, n);
    let i = (x as usize).min(table.len() - 2);
    let t = x - i as f64;
    table[i] * (1.0 - t) + table[i + 1] * t
}

/// Points of a fault's compliance tables along a path ([`MeshFault`]).
pub const FAULT_TABLE_POINTS: usize = RING_TABLE_POINTS;
