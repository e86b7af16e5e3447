//! The per-tooth inputs of a case (`[teeth]`, `[modification]`, `[[fault]]`) turned into
//! the teeth of the tooth-resolved mesh, once when the model is built; the wear of each
//! evaluation is added by [`ToothInputs::mesh_for`].
//!
//! The checks that need the geometry are made here: a crack deeper than the tooth, a
//! spall off the active profile, a relief longer than the addendum or dedendum, a broken
//! tip below the root circle; each names the key, the tooth and the valid range.

mod checks;
mod errors;
mod faults;
mod helical;
mod helical_tip;
mod line_wear;
mod sides;
mod worn;

pub(crate) use checks::{fault_problem, lower_mm, upper_mm};
pub use errors::{FlankTolerancesReport, GearErrors};
pub(crate) use faults::apply_fault;
pub(crate) use line_wear::{LineTeeth, ToothSlices};

use crate::config::case::{Case, Member, ReliefShape, ToothFault, WornGeometry};
use crate::dynamics::tooth_mesh::{Runout, ToothFlank, ToothMesh};
use crate::geometry::flank_shape::{
    slope_form_added_m, ActiveFlank, FlankModification, Relief, Side,
};
use crate::geometry::{GearPair, ProfileGrid};
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::tooth_faults::deg;
use crate::wear::WearState;
use checks::geometry_problems;
use errors::gear_errors;
use sides::{member_gear, side};
use worn::{WornFlanks, WornTables};

/// The teeth of a case, before wear (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ToothInputs {
    /// Each pinion tooth's flank (removed material, errors), tooth order.
    pub pinion: Vec<ToothFlank>,
    /// Each gear tooth's flank, tooth order.
    pub gear: Vec<ToothFlank>,
    /// Run-out of pinion and gear.
    pub runout: [Runout; 2],
    /// What each gear's teeth were given, for reports.
    pub errors: [GearErrors; 2],
    /// The tooth faults of the case.
    pub faults: Vec<ToothFault>,
    rho_start_m: f64,
    spacing_m: f64,
    /// Severe wear (`wear.worn_geometry = "worn"`): the tooth beams and base radii, the
    /// own radii of curvature of the grid points (ascending) of pinion and gear, and the
    /// nominal Hertz half-width, for the worn flanks' stiffness and curvature.
    worn: Option<WornFlanks>,
    /// A helical pair's teeth as contact lines on its line pair (`teeth::helical`,
    /// docs/MODEL.md 11.10), with what their wear per face slice needs
    /// (docs/MODEL.md 11.13).
    lines: Option<Box<LineTeeth>>,
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
        let errors = gear_errors(case, pair).map_err(|e| vec![e.to_string()])?;
        let n = grid.len();
        let build = |member: Member, e: &GearErrors| flanks_of(case, pair, mesh, grid, member, e);
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
            worn: (case.wear.worn_geometry == WornGeometry::Worn)
                .then(|| WornFlanks::of(case, pair, mesh, grid, static_force_n)),
            lines: None,
        };
        let perfect = |f: &[ToothFlank]| f.iter().all(|t| t == &ToothFlank::perfect(n));
        let trivial = perfect(&me.pinion)
            && perfect(&me.gear)
            && me.runout.iter().all(|r| r.eccentricity_m == 0.0)
            && me.worn.is_none();
        Ok((!trivial).then_some(me))
    }

    /// A helical pair's teeth as contact lines, with what their wear per face slice needs
    /// (docs/MODEL.md 11.13); None for a spur pair's teeth.
    pub(crate) fn line_teeth(&self) -> Option<&LineTeeth> {
        self.lines.as_deref()
    }

    /// The tooth-resolved mesh of a wear state: each tooth's own wear (or the common
    /// profile of a state without per-tooth wear) added to its flank.
    pub fn mesh_for(&self, wear: &WearState) -> ToothMesh {
        if let Some(l) = &self.lines {
            // A helical pair's lines: each tooth's own wear per face slice as its line's
            // gap (docs/MODEL.md 11.13).
            let add = |flanks: &[ToothFlank],
                       sections: &[ToothSlices],
                       own: Option<&Vec<Vec<f64>>>|
             -> Vec<ToothFlank> {
                (flanks.iter().enumerate())
                    .map(|(t, f)| {
                        let mut f = f.clone();
                        if let (Some(w), Some(s)) = (own, sections.get(t)) {
                            l.add_wear(&mut f.removed_m, w, t, s);
                        }
                        f
                    })
                    .collect()
            };
            let teeth = wear.teeth.as_ref();
            return ToothMesh::new(
                add(&self.pinion, &l.pinion, teeth.map(|t| &t.pinion_m)),
                add(&self.gear, &l.gear, teeth.map(|t| &t.gear_m)),
                self.runout,
                self.rho_start_m,
                self.spacing_m,
                self.pinion.first().map_or(2, |f| f.removed_m.len()),
            );
        }
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

/// The modification of the flanks of side `s` (`[modification]`): the tip and root
/// reliefs, and a profile given point by point (roll angles, deg, to roll lengths on the
/// base circle; deviations, um, to m).
fn modification_of(case: &Case, pair: &GearPair, s: Side) -> FlankModification {
    let m = &case.modification;
    let shape_parabolic = m.shape == Some(ReliefShape::Parabolic);
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
}

/// The flank of every tooth of `member` before wear, on the grid: material removed by
/// the modification less that added by the tooth's profile slope and form errors
/// (`e`), the tooth's position error, and its faults.
fn flanks_of(
    case: &Case,
    pair: &GearPair,
    mesh: &MeshStiffness,
    grid: &ProfileGrid,
    member: Member,
    e: &GearErrors,
) -> Vec<ToothFlank> {
    let cos_alpha = pair.pressure_angle_rad.cos();
    let n = grid.len();
    let s = side(member);
    let flank = ActiveFlank::of(pair, s);
    let modif = modification_of(case, pair, s);
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
                .filter(|x| x.gear == member && x.tooth == t)
            {
                apply_fault(&mut f, fault, pair, mesh, s, &own);
            }
            without_empty_tables(f)
        })
        .collect()
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

impl ToothFlank {
    /// A perfect tooth on a grid of `n` points.
    pub fn perfect(n: usize) -> Self {
        Self {
            removed_m: vec![0.0; n],
            ..Default::default()
        }
    }
}
