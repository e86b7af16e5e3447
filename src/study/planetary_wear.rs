//! The wear model of a planetary set (`[planetary]`, docs/MODEL.md 12.9): every sun-planet
//! and ring-planet mesh worn by the project's Archard law (paper eq. 14-17,
//! `wear::archard::per_cycle_wear`) from the mesh forces of the set's dynamic model
//! (`study::planetary_dynamics`) or of its quasi-static equilibrium
//! (`PlanetaryDynamic::quasi_static_mesh_forces`), and the members' wear from their
//! meshes'. The loop over updates is `study::planetary_wear_loop`.
//!
//! Meshes, in the dynamic model's order: the sun meshes of planets 1..N (pinion = sun,
//! gear = planet), then their ring meshes (pinion = planet, gear = ring). Each mesh's
//! wear state counts its pinion's revolutions relative to the carrier (a sun tooth meets
//! planet n once per sun revolution relative to the carrier, a planet tooth meets the ring
//! once per planet revolution relative to the carrier), so the Archard increments per
//! pinion cycle and the gear factor z1 / z2 of eq. 17 hold as for a pair.
//!
//! Flanks: the sun's loaded flank meets every planet, so the sun's wear is the sum of its N
//! meshes' pinion wear; likewise the ring's of its N meshes' gear wear. A planet is an
//! idler between sun and ring: the sun loads one flank of its teeth, the ring the other,
//! so its two meshes wear two different flanks and their wear never adds (its limit is the
//! deeper flank; its volume the sum of both).
//!
//! The load of a mesh along its path: its force at each recorded instant split over its
//! tooth pairs in contact by their stiffness and wear gaps (pair i carries
//! k_i max(delta - g_i, 0) with delta the common approach, scaled to the mesh force),
//! with the Hertz band of each pair (Johnson 1985; the internal contact's effective radius
//! rho1 rho2 / (rho2 - rho1), ring concave) and the surface speeds relative to the
//! carrier (the relative motion of two flanks is the same in every frame).

use super::model::ModelError;
use super::planetary_dynamics::PlanetaryDynamics;
use crate::config::case::Case;
use crate::contact::hertz::{effective_modulus_pa, HertzContact};
use crate::dynamics::excitation::PairGap;
use crate::dynamics::planetary_dynamic::MeshStiffnessSource;
use crate::dynamics::planetary_steady::{
    solve_planetary_steady_state, PlanetaryDynamicsError, PlanetarySettings,
};
use crate::dynamics::response::{sorted_by_rho1, PathSample};
use crate::geometry::ProfileGrid;
use crate::stiffness::planetary_mesh::FaultMember;
use crate::wear::{per_cycle_wear, WearIncrement, WearState};
use std::f64::consts::PI;

/// A planetary set's wear model, built once (see the module docs).
#[derive(Debug, Clone)]
pub struct PlanetaryWearModel {
    /// The set's dynamic model (geometry, meshes, speeds, settings).
    pub dynamics: PlanetaryDynamics,
    /// The profile grids of the sun-planet (sun's rho1) and ring-planet (planet's rho1) mesh.
    pub grids: [ProfileGrid; 2],
    /// Effective contact modulus E* of the sun-planet and ring-planet contacts, Pa.
    pub e_star_pa: [f64; 2],
    /// Face widths of the two meshes, m.
    pub face_width_m: [f64; 2],
    /// Speeds relative to the carrier, |w_s - w_c|, |w_p - w_c|, |w_r - w_c|, rad/s.
    pub relative_rad_s: [f64; 3],
    /// Pinion revolutions relative to the carrier per input-member revolution of a sun
    /// mesh (the sun's) and a ring mesh (the planet's).
    pub pinion_cycles_per_input: [f64; 2],
    /// Archard coefficient k, m^2/N.
    pub coefficient_m2_per_n: f64,
}

/// Why the set's force history could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ForceHistoryError {
    /// The stiffness matrix of the quasi-static equilibrium is singular at some instant.
    #[error("the quasi-static equilibrium of the set is singular (a planet lost both its meshes)")]
    Singular,
    /// The dynamic steady state was not found (after the retry with tighter settings).
    #[error(transparent)]
    Dynamics(#[from] PlanetaryDynamicsError),
}

/// The set's force history over a steady mesh period: sample times in mesh cycles and,
/// per sample, every mesh's force (sun meshes 1..N, then ring meshes), N.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceHistory {
    /// Sample times, mesh cycles from the reference event, equally spaced over one period.
    pub cycles: Vec<f64>,
    /// Mesh forces per sample, N.
    pub forces_n: Vec<Vec<f64>>,
}

impl PlanetaryWearModel {
    /// Build from a validated planetary case; what `gearwear wear` does not take yet is an
    /// input error naming the key.
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        if case.wear.worn_geometry != crate::config::case::WornGeometry::Involute {
            return Err(ModelError(vec!["`wear.worn_geometry` = \"worn\" on a planetary set: its meshes take the involute geometry (wear opens gaps) so far; remove the key".into()]));
        }
        let dynamics = PlanetaryDynamics::from_case(case)?;
        let set = &dynamics.study.set;
        let n = case.wear.points_per_profile.max(2) as usize;
        let grids = [
            ProfileGrid::new(&set.sun_planet, n),
            ProfileGrid::internal(&set.ring_planet, n),
        ];
        let m = &case.materials;
        let e_star_pa = [
            effective_modulus_pa(
                m.youngs_modulus_pinion_gpa * 1e9,
                m.poisson_ratio_pinion,
                m.youngs_modulus_gear_gpa * 1e9,
                m.poisson_ratio_gear,
            ),
            effective_modulus_pa(
                m.youngs_modulus_gear_gpa * 1e9,
                m.poisson_ratio_gear,
                m.youngs_modulus_gear_gpa * 1e9,
                m.poisson_ratio_gear,
            ),
        ];
        let [fs, fc, fr] = dynamics.study.speeds_hz;
        let (zs, zp, zr) = (
            set.teeth_sun() as f64,
            set.teeth_planet() as f64,
            set.teeth_ring() as f64,
        );
        // Willis: relative to the carrier the set is the fixed-axis train sun -> planet ->
        // ring, w_p,rel = -(z_s / z_p) w_s,rel and w_r,rel = -(z_s / z_r) w_s,rel.
        let sun_rel = (fs - fc).abs();
        let relative_rad_s = [sun_rel, sun_rel * zs / zp, (fr - fc).abs()].map(|f| 2.0 * PI * f);
        let input = case.operating.input_speed_hz.abs();
        let pinion_cycles_per_input = [sun_rel / input, sun_rel * zs / zp / input];
        debug_assert!(((fr - fc).abs() - sun_rel * zs / zr).abs() <= 1e-9 * sun_rel.max(1.0));
        Ok(Self {
            face_width_m: [set.sun_planet.face_width_m, set.ring_planet.face_width_m],
            dynamics,
            grids,
            e_star_pa,
            relative_rad_s,
            pinion_cycles_per_input,
            coefficient_m2_per_n: case.wear.coefficient_m2_per_n,
        })
    }

    /// Mesh periods the set's force history spans: a tooth fault's period P (z_s, z_p or
    /// z_r, `PlanetaryMeshes::periods`; docs/MODEL.md 12.15), 1 with every tooth alike.
    pub fn periods(&self) -> usize {
        self.dynamics.model.source.periods().max(1)
    }

    /// Number of planets N.
    pub fn planets(&self) -> usize {
        self.dynamics.study.set.planets()
    }

    /// Which of the two meshes mesh `j` is (0 sun-planet, 1 ring-planet) and its planet.
    pub fn kind_of(&self, j: usize) -> (usize, usize) {
        let n = self.planets();
        (j / n, j % n)
    }

    /// Tooth counts (pinion, gear) of mesh kind `kind` (0 sun-planet, 1 ring-planet).
    pub fn teeth(&self, kind: usize) -> [usize; 2] {
        let set = &self.dynamics.study.set;
        match kind {
            0 => [set.teeth_sun(), set.teeth_planet()],
            _ => [set.teeth_planet(), set.teeth_ring()],
        }
    }

    /// Why the quasi-static wear model cannot run the set's new teeth: a tooth fault that
    /// leaves a planet's mesh with no tooth pair at some instant (a broken tip cut deep)
    /// frees the planet's rotation, and its equilibrium is singular; the dynamic model,
    /// with the planet's inertia, runs it. Names the fault's keys; None when it runs.
    pub fn quasi_static_problem(&self) -> Option<String> {
        let fault = self.dynamics.study.section.active_fault()?;
        match self.force_history(false, &[]) {
            Err(ForceHistoryError::Singular) => Some(format!(
                "`planetary.fault.kind` = \"{}\" on {}{}: a planet is left with no tooth pair in contact on one of its meshes at some instant, so the set's quasi-static equilibrium is singular (the planet turns freely) and the quasi-static wear model cannot run it: run the dynamic wear model only, or remove less of the tooth",
                fault.kind.name(),
                fault.who(),
                fault
                    .removed_height_mm
                    .map_or(String::new(), |h| format!(" with `planetary.fault.removed_height_mm` = {h}")),
            )),
            _ => None,
        }
    }

    /// The steady force history of the set with every mesh's wear gap `gaps` (module
    /// order): dynamic (`dynamic` true; retried once from scratch with a ten times tighter
    /// integration tolerance, twice the samples and periods, as `wear_loop::solve_by`) or
    /// quasi-static at `numerics.steps_per_mesh_period` instants of each mesh period (at
    /// least 8, as the dynamic model samples it: `study::planetary_dynamics`), over the
    /// [`Self::periods`] mesh periods the response repeats over.
    pub fn force_history(
        &self,
        dynamic: bool,
        gaps: &[PairGap],
    ) -> Result<ForceHistory, ForceHistoryError> {
        let mut sys = self.dynamics.model.clone();
        if gaps.iter().any(|g| !g.is_zero()) {
            sys.set_wear_gaps(gaps.to_vec());
        }
        let s = self.dynamics.settings;
        if !dynamic {
            let k = s.samples_per_period;
            let cycles: Vec<f64> = (0..k * self.periods())
                .map(|i| i as f64 / k as f64)
                .collect();
            let forces_n = cycles
                .iter()
                .map(|c| sys.quasi_static_mesh_forces(*c))
                .collect::<Option<Vec<_>>>()
                .ok_or(ForceHistoryError::Singular)?;
            return Ok(ForceHistory { cycles, forces_n });
        }
        let tight = PlanetarySettings {
            integration_tolerance: 0.1 * s.integration_tolerance,
            samples_per_period: 2 * s.samples_per_period,
            max_periods: 2 * s.max_periods,
            ..s
        };
        let r = solve_planetary_steady_state(&mut sys, &s)
            .or_else(|_| solve_planetary_steady_state(&mut sys, &tight))?;
        let f_m = sys.mesh_frequency_hz;
        Ok(ForceHistory {
            cycles: r.times_s.iter().map(|t| t * f_m).collect(),
            forces_n: r.mesh_forces_n,
        })
    }

    /// Mesh `j`'s contacts along its path over the history `h` (see the module docs),
    /// sorted by rho1: the pairs' loads, Hertz bands and surface speeds relative to the
    /// carrier. `gap` is the mesh's wear gap on its path.
    pub fn mesh_path(&self, j: usize, h: &ForceHistory, gap: &PairGap) -> Vec<PathSample> {
        self.paths_over(j, (&h.cycles, &h.forces_n), gap, None)
            .pop()
            .unwrap_or_default()
    }

    /// Mesh `j`'s contacts at the instants `cycles` with the mesh forces `forces` (N), as
    /// [`Self::mesh_path`]: one path of every pair, or with `by_tooth` = (member, its
    /// teeth z) z paths, path t of the pairs holding tooth t of that member
    /// (`PlanetaryMeshes::pair_tooth`; none on a set without a tooth fault), the loads
    /// still split over every pair in contact.
    fn paths_over(
        &self,
        j: usize,
        (cycles, forces_n): (&[f64], &[Vec<f64>]),
        gap: &PairGap,
        by_tooth: Option<(FaultMember, usize)>,
    ) -> Vec<Vec<PathSample>> {
        let (kind, p) = self.kind_of(j);
        let meshes = match &self.dynamics.model.source {
            MeshStiffnessSource::Tables(m) => m,
            MeshStiffnessSource::Constant(_) => return vec![Vec::new()],
        };
        let set = &self.dynamics.study.set;
        let loa = [set.sun_planet.loa_length_m, set.ring_planet.loa_length_m][kind];
        let [w_pinion, w_gear] = match kind {
            0 => [self.relative_rad_s[0], self.relative_rad_s[1]],
            _ => [self.relative_rad_s[1], self.relative_rad_s[2]],
        };
        let mut paths = vec![Vec::new(); by_tooth.map_or(1, |b| b.1)];
        for (c, forces) in cycles.iter().zip(forces_n) {
            let pairs: Vec<(f64, f64)> = match kind {
                0 => meshes.sun_pairs_decided(p, *c, *c).collect(),
                _ => meshes.ring_pairs_decided(p, *c, *c).collect(),
            };
            for (k, (rho1, load)) in pair_loads(&pairs, forces[j], gap).into_iter().enumerate() {
                let bucket = match by_tooth {
                    None => 0,
                    Some((member, _)) => match meshes.pair_tooth((p, kind == 1), *c, k, member) {
                        Some(t) => t,
                        None => continue,
                    },
                };
                // Sun mesh: rho2 = N1N2 - rho1 (convex); ring mesh: rho2 = rho1 + N1N2
                // (concave ring), 1/R = 1/rho1 - 1/rho2.
                let (rho2, radius) = match kind {
                    0 => (loa - rho1, rho1 * (loa - rho1) / loa),
                    _ => (rho1 + loa, rho1 * (rho1 + loa) / loa),
                };
                let hz = HertzContact::with_radius(
                    load,
                    self.face_width_m[kind],
                    radius,
                    self.e_star_pa[kind],
                );
                paths[bucket].push(PathSample {
                    rho1_m: rho1,
                    load_n: load,
                    pressure_pa: hz.max_pressure_pa,
                    half_width_m: hz.half_width_m,
                    pinion_surface_speed_m_per_s: w_pinion * rho1,
                    gear_surface_speed_m_per_s: w_gear * rho2,
                    ..Default::default()
                });
            }
        }
        paths.iter().map(|p| sorted_by_rho1(p)).collect()
    }

    /// Mesh `j`'s Archard wear per pinion cycle (relative to the carrier) over the
    /// history `h` (paper eq. 14-17, `wear::archard`), with its wear gap `gap`: with a
    /// tooth fault the mean of the history's [`Self::periods`] mesh periods' increments,
    /// each from its own period's contacts (every position on the path is passed once a
    /// mesh period, by the teeth of that period; over the fault's period by every tooth
    /// of the faulty member: docs/MODEL.md 12.15).
    pub fn mesh_increment(&self, j: usize, h: &ForceHistory, gap: &PairGap) -> WearIncrement {
        let periods = self.periods();
        let samples = h.cycles.len();
        if periods == 1 || samples < periods {
            return self.increment_of(j, &self.mesh_path(j, h, gap));
        }
        // The recorded samples are equally spaced from the period's start (the dynamic
        // response's and the quasi-static history's), a whole number per mesh period.
        let per = samples / periods;
        let increments: Vec<WearIncrement> = (0..periods)
            .map(|k| {
                let r = k * per..(k + 1) * per;
                let h = (&h.cycles[r.clone()], &h.forces_n[r]);
                let path = self.paths_over(j, h, gap, None).pop().unwrap_or_default();
                self.increment_of(j, &path)
            })
            .collect();
        mean_increment(&increments)
    }

    /// Tooth `tooth` of the faulty member's wear per pinion cycle on mesh `j` from its
    /// own contacts over the history `h` of a set with a tooth fault (one passage of
    /// every mesh that meets it over the fault's period): None without a fault or when
    /// mesh `j` never meets that member's teeth (docs/MODEL.md 12.15).
    pub fn tooth_increment(
        &self,
        j: usize,
        h: &ForceHistory,
        gap: &PairGap,
        tooth: usize,
    ) -> Option<WearIncrement> {
        self.teeth_increments(j, h, gap)?.into_iter().nth(tooth)?
    }

    /// Every tooth of the faulty member's wear per pinion cycle on mesh `j`, as
    /// [`Self::tooth_increment`] (one pass over the history, its pairs grouped by the
    /// tooth they hold): entry t is tooth t's, None for a tooth mesh `j` never loads; None
    /// without a fault.
    pub fn teeth_increments(
        &self,
        j: usize,
        h: &ForceHistory,
        gap: &PairGap,
    ) -> Option<Vec<Option<WearIncrement>>> {
        let MeshStiffnessSource::Tables(m) = &self.dynamics.model.source else {
            return None;
        };
        let member = m.fault()?.member;
        let set = &self.dynamics.study.set;
        let z = match member {
            FaultMember::Sun => set.teeth_sun(),
            FaultMember::Planet(_) => set.teeth_planet(),
            FaultMember::Ring => set.teeth_ring(),
        };
        let paths = self.paths_over(j, (&h.cycles, &h.forces_n), gap, Some((member, z)));
        Some(
            paths
                .iter()
                .map(|p| (!p.is_empty()).then(|| self.increment_of(j, p)))
                .collect(),
        )
    }

    /// The Archard wear per pinion cycle of mesh `j`'s contacts `path` (paper eq. 14-17,
    /// the gear's share by z1 / z2).
    fn increment_of(&self, j: usize, path: &[PathSample]) -> WearIncrement {
        let (kind, _) = self.kind_of(j);
        let [z1, z2] = self.teeth(kind);
        per_cycle_wear(
            &self.grids[kind],
            path,
            self.coefficient_m2_per_n,
            z1 as f64 / z2 as f64,
        )
    }
}

/// The mean of increments on one grid, point by point (each of its four profiles).
fn mean_increment(increments: &[WearIncrement]) -> WearIncrement {
    let n = increments.len().max(1) as f64;
    let mean = |f: fn(&WearIncrement) -> &Vec<f64>| {
        let len = increments.first().map_or(0, |i| f(i).len());
        sum_of(increments.iter().map(f), len)
            .into_iter()
            .map(|x| x / n)
            .collect()
    };
    WearIncrement {
        pinion_m: mean(|i| &i.pinion_m),
        gear_m: mean(|i| &i.gear_m),
        sliding_pinion_m: mean(|i| &i.sliding_pinion_m),
        sliding_gear_m: mean(|i| &i.sliding_gear_m),
        teeth: None,
        slices: None,
    }
}

/// The loads of a mesh's tooth pairs (given as (rho1 in m, stiffness in N/m); returned
/// as (rho1 in m, load in N)) carrying `force_n` (N) together, with
/// the wear gap `gap`: pair i carries k_i max(delta - g_i, 0), delta the approach that
/// every pair in contact shares, taken as F / sum k + e_w (e_w the stiffness-weighted gap,
/// so the loads sum to F when every pair touches), then scaled to sum to F exactly (the
/// damping share of F and a pair the gap keeps apart).
pub fn pair_loads(pairs: &[(f64, f64)], force_n: f64, gap: &PairGap) -> Vec<(f64, f64)> {
    let k: f64 = pairs.iter().map(|p| p.1).sum();
    if force_n <= 0.0 || k <= 0.0 {
        return pairs.iter().map(|p| (p.0, 0.0)).collect();
    }
    let g: Vec<f64> = pairs.iter().map(|p| gap.at(p.0).0).collect();
    let e_w = pairs.iter().zip(&g).map(|(p, g)| p.1 * g).sum::<f64>() / k;
    let delta = force_n / k + e_w;
    let w: Vec<f64> = pairs
        .iter()
        .zip(&g)
        .map(|(p, g)| p.1 * (delta - g).max(0.0))
        .collect();
    let total: f64 = w.iter().sum();
    pairs
        .iter()
        .zip(&w)
        .map(|(p, w)| {
            let load = if total > 0.0 {
                force_n * w / total
            } else {
                force_n * p.1 / k
            };
            (p.0, load)
        })
        .collect()
}

/// The wear volume of a flank whose depth is `depth_m` at the grid points of radius of
/// curvature `rho_m` (equally spaced by `spacing_m` along the line of action), m^3:
/// b z integral h ds, ds = rho d rho / r_b the involute's arc length (its arc length from
/// the base circle is rho^2 / 2 r_b), by the trapezoidal rule over the grid.
pub fn flank_volume_m3(
    depth_m: &[f64],
    rho_m: &[f64],
    spacing_m: f64,
    base_radius_m: f64,
    face_width_m: f64,
    teeth: usize,
) -> f64 {
    let f: Vec<f64> = depth_m
        .iter()
        .zip(rho_m)
        .map(|(h, r)| h * r.abs() / base_radius_m)
        .collect();
    let n = f.len();
    if n < 2 {
        return 0.0;
    }
    let inner: f64 = f[1..n - 1].iter().sum();
    face_width_m * teeth as f64 * spacing_m * (inner + 0.5 * (f[0] + f[n - 1]))
}

/// Every mesh's new teeth (module order).
pub fn new_teeth(model: &PlanetaryWearModel) -> Vec<WearState> {
    (0..2 * model.planets())
        .map(|j| WearState::new(model.grids[model.kind_of(j).0].len()))
        .collect()
}

/// Sum of profiles of equal length.
fn sum_of<'a>(profiles: impl Iterator<Item = &'a Vec<f64>>, n: usize) -> Vec<f64> {
    let mut s = vec![0.0; n];
    for p in profiles {
        for (a, b) in s.iter_mut().zip(p) {
            *a += b;
        }
    }
    s
}

/// Every mesh's wear gap (module order) from the meshes' wear states: a sun mesh's is the
/// sun's wear (all its meshes' pinion wear) plus its planet's sun-side flank's; a ring
/// mesh's its planet's ring-side flank's plus the ring's (all its meshes' gear wear).
pub fn wear_gaps(model: &PlanetaryWearModel, wears: &[WearState]) -> Vec<PairGap> {
    let n = model.planets();
    let [gs, gr] = &model.grids;
    let sun = sum_of(wears[..n].iter().map(|w| &w.pinion_m), gs.len());
    let ring = sum_of(wears[n..].iter().map(|w| &w.gear_m), gr.len());
    let gap = |g: &ProfileGrid, a: &[f64], b: &[f64]| {
        PairGap::from_flanks(g.rho_pinion_m[0], g.spacing_m, a.to_vec(), b.to_vec())
    };
    (0..n)
        .map(|p| gap(gs, &sun, &wears[p].gear_m))
        .chain((0..n).map(|p| gap(gr, &wears[n + p].pinion_m, &ring)))
        .collect()
}

/// One flank of a member: which member, which side, and its wear profile.
#[derive(Debug, Clone, PartialEq)]
pub struct MemberFlank {
    /// "sun", "planet_N" or "ring".
    pub member: String,
    /// The flank: "sun" and "ring" for their loaded flank, "sun_side" / "ring_side" for a
    /// planet's flank meshing with the sun / the ring.
    pub flank: &'static str,
    /// Depth at the grid points, m.
    pub depth_m: Vec<f64>,
    /// Depth added per input-member revolution at the grid points, m.
    pub rate_m_per_input: Vec<f64>,
    /// The flank's wear volume over all the member's teeth, m^3.
    pub volume_m3: f64,
}

/// Every member's flanks (sun; each planet's sun-side and ring-side flank; ring) from
/// the meshes' wear states and their increments per pinion cycle (module order).
pub fn member_flanks(
    model: &PlanetaryWearModel,
    wears: &[WearState],
    increments: &[WearIncrement],
) -> Vec<MemberFlank> {
    let n = model.planets();
    let set = &model.dynamics.study.set;
    let [gs, gr] = &model.grids;
    let [cs, cp] = model.pinion_cycles_per_input;
    let scaled = |v: &[f64], c: f64| v.iter().map(|x| x * c).collect::<Vec<f64>>();
    let (rbs, rbp, rbr) = (
        set.sun_planet.pinion.base_radius_m,
        set.sun_planet.gear.base_radius_m,
        set.ring_planet.ring.base_radius_m,
    );
    let [bs, br] = model.face_width_m;
    let (zs, zp, zr) = (set.teeth_sun(), set.teeth_planet(), set.teeth_ring());
    let flank = |member: String, flank, depth: Vec<f64>, rate, on: FlankOn| {
        let volume_m3 = flank_volume_m3(&depth, on.rho_m, on.spacing_m, on.rb, on.b, on.z);
        MemberFlank {
            member,
            flank,
            depth_m: depth,
            rate_m_per_input: rate,
            volume_m3,
        }
    };
    let mut out = vec![flank(
        "sun".into(),
        "sun",
        sum_of(wears[..n].iter().map(|w| &w.pinion_m), gs.len()),
        sum_of(increments[..n].iter().map(|i| &i.pinion_m), gs.len())
            .iter()
            .map(|x| x * cs)
            .collect(),
        on(gs, false, rbs, bs, zs),
    )];
    for p in 0..n {
        out.push(flank(
            format!("planet_{}", p + 1),
            "sun_side",
            wears[p].gear_m.clone(),
            scaled(&increments[p].gear_m, cs),
            on(gs, true, rbp, bs, zp),
        ));
        out.push(flank(
            format!("planet_{}", p + 1),
            "ring_side",
            wears[n + p].pinion_m.clone(),
            scaled(&increments[n + p].pinion_m, cp),
            on(gr, false, rbp, br, zp),
        ));
    }
    out.push(flank(
        "ring".into(),
        "ring",
        sum_of(wears[n..].iter().map(|w| &w.gear_m), gr.len()),
        sum_of(increments[n..].iter().map(|i| &i.gear_m), gr.len())
            .iter()
            .map(|x| x * cp)
            .collect(),
        on(gr, true, rbr, br, zr),
    ));
    out
}

/// Where a flank lies: its grid's radii of curvature and spacing, its base radius (m),
/// face width (m) and tooth count.
struct FlankOn<'a> {
    rho_m: &'a [f64],
    spacing_m: f64,
    rb: f64,
    b: f64,
    z: usize,
}

/// The flank on grid `g`'s pinion (`gear` false) or gear side.
fn on(g: &ProfileGrid, gear: bool, rb: f64, b: f64, z: usize) -> FlankOn<'_> {
    FlankOn {
        rho_m: if gear { &g.rho_gear_m } else { &g.rho_pinion_m },
        spacing_m: g.spacing_m,
        rb,
        b,
        z,
    }
}

/// Tooth contacts per input-member revolution of a tooth of the sun, a planet (each flank)
/// and the ring: N c_s (a sun tooth meets every planet once per sun revolution relative
/// to the carrier), c_p (a planet tooth meets the sun, and the ring, once per planet
/// revolution relative to the carrier) and N c_p z_p / z_r (a ring tooth meets every planet
/// once per ring revolution relative to the carrier), with c_s and c_p the model's
/// `pinion_cycles_per_input`.
pub fn contacts_per_input(model: &PlanetaryWearModel) -> [f64; 3] {
    let n = model.planets() as f64;
    let [cs, cp] = model.pinion_cycles_per_input;
    let set = &model.dynamics.study.set;
    [
        n * cs,
        cp,
        n * cp * set.teeth_planet() as f64 / set.teeth_ring() as f64,
    ]
}
