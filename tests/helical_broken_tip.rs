//! A broken tip on a helical tooth (docs/MODEL.md 11.12, `study::teeth::helical_tip`)
//! against independent facts: across the whole face at beta -> 0 with one slice it is the
//! spur pair's broken tip (pinion and gear); the mesh stiffness it takes, integrated over the
//! pinion's roll, is the covered slices' count times one slice's stiffness integrated from
//! the cut to the path's end (parallel slices, worked by hand from the involute), so half the
//! face takes half, and only while a covered slice is past the cut; the broken tooth's line
//! stops touching once its trailing slice passes the cut radius, a contact shorter by the
//! path the lost tip held, (rho_E - rho_cut) / p_b from the involute by hand; a tip cut
//! below the start of active profile over the leading part of the face exits 2.

mod common;

use common::helical::{close, model, quasi, same_summaries, steady, stiffness_dips};
use common::rejected;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;

/// A broken tip of 1 mm radial height on tooth 3 of `gear`.
fn tip(gear: &str) -> Vec<String> {
    vec![
        "fault.kind=\"broken_tip\"".into(),
        format!("fault.gear=\"{gear}\""),
        "fault.tooth=3".into(),
        "fault.removed_height_mm=1".into(),
    ]
}

fn with(base: &[String], more: &[&str]) -> Model {
    let mut s: Vec<&str> = base.iter().map(|x| x.as_str()).collect();
    s.extend(more);
    model(&s)
}

#[test]
fn a_tip_broken_across_the_face_at_a_vanishing_helix_angle_is_the_spur_pair_s() {
    // beta = 1e-6 deg with one slice: the slice is the spur pair (its transverse section
    // the normal one to 1e-12), its one contact line the spur pair's tooth pair at offset 0,
    // and the tip broken over the whole face that slice's broken tip: the line stops
    // touching where the spur pair's tooth does (the cut radius's rho on the path). Both
    // limits are exact positions, so the responses over the hunting period agree to
    // rounding amplified by the steady-state solver: 1e-9 relative (as for a crack).
    let healthy = ResponseSummary::of(&steady(&model(&[]), &ExternalError::none()));
    for (gear, periods) in [("pinion", 19), ("gear", 31)] {
        let spur = with(&tip(gear), &[]);
        let helical = with(
            &tip(gear),
            &["gear.helix_angle_deg=1e-6", "stiffness.slices=1"],
        );
        let (a, b) = (
            steady(&spur, &ExternalError::none()),
            steady(&helical, &ExternalError::none()),
        );
        assert_eq!(
            (a.excitation_periods, b.excitation_periods),
            (periods, periods)
        );
        let (sa, sb) = (ResponseSummary::of(&a), ResponseSummary::of(&b));
        same_summaries(&sa, &sb, 1e-9);
        // The broken tip is felt: the DTE's peak grows by far more than that.
        assert!(
            sa.dte_max_m - healthy.dte_max_m > 1e-3 * sa.dte_max_m,
            "{gear}"
        );
    }
}

/// The quantities of the built-in pair's transverse section worked by hand for a pinion
/// tip broken by `h_m` (m): rho_cut and rho_E on the involute (r^2 = r_b^2 + rho^2, m), the
/// base pitch p_b = 2 pi r_b1 / z1 (m), and the contact line's extent L = b tan(beta_b) (m).
struct Hand {
    rho_cut_m: f64,
    rho_e_m: f64,
    base_pitch_m: f64,
    line_m: f64,
}

impl Hand {
    fn of(m: &Model, h_m: f64) -> Self {
        let h = m.helical.as_ref().expect("a helical model");
        let p = &h.pair.transverse.pinion;
        let (ra, rb) = (p.tip_radius_m, p.base_radius_m);
        Self {
            rho_cut_m: ((ra - h_m).powi(2) - rb * rb).sqrt(),
            rho_e_m: (ra * ra - rb * rb).sqrt(),
            base_pitch_m: 2.0 * std::f64::consts::PI * rb / p.teeth as f64,
            line_m: h.pair.face_width_m * h.pair.base_helix_angle_rad.tan(),
        }
    }
}

const SLICES: usize = 100;

fn helical_tip(gear: &str, more: &[&str]) -> Model {
    let mut m = vec![
        "gear.helix_angle_deg=15",
        "stiffness.slices=100",
        "numerics.steps_per_mesh_period=400",
    ];
    m.extend(more);
    with(&tip(gear), &m)
}

/// int_lo^hi f dr by Simpson's rule on 4000 intervals.
fn simpson(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let q = 4000;
    let d = (hi - lo) / q as f64;
    let w = |i: usize| match i {
        0 => 1.0,
        i if i == q => 1.0,
        i if i % 2 == 1 => 4.0,
        _ => 2.0,
    };
    (0..=q).map(|i| w(i) * f(lo + i as f64 * d)).sum::<f64>() * d / 3.0
}

#[test]
fn a_tip_broken_over_half_the_face_takes_half_the_stiffness_and_only_past_the_cut() {
    // Tooth 3's tip 1 mm lower: the pinion's over the face [0, b] and over [0, b/2], the
    // gear's over [0, b]. By hand, with no coupling between slices (the slice model's
    // assumption): a covered slice carries nothing at a transverse position r past the cut
    // (the cut radius's rho on the involute, r^2 = r_b^2 + rho^2: r > rho_cut for the
    // pinion, r < loa - rho_cut,2 for the gear), its stiffness k(r) otherwise; as the line
    // crosses the path every slice sweeps [A, E] once, so the stiffness lost, integrated
    // over the pinion's roll, is n_span I, I = int k(r) dr over the cut part of the path
    // (Simpson, 4000 intervals), n_span the covered slices (N and N/2; k: one slice's
    // stiffness, evaluated here). Tolerance as for a crack: the 400 quasi-static steps a
    // mesh period and the line tables' linear interpolation at the wear grid's spacing,
    // each slice's cut a step: 1 %.
    let whole = helical_tip("pinion", &[]);
    let half = helical_tip("pinion", &["fault.face_end_mm=10"]);
    let gear = helical_tip("gear", &[]);
    let hand = Hand::of(&whole, 1e-3);
    let h = whole.helical.as_ref().unwrap();
    let t = &h.pair.transverse;
    // The path runs from the gear's tip to the pinion's (no relief): rho_E and A by hand
    // are the model's.
    close(hand.rho_e_m, t.rho_end_m, 1e-12, "rho_E");
    let g = &t.gear;
    let own = |r: f64| (r * r - g.base_radius_m.powi(2)).sqrt();
    let a = t.loa_length_m - own(g.tip_radius_m);
    close(a, t.rho_start_m, 1e-12, "A");
    let gear_cut = t.loa_length_m - own(g.tip_radius_m - 1e-3);
    let slice = h.slice_model.slice();
    let k = |r: f64| slice.pair_stiffness_n_per_m(r);
    let pinion_lost = simpson(k, hand.rho_cut_m, hand.rho_e_m);
    let gear_lost = simpson(k, a, gear_cut);
    let period_roll = hand.base_pitch_m;
    let o = |j: usize| (j as f64 + 0.5) * hand.line_m / SLICES as f64;
    // Only while a covered slice is past the cut: a right-hand pinion's line has its
    // trailing end on the face end y = 0, so the covered slices are its first `covered`
    // (offsets o_0 .. o_{covered-1}). A pinion's: the first passes the cut at trailing end
    // rho_cut - o_{covered-1}, the last leaves at rho_E - o_0; a gear's: the first enters
    // at A - o_{N-1} already cut, the last passes the cut at loa - rho_cut,2 - o_0.
    let n = SLICES;
    let cases = [
        (
            &whole,
            n,
            pinion_lost,
            (hand.rho_cut_m - o(n - 1), hand.rho_e_m - o(0)),
            19,
            "pinion, whole face",
        ),
        (
            &half,
            n / 2,
            pinion_lost,
            (hand.rho_cut_m - o(n / 2 - 1), hand.rho_e_m - o(0)),
            19,
            "pinion, half face",
        ),
        (
            &gear,
            n,
            gear_lost,
            (a - o(n - 1), gear_cut - o(0)),
            31,
            "gear, whole face",
        ),
    ];
    for (m, covered, integral, (from, to), periods, what) in cases {
        let r = quasi(m);
        assert_eq!(r.excitation_periods, periods);
        let dips = stiffness_dips(m, &r);
        let area: f64 = dips.iter().map(|(d, w)| d * w).sum();
        close(area, covered as f64 * integral, 0.01, what);
        // Mesh cycle 3's line has its trailing end at A - L at 3 mesh periods. Tolerance:
        // one wear-grid spacing (the tables' interpolation starts the dip at the sample
        // before a cut) and one quasi-static step.
        let at = |rho: f64| 3.0 + (rho - (a - hand.line_m)) / period_roll;
        let (start, end) = (at(from), at(to));
        let tol = m.grid.spacing_m / period_roll + 1.0 / 400.0;
        let top = dips.iter().map(|(d, _)| *d).fold(0.0, f64::max);
        let times = &r.signals.time_s;
        let on: Vec<f64> = (0..dips.len())
            .filter(|k| dips[*k].0 > 1e-9 * top)
            .map(|k| times[k] / r.mesh_period_s)
            .collect();
        assert!(
            on.iter().all(|u| *u > start - tol && *u < end + tol),
            "{what}: a dip outside [{start}, {end}]"
        );
        assert!((on[0] - start).abs() < tol, "{what}: starts at {}", on[0]);
        let last = on[on.len() - 1];
        assert!((last - end).abs() < tol, "{what}: ends at {last}");
    }
    // Half the face: half the whole face's loss (the integral exactly n_span).
    let lost = |m: &Model| -> f64 {
        stiffness_dips(m, &quasi(m))
            .iter()
            .map(|(d, w)| d * w)
            .sum()
    };
    close(lost(&half) / lost(&whole), 0.5, 0.01, "half over whole");
}

#[test]
fn a_tip_broken_across_the_face_ends_its_line_s_contact_at_the_cut_radius() {
    // The tip 1 mm lower over the whole face: the broken tooth's line touches while any
    // slice lies on [A, rho_cut] and no more once its trailing slice (offset o_0 = L / 2N)
    // passes rho_cut. From then until the healthy line would leave (its trailing slice at
    // rho_E) the mesh lacks that whole line: the stiffness lost equals the healthy line's
    // K(rho) (the model's line table) to rounding, 1e-9 of the mesh stiffness. So the
    // tooth's contact ends earlier than the healthy line's by the contact ratio the lost
    // tip held, (rho_E - rho_cut) / p_b, from the involute by hand. Tolerance: one quasi-static step (1/400 of a period)
    // plus the grid's uneven steps near mesh events, 0.01 period (as for a pitch error).
    let m = helical_tip("pinion", &[]);
    let hand = Hand::of(&m, 1e-3);
    let r = quasi(&m);
    let dips = stiffness_dips(&m, &r);
    let ms = &r.signals.meshes[0];
    let (rb1, omega) = (
        m.pair.pinion.base_radius_m,
        m.params.operating.pinion_speed_rad_s,
    );
    let o0 = 0.5 * hand.line_m / SLICES as f64;
    let a = m.helical.as_ref().unwrap().pair.transverse.rho_start_m;
    // Cycle 3's line: its trailing end on the line pair at time t.
    let rho3 = |t: f64| m.pair.rho_start_m + rb1 * omega * t - 3.0 * hand.base_pitch_m;
    let mut first_gone = None;
    for (k, t) in r.signals.time_s.iter().enumerate() {
        let rho = rho3(*t);
        if rho < a || rho > hand.rho_e_m - o0 {
            continue;
        }
        let line = m.mesh.pair_stiffness_n_per_m(rho);
        let gone = (dips[k].0 - line).abs() <= 1e-9 * ms.mesh_stiffness_n_per_m[k].max(line);
        if gone && first_gone.is_none() {
            first_gone = Some(*t / r.mesh_period_s);
        }
        if first_gone.is_some() && rho > hand.rho_cut_m - o0 + 1e-3 * hand.base_pitch_m {
            assert!(gone, "the line touches past the cut at rho {rho}");
        }
    }
    let end = first_gone.expect("the line stops touching");
    // The healthy line leaves when its trailing slice passes E: at 3 + epsilon_gamma -
    // o_0 / p_b (epsilon_gamma p_b = E - A + L, the geometry's total contact ratio); the
    // broken one earlier by the drop worked by hand.
    let eps_gamma = m.helical.as_ref().unwrap().pair.total_contact_ratio;
    let drop = (hand.rho_e_m - hand.rho_cut_m) / hand.base_pitch_m;
    assert!(drop > 0.1, "a drop well above the tolerance: {drop}");
    let expected = 3.0 + eps_gamma - o0 / hand.base_pitch_m - drop;
    assert!(
        (end - expected).abs() < 0.01,
        "ends at {end}, by hand {expected}"
    );
}

#[test]
fn a_tip_broken_below_the_active_profile_over_the_leading_face_exits_2() {
    // 4.4 mm off the pinion's tip lies below its start of active profile; over the face
    // half [10, 20] mm that a right-hand pinion's line brings into contact first, the line
    // would enter touching nothing and start touching when its uncut half arrives: refused,
    // naming the key, the value and the range.
    rejected(
        &[
            "dynamics",
            "--set",
            "gear.helix_angle_deg=15",
            "--set",
            "fault.kind=\"broken_tip\"",
            "--set",
            "fault.gear=\"pinion\"",
            "--set",
            "fault.tooth=3",
            "--set",
            "fault.removed_height_mm=4.4",
            "--set",
            "fault.face_start_mm=10",
        ],
        &[
            "fault.removed_height_mm",
            "4.4",
            "valid (0, ",
            "stiffness.slices",
        ],
    );
}
