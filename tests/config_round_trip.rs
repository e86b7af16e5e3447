//! The commented case (`gearwear config --config FILE`, Python's `Case.to_toml`) reads
//! back to the same case for every structure a case can hold: gear trains (`[[stage]]`),
//! planetary sets with their lumped sub-table, faults (`[[fault]]`), per-tooth inputs,
//! load spectra. Before this test a train's stages, a planetary set and every fault were
//! written only as commented templates, so the text read back as the single paper pair.

mod common;

use common::planetary::lin_parker_lumped;
use gearwear::config::{commented_template, load_case, Case};

fn read(text: &str) -> Case {
    load_case(text, &[]).unwrap_or_else(|e| panic!("{:?}", e.problems))
}

/// The case's commented text, read back, is the case; and writing it again gives the
/// same text (a fixed point).
fn assert_round_trip(name: &str, text: &str) {
    let case = read(text);
    let written = commented_template(&case);
    let back = read(&written);
    assert!(
        back == case,
        "{name}: the commented case reads back to another case"
    );
    assert_eq!(
        commented_template(&back),
        written,
        "{name}: not a fixed point"
    );
}

#[test]
fn every_structure_survives_the_commented_case() {
    let root = env!("CARGO_MANIFEST_DIR");
    let file = |p: &str| std::fs::read_to_string(format!("{root}/{p}")).unwrap();
    let planetary = format!(
        "[planetary]\nplanets = 4\nteeth_sun = 24\nteeth_planet = 30\nteeth_ring = 84\nmodule_mm = 2.0\n{}",
        lin_parker_lumped(1e6)
    );
    let faults = "[[fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 3\ncrack_depth_mm = 1.0\n\
                  [[fault]]\nkind = \"spall\"\ngear = \"gear\"\ntooth = 7\nspall_position_mm = 0.0\nspall_length_mm = 1.0\nspall_depth_um = 20.0\n";
    let cases = [
        ("paper", String::new()),
        ("two-stage reducer", file("examples/two_stage_reducer.toml")),
        ("planetary with lumped parameters", planetary),
        ("two faults", faults.to_string()),
        ("per-tooth inputs", file("examples/teeth/grade6_runout_spall.toml")),
        (
            "load spectrum",
            "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 80, input_speed_hz = 45, share = 0.3}]\n"
                .to_string(),
        ),
    ];
    for (name, text) in &cases {
        assert_round_trip(name, text);
    }
}

#[test]
fn a_case_without_a_planetary_set_does_not_gain_one() {
    // The section's header is commented while the case has none: an empty `[planetary]`
    // table would make the text a planetary case.
    let written = commented_template(&read(""));
    assert!(!written.lines().any(|l| l.trim() == "[planetary]"));
    assert!(read(&written).planetary.is_none());
}
