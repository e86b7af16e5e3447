//! The model objects of a helical case for `gearwear stiffness`: the helical pair (its
//! transverse section read from the case's normal section), the slice mesh stiffness, and
//! the transverse section as a spur pair of the full face width for comparison
//! (docs/MODEL.md section 11); and [`HelicalDynamics`], what the planar dynamic model of a
//! helical case (`study::helical_dynamics`) adds to a spur model. `Model::from_case`
//! refuses a helical case; `Model::helical_from_case` builds the planar one.

use super::model_error::ModelError;
use crate::config::case::{Case, ContactPathModel, GearSection, HelixHand};
use crate::dynamics::contact_path::ContactPath;
use crate::dynamics::excitation::PairGap;
use crate::dynamics::model::MAX_PAIRS;
use crate::dynamics::params::AxialSupport;
use crate::geometry::helical::{Hand, HelicalPair, HelixSpec};
use crate::geometry::{GearPair, ProfileGrid};
use crate::stiffness::face_load::{FaceLoad, LeadGap};
use crate::stiffness::helical::SliceMeshStiffness;
use crate::stiffness::mesh::{FilletSettings, MeshStiffness};
use crate::stiffness::potential_energy::ElasticPair;
use crate::wear::WearState;

/// A helical case's stiffness model, built once.
#[derive(Debug, Clone)]
pub struct HelicalModel {
    /// The validated case.
    pub case: Case,
    /// The slice model (it holds the helical pair).
    pub slices: SliceMeshStiffness,
    /// The transverse section as a spur pair of face width b (no stagger, Hertz on a line
    /// parallel to the axis): what the pair would be without its helix.
    pub spur_transverse: MeshStiffness,
    /// Warnings of the geometry and the stiffness, for the user.
    pub warnings: Vec<String>,
}

/// The case's helix.
pub fn helix_of(g: &GearSection) -> HelixSpec {
    HelixSpec {
        helix_angle_deg: g.helix_angle_deg,
        hand_pinion: match g.helix_hand_pinion {
            HelixHand::Left => Hand::Left,
            HelixHand::Right => Hand::Right,
        },
    }
}

impl HelicalModel {
    /// Build the pair, the slice model with `stiffness.slices` slices and the spur
    /// comparison. The fillet convention is the spur model's (`study::Model`): the
    /// built-in tooth form's theta_f extrapolation exemption holds for its normal section.
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        let pair = HelicalPair::from_case(&case.gear, &helix_of(&case.gear))?;
        let elastic = ElasticPair::from_case(&case.materials);
        let fillet = FilletSettings::from_case(&case.stiffness).map(|mut s| {
            s.allow_theta_f_extrapolation = case.gear.same_tooth_form(&GearSection::default());
            s
        });
        let n_table = case.stiffness.table_points_per_mesh_period.max(16) as usize;
        let slices = usize::try_from(case.stiffness.slices).unwrap_or(0);
        let model = SliceMeshStiffness::new(&pair, &elastic, slices, n_table, fillet)?;
        let spur_transverse =
            MeshStiffness::with_fillet(&pair.transverse, &elastic, n_table, fillet)?;
        let mut warnings = pair.transverse.warnings.clone();
        warnings.extend(spur_transverse.warnings().iter().cloned());
        Ok(Self {
            case: case.clone(),
            slices: model,
            spur_transverse,
            warnings,
        })
    }

    /// The helical pair.
    pub fn pair(&self) -> &HelicalPair {
        self.slices.pair()
    }
}

/// What the planar model of a helical pair adds to a spur model, for its outputs.
#[derive(Debug, Clone)]
pub struct HelicalDynamics {
    /// The helical pair (its transverse section is the model's spur pair).
    pub pair: HelicalPair,
    /// Slice count N of the mesh stiffness.
    pub slices: usize,
    /// The slice model (its slices wear one by one, `study::helical_wear`).
    pub slice_model: SliceMeshStiffness,
    /// Mean of the slice model's mesh stiffness over a mesh period, N/m (N times a slice's,
    /// exact for its spline), beside the line table's (the model's `mesh`).
    pub slice_mean_stiffness_n_per_m: f64,
    /// The lead gaps across the face, when the case gives some (docs/MODEL.md 11.1).
    pub lead: Option<LeadDynamics>,
}

impl HelicalDynamics {
    /// tan(beta_b): the axial force per unit transverse mesh force (the normal force
    /// F_n = F_t / cos(beta_b) along the normal line of action, inclined at beta_b to the
    /// transverse plane: axial part F_n sin(beta_b) = F_t tan(beta_b); ISO 6336-1 eq. for
    /// F_x, Niemann & Winter II, 21.2).
    pub fn axial_per_transverse(&self) -> f64 {
        self.pair.base_helix_angle_rad.tan()
    }

    /// Sign of the axial force on the pinion along its axis ([`pinion_axial_sign`]).
    pub fn pinion_axial_sign(&self) -> f64 {
        pinion_axial_sign(self.pair.hand_pinion)
    }

    /// cos(beta_b): a wear depth h_n normal to the flank is h_n / cos(beta_b) along the
    /// transverse line of action, and the flank's area is the transverse section's over
    /// cos(beta_b) (docs/MODEL.md 11.3 derives both; ISO 21771:2007, 4.4, and Litvin &
    /// Fuentes, *Gear Geometry and Applied Theory*, 2nd ed. 2004, on involute helical gears
    /// with parallel axes: the normal to the involute helicoid lies in the plane of action
    /// at beta_b to the transverse plane). Exactly 1 at beta = 0.
    pub(crate) fn cos_base_helix(&self) -> f64 {
        self.pair.base_helix_angle_rad.cos()
    }

    /// The worn slices as each contact line's gap on the line pair, m (docs/MODEL.md 11.3,
    /// `study::helical_wear`): the stiffness-weighted mean of the line's slices' wear gaps
    /// along the transverse line of action (`slice_gap_m`: the normal depths over
    /// cos(beta_b)),
    ///   e_l(rho) = sum_i k_i g_j(i)(rho + o_i) / sum_i k_i,
    /// at the wear grid's spacing over the positions of the line's trailing end (rho, where
    /// the solver reads it, `ContactPath::plain_pair`), slice i at its offset o_i from it.
    /// One slice (no lead: the slice is its own line) gives the wear state's own gap, the
    /// mean profile over the slices over cos(beta_b); at beta = 0 that is the spur pair's
    /// gap bit for bit.
    pub fn wear_gap(&self, grid: &ProfileGrid, wear: &WearState) -> PairGap {
        let s = &self.slice_model;
        let lines = s.line_grid();
        let cos_bb = self.cos_base_helix();
        if wear.slices.is_none() || lines.lead == 0.0 {
            if cos_bb == 1.0 {
                return wear.pair_gap(grid);
            }
            let transverse = |h: &[f64]| h.iter().map(|x| x / cos_bb).collect();
            return PairGap::from_flanks(
                grid.rho_pinion_m[0],
                grid.spacing_m,
                transverse(&wear.pinion_m),
                transverse(&wear.gear_m),
            );
        }
        let t = &s.pair().transverse;
        let spacing = grid.spacing_m;
        let points = (lines.line.path_length_m() / spacing).ceil() as usize + 1;
        let (start, end) = (t.rho_start_m, t.rho_end_m);
        let off_path = |r: f64| (start - r).max(r - end);
        let gap = (0..points)
            .map(|p| {
                let rho = lines.line.rho_start_m + p as f64 * spacing;
                let (mut kg, mut k) = (0.0, 0.0);
                for (i, o) in lines.offsets.iter().enumerate() {
                    let r = rho + o;
                    if (start..=end).contains(&r) {
                        let ki = s.slice().pair_stiffness_n_per_m(r);
                        let j = s.face_slice_of_line_slice(i);
                        kg += ki * slice_gap_m(grid, wear, j, r, cos_bb);
                        k += ki;
                    }
                }
                if k > 0.0 {
                    return kg / k;
                }
                // No slice of the line on the path here (it is about to enter or has
                // just left): the gap continues its nearest slice's at the path's end, so
                // that the table's last cell, read by interpolation where that slice is
                // on the path, holds the end's wear instead of falling to nothing (one
                // slice at a vanishing helix angle, at rho_start - L/2 here, lost the
                // pinion root's deepest wear: 7 % more wear than the spur pair's after
                // 1.2e4 cycles, tests/helical_dataset.rs).
                let nearest = lines
                    .offsets
                    .iter()
                    .enumerate()
                    .min_by(|a, b| off_path(rho + a.1).total_cmp(&off_path(rho + b.1)));
                nearest.map_or(0.0, |(i, o)| {
                    let j = s.face_slice_of_line_slice(i);
                    slice_gap_m(grid, wear, j, (rho + o).clamp(start, end), cos_bb)
                })
            })
            .collect();
        PairGap::new(lines.line.rho_start_m, spacing, gap)
    }
}

/// Sign s of the axial mesh force on the pinion along its axis (+z along the pinion's
/// angular velocity, the y of `geometry::helical`): F_a = s F tan(beta_b), the gear
/// taking -F_a (docs/MODEL.md 11.6). On the plane of action the pinion's flank at the
/// face position y sits at u = r_b1 phi + s_h y tan(beta_b) (section 11's contact lines,
/// s_h = +1 for a right hand: the section at larger y is turned forward). Moved axially
/// by z_p, the pinion brings its section y - z_p to y, so its flank there retreats along
/// the path by s_h z_p tan(beta_b), the gear's likewise by z_g: the deflection is
///   delta = r_b1 phi_p - r_b2 phi_g + d . (u_p - u_g) - s_h tan(beta_b) (z_p - z_g)
/// and the mesh force's generalised force on z_p, -F d delta / d z_p, is
/// +s_h F tan(beta_b) (Kahraman, J. Mech. Des. 116 (1994) 706-712, and Velex & Maatar, J.
/// Sound Vib. 191 (1996) 629: the axial displacements projected on the normal line of
/// action through sin(beta_b)). A driving right-hand pinion is pushed along its angular
/// velocity (+1), a left-hand one against it (-1): the gear's reaction on the front
/// flank, whose outward normal leans against the helix, points into the tooth.
pub fn pinion_axial_sign(hand: Hand) -> f64 {
    match hand {
        Hand::Right => 1.0,
        Hand::Left => -1.0,
    }
}

/// Wear gap of face slice `j` at transverse position `rho_m` along the transverse line of
/// action, the slice's deflection direction, m: pinion plus gear wear depth at the
/// conjugate points (Archard's, normal to the flank) over `cos_bb` = cos(beta_b) (0 with no
/// per-slice wear). The flank's normal lies in the plane of action at beta_b to the
/// transverse plane (ISO 21771:2007, 4.4; Litvin & Fuentes 2004), so a layer of normal
/// thickness h_n cut by the transverse plane is h_n / cos(beta_b) thick along the
/// transverse line of action (docs/MODEL.md 11.3).
pub(crate) fn slice_gap_m(
    grid: &ProfileGrid,
    wear: &WearState,
    j: usize,
    rho_m: f64,
    cos_bb: f64,
) -> f64 {
    wear.slices.as_ref().map_or(0.0, |s| {
        (grid.interpolate(&s.pinion_m[j], rho_m) + grid.interpolate(&s.gear_m[j], rho_m)) / cos_bb
    })
}

/// What the planar model of a helical pair with lead gaps keeps for its face load outputs
/// (`study::face_load_dynamic`).
#[derive(Debug, Clone)]
pub struct LeadDynamics {
    /// The slice model the contact lines are made of.
    pub slices: SliceMeshStiffness,
    /// The static face load (`gearwear stiffness`'s exact solve at the case's static mesh
    /// force, `study::face_load::face_load`).
    pub static_load: FaceLoad,
    /// The gap across the face it was solved with.
    pub gap: LeadGap,
}

/// Where a helical pair's teeth touch in its planar model (docs/MODEL.md 11.1): the
/// contact lines of `line_pair` over the transverse path, each L = `lead_m` = b tan(beta_b)
/// long (one slice, `lead_m` = 0: the transverse pair on its nominal path), between flanks
/// whose Hertz radii are the contact line's normal section's (`in_normal_section`).
pub(crate) fn helical_contact(hp: &HelicalPair, line_pair: &GearPair, lead_m: f64) -> ContactPath {
    let t = &hp.transverse;
    if lead_m > 0.0 {
        ContactPath::helical_lines(line_pair, (t.rho_start_m, t.rho_end_m), lead_m)
    } else {
        ContactPath::new(line_pair, ContactPathModel::Nominal, MAX_PAIRS)
    }
    .in_normal_section(hp.base_helix_angle_rad.cos())
}

/// The axial degrees of freedom of a helical case (docs/MODEL.md 11.6): the mesh's
/// d delta / d z_p = -s tan(beta_b) ([`pinion_axial_sign`]; m/m) and each body's axial
/// bearing from `[dynamics]` (`DynamicsSection::axial_bearings`); None where the case gives
/// neither axial stiffness (rigid axial bearings: the planar model).
pub(crate) fn axial_support(case: &Case, pair: &HelicalPair) -> Option<AxialSupport> {
    let bearings = case.dynamics.axial_bearings();
    bearings.iter().any(Option::is_some).then(|| AxialSupport {
        axial_gradient: -pinion_axial_sign(pair.hand_pinion) * pair.base_helix_angle_rad.tan(),
        bearings,
    })
}

/// The refusal of a helical pair whose total contact ratio epsilon_gamma exceeds the
/// contact lines the dynamic mesh follows (`MAX_PAIRS`), naming `case`'s keys; None
/// within (0, `MAX_PAIRS`].
pub(crate) fn contact_ratio_problem(case: &Case, hp: &HelicalPair) -> Option<String> {
    use crate::dynamics::model::MAX_PAIRS;
    let eps = hp.total_contact_ratio;
    (eps.ceil() as usize > MAX_PAIRS).then(|| format!(
        "`gear.helix_angle_deg` = {} with `gear.face_width_mm` = {} gives a total contact ratio epsilon_gamma = {eps:.3} (epsilon_alpha {:.3} + epsilon_beta {:.3}): `gearwear dynamics` follows at most {MAX_PAIRS} contact lines, so epsilon_gamma must lie in (0, {MAX_PAIRS}]; reduce the helix angle or the face width",
        case.gear.helix_angle_deg, case.gear.face_width_mm, hp.transverse_contact_ratio, hp.overlap_ratio
    ))
}

/// The default `contact.path` = "extended" on a helical pair: its tip corners are not
/// modelled (a helical tooth's corner meets the mate along a line across the face, one
/// slice at a time), so the lines are followed on the nominal path.
pub const EXTENDED_PATH_WARNING: &str = "`contact.path` = \"extended\": the tip corners of a helical tooth are not modelled, so its contact lines are followed on the nominal path of contact (as `contact.path` = \"nominal\")";
