//! Checks of a case against its own geometry, after the key ranges (`config::schema`)
//! and before anything is computed: what a single key's range cannot say.
//!
//! Also the values the model resolves from the geometry (`"derived"` hub bores, masses and
//! inertias), reported by [`ResolvedParameters`] and compared with what a case gives.

use crate::config::case::{BodyValues, Case, DynamicsSection, FrictionModel};
use crate::contact::friction::Friction;
use crate::contact::hertz::{effective_modulus_of, HertzContact};
use crate::contact::kinematics::SurfaceKinematics;
use crate::contact::load_sharing::pedrero_share_at;
use crate::dynamics::params::OperatingPoint;
use crate::geometry::planetary::PlanetarySet;
use crate::geometry::GearPair;
use crate::stiffness::fillet::FilletFoundation;
use serde::Serialize;

/// Largest friction coefficient accepted at the nominal operating point. Dry steel on
/// steel reaches ~0.8; a lubricated gear contact stays below ~0.1. Xu's regression is
/// unbounded outside the conditions it was fitted on (it exponentiates the roughness and
/// grows with the viscosity): above 1 it describes no contact, and the quasi-static
/// equilibrium (gear moment r_gb F + sum rho2 f = T) loses its meaning as mu rho2 nears
/// r_gb.
pub const MAX_FRICTION_COEFFICIENT: f64 = 1.0;

/// One contact along the path of contact at the nominal operating point.
#[derive(Debug, Clone, Copy)]
pub(crate) struct NominalContact {
    /// The Hertzian band under the pair's share of the static mesh force.
    pub hertz: HertzContact,
    /// The flanks' surface speeds at the nominal speeds.
    pub kinematics: SurfaceKinematics,
}

/// `n` + 1 contacts evenly along the path at the nominal load, shared between pairs by
/// paper eq. (7) (equally when the contact ratio is 2 or more), and at the nominal speeds.
pub(crate) fn nominal_contacts(case: &Case, pair: &GearPair, n: usize) -> Vec<NominalContact> {
    let op = OperatingPoint::of(&case.operating, pair);
    let force = op.static_mesh_force_n;
    let e_star = effective_modulus_of(&case.materials);
    let (omega_p, omega_g) = (op.pinion_speed_rad_s, op.gear_speed_rad_s);
    (0..=n)
        .map(|i| {
            let rho1 = pair.rho_start_m + pair.path_length_m() * i as f64 / n as f64;
            let rho2 = pair.rho_gear(rho1);
            let share = if pair.contact_ratio > 1.0 && pair.contact_ratio < 2.0 {
                pedrero_share_at(pair, rho1)
            } else {
                1.0 / pair.contact_ratio.floor().max(1.0)
            };
            NominalContact {
                hertz: HertzContact::with_modulus(
                    force * share,
                    pair.face_width_m,
                    rho1,
                    rho2,
                    e_star,
                ),
                kinematics: SurfaceKinematics::new(omega_p, omega_g, rho1, rho2),
            }
        })
        .collect()
}

/// Largest nominal Hertz pressure accepted at the pitch point, Pa. No steel stays elastic
/// far beyond ~2.5 GPa (case-hardened flanks, ISO 6336-5 allowable contact stresses stay
/// below 1.7 GPa); 10 GPa leaves room for any material the moduli allow, while the loads
/// that hung the solver (a torque of 9.2e18 N m) lie far above it.
pub const MAX_PITCH_PRESSURE_PA: f64 = 10e9;

/// A given value this far from the geometry's estimate (either way) is warned about.
pub const BODY_VALUE_FACTOR: f64 = 2.0;

/// Problems of a planetary case's load that need its geometry: the sun-planet flanks
/// under an equal share of the sun's torque, |T_s| / (N r_b,sun), with T_s from the input
/// torque by the set's torque split (T_s : T_r : T_c = 1 : z_r / z_s : -(1 + z_r / z_s),
/// Willis), must stay below [`MAX_PITCH_PRESSURE_PA`] at the pitch point (Hertz, as for a
/// pair). The ring-planet mesh carries the same force on a concave flank, so a lower
/// pressure: the sun mesh bounds the set.
pub fn planetary_domain_problems(case: &Case, set: &PlanetarySet) -> Vec<String> {
    let share = set.input_torque_per_sun_torque();
    let pair = &set.sun_planet;
    let torque = case.operating.load_torque_nm;
    let force = (torque / share).abs() / (set.planets() as f64 * pair.pinion.base_radius_m);
    pitch_pressure_gpa(case, pair, force)
        .map(|p| vec![format!(
            "`operating.load_torque_nm` = {torque} is more than this planetary set's flanks can carry: each sun-planet mesh would carry {force:.4e} N and see a Hertz pressure of {p:.1} GPa at its pitch point, above {} GPa, beyond any gear material's elastic range (the model is linear elastic)",
            MAX_PITCH_PRESSURE_PA * 1e-9
        )])
        .unwrap_or_default()
}

/// The Hertz pressure (Johnson 1985, line contact) at the pitch point of `pair` under
/// `force` N on its whole face, in GPa, when it is above [`MAX_PITCH_PRESSURE_PA`] (or
/// not a number); `None` when the flanks carry it.
fn pitch_pressure_gpa(case: &Case, pair: &GearPair, force: f64) -> Option<f64> {
    let rho1 = pair.rho_pitch_m;
    let h = HertzContact::with_modulus(
        force,
        pair.face_width_m,
        rho1,
        pair.rho_gear(rho1),
        effective_modulus_of(&case.materials),
    );
    (h.max_pressure_pa.is_nan() || h.max_pressure_pa > MAX_PITCH_PRESSURE_PA)
        .then_some(h.max_pressure_pa * 1e-9)
}

/// Problems of `case` that need its geometry: an impossible load for the flanks.
pub fn domain_problems(case: &Case, pair: &GearPair) -> Vec<String> {
    let torque = format!(
        "`operating.load_torque_nm` = {}",
        crate::format::shown(case.operating.load_torque_nm)
    );
    domain_problems_naming(case, pair, &torque)
}

/// [`domain_problems`] with the load named as `torque` says (a train's stage: its
/// pinion's torque, which the case's input torque sets through the ratios).
pub(crate) fn domain_problems_naming(case: &Case, pair: &GearPair, torque: &str) -> Vec<String> {
    let mut problems: Vec<String> = super::face_load::lead_refusal(case).into_iter().collect();
    let o = &case.operating;
    let force = OperatingPoint::of(o, pair).static_mesh_force_n;
    if let Some(p) = pitch_pressure_gpa(case, pair, force) {
        problems.push(format!(
            "{torque} is more than this pair's flanks can carry: one tooth pair at the pitch point would see a Hertz pressure of {p:.1} GPa, above {} GPa, beyond any gear material's elastic range (the model is linear elastic)",
            MAX_PITCH_PRESSURE_PA * 1e-9
        ));
    }
    if case.friction.model == FrictionModel::Xu2007 && problems.is_empty() {
        let friction = Friction::from_case(&case.friction);
        let roughness = case
            .surface
            .roughness_table_rms_um
            .iter()
            .fold(0.0_f64, |a, b| a.max(*b));
        let mu = nominal_contacts(case, pair, 64)
            .iter()
            .map(|c| {
                friction.coefficient(
                    &c.hertz,
                    &c.kinematics,
                    case.lubricant.viscosity_cp,
                    roughness,
                )
            })
            .fold(
                0.0_f64,
                |a, b| if b.is_nan() { f64::INFINITY } else { a.max(b) },
            );
        if mu > MAX_FRICTION_COEFFICIENT {
            problems.push(format!(
                "`friction.model` = \"xu2007\" gives a friction coefficient of {mu:.3} on this case's flanks at the nominal load and speed (with `lubricant.viscosity_cp` = {} and a roughness of {roughness} µm from `surface.roughness_table_rms_um`): above {MAX_FRICTION_COEFFICIENT}, no lubricated or dry steel contact; the conditions lie outside those Xu et al. fitted. Use friction.model = \"constant\", or a viscosity and roughness the regression covers",
                case.lubricant.viscosity_cp
            ));
        }
    }
    problems
}

/// One value the geometry could give, as the model uses it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResolvedValue {
    /// The case key.
    pub key: &'static str,
    /// The value used, in the key's unit.
    pub value: f64,
    /// The key's unit.
    pub unit: &'static str,
    /// Whether it was derived from the geometry (`"derived"` in the case).
    pub derived: bool,
    /// What the geometry gives, in the key's unit.
    pub geometry_estimate: f64,
}

/// The values a case may leave to the geometry, resolved: what every summary can state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResolvedParameters {
    /// Hub bores (mm), masses (kg) and polar inertias (kg m^2) of pinion and gear.
    pub values: Vec<ResolvedValue>,
    /// Density of the gear blanks, kg/m^3.
    pub blank_density_kg_per_m3: f64,
    /// h_f = r_f / r_int and theta_f (rad) of pinion and gear in Sainsot's fit, when the
    /// fillet foundation is included.
    pub fillet_h_f: Option<[f64; 2]>,
    /// theta_f of pinion and gear, rad (Sainsot's fit, with `fillet_h_f`).
    pub fillet_theta_f_rad: Option<[f64; 2]>,
}

impl ResolvedParameters {
    /// From the case, its pair (bores resolved), the resolved lumped parameters and the
    /// fillet foundations.
    pub fn new(
        case: &Case,
        pair: &GearPair,
        lumped: &DynamicsSection<f64>,
        fillets: Option<&[FilletFoundation; 2]>,
    ) -> Self {
        let density = case.dynamics.blank_density_kg_per_m3;
        let estimate = pair.blank_estimates(density);
        let mut values = Vec::new();
        for (key, gear, given) in [
            (
                "gear.hub_bore_radius_pinion_mm",
                &pair.pinion,
                case.gear.hub_bore_radius_pinion_mm,
            ),
            (
                "gear.hub_bore_radius_gear_mm",
                &pair.gear,
                case.gear.hub_bore_radius_gear_mm,
            ),
        ] {
            values.push(ResolvedValue {
                key,
                value: gear.bore_radius_m * 1e3,
                unit: "mm",
                derived: given.given().is_none(),
                geometry_estimate: gear.root_radius_m / crate::geometry::pair::DERIVED_BORE_H_F
                    * 1e3,
            });
        }
        let given = case.dynamics.given_body_values();
        for (((key, value), (_, est)), g) in lumped
            .body_values()
            .named()
            .into_iter()
            .zip(estimate.named())
            .zip(given)
        {
            values.push(ResolvedValue {
                key,
                value,
                unit: if key.contains("mass") { "kg" } else { "kg m^2" },
                derived: g.is_none(),
                geometry_estimate: est,
            });
        }
        Self {
            values,
            blank_density_kg_per_m3: density,
            fillet_h_f: fillets.map(|f| [f[0].h_f, f[1].h_f]),
            fillet_theta_f_rad: fillets
                .map(|f| [f[0].root_half_angle_rad, f[1].root_half_angle_rad]),
        }
    }
}

/// What a summary records beside the case as given (`metadata.resolved`): the values the
/// model used where the case may leave them to the geometry, and the operating point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Resolved {
    /// The values resolved from the geometry.
    #[serde(flatten)]
    pub parameters: ResolvedParameters,
    /// The nominal operating point (speeds, torques, static mesh force).
    pub operating_point: OperatingPoint,
}

/// Warnings for masses and inertias given more than [`BODY_VALUE_FACTOR`] from the
/// geometry's estimate. The built-in values on the built-in pair are not checked: the
/// paper printed them for that pair (they are 4.8-7.5 times a bare blank, so they include
/// shafts and hubs; docs/MODEL.md, section 7).
pub fn body_value_warnings(case: &Case, estimate: &BodyValues) -> Vec<String> {
    let builtin = Case::default();
    let builtin_pair = case.gear.same_pair(&builtin.gear);
    let builtin_values = builtin.dynamics.given_body_values();
    case.dynamics
        .given_body_values()
        .into_iter()
        .zip(builtin_values)
        .zip(estimate.named())
        .filter_map(|((given, paper), (key, est))| {
            let v = given?;
            if builtin_pair && given == paper {
                return None;
            }
            let factor = (v / est).max(est / v);
            (factor > BODY_VALUE_FACTOR).then(|| {
                format!(
                    "`{key}` = {v:.4e} is {factor:.1} times {} the {est:.4e} of a solid blank of this pair (docs/MODEL.md, section 7); check it, or write \"derived\"",
                    if v > est { "above" } else { "below" }
                )
            })
        })
        .collect()
}

/// The axial bearing keys on a spur pair or a spur train: a spur mesh has no axial force,
/// so its bodies carry no axial degree of freedom and the keys change nothing
/// (docs/MODEL.md 11.6).
pub fn axial_key_warnings(case: &Case) -> Vec<String> {
    let d = &case.dynamics;
    let given = [
        (
            "dynamics.bearing_axial_stiffness_pinion_n_per_m",
            d.bearing_axial_stiffness_pinion_n_per_m,
        ),
        (
            "dynamics.bearing_axial_stiffness_gear_n_per_m",
            d.bearing_axial_stiffness_gear_n_per_m,
        ),
        (
            "dynamics.bearing_axial_damping_pinion_n_s_per_m",
            d.bearing_axial_damping_pinion_n_s_per_m,
        ),
        (
            "dynamics.bearing_axial_damping_gear_n_s_per_m",
            d.bearing_axial_damping_gear_n_s_per_m,
        ),
    ];
    given
        .iter()
        .filter_map(|(key, v)| v.map(|v| format!("`{key}` = {v} is ignored: a spur mesh (`gear.helix_angle_deg` = 0) has no axial force, so its gears carry no axial degree of freedom (docs/MODEL.md 11.6)")))
        .collect()
}

/// Warnings for a helical pair's axial or tilt damping given without that body's stiffness
/// of the same kind: the body's axial bearing is then rigid (docs/MODEL.md 11.6), or its
/// tilting held rigidly (11.8), so the damping is unused.
pub fn damping_alone_warnings(case: &Case) -> Vec<String> {
    let d = &case.dynamics;
    let axial = "axial bearing is rigid (docs/MODEL.md 11.6); give the stiffness for an elastic axial bearing";
    let tilt = "tilting is held rigidly (docs/MODEL.md 11.8); give the stiffness for an elastic tilting bearing";
    [
        ("axial", "pinion", "n_s_per_m", "n_per_m", d.bearing_axial_damping_pinion_n_s_per_m, d.bearing_axial_stiffness_pinion_n_per_m, axial),
        ("axial", "gear", "n_s_per_m", "n_per_m", d.bearing_axial_damping_gear_n_s_per_m, d.bearing_axial_stiffness_gear_n_per_m, axial),
        ("tilt", "pinion", "nm_s_per_rad", "nm_per_rad", d.bearing_tilt_damping_pinion_nm_s_per_rad, d.bearing_tilt_stiffness_pinion_nm_per_rad, tilt),
        ("tilt", "gear", "nm_s_per_rad", "nm_per_rad", d.bearing_tilt_damping_gear_nm_s_per_rad, d.bearing_tilt_stiffness_gear_nm_per_rad, tilt),
    ]
    .into_iter()
    .filter_map(|(kind, body, c_unit, k_unit, c, k, why)| match (c, k) {
        (Some(c), None) => Some(format!("`dynamics.bearing_{kind}_damping_{body}_{c_unit}` = {c} is ignored: without `dynamics.bearing_{kind}_stiffness_{body}_{k_unit}` the {body}'s {why}")),
        _ => None,
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load_case;

    fn warnings(sets: &[&str]) -> Vec<String> {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        let case = load_case("", &sets).unwrap();
        let pair = GearPair::from_case(&case.gear).unwrap();
        body_value_warnings(
            &case,
            &pair.blank_estimates(case.dynamics.blank_density_kg_per_m3),
        )
    }

    #[test]
    fn values_far_from_the_blank_are_warned_about_with_both_numbers() {
        // The built-in case on its own pair: no warning.
        assert!(warnings(&[]).is_empty());
        // The paper's pinion mass (0.7 kg) on a 3 mm, 25/50 pair: the blank of that pinion
        // (derived bore) is 0.83 kg x 20/30 = 0.553 kg at b = 20 mm: factor 1.27, quiet;
        // its gear mass 1.822 kg against 2.148 kg: quiet; the inertias are far off.
        let w = warnings(&[
            "gear.module_mm=3",
            "gear.teeth_pinion=25",
            "gear.teeth_gear=50",
        ]);
        assert!(w.iter().all(|m| m.contains("inertia")), "{w:?}");
        let w = warnings(&["dynamics.mass_pinion_kg=0.05"]);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].contains("dynamics.mass_pinion_kg") && w[0].contains("5.0000e-2"));
        // Derived values are never warned about.
        assert!(
            warnings(&["dynamics.mass_pinion_kg=derived", "gear.module_mm=3"])
                .iter()
                .all(|m| !m.contains("mass_pinion"))
        );
    }

    #[test]
    fn friction_beyond_any_contact_is_refused() {
        // Xu's coefficient on the paper's pair: a few hundredths by default (docs/MODEL.md);
        // with a cold heavy oil (72 000 cP) it passes 4.
        let pair = GearPair::from_case(&Case::default().gear).unwrap();
        let case = load_case("", &["lubricant.viscosity_cp=72000".into()]).unwrap();
        let p = domain_problems(&case, &pair);
        assert!(
            p[0].contains("friction.model") && p[0].contains("lubricant.viscosity_cp"),
            "{p:?}"
        );
        // The fuzzer's case (fuzz target case_values): a 1 GPa pinion in that oil gave a
        // negative quasi-static mesh force; refused now, before any model is built.
        let fuzzed = load_case(
            "",
            &[
                "lubricant.viscosity_cp=72000".into(),
                "materials.youngs_modulus_pinion_gpa=1.0000077".into(),
                "dynamics.coupling_damping_motor_nm_s_per_rad=9.96e6".into(),
            ],
        )
        .unwrap();
        let e = crate::study::Model::from_case(&fuzzed).err().unwrap();
        assert!(e.0[0].contains("friction coefficient"), "{e}");
        let paper_mm = load_case(
            "[friction]\nxu_radius_unit = \"mm\"\n[surface]\nroughness_table_rms_um = [2.1, 1.9, 1.5]\n",
            &[],
        )
        .unwrap();
        assert!(domain_problems(&paper_mm, &pair).is_empty());
    }

    #[test]
    fn loads_beyond_any_flank_are_refused() {
        let case = load_case("", &["operating.load_torque_nm=1e7".into()]).unwrap();
        let pair = GearPair::from_case(&case.gear).unwrap();
        let p = domain_problems(&case, &pair);
        assert!(p[0].contains("operating.load_torque_nm"), "{p:?}");
        assert!(domain_problems(&Case::default(), &pair).is_empty());
    }
}
