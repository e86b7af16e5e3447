//! `gearwear dynamics` on a planetary case: the dynamic model of the set
//! (`dynamics::planetary_dynamic`) built from `[planetary]` (teeth, meshes, phases) and
//! the lumped parameters (masses, inertias, supports: `[planetary.lumped]`'s given keys,
//! the others derived from the geometry, `study::planetary_lumped`), driven by a torque on the input
//! member, its steady state, and the numbers of its summary: each mesh's mean and largest
//! force, the load sharing factor per planet and the dynamic factor (docs/MODEL.md 12.5).
//!
//! Planet pin position errors (`planetary.planet_tangential_error_um`,
//! `planet_radial_error_um`) open gaps on each planet's meshes
//! (`dynamics::planetary_dynamic::pin_error_gaps`), set after the torque's sense is chosen
//! on the error-free set; a floating sun (`planetary.floating_sun`) has no lateral bearing.
//!
//! The radii and operating pressure angles come from the geometry (the lumped section's
//! radii, mean mesh stiffness and pressure angle serve its modal table only); the input
//! member's torsional support is left out (a constant torque drives it); the output and
//! fixed members are held by their torsional supports (the output's: the load's shaft
//! to a load at constant speed), which must then be positive.

use super::model::ModelError;
use super::planetary::PlanetaryStudy;
use crate::config::case::Case;
use crate::config::planetary::Member;
use crate::dynamics::planetary_dynamic::{MeshStiffnessSource, PlanetaryDynamic};
use crate::dynamics::planetary_lumped::PlanetaryLumped;
use crate::dynamics::planetary_steady::{
    solve_planetary_steady_state, PlanetaryDynamicsError, PlanetaryResponse, PlanetarySettings,
};

/// A planetary case's dynamic model and its steady state.
#[derive(Debug, Clone)]
pub struct PlanetaryDynamics {
    /// The stiffness study it is built on (geometry, meshes, speeds).
    pub study: PlanetaryStudy,
    /// The dynamic model, loaded.
    pub model: PlanetaryDynamic,
    /// The torque on the input member, N m, with the sense that loads the modelled flanks.
    pub input_torque_nm: f64,
    /// Integration settings.
    pub settings: PlanetarySettings,
}

/// Index of a member in the lumped model's order [carrier, ring, sun].
pub(crate) fn lumped_index(m: Member) -> usize {
    match m {
        Member::Carrier => 0,
        Member::Ring => 1,
        Member::Sun => 2,
    }
}

impl PlanetaryDynamics {
    /// Build the model from a validated case; `ModelError` names each missing or invalid key.
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        let study = PlanetaryStudy::from_case(case)?;
        let mut params =
            PlanetaryLumped::from_section(&study.lumped, study.set.planet_angles_rad.clone())
                .map_err(|p| ModelError(p.messages()))?;
        let set = &study.set;
        let radius_m = [
            set.carrier_radius_m,
            set.ring_planet.ring.base_radius_m,
            set.sun_planet.pinion.base_radius_m,
            set.sun_planet.gear.base_radius_m,
        ];
        for (i, r) in radius_m.iter().enumerate() {
            let ratio = (params.radius_m[i] / r).powi(2);
            params.inertia_over_r2_kg[i] *= ratio;
            if i < 3 {
                params.torsional_n_per_m[i] *= ratio;
            }
        }
        params.radius_m = radius_m;
        params.mesh_stiffness_n_per_m = study.meshes.mean_n_per_m();
        params.torsional_n_per_m[lumped_index(set.input)] = 0.0;
        if study.section.floating_sun {
            // A floating sun (docs/MODEL.md 12.8): no lateral bearing, held by its meshes.
            params.bearing_n_per_m[lumped_index(Member::Sun)] = 0.0;
        }
        let mut errs = Vec::new();
        for m in [set.output, set.fixed] {
            if params.torsional_n_per_m[lumped_index(m)] <= 0.0 {
                errs.push(format!("`planetary.lumped.torsional_stiffness_{}_nm_per_rad` = 0 is invalid for `gearwear dynamics`: the {} is the set's {} and is held by its torsional support, which must be positive", m.name(), m.name(), if m == set.fixed { "fixed member" } else { "output" }));
            }
        }
        if !errs.is_empty() {
            return Err(ModelError(errs));
        }
        let alpha = [
            set.sun_planet.operating_pressure_angle_rad,
            set.ring_planet.operating_pressure_angle_rad,
        ];
        let f_m = set.mesh_frequency_hz(study.speeds_hz);
        let mut model = PlanetaryDynamic::new(
            params,
            alpha,
            MeshStiffnessSource::Tables(Box::new(study.meshes.clone())),
            f_m,
            case.dynamics.mesh_damping_ratio,
        );
        let torque = load_input(&mut model, set.input, case.operating.load_torque_nm)?;
        model.set_pin_errors(&study.section.pin_errors_m());
        check_static_contact(&model, &study.section, case.operating.load_torque_nm)?;
        let nm = &case.numerics;
        let settings = PlanetarySettings {
            samples_per_period: nm.steps_per_mesh_period.max(8) as usize,
            integration_tolerance: nm.integration_tolerance,
            max_periods: nm.max_mesh_periods.max(1) as usize,
            steady_state_tolerance: nm.steady_state_tolerance,
        };
        Ok(Self {
            study,
            model,
            input_torque_nm: torque,
            settings,
        })
    }

    /// The steady state (`dynamics::planetary_steady`).
    pub fn solve(&mut self) -> Result<PlanetaryResponse, PlanetaryDynamicsError> {
        solve_planetary_steady_state(&mut self.model, &self.settings)
    }

    /// The nominal force of every sun (and ring) mesh with equal sharing, N: the sun's
    /// torque |T_s| / (N r_bs), with T_s from the input torque by the set's torque split
    /// (T_s : T_r : T_c = 1 : z_r / z_s : -(1 + z_r / z_s), Willis). A mesh's dynamic
    /// factor is its largest force over this (docs/MODEL.md 12.6).
    pub fn nominal_mesh_force_n(&self) -> f64 {
        let set = &self.study.set;
        (self.input_torque_nm / set.input_torque_per_sun_torque()).abs()
            / (set.planets() as f64 * self.model.params.radius_m[2])
    }
}

/// Load sharing factors L_n = N F_n / sum_k F_k of the planets' forces `f` (one mesh kind),
/// all 0 when no planet carries load (docs/MODEL.md 12.8).
pub fn shares(f: &[f64]) -> Vec<f64> {
    let sum: f64 = f.iter().sum();
    f.iter()
        .map(|v| {
            if sum > 0.0 {
                f.len() as f64 * v / sum
            } else {
                0.0
            }
        })
        .collect()
}

/// Put the torque `torque_nm` on the input member's u (as T / r), with the sense that
/// compresses the sun meshes statically (the drive flanks the model describes); returns
/// the signed torque.
pub(crate) fn load_input(
    model: &mut PlanetaryDynamic,
    input: Member,
    torque_nm: f64,
) -> Result<f64, ModelError> {
    let j = lumped_index(input);
    let u = PlanetaryDynamic::rotation_index(j);
    model.force_n[u] = torque_nm / model.params.radius_m[j];
    let Some(q) = model.static_deflection() else {
        return Err(ModelError(vec!["the planetary set has a member with no path to ground: give `planetary.lumped`'s bearing stiffness of the sun, ring and carrier, or the torsional support of the output and fixed members, a positive value".into()]));
    };
    let n = model.dofs();
    let y: Vec<f64> = q
        .iter()
        .copied()
        .chain(std::iter::repeat_n(0.0, n))
        .collect();
    let sun: f64 = model
        .mesh_forces(0.0, &y)
        .iter()
        .take(model.params.planet_angles_rad.len())
        .sum();
    if sun < 0.0 || (sun == 0.0 && torque_nm != 0.0) {
        model.force_n[u] = -model.force_n[u];
        return Ok(-torque_nm);
    }
    Ok(torque_nm)
}

/// With pin errors or a floating sun, the static equilibrium at mean mesh stiffness must
/// keep every mesh compressed: a planet whose error keeps it off the load would be held by
/// nothing (the model has no back flanks) and a floating sun held by too few meshes has no
/// path to ground. Each is an input error naming the keys and the planets.
fn check_static_contact(
    model: &PlanetaryDynamic,
    section: &crate::config::planetary::PlanetarySection,
    torque_nm: f64,
) -> Result<(), ModelError> {
    let keys = || {
        format!(
            "`planetary.planet_tangential_error_um` = {:?}, `planetary.planet_radial_error_um` = {:?}, `planetary.floating_sun` = {} at `operating.load_torque_nm` = {torque_nm}",
            section.planet_tangential_error_um.as_deref().unwrap_or(&[]),
            section.planet_radial_error_um.as_deref().unwrap_or(&[]),
            section.floating_sun,
        )
    };
    let Some(f) = model.static_mesh_forces() else {
        return Err(ModelError(vec![format!(
            "{} are invalid: the set has a member with no path to ground",
            keys()
        )]));
    };
    let n = f.len() / 2;
    let off: Vec<String> = (0..n)
        .filter(|p| f[*p] <= 0.0 || f[n + p] <= 0.0)
        .map(|p| (p + 1).to_string())
        .collect();
    if off.is_empty() {
        return Ok(());
    }
    Err(ModelError(vec![format!(
        "{} are invalid: the static equilibrium with every mesh closed puts the meshes of planet {} in tension, so a planet would carry no load (the model has no back flanks to hold an unloaded planet): give smaller errors or a larger torque",
        keys(),
        off.join(", ")
    )]))
}
