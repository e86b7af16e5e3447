//! The spectrum's scale factors as sweep axes: a wear sweep runs each case under its
//! spectrum (the same numbers as `wear` on that case), and the quasi-static wear follows
//! Archard's law in the torque scale.

mod common;
use common::gearwear;

const TWO: &str = "[load_spectrum]\nbins = [{torque_nm = 40, input_speed_hz = 20, share = 0.6}, {torque_nm = 80, input_speed_hz = 30, share = 0.4}]\n[wear]\ntotal_cycles = 1.5e4\n[numerics]\nsteps_per_mesh_period = 60\nevaluated_mesh_periods = 2\n[stiffness]\ntable_points_per_mesh_period = 60\n";

fn column(csv: &str, name: &str) -> Vec<f64> {
    let mut lines = csv.lines();
    let i = lines
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == name)
        .unwrap();
    lines
        .map(|l| l.split(',').nth(i).unwrap().parse().unwrap())
        .collect()
}

#[test]
fn a_torque_scale_axis_runs_each_case_under_its_spectrum() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("two.toml");
    std::fs::write(&case, TWO).unwrap();
    let case = case.to_str().unwrap();
    let sweep = dir.path().join("s");
    let o = gearwear(&[
        "-q",
        "sweep",
        "--config",
        case,
        "--vary",
        "load_spectrum.torque_scale=1,1.2",
        "--run",
        "wear",
        "--out",
        sweep.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let table = std::fs::read_to_string(sweep.join("sweep.csv")).unwrap();
    let qs = column(&table, "wear_max_pinion_quasi_static_um");
    // Archard wear per cycle is p0 x 2a x sliding: p0 and the Hertz band 2a both grow as
    // W^1/2, so the wear of new teeth is linear in the load. The 15 000 cycles wear about
    // 1.5 um, which moves the loads by a few per mille: 1 % holds it with margin.
    let ratio = qs[1] / qs[0];
    assert!((ratio / 1.2 - 1.0).abs() < 0.01, "{ratio}");
    // The sweep's row is the wear study of that case, bit for bit.
    let out = dir.path().join("w");
    let o = gearwear(&[
        "-q",
        "wear",
        "--config",
        case,
        "--set",
        "load_spectrum.torque_scale=1.2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let updates = std::fs::read_to_string(out.join("updates_quasi_static.csv")).unwrap();
    let max = column(&updates, "max_wear_pinion_um");
    assert_eq!(max.last().unwrap().to_bits(), qs[1].to_bits());
    let dynamic = std::fs::read_to_string(out.join("updates_dynamic.csv")).unwrap();
    assert_eq!(
        column(&dynamic, "max_wear_pinion_um")
            .last()
            .unwrap()
            .to_bits(),
        column(&table, "wear_max_pinion_dynamic_um")[1].to_bits()
    );
}
