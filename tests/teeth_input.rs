//! Bad per-tooth inputs are exit-2 errors that name the key, the tooth and the valid
//! range (a per-tooth array of the wrong length names both lengths), before anything is
//! computed.

mod common;
use common::rejected;

#[test]
fn tooth_indices_and_array_lengths_name_the_key_and_the_range() {
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=crack",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=19",
            "--set",
            "fault.crack_depth_mm=0.5",
        ],
        &["`fault.tooth` = 19", "pinion", "0 to 18"],
    );
    rejected(
        &["dynamics", "--set", "teeth.pitch_error_gear_um=[1,2,3]"],
        &["`teeth.pitch_error_gear_um`", "3 values", "31 teeth"],
    );
    rejected(
        &["stiffness", "--set", "teeth.profile_form_pinion_um=[1,2]"],
        &["`teeth.profile_form_pinion_um`", "2 values", "(19)"],
    );
    rejected(
        &["dynamics", "--set", "teeth.accuracy_grade=13"],
        &["`teeth.accuracy_grade` = 13", "[1, 12]"],
    );
    rejected(
        &["dynamics", "--set", "teeth.accuracy_grade=0"],
        &["`teeth.accuracy_grade` = 0", "[1, 12]"],
    );
}

#[test]
fn faults_and_reliefs_the_geometry_cannot_hold_name_the_key_tooth_and_range() {
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=crack",
            "--set",
            "fault.gear=gear",
            "--set",
            "fault.tooth=3",
            "--set",
            "fault.crack_depth_mm=6",
        ],
        &[
            "`fault.crack_depth_mm` = 6",
            "gear tooth 3",
            "deeper than the tooth",
            "valid [0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=2",
            "--set",
            "fault.spall_position_mm=0",
            "--set",
            "fault.spall_length_mm=20",
            "--set",
            "fault.spall_depth_um=50",
        ],
        &[
            "`fault.spall_length_mm` = 20",
            "pinion tooth 2",
            "longer than the active profile",
            "valid (0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=2",
            "--set",
            "fault.spall_position_mm=4.3",
            "--set",
            "fault.spall_length_mm=1",
            "--set",
            "fault.spall_depth_um=50",
        ],
        &[
            "`fault.spall_position_mm` = 4.3",
            "pinion tooth 2",
            "off the active profile",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "modification.tip_relief_um=10",
            "--set",
            "modification.tip_relief_length_mm=9",
        ],
        &[
            "`modification.tip_relief_length_mm` = 9",
            "longer than the addendum",
            "valid (0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=broken_tip",
            "--set",
            "fault.gear=pinion",
            "--set",
            "fault.tooth=1",
            "--set",
            "fault.removed_height_mm=6",
        ],
        &[
            "`fault.removed_height_mm` = 6",
            "pinion tooth 1",
            "valid (0,",
        ],
    );
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=spall",
            "--set",
            "fault.gear=gear",
            "--set",
            "fault.tooth=1",
            "--set",
            "fault.crack_depth_mm=1",
        ],
        &[
            "`fault.crack_depth_mm`",
            "does not apply",
            "`fault.spall_position_mm` is required",
        ],
    );
}

#[test]
fn pedrero_load_sharing_on_teeth_that_differ_names_both_keys() {
    // Pedrero's law (paper eq. 7) has no place for one pair's gap or softer tooth: asked
    // for explicitly on teeth that differ, it is refused, naming the law's key and what
    // makes the teeth differ.
    rejected(
        &[
            "stiffness",
            "--set",
            "teeth.runout_gear_um=2",
            "--set",
            "contact.load_sharing=pedrero",
        ],
        &[
            "`contact.load_sharing` = \"pedrero\"",
            "`[teeth]`",
            "\"stiffness\"",
        ],
    );
    rejected(
        &[
            "stiffness",
            "--set",
            "wear.worn_geometry=worn",
            "--set",
            "contact.load_sharing=pedrero",
        ],
        &[
            "`contact.load_sharing` = \"pedrero\"",
            "`wear.worn_geometry` = \"worn\"",
        ],
    );
}
