//! Results of `gearwear stiffness` on a planetary case (`[planetary]`): `summary.json` with
//! the set's geometry (planet angles, contact ratios, carrier radius), each mesh's mean,
//! smallest and largest stiffness, the relative phases of every mesh (Parker & Lin 2004),
//! the member speeds, mesh and planet-pass frequencies at the case's input speed, and, with
//! `[planetary.lumped]`, the natural frequencies of the time-invariant lumped model with
//! each mode's class (docs/MODEL.md section 12); `mesh_stiffness_carrier_revolution.csv`,
//! every mesh's stiffness over one carrier revolution with its phase (section 12.4).

use super::artifacts::Artifacts;
use crate::format::shown;
use crate::study::planetary::PlanetaryStudy;
use serde_json::json;

/// The geometry block of `summary.json`.
fn geometry_json(s: &PlanetaryStudy) -> serde_json::Value {
    let set = &s.set;
    json!({
        "planets": set.planets(),
        "planet_angles_deg": set.planet_angles_rad.iter().map(|a| a.to_degrees()).collect::<Vec<_>>(),
        "teeth_sun": set.teeth_sun(),
        "teeth_planet": set.teeth_planet(),
        "teeth_ring": set.teeth_ring(),
        "carrier_radius_mm": set.carrier_radius_m * 1e3,
        "contact_ratio_sun_planet": set.sun_planet.contact_ratio,
        "contact_ratio_ring_planet": set.ring_planet.contact_ratio,
        "operating_pressure_angle_sun_planet_deg": set.sun_planet.operating_pressure_angle_rad.to_degrees(),
        "operating_pressure_angle_ring_planet_deg": set.ring_planet.operating_pressure_angle_rad.to_degrees(),
    })
}

/// The kinematics block: signed member speeds, the ratio, the mesh and planet-pass
/// frequencies, Hz.
fn kinematics_json(s: &PlanetaryStudy) -> serde_json::Value {
    let [sun, carrier, ring] = s.speeds_hz;
    json!({
        "input": s.set.input.name(),
        "output": s.set.output.name(),
        "fixed": s.set.fixed.name(),
        "ratio_input_to_output": s.set.ratio(),
        "speed_sun_hz": sun,
        "speed_carrier_hz": carrier,
        "speed_ring_hz": ring,
        "speed_planet_relative_to_carrier_hz": -(sun - carrier) * s.set.teeth_sun() as f64 / s.set.teeth_planet() as f64,
        "mesh_frequency_hz": s.set.mesh_frequency_hz(s.speeds_hz),
        "planet_pass_frequency_hz": s.set.planet_pass_frequency_hz(s.speeds_hz),
    })
}

/// The lumped parameters used (`[planetary.lumped]`'s units: kg, kg m^2, mm, N/m,
/// N m/rad, deg) and the keys derived from the geometry (absent or `"derived"` in the
/// case; docs/MODEL.md 12.4), so a user sees what the model took.
pub(crate) fn lumped_json(s: &PlanetaryStudy) -> serde_json::Value {
    let values = serde_json::to_value(&s.lumped).unwrap_or_default();
    let given = s
        .section
        .lumped
        .as_ref()
        .and_then(|l| serde_json::to_value(l).ok())
        .unwrap_or_default();
    let derived: Vec<&String> = values
        .as_object()
        .map(|o| {
            o.keys()
                .filter(|k| !given[k.as_str()].is_number())
                .collect()
        })
        .unwrap_or_default();
    json!({ "values": values, "derived_keys": derived })
}

/// The modes block: each natural frequency with its class and multiplicity.
fn modes_json(s: &PlanetaryStudy) -> serde_json::Value {
    match &s.modes {
        Some(modes) => json!({
            "undamped_natural_frequencies_hz": modes.iter().map(|m| m.frequency_hz).collect::<Vec<_>>(),
            "mode_classes": modes.iter().map(|m| m.class.name()).collect::<Vec<_>>(),
            "multiplicities": modes.iter().map(|m| m.multiplicity).collect::<Vec<_>>(),
            "source": "lumped_parameters: [planetary.lumped]'s given keys, the others derived from the geometry (Lin & Parker 1999, time-invariant, carrier frame without gyroscopic terms)",
        }),
        None => json!(null),
    }
}

/// Everything `gearwear stiffness` writes for a planetary case: `summary.json` content.
pub fn planetary_stiffness_artifacts(s: &PlanetaryStudy) -> Artifacts {
    let (ring_min, ring_max) = s.ring_extremes_n_per_m();
    let ring_mean = s.ring_mesh.mean_stiffness_n_per_m();
    let sun = &s.sun_mesh;
    let v = json!({
        "planetary": {
            "geometry": geometry_json(s),
            "mesh_stiffness_sun_planet": {
                "min_n_per_m": sun.min_stiffness_n_per_m(),
                "max_n_per_m": sun.max_stiffness_n_per_m(),
                "mean_n_per_m": sun.mean_stiffness_n_per_m(),
            },
            "mesh_stiffness_ring_planet": {
                "min_n_per_m": ring_min,
                "max_n_per_m": ring_max,
                "mean_n_per_m": ring_mean,
                "rim": "rigid",
            },
            "mesh_phases": {
                "sun_planet_cycles": s.set.sun_planet_phases(),
                "ring_planet_cycles": s.set.ring_planet_phases(),
                "ring_to_sun_cycles": s.set.ring_sun_phase(),
            },
            "kinematics": kinematics_json(s),
            "lumped_parameters": lumped_json(s),
            "modes": modes_json(s),
        },
        "warnings": s.warnings,
    });
    let modes = match &s.modes {
        Some(m) => format!("; lumped model: {} modes", m.len()),
        None => String::new(),
    };
    let mut artifacts = Artifacts {
        headline: format!(
            "planetary set {}/{}/{}, {} planets: sun-planet mesh stiffness mean {} N/m, ring-planet mean {} N/m; mesh frequency {} Hz, planet pass {} Hz{modes}",
            s.set.teeth_sun(),
            s.set.teeth_planet(),
            s.set.teeth_ring(),
            s.set.planets(),
            shown(sun.mean_stiffness_n_per_m()),
            shown(ring_mean),
            shown(s.set.mesh_frequency_hz(s.speeds_hz)),
            shown(s.set.planet_pass_frequency_hz(s.speeds_hz)),
        ),
        summary: v,
        ..Default::default()
    };
    artifacts.table(
        "mesh_stiffness_carrier_revolution.csv",
        s.stiffness_table(TABLE_SAMPLES_PER_MESH_CYCLE),
    );
    artifacts
}

/// Samples per mesh cycle of the carrier-revolution stiffness table: 32 resolve the
/// double/single contact plateaus of a contact ratio 1.3-1.9 mesh (each at least 0.1 cycle
/// long, so at least 3 samples) while a revolution of an 84-tooth ring stays 2688 rows.
const TABLE_SAMPLES_PER_MESH_CYCLE: usize = 32;
