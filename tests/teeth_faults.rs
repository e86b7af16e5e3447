//! Tooth faults checked against independent facts: the cracked tooth's compliance
//! against the closed form of a uniform cantilever of the cracked section, its trend with
//! depth, a spall's reduced Hertz line, a broken tip's lost contact.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::stiffness::potential_energy::ToothBeam;
use gearwear::stiffness::tooth_faults::{crack_compliance_m_per_n, deg, Crack};
use gearwear::study::Model;

fn model(sets: &[&str]) -> Model {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    Model::from_case(&load_case("", &sets).expect("valid case")).expect("valid model")
}

/// Bending, shear and axial compliance (m/N) of a uniform cantilever of thickness t
/// (section t x b) and length l loaded at its end, at angle alpha_1 to the normal of its
/// axis, at a lever h_c from its axis (Timoshenko beam energy, the healthy tooth's
/// straight root part at rho = 0; Yang & Sun 1985):
/// int_0^l (c u - s h_c)^2 du = c^2 l^3 / 3 - c s h_c l^2 + s^2 h_c^2 l, over E t^3 b / 12.
fn uniform_cantilever(beam: &ToothBeam, t: f64, l: f64, hc: f64) -> f64 {
    let (s1, c1) = (-beam.half_base_angle_rad).sin_cos();
    let (e, g, b) = (
        beam.youngs_modulus_pa,
        beam.shear_modulus_pa,
        beam.face_width_m,
    );
    let bend = (c1 * c1 * l.powi(3) / 3.0 - c1 * s1 * hc * l * l + (s1 * hc).powi(2) * l)
        / (e * t.powi(3) * b / 12.0);
    let shear = 1.2 * c1 * c1 * l / (g * t * b);
    let axial = s1 * s1 * l / (e * t * b);
    bend + shear + axial
}

#[test]
fn a_root_crack_loads_the_tooth_as_a_cantilever_of_the_cracked_section() {
    // Contact at the base circle (rho = 0): the beam is the straight root part of
    // half-thickness h_r alone, and a crack of reach q sin(nu) leaves it h_r + h_q thick
    // (h_q = h_r - q sin nu) over its whole length while h_q stays above the tip's
    // half-thickness (the parallel limit line of Chen & Shao 2011). So the cracked
    // compliance is the closed form of that cantilever; the quadrature is exact for the
    // polynomial integrands to round-off (1e-12).
    let m = model(&[]);
    let beam = &m.mesh.tooth_beams()[1];
    let tip = m.pair.gear.tip_rho_m();
    let (h_r, y_root) = beam.root_section();
    let (hc, yc) = beam.involute_point(beam.contact_angle_rad(0.0));
    assert!((hc - h_r).abs() < 1e-15);
    let healthy = uniform_cantilever(beam, 2.0 * h_r, yc - y_root, hc);
    assert!((beam.compliance(0.0).total_m_per_n() / healthy - 1.0).abs() < 1e-12);
    for q_mm in [0.2, 0.5, 0.8] {
        let crack = Crack {
            depth_m: q_mm * 1e-3,
            angle_rad: deg(45.0),
            width_fraction: 1.0,
        };
        let h_q = h_r - crack.depth_m * crack.angle_rad.sin();
        let cracked = uniform_cantilever(beam, h_r + h_q, yc - y_root, hc);
        let model_value = healthy + crack_compliance_m_per_n(beam, tip, &crack, 0.0);
        assert!(
            (model_value / cracked - 1.0).abs() < 1e-12,
            "{q_mm} mm: {model_value:e} vs {cracked:e}"
        );
    }
}

#[test]
fn crack_stiffness_loss_starts_at_zero_and_grows_with_depth_most_near_the_tip() {
    // The published trend (Chen & Shao 2011; Mohammed et al. 2013): no loss without a
    // crack, a loss growing monotonically with the depth, and larger for contacts near
    // the tip (longer lever over the cracked root).
    let m = model(&[]);
    let beam = &m.mesh.tooth_beams()[0];
    let tip = m.pair.pinion.tip_rho_m();
    let q_max = Crack::max_depth_m(beam, deg(45.0));
    let loss = |q: f64, rho: f64| {
        let k0 = m.mesh.pair_stiffness_n_per_m(rho);
        let c = Crack {
            depth_m: q,
            angle_rad: deg(45.0),
            width_fraction: 1.0,
        };
        1.0 - 1.0 / (1.0 / k0 + crack_compliance_m_per_n(beam, tip, &c, rho)) / k0
    };
    let (root, pitch, tip_rho) = (m.pair.rho_start_m, m.pair.rho_pitch_m, m.pair.rho_end_m);
    assert_eq!(loss(0.0, pitch), 0.0);
    let mut last = [0.0; 3];
    for i in 1..20 {
        let q = q_max * i as f64 / 20.0;
        let now = [loss(q, root), loss(q, pitch), loss(q, tip_rho)];
        for j in 0..3 {
            assert!(now[j] > last[j], "depth {q}: {now:?} after {last:?}");
        }
        assert!(now[0] < now[1] && now[1] < now[2], "{now:?}");
        last = now;
    }
    println!(
        "pinion pair stiffness loss at the pitch point, 45 deg crack: 0.5 mm {:.1} %, 1 mm {:.1} %, 2 mm {:.1} %",
        100.0 * loss(0.5e-3, pitch),
        100.0 * loss(1e-3, pitch),
        100.0 * loss(2e-3, pitch)
    );
}

#[test]
fn a_broken_tip_carries_nothing_beyond_its_cut() {
    // Pinion tooth 4 loses 0.8 mm of its tip: its contacts at a pinion radius above
    // r_a - 0.8 mm carry no load, those below are untouched. On the nominal path: with
    // corner contact the cut's edge is the tooth's new tip corner, which does touch
    // beyond the shortened path (docs/MODEL.md section 4.2).
    let m = model(&[
        "contact.path=nominal",
        "friction.model=none",
        "fault.kind=broken_tip",
        "fault.gear=pinion",
        "fault.tooth=4",
        "fault.removed_height_mm=0.8",
    ]);
    let r = m.quasi_static(&m.new_wear_state(), &ExternalError::none());
    let cut = m.pair.pinion.tip_radius_m - 0.8e-3;
    let rho_cut = (cut * cut - m.pair.pinion.base_radius_m.powi(2)).sqrt();
    let (mut beyond, mut below) = (0, 0);
    for s in r.meshes[0]
        .path
        .iter()
        .filter(|s| s.cycle.rem_euclid(19) == 4)
    {
        if s.rho1_m > rho_cut + 1e-9 {
            assert_eq!(s.load_n, 0.0, "at rho1 {}", s.rho1_m);
            beyond += 1;
        } else if s.rho1_m < rho_cut - 1e-9 {
            assert!(s.load_n > 0.0);
            below += 1;
        }
    }
    assert!(beyond > 5 && below > 50, "{beyond} {below}");
}

/// Bounds (m/N) on the compliance a pit of depth `d` over a share `f` of the face adds to
/// the gear's tooth beam loaded at the gear's pitch point, the pit centred there and 1 mm
/// of roll long: the potential energy integrals (Yang & Sun 1985; section 2 of
/// docs/MODEL.md) of the change of the section over the heights y from the pit's lower
/// edge to the contact, where the full section 2h x b (A = 2 h b, I = (2h)^3 b / 12)
/// loses the rectangle f b x d at its loaded face: A' = A - f b d, its centroid moves by
/// u = -f b d (h - d/2) / A', and I' = I - f b d^3 / 12 - f b d (h - d/2)^2 - A' u^2
/// (parallel axes). Over the interval each integrand, M^2 (1/I' - 1/I) / E (bending, the
/// moment M = cos(a1) (y_c - y) - sin(a1) h_c per newton, linear in y, so its square is
/// largest at an end), 1.2 cos^2(a1) (1/A' - 1/A) / G (shear) and sin^2(a1) (1/A' - 1/A)
/// / E (axial), lies between its smallest and largest value, which fall at the ends of
/// the interval (h changes monotonically over it, and the losses grow as h falls); M^2
/// may vanish inside, so the lower bound keeps only shear and axial.
fn pit_section_compliance_bounds(m: &Model, beam: &ToothBeam, d: f64, f: f64) -> (f64, f64) {
    let rho_c = m.pair.rho_gear(m.pair.rho_pitch_m);
    let a1 = beam.contact_angle_rad(rho_c);
    let (s1, c1) = a1.sin_cos();
    let (hc, yc) = beam.involute_point(a1);
    let (h_lo, y_lo) = beam.involute_point(beam.contact_angle_rad(rho_c - 0.5e-3));
    let (e, g, b) = (
        beam.youngs_modulus_pa,
        beam.shear_modulus_pa,
        beam.face_width_m,
    );
    let losses = |h: f64| {
        let (a, i) = (2.0 * h * b, (2.0 * h).powi(3) * b / 12.0);
        let pit = f * b * d;
        let a_p = a - pit;
        let u = -pit * (h - 0.5 * d) / a_p;
        let i_p = i - f * b * d.powi(3) / 12.0 - pit * (h - 0.5 * d).powi(2) - a_p * u * u;
        (1.0 / i_p - 1.0 / i, 1.0 / a_p - 1.0 / a)
    };
    let (di_a, da_a) = losses(h_lo);
    let (di_b, da_b) = losses(hc);
    let moment = |y: f64| c1 * (yc - y) - s1 * hc;
    let m2_max = moment(y_lo).powi(2).max(moment(yc).powi(2));
    let len = yc - y_lo;
    let per_area = 1.2 * c1 * c1 / g + s1 * s1 / e;
    let lower = len * per_area * da_a.min(da_b);
    let upper = len * (m2_max * di_a.max(di_b) / e + per_area * da_a.max(da_b));
    (lower, upper)
}

#[test]
fn a_partial_spall_shortens_the_hertz_line_over_its_extent() {
    // A spall over half the face of gear tooth 7: with the contact inside it the Hertz
    // stiffness is that of half the line, k_h / 2, so the pair compliance gains 1/k_h
    // there, plus what the pit's rectangle takes from the tooth's section, which must lie
    // within the closed-form bounds of `pit_section_compliance_bounds`; outside its heights
    // nothing changes.
    let m = model(&[
        "fault.kind=spall",
        "fault.gear=gear",
        "fault.tooth=7",
        "fault.spall_position_mm=0",
        "fault.spall_length_mm=1",
        "fault.spall_depth_um=30",
        "fault.spall_width_fraction=0.5",
    ]);
    let tm = m.tooth_mesh(&m.new_wear_state()).unwrap();
    let kh = 1.0 / m.mesh.hertz_compliance_m_per_n();
    let at = |rho1: f64| {
        let k0 = m.mesh.pair_stiffness_n_per_m(rho1);
        let k = tm.pair(&m.mesh, 7, rho1).stiffness_n_per_m;
        1.0 / k - 1.0 / k0
    };
    let pitch = m.pair.rho_pitch_m;
    let inside = at(pitch);
    // What the pit adds beyond the Hertz line: the section's rectangle removed over the
    // heights from the pit's lower edge to the contact, bounded by closed forms.
    let (lo, hi) = pit_section_compliance_bounds(&m, &m.mesh.tooth_beams()[1], 30e-6, 0.5);
    let section = inside - 1.0 / kh;
    println!(
        "pit section compliance {section:e} in [{lo:e}, {hi:e}] m/N; Hertz part {:e}",
        1.0 / kh
    );
    assert!(
        section >= lo && section <= hi,
        "{section:e} not in [{lo:e}, {hi:e}]"
    );
    // Far below the spall on the gear's flank (its root side is the pinion's tip side).
    assert!(at(m.pair.rho_end_m - 0.2e-3).abs() < 1e-6 / kh);
    assert_eq!(tm.pair(&m.mesh, 7, pitch).width_loss, 0.5);
}
