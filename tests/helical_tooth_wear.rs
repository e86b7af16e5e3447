//! Wear of a helical pair's teeth tooth by tooth and slice by slice (docs/MODEL.md 11.13,
//! `study::helical_tooth_wear`) against independent facts: at a vanishing helix angle
//! with one slice the spur pair's per-tooth wear run with the same per-tooth inputs;
//! every tooth perfect through the tooth-resolved path is the identical teeth's wear per
//! slice; a pitch error moves its own tooth's wear in proportion to the error but the
//! mean over the teeth only to second order (as for a spur pair, tests/teeth_wear.rs), on
//! the pinion and on the gear; a broken tip's covered slices wear exactly nothing past the
//! cut radius worked by hand; a cut run resumes to the same bytes and a forged per-tooth
//! profile count is refused.

mod common;

use common::helical::{model, NOMINAL};
use common::resume::{cut_log, cut_then_resumed_is_unchanged, edit_update, refused, run};
use gearwear::study::wear_loop::{next_update, run_wear, Next, UpdateRecord, WearMode, WearRun};
use gearwear::study::Model;
use std::path::Path;

fn wear_run(m: &Model, mode: WearMode) -> WearRun {
    run_wear(m, WearRun::new(mode), &mut |_| Ok(())).expect("wear run")
}

/// `teeth.pitch_error_pinion_um` with `e_um` on `tooth` of the 19.
fn pitch_error(e_um: f64, tooth: usize) -> String {
    let mut v = vec!["0".to_string(); 19];
    v[tooth] = format!("{e_um}");
    format!("teeth.pitch_error_pinion_um=[{}]", v.join(","))
}

/// Largest |a - b| over two sets of profiles.
fn worst(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

#[test]
fn one_slice_at_a_vanishing_helix_angle_is_the_spur_pair_s_per_tooth_wear() {
    // beta = 1e-6 deg with one slice: the slice is the spur pair (its transverse section
    // the normal one to 1e-12, cos(beta_b) = 1 - 1.4e-16), its one contact line the spur
    // pair's tooth pair (tests/helical_teeth.rs: the responses agree to 1e-9), each tooth's
    // slice 0 its spur tooth, worn by the same per-tooth bookkeeping. The spur run takes
    // the same per-tooth inputs through its own tooth-resolved mesh. Every tooth's wear of
    // every update must agree to 1e-9 of the deepest wear (rounding amplified by the
    // steady-state solver, whose tolerance is 1e-6 relative), in both modes; a pitch error
    // and a crack over the whole face.
    let faults: [&[&str]; 2] = [
        &["PITCH"],
        &[
            "fault.kind=\"crack\"",
            "fault.gear=\"gear\"",
            "fault.tooth=5",
            "fault.crack_depth_mm=1.5",
        ],
    ];
    let pe = pitch_error(4.0, 3);
    for (f, mode) in [
        (faults[0], WearMode::QuasiStatic),
        (faults[1], WearMode::QuasiStatic),
        (faults[0], WearMode::Dynamic),
    ] {
        let f: Vec<&str> = f
            .iter()
            .map(|s| if *s == "PITCH" { pe.as_str() } else { s })
            .collect();
        let mut common = f.clone();
        common.extend(["wear.total_cycles=3e4", "wear.threshold_um=0.5"]);
        let spur = model(&common);
        let mut h = common.clone();
        h.extend(["gear.helix_angle_deg=1e-6", "stiffness.slices=1"]);
        if f.len() > 1 {
            h.extend(["fault.face_start_mm=0", "fault.face_end_mm=20"]);
        }
        let helical = model(&h);
        assert!(helical.helical.is_some() && helical.teeth.is_some());
        let (a, b) = (wear_run(&spur, mode), wear_run(&helical, mode));
        assert!(a.records.len() >= 3, "{} updates", a.records.len());
        assert_eq!(a.records.len(), b.records.len());
        let scale = a.last().unwrap().wear.max_pinion_m();
        let mut w: f64 = 0.0;
        for (ra, rb) in a.records.iter().zip(&b.records) {
            assert_eq!(ra.wear.cycles, rb.wear.cycles);
            let (ta, tb) = (
                ra.wear.teeth.as_ref().unwrap(),
                rb.wear.teeth.as_ref().unwrap(),
            );
            assert_eq!(tb.pinion_m.len(), 19, "one slice: a profile per tooth");
            w = w.max(worst(&ta.pinion_m, &tb.pinion_m) / scale);
            w = w.max(worst(&ta.gear_m, &tb.gear_m) / scale);
        }
        println!("{f:?} {mode:?}: worst difference {w:.2e} of the deepest wear {scale:.3e} m");
        assert!(scale > 0.0 && w < 1e-9, "{w:e}");
        // The teeth do differ (the comparison is of per-tooth wear, not of alike teeth).
        let t = a.last().unwrap().wear.teeth.as_ref().unwrap();
        let spread =
            worst(&t.pinion_m[..1], &t.pinion_m[3..4]).max(worst(&t.gear_m[..1], &t.gear_m[5..6]));
        assert!(spread > 1e-3 * scale, "{spread:e}");
    }
}

/// The helical case of the tests below: 15 deg, 12 slices, on the nominal path.
const HELIX: [&str; 2] = ["gear.helix_angle_deg=15", "stiffness.slices=12"];

#[test]
fn perfect_teeth_through_the_resolved_path_wear_as_the_identical_teeth_slice_by_slice() {
    // A pitch error resolves the teeth; with every position error set to zero each tooth
    // is perfect, so every tooth's face slice j must wear as the identical teeth's slice
    // j (`study::helical_wear`), in both modes over three updates. The two routes differ
    // only in rounding: the resolved lines add each flank's worn line, the plain one their
    // sum; 1e-9 of the deepest wear, the steady-state solver's tolerance (1e-6) far
    // above it. Every tooth must carry the same profiles bit for bit.
    let mut sets = HELIX.to_vec();
    sets.extend(["wear.total_cycles=3e4", "wear.threshold_um=1e3"]);
    let plain = model(&sets);
    let pe = pitch_error(3.0, 2);
    let mut with = sets.clone();
    with.push(&pe);
    let mut resolved = model(&with);
    let t = resolved.teeth.as_mut().unwrap();
    for f in t.pinion.iter_mut().chain(t.gear.iter_mut()) {
        f.position_m = 0.0;
    }
    let n = 12;
    for mode in [WearMode::QuasiStatic, WearMode::Dynamic] {
        let (a, b) = (wear_run(&plain, mode), wear_run(&resolved, mode));
        assert_eq!(a.records.len(), 4, "three updates");
        assert_eq!(b.records.len(), a.records.len());
        let scale = a.last().unwrap().wear.max_pinion_m();
        let mut w: f64 = 0.0;
        for (ra, rb) in a.records.iter().zip(&b.records) {
            let s = ra.wear.slices.as_ref().unwrap();
            let t = rb.wear.teeth.as_ref().unwrap();
            assert_eq!((t.pinion_m.len(), t.gear_m.len()), (19 * n, 31 * n));
            for (each, one, z) in [(&t.pinion_m, &s.pinion_m, 19), (&t.gear_m, &s.gear_m, 31)] {
                for tooth in 0..z {
                    assert_eq!(
                        &each[tooth * n..(tooth + 1) * n],
                        &each[..n],
                        "tooth {tooth}"
                    );
                }
                w = w.max(worst(&each[..n], one) / scale);
            }
        }
        println!("{mode:?}: worst difference {w:.2e} of the deepest wear {scale:.3e} m");
        assert!(scale > 0.0 && w < 1e-9, "{mode:?}: {w:e}");
    }
}

/// The first record (new teeth) of `m`, quasi-static.
fn first(m: &Model) -> UpdateRecord {
    match next_update(m, WearMode::QuasiStatic, None).unwrap() {
        Next::Record(r) => *r,
        _ => panic!("no first record"),
    }
}

#[test]
fn a_pitch_error_moves_its_tooth_s_wear_but_not_the_mean_to_first_order() {
    // Archard's depth per pass, k p0 2a |u_s| / u, is proportional to the load on a slice
    // (p0 and a both grow as sqrt(load)); a pitch error moves load between neighbouring
    // engagements, so to first order the mean over the teeth keeps the identical teeth's
    // wear per slice while a single tooth changes in proportion to the error (the spur
    // pair's fact, tests/teeth_wear.rs). Quasi-static, the first increments; measured as
    // the largest change of a face slice's profile over the identical teeth's deepest.
    let plain = first(&model(&HELIX));
    let s = plain.increment_slices.as_ref().unwrap();
    let scale = s.pinion_m.iter().flatten().fold(0.0_f64, |a, b| a.max(*b));
    let n = 12;
    let change = |e_um: f64| {
        let pe = pitch_error(e_um, 3);
        let mut sets = HELIX.to_vec();
        sets.push(&pe);
        let r = first(&model(&sets));
        let t = r.increment_teeth.unwrap();
        // The mean over the teeth of each face slice.
        let mean: Vec<Vec<f64>> = (0..n)
            .map(|j| {
                (0..s.pinion_m[0].len())
                    .map(|i| (0..19).map(|a| t.pinion_m[a * n + j][i]).sum::<f64>() / 19.0)
                    .collect()
            })
            .collect();
        let mean_dev = worst(&mean, &s.pinion_m) / scale;
        let tooth_dev = worst(&t.pinion_m[3 * n..4 * n], &s.pinion_m) / scale;
        let far_dev = worst(&t.pinion_m[12 * n..13 * n], &s.pinion_m) / scale;
        (mean_dev, tooth_dev, far_dev)
    };
    let (m1, t1, f1) = change(1.0);
    let (m2, t2, _) = change(2.0);
    println!(
        "pitch error 1 um: mean {m1:.3e}, tooth 3 {t1:.3e}, tooth 12 {f1:.3e}; 2 um: mean {m2:.3e}, tooth 3 {t2:.3e}"
    );
    // The tooth moves in proportion to the error (ratio ~2), the mean far less and
    // faster than linearly (second order); a tooth far from it is not moved.
    assert!(t1 > 0.02 && (t2 / t1 - 2.0).abs() < 0.2, "{t1} {t2}");
    assert!(m1 < 0.05 * t1 && m2 < 0.05 * t2, "{m1} {m2}");
    assert!(f1 < 1e-9, "{f1}");
}

/// A small helical case with per-tooth inputs: 15 deg, 4 slices, a pitch error on pinion
/// tooth 3, its wear threshold small enough for more updates than the resume recomputes.
fn args(mode: &str, out: &Path) -> Vec<String> {
    let mut a: Vec<String> = ["-q", "wear", "--mode", mode]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let pe = pitch_error(5.0, 3);
    let mut sets: Vec<&str> = NOMINAL.to_vec();
    sets.extend([
        "gear.helix_angle_deg=15",
        "stiffness.slices=4",
        "wear.total_cycles=2e4",
        "wear.threshold_um=0.1",
        &pe,
    ]);
    for s in sets {
        a.extend(["--set".to_string(), s.to_string()]);
    }
    a.extend(["--out".to_string(), out.to_str().unwrap().to_string()]);
    a
}

#[test]
fn a_cut_run_with_helical_teeth_resumes_to_the_same_bytes() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let cut = |out: &Path| {
        cut_log(&out.join("checkpoint_dynamic.jsonl"), 2, true);
        cut_log(&out.join("checkpoint_quasi_static.jsonl"), 3, false);
    };
    cut_then_resumed_is_unchanged(&args("both", &out), &out, &cut);
}

#[test]
fn a_checkpoint_without_a_tooth_s_slices_is_refused() {
    // One profile less in an update's per-tooth, per-slice pinion wear (its checksum
    // recomputed): the resume refuses the log, naming the line and the profile count
    // (19 teeth x 4 slices).
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let a = args("quasi-static", &out);
    let o = run(&a);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let log = out.join("checkpoint_quasi_static.jsonl");
    edit_update(&log, 1, true, &|v| {
        v.pointer_mut("/wear/teeth/pinion_m")
            .expect("per-tooth wear in the log")
            .as_array_mut()
            .unwrap()
            .pop();
    });
    refused(
        &a,
        "a missing tooth slice",
        &["checkpoint_quasi_static.jsonl", "76 profiles"],
    );
}

#[test]
fn the_budget_counts_every_tooth_s_slices() {
    // A record of a toothed helical pair holds every tooth's face slices (wear and
    // increment, (z1 + z2) N G numbers each): the budget's count of a record is exactly
    // that, counted here from the record itself; so the estimate of the study (memory of
    // the records, time of the slice contacts over the excitation's P periods) and the
    // checkpoint read cap exceed those of the same pair with identical teeth.
    use gearwear::study::budget::helical::{record_numbers, wear_record_numbers};
    use gearwear::study::budget::{estimate, max_checkpoint_bytes, Job};
    let pe = pitch_error(5.0, 3);
    let mut s = HELIX.to_vec();
    s.push("wear.total_cycles=2e4");
    let plain = model(&s).case;
    s.push(&pe);
    let m = model(&s);
    let rec = first(&m);
    let (t, i) = (rec.wear.teeth.unwrap(), rec.increment_teeth.unwrap());
    let numbers: usize = [&t.pinion_m, &t.gear_m, &i.pinion_m, &i.gear_m]
        .iter()
        .flat_map(|p| p.iter().map(Vec::len))
        .sum();
    assert_eq!(wear_record_numbers(&m.case), numbers as f64);
    assert_eq!(wear_record_numbers(&plain), record_numbers(&plain));
    let job = Job::Wear {
        dynamic: false,
        quasi_static: true,
    };
    let (et, ep) = (estimate(&m.case, job), estimate(&plain, job));
    assert!(
        et.memory_bytes() > ep.memory_bytes() && et.seconds() > ep.seconds(),
        "toothed {} s {} B, identical {} s {} B",
        et.seconds(),
        et.memory_bytes(),
        ep.seconds(),
        ep.memory_bytes()
    );
    // At the default 400 slices the records are past the cap's 64 MiB floor.
    let mut big = m.case.clone();
    big.stiffness.slices = 400;
    let mut big_plain = plain.clone();
    big_plain.stiffness.slices = 400;
    let mode = WearMode::QuasiStatic;
    assert!(max_checkpoint_bytes(&big, mode) > max_checkpoint_bytes(&big_plain, mode));
}

#[test]
fn a_broken_tip_s_slices_wear_nothing_where_they_do_not_touch() {
    // Tooth 3's tip 1 mm lower over the face [0, 10] mm of 20 (8 slices; covered: those
    // whose centre (j + 1/2) b / N lies in the span, worked here by hand), on the pinion
    // and, separately, on the gear. A covered slice of the broken tooth does not touch past
    // the cut: pinion rho1 > rho_cut for the pinion's tip (on the involute,
    // r^2 = r_b^2 + rho^2 at r = r_a - 1 mm), pinion rho1 < loa - rho_cut,2 for the gear's.
    // There Archard's depth of its every pass is zero, so its increment must be exactly
    // zero; its uncovered slices touch there and wear. The increments are the quasi-static
    // first ones (new teeth). Between the last sample before the cut and the first past it
    // the pass is joined linearly over one sample's advance along the path (base pitch
    // over the steps of a mesh period): the check starts two such advances past the cut.
    let n = 8;
    for gear in ["pinion", "gear"] {
        let side = format!("fault.gear=\"{gear}\"");
        let m = model(&[
            "gear.helix_angle_deg=15",
            "stiffness.slices=8",
            "numerics.steps_per_mesh_period=400",
            "fault.kind=\"broken_tip\"",
            &side,
            "fault.tooth=3",
            "fault.removed_height_mm=1",
            "fault.face_start_mm=0",
            "fault.face_end_mm=10",
        ]);
        let h = m.helical.as_ref().unwrap();
        let t = &h.pair.transverse;
        let b = h.pair.face_width_m;
        let covered: Vec<bool> = (0..n)
            .map(|j| (j as f64 + 0.5) * b / n as f64 <= 10e-3)
            .collect();
        assert_eq!(covered.iter().filter(|c| **c).count(), 4);
        let on_involute = |ra: f64, rb: f64| ((ra - 1e-3).powi(2) - rb * rb).sqrt();
        let p = &t.pinion;
        let advance = 2.0 * std::f64::consts::PI * p.base_radius_m / p.teeth as f64 / 400.0;
        let past: Box<dyn Fn(f64) -> bool> = if gear == "pinion" {
            let cut = on_involute(p.tip_radius_m, p.base_radius_m);
            Box::new(move |x| x > cut + 2.0 * advance)
        } else {
            let g = &t.gear;
            let cut = t.loa_length_m - on_involute(g.tip_radius_m, g.base_radius_m);
            Box::new(move |x| x < cut - 2.0 * advance)
        };
        let points: Vec<usize> = (0..m.grid.len())
            .filter(|i| past(m.grid.rho_pinion_m[*i]))
            .collect();
        assert!(
            points.len() >= 3,
            "{gear}: {} grid points past the cut",
            points.len()
        );
        let inc = first(&m).increment_teeth.unwrap();
        let teeth = if gear == "pinion" {
            &inc.pinion_m
        } else {
            &inc.gear_m
        };
        let mut worn: f64 = 0.0;
        for j in 0..n {
            let w = &teeth[3 * n + j];
            for &i in &points {
                if covered[j] {
                    assert_eq!(w[i], 0.0, "{gear} tooth 3 slice {j} at grid point {i}");
                } else {
                    worn = worn.max(w[i]);
                }
            }
        }
        // The uncovered slices wear there as a healthy tooth's does: the deepest increment
        // there of tooth 0's last face slice (no fault), of the same order.
        let healthy = (points.iter())
            .map(|&i| teeth[n - 1][i])
            .fold(0.0_f64, f64::max);
        println!(
            "{gear}: {} points past the cut; uncovered {worn:.3e}, healthy {healthy:.3e}",
            points.len()
        );
        assert!(
            healthy > 0.0 && worn > 0.1 * healthy,
            "{worn:e} {healthy:e}"
        );
    }
}

#[test]
fn a_gear_pitch_error_moves_its_gear_tooth_s_wear_but_not_the_mean_to_first_order() {
    // The pinion test's fact (above) on the gear's side, through the lines' gear teeth
    // b = n mod z2: a pitch error on gear tooth 5 of 31 moves that tooth's wear per slice
    // in proportion to the error and the mean over the gear's 31 teeth only to second
    // order; a gear tooth half the gear away (20) is not moved. Same measure and bounds.
    let plain = first(&model(&HELIX));
    let s = plain.increment_slices.as_ref().unwrap();
    let scale = s.gear_m.iter().flatten().fold(0.0_f64, |a, b| a.max(*b));
    let n = 12;
    let change = |e_um: f64| {
        let mut v = vec!["0".to_string(); 31];
        v[5] = format!("{e_um}");
        let pe = format!("teeth.pitch_error_gear_um=[{}]", v.join(","));
        let mut sets = HELIX.to_vec();
        sets.push(&pe);
        let t = first(&model(&sets)).increment_teeth.unwrap();
        let mean: Vec<Vec<f64>> = (0..n)
            .map(|j| {
                (0..s.gear_m[0].len())
                    .map(|i| (0..31).map(|b| t.gear_m[b * n + j][i]).sum::<f64>() / 31.0)
                    .collect()
            })
            .collect();
        let mean_dev = worst(&mean, &s.gear_m) / scale;
        let tooth_dev = worst(&t.gear_m[5 * n..6 * n], &s.gear_m) / scale;
        let far_dev = worst(&t.gear_m[20 * n..21 * n], &s.gear_m) / scale;
        (mean_dev, tooth_dev, far_dev)
    };
    let (m1, t1, f1) = change(1.0);
    let (m2, t2, _) = change(2.0);
    println!(
        "gear pitch error 1 um: mean {m1:.3e}, tooth 5 {t1:.3e}, tooth 20 {f1:.3e}; 2 um: mean {m2:.3e}, tooth 5 {t2:.3e}"
    );
    assert!(t1 > 0.02 && (t2 / t1 - 2.0).abs() < 0.2, "{t1} {t2}");
    assert!(m1 < 0.05 * t1 && m2 < 0.05 * t2, "{m1} {m2}");
    assert!(f1 < 1e-9, "{f1}");
}
