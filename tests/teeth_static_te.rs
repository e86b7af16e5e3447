//! `gearwear stiffness` on a tooth-resolved case reports the static transmission error
//! of those teeth (`teeth.quasi_static_te`), beside the identical teeth's: checked
//! against a second method (the stiffness table's equilibria) and against bounds the
//! compatibility of the pairs gives for tip relief.

mod common;

use common::ok;

fn stiffness(sets: &[&str]) -> serde_json::Value {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    let mut a = vec!["stiffness", "-q", "--out", out.to_str().unwrap()];
    for s in sets {
        a.extend(["--set", s]);
    }
    ok(&a);
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn identical_teeth_resolved_give_the_static_te_of_the_stiffness_table() {
    // A run-out of 1e-6 µm makes the case tooth-resolved without changing anything
    // measurable (1e-12 m against micrometres). The tooth-resolved quasi-static solver
    // over the 31 mesh periods (200 steps each) and the stiffness table's 720 equilibria
    // of one period solve the same compatibility on different grids. The extremes lie
    // at the changes between single and double contact, which each grid meets at its
    // nearest sample, so they agree to the TE's change over one step of the coarser grid
    // (measured: 0.25 % of the range at the maximum); bound 0.5 % of the range.
    let s = stiffness(&["teeth.runout_gear_um=0.000001"]);
    let table = &s["quasi_static_te"];
    let teeth = &s["teeth"]["quasi_static_te"];
    assert_eq!(teeth["mesh_periods"], 31);
    let range = num(&table["max_um"]) - num(&table["min_um"]);
    for k in ["min_um", "max_um"] {
        let (a, b) = (num(&teeth[k]), num(&table[k]));
        assert!((a - b).abs() < 5e-3 * range, "{k}: teeth {a}, table {b}");
    }
}

#[test]
fn tip_relief_raises_the_static_te_at_light_load_and_lowers_it_at_the_design_load() {
    // Light load (5 N m, deflections ~1 µm) with a 10 µm linear tip relief over the
    // whole double-contact length (eps - 1) p_b = 3.556 mm on both gears: halfway through
    // double contact both pairs stand C/2 = 5 µm open, so the static TE there is at least
    // 5 µm, while at the pitch point (single contact, outside every relief zone) it is
    // the single pair's deflection, at most the identical teeth's maximum. So the
    // peak-to-peak is at least C/2 minus that maximum, far above the unrelieved one.
    let light = stiffness(&[
        "operating.load_torque_nm=5",
        "teeth.runout_gear_um=0.000001",
    ]);
    let relieved = stiffness(&[
        "operating.load_torque_nm=5",
        "modification.tip_relief_um=10",
        "modification.tip_relief_length_mm=3.556",
    ]);
    let plain_max = num(&light["quasi_static_te"]["max_um"]);
    let plain_ptp = plain_max - num(&light["quasi_static_te"]["min_um"]);
    let ptp = num(&relieved["teeth"]["quasi_static_te"]["peak_to_peak_um"]);
    assert!(
        ptp >= 5.0 - plain_max,
        "light load: {ptp} µm, bound {}",
        5.0 - plain_max
    );
    assert!(
        ptp > 3.0 * plain_ptp,
        "light load: {ptp} against {plain_ptp} µm"
    );
    // Design load (60 N m): a relief of the single-pair deflection at the pitch point
    // (11.915 µm, tests/teeth_mesh.rs) over that length evens out the load transfer; the
    // hand calculation there gives a fall from 5.339 to 0.952 µm (ratio 0.18), so the
    // relieved peak-to-peak must be well under half the plain one.
    let plain = stiffness(&["teeth.runout_gear_um=0.000001"]);
    let plain_ptp = num(&plain["teeth"]["quasi_static_te"]["peak_to_peak_um"]);
    let relieved = stiffness(&[
        "modification.tip_relief_um=11.915",
        "modification.tip_relief_length_mm=3.556",
    ]);
    let ptp = num(&relieved["teeth"]["quasi_static_te"]["peak_to_peak_um"]);
    assert!(
        ptp < 0.5 * plain_ptp,
        "design load: {ptp} against {plain_ptp} µm"
    );
}
