//! The wear-rate column of a tooth-resolved wear study is the fastest tooth's (issue 18):
//! `max_wear_pinion_um` is the deepest tooth's, so the rate beside it must bound that
//! tooth's growth. The paper's update (eq. 17) advances every profile point by its
//! per-cycle wear times the block, so max(w + d N) <= max(w) + max(d) N: the deepest
//! wear can grow by at most the largest rate times the block. A rate taken from the
//! mean tooth's profile (as before) understates the proud tooth's and breaks the bound.

mod common;

use common::{ok, read_csv};

/// Coarse grids (the bookkeeping is under test, not accuracy); pinion tooth 3 stands
/// 5 um proud, so it carries the load alone for longer and wears fastest.
fn proud_tooth_case() -> String {
    let mut pitch = vec!["0"; 19];
    pitch[3] = "5";
    format!(
        "[numerics]\nsteps_per_mesh_period = 60\nevaluated_mesh_periods = 2\n\
         [stiffness]\ntable_points_per_mesh_period = 60\n\
         [wear]\npoints_per_profile = 31\ntotal_cycles = 2e4\n\
         [teeth]\npitch_error_pinion_um = [{}]\n",
        pitch.join(", ")
    )
}

#[test]
fn the_deepest_tooth_grows_no_faster_than_the_reported_rate() {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("proud.toml");
    std::fs::write(&case, proud_tooth_case()).unwrap();
    let out = d.path().join("w");
    ok(&[
        "wear",
        "-q",
        "--config",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    for mode in ["dynamic", "quasi_static"] {
        let (h, rows) = read_csv(&out.join(format!("updates_{mode}.csv")));
        let col = |n: &str| h.iter().position(|x| x == n).unwrap();
        let v = |r: &Vec<String>, n: &str| r[col(n)].parse::<f64>().unwrap();
        assert!(rows.len() >= 3, "{mode}: {} updates", rows.len());
        let mut grew = 0.0_f64;
        for w in rows.windows(2) {
            let block_kcycles = (v(&w[1], "cycles") - v(&w[0], "cycles")) / 1e3;
            let growth_um = v(&w[1], "max_wear_pinion_um") - v(&w[0], "max_wear_pinion_um");
            let bound_um = v(&w[0], "max_wear_rate_pinion_um_per_kcycle") * block_kcycles;
            // 1e-9 relative for the CSV's printed digits (17 significant) and the
            // summation order; the old mean-tooth rate missed by ~30 %.
            assert!(
                growth_um <= bound_um * (1.0 + 1e-9) + 1e-12,
                "{mode}: deepest wear grew {growth_um} um over {block_kcycles} kcycles, \
                 more than the reported rate allows ({bound_um} um)"
            );
            grew = grew.max(growth_um / bound_um);
        }
        // The bound is reached where the deepest point stays on the fastest tooth: the
        // rate is that tooth's, not an over-estimate (within 10 %: the deepest point may
        // move along the profile between updates).
        assert!(grew > 0.9, "{mode}: largest growth / bound {grew}");
    }
}
