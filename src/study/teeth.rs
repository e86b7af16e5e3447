//! The per-tooth inputs of a case (`[teeth]`, `[modification]`, `[[fault]]`) turned into
//! the teeth of the tooth-resolved mesh, once when the model is built; the wear of each
//! evaluation is added by [`ToothInputs::mesh_for`].
//!
//! The checks that need the geometry are made here: a crack deeper than the tooth, a
//! spall off the active profile, a relief longer than the addendum or dedendum, a broken
//! tip below the root circle; each names the key, the tooth and the valid range.

use crate::config::case::{Case, FaultKind, FaultSpec, Member, ReliefShape, WornGeometry};
use crate::contact::worn_curvature::curvature_change_per_m;
use crate::dynamics::tooth_mesh::{Runout, ToothFlank, ToothMesh};
use crate::geometry::flank_shape::{
    slope_form_added_m, ActiveFlank, FlankModification, Relief, Side,
};
use crate::geometry::iso1328::{
    draw_gear, flank_tolerances, round_iso, FlankTolerances, MAX_DRAWS,
};
use crate::geometry::{Gear, GearPair, ProfileGrid};
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::potential_energy::ToothBeam;
use crate::stiffness::tooth_faults::{
    crack_compliance_m_per_n, deg, spall_compliance_m_per_n, spall_gap_m, Crack, Spall,
};
use crate::stiffness::worn_tooth::worn_compliance_m_per_n;
use crate::wear::WearState;
use serde::Serialize;

/// The errors each tooth of one gear was given (um; drawn or from the case).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct GearErrors {
    /// Position (pitch) error of each tooth on the reference circle, um.
    pub position_um: Vec<f64>,
    pub profile_slope_um: Vec<f64>,
    pub profile_form_um: Vec<f64>,
    /// Radial run-out, um.
    pub runout_um: f64,
    /// ISO 1328-1 tolerances of the class drawn for, if any.
    pub tolerances: Option<FlankTolerancesReport>,
}

/// ISO 1328-1 tolerances of one gear, for reports (um, rounded as the standard publishes
/// them, 5.2.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlankTolerancesReport {
    pub class: i64,
    pub single_pitch_um: f64,
    pub cumulative_pitch_um: f64,
    pub profile_slope_um: f64,
    pub profile_form_um: f64,
    pub runout_um: f64,
}

impl From<FlankTolerances> for FlankTolerancesReport {
    fn from(t: FlankTolerances) -> Self {
        Self {
            class: t.class,
            single_pitch_um: round_iso(t.single_pitch_um),
            cumulative_pitch_um: round_iso(t.cumulative_pitch_um),
            profile_slope_um: round_iso(t.profile_slope_um),
            profile_form_um: round_iso(t.profile_form_um),
            runout_um: round_iso(t.runout_um),
        }
    }
}

/// The teeth of a case, before wear (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ToothInputs {
    pub pinion: Vec<ToothFlank>,
    pub gear: Vec<ToothFlank>,
    pub runout: [Runout; 2],
    /// What each gear's teeth were given, for reports.
    pub errors: [GearErrors; 2],
    pub faults: Vec<FaultSpec>,
    rho_start_m: f64,
    spacing_m: f64,
    /// Severe wear (`wear.worn_geometry = "worn"`): the tooth beams and base radii, the
    /// own radii of curvature of the grid points (ascending) of pinion and gear, and the
    /// nominal Hertz half-width, for the worn flanks' stiffness and curvature.
    worn: Option<WornFlanks>,
}

/// What the worn flanks of severe wear are computed from (see [`ToothInputs`]).
#[derive(Debug, Clone, PartialEq)]
struct WornFlanks {
    beams: [ToothBeam; 2],
    /// Own rho of the grid points, ascending, and the grid index of each.
    rho_m: [Vec<f64>; 2],
    half_width_m: f64,
}

fn member_gear(pair: &GearPair, m: Member) -> &Gear {
    match m {
        Member::Pinion => &pair.pinion,
        Member::Gear => &pair.gear,
    }
}

fn side(m: Member) -> Side {
    match m {
        Member::Pinion => Side::Pinion,
        Member::Gear => Side::Gear,
    }
}

/// One value per tooth from an array of 1 or z values (absent: zeros).
fn per_tooth(v: &Option<Vec<f64>>, z: usize) -> Option<Vec<f64>> {
    v.as_ref().map(|v| {
        if v.len() == 1 {
            vec![v[0]; z]
        } else {
            v.clone()
        }
    })
}

impl ToothInputs {
    /// The teeth of `case` on the wear grid, or None when the case gives no per-tooth
    /// input that changes anything (every tooth the paper's). Errors: the geometry
    /// checks of the module docs.
    pub fn from_case(
        case: &Case,
        pair: &GearPair,
        mesh: &MeshStiffness,
        grid: &ProfileGrid,
        shaft_speeds_rad_s: [f64; 2],
        static_force_n: f64,
    ) -> Result<Option<Self>, Vec<String>> {
        let mut problems = geometry_problems(case, pair, mesh);
        if !problems.is_empty() {
            return Err(std::mem::take(&mut problems));
        }
        let errors = gear_errors(case, pair).map_err(|e| vec![e])?;
        let cos_alpha = pair.pressure_angle_rad.cos();
        let m = &case.modification;
        let shape_parabolic = m.shape == Some(ReliefShape::Parabolic);
        let modification = |s: Side| {
            let relief = |amount: Option<f64>, len: Option<f64>| match (amount, len) {
                (Some(a), Some(l)) if a > 0.0 => Some(Relief {
                    amount_m: a * 1e-6,
                    length_m: l * 1e-3,
                    parabolic: shape_parabolic,
                }),
                _ => None,
            };
            let (roll, dev, rb) = match s {
                Side::Pinion => (
                    &m.profile_roll_pinion_deg,
                    &m.profile_deviation_pinion_um,
                    pair.pinion.base_radius_m,
                ),
                Side::Gear => (
                    &m.profile_roll_gear_deg,
                    &m.profile_deviation_gear_um,
                    pair.gear.base_radius_m,
                ),
            };
            FlankModification {
                tip: relief(m.tip_relief_um, m.tip_relief_length_mm),
                root: relief(m.root_relief_um, m.root_relief_length_mm),
                user: match (roll, dev) {
                    (Some(r), Some(d)) => Some((
                        r.iter().map(|x| deg(*x) * rb).collect(),
                        d.iter().map(|x| x * 1e-6).collect(),
                    )),
                    _ => None,
                },
            }
        };
        let n = grid.len();
        let build = |member: Member, e: &GearErrors| -> Vec<ToothFlank> {
            let s = side(member);
            let flank = ActiveFlank::of(pair, s);
            let modif = modification(s);
            let own: Vec<f64> = match s {
                Side::Pinion => grid.rho_pinion_m.clone(),
                Side::Gear => grid.rho_gear_m.clone(),
            };
            let z = member_gear(pair, member).teeth;
            (0..z)
                .map(|t| {
                    let removed_m = (0..n)
                        .map(|i| {
                            modif.removed_m(&flank, own[i])
                                - slope_form_added_m(
                                    &flank,
                                    own[i],
                                    e.profile_slope_um[t] * 1e-6,
                                    e.profile_form_um[t] * 1e-6,
                                )
                        })
                        .collect();
                    let mut f = ToothFlank {
                        removed_m,
                        // A pitch deviation is an arc on the reference circle (ISO
                        // 1328-1); along the line of action it is that arc on the base
                        // circle, r_b / r = cos(alpha) times it (alpha the reference
                        // pressure angle).
                        position_m: e.position_um[t] * 1e-6 * cos_alpha,
                        ..Default::default()
                    };
                    for fault in case
                        .fault
                        .iter()
                        .filter(|x| x.gear == member && x.tooth as usize == t)
                    {
                        apply_fault(&mut f, fault, pair, mesh, s, &own);
                    }
                    without_empty_tables(f)
                })
                .collect()
        };
        let runout = |e: &GearErrors, phase_deg: Option<f64>, speed: f64| Runout {
            eccentricity_m: 0.5 * e.runout_um * 1e-6,
            phase_rad: deg(phase_deg.unwrap_or(0.0)),
            shaft_speed_rad_s: speed,
        };
        let me = Self {
            pinion: build(Member::Pinion, &errors[0]),
            gear: build(Member::Gear, &errors[1]),
            runout: [
                runout(
                    &errors[0],
                    case.teeth.runout_pinion_phase_deg,
                    shaft_speeds_rad_s[0],
                ),
                runout(
                    &errors[1],
                    case.teeth.runout_gear_phase_deg,
                    shaft_speeds_rad_s[1],
                ),
            ],
            errors,
            faults: case.fault.clone(),
            rho_start_m: grid.rho_pinion_m[0],
            spacing_m: grid.spacing_m,
            worn: (case.wear.worn_geometry == WornGeometry::Worn).then(|| {
                let r = crate::contact::hertz::effective_radius_m(
                    pair.rho_pitch_m,
                    pair.rho_gear(pair.rho_pitch_m),
                );
                WornFlanks {
                    beams: mesh.tooth_beams().clone(),
                    rho_m: [
                        grid.rho_pinion_m.clone(),
                        grid.rho_gear_m.iter().rev().copied().collect(),
                    ],
                    half_width_m: crate::contact::hertz::HertzContact::with_radius(
                        static_force_n,
                        pair.face_width_m,
                        r,
                        crate::contact::hertz::effective_modulus_of(&case.materials),
                    )
                    .half_width_m,
                }
            }),
        };
        let perfect = |f: &[ToothFlank]| f.iter().all(|t| t == &ToothFlank::perfect(n));
        let trivial = perfect(&me.pinion)
            && perfect(&me.gear)
            && me.runout.iter().all(|r| r.eccentricity_m == 0.0)
            && me.worn.is_none();
        Ok((!trivial).then_some(me))
    }

    /// The tooth-resolved mesh of a wear state: each tooth's own wear (or the common
    /// profile of a state without per-tooth wear) added to its flank.
    pub fn mesh_for(&self, wear: &WearState) -> ToothMesh {
        let add =
            |side: usize, flanks: &[ToothFlank], common: &[f64], own: Option<&Vec<Vec<f64>>>| {
                // Teeth worn alike share their worn stiffness and curvature (computed once).
                let mut memo: Vec<(&[f64], WornTables)> = Vec::new();
                flanks
                    .iter()
                    .enumerate()
                    .map(|(t, f)| {
                        let w = own.and_then(|o| o.get(t)).map_or(common, |v| v.as_slice());
                        let mut f = f.clone();
                        for (r, h) in f.removed_m.iter_mut().zip(w) {
                            *r += h;
                        }
                        if let Some(worn) = &self.worn {
                            let tables = match memo.iter().find(|(m, _)| *m == w) {
                                Some((_, t)) => t.clone(),
                                None => {
                                    let t = worn.tables(side, w);
                                    memo.push((w, t.clone()));
                                    t
                                }
                            };
                            tables.apply(&mut f);
                        }
                        f
                    })
                    .collect()
            };
        let teeth = wear.teeth.as_ref();
        ToothMesh::new(
            add(0, &self.pinion, &wear.pinion_m, teeth.map(|t| &t.pinion_m)),
            add(1, &self.gear, &wear.gear_m, teeth.map(|t| &t.gear_m)),
            self.runout,
            self.rho_start_m,
            self.spacing_m,
            self.pinion.first().map_or(2, |f| f.removed_m.len()),
        )
    }
}

/// A flank whose fault tables add nothing (a crack of zero depth adds a compliance of
/// zero everywhere) without them: a tooth is judged by its effect, so such a tooth is
/// the perfect one and, when every tooth is, the case takes the identical-teeth path.
fn without_empty_tables(mut f: ToothFlank) -> ToothFlank {
    let empty = |t: &Option<Vec<f64>>| t.as_ref().is_some_and(|v| v.iter().all(|x| *x == 0.0));
    if empty(&f.compliance_m_per_n) {
        f.compliance_m_per_n = None;
    }
    if empty(&f.width_loss) {
        f.width_loss = None;
    }
    f
}

/// The added compliance and the curvature change of one worn flank on the grid.
#[derive(Debug, Clone, PartialEq)]
struct WornTables {
    compliance_m_per_n: Vec<f64>,
    curvature_change_per_m: Vec<f64>,
}

impl WornTables {
    fn apply(self, f: &mut ToothFlank) {
        if self.compliance_m_per_n.iter().all(|c| *c == 0.0) {
            return;
        }
        let table = f
            .compliance_m_per_n
            .get_or_insert_with(|| vec![0.0; self.compliance_m_per_n.len()]);
        for (a, b) in table.iter_mut().zip(&self.compliance_m_per_n) {
            *a += b;
        }
        f.curvature_change_per_m = Some(self.curvature_change_per_m);
    }
}

impl WornFlanks {
    /// The tables of a flank of gear `side` worn by `wear_m` (grid order: the pinion's
    /// ascending rho1, the gear's conjugate points).
    fn tables(&self, side: usize, wear_m: &[f64]) -> WornTables {
        let rho = &self.rho_m[side];
        // The wear in ascending own rho (the gear's grid runs the other way).
        let w: Vec<f64> = match side {
            0 => wear_m.to_vec(),
            _ => wear_m.iter().rev().copied().collect(),
        };
        let beam = &self.beams[side];
        let compliance: Vec<f64> = rho
            .iter()
            .map(|r| worn_compliance_m_per_n(beam, rho, &w, *r))
            .collect();
        let curvature = curvature_change_per_m(rho, &w, beam.base_radius_m, self.half_width_m);
        let grid_order = |v: Vec<f64>| match side {
            0 => v,
            _ => v.into_iter().rev().collect(),
        };
        WornTables {
            compliance_m_per_n: grid_order(compliance),
            curvature_change_per_m: grid_order(curvature),
        }
    }
}

impl ToothFlank {
    /// A perfect tooth on a grid of `n` points.
    pub fn perfect(n: usize) -> Self {
        Self {
            removed_m: vec![0.0; n],
            ..Default::default()
        }
    }
}

/// The errors of both gears: given, or drawn for the accuracy grade, else zero.
fn gear_errors(case: &Case, pair: &GearPair) -> Result<[GearErrors; 2], String> {
    let t = &case.teeth;
    let module_mm = pair.module_m * 1e3;
    let one = |member: Member| -> Result<GearErrors, String> {
        let g = member_gear(pair, member);
        let z = g.teeth;
        let (pitch, slope, form, runout) = match member {
            Member::Pinion => (
                &t.pitch_error_pinion_um,
                &t.profile_slope_pinion_um,
                &t.profile_form_pinion_um,
                t.runout_pinion_um,
            ),
            Member::Gear => (
                &t.pitch_error_gear_um,
                &t.profile_slope_gear_um,
                &t.profile_form_gear_um,
                t.runout_gear_um,
            ),
        };
        let tol = t
            .accuracy_grade
            .map(|a| flank_tolerances(a, module_mm * z as f64, module_mm));
        let drawn = match tol {
            Some(tol) => {
                let stream = match member {
                    Member::Pinion => 0,
                    Member::Gear => 1,
                };
                let seed = t.error_seed.unwrap_or(0);
                Some(draw_gear(z, &tol, seed as u64, stream).map_err(|u| {
                    format!(
                        "`teeth.accuracy_grade` = {}: no {} of {} teeth drawn from `teeth.error_seed` = {seed} passed the class's inspection in {MAX_DRAWS} draws; give its errors explicitly (`teeth.pitch_error_*_um`, `teeth.profile_*_um`)",
                        u.class, member.name(), u.teeth
                    )
                })?)
            }
            None => None,
        };
        let pick = |given: Option<Vec<f64>>, drawn: Option<Vec<f64>>| {
            given.or(drawn).unwrap_or_else(|| vec![0.0; z])
        };
        Ok(GearErrors {
            position_um: pick(pitch.clone(), drawn.as_ref().map(|d| d.position_um.clone())),
            profile_slope_um: pick(
                per_tooth(slope, z),
                drawn.as_ref().map(|d| d.slope_um.clone()),
            ),
            profile_form_um: pick(
                per_tooth(form, z),
                drawn.as_ref().map(|d| d.form_um.clone()),
            ),
            runout_um: runout.unwrap_or(0.0),
            tolerances: tol.map(Into::into),
        })
    };
    Ok([one(Member::Pinion)?, one(Member::Gear)?])
}

/// Adds one fault to a tooth's flank (`own` the tooth's own rho at the grid points).
fn apply_fault(
    f: &mut ToothFlank,
    fault: &FaultSpec,
    pair: &GearPair,
    mesh: &MeshStiffness,
    s: Side,
    own: &[f64],
) {
    let flank = ActiveFlank::of(pair, s);
    let beam = &mesh.tooth_beams()[match s {
        Side::Pinion => 0,
        Side::Gear => 1,
    }];
    let n = own.len();
    let add_compliance = |c: Vec<f64>, f: &mut ToothFlank| {
        let table = f.compliance_m_per_n.get_or_insert_with(|| vec![0.0; n]);
        for (a, b) in table.iter_mut().zip(c) {
            *a += b;
        }
    };
    match fault.kind {
        FaultKind::Crack => {
            let crack = Crack {
                depth_m: fault.crack_depth_mm.unwrap_or(0.0) * 1e-3,
                angle_rad: deg(fault
                    .crack_angle_deg
                    .unwrap_or(crate::config::teeth::DEFAULT_CRACK_ANGLE_DEG)),
                width_fraction: fault.crack_width_fraction.unwrap_or(1.0),
            };
            let c = own
                .iter()
                .map(|rho| crack_compliance_m_per_n(beam, flank.tip_rho_m, &crack, *rho))
                .collect();
            add_compliance(c, f);
        }
        FaultKind::Spall => {
            let spall = spall_of(fault, &flank);
            let c = own
                .iter()
                .map(|rho| {
                    spall_compliance_m_per_n(beam, &spall, mesh.hertz_compliance_m_per_n(), *rho)
                })
                .collect();
            add_compliance(c, f);
            if spall.width_fraction < 1.0 {
                let loss = f.width_loss.get_or_insert_with(|| vec![0.0; n]);
                for (l, rho) in loss.iter_mut().zip(own) {
                    if spall.contains(*rho) {
                        *l += spall.width_fraction;
                    }
                }
            }
            for (i, rho) in own.iter().enumerate() {
                let (r1, r2) = match s {
                    Side::Pinion => (*rho, pair.rho_gear(*rho)),
                    Side::Gear => (pair.loa_length_m - rho, *rho),
                };
                let radius = r1 * r2 / (r1 + r2);
                f.removed_m[i] += spall_gap_m(&spall, flank.base_radius_m, radius, *rho);
            }
        }
        FaultKind::BrokenTip => {
            let g = match s {
                Side::Pinion => &pair.pinion,
                Side::Gear => &pair.gear,
            };
            let r_cut = g.tip_radius_m - fault.removed_height_mm.unwrap_or(0.0) * 1e-3;
            let rho_cut = (r_cut.powi(2) - g.base_radius_m.powi(2)).max(0.0).sqrt();
            let limit = match s {
                Side::Pinion => rho_cut,
                Side::Gear => pair.loa_length_m - rho_cut,
            };
            f.contact_limit_rho1_m = Some(match (s, f.contact_limit_rho1_m) {
                (Side::Pinion, Some(l)) => l.min(limit),
                (Side::Gear, Some(l)) => l.max(limit),
                (_, None) => limit,
            });
        }
    }
}

/// The spall of a `[[fault]]` table on its flank (own rho, m).
fn spall_of(fault: &FaultSpec, flank: &ActiveFlank) -> Spall {
    let centre = flank.pitch_rho_m + fault.spall_position_mm.unwrap_or(0.0) * 1e-3;
    let half = 0.5 * fault.spall_length_mm.unwrap_or(0.0) * 1e-3;
    Spall {
        rho_lo_m: centre - half,
        rho_hi_m: centre + half,
        depth_m: fault.spall_depth_um.unwrap_or(0.0) * 1e-6,
        width_fraction: fault.spall_width_fraction.unwrap_or(1.0),
    }
}

/// An upper limit shown to 4 decimals, rounded down, so that every value up to the shown
/// limit is accepted (a limit rounded to nearest could show 4.5000 for 4.49999).
fn upper_mm(x: f64) -> String {
    format!("{:.4}", (x * 1e4).floor() / 1e4)
}

/// A lower limit shown to 4 decimals, rounded up (see [`upper_mm`]).
fn lower_mm(x: f64) -> String {
    format!("{:.4}", (x * 1e4).ceil() / 1e4)
}

/// The checks of the module docs.
fn geometry_problems(case: &Case, pair: &GearPair, mesh: &MeshStiffness) -> Vec<String> {
    let mut p = Vec::new();
    let flanks = [Side::Pinion, Side::Gear].map(|s| ActiveFlank::of(pair, s));
    let m = &case.modification;
    let mm = 1e3;
    let addendum = flanks[0].addendum_roll_m().min(flanks[1].addendum_roll_m());
    if let Some(l) = m.tip_relief_length_mm {
        if l * 1e-3 > addendum {
            p.push(format!(
                "`modification.tip_relief_length_mm` = {l} is longer than the addendum: a tip relief runs from the tip at most to the pitch point, valid (0, {}] mm on this pair (the shorter of the pinion's {:.4} and the gear's {:.4} mm roll length)",
                upper_mm(addendum * mm),
                flanks[0].addendum_roll_m() * mm,
                flanks[1].addendum_roll_m() * mm
            ));
        }
    }
    let dedendum = flanks[0].dedendum_roll_m().min(flanks[1].dedendum_roll_m());
    if let Some(l) = m.root_relief_length_mm {
        if l * 1e-3 > dedendum {
            p.push(format!(
                "`modification.root_relief_length_mm` = {l} is longer than the active dedendum: a root relief runs from the start of active profile at most to the pitch point, valid (0, {}] mm on this pair",
                upper_mm(dedendum * mm)
            ));
        }
    }
    for (key_amount, key_len, amount, len) in [
        (
            "tip_relief_um",
            "tip_relief_length_mm",
            m.tip_relief_um,
            m.tip_relief_length_mm,
        ),
        (
            "root_relief_um",
            "root_relief_length_mm",
            m.root_relief_um,
            m.root_relief_length_mm,
        ),
    ] {
        if amount.is_some() != len.is_some() {
            p.push(format!(
                "`modification.{key_amount}` and `modification.{key_len}` go together: give both or neither"
            ));
        }
    }
    for (i, f) in case.fault.iter().enumerate() {
        let s = side(f.gear);
        let g = member_gear(pair, f.gear);
        let flank = flanks[match s {
            Side::Pinion => 0,
            Side::Gear => 1,
        }];
        let who = format!("fault {i}, {} tooth {}", f.gear.name(), f.tooth);
        match f.kind {
            FaultKind::Crack => {
                let beam = &mesh.tooth_beams()[match s {
                    Side::Pinion => 0,
                    Side::Gear => 1,
                }];
                let angle = f
                    .crack_angle_deg
                    .unwrap_or(crate::config::teeth::DEFAULT_CRACK_ANGLE_DEG);
                let q_max = Crack::max_depth_m(beam, deg(angle));
                let q = f.crack_depth_mm.unwrap_or(0.0);
                if q * 1e-3 >= q_max {
                    p.push(format!(
                        "`fault.crack_depth_mm` = {q} ({who}) is deeper than the tooth: at {angle} deg its reach across the root must stay below the root's thickness {:.4} mm, valid [0, {}) mm",
                        2.0 * beam.root_section().0 * mm,
                        upper_mm(q_max * mm)
                    ));
                }
            }
            FaultKind::Spall => {
                let spall = spall_of(f, &flank);
                let profile = flank.tip_rho_m - flank.sap_rho_m;
                let len = spall.rho_hi_m - spall.rho_lo_m;
                if len > profile {
                    p.push(format!(
                        "`fault.spall_length_mm` = {} ({who}) is longer than the active profile: valid (0, {}] mm",
                        f.spall_length_mm.unwrap_or(0.0),
                        upper_mm(profile * mm)
                    ));
                } else if spall.rho_lo_m < flank.sap_rho_m - 1e-12
                    || spall.rho_hi_m > flank.tip_rho_m + 1e-12
                {
                    p.push(format!(
                        "`fault.spall_position_mm` = {} ({who}) puts the spall off the active profile: with length {} mm its centre must lie within [{}, {}] mm of the pitch point",
                        f.spall_position_mm.unwrap_or(0.0),
                        f.spall_length_mm.unwrap_or(0.0),
                        lower_mm((flank.sap_rho_m - flank.pitch_rho_m + 0.5 * len) * mm),
                        upper_mm((flank.tip_rho_m - flank.pitch_rho_m - 0.5 * len) * mm)
                    ));
                } else {
                    let beam = &mesh.tooth_beams()[match s {
                        Side::Pinion => 0,
                        Side::Gear => 1,
                    }];
                    let d_max = spall.max_depth_m(beam);
                    if spall.depth_m > d_max {
                        p.push(format!(
                            "`fault.spall_depth_um` = {} ({who}) is deeper than the tooth holds: a pit may take at most {:.0} % of the tooth's thickness at its upper edge ({:.4} mm), valid (0, {:.1}] µm",
                            f.spall_depth_um.unwrap_or(0.0),
                            Spall::MAX_THICKNESS_SHARE * 100.0,
                            d_max / Spall::MAX_THICKNESS_SHARE * mm,
                            (d_max * 1e7).floor() / 10.0
                        ));
                    }
                }
            }
            FaultKind::BrokenTip => {
                let h = f.removed_height_mm.unwrap_or(0.0);
                let height = g.tip_radius_m - g.root_radius_m;
                if h * 1e-3 > height {
                    p.push(format!(
                        "`fault.removed_height_mm` = {h} ({who}) is more than the tooth: valid (0, {}] mm (tip to root circle)",
                        upper_mm(height * mm)
                    ));
                }
            }
        }
    }
    p
}
