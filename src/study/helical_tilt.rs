//! The tilting degrees of freedom of a helical pair (docs/MODEL.md 11.8): the mesh's
//! tilting terms from the slice model, the tilting bearings from `[dynamics]`, the studies
//! that refuse them, and the face load the mean tilt implies.

use super::helical::pinion_axial_sign;
use super::model_error::ModelError;
use super::Model;
use crate::config::case::Case;
use crate::dynamics::assembly::elements::Elements;
use crate::dynamics::assembly::elements::MeshTilt;
use crate::dynamics::assembly::Assembly;
use crate::dynamics::params::{DynamicParams, TiltSupport};
use crate::dynamics::response::DynamicResponse;
use crate::geometry::helical::HelicalPair;
use crate::stiffness::face_load::FaceLoad;
use crate::stiffness::helical::SliceMeshStiffness;

/// The mesh's tilting terms (docs/MODEL.md 11.8) from the slice model `s`: with the
/// moments K_n = int_A^E k rho^n drho of one slice over the path
/// (`SliceMeshStiffness::path_moments`), the mean mesh stiffness K = N K_0 / p_b, the
/// stiffness centroid along the path rho_bar = K_1 / K_0 and its spread
/// sigma^2 = K_2 / K_0 - rho_bar^2:
///   mu = s t rho_bar                                  (m),
///   J  = K [b^2 (1 - 1/N^2) / 12 + t^2 sigma^2]       (N m/rad),
/// the period means of sum k_j mu_j / sum k_j and of sum k_j (mu_j - mu)^2 over the slices
/// in contact, mu_j = (y_j - b/2) + s t rho_j (s the hand's sign of
/// [`pinion_axial_sign`], t = tan(beta_b), y_j the slice's face position, rho_j its
/// position on the path): each face slice sweeps the whole path once per base pitch.
///
/// With lead gaps G_j every slice loaded adds the period mean of the slices' moment of
/// their gaps, (K / N) sum_j G_j (y_j - b/2) (N m), to the relative tilt's generalised
/// force (`gap_moment_nm`; the part along mu is in the mesh force already).
pub fn mesh_tilt(s: &SliceMeshStiffness, gaps_m: Option<&[f64]>) -> MeshTilt {
    let hp = s.pair();
    let t = &hp.transverse;
    let [k0, k1, k2] = s.path_moments();
    let n = s.slices() as f64;
    let b = hp.face_width_m;
    let st = pinion_axial_sign(hp.hand_pinion) * hp.base_helix_angle_rad.tan();
    let k_mean = n * k0 / t.base_pitch_m;
    let rho_bar = k1 / k0;
    let spread = (k2 / k0 - rho_bar * rho_bar).max(0.0);
    let centre = 0.5 * b;
    let gap_moment_nm = gaps_m.map_or(0.0, |g| {
        let y = s.positions_m();
        k_mean / n * g.iter().zip(y).map(|(g, y)| g * (y - centre)).sum::<f64>()
    });
    MeshTilt {
        centre_lever_m: st * rho_bar,
        signed_tan_base_helix: st,
        gap_moment_nm,
        line_of_action_length_m: t.rho_gear(0.0),
        tilting_stiffness_nm_per_rad: k_mean
            * (b * b * (1.0 - 1.0 / (n * n)) / 12.0 + st * st * spread),
    }
}

/// The tilting keys of `case` as a message names them: "`key` = value, ...".
fn tilt_keys_named(case: &Case) -> String {
    let keys: Vec<String> = case
        .dynamics
        .tilt_keys()
        .iter()
        .map(|(k, v)| format!("`{k}` = {v}"))
        .collect();
    keys.join(", ")
}

/// The static relative tilt tau = a_g - a_p (rad) of an unmodified pair at the mean mesh
/// force `force_n` (N), friction and the lines' fluctuation left out (docs/MODEL.md 11.8):
/// the slices' moment about the plane of action's normal is mu F + J tau on the pinion and
/// s t L F - (mu F + J tau) on the gear (the generalised forces of the slice deflections
/// c_j, 11.8), each held by its bearing, k_t a = moment (a = 0 where tilting is rigid), so
///   tau (1 + J (c_p + c_g)) = s t L F c_g - mu F (c_p + c_g),  c = 1 / k_t (0 rigid).
pub(crate) fn static_relative_tilt_rad(
    m: &MeshTilt,
    bearings: [Option<(f64, f64)>; 2],
    force_n: f64,
) -> f64 {
    let [cp, cg] = bearings.map(|b| b.map_or(0.0, |(k, _)| 1.0 / k));
    let st_l = m.signed_tan_base_helix * m.line_of_action_length_m;
    (st_l * force_n * cg - m.centre_lever_m * force_n * (cp + cg))
        / (1.0 + m.tilting_stiffness_nm_per_rad * (cp + cg))
}

/// Diametral moment of inertia of a body of mass m (kg) and polar inertia J (kg m^2) on a
/// face of width b (m), kg m^2: J / 2 + m b^2 / 12, a solid cylinder's (the blank's,
/// docs/MODEL.md 11.8; exact for a solid blank, whose J = m r^2 / 2).
pub fn diametral_inertia_kg_m2(mass_kg: f64, polar_kg_m2: f64, face_width_m: f64) -> f64 {
    0.5 * polar_kg_m2 + mass_kg * face_width_m * face_width_m / 12.0
}

/// The tilting degrees of freedom of a helical case, or None where the case gives no
/// tilting stiffness (tilting held rigidly: the planar or axial model exactly).
///
/// With lead gaps (`load`, the static face load of docs/MODEL.md 11.2) the linear law
/// holds only while every slice carries load: a case whose static solve leaves a slice
/// unloaded at some mesh position is refused, naming the keys.
pub fn tilt_support(
    case: &Case,
    s: &SliceMeshStiffness,
    params: &DynamicParams,
    load: Option<&FaceLoad>,
) -> Result<Option<TiltSupport>, ModelError> {
    let bearings = case.dynamics.tilt_bearings();
    if bearings.iter().all(Option::is_none) {
        return Ok(None);
    }
    if let Some(f) = load.filter(|f| f.fewest_loaded_slices() < s.slices()) {
        return Err(ModelError(vec![format!(
            "{} with the lead keys {}: the static face load leaves only {} of the {} slices loaded at some mesh position, and the tilting degrees of freedom take a face whose every slice is loaded (docs/MODEL.md 11.8); reduce the modification or the misalignment, or remove the tilting keys",
            tilt_keys_named(case),
            super::face_load::lead_keys(case).join(", "),
            f.fewest_loaded_slices(),
            s.slices()
        )]));
    }
    if load.is_none() {
        let force = params.operating.static_mesh_force_n;
        let tau = static_relative_tilt_rad(&mesh_tilt(s, None), bearings, force);
        let k_mean = s.mean_stiffness_n_per_m();
        if k_h_beta_of_tilt(s.pair(), s.slices(), k_mean, force, tau).is_none() {
            return Err(ModelError(vec![format!(
                "{}: the static mean tilt {tau:.3e} rad between the gears would unload a face end of the {} mm face at the mean mesh force {force:.0} N (K_Hbeta over 2), and the tilting degrees of freedom take a face whose every slice is loaded (their linear law, docs/MODEL.md 11.8); stiffen the tilting bearings or remove the keys",
                tilt_keys_named(case),
                1e3 * s.pair().face_width_m
            )]));
        }
    }
    let l = &params.lumped;
    let b = s.pair().face_width_m;
    Ok(Some(TiltSupport {
        mesh: mesh_tilt(s, load.map(|f| &f.gaps_m[..])),
        bearings,
        diametral_inertia_kg_m2: [
            diametral_inertia_kg_m2(l.mass_pinion_kg, l.inertia_pinion_kg_m2, b),
            diametral_inertia_kg_m2(l.mass_gear_kg, l.inertia_gear_kg_m2, b),
        ],
    }))
}

/// Refuse the tilting keys for `study` (a command or a case kind that has no tilting
/// degrees of freedom yet), naming the keys; Ok without them.
pub(crate) fn refuse_tilt(case: &Case, study: &str) -> Result<(), ModelError> {
    tilt_refusal(case, study).map_or(Ok(()), |r| Err(ModelError(vec![r])))
}

/// The refusal of the tilting keys by `study` (a command or a case kind that has no
/// tilting degrees of freedom yet), naming the keys; None without them.
pub(crate) fn tilt_refusal(case: &Case, study: &str) -> Option<String> {
    let keys = case.dynamics.tilt_keys();
    (!keys.is_empty()).then(|| {
        let named: Vec<String> = keys.iter().map(|(k, v)| format!("`{k}` = {v}")).collect();
        format!(
            "{}: the tilting degrees of freedom are built only for a single helical pair in `gearwear dynamics`, `gearwear signals` and `gearwear stiffness` (docs/MODEL.md 11.8); {study} does not take them yet (its face load and wear would ignore the tilt); remove them for this study",
            named.join(", ")
        )
    })
}

/// The tilting keys on a spur pair: ignored with a warning (a spur mesh with rigid bodies
/// has no mean tilting moment from its uniform face load, and the spur model has no
/// slices to tilt; docs/MODEL.md 11.8).
pub fn tilt_key_warnings(case: &Case) -> Vec<String> {
    case.dynamics
        .tilt_keys()
        .into_iter()
        .map(|(k, v)| format!("`{k}` = {v} is ignored: a spur pair (`gear.helix_angle_deg` = 0) is modelled without tilting degrees of freedom (docs/MODEL.md 11.8)"))
        .collect()
}

/// K_Hbeta that a mean relative tilt `tau` (rad, a_g - a_p about the plane of action's
/// normal) implies for the unmodified pair `hp` at the mean mesh force `force_n` (N) and
/// mean mesh stiffness `k_mean` (N/m) with N slices: the slices' period-mean load is
/// linear across the face, w(y_j) = F / b + K tau (y_j - b/2) / b (each face slice sweeps
/// the path, so its mean compression gains tau (y_j - b/2) beside the common part), its
/// largest at the end slice, y_j - b/2 = +-(b/2)(1 - 1/N):
///   K_Hbeta = 1 + K |tau| (b/2) (1 - 1/N) / F,
/// while every slice stays loaded (the value up to 2); None when it exceeds 2 (an end of
/// the face would unload, which the linear law does not follow) or the force is 0.
pub fn k_h_beta_of_tilt(
    hp: &HelicalPair,
    slices: usize,
    k_mean: f64,
    force_n: f64,
    tau: f64,
) -> Option<f64> {
    let half = 0.5 * hp.face_width_m * (1.0 - 1.0 / slices as f64);
    let k = 1.0 + k_mean * tau.abs() * half / force_n;
    (force_n > 0.0 && k <= 2.0).then_some(k)
}

/// The relative tilt tau = a_g - a_p (rad, about the plane of action's normal) at each
/// recorded sample of `r`, from the assembled coordinates; None without tilting
/// coordinates.
pub fn relative_tilt_rad(model: &Model, r: &DynamicResponse) -> Option<Vec<f64>> {
    model.params.tilt?;
    let asm = Assembly::new(Elements::single_pair(&model.params, &model.pair)).ok()?;
    let h = asm.relative_tilt_gradient(0);
    let q = &r.signals.displacement;
    Some(
        q.iter()
            .map(|qi| h.iter().map(|(k, hk)| hk * qi[*k]).sum())
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load_case;
    use crate::study::helical::HelicalModel;

    /// The mesh's mean lever and tilting stiffness against a second method: the time
    /// average, over 4000 positions of the contact lines within one base pitch, of the
    /// sums over every slice of every line in contact of k, k mu_j and k mu_j^2, mu_j
    /// built from the slice's face position (the face slice the line's slice sits on) and
    /// its path position rho_l + o_i, as docs/MODEL.md 11.8 defines them, with no path
    /// integral. Tolerance 1e-4: the slice stiffness jumps where a slice enters or leaves
    /// the path, so a uniform sampling of the lines' positions converges as 1/M (M =
    /// 4000) at worst; measured 2.5e-6 (K), 4.7e-6 (mu) and 8.9e-6 (J).
    #[test]
    fn the_mean_lever_and_tilting_stiffness_are_the_slices_time_means() {
        for hand in ["right", "left"] {
            let sets = vec![
                "gear.helix_angle_deg=15".to_string(),
                "stiffness.slices=40".to_string(),
                format!("gear.helix_hand_pinion=\"{hand}\""),
            ];
            let hm = HelicalModel::from_case(&load_case("", &sets).unwrap()).unwrap();
            let s = &hm.slices;
            let hp = s.pair();
            let t = &hp.transverse;
            let b = hp.face_width_m;
            let grid = s.line_grid();
            let st = pinion_axial_sign(hp.hand_pinion) * hp.base_helix_angle_rad.tan();
            let m = 4000;
            let (mut k0, mut k1, mut k2) = (0.0, 0.0, 0.0);
            for u in 0..m {
                let mut rho_l = t.rho_start_m - grid.lead + t.base_pitch_m * u as f64 / m as f64;
                while rho_l <= t.rho_end_m {
                    for (i, o) in grid.offsets.iter().enumerate() {
                        let r = rho_l + o;
                        if !(t.rho_start_m..=t.rho_end_m).contains(&r) {
                            continue;
                        }
                        let y = s.positions_m()[s.face_slice_of_line_slice(i)];
                        let k = s.slice().pair_stiffness_n_per_m(r);
                        let mu = (y - 0.5 * b) + st * r;
                        k0 += k;
                        k1 += k * mu;
                        k2 += k * mu * mu;
                    }
                    rho_l += t.base_pitch_m;
                }
            }
            let (k0, k1, k2) = (k0 / m as f64, k1 / m as f64, k2 / m as f64);
            let tilt = mesh_tilt(s, None);
            let lever = k1 / k0;
            let spring = k2 - k1 * k1 / k0;
            eprintln!(
                "{hand}: K {k0:.6e} vs {:.6e}; mu {lever:.6e} vs {:.6e}; J {spring:.6e} vs {:.6e}",
                s.mean_stiffness_n_per_m(),
                tilt.centre_lever_m,
                tilt.tilting_stiffness_nm_per_rad
            );
            assert!((k0 / s.mean_stiffness_n_per_m() - 1.0).abs() < 1e-4);
            assert!((lever / tilt.centre_lever_m - 1.0).abs() < 1e-4, "{hand}");
            assert!(
                (spring / tilt.tilting_stiffness_nm_per_rad - 1.0).abs() < 1e-4,
                "{hand}"
            );
        }
    }
}
