//! `gearwear wear` on a planetary set (`study::planetary_wear`, docs/MODEL.md 12.9),
//! checked against independent facts:
//! - identical, equally spaced planets without errors wear alike (planet, sun-planet
//!   and ring-planet mesh), in-phase and sequentially phased;
//! - each member's wear volume equals the sum of its meshes' Archard integrals
//!   k (4 / pi) integral W |v_s| dt, computed here from the mesh forces, the pairs'
//!   stiffness and hand kinematics (not from the wear profiles);
//! - the tooth contacts per input revolution equal the hand kinematics of the set;
//! - at a very low speed the dynamic and the quasi-static study agree;
//! - what the study does not take is refused with exit 2, naming the key.

mod common;

use common::planetary::run_case;
use common::{gearwear, stderr};
use gearwear::config::load_case;
use gearwear::study::planetary_wear::{new_teeth, wear_gaps, PlanetaryWearModel};
use gearwear::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use gearwear::study::wear_loop::WearMode;
use std::f64::consts::PI;

/// The default set (24 / 30 / 84, four planets in phase, module 2, sun in at 60 N m and
/// the case's input speed, ring fixed, carrier out) with a short wear study.
const IN_PHASE: &str = "[planetary]\n[wear]\ntotal_cycles = 20000\nblock_cycles = 10000\n";

/// Five sequentially phased planets (26 / 29 / 84: z_s / N = 5.2), the rest as above.
const SEQUENTIAL: &str = "[planetary]\nplanets = 5\nteeth_sun = 26\nteeth_planet = 29\nteeth_ring = 84\n[wear]\ntotal_cycles = 20000\nblock_cycles = 10000\n";

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Each member's final (largest depth µm, volume mm^3) in `mode` from a summary.
fn members(s: &serde_json::Value, mode: &str) -> Vec<(String, f64, f64)> {
    s["planetary_wear"]["members"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| {
            let fin = &m["final"][mode];
            (
                m["member"].as_str().unwrap().to_string(),
                f(&fin["max_wear_um"]),
                f(&fin["volume_mm3"]),
            )
        })
        .collect()
}

#[test]
fn identical_planets_wear_alike() {
    for (case, planets, tol) in [
        // In phase (z_s / N an integer): every planet's equations are the same equations
        // at every instant, so they differ by round-off only: 1e-12 relative.
        (IN_PHASE, 4, 1e-12),
        // Sequentially phased: planet n's history is planet 1's shifted by a multiple of
        // 1/N mesh period. The quasi-static one is the same function of the shifted time
        // at the same instants (the default 200 samples per period are a multiple of 5):
        // round-off (measured 1e-14). The dynamic one adds the integrator's error, its
        // local tolerance 1e-5 of the deflection's scale, and wear goes as the load to
        // the power of about 1.5: 2e-5 (measured 5e-7).
        (SEQUENTIAL, 5, 2e-5),
    ] {
        let (_d, s) = run_case("wear", case);
        for mode in ["dynamic", "quasi_static"] {
            let m = members(&s, mode);
            let planet: Vec<&(String, f64, f64)> =
                m.iter().filter(|x| x.0.starts_with("planet_")).collect();
            assert_eq!(planet.len(), planets);
            for p in &planet {
                for (a, b, what) in [(p.1, planet[0].1, "depth"), (p.2, planet[0].2, "volume")] {
                    assert!(
                        (a / b - 1.0).abs() <= tol,
                        "{mode}: {} {what} {a} against planet 1's {b}",
                        p.0
                    );
                }
            }
        }
        // Every sun-planet (ring-planet) mesh alike as well: their own wear history.
        let dir = _d.path().join("out");
        for mode in ["dynamic", "quasi_static"] {
            let (head, rows) = common::read_csv(&dir.join(format!("mesh_history_{mode}.csv")));
            for kind in ["sun", "ring"] {
                for side in ["pinion", "gear"] {
                    let col = |p: usize| -> Vec<f64> {
                        let name = format!("max_wear_{side}_{kind}_planet_{p}_um");
                        let i = head.iter().position(|h| *h == name).unwrap();
                        rows.iter().map(|r| r[i].parse().unwrap()).collect()
                    };
                    let first = col(1);
                    for p in 2..=planets {
                        for (a, b) in col(p).iter().zip(&first) {
                            assert!(
                                (a - b).abs() <= tol * b.abs(),
                                "{mode} {kind} mesh {p} {side}: {a} against {b}"
                            );
                        }
                    }
                }
            }
            // The figures' data: every planet's flank profile (the last update, along
            // its mesh's path) and largest depth at every update alike, as above, with
            // the same tol taken of the profile's peak (the profile's ends near the
            // pitch point hold depths near zero, where a relative test is meaningless).
            for (fig, stem) in [("wear_profiles", ""), ("wear_history", "max_wear_")] {
                assert!(dir.join(format!("{fig}_{mode}.png")).exists());
                let (head, rows) = common::read_csv(&dir.join(format!("csv/{fig}_{mode}.csv")));
                for side in ["sun_side", "ring_side"] {
                    let col = |p: usize| -> Vec<f64> {
                        let name = format!("{stem}planet_{p}_{side}_um");
                        let i = head.iter().position(|h| *h == name).unwrap();
                        rows.iter().map(|r| r[i].parse().unwrap()).collect()
                    };
                    let first = col(1);
                    let peak = first.iter().fold(0.0_f64, |m, x| m.max(*x));
                    assert!(peak > 0.0, "{fig} {mode} {side}: no wear drawn");
                    for p in 2..=planets {
                        for (a, b) in col(p).iter().zip(&first) {
                            assert!(
                                (a - b).abs() <= tol * peak,
                                "{fig} {mode} planet {p} {side}"
                            );
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn tooth_contacts_per_revolution_follow_the_set_kinematics() {
    let (_d, s) = run_case("wear", SEQUENTIAL);
    let (n, zs, zp, zr) = (5.0, 26.0, 29.0, 84.0);
    // Sun in, ring fixed: the carrier turns z_s / (z_s + z_r) per sun revolution, so the
    // sun turns z_r / (z_s + z_r) relative to the carrier (z_r / z_s per carrier revolution)
    // and meets each of the N planets once per relative revolution; a planet turns
    // (z_s / z_p) times the sun's relative angle, each of its teeth meeting the sun (and the
    // ring, on its other flank) once per relative revolution; the ring turns -z_s/(z_s+z_r)
    // relative to the carrier and meets each planet once per relative revolution.
    let per_sun_rev = [
        ("sun", n * zr / (zs + zr)),
        ("planet_1", zs / zp * zr / (zs + zr)),
        ("ring", n * zs / (zs + zr)),
    ];
    let members = s["planetary_wear"]["members"].as_array().unwrap();
    for (name, want) in per_sun_rev {
        let m = members.iter().find(|m| m["member"] == name).unwrap();
        let got = f(&m["tooth_contacts_per_input_cycle"]);
        // Two ways of the same ratio of small integers: round-off only.
        assert!(
            (got / want - 1.0).abs() < 1e-12,
            "{name}: {got} against {want}"
        );
    }
    // Per carrier revolution a sun tooth meets N z_r / z_s planets (the brief's check).
    let sun = f(&members[0]["tooth_contacts_per_input_cycle"]);
    let carrier_per_sun = zs / (zs + zr);
    assert!((sun / carrier_per_sun / (n * zr / zs) - 1.0).abs() < 1e-12);
}

/// k (4 / pi) integral over one mesh period of sum_pairs W_i |v_s(rho_i)| dt for every
/// mesh of `model` under its response to new teeth, m^3 per mesh period on each flank:
/// Archard's law V = k W s in the single-point form the project uses (the wear of a point
/// is k p0 s, p0 2a = (4 / pi) W / b), from the mesh forces split over the pairs in
/// contact by their stiffness and the sliding speeds of hand kinematics.
fn archard_per_period(
    model: &PlanetaryWearModel,
    dynamic: bool,
    case: &gearwear::config::Case,
) -> Vec<f64> {
    let n = model.planets();
    let h = model
        .force_history(dynamic, &wear_gaps(model, &new_teeth(model)))
        .unwrap();
    let set = &model.dynamics.study.set;
    let (zs, zp, zr) = (
        set.teeth_sun() as f64,
        set.teeth_planet() as f64,
        set.teeth_ring() as f64,
    );
    // Ring fixed, sun in at f_s: relative to the carrier the sun turns at
    // f_s z_r / (z_s + z_r), the planet at (z_s / z_p) of that, the ring at (z_s / z_r).
    let w_s = 2.0 * PI * case.operating.input_speed_hz * zr / (zs + zr);
    let (w_p, w_r) = (w_s * zs / zp, w_s * zs / zr);
    let f_m = zs * w_s / (2.0 * PI);
    let dt = 1.0 / f_m / h.cycles.len() as f64;
    let (l_s, l_r) = (set.sun_planet.loa_length_m, set.ring_planet.loa_length_m);
    let gearwear::dynamics::planetary_dynamic::MeshStiffnessSource::Tables(meshes) =
        &model.dynamics.model.source
    else {
        panic!("tables expected")
    };
    let k_wear = case.wear.coefficient_m2_per_n;
    (0..2 * n)
        .map(|j| {
            let (p, ring) = (j % n, j >= n);
            let mut e = 0.0;
            for (c, forces) in h.cycles.iter().zip(&h.forces_n) {
                let pairs: Vec<(f64, f64)> = if ring {
                    meshes.ring_pairs_decided(p, *c, *c).collect()
                } else {
                    meshes.sun_pairs_decided(p, *c, *c).collect()
                };
                let k: f64 = pairs.iter().map(|x| x.1).sum();
                for (rho, kp) in pairs {
                    let slide = if ring {
                        (w_p * rho - w_r * (rho + l_r)).abs()
                    } else {
                        (w_s * rho - w_p * (l_s - rho)).abs()
                    };
                    e += forces[j] * kp / k * slide * dt;
                }
            }
            k_wear * 4.0 / PI * e
        })
        .collect()
}

#[test]
fn member_volume_is_the_sum_of_its_meshes_archard_integrals() {
    // One block from new teeth (no threshold cut): the wear at its end is the block times
    // the new teeth's rate.
    let text = format!("{SEQUENTIAL}threshold_um = 1000\n");
    let case = load_case(
        &text.replace("total_cycles = 20000", "total_cycles = 10000"),
        &[],
    )
    .unwrap();
    let model = PlanetaryWearModel::from_case(&case).unwrap();
    let n = model.planets();
    let set = &model.dynamics.study.set;
    let cycles = case.wear.total_cycles;
    for (mode, dynamic) in [(WearMode::QuasiStatic, false), (WearMode::Dynamic, true)] {
        let run = run_planetary_wear(&model, &case.wear, PlanetaryWearRun::new(mode), &mut |_| {
            Ok(())
        })
        .unwrap();
        assert_eq!(run.updates.len(), 2, "one block");
        let flanks = run.updates[1].flanks(&model);
        let archard = archard_per_period(&model, dynamic, &case);
        // Mesh periods per input (sun) revolution: z_s times the sun's turns relative to
        // the carrier.
        let periods = cycles * set.teeth_sun() as f64 * model.pinion_cycles_per_input[0];
        let volume = |member: &str| -> f64 {
            flanks
                .iter()
                .filter(|f| f.member == member)
                .map(|f| f.volume_m3)
                .sum()
        };
        let mut want = vec![(
            "sun".to_string(),
            archard[..n].iter().sum::<f64>() * periods,
        )];
        for p in 0..n {
            want.push((
                format!("planet_{}", p + 1),
                (archard[p] + archard[n + p]) * periods,
            ));
        }
        want.push(("ring".into(), archard[n..].iter().sum::<f64>() * periods));
        for (member, v) in want {
            let got = volume(&member);
            // Both sides see the load at the 200 samples of the period only. Where a pair
            // enters or leaves contact every pair's load jumps by about half the mesh force
            // between two samples; this sum puts each jump at a sample, the bookkeeping
            // interpolates across it along the path: each of the ~4 jumps per period errs
            // by up to a sample's share of it, 0.5 / 200 / 2 ~ 1.3e-3 of the integral,
            // so 5e-3 bounds them (measured 2.3e-3 dynamic, 5e-4 quasi-static; a 4x finer
            // profile grid does not lower it, so it is not the grid's error).
            assert!(
                (got / v - 1.0).abs() < 5e-3,
                "{mode:?} {member}: volume {got:e} m^3 against the Archard integrals' {v:e}"
            );
        }
    }
}

#[test]
fn quasi_static_and_dynamic_wear_agree_at_a_very_low_speed() {
    // At 0.01 Hz input the mesh frequency (0.18 Hz) is some 1e-4 of the set's lowest
    // natural frequency (about 1 kHz), so the dynamic forces differ from the static ones
    // by the inertia, (f_m / f_n)^2 ~ 3e-8, and the damping, 2 zeta f_m / f_n ~ 2e-5, except
    // in the ringing after each stiffness jump (a pair entering or leaving), which decays
    // in about 1 / (2 pi zeta f_n) = 3 ms, 6e-4 of the mesh period. The volumes integrate
    // over the whole period: 1e-4 (measured 1.3e-6; 3e-3 at 0.5 Hz, 2e-4 at 0.05 Hz, so
    // the agreement is the low-speed limit). The largest depth sits at a path end where
    // that ringing acts: 1e-3 (measured 1.3e-4).
    let text = IN_PHASE.replace("[wear]", "[operating]\ninput_speed_hz = 0.01\n[wear]");
    let (_d, s) = run_case("wear", &text);
    let (d, q) = (members(&s, "dynamic"), members(&s, "quasi_static"));
    for (a, b) in d.iter().zip(&q) {
        assert_eq!(a.0, b.0);
        for (x, y, tol, what) in [(a.1, b.1, 1e-3, "depth"), (a.2, b.2, 1e-4, "volume")] {
            assert!((x / y - 1.0).abs() < tol, "{}: {what} {x} against {y}", a.0);
        }
    }
}

#[test]
fn what_the_planetary_wear_study_does_not_take_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("case.toml");
    // Resuming is taken (tests/planetary_wear_resume.rs), and so is a load spectrum
    // (tests/planetary_duty.rs).
    let key = "wear.worn_geometry";
    std::fs::write(&case, format!("{IN_PHASE}worn_geometry = \"worn\"\n")).unwrap();
    let out = d.path().join("out");
    let mut a = vec!["wear", "-q", "--config", case.to_str().unwrap()];
    a.extend(["--out", out.to_str().unwrap()]);
    let o = gearwear(&a);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains(key), "{key}: {}", stderr(&o));
}

#[test]
fn a_uniform_wear_depth_loads_the_set_as_the_equal_pin_gap() {
    use gearwear::dynamics::excitation::PairGap;
    use gearwear::dynamics::planetary_dynamic::pin_error_gaps;
    // Second method: a tangential pin error e_t on planet 1 opens its sun and ring mesh by
    // e_t cos alpha (12.8, checked there against a hand calculation of the compliances).
    // Worn flanks of that uniform depth on planet 1's two meshes must load the set the
    // same: the stiffness-weighted gap of equal gaps is the gap itself.
    let case = load_case("[planetary]\n", &[]).unwrap();
    let model = PlanetaryWearModel::from_case(&case).unwrap();
    let n = model.planets();
    let e_t = 2e-6;
    let want = pin_error_gaps(e_t, 0.0, model.dynamics.model.alpha_rad);
    let gaps: Vec<PairGap> = (0..2 * n)
        .map(|j| {
            let (kind, p) = model.kind_of(j);
            let g = &model.grids[kind];
            let depth = if p == 0 { want[kind] } else { 0.0 };
            PairGap::new(g.rho_pinion_m[0], g.spacing_m, vec![depth; g.len()])
        })
        .collect();
    let mut worn = model.dynamics.model.clone();
    worn.set_wear_gaps(gaps);
    let mut pinned = model.dynamics.model.clone();
    let mut errors = vec![(0.0, 0.0); n];
    errors[0] = (e_t, 0.0);
    pinned.set_pin_errors(&errors);
    for c in [0.0, 0.13, 0.5, 0.77] {
        let a = worn.quasi_static_mesh_forces(c).unwrap();
        let b = pinned.quasi_static_mesh_forces(c).unwrap();
        // The same linear system but for the gaps' round-off (a weighted mean of equal
        // values): 1e-9 relative.
        for (x, y) in a.iter().zip(&b) {
            assert!(
                (x - y).abs() <= 1e-9 * y.abs(),
                "cycle {c}: {x} against {y}"
            );
        }
        // And the gap matters: planet 1 carries clearly less than planet 2 (shares 0.76
        // against 1.15 at 2 µm in `gearwear dynamics`).
        assert!(a[0] < 0.9 * a[1], "{a:?}");
    }
}

#[test]
fn a_uniform_depth_removes_the_volume_of_a_layer_on_the_involute() {
    use gearwear::study::planetary_wear::flank_volume_m3;
    // An involute's arc length from its base circle is rho^2 / (2 r_b): a layer of depth h
    // over the active profile from rho_s to rho_e on z teeth of width b has the volume
    // b z h (rho_e^2 - rho_s^2) / (2 r_b). The trapezoidal rule integrates the linear
    // integrand h rho / r_b exactly: round-off only.
    let (h, rb, b, z) = (1e-6, 0.02, 0.03, 17);
    let rho: Vec<f64> = (0..51).map(|i| 0.004 + 0.0002 * i as f64).collect();
    let got = flank_volume_m3(&vec![h; rho.len()], &rho, 0.0002, rb, b, z);
    let want = b * z as f64 * h * (rho[50].powi(2) - rho[0].powi(2)) / (2.0 * rb);
    assert!((got / want - 1.0).abs() < 1e-12, "{got} against {want}");
}
