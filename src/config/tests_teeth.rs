//! Tests of the per-tooth inputs: the checks the case alone allows, and the faults
//! resolved to SI units with their defaults.

use super::case::Case;
use super::load::load_case;
use super::teeth::*;
use super::teeth_checks::teeth_problems;
use std::f64::consts::PI;

fn fault(kind: FaultKind, tooth: i64) -> FaultTable {
    FaultTable {
        kind,
        gear: Member::Pinion,
        tooth,
        stage: None,
        crack_depth_mm: None,
        crack_angle_deg: None,
        crack_width_fraction: None,
        spall_position_mm: None,
        spall_length_mm: None,
        spall_depth_um: None,
        spall_width_fraction: None,
        removed_height_mm: None,
        face_start_mm: None,
        face_end_mm: None,
    }
}

#[test]
fn wrong_lengths_name_both_lengths_and_indices_the_valid_range() {
    let t = TeethSection {
        pitch_error_pinion_um: Some(vec![1.0; 18]),
        profile_form_gear_um: Some(vec![1.0; 2]),
        ..Default::default()
    };
    let mut crack = fault(FaultKind::Crack, 19);
    crack.spall_depth_um = Some(3.0);
    let p = teeth_problems(&t, &ModificationSection::default(), &[crack], 19, 31, &[]);
    let all = p.join("\n");
    assert!(
        all.contains("18 values") && all.contains("19 teeth"),
        "{all}"
    );
    assert!(
        all.contains("has 2 values") && all.contains("(31)"),
        "{all}"
    );
    assert!(
        all.contains("`fault.tooth` = 19") && all.contains("0 to 18"),
        "{all}"
    );
    assert!(all.contains("`fault.crack_depth_mm` is required"), "{all}");
    assert!(all.contains("`fault.spall_depth_um`") && all.contains("does not apply"));
}

#[test]
fn empty_sections_serialise_to_nothing() {
    let v = toml::Value::try_from(TeethSection::default()).unwrap();
    assert_eq!(v.as_table().map(|t| t.len()), Some(0));
    let v = toml::Value::try_from(ModificationSection::default()).unwrap();
    assert_eq!(v.as_table().map(|t| t.len()), Some(0));
}

#[test]
fn faults_resolve_to_si_units_with_their_defaults() {
    let c = load_case(
        "[[fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 3\ncrack_depth_mm = 0.5\n\
         [[fault]]\nkind = \"spall\"\ngear = \"gear\"\ntooth = 7\nspall_position_mm = -0.25\n\
         spall_length_mm = 2\nspall_depth_um = 32\nspall_width_fraction = 0.5\n\
         [[fault]]\nkind = \"broken_tip\"\ngear = \"gear\"\ntooth = 0\nremoved_height_mm = 0.5\n",
        &[],
    )
    .unwrap();
    assert_eq!((c.fault[0].gear, c.fault[0].tooth), (Member::Pinion, 3));
    // Chen & Shao's 45 deg and a crack through the whole face where the file gives none.
    // The sizes are powers of two times 1e-3 and 1e-6, so their products are exact; the
    // angle is 45 pi / 180, within one rounding of pi / 4.
    let Fault::Crack {
        depth_m,
        angle_rad,
        width_fraction,
    } = c.fault[0].fault
    else {
        panic!("{:?}", c.fault[0]);
    };
    assert_eq!((depth_m, width_fraction), (0.5e-3, 1.0));
    assert!((angle_rad - PI / 4.0).abs() < 1e-15, "{angle_rad}");
    assert_eq!(
        c.fault[1].fault,
        Fault::Spall {
            position_m: -0.25e-3,
            length_m: 2e-3,
            depth_m: 32e-6,
            width_fraction: 0.5
        }
    );
    assert_eq!(
        c.fault[2].fault,
        Fault::BrokenTip {
            removed_height_m: 0.5e-3
        }
    );
    // Messages quote the values as written, defaults included.
    assert_eq!(c.fault[0].written("crack_angle_deg"), 45.0);
    assert_eq!(c.fault[1].written("spall_depth_um"), 32.0);
    // The case writes its faults back as the tables it read, and reads back to itself.
    let text = toml::to_string(&c).unwrap();
    assert!(!text.contains("crack_angle_deg") && text.contains("crack_depth_mm = 0.5"));
    let again: Case = load_case(&text, &[]).unwrap();
    assert_eq!(again, c);
}

#[test]
fn a_fault_table_that_is_no_fault_is_refused_when_deserialised() {
    let mut crack = fault(FaultKind::Crack, 2);
    assert!(ToothFault::try_from(crack.clone())
        .unwrap_err()
        .contains("`fault.crack_depth_mm` is required"));
    crack.crack_depth_mm = Some(1.0);
    crack.tooth = -1;
    assert!(ToothFault::try_from(crack)
        .unwrap_err()
        .contains("`fault.tooth` = -1"));
}
