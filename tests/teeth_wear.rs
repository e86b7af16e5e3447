//! Per-tooth wear checked against independent facts: identical teeth through the
//! tooth-resolved path wear as one tooth pair of the paper's path, the volume the teeth
//! lose is the Archard integral of every engagement's own contact history, and a pitch
//! error moves the teeth's wear about the identical teeth's wear without moving their
//! mean (first order).

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::{DynamicResponse, PathSample};
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;
use gearwear::wear::per_cycle_wear;
use gearwear::wear::per_tooth::per_tooth_wear;

fn model(sets: &[String]) -> Model {
    Model::from_case(&load_case("", sets).expect("valid case")).expect("valid model")
}

fn pitch_error_case(e_um: f64, tooth: usize) -> Vec<String> {
    let mut v = vec!["0".to_string(); 19];
    v[tooth] = format!("{e_um}");
    vec![format!("teeth.pitch_error_pinion_um=[{}]", v.join(","))]
}

/// The teeth of a case with every flank perfect, forced through the tooth-resolved path:
/// the inputs of a case with a pitch error, its position errors set to zero.
fn perfect_teeth() -> gearwear::study::teeth::ToothInputs {
    let mut sets = pitch_error_case(3.0, 2);
    sets.push("contact.load_sharing=stiffness".to_string());
    let mut t = model(&sets)
        .teeth
        .expect("a pitch error resolves the teeth");
    for f in t.pinion.iter_mut().chain(t.gear.iter_mut()) {
        f.position_m = 0.0;
    }
    t
}

#[test]
fn identical_teeth_through_the_resolved_path_wear_as_one_pair() {
    // With corner contact (the default) and on the paper's path.
    for path in ["extended", "nominal"] {
        resolved_path_wears_as_one_pair(path);
    }
}

fn resolved_path_wears_as_one_pair(path: &str) {
    // A dynamic wear study of two updates with every tooth perfect, once through the
    // tooth-resolved mesh (per-tooth wear state, each pair's teeth from its mesh cycle,
    // per-tooth Archard bookkeeping) and once through the paper's path, both sharing the
    // load by compression. Each evaluation's steady state is the same orbit; the paths
    // differ only in rounding (the resolved gap interpolates each flank's wear and adds,
    // the plain one interpolates their sum: a few ulp of the wear), which the shooting
    // and integration carry to the wear at a level far below the solver's tolerances
    // (relative 1e-6 of the steady state): 1e-9 of the deepest wear is the requirement,
    // and every tooth must carry the same profile bit for bit (all teeth alike). A corner
    // pair loads each flank at its own point (the mate's flank where the corner touches
    // it, the corner's tooth at its tip): both paths read each flank's wear there (with
    // the sum of the two read at one point, the plain path was 1.2e-3 of the deepest
    // wear off the resolved one).
    let sets = vec![
        format!("contact.path={path}"),
        "contact.load_sharing=stiffness".to_string(),
        "wear.total_cycles=2e4".to_string(),
        // Blocks of the full 1e4 cycles, not cut by the depth threshold: two updates.
        "wear.threshold_um=1e3".to_string(),
    ];
    let plain = model(&sets);
    let mut resolved = model(&sets);
    resolved.teeth = Some(perfect_teeth());
    let run = |m: &Model| run_wear(m, WearRun::new(WearMode::Dynamic), &mut |_| Ok(())).unwrap();
    let (a, b) = (run(&plain), run(&resolved));
    assert_eq!(a.records.len(), 3, "two updates");
    assert_eq!(b.records.len(), a.records.len());
    let mut worst: f64 = 0.0;
    for (ra, rb) in a.records.iter().zip(&b.records) {
        assert_eq!(ra.wear.cycles, rb.wear.cycles);
        let teeth = rb.wear.teeth.as_ref().expect("per-tooth wear state");
        assert!(teeth.pinion_m.iter().all(|p| p == &teeth.pinion_m[0]));
        assert!(teeth.gear_m.iter().all(|p| p == &teeth.gear_m[0]));
        let scale = ra.wear.max_pinion_m().max(1e-300);
        for (pa, pb) in [
            (&ra.wear.pinion_m, &teeth.pinion_m[0]),
            (&ra.wear.gear_m, &teeth.gear_m[0]),
        ] {
            for (x, y) in pa.iter().zip(pb.iter()) {
                worst = worst.max((x - y).abs() / scale);
            }
        }
    }
    println!("{path}: identical teeth, resolved against plain path: worst wear difference {worst:.2e} of the deepest");
    assert!(a.records[2].wear.max_pinion_m() > 0.0);
    assert!(worst < 1e-9, "{path}: {worst:e}");
}

/// Archard volume per unit face width removed from a flank in one pass, straight from
/// the samples of one engagement (sorted by rho1): int k p s ds over the flank's arc
/// length, ds = rho d rho / r_b on an involute, by the trapezoid rule on the samples
/// (no grid), for the pinion (`gear` false) or the gear.
fn pass_volume(samples: &[PathSample], m: &Model, k: f64, gear: bool) -> f64 {
    let f = |s: &PathSample| {
        let (up, ug) = (s.pinion_surface_speed_m_per_s, s.gear_surface_speed_m_per_s);
        if s.load_n <= 0.0 || up <= 0.0 || ug <= 0.0 {
            return 0.0;
        }
        let slide = 2.0 * s.half_width_m * (up - ug).abs() / if gear { ug } else { up };
        let (rho, rb) = if gear {
            (m.pair.rho_gear(s.rho1_m), m.pair.gear.base_radius_m)
        } else {
            (s.rho1_m, m.pair.pinion.base_radius_m)
        };
        k * s.pressure_pa * slide * rho / rb
    };
    samples
        .windows(2)
        .map(|w| 0.5 * (f(&w[0]) + f(&w[1])) * (w[1].rho1_m - w[0].rho1_m))
        .sum()
}

/// Volume per unit face width of a wear profile on the grid, int h ds (trapezoid).
fn profile_volume(h: &[f64], m: &Model, gear: bool) -> f64 {
    let g = &m.grid;
    let ds = |i: usize| {
        if gear {
            g.rho_gear_m[i] / m.pair.gear.base_radius_m
        } else {
            g.rho_pinion_m[i] / m.pair.pinion.base_radius_m
        }
    };
    (1..h.len())
        .map(|i| 0.5 * (h[i] * ds(i) + h[i - 1] * ds(i - 1)) * g.spacing_m)
        .sum()
}

fn engagements(r: &DynamicResponse) -> Vec<Vec<PathSample>> {
    let mut by = vec![Vec::new(); r.excitation_periods];
    for s in &r.meshes[0].path {
        by[s.cycle as usize].push(*s);
    }
    for e in &mut by {
        e.sort_by(|a, b| a.rho1_m.total_cmp(&b.rho1_m));
    }
    by
}

#[test]
fn removed_volume_is_the_sum_of_every_engagements_archard_integral() {
    // One pinion tooth 8 um proud. Per pinion revolution each pinion tooth passes once
    // and the gear sees z1 passes: the volume the teeth lose per revolution must be the
    // sum over the 19 engagements of their Archard integrals from the raw samples. The
    // two routes differ only in how the integral is taken (grid of 101 points and linear
    // interpolation of the samples, against the trapezoid on the samples): the Hertz
    // pressure and half-width jump where the second pair enters and leaves, which the
    // 0.09 mm grid resolves to ~0.5 % of the integral; 2 % is the requirement.
    let m = model(&pitch_error_case(8.0, 3));
    let r = m
        .dynamic(&m.new_wear_state(), &ExternalError::none())
        .unwrap();
    assert_eq!(r.excitation_periods, 19);
    let k = m.case.wear.coefficient_m2_per_n;
    let inc = per_tooth_wear(&m.grid, &r.meshes[0].path, 19, 19, 31, k);
    let teeth = inc.teeth.as_ref().unwrap();
    let by = engagements(&r);
    for (gear, profiles) in [(false, &teeth.pinion_m), (true, &teeth.gear_m)] {
        let from_teeth: f64 = profiles.iter().map(|h| profile_volume(h, &m, gear)).sum();
        let per_pass: f64 = by.iter().map(|e| pass_volume(e, &m, k, gear)).sum();
        let rel = from_teeth / per_pass - 1.0;
        println!(
            "{}: volume per revolution and unit width {:.6e} m^2 from the teeth, {:.6e} m^2 from the passes ({:+.3} %)",
            if gear { "gear" } else { "pinion" },
            from_teeth,
            per_pass,
            100.0 * rel
        );
        assert!(rel.abs() < 0.02, "{rel}");
    }
    // Tooth 3 takes more load and wears more than a tooth far from it.
    let max = |v: &Vec<f64>| v.iter().fold(0.0_f64, |a, b| a.max(*b));
    assert!(max(&teeth.pinion_m[3]) > 1.1 * max(&teeth.pinion_m[10]));
}

#[test]
fn a_pitch_error_moves_single_teeth_but_not_the_mean_wear_to_first_order() {
    // Archard's depth per pass, k p0 2a |u_s| / u, is proportional to the pair load
    // (p0 and a both grow as sqrt(load)); a pitch error moves load between neighbouring
    // engagements, so to first order in the error the mean over the teeth keeps the
    // identical teeth's wear while single teeth change by the error's first-order effect.
    // Quasi-static (the load split follows compatibility alone; the identical teeth with
    // the same load-sharing law as a tooth-resolved mesh, by compression); measured as
    // the largest change of a profile over the identical teeth's maximum.
    let by_stiffness = "contact.load_sharing=stiffness".to_string();
    let plain = model(std::slice::from_ref(&by_stiffness));
    let r0 = plain.quasi_static(&plain.new_wear_state(), &ExternalError::none());
    let k = plain.case.wear.coefficient_m2_per_n;
    let h0 = per_cycle_wear(&plain.grid, &r0.meshes[0].path, k, 19.0 / 31.0).pinion_m;
    let scale = h0.iter().fold(0.0_f64, |a, b| a.max(*b));
    let change = |e_um: f64| {
        let mut case = pitch_error_case(e_um, 3);
        case.push(by_stiffness.clone());
        let m = model(&case);
        let r = m.quasi_static(&m.new_wear_state(), &ExternalError::none());
        let inc = per_tooth_wear(&m.grid, &r.meshes[0].path, r.excitation_periods, 19, 31, k);
        let mean_dev = inc
            .pinion_m
            .iter()
            .zip(&h0)
            .fold(0.0_f64, |a, (x, y)| a.max((x - y).abs()))
            / scale;
        let tooth_dev = inc.teeth.unwrap().pinion_m[3]
            .iter()
            .zip(&h0)
            .fold(0.0_f64, |a, (x, y)| a.max((x - y).abs()))
            / scale;
        (mean_dev, tooth_dev)
    };
    let (m1, t1) = change(1.0);
    let (m2, t2) = change(2.0);
    println!(
        "pitch error 1 um: mean {m1:.3e}, tooth 3 {t1:.3e}; 2 um: mean {m2:.3e}, tooth 3 {t2:.3e}"
    );
    // The tooth moves in proportion to the error (ratio ~2), the mean far less and
    // faster than linearly (second order).
    assert!(t1 > 0.02 && (t2 / t1 - 2.0).abs() < 0.2);
    assert!(m1 < 0.05 * t1 && m2 < 0.05 * t2);
}
