//! The quasi-static wear of a helical pair with lead gaps (docs/MODEL.md 11.3): its load
//! sharing over the face slices takes the lead gaps as the dynamic model does
//! (`LineGapTable::force` in `dynamics::quasi_static`), checked against a deflection solved
//! here by hand for a linear gap on slices of equal stiffness, and against the static exact
//! solve of `gearwear stiffness` (`stiffness::face_load`, a second method).

use gearwear::config::load_case;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::quasi_static::equilibrium;
use gearwear::stiffness::face_load::FaceLoad;
use gearwear::study::face_load_dynamic::DynamicFaceLoad;
use gearwear::study::Model;

fn helical(s: &[&str]) -> Model {
    let s: Vec<String> = s.iter().map(|x| x.to_string()).collect();
    Model::helical_from_case(&load_case("", &s).expect("valid case")).expect("helical")
}

#[test]
fn a_linear_lead_gap_on_equal_slices_gives_the_hand_solved_deflection() {
    // beta = 0 cut into N = 10 slices: every slice of a contact line sits at the same
    // place on the path, so each carries k = K_l / N (K_l the line's stiffness with every
    // slice touching, read from the line table: an input here, not a result). A
    // misalignment f_ma = 4 µm in the plane of action gives slice j at y_j = (j + 1/2) b/N
    // the gap f_ma y_j / b, shifted to start at 0: G_j = f_ma j / N (docs/MODEL.md 11.2).
    // While every slice touches (delta >= G_max = f_ma (N - 1)/N, checked), the lines carry
    //   F = sum_l sum_j (K_l / N)(delta - G_j) = K (delta - G_mean),  K = sum_l K_l,
    // so delta = F / K + f_ma (N - 1) / (2N), and line l carries K_l F / K. Both to 1e-9
    // (the exact piecewise-linear solve against this closed form: round-off). The old
    // quasi-static solve, without the lead gaps, gave delta = F / K (1.8 µm short).
    let (n, f_ma) = (10usize, 4e-6);
    let m = helical(&[
        "gear.helix_angle_deg=0",
        "stiffness.slices=10",
        "operating.misalignment_um=4",
    ]);
    let table = m.contact.lead_gaps().expect("lead gaps");
    let (gap, none) = (PairGap::none(), ExternalError::none());
    let sys = m.system(&gap, &none, 0.0);
    let g_mean = f_ma * (n as f64 - 1.0) / (2.0 * n as f64);
    let g_max = f_ma * (n as f64 - 1.0) / n as f64;
    let period = m.pair.mesh_angle_rad();
    for i in 0..40 {
        let phase = period * (i as f64 + 0.25) / 40.0;
        let ms = equilibrium(&sys, 0, phase);
        let lines = &ms.rho1_m[..ms.n_pairs];
        let k_l: Vec<f64> = lines
            .iter()
            .map(|r| table.force(*r, 1.0, false).1)
            .collect();
        let k: f64 = k_l.iter().sum();
        let delta = ms.force_n / k + g_mean;
        assert!(delta >= g_max, "phase {phase}: not every slice touches");
        assert!(
            (ms.deflection_m - delta).abs() <= 1e-9 * delta,
            "phase {phase}: deflection {:e} m, by hand {delta:e} m",
            ms.deflection_m
        );
        let mut sum = 0.0;
        for (l, kl) in k_l.iter().enumerate() {
            let slices: f64 = (0..n)
                .map(|j| kl / n as f64 * (delta - f_ma * j as f64 / n as f64))
                .sum();
            sum += slices;
            assert!(
                (ms.load_n[l] - slices).abs() <= 1e-9 * ms.force_n,
                "phase {phase}, line {l}: {} N, its slices by hand {slices} N",
                ms.load_n[l]
            );
        }
        assert!((sum - ms.force_n).abs() <= 1e-9 * ms.force_n);
    }
}

#[test]
fn the_quasi_static_face_load_is_the_static_solve() {
    // Second method: `gearwear stiffness`'s exact solve of sum_j K_j (delta - g_j)+ = F at
    // 720 positions (slice by slice, from the slice splines), against the slice loads the
    // quasi-static wear takes (the mesh deflection from the line table with the lead gaps,
    // the slices' springs shared to the mesh force, `study::face_load_dynamic` on the
    // quasi-static response). No friction, so the mesh force is T / r_b1 in both. The
    // differences: the line table's linear interpolation in rho between samples at the
    // slice spacing (a few 1e-3 of w_m at most over 400 slices, as in
    // tests/helical_lead_dynamics.rs), and the trapezoid mean over the response's samples
    // of one period against 720 uniform positions. Allowed as there: 1 % of w_m per slice,
    // 0.5 % on K_Hbeta. The old solve (the deflection without the lead gaps, the slices'
    // forces then scaled to the mesh force) piled the load on the slices of smallest gap.
    for gaps in [
        &["modification.crowning_um=8"][..],
        &["operating.misalignment_um=10"],
        &[
            "modification.end_relief_um=10",
            "modification.end_relief_length_mm=4",
            "modification.end_relief_shape=\"parabolic\"",
        ],
    ] {
        let mut s = vec!["gear.helix_angle_deg=15", "friction.model=\"none\""];
        s.extend(gaps);
        let m = helical(&s);
        let none = ExternalError::none();
        let r = m.quasi_static(&m.new_wear_state(), &none);
        let d = DynamicFaceLoad::of(&m, &r, &none).expect("a face load");
        let lead = m.helical.as_ref().unwrap().lead.as_ref().unwrap();
        let force = r.meshes[0].mean_mesh_force_n;
        let st = FaceLoad::solve(&lead.slices, &lead.gap, force, 720).unwrap();
        let wm = st.mean_load_per_width_n_per_m();
        let worst = d
            .mean_n_per_m
            .iter()
            .zip(&st.period_mean_n_per_m())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0_f64, f64::max);
        eprintln!(
            "{gaps:?}: worst {:.2e} of w_m, K_Hbeta {} / {}",
            worst / wm,
            d.k_h_beta(),
            st.k_h_beta()
        );
        assert!(worst <= 0.01 * wm, "{gaps:?}: {worst} N/m of {wm}");
        assert!(
            (d.k_h_beta() / st.k_h_beta() - 1.0).abs() <= 5e-3,
            "{gaps:?}: K_Hbeta {} against {}",
            d.k_h_beta(),
            st.k_h_beta()
        );
    }
}
