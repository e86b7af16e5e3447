//! Lead modifications and misalignment in the planar dynamics of a helical pair
//! (`stiffness::helical_lead`, `study::face_load_dynamic`, docs/MODEL.md 11.1) checked
//! against independent facts: the static exact solve of `gearwear stiffness`
//! (`stiffness::face_load`, a second method) at low speed, the symmetry of a crowning, the
//! statics of slice springs under a linear gap computed by hand, the triangle of a partial
//! contact, the torque balance of the mean mesh force, and the refusals.

mod common;

use common::{gearwear, read_csv, rejected, stderr};
use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::stiffness::face_load::FaceLoad;
use gearwear::study::face_load_dynamic::DynamicFaceLoad;
use gearwear::study::helical::LeadDynamics;
use gearwear::study::Model;
use gearwear::wear::WearState;

/// The case at beta = 15 deg with `sets`, at 0.05 Hz input without friction (quasi-static:
/// the mesh's first mode is near 2 kHz, so the dynamic amplification is below 1e-8).
fn slow(sets: &[&str]) -> Vec<String> {
    let mut s = vec![
        "gear.helix_angle_deg=15".to_string(),
        "operating.input_speed_hz=0.05".to_string(),
        "friction.model=\"none\"".to_string(),
    ];
    s.extend(sets.iter().map(|x| x.to_string()));
    s
}

fn model(sets: &[String]) -> Model {
    Model::helical_from_case(&load_case("", sets).expect("valid case")).expect("valid model")
}

fn steady(m: &Model) -> DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .expect("steady state")
}

fn lead(m: &Model) -> &LeadDynamics {
    m.helical
        .as_ref()
        .unwrap()
        .lead
        .as_ref()
        .expect("lead gaps")
}

fn face(m: &Model, r: &DynamicResponse) -> DynamicFaceLoad {
    DynamicFaceLoad::of(m, r, &ExternalError::none()).expect("a face load")
}

/// F_t = T / r_b1 with r_b1 from ISO 21771's transverse section by hand (m_t = m_n /
/// cos beta, tan alpha_t = tan alpha_n / cos beta), N: the static mesh force.
fn tangential_force(m: &Model) -> f64 {
    let c = &m.case;
    let beta = c.gear.helix_angle_deg.to_radians();
    let alpha_t = (c.gear.pressure_angle_deg.to_radians().tan() / beta.cos()).atan();
    let rb1 =
        0.5 * c.gear.module_mm * 1e-3 / beta.cos() * c.gear.teeth_pinion as f64 * alpha_t.cos();
    c.operating.load_torque_nm / rb1
}

/// The static exact solve at 720 mesh positions over a period at F_t.
fn static_solve(m: &Model) -> FaceLoad {
    let l = lead(m);
    FaceLoad::solve(&l.slices, &l.gap, tangential_force(m), 720).unwrap()
}

#[test]
fn at_low_speed_the_dynamic_face_load_is_the_static_solve() {
    // Second method: `gearwear stiffness`'s exact solve of sum_j K_j (delta - g_j)+ = F at
    // 720 positions, against the dynamic model's tabulated line force at 0.05 Hz. The
    // differences: the table's linear interpolation in rho between samples at the slice
    // spacing (below 1.5 slices' force, tests_helical_lead; as a spread over the face's
    // 400 slices a few 1e-3 of w_m at most), the time mean on the solver's samples
    // against 720 uniform positions, and the dynamic amplification (below 1e-8). Allowed:
    // 1 % of w_m per slice, 0.5 % on K_Hbeta, a tenth of a slice width on the centre.
    for gaps in [
        &["modification.crowning_um=8"][..],
        &[
            "modification.helix_slope_deviation_um=6",
            "gear.helix_hand_pinion=\"left\"",
        ],
        &[
            "modification.end_relief_um=10",
            "modification.end_relief_length_mm=4",
            "modification.end_relief_shape=\"parabolic\"",
        ],
    ] {
        let m = model(&slow(gaps));
        let d = face(&m, &steady(&m));
        let s = static_solve(&m);
        let wm = s.mean_load_per_width_n_per_m();
        let sm = s.period_mean_n_per_m();
        let worst = d
            .mean_n_per_m
            .iter()
            .zip(&sm)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0_f64, f64::max);
        eprintln!(
            "{gaps:?}: worst {:.2e} of w_m, K_Hbeta {} / {}, centre {} / {} mm",
            worst / wm,
            d.k_h_beta(),
            s.k_h_beta(),
            d.centre_of_pressure_m() * 1e3,
            s.centre_of_pressure_m() * 1e3
        );
        assert!(worst <= 0.01 * wm, "{gaps:?}: {worst} N/m of {wm}");
        assert!(
            (d.k_h_beta() / s.k_h_beta() - 1.0).abs() <= 5e-3,
            "{gaps:?}"
        );
        let slice = d.face_width_m / d.positions_m.len() as f64;
        assert!((d.centre_of_pressure_m() - s.centre_of_pressure_m()).abs() <= 0.1 * slice);
        // The time-mean distribution carries the mean force: w_m = F_t / b to the
        // solver's tolerance (the trapezoid mean on its samples: 1e-6).
        let dm = d.mean_load_per_width_n_per_m();
        assert!((dm / wm - 1.0).abs() <= 1e-6, "{dm} against {wm}");
    }
}

#[test]
fn a_symmetric_crowning_centres_the_load_and_its_mean_tilting_moment_vanishes() {
    // A crowning is symmetric about mid-face. On a spur pair every slice has the same
    // stiffness and the centre is exactly b/2; on a helical pair slice j sees the same
    // stiffness history shifted in phase while the compression varies over the period, a
    // correlation that leaves the centre off b/2 by a fraction of a slice (static solve:
    // 1e-4 mm). Allowed: half a slice width (b/(2N), the discretisation), at 0.05 Hz and at
    // the case's speed with Xu's friction; the mean moment is the mean force times the
    // centre's offset, so below F b/(2N).
    for sets in [slow(&["modification.crowning_um=8"]), {
        vec![
            "gear.helix_angle_deg=15".into(),
            "modification.crowning_um=8".into(),
        ]
    }] {
        let m = model(&sets);
        let r = steady(&m);
        let d = face(&m, &r);
        let b = d.face_width_m;
        let half_slice = b / (2 * d.positions_m.len()) as f64;
        let off = d.centre_of_pressure_m() - 0.5 * b;
        assert!(off.abs() <= half_slice, "centre off b/2 by {off} m");
        let f = r.meshes[0].mean_mesh_force_n;
        let (mean, lo, hi) = d.tilting_moment_nm();
        eprintln!("centre off {off:.3e} m; moment mean {mean} in [{lo}, {hi}] N m");
        assert!(mean.abs() <= f * half_slice, "mean moment {mean} N m");
        // The moment swings both ways as the lines cross the face.
        assert!(lo < 0.0 && hi > 0.0);
        // The time-mean distribution is symmetric about mid-face up to the same
        // correlation: w_j against w_(N-1-j) within 1 % of w_m (measured 0.4 % at 0.05 Hz;
        // the static solve at its 72 positions has 1.0 %: its sampling of the period).
        let w = &d.mean_n_per_m;
        let wm = d.mean_load_per_width_n_per_m();
        let asym = w
            .iter()
            .zip(w.iter().rev())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0_f64, f64::max);
        assert!(asym <= 0.01 * wm, "asymmetry {asym} N/m of {wm}");
    }
}

#[test]
fn a_linear_gap_moves_the_centre_to_the_closed_side_as_slice_statics_predict() {
    // Hand statics of N slice springs of equal stiffness per unit width k' = K_mean / b
    // (the slice model's mean, N/m^2) under a gap g = s y in full contact: w(y) = w_m +
    // k' s (b/2 - y), so the centre of pressure moves by -k' s b^2 / (12 w_m) times
    // (1 - 1/N^2) (the midpoint slices), towards y = 0 for s > 0 (the closed side). The
    // helical pair's slices vary along each line: the static solve moves by 97 % of the
    // uniform value (docs/MODEL.md 11.2). Allowed: 5 %. A helix slope deviation and a
    // misalignment in the plane of action are the same gap; a negative one, or the
    // other hand, mirrors it.
    for (sets, sign) in [
        (&["modification.helix_slope_deviation_um=5"][..], 1.0),
        (&["operating.misalignment_um=-5"], -1.0),
        (
            &[
                "operating.misalignment_um=5",
                "gear.helix_hand_pinion=\"left\"",
            ],
            1.0,
        ),
    ] {
        let m = model(&slow(sets));
        let d = face(&m, &steady(&m));
        let l = lead(&m);
        let b = d.face_width_m;
        let n = d.positions_m.len() as f64;
        let k_per_width = l.slices.mean_stiffness_n_per_m() / b;
        let wm = tangential_force(&m) / b;
        let s = sign * 5e-6 / b;
        let hand = -k_per_width * s * b * b / (12.0 * wm) * (1.0 - 1.0 / (n * n));
        let moved = d.centre_of_pressure_m() - 0.5 * b;
        eprintln!("{sets:?}: moved {moved:.4e} m, hand {hand:.4e} m");
        assert!(moved * hand > 0.0, "{sets:?}: moved the wrong way");
        assert!(
            (moved / hand - 1.0).abs() <= 0.05,
            "{sets:?}: {moved} against {hand}"
        );
        // The mean tilting moment is the mean force times the shift.
        let (mean, _, _) = d.tilting_moment_nm();
        assert!((mean / (wm * b * moved) - 1.0).abs() <= 1e-3);
    }
}

#[test]
fn a_large_misalignment_leaves_a_triangle_whose_slices_the_static_solve_loads() {
    // A linear gap T across the face much above the approach leaves a triangle of width
    // c = sqrt(2 F b / (k T)) (k the mesh stiffness, docs/MODEL.md 11.2): T = 250 um gives
    // c = b/4 here. The dynamic model runs and loads the slices the static solve loads
    // (time mean > 0 against period mean > 0 at 720 positions; the pattern's edge moves
    // over the period, so one slice either side may differ) and the width is the hand
    // triangle's to 15 % (the stiffness per unit width varies along the lines).
    let m = model(&slow(&["operating.misalignment_um=250"]));
    let d = face(&m, &steady(&m));
    let s = static_solve(&m);
    let loaded = |w: &[f64]| w.iter().filter(|x| **x > 0.0).count();
    let (nd, ns) = (loaded(&d.mean_n_per_m), loaded(&s.period_mean_n_per_m()));
    let sm = s.period_mean_n_per_m();
    let first_unloaded = |w: &[f64]| w.iter().position(|x| *x <= 0.0).unwrap();
    eprintln!("loaded slices: dynamic {nd}, static {ns}");
    assert!(nd.abs_diff(ns) <= 2, "dynamic {nd}, static {ns}");
    assert!(first_unloaded(&d.mean_n_per_m).abs_diff(first_unloaded(&sm)) <= 1);
    // The hand triangle at the mean stiffness per unit width k' = k/b and slope T/b:
    // c = b sqrt(2 F / (k T)); each position's pattern follows the stiffness there, so c
    // lies within the range of the static solve's instantaneous widths.
    let b = d.face_width_m;
    let n = d.positions_m.len() as f64;
    let k = lead(&m).slices.mean_stiffness_n_per_m();
    let c = b * (2.0 * tangential_force(&m) / (k * 250e-6)).sqrt();
    let widths: Vec<f64> = s
        .positions
        .iter()
        .map(|p| p.loaded_slices() as f64 * b / n)
        .collect();
    let lo = widths.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = widths.iter().copied().fold(0.0, f64::max);
    eprintln!("triangle {c} m; static widths [{lo}, {hi}] m");
    assert!(lo <= c && c <= hi, "{c} m outside [{lo}, {hi}] m");
    assert!(lo > 0.1 * b && hi < 0.5 * b, "a partial contact");
}

#[test]
fn the_mean_mesh_force_is_still_the_torque_over_the_base_radius() {
    // Statics of the steady state (every acceleration averages to zero): the pinion's
    // torque balance gives a mean mesh force T / r_b1 without friction, whatever the gaps.
    // Tolerance 1e-6 (the periodic solution's residual and Simpson's rule, as for the
    // unmodified pair in tests/helical_dynamics.rs), at the case's speed.
    let m = model(&[
        "gear.helix_angle_deg=15".into(),
        "friction.model=\"none\"".into(),
        "modification.crowning_um=8".into(),
        "operating.misalignment_um=6".into(),
    ]);
    let r = steady(&m);
    let ft = tangential_force(&m);
    let f = r.meshes[0].mean_mesh_force_n;
    assert!((f / ft - 1.0).abs() <= 1e-6, "{f} N against {ft} N");
}

#[test]
fn the_cli_writes_the_face_load_and_refuses_what_leaves_no_load() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let o = gearwear(&[
        "-q",
        "dynamics",
        "--set",
        "gear.helix_angle_deg=15",
        "--set",
        "modification.crowning_um=8",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (head, rows) = read_csv(&out.join("face_load.csv"));
    assert_eq!(head[0], "face_position_mm");
    assert!(head.contains(&"load_per_width_static_mean_n_per_mm".to_string()));
    assert_eq!(rows.len(), 400);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    for key in [
        "k_h_beta",
        "k_h_beta_instantaneous_max",
        "centre_of_pressure_mm",
    ] {
        assert!(s["face_load"][key].as_f64().unwrap().is_finite(), "{key}");
    }
    assert!(s["face_load"]["tilting_moment_nm"]["mean"].is_f64());
    assert!(s["face_load"]["static"]["k_h_beta"].is_f64());
    // What leaves the load on a single slice (or none): exit 2 naming the key and value,
    // `gearwear stiffness`'s check.
    let h = ["dynamics", "--set", "gear.helix_angle_deg=15", "--set"];
    let mut a = h.to_vec();
    a.extend([
        "operating.misalignment_um=900",
        "--set",
        "stiffness.slices=4",
    ]);
    rejected(&a, &["operating.misalignment_um", "900", "single slice"]);
    let mut a = h.to_vec();
    a.push("modification.crowning_um=2000");
    rejected(&a, &["modification.crowning_um", "2000"]);
    // Profile modifications stay refused on a helical pair; the lead keys stay refused by
    // the other studies (a helical case by every study but dynamics and stiffness).
    let mut a = h.to_vec();
    a.extend([
        "modification.tip_relief_um=10",
        "--set",
        "modification.tip_relief_length_mm=1",
    ]);
    rejected(&a, &["[modification]", "profile"]);
    rejected(
        &["wear", "--set", "modification.crowning_um=8"],
        &["modification.crowning_um"],
    );
}
