//! The tooth-resolved mesh checked against independent facts: identical teeth reduce to
//! the one-mesh-period solution, a pitch error shifts the static transmission error by
//! what the compatibility of the pairs predicts, a case without per-tooth inputs is
//! today's case bit for bit.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::hunting::{run_in_periods, solve_hunting};
use gearwear::dynamics::model::ContactFrame;
use gearwear::dynamics::steady::solve_steady_state;
use gearwear::study::Model;

/// The built-in case with `sets`, on the paper's contact model (`contact.path` =
/// "nominal"): the hand calculations here sum the pairs on the nominal path
/// (`pairs_in_contact`), and eq. (7) is defined there only. The corner contact beyond
/// the path is checked in tests/corner_contact.rs.
fn model(sets: &[&str]) -> Model {
    model_on("nominal", sets)
}

/// The built-in case with `sets` under the contact model `path` ("nominal", "extended").
fn model_on(path: &str, sets: &[&str]) -> Model {
    let sets: Vec<String> = std::iter::once(format!("contact.path={path}"))
        .chain(sets.iter().map(|s| s.to_string()))
        .collect();
    Model::from_case(&load_case("", &sets).expect("valid case")).expect("valid model")
}

fn zeros(n: usize) -> String {
    format!("[{}]", vec!["0"; n].join(","))
}

#[test]
fn identical_teeth_over_the_hunting_period_repeat_the_mesh_period_solution() {
    // Forced over 19 mesh periods, a pair of identical teeth must give the one-period
    // solution in every period. The hunting solver replays the one-period search's step
    // plan from the same periodic state, so the samples fall at the same phases; what
    // may differ is round-off of the absolute time (t0 = k T) and of the event
    // location: 1e-9 of each signal's range is the requirement.
    let m = model(&["numerics.steady_state_tolerance=1e-10"]);
    let gap = gearwear::dynamics::excitation::PairGap::none();
    let ext = ExternalError::none();
    let sys = m.system(&gap, &ext, m.roughness.rms_um(0.0));
    let one = solve_steady_state(&sys, &m.settings).unwrap();
    let hunt = solve_hunting(&sys, &m.settings, None, 19).unwrap();
    assert_eq!(hunt.excitation_periods, 19);
    let t = one.mesh_period_s;
    let n1 = one.signals.time_s.len() / m.settings.evaluated_mesh_periods;
    let (s1, sh) = (&one.signals, &hunt.signals);
    let range = |v: &[f64]| {
        v.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b))
            - v.iter().fold(f64::INFINITY, |a, b| a.min(*b))
    };
    let (dte_range, f_range) = (
        range(&s1.meshes[0].dte_m[..n1]),
        range(&s1.meshes[0].mesh_force_n[..n1]),
    );
    let mut worst: f64 = 0.0;
    let mut compared = 0;
    for (j, th) in sh.time_s.iter().enumerate() {
        let k = (th / t).floor();
        let local = th - k * t;
        // The same phase in the one-period record (every sample of a replayed plan).
        if let Some(i) = s1.time_s[..n1]
            .iter()
            .position(|x| (x - local).abs() < 1e-9 * t)
        {
            worst = worst
                .max((sh.meshes[0].dte_m[j] - s1.meshes[0].dte_m[i]).abs() / dte_range)
                .max((sh.meshes[0].mesh_force_n[j] - s1.meshes[0].mesh_force_n[i]).abs() / f_range);
            compared += 1;
        }
    }
    println!("identical teeth over 19 periods: {compared} samples, worst {worst:.2e}");
    assert!(compared > 19 * n1 * 9 / 10, "{compared} of {}", 19 * n1);
    assert!(worst < 1e-9, "{worst:e}");
    assert!(hunt.periodicity_error < 1e-9);
    // An excitation period of one mesh period: the run-in is capped at one period (it
    // panicked in `Ord::clamp(2, 1)` before), and the pass repeats the one-period
    // solution (same bound as above).
    assert_eq!(run_in_periods(&sys, t, m.settings.tolerance, 1), 1);
    let single = solve_hunting(&sys, &m.settings, None, 1).unwrap();
    let n = single.signals.time_s.len().min(n1);
    for i in 0..n {
        let j = s1.time_s[..n1]
            .iter()
            .position(|x| (x - single.signals.time_s[i]).abs() < 1e-9 * t);
        if let Some(j) = j {
            assert!(
                (single.signals.meshes[0].dte_m[i] - s1.meshes[0].dte_m[j]).abs()
                    < 1e-9 * dte_range
            );
        }
    }
}

/// A tiny deterministic generator (xorshift64*) for the random states below, in [-1, 1).
fn uniform(state: &mut u64) -> f64 {
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    let x = state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
    2.0 * (x as f64 / (1u64 << 53) as f64) - 1.0
}

/// The teeth of a case with every flank perfect, forced through the tooth-resolved path:
/// the inputs of a case with a pitch error, its position errors set to zero.
fn perfect_teeth(plain: &Model) -> gearwear::study::teeth::ToothInputs {
    let mut pitch = vec!["0"; 19];
    pitch[2] = "3";
    let m = model(&[
        "contact.load_sharing=stiffness",
        &format!("teeth.pitch_error_pinion_um=[{}]", pitch.join(",")),
    ]);
    assert_eq!(m.pair, plain.pair);
    let mut t = m.teeth.expect("a pitch error resolves the teeth");
    for f in t.pinion.iter_mut().chain(t.gear.iter_mut()) {
        f.position_m = 0.0;
    }
    t
}

#[test]
fn perfect_teeth_through_the_resolved_springs_are_the_plain_springs_state_by_state() {
    // On the paper's path and with corner contact (the default): a corner pair loads
    // each flank at its own point (the mate's flank where the corner touches it, the
    // corner's tooth at its tip), so each path must take each flank's wear there.
    for path in ["nominal", "extended"] {
        resolved_springs_are_the_plain_springs(path);
    }
}

fn resolved_springs_are_the_plain_springs(path: &str) {
    // The tooth-resolved springs (each pair's teeth from its mesh cycle) with every flank
    // perfect and a wear profile common to all teeth must be the plain springs with the
    // same load-sharing law ("stiffness") at any time and state. 2000 random states:
    // times over 3 mesh periods, deflections of -40..+40 um (pairs open and closed),
    // velocities of +-0.05 m/s or rad/s. The pair positions and stiffnesses come from the
    // same table (equal bits); the gap differs only in rounding: the plain path
    // interpolates the sum of the two flanks' wear, the resolved one each flank and adds,
    // a few ulp of the ~10 um wear (1e-20 m) against compressions of 1e-6 m: the mesh
    // force, loads and accelerations agree to 1e-12 of their scale (a 1 nm gap change
    // would move the force by 1e-4 of it).
    let plain = model_on(path, &["contact.load_sharing=stiffness"]);
    let mut resolved = model_on(path, &["contact.load_sharing=stiffness"]);
    resolved.teeth = Some(perfect_teeth(&plain));
    let n = plain.grid.len();
    let mut wear = gearwear::wear::WearState::new(n);
    for i in 0..n {
        let s = i as f64 / (n - 1) as f64;
        wear.pinion_m[i] = 10e-6 * (1.0 - s).powi(2) + 1e-6 * (7.0 * s).sin().abs();
        wear.gear_m[i] = 6e-6 * s * s + 0.5e-6 * (5.0 * s).cos().abs();
    }
    let tm = resolved.tooth_mesh(&wear).unwrap();
    assert_eq!(tm.periods(), 1);
    let gap = wear.pair_gap(&plain.grid);
    let ext = ExternalError::none();
    let rough = plain.roughness_for(&wear);
    let a = plain.system(&gap, &ext, rough);
    let b = resolved.system_for(&gap, &ext, rough, Some(&tm));
    let t_mesh = plain.pair.mesh_angle_rad() / plain.params.operating.pinion_speed_rad_s;
    // Scale of the generalised coordinates: 40 um of mesh deflection each.
    let grad = a.mesh_gradient(0);
    let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
    let (mut touching, mut open, mut corners_touching) = (0, 0, 0);
    for _ in 0..2000 {
        let t = 3.0 * t_mesh * 0.5 * (1.0 + uniform(&mut seed));
        let mut y = gearwear::dynamics::model::State::zeros(16);
        for i in 0..8 {
            let g = grad[i].abs().max(1e-3);
            y[i] = 20e-6 / g * uniform(&mut seed);
            y[8 + i] = 0.05 * uniform(&mut seed);
        }
        let frame = ContactFrame::NATURAL;
        let (q, v) = (&y.as_slice()[..8], &y.as_slice()[8..]);
        let (sa, sb) = (
            a.mesh(0).springs(frame.mesh(0), t, q, v),
            b.mesh(0).springs(frame.mesh(0), t, q, v),
        );
        assert_eq!(sa.n_pairs, sb.n_pairs);
        for k in 0..sa.n_pairs {
            assert_eq!(sa.rho1_m[k].to_bits(), sb.rho1_m[k].to_bits());
            assert_eq!(sa.corner[k], sb.corner[k]);
            let (ka, kb) = (sa.stiffness_n_per_m[k], sb.stiffness_n_per_m[k]);
            assert_eq!(ka, kb, "{path}: pair {k} (corner {})", sa.corner[k]);
            let dc = (sa.compression_m[k] - sb.compression_m[k]).abs();
            assert!(
                dc < 1e-19,
                "{path}: pair {k} (corner {}): {dc:e} m",
                sa.corner[k]
            );
            assert_eq!(sa.touching[k], sb.touching[k]);
            if sa.touching[k] {
                touching += 1;
                corners_touching += usize::from(sa.corner[k]);
            } else {
                open += 1;
            }
        }
        let scale_f = 1e-12 * (sa.force_unclipped_n.abs() + 1e3);
        assert!((sa.force_unclipped_n - sb.force_unclipped_n).abs() < scale_f);
        assert_eq!(sa.pushing, sb.pushing);
        let ((da, ma), (db, mb)) = (
            a.derivative(frame, t, y.as_slice()),
            b.derivative(frame, t, y.as_slice()),
        );
        let (ma, mb) = (ma[0], mb[0]);
        for k in 0..ma.n_pairs {
            assert!((ma.load_n[k] - mb.load_n[k]).abs() < scale_f);
            assert!(
                (ma.pressure_pa[k] - mb.pressure_pa[k]).abs()
                    < 1e-12 * ma.pressure_pa[k].abs().max(1.0)
            );
        }
        for i in 0..16 {
            let s = da[i].abs().max(db[i].abs()).max(1e-300);
            assert!(
                (da[i] - db[i]).abs() <= 1e-12 * s + 1e-300,
                "component {i}: {} vs {}",
                da[i],
                db[i]
            );
        }
    }
    println!(
        "{path}: 2000 states, {touching} touching ({corners_touching} corners) and {open} open pairs compared"
    );
    assert!(touching > 500 && open > 500);
    // With corner contact the random deflections close some corners' gaps.
    assert_eq!(corners_touching > 0, path == "extended");
}

#[test]
fn zero_per_tooth_inputs_are_the_paper_case_bit_for_bit() {
    let plain = model(&[]);
    let zero = model(&[
        &format!("teeth.pitch_error_pinion_um={}", zeros(19)),
        "teeth.runout_gear_um=0",
        "teeth.profile_slope_gear_um=[0]",
    ]);
    assert!(zero.teeth.is_none());
    let a = plain
        .dynamic(&plain.new_wear_state(), &ExternalError::none())
        .unwrap();
    let b = zero
        .dynamic(&zero.new_wear_state(), &ExternalError::none())
        .unwrap();
    assert_eq!(a.signals.meshes[0].dte_m, b.signals.meshes[0].dte_m);
    assert_eq!(a.end_state, b.end_state);
}

#[test]
fn a_pitch_error_shifts_the_static_transmission_error_as_compatibility_predicts() {
    // Quasi-static, no friction (so the mesh force is T / r_pb exactly), pinion tooth 3
    // 5 um proud. Hand calculation at every sample: the pairs in contact with their
    // stiffness k_i (the healthy table) and gaps g_i (-e cos(alpha) for tooth 3, 0
    // otherwise); sum k_i (d - g_i)+ = F solved pair by pair. With the proud tooth alone
    // in contact d shifts by -e cos(alpha); sharing with a healthy tooth it shifts by
    // -k_3 e cos(alpha) / (k_3 + k_other) while both touch.
    let e_um = 5.0;
    let mut pitch = vec!["0".to_string(); 19];
    pitch[3] = format!("{e_um}");
    let case = [
        "friction.model=none".to_string(),
        format!("teeth.pitch_error_pinion_um=[{}]", pitch.join(",")),
    ];
    let m = model(&[&case[0], &case[1]]);
    let r = m.quasi_static(&m.new_wear_state(), &ExternalError::none());
    assert_eq!(r.excitation_periods, 19);
    let e = e_um * 1e-6 * m.pair.pressure_angle_rad.cos();
    let f = m.case.operating.load_torque_nm / m.pair.pinion.base_radius_m;
    let omega = m.params.operating.pinion_speed_rad_s;
    let period = m.pair.mesh_angle_rad();
    let (mut checked_single, mut checked_double) = (0, 0);
    for ((t, dte), local) in r
        .signals
        .time_s
        .iter()
        .zip(&r.signals.meshes[0].dte_m)
        .zip(&r.signals.meshes[0].phase_rad)
    {
        // The sample's mesh cycle: whole periods before its phase within the period (a
        // sample on a period boundary opens the next cycle).
        let cycle = ((omega * t - local) / period).round() as i64;
        let phase = *local;
        let mut k = Vec::new();
        let mut g = Vec::new();
        for (pair_k, rho1) in m.pair.pairs_in_contact(phase) {
            let tooth = (cycle - pair_k as i64).rem_euclid(19);
            k.push(m.mesh.pair_stiffness_n_per_m(rho1));
            g.push(if tooth == 3 { -e } else { 0.0 });
        }
        // Hand solution: try all pairs touching, drop the one with the largest gap if
        // it would not touch.
        let all = (f + k.iter().zip(&g).map(|(k, g)| k * g).sum::<f64>()) / k.iter().sum::<f64>();
        let d = if g.iter().all(|gi| all > *gi) {
            all
        } else {
            let i = (0..k.len()).min_by(|a, b| g[*a].total_cmp(&g[*b])).unwrap();
            f / k[i] + g[i]
        };
        assert!((dte - d).abs() < 1e-9 * d.abs(), "t {t}: {dte} vs {d}");
        if g.iter().any(|x| *x != 0.0) {
            if k.len() == 1 {
                checked_single += 1;
            } else {
                checked_double += 1;
            }
        }
    }
    // Every engagement of tooth 3 was seen in single and in double contact.
    assert!(checked_single > 10 && checked_double > 10);
    // Each contact is tagged with its engagement within the excitation period, as the
    // dynamic recorder tags it: every engagement 0..19 and nothing else (the leaving pair
    // of cycle 0 is engagement 18, not -1).
    let mut seen = [false; 19];
    for s in &r.meshes[0].path {
        assert!((0..19).contains(&s.cycle), "cycle {}", s.cycle);
        seen[s.cycle as usize] = true;
    }
    assert!(seen.iter().all(|x| *x));
}

/// Peak-to-peak of a signal.
fn ptp(v: &[f64]) -> f64 {
    v.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b))
        - v.iter().fold(f64::INFINITY, |a, b| a.min(*b))
}

#[test]
fn tip_relief_sized_to_the_load_lowers_the_static_transmission_error_as_by_hand() {
    // Linear tip relief on both gears, amount C = the single-pair deflection at the pitch
    // point under the design load (F / k_pitch), length L = (eps - 1) p_b (the double
    // contact zone: a "long" relief ending at the highest point of single contact).
    // Hand calculation at every sample of the quasi-static response (no friction, so F
    // = T / r_pb): the pairs in contact with their healthy stiffness k_i and relief gaps
    // g_i = C (1 - u/L) inside a tip zone (u the roll distance from that gear's tip
    // contact), sum k_i (d - g_i)+ = F. With constant pair stiffness this relief would
    // make the static TE flat (d = F/k everywhere, Tavakoli & Houser 1986); with the
    // pair stiffness varying along the path a residual remains, and the fall of its
    // peak-to-peak is what the hand calculation gives.
    let base = model(&["friction.model=none", "wear.points_per_profile=2001"]);
    let p = &base.pair;
    let f = base.case.operating.load_torque_nm / p.pinion.base_radius_m;
    let c = f / base.mesh.pair_stiffness_n_per_m(p.rho_pitch_m);
    let l = (p.contact_ratio - 1.0) * p.base_pitch_m;
    let relief = [
        "friction.model=none".to_string(),
        "wear.points_per_profile=2001".to_string(),
        format!("modification.tip_relief_um={}", c * 1e6),
        format!("modification.tip_relief_length_mm={}", l * 1e3),
    ];
    let m = model(&relief.iter().map(String::as_str).collect::<Vec<_>>());
    let plain = base.quasi_static(&base.new_wear_state(), &ExternalError::none());
    let relieved = m.quasi_static(&m.new_wear_state(), &ExternalError::none());
    let omega = base.params.operating.pinion_speed_rad_s;
    let hand = |with_relief: bool, t: f64| -> f64 {
        let mut k = Vec::new();
        let mut g = Vec::new();
        for (_, rho1) in p.pairs_in_contact(omega * t) {
            k.push(base.mesh.pair_stiffness_n_per_m(rho1));
            let u_pinion = p.rho_end_m - rho1; // from the pinion's tip
            let u_gear = rho1 - p.rho_start_m; // from the gear's tip
            let zone = |u: f64| if u < l { c * (1.0 - u / l) } else { 0.0 };
            g.push(if with_relief {
                zone(u_pinion) + zone(u_gear)
            } else {
                0.0
            });
        }
        // Pairs close in the order of their gaps.
        let mut order: Vec<usize> = (0..k.len()).collect();
        order.sort_by(|a, b| g[*a].total_cmp(&g[*b]));
        let (mut ks, mut kg) = (0.0, 0.0);
        for (j, i) in order.iter().enumerate() {
            ks += k[*i];
            kg += k[*i] * g[*i];
            let d = (f + kg) / ks;
            if j + 1 == order.len() || d <= g[order[j + 1]] {
                return d;
            }
        }
        unreachable!()
    };
    let hand_plain: Vec<f64> = plain
        .signals
        .time_s
        .iter()
        .map(|t| hand(false, *t))
        .collect();
    let hand_relief: Vec<f64> = relieved
        .signals
        .time_s
        .iter()
        .map(|t| hand(true, *t))
        .collect();
    let (ptp_plain, ptp_relief) = (
        ptp(&plain.signals.meshes[0].dte_m),
        ptp(&relieved.signals.meshes[0].dte_m),
    );
    let (hand_fall, fall) = (ptp(&hand_plain) - ptp(&hand_relief), ptp_plain - ptp_relief);
    println!(
        "tip relief C = {:.3} um, L = {:.3} mm: static TE peak-to-peak {:.4} -> {:.4} um (fall {:.4} um; hand calculation {:.4} um)",
        c * 1e6,
        l * 1e3,
        ptp_plain * 1e6,
        ptp_relief * 1e6,
        fall * 1e6,
        hand_fall * 1e6
    );
    // The model samples the relief on the wear grid (2001 points, 4.5 um apart) and
    // interpolates linearly: the gap is exact at the grid points and off by at most
    // C h / L ~ 8e-3 um in the one interval where the relief starts; 1 % of the fall.
    assert!(
        (fall - hand_fall).abs() < 0.01 * hand_fall,
        "{fall:e} vs {hand_fall:e}"
    );
    // The relief removes most of the plain pair's peak-to-peak.
    assert!(ptp_relief < 0.5 * ptp_plain);
}

#[test]
fn under_one_load_sharing_law_a_vanishing_error_is_continuous_with_identical_teeth() {
    // A gear run-out of 1e-9 µm (eccentricity 5e-16 m) moves the static transmission
    // error by at most that much: 5e-10 of its ~1 µm range. Under the one law that
    // both cases can use ("stiffness") the tooth-resolved mesh must therefore give the
    // identical-teeth extremes to 1e-7 of the range (the rest is round-off of a
    // different summation order). "auto" is defined as that law for differing teeth
    // and as Pedrero's (paper eq. 7) for identical ones, so it must equal those
    // explicit choices bit for bit.
    let tiny = "teeth.runout_gear_um=1e-9";
    let qs = |m: &Model| m.quasi_static(&m.new_wear_state(), &ExternalError::none());
    let plain = qs(&model(&["contact.load_sharing=stiffness"]));
    let resolved = qs(&model(&["contact.load_sharing=stiffness", tiny]));
    assert_eq!(resolved.excitation_periods, 31);
    let extremes = |v: &[f64]| {
        (
            v.iter().fold(f64::INFINITY, |a, b| a.min(*b)),
            v.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b)),
        )
    };
    let (lo, hi) = extremes(&plain.signals.meshes[0].dte_m);
    let (rlo, rhi) = extremes(&resolved.signals.meshes[0].dte_m);
    let range = hi - lo;
    assert!(range > 1e-7, "STE range {range} m");
    assert!((rlo - lo).abs() < 1e-7 * range, "min {rlo} vs {lo}");
    assert!((rhi - hi).abs() < 1e-7 * range, "max {rhi} vs {hi}");
    let force = |r: &gearwear::dynamics::response::DynamicResponse| {
        extremes(&r.signals.meshes[0].pair_load_n[0])
    };
    let ((flo, fhi), (rflo, rfhi)) = (force(&plain), force(&resolved));
    assert!((rflo - flo).abs() < 1e-7 * (fhi - flo).max(1.0));
    assert!((rfhi - fhi).abs() < 1e-7 * (fhi - flo).max(1.0));

    let auto_resolved = qs(&model(&[tiny]));
    assert_eq!(
        auto_resolved.signals.meshes[0].dte_m,
        resolved.signals.meshes[0].dte_m
    );
    let auto_plain = qs(&model(&[]));
    let pedrero = qs(&model(&["contact.load_sharing=pedrero"]));
    assert_eq!(
        auto_plain.signals.meshes[0].dte_m,
        pedrero.signals.meshes[0].dte_m
    );
    assert_eq!(
        auto_plain.signals.meshes[0].pair_load_n,
        pedrero.signals.meshes[0].pair_load_n
    );
}

#[test]
fn a_gear_runout_shifts_the_static_transmission_error_by_half_the_runout_in_phase() {
    // Quasi-static, no friction (so the mesh force is T / r_pb exactly). A gear with
    // radial run-out F_r is an eccentricity e_c = F_r / 2 (a probe in the tooth spaces
    // reads e_c cos(theta), a range of 2 e_c) turning with the gear shaft; its component
    // along the line of action, e_c cos(Omega_g t - phi), pushes every pair together at
    // once. Hand solution at every sample: the pairs in contact with their stiffness k_i
    // (the healthy table) all close the same extra e_c cos(...), so
    // d = F / sum k_i - e_c cos(Omega_g t - phi), Omega_g = omega_p z1 / z2. This checks
    // the run-out's amplitude, sign, phase and speed against geometry, not against the
    // model's own run-out code; 1e-9 of d is round-off of the equilibrium solve.
    let f_r_um = 2.0;
    for phase_deg in [0.0_f64, 90.0] {
        let m = model(&[
            "friction.model=none",
            &format!("teeth.runout_gear_um={f_r_um}"),
            &format!("teeth.runout_gear_phase_deg={phase_deg}"),
        ]);
        let r = m.quasi_static(&m.new_wear_state(), &ExternalError::none());
        assert_eq!(r.excitation_periods, 31);
        let e_c = 0.5 * f_r_um * 1e-6;
        let f = m.case.operating.load_torque_nm / m.pair.pinion.base_radius_m;
        let omega_g = m.params.operating.pinion_speed_rad_s * 19.0 / 31.0;
        let phi = phase_deg.to_radians();
        let mut seen = (f64::INFINITY, f64::NEG_INFINITY);
        for ((t, dte), phase) in r
            .signals
            .time_s
            .iter()
            .zip(&r.signals.meshes[0].dte_m)
            .zip(&r.signals.meshes[0].phase_rad)
        {
            let k: f64 = m
                .pair
                .pairs_in_contact(*phase)
                .map(|(_, rho1)| m.mesh.pair_stiffness_n_per_m(rho1))
                .sum();
            let shift = e_c * (omega_g * t - phi).cos();
            let d = f / k - shift;
            assert!(
                (dte - d).abs() < 1e-9 * d.abs(),
                "phi {phase_deg}, t {t}: {dte} vs {d}"
            );
            seen = (seen.0.min(shift), seen.1.max(shift));
        }
        // The recorded gear revolution sweeps the whole cosine.
        assert!(seen.0 < -0.99 * e_c && seen.1 > 0.99 * e_c);
    }
}
