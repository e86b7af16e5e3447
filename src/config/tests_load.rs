//! Tests of reading a case: overrides, key and type checks, ranges, the forms of a section.

use super::case::Case;
use super::load::{check_all_ranges, load_case};
use crate::config::case::{Derivable, FrictionModel};

fn err(text: &str, sets: &[&str]) -> String {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    load_case(text, &sets).unwrap_err().to_string()
}

#[test]
fn defaults_and_new_pair_template_are_valid() {
    assert!(check_all_ranges(&Case::default()).is_empty());
    assert!(check_all_ranges(&Case::new_pair_template()).is_empty());
}

#[test]
fn overrides_apply_and_integers_widen() {
    let c = load_case(
        "",
        &[
            "operating.input_speed_hz=45".into(),
            "friction.model=constant".into(),
        ],
    )
    .unwrap();
    assert_eq!(c.operating.input_speed_hz, 45.0);
    assert_eq!(c.friction.model, FrictionModel::Constant);
}

#[test]
fn whole_numbers_written_with_a_decimal_point_are_accepted() {
    let c = load_case("", &["gear.teeth_pinion=25.0".into()]).unwrap();
    assert_eq!(c.gear.teeth_pinion, 25);
    let e = err("", &["gear.teeth_pinion=25.5"]);
    assert!(
        e.contains("gear.teeth_pinion") && e.contains("whole number"),
        "{e}"
    );
    // The inclusive upper end of a range, 2^53, written as a float (as a JSON or Python
    // writer may give it) is the whole number it says.
    let c = load_case("", &["signals.noise_seed=9.007199254740992e15".into()]).unwrap();
    assert_eq!(c.signals.noise_seed, 1i64 << 53);
    // 2^53 + 2, the next float: out of the range, refused by the range, not by its form.
    let e = err("", &["signals.noise_seed=9.007199254740994e15"]);
    assert!(e.contains("signals.noise_seed"), "{e}");
}

#[test]
fn derived_is_accepted_only_where_the_geometry_can_give_the_value() {
    let c = load_case(
        "[dynamics]\nmass_pinion_kg = \"derived\"\n",
        &["gear.hub_bore_radius_gear_mm=derived".into()],
    )
    .unwrap();
    assert_eq!(c.dynamics.mass_pinion_kg, Derivable::Derived);
    assert_eq!(c.gear.hub_bore_radius_gear_mm, Derivable::Derived);
    let e = err("", &["dynamics.inertia_motor_kg_m2=derived"]);
    assert!(e.contains("dynamics.inertia_motor_kg_m2"), "{e}");
    let e = err("", &["dynamics.mass_gear_kg=derive"]);
    assert!(
        e.contains("dynamics.mass_gear_kg") && e.contains("\"derived\""),
        "{e}"
    );
}

#[test]
fn a_bad_value_in_a_long_per_tooth_array_is_named_by_its_tooth() {
    // 31 values: the shown array is clipped before value 15, so only the index says
    // which tooth is wrong. NaN and inf are not numbers in any range.
    let mut gear = vec!["0"; 31];
    gear[15] = "5000";
    let e = err(
        "",
        &[&format!("teeth.pitch_error_gear_um=[{}]", gear.join(","))],
    );
    assert!(
        e.contains("`teeth.pitch_error_gear_um`")
            && e.contains("(value 15 of 0 to 30, tooth 15, is 5000)")
            && e.contains("[-1000, 1000]"),
        "{e}"
    );
    let e = err("[teeth]\nprofile_slope_pinion_um = [nan]\n", &[]);
    assert!(e.contains("(value 0 of 0 to 0, is NaN)"), "{e}");
    let e = err("[surface]\nroughness_table_wear_um = [0.1, inf, 1]\n", &[]);
    assert!(e.contains("(value 1 of 0 to 2, is inf)"), "{e}");
}

#[test]
fn every_problem_is_reported_once_with_key_and_value() {
    let e = load_case(
        "[gear]\nmodule_mm = -2\nface_width_mm = 0\n[wear]\ncoefficient_m2_per_n = -1e-16\n",
        &[],
    )
    .unwrap_err();
    assert_eq!(e.problems.len(), 3, "{e}");
    let m = e.messages();
    assert!(m
        .iter()
        .any(|p| p.contains("gear.module_mm") && p.contains("-2")));
    assert!(m.iter().any(|p| p.contains("wear.coefficient_m2_per_n")));
}

#[test]
fn non_finite_and_subnormal_values_are_rejected_everywhere() {
    for v in ["nan", "inf", "-inf", "5e-324", "1e-310"] {
        for key in [
            "gear.module_mm",
            "wear.block_cycles",
            "dynamics.bearing_damping_gear_n_s_per_m",
        ] {
            let e = err("", &[&format!("{key}={v}")]);
            assert!(e.contains(key), "{key}={v}: {e}");
        }
        let e = err(
            &format!("[surface]\nroughness_table_rms_um = [0.2, {v}, 0.1]\n"),
            &[],
        );
        assert!(e.contains("surface.roughness_table_rms_um"), "{v}: {e}");
    }
}

#[test]
fn unknown_key_names_the_valid_ones() {
    let e = err("[operating]\nspeed_hz = 3\n", &[]);
    assert!(e.contains("operating.speed_hz"));
    assert!(e.contains("operating.input_speed_hz"));
    let e = err("[gears]\n", &[]);
    assert!(e.contains("unknown section [gears]"));
}

#[test]
fn wrong_type_and_bad_choice() {
    let e = err("[operating]\ninput_speed_hz = \"fast\"\n", &[]);
    assert!(e.contains("is a string"), "{e}");
    let e = err("", &["friction.model=coulomb"]);
    assert!(e.contains("\"xu2007\""), "{e}");
}

#[test]
fn xu_needs_viscosity_above_one_cp() {
    let e = err("", &["lubricant.viscosity_cp=0.8"]);
    assert!(e.contains("lubricant.viscosity_cp"), "{e}");
    // Fine without the Xu model.
    load_case(
        "",
        &[
            "lubricant.viscosity_cp=0.8".into(),
            "friction.model=none".into(),
        ],
    )
    .unwrap();
}

#[test]
fn toml_forms_of_a_section_give_the_same_case_and_others_are_errors() {
    let section = load_case("[gear]\nmodule_mm = 3\n", &[]).unwrap();
    for text in ["gear = { module_mm = 3 }\n", "gear.module_mm = 3\n"] {
        assert_eq!(load_case(text, &[]).unwrap(), section, "{text}");
    }
    for text in ["gear = 3\n", "[[gear]]\nmodule_mm = 3\n"] {
        assert!(err(text, &[]).contains("[gear] must be a table"), "{text}");
    }
}

#[test]
fn set_values_are_one_line_and_never_cut_silently() {
    for bad in [
        "gear.module_mm=3\n[gear]\nmodule_mm = 5",
        "gear.module_mm=3\r\nx",
        "friction.model=constant\tx",
    ] {
        let e = err("", &[bad]);
        assert!(e.contains("line break or another control character"), "{e}");
    }
}

#[test]
fn long_values_are_echoed_cut() {
    let huge = "x".repeat(10_000_000);
    let e = err("", &[&format!("friction.model={huge}")]);
    assert!(e.len() < 2000, "{} bytes", e.len());
    assert!(
        e.contains("friction.model") && e.contains("characters)"),
        "{e}"
    );
    let e = err(&format!("[gear]\nmodule_mm = \"{huge}\"\n"), &[]);
    assert!(e.len() < 2000 && e.contains("gear.module_mm"));
    let e = err(&format!("[gear]\nmodule_mm = {huge}\n"), &[]);
    assert!(e.len() < 2000, "{} bytes", e.len());
}

#[test]
fn face_width_must_suit_the_module() {
    let e = err("", &["gear.face_width_mm=0.5"]);
    assert!(
        e.contains("gear.face_width_mm") && e.contains("gear.module_mm"),
        "{e}"
    );
}
