//! Per-tooth errors and faults on a helical pair (docs/MODEL.md 11.10,
//! `study::teeth::ToothInputs::helical`) against independent facts: a gap common to every
//! tooth is the untoothed pair with that gap as an external error; a fault across the
//! whole face at beta -> 0 with one slice is the spur pair's fault; a crack over part of
//! the face lowers the mesh stiffness as the statics of its parallel slice springs, worked
//! by hand from one slice's stiffness and the crack's compliance, predict; one tooth's pitch
//! error acts once per pinion revolution, for the time its contact line takes to cross
//! the path (the geometry's total contact ratio); bad spans exit 2 naming the key.

mod common;

use common::helical::{close, model, quasi, same_summaries, steady, stiffness_dips};
use common::rejected;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::stiffness::tooth_faults::{crack_compliance_m_per_n, Crack};
use gearwear::study::Model;

#[test]
fn a_pitch_error_common_to_every_tooth_is_the_untoothed_pair_with_that_gap() {
    // Every pinion tooth 4 um proud: every contact line closes 4 um of the reference
    // circle's arc earlier, along the line of action 4 um cos(alpha_t) (alpha_t the
    // transverse reference pressure angle, tan alpha_t = tan alpha_n / cos beta, by hand
    // from the case). The untoothed pair takes the same constant as an external error
    // (paper eq. 2's sign: positive adds compression). The tooth-resolved mesh sums the
    // same springs through another path (`springs_resolved`), so the two agree to
    // rounding amplified by the steady-state solver (its tolerance 1e-6): 1e-9 relative.
    let helix = ["gear.helix_angle_deg=15", "stiffness.slices=100"];
    let errors = format!("teeth.pitch_error_pinion_um=[{}]", ["4"; 19].join(","));
    let mut toothed_sets = helix.to_vec();
    toothed_sets.push(&errors);
    let toothed = model(&toothed_sets);
    let plain = model(&helix);
    let (beta, alpha_n) = (15f64.to_radians(), 20f64.to_radians());
    let alpha_t = (alpha_n.tan() / beta.cos()).atan();
    let e = 4e-6 * alpha_t.cos();
    let period = plain.pair.mesh_angle_rad();
    let a = steady(&toothed, &ExternalError::none());
    let b = steady(&plain, &ExternalError::new(&[(0.0, e)], period));
    assert_eq!(a.excitation_periods, 1, "identical teeth repeat every mesh");
    same_summaries(&ResponseSummary::of(&a), &ResponseSummary::of(&b), 1e-9);
    // And the gap matters: without it the DTE differs by about e.
    let c = ResponseSummary::of(&steady(&plain, &ExternalError::none()));
    let shift = ResponseSummary::of(&a).dte_mean_m - c.dte_mean_m;
    close(shift.abs(), e, 0.05, "the DTE's shift by the common gap");
}

#[test]
fn a_crack_across_the_face_at_a_vanishing_helix_angle_is_the_spur_pair_s() {
    // beta = 1e-6 deg with one slice: the slice is the spur pair (its transverse section
    // the normal one to 1e-12, its Hertz term times cos(beta_b) = 1 - 1.4e-16), its one
    // contact line the spur pair's tooth pair, and the crack over the whole face [0, b]
    // that slice's crack. The line's compliance is sampled at the wear grid's points, where
    // the spur pair's table is, so the responses over the 19 mesh periods agree to
    // rounding amplified by the steady-state solver: 1e-9 relative.
    let crack = [
        "fault.kind=\"crack\"",
        "fault.gear=\"pinion\"",
        "fault.tooth=3",
        "fault.crack_depth_mm=2",
    ];
    let spur = model(&crack);
    let mut h = crack.to_vec();
    h.extend([
        "gear.helix_angle_deg=1e-6",
        "stiffness.slices=1",
        "fault.face_start_mm=0",
        "fault.face_end_mm=20",
    ]);
    let helical = model(&h);
    let (a, b) = (
        steady(&spur, &ExternalError::none()),
        steady(&helical, &ExternalError::none()),
    );
    assert_eq!((a.excitation_periods, b.excitation_periods), (19, 19));
    let (sa, sb) = (ResponseSummary::of(&a), ResponseSummary::of(&b));
    same_summaries(&sa, &sb, 1e-9);
    // The crack is felt: the healthy pair's peak force is lower by far more than that.
    let healthy = ResponseSummary::of(&steady(&model(&[]), &ExternalError::none()));
    assert!(sa.mesh_force_max_n - healthy.mesh_force_max_n > 1e-3 * sa.mesh_force_max_n);
}

#[test]
fn a_crack_over_half_the_face_removes_half_the_stiffness_parallel_slices_predict() {
    // A crack 2 mm deep on pinion tooth 3 over the face [0, b] and over [0, b/2]. By hand,
    // with no coupling between slices (the slice model's own assumption): each of the
    // face slice's springs k(r) in the span takes the crack's compliance c(r) in series,
    // 1 / (1/k + c), so a line whose cracked slices sit at r_i loses
    // sum_i [k(r_i) - 1/(1/k(r_i) + c(r_i))]; as the line crosses the path every slice
    // sweeps the whole path [A, E] once, so the stiffness lost, integrated over the pinion's
    // roll, is n_span I with I = int_A^E [k - 1/(1/k + c)] dr (Simpson, 4000 intervals) and
    // n_span the slices whose centres lie in the span (N and N/2). Its peak is the largest
    // over the line's positions of the same sum (4000 positions). k: one slice's stiffness
    // (`MeshStiffness::pair_stiffness_n_per_m` of the slice model's slice), c: the crack's
    // compliance on the slice's pinion beam (`crack_compliance_m_per_n`), both evaluated
    // here, not by the model's line tables. The model's mesh stiffness is load-free (the
    // sum of the springs in contact), at any load. Tolerances: the quasi-static grid of
    // 400 steps a mesh period and the line tables' linear interpolation at the wear grid's
    // spacing (101 points on the profile), with each slice's jump on entering the path
    // resolved to a step: 1 % on the integral, 2 % on the peak.
    let n = 100usize;
    let base = [
        "gear.helix_angle_deg=15",
        "stiffness.slices=100",
        "numerics.steps_per_mesh_period=400",
        "fault.kind=\"crack\"",
        "fault.gear=\"pinion\"",
        "fault.tooth=3",
        "fault.crack_depth_mm=2",
    ];
    let run = |end: &str| {
        let mut s = base.to_vec();
        s.push(end);
        let m = model(&s);
        let r = quasi(&m);
        (m, r)
    };
    let (full_m, full_r) = run("fault.face_end_mm=20");
    let (half_m, half_r) = run("fault.face_end_mm=10");
    // The hand statics.
    let h = full_m.helical.as_ref().expect("a helical model");
    let slice = h.slice_model.slice();
    let t = &h.pair.transverse;
    let beam = &slice.tooth_beams()[0];
    // The pinion's tip contact: the transverse path's end E.
    let tip = t.rho_end_m;
    let crack = Crack {
        depth_m: 2e-3,
        angle_rad: 45f64.to_radians(),
        width_fraction: 1.0,
    };
    let lost = |r: f64| {
        let k = slice.pair_stiffness_n_per_m(r);
        k - 1.0 / (1.0 / k + crack_compliance_m_per_n(beam, tip, &crack, r))
    };
    let (a, e) = (t.rho_start_m, t.rho_end_m);
    let q = 4000;
    let hq = (e - a) / q as f64;
    let integral: f64 = (0..=q)
        .map(|i| {
            let w = match i {
                0 => 1.0,
                i if i == q => 1.0,
                i if i % 2 == 1 => 4.0,
                _ => 2.0,
            };
            w * lost(a + i as f64 * hq)
        })
        .sum::<f64>()
        * hq
        / 3.0;
    // The line's slices at offsets (j + 1/2) L / N from its trailing end; a right-hand
    // pinion's trailing end is the face end y = 0, so the span [0, b/2] is the first N/2.
    let lead = h.pair.face_width_m * h.pair.base_helix_angle_rad.tan();
    let peak = |slices: usize| {
        (0..=q)
            .map(|p| {
                let rho = a - lead + p as f64 * (e - a + lead) / q as f64;
                (0..slices)
                    .map(|j| rho + (j as f64 + 0.5) * lead / n as f64)
                    .filter(|r| (a..=e).contains(r))
                    .map(lost)
                    .sum::<f64>()
            })
            .fold(0.0, f64::max)
    };
    for (m, r, slices, what) in [
        (&full_m, &full_r, n, "whole face"),
        (&half_m, &half_r, n / 2, "half face"),
    ] {
        let dips = stiffness_dips(m, r);
        let area: f64 = dips.iter().map(|(d, w)| d * w).sum();
        close(area, slices as f64 * integral, 0.01, what);
        let top = dips.iter().map(|(d, _)| *d).fold(0.0, f64::max);
        close(top, peak(slices), 0.02, what);
    }
    // About half: the integral exactly (n_span), the peak nearly.
    let area = |m: &Model, r: &DynamicResponse| -> f64 {
        stiffness_dips(m, r).iter().map(|(d, w)| d * w).sum()
    };
    close(
        area(&half_m, &half_r) / area(&full_m, &full_r),
        0.5,
        0.01,
        "half over whole",
    );
}

#[test]
fn one_tooth_s_pitch_error_acts_once_a_revolution_while_its_line_crosses_the_path() {
    // Pinion tooth 5 stands 3 um proud. Mesh cycle n meets pinion tooth n mod z1 and its
    // contact line enters at pinion rotation n theta_m (docs/MODEL.md 9.2 and 11.10), its
    // leading face end first; the line leaves when its trailing end passes E, after
    // epsilon_gamma = epsilon_alpha + epsilon_beta mesh periods (the geometry's total
    // contact ratio: the path plus the line's extent b tan(beta_b), over the base pitch).
    // So the quasi-static DTE differs from the untoothed pair's in one window per pinion
    // revolution (19 mesh periods), from 5 theta_m to (5 + epsilon_gamma) theta_m. The
    // first slice to enter carries 1/N of a line, so the window is found where the
    // difference exceeds 1e-6 of its peak (rounding between the two paths is ~1e-16);
    // tolerance: one quasi-static step on either side (1/400 of a mesh period) plus the
    // grid's uneven steps near the mesh events: 0.01 mesh period.
    let helix = [
        "gear.helix_angle_deg=15",
        "stiffness.slices=100",
        "numerics.steps_per_mesh_period=400",
    ];
    let mut errors = vec!["0"; 19];
    errors[5] = "3";
    let errors = format!("teeth.pitch_error_pinion_um=[{}]", errors.join(","));
    let mut toothed_sets = helix.to_vec();
    toothed_sets.push(&errors);
    let toothed = model(&toothed_sets);
    let plain = model(&helix);
    let (a, b) = (quasi(&toothed), quasi(&plain));
    assert_eq!(a.excitation_periods, 19, "once per pinion revolution");
    let (da, db) = (&a.signals.meshes[0].dte_m, &b.signals.meshes[0].dte_m);
    let s = db.len();
    assert_eq!(da.len(), 19 * s);
    let diff: Vec<f64> = (0..da.len()).map(|k| (da[k] - db[k % s]).abs()).collect();
    let top = diff.iter().cloned().fold(0.0, f64::max);
    assert!(top > 1e-7, "the proud tooth shows: {top}");
    let on: Vec<usize> = (0..diff.len()).filter(|k| diff[*k] > 1e-6 * top).collect();
    // One contiguous window.
    assert!(
        on.windows(2).all(|w| w[1] == w[0] + 1),
        "one window per revolution"
    );
    let t_m = a.mesh_period_s;
    let times = &a.signals.time_s;
    let start = times[on[0]] / t_m;
    let end = times[*on.last().unwrap()] / t_m;
    let eps_gamma = toothed.helical.as_ref().unwrap().pair.total_contact_ratio;
    assert!((start - 5.0).abs() < 0.01, "enters at {start} mesh periods");
    assert!(
        (end - (5.0 + eps_gamma)).abs() < 0.01,
        "leaves at {end} mesh periods, epsilon_gamma {eps_gamma}"
    );
}

#[test]
fn bad_face_spans_exit_2_naming_the_key_and_the_range() {
    let crack = [
        "--set",
        "gear.helix_angle_deg=15",
        "--set",
        "fault.kind=\"crack\"",
        "--set",
        "fault.gear=\"pinion\"",
        "--set",
        "fault.tooth=3",
        "--set",
        "fault.crack_depth_mm=1",
    ];
    let with = |more: &[&'static str]| {
        let mut a = vec!["dynamics"];
        a.extend(crack);
        a.extend(more);
        a
    };
    // Beyond the face width (20 mm).
    rejected(
        &with(&["--set", "fault.face_end_mm=25"]),
        &["fault.face_end_mm", "25", "[0, 20]"],
    );
    // Below 0: the schema's range.
    rejected(
        &with(&["--set", "fault.face_start_mm=-1"]),
        &["fault.face_start_mm", "-1"],
    );
    // Start at or after the end.
    rejected(
        &with(&[
            "--set",
            "fault.face_start_mm=12",
            "--set",
            "fault.face_end_mm=12",
        ]),
        &["fault.face_start_mm", "fault.face_end_mm", "12"],
    );
    // A span on a spur pair; a spur pair's width fraction on a helical one.
    rejected(
        &[
            "dynamics",
            "--set",
            "fault.kind=\"crack\"",
            "--set",
            "fault.gear=\"pinion\"",
            "--set",
            "fault.tooth=3",
            "--set",
            "fault.crack_depth_mm=1",
            "--set",
            "fault.face_end_mm=10",
        ],
        &["fault.face_end_mm", "gear.helix_angle_deg"],
    );
    rejected(
        &with(&["--set", "fault.crack_width_fraction=0.5"]),
        &["fault.crack_width_fraction", "fault.face_start_mm"],
    );
    // A span that holds no slice centre would change nothing (review finding: it ran as
    // the healthy pair): refused naming the keys and the slice width.
    rejected(
        &with(&[
            "--set",
            "stiffness.slices=40",
            "--set",
            "fault.face_start_mm=0",
            "--set",
            "fault.face_end_mm=0.01",
        ]),
        &["fault.face_start_mm", "no slice centre", "stiffness.slices"],
    );
    // A wear sweep does not take helical teeth yet (`gearwear wear` and `gearwear run` do,
    // docs/MODEL.md 11.13).
    rejected(
        &[
            "sweep",
            "--run",
            "wear",
            "--set",
            "gear.helix_angle_deg=15",
            "--set",
            "teeth.accuracy_grade=6",
            "--vary",
            "operating.input_speed_hz=20,30",
        ],
        &["`[teeth]`", "gear.helix_angle_deg", "a wear sweep"],
    );
}
