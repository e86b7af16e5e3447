//! The wear of a planetary set with a tooth fault (docs/MODEL.md 12.15), checked against
//! independent facts:
//! - a crack of vanishing depth wears the set as the healthy set does, to the fault's
//!   own relative compliance (computed here from its table and the mesh stiffness);
//! - the member's mean wear (the mean of the fault period's mesh periods) equals the mean
//!   over the member's teeth of each tooth's wear from its own contacts (a second
//!   partition of the same history: by tooth instead of by mesh period);
//! - a broken tip's tooth wears nothing beyond its cut (the contact there is removed),
//!   the cut's radius of curvature computed here from the geometry, while the next tooth
//!   wears there;
//! - `gearwear wear` and `run` take the fault; the budget counts a faulty update at or
//!   above its measured time and the memory its response holds.

mod common;

use common::{gearwear, stderr};
use gearwear::config::{load_case, Case};
use gearwear::dynamics::planetary_dynamic::MeshStiffnessSource;
use gearwear::study::budget::planetary::estimate_planetary_wear;
use gearwear::study::planetary_teeth::tooth_rates;
use gearwear::study::planetary_wear::{
    member_flanks, new_teeth, wear_gaps, ForceHistory, MemberFlank, PlanetaryWearModel,
};
use gearwear::study::planetary_wear_loop::update_of;
use gearwear::study::wear_loop::WearMode;

/// The built-in set (24 / 30 / 84, four planets, sun in, ring fixed) with `fault` (the
/// keys of one `[[planetary.fault]]` table; empty: healthy).
fn text(fault: &str) -> String {
    if fault.is_empty() {
        "[planetary]\n".to_string()
    } else {
        format!("[planetary]\n[[planetary.fault]]\n{fault}\n")
    }
}

fn case(fault: &str) -> Case {
    load_case(&text(fault), &[]).unwrap()
}

fn model(fault: &str) -> PlanetaryWearModel {
    PlanetaryWearModel::from_case(&case(fault)).unwrap()
}

/// The new set's force history and its member flanks (rates per input cycle).
fn first(model: &PlanetaryWearModel, dynamic: bool) -> (ForceHistory, Vec<MemberFlank>) {
    let gaps = wear_gaps(model, &new_teeth(model));
    let h = model.force_history(dynamic, &gaps).unwrap();
    let incs: Vec<_> = (0..2 * model.planets())
        .map(|j| model.mesh_increment(j, &h, &gaps[j]))
        .collect();
    (h, member_flanks(model, &new_teeth(model), &incs))
}

/// CPU time of the calling thread, s (Linux's per-thread clock, not the wall clock that
/// other tests and builders sharing the cores would inflate).
fn thread_cpu_s() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec the call writes.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    assert_eq!(rc, 0);
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |a, b| a.max(b.abs()))
}

fn largest_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn a_crack_of_vanishing_depth_wears_the_set_as_the_healthy_set() {
    let healthy = model("");
    let tiny = model("kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1e-4");
    assert_eq!(
        tiny.periods(),
        24,
        "a sun fault's period is z_s mesh periods"
    );
    // The crack's relative compliance delta = c_fault k: a pair's load, and with it its
    // Archard wear (k p 2a |du| / u grows as the load, p and a each as its square root),
    // changes by at most about delta; the others share what it sheds.
    let MeshStiffnessSource::Tables(m) = &tiny.dynamics.model.source else {
        panic!("tables")
    };
    let c = max_abs(m.fault().unwrap().sun_m_per_n.as_ref().unwrap());
    let delta = c * m.mean_n_per_m()[0];
    assert!(delta > 0.0 && delta < 1e-3, "delta {delta}");
    for dynamic in [false, true] {
        let (_, a) = first(&healthy, dynamic);
        let (_, b) = first(&tiny, dynamic);
        for (fa, fb) in a.iter().zip(&b) {
            let d = largest_difference(&fa.rate_m_per_input, &fb.rate_m_per_input);
            // Four times delta: the difference at one point over the flank's largest
            // rate elsewhere; dynamic: plus 1e-5 for the two steady states' residuals
            // (each within `numerics.steady_state_tolerance` 1e-6 of the state's scale).
            let tol = 4.0 * delta + if dynamic { 1e-5 } else { 1e-12 };
            assert!(
                d <= tol * max_abs(&fa.rate_m_per_input),
                "dynamic {dynamic}, {} {}: {d:e} of {:e} (tolerance {tol:e})",
                fa.member,
                fa.flank,
                max_abs(&fa.rate_m_per_input)
            );
        }
    }
}

#[test]
fn a_members_mean_wear_is_the_mean_of_its_teeths_own_wear() {
    for (fault, z, flank) in [
        (
            "kind = \"broken_tip\"\ngear = \"sun\"\ntooth = 2\nremoved_height_mm = 1.0",
            24,
            0,
        ),
        (
            "kind = \"crack\"\ngear = \"planet\"\nplanet = 2\ntooth = 7\ncrack_depth_mm = 1.5",
            30,
            3,
        ),
        (
            "kind = \"crack\"\ngear = \"ring\"\ntooth = 5\ncrack_depth_mm = 1.0",
            84,
            9,
        ),
    ] {
        let m = model(fault);
        for dynamic in [false, true] {
            let gaps = wear_gaps(&m, &new_teeth(&m));
            let (h, flanks) = first(&m, dynamic);
            let rates: Vec<_> = (0..z)
                .map(|t| tooth_rates(&m, &h, &gaps, t).unwrap())
                .collect();
            for (k, (name, _)) in rates[0].iter().enumerate() {
                let f = &flanks[flank + k];
                assert_eq!(f.flank, *name);
                let n = f.rate_m_per_input.len();
                let mean: Vec<f64> = (0..n)
                    .map(|i| rates.iter().map(|r| r[k].1[i]).sum::<f64>() / z as f64)
                    .collect();
                // The same samples, grouped by tooth instead of by mesh period, each
                // position met once by each tooth over the period: equal to the sums'
                // rounding (z terms).
                let d = largest_difference(&mean, &f.rate_m_per_input);
                assert!(
                    d <= 1e-12 * max_abs(&mean),
                    "{fault} dynamic {dynamic} {name}: {d:e} of {:e}",
                    max_abs(&mean)
                );
            }
        }
    }
}

#[test]
fn a_broken_sun_tip_wears_nothing_beyond_its_cut() {
    let h_cut = 1.0e-3;
    let m = model("kind = \"broken_tip\"\ngear = \"sun\"\ntooth = 2\nremoved_height_mm = 1.0");
    let sun = &m.dynamics.study.set.sun_planet.pinion;
    // The sun's flank ends at its new tip circle r_a - h: rho = sqrt((r_a - h)^2 - r_b^2).
    let rho_cut = ((sun.tip_radius_m - h_cut).powi(2) - sun.base_radius_m.powi(2)).sqrt();
    let rho = &m.grids[0].rho_pinion_m;
    let spacing = m.grids[0].spacing_m;
    assert!(
        rho.iter().any(|r| *r > rho_cut + spacing),
        "the grid reaches past the cut"
    );
    for dynamic in [false, true] {
        let gaps = wear_gaps(&m, &new_teeth(&m));
        let (h, _) = first(&m, dynamic);
        let broken = &tooth_rates(&m, &h, &gaps, 2).unwrap()[0].1;
        let next = &tooth_rates(&m, &h, &gaps, 3).unwrap()[0].1;
        for (i, r) in rho.iter().enumerate() {
            // One grid spacing beyond the cut: the last contact sample before it is
            // interpolated over that spacing.
            if *r > rho_cut + spacing {
                assert_eq!(
                    broken[i], 0.0,
                    "dynamic {dynamic}: wear at rho {r} beyond the cut"
                );
                assert!(next[i] > 0.0, "dynamic {dynamic}: tooth 3 at {r}");
            } else if *r < rho_cut - spacing {
                assert!(
                    broken[i] > 0.0,
                    "dynamic {dynamic}: no wear at {r} below the cut"
                );
            }
        }
    }
}

#[test]
fn wear_and_run_take_a_fault_and_the_budget_counts_it() {
    let faulty = case("kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1.5");
    let m = PlanetaryWearModel::from_case(&faulty).unwrap();
    let one = gearwear::config::case::WearSection {
        total_cycles: 0.0,
        ..faulty.wear.clone()
    };
    let e = estimate_planetary_wear(&m, &one, &[WearMode::Dynamic]);
    let t = thread_cpu_s();
    let u = update_of(&m, WearMode::Dynamic, (0.0, None), new_teeth(&m)).unwrap();
    let took = thread_cpu_s() - t;
    assert_eq!(u.meshes.len(), 8);
    // The terms alone (without the process's start-up and base memory) against the CPU
    // time of this thread (the update runs on it alone).
    let seconds: f64 = e.terms.iter().map(|t| t.seconds).sum();
    let bytes: f64 = e.terms.iter().map(|t| t.bytes).sum();
    assert!(seconds >= took, "estimate {seconds} s, took {took} s");
    // The response's samples over the fault's period, each [q, q'] of the 3 (N + 3)
    // coordinates and the 2 N mesh forces, 8 bytes a number.
    let h = m
        .force_history(true, &wear_gaps(&m, &new_teeth(&m)))
        .unwrap();
    let held = h.forces_n.len() as f64 * (6.0 * 7.0 + 8.0) * 8.0;
    assert!(bytes >= held, "estimate {bytes} B, the response {held} B");
    for cmd in ["wear", "run"] {
        let d = tempfile::tempdir().unwrap();
        let path = d.path().join("case.toml");
        std::fs::write(
            &path,
            text("kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1.5"),
        )
        .unwrap();
        let out = d.path().join("out");
        let o = gearwear(&[
            cmd,
            "-q",
            "--config",
            path.to_str().unwrap(),
            "--set",
            "wear.total_cycles=2e4",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{cmd}: {}", stderr(&o));
    }
}

/// A broken sun tip cut deep enough leaves a planet's sun mesh with no tooth pair at some
/// instant: the quasi-static equilibrium's planet then turns freely (singular), which the
/// quasi-static wear model cannot run. Refused before any work and before the output
/// folder opens (exit 2, naming the fault's keys and the way out), by `wear` and `run`;
/// a shallow cut runs (the check is not a blanket refusal).
#[test]
fn a_planet_left_without_a_tooth_pair_is_refused_by_the_quasi_static_wear_model() {
    let d = tempfile::tempdir().unwrap();
    let example = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/planetary_set.toml"),
    )
    .unwrap();
    let write = |name: &str, h: f64| {
        let p = d.path().join(name);
        std::fs::write(
            &p,
            format!("{example}\n[[planetary.fault]]\ngear = \"sun\"\nkind = \"broken_tip\"\ntooth = 0\nremoved_height_mm = {h}\n"),
        )
        .unwrap();
        p.to_str().unwrap().to_owned()
    };
    let deep = write("deep.toml", 3.0);
    for command in [
        vec!["wear", "--mode", "quasi-static"],
        vec!["wear"],
        vec!["run"],
    ] {
        let mut a = command.clone();
        a.extend(["--config", deep.as_str()]);
        common::rejected(
            &a,
            &[
                "`planetary.fault.removed_height_mm` = 3",
                "singular",
                "dynamic wear model",
            ],
        );
    }
    let shallow = write("shallow.toml", 0.5);
    let model = PlanetaryWearModel::from_case(
        &load_case(&std::fs::read_to_string(&shallow).unwrap(), &[]).unwrap(),
    )
    .unwrap();
    assert_eq!(model.quasi_static_problem(), None);
}
