//! The case that was run, in words and numbers: whether it is the paper's case (so that a
//! comparison with the paper's numbers means something), and the sentences of the report
//! that explain a result, each taking its numbers from the run.

use crate::config::case::TorqueShaft;
use crate::config::Case;
use crate::format::shown;
use crate::study::{ModalAnalysis, Model};
use serde_json::{json, Value};

pub use crate::config::paper_case::{is_paper_case, paper_case_differences, PAPER_CASE};

/// Mesh frequency z1 f_in, Hz.
pub fn mesh_frequency_hz(model: &Model) -> f64 {
    model.params.operating.mesh_frequency_hz
}

/// Mean mesh force without friction, N: the brake torque over the gear's base radius
/// (docs/MODEL.md, "Mean balance"), which is the load torque over the base radius of the
/// shaft it acts on.
pub fn static_mesh_force_n(model: &Model) -> f64 {
    model.params.operating.static_mesh_force_n
}

/// "100 N m on the pinion".
pub fn load_words(case: &Case) -> String {
    let shaft = match case.operating.load_torque_shaft {
        TorqueShaft::Pinion => "pinion",
        TorqueShaft::Gear => "gear",
    };
    format!(
        "{} N m on the {shaft}",
        shown(case.operating.load_torque_nm)
    )
}

/// The mean mesh force the load sets, with its numbers: "Without friction the mean mesh
/// force is 60 N m / r_pb = 60 N m / 17.854 mm = 3361 N."
pub fn load_sentence(model: &Model) -> String {
    let op = &model.case.operating;
    let (name, r_m) = match op.load_torque_shaft {
        TorqueShaft::Pinion => ("r_pb", model.pair.pinion.base_radius_m),
        TorqueShaft::Gear => ("r_gb", model.pair.gear.base_radius_m),
    };
    format!(
        "Without friction the mean mesh force is {t} N m / {name} = {t} N m / {} mm = {} N.",
        shown(r_m * 1e3),
        shown(static_mesh_force_n(model)),
        t = shown(op.load_torque_nm),
    )
}

/// The damped mesh poles of the linearised drivetrain (new teeth, mean mesh stiffness;
/// docs/MODEL.md, "Modes"): (damped frequency |Im lambda| / 2 pi in Hz, damping ratio),
/// ascending. These are where the response to the mesh excitation peaks, damping included,
/// and the same poles the summary key `mesh_poles` lists.
pub fn mesh_poles(model: &Model) -> Vec<(f64, f64)> {
    ModalAnalysis::of(model)
        .damped
        .mesh_poles()
        .iter()
        .map(|m| (m.damped_frequency_hz, m.damping_ratio))
        .collect()
}

/// The sentence on the damped mesh poles against the mesh frequency, with this run's
/// numbers: the pole, its damping ratio, and the mesh harmonic k z1 f_in nearest to it.
pub fn poles_sentence(model: &Model) -> String {
    poles_words(mesh_frequency_hz(model), &mesh_poles(model))
}

/// [`poles_sentence`] from the mesh frequency and the poles (Hz, damping ratio).
fn poles_words(f_mesh: f64, poles: &[(f64, f64)]) -> String {
    let Some(&(f, zeta)) = poles.first() else {
        return format!(
            "The linearised drivetrain has no damped mesh pole to set against the {f_mesh:.0} Hz mesh frequency."
        );
    };
    let side = if f >= f_mesh { "above" } else { "below" };
    // The harmonic k f_mesh (k = 1..4, as the sweep markers) nearest the pole.
    let k = (1..=4)
        .min_by(|a, b| {
            let d = |k: i32| (f64::from(k) * f_mesh - f).abs();
            d(*a).total_cmp(&d(*b))
        })
        .unwrap_or(1);
    let mut s = format!(
        "The damped mesh pole (the resonance of the mesh with all damping included) is at {f:.0} Hz, damping ratio {zeta:.2}, {side} the {f_mesh:.0} Hz mesh frequency (ratio {:.2})",
        f / f_mesh
    );
    if k > 1 {
        s.push_str(&format!(
            "; the nearest mesh harmonic is the {} at {:.0} Hz",
            ordinal(k),
            f64::from(k) * f_mesh
        ));
    }
    for &(g, z) in &poles[1..] {
        s.push_str(&format!(
            "; another mesh pole is at {g:.0} Hz (damping ratio {z:.2})"
        ));
    }
    s.push('.');
    s
}

/// "second", "third", "fourth" (k = 2..4), else "k-th".
fn ordinal(k: i32) -> String {
    match k {
        1 => "first".into(),
        2 => "second".into(),
        3 => "third".into(),
        4 => "fourth".into(),
        _ => format!("{k}-th"),
    }
}

/// The choices the paper leaves open, as this run made them: "mesh damping ratio 0.05,
/// speed boundary condition "motor slip", 40 cP, hub bore radii 8/14 mm" (bores as the
/// model uses them, "derived" when the geometry gave them).
pub fn open_choices_words(model: &Model) -> String {
    let case = &model.case;
    let boundary = serde_json::to_value(case.operating.speed_boundary)
        .ok()
        .and_then(|v| v.as_str().map(|s| s.replace('_', " ")))
        .unwrap_or_default();
    // To the micrometre: a derived bore is not a round number.
    let mm = |m: f64| (m * 1e6).round() / 1e3;
    let g = &case.gear;
    let derived = [g.hub_bore_radius_pinion_mm, g.hub_bore_radius_gear_mm]
        .iter()
        .any(|b| b.given().is_none());
    format!(
        "mesh damping ratio {}, speed boundary condition \"{boundary}\", {} cP, hub bore radii {}/{} mm{}",
        case.dynamics.mesh_damping_ratio,
        case.lubricant.viscosity_cp,
        mm(model.pair.pinion.bore_radius_m),
        mm(model.pair.gear.bore_radius_m),
        if derived { " (derived from the geometry)" } else { "" },
    )
}

/// A cycle count in words: "40000", "3000".
pub fn cycles_words(cycles: f64) -> String {
    crate::io::format_number(cycles)
}

/// The case as `summary.json` describes a case that is not the paper's: the pair, the
/// operating point, the mesh frequency, the wear inputs.
pub fn case_json(model: &Model) -> Value {
    let c = &model.case;
    json!({
        "teeth": [c.gear.teeth_pinion, c.gear.teeth_gear],
        "module_mm": c.gear.module_mm,
        "face_width_mm": c.gear.face_width_mm,
        "pressure_angle_deg": c.gear.pressure_angle_deg,
        "contact_ratio": model.pair.contact_ratio,
        "input_speed_hz": c.operating.input_speed_hz,
        "load_torque_nm": c.operating.load_torque_nm,
        "load_torque_shaft": c.operating.load_torque_shaft,
        "mesh_frequency_hz": mesh_frequency_hz(model),
        "static_mesh_force_n": static_mesh_force_n(model),
        "mesh_poles_hz": mesh_poles(model).iter().map(|p| p.0).collect::<Vec<f64>>(),
        "wear_coefficient_m2_per_n": c.wear.coefficient_m2_per_n,
        "total_cycles": c.wear.total_cycles,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(sets: &[&str]) -> Case {
        crate::config::load::default_with(sets)
    }

    #[test]
    fn the_built_in_case_is_the_papers() {
        // The case file's defaults are documented as the paper's case (docs/CONFIG.md).
        assert!(is_paper_case(&Case::default()));
        // The same numbers typed another way are the same case.
        assert!(is_paper_case(&case(&["gear.centre_distance_mm=50.0"])));
        // A shorter run of the same pair is the same case (the labels state its cycles).
        assert!(is_paper_case(&case(&["wear.total_cycles=6000"])));
    }

    #[test]
    fn each_compared_input_makes_another_case() {
        // Every key of the list, moved by 1 %, is a different case, named as such.
        for (key, paper) in PAPER_CASE {
            let moved = if paper == 0.0 { 0.01 } else { paper * 1.01 };
            let moved = if key.contains("teeth") {
                paper + 1.0
            } else {
                moved
            };
            let c = case(&[&format!("{key}={moved}")]);
            assert_eq!(paper_case_differences(&c), vec![key.to_string()], "{key}");
        }
        let c = case(&["gear.centre_distance_mm=50.5"]);
        assert_eq!(paper_case_differences(&c), vec!["gear.centre_distance_mm"]);
    }

    #[test]
    fn pole_words_name_the_pole_and_the_nearest_harmonic() {
        // A pole at 1250 Hz against a 570 Hz mesh: the second harmonic (1140 Hz) is the
        // nearest of k = 1..4 (|1140 - 1250| = 110 < |1710 - 1250| = 460).
        let s = poles_words(570.0, &[(1250.0, 0.29)]);
        assert!(
            s.contains("1250 Hz, damping ratio 0.29, above the 570 Hz"),
            "{s}"
        );
        assert!(s.contains("second at 1140 Hz"), "{s}");
        assert!(poles_words(570.0, &[]).contains("no damped mesh pole"));
    }

    #[test]
    fn choices_the_paper_leaves_open_keep_the_comparison() {
        let c = case(&[
            "dynamics.mesh_damping_ratio=0.1",
            "operating.speed_boundary=motor_speed_imposed",
            "lubricant.viscosity_cp=20",
            "numerics.steps_per_mesh_period=100",
        ]);
        assert!(is_paper_case(&c));
    }
}
