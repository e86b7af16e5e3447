//! Gear trains (`[[stage]]`): the assembled model of a two-stage reducer against facts
//! that do not come from the assembly: the single pair as the one-stage train, matrices
//! assembled by hand, statics, a second stage that cannot move.

use gearwear::dynamics::damped_modes::damped_modes;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::study::Model;
use gearwear::wear::WearState;
use nalgebra::{Complex, DMatrix};

mod common;
use common::train::{model, two_stage_by_hand, TWO_STAGE};

#[test]
fn the_one_stage_train_is_the_single_pair_bit_for_bit() {
    // A [[stage]] with no keys takes every key of [gear] and [dynamics]: the paper's pair
    // through the train's path (stages, operating point of the train, Elements::train).
    let single = model("", &[]);
    let train = model("[[stage]]\n", &[]);
    assert!(train.train.is_some() && single.train.is_none());
    let none = ExternalError::none();
    let a = single
        .dynamic(&WearState::new(single.grid.len()), &none)
        .unwrap();
    let b = train
        .dynamic(&WearState::new(train.grid.len()), &none)
        .unwrap();
    assert_eq!(a.end_state, b.end_state);
    assert_eq!(a.signals.time_s, b.signals.time_s);
    assert_eq!(a.signals.meshes[0].dte_m, b.signals.meshes[0].dte_m);
    assert_eq!(
        a.signals.meshes[0].mesh_force_n,
        b.signals.meshes[0].mesh_force_n
    );
    assert_eq!(a.meshes[0].mean_mesh_force_n, b.meshes[0].mean_mesh_force_n);
}

#[test]
fn damped_poles_of_a_two_stage_train_are_the_eigenvalues_of_matrices_assembled_by_hand() {
    // The nominal path: the hand matrices take each mesh's table mean stiffness, the
    // loaded mean there (with corner contact the loaded mean counts the corners the load
    // closes; tests/corner_contact.rs checks it by a second method).
    let m = model(TWO_STAGE, &["contact.path=nominal"]);
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = m.system(&gap, &ext, 0.2);
    let poles = damped_modes(&sys).modes;
    let (mass, k, c) = two_stage_by_hand(&m);
    // Every pole of the solver is a root of det(lambda^2 M + lambda C + K) of the hand
    // matrices: in mass-normalised form D~ = lambda^2 I + lambda C~ + K~, its smallest
    // singular value vanishes (1e-9 of the scale |lambda|^2 + |K~|, the round-off of a
    // pole refined to ~1e-14 being far below).
    let s: Vec<f64> = mass.iter().map(|x| 1.0 / x.sqrt()).collect();
    let kt = DMatrix::from_fn(14, 14, |i, j| s[i] * k[(i, j)] * s[j]);
    let ct = DMatrix::from_fn(14, 14, |i, j| s[i] * c[(i, j)] * s[j]);
    for p in &poles {
        let lam = Complex::new(p.real_per_s, p.imag_rad_per_s);
        let d = DMatrix::from_fn(14, 14, |i, j| {
            let diag = if i == j {
                lam * lam
            } else {
                Complex::new(0.0, 0.0)
            };
            diag + lam * ct[(i, j)] + Complex::new(kt[(i, j)], 0.0)
        });
        let sv = d.singular_values();
        let smallest = sv.iter().fold(f64::INFINITY, |a, b| a.min(*b));
        let scale = lam.norm_sqr() + kt.norm();
        assert!(
            smallest < 1e-9 * scale,
            "pole {lam}: sigma_min {smallest:e} of {scale:e}"
        );
    }
    // And none is missing: 14 coordinates, all free under motor slip, give 28
    // eigenvalues; the rigid rotation's zero is left out, the rest come in conjugate
    // pairs or as real poles, each reported once with Im >= 0.
    let reported: usize = poles
        .iter()
        .map(|p| if p.imag_rad_per_s > 0.0 { 2 } else { 1 })
        .sum();
    assert_eq!(reported, 28 - 1, "{} poles", poles.len());
}

#[test]
fn two_stage_statics_carry_each_shaft_torque_through_each_mesh() {
    // Friction off: the static equilibrium at the mean mesh stiffnesses (the solver's
    // cold start) must put on each mesh its shaft's torque over its base radius, and the
    // coupling at the motor must hold the output torque times the product of the ratios.
    let m = model(TWO_STAGE, &["friction.model=none"]);
    let t = m.train.as_ref().unwrap();
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = m.system(&gap, &ext, 0.2);
    let y = sys.static_equilibrium();
    let q = y.rows(0, 14);
    let t_out = t.operating.meshes[1].gear_torque_nm;
    let mut ratio = 1.0;
    for (k, stage) in t.stages.iter().enumerate() {
        let delta = sys.mesh_gradient(k).dot(&q);
        let force = stage.mesh.mean_stiffness_n_per_m() * delta;
        let expected = t.operating.meshes[k].gear_torque_nm / stage.pair.gear.base_radius_m;
        assert!(
            (force - expected).abs() < 1e-9 * expected,
            "mesh {k}: {force} vs {expected}"
        );
        ratio *= stage.pair.pinion.base_radius_m / stage.pair.gear.base_radius_m;
        // The pair alone at its own torque: its static TE, delta = F / k_mean.
        let alone = Model::from_case(&t.stages[k].case).unwrap();
        let y1 = alone.system(&gap, &ext, 0.2).static_equilibrium();
        let delta1 = alone
            .system(&gap, &ext, 0.2)
            .mesh_gradient(0)
            .dot(&y1.rows(0, 8));
        assert!(
            (delta - delta1).abs() < 1e-9 * delta1,
            "mesh {k}: {delta} vs alone {delta1}"
        );
    }
    let k_motor = m.case.dynamics.coupling_stiffness_motor_nm_per_rad;
    let t_in = k_motor * (q[8] - q[9]);
    assert!(
        (t_in - t_out * ratio).abs() < 1e-9 * t_in,
        "{t_in} vs {}",
        t_out * ratio
    );
    // The input torque of the case, 60 N m, is what the motor carries.
    assert!((t_in - 60.0).abs() < 1e-9 * 60.0);
}

#[test]
fn steady_means_of_a_two_stage_train_are_the_static_forces_and_both_meshes_sound() {
    // Over a periodic orbit every velocity returns, so the mean of every force balance is
    // the static one: friction off, each mesh's mean force is its shaft torque over its
    // base radius (to the solver's accuracy: Simpson means, periodicity 1e-9).
    let m = model(
        TWO_STAGE,
        &["friction.model=none", "numerics.evaluated_mesh_periods=31"],
    );
    let t = m.train.as_ref().unwrap();
    let r = m
        .dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .unwrap();
    for (k, stage) in t.stages.iter().enumerate() {
        let expected = t.operating.meshes[k].gear_torque_nm / stage.pair.gear.base_radius_m;
        let mean = r.meshes[k].mean_mesh_force_n;
        assert!(
            (mean - expected).abs() < 1e-6 * expected,
            "mesh {k}: {mean} vs {expected}"
        );
    }
    // The base period is one turn of the intermediate shaft: 31 periods of mesh 1, 23 of
    // mesh 2 (lcm of the mesh periods).
    let f1 = t.operating.meshes[0].mesh_frequency_hz;
    let f2 = t.operating.meshes[1].mesh_frequency_hz;
    assert!((r.mesh_period_s * f1 - 31.0).abs() < 1e-9);
    assert!((r.mesh_period_s * f2 - 23.0).abs() < 1e-9);
    // Spectrum of the intermediate shaft's gear y velocity (coordinate 3: y of gear 1,
    // which both meshes shake through the shaft's bearings... and its own mesh): lines at
    // both mesh frequencies, and the sum and difference tones the time-varying stiffness
    // of one mesh makes of the other's response, above the high-order combinations.
    let v = gearwear::dynamics::summary::velocity_signal(&r, 3);
    let spec = gearwear::dynamics::spectrum::amplitude_spectrum(&v, 1);
    let bin = |f: f64| spec.amplitude[(f * r.mesh_period_s).round() as usize];
    let (a1, a2, sum, diff) = (bin(f1), bin(f2), bin(f1 + f2), bin(f1 - f2));
    // Combination orders |a| + |b| of a f1 + b f2 at the bins 1-3 (1 = 3 f1 - 4 f2): 7
    // and more; the sum and difference tones are of order 2.
    let high = (1..=3).map(|b| spec.amplitude[b]).fold(0.0_f64, f64::max);
    println!("f1 {a1:e}, f2 {a2:e}, f1+f2 {sum:e}, f1-f2 {diff:e}, high-order {high:e}");
    assert!(a1 > 10.0 * high && a2 > 10.0 * high);
    assert!(
        sum > 3.0 * high && diff > 3.0 * high,
        "sum {sum:e}, diff {diff:e}, high {high:e}"
    );
}

#[test]
fn the_train_grid_holds_every_mesh_event_and_repeats_its_step_lengths() {
    // The base period (31 periods of mesh 1, 23 of mesh 2) on a grid of 200 intervals per
    // mesh-1 period: each mesh's pair changes (its period boundaries and (eps - 1) T
    // after each, eps its contact ratio, computed here from the stage's geometry) are
    // nodes, no interval exceeds T_1 / 200, and the interval length changes only at
    // events, where spreading 200 nodes over each mesh's own periods and merging gave a
    // new length at nearly every one of ~10 800 intervals. Events per mesh period: on the
    // nominal path at most 3 (a boundary, a pair change, a pitch passage); with corner
    // contact 2 more (a pair entering and leaving the reach of its corners).
    for (path, events_per_period) in [("nominal", 3), ("extended", 5)] {
        let m = model(TWO_STAGE, &[&format!("contact.path={path}")]);
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.2);
        let t = m.train.as_ref().unwrap();
        let nodes = gearwear::dynamics::grid::train_nodes(&sys, 200).unwrap();
        let f: Vec<f64> = t
            .operating
            .meshes
            .iter()
            .map(|p| p.mesh_frequency_hz)
            .collect();
        let period = 31.0 / f[0];
        assert_eq!(nodes[0], 0.0);
        assert!((nodes[nodes.len() - 1] - period).abs() < 1e-12 * period);
        let h_max = 1.0 / (200.0 * f[0]);
        let lengths: Vec<f64> = nodes.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(lengths
            .iter()
            .all(|h| *h > 0.0 && *h <= h_max * (1.0 + 1e-9)));
        for (k, stage) in t.stages.iter().enumerate() {
            let t_mesh = 1.0 / f[k];
            let frac = stage.pair.contact_ratio - stage.pair.contact_ratio.floor();
            let cycles = (period * f[k]).round() as usize;
            for j in 0..cycles {
                for event in [j as f64 * t_mesh, (j as f64 + frac) * t_mesh] {
                    let nearest = nodes
                        .iter()
                        .map(|n| (n - event).abs())
                        .fold(f64::INFINITY, f64::min);
                    assert!(
                        nearest < 1e-9 * t_mesh,
                        "{path}: mesh {k} event at {event} s"
                    );
                }
            }
        }
        let changes = lengths
            .windows(2)
            .filter(|w| (w[1] - w[0]).abs() > 1e-9 * w[1])
            .count();
        println!(
            "{path}: {} intervals, {changes} changes of length",
            lengths.len()
        );
        assert!(
            changes <= events_per_period * (31 + 23),
            "{path}: {changes} changes of length"
        );
    }
}

#[test]
fn the_train_steady_state_at_the_default_tolerance_is_the_tight_one_within_that_tolerance() {
    // A second solution of the same equations at 1e-7 local error (100 times tighter than
    // the default 1e-5, with its own steps): each mesh's DTE peak-to-peak and maximum
    // force agree within 3e-4 of the state scale (the smaller static deflection, and the
    // force it takes through that mesh's mean stiffness). The local tolerance is 1e-5 of
    // the scale per step; the error of the ringing after each mesh event adds up over a
    // few dozen steps before the damping takes it, so 30 local tolerances bound it (this
    // case errs by 1.2e-4 and 2.0e-4 in the DTE peak-to-peak, 6e-5 and 1e-5 in the
    // forces; the two-stage example by under 1e-4). The work: equal steps between events let one
    // factorisation serve several steps (fewer than one per three steps; before the
    // equal-step rule it was 0.86 per step).
    let run = |tol: &str| {
        let m = model(TWO_STAGE, &[tol, "numerics.evaluated_mesh_periods=1"]);
        let r = m
            .dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
            .unwrap();
        (m, r)
    };
    let (m, loose) = run("numerics.integration_tolerance=1e-5");
    let (_, tight) = run("numerics.integration_tolerance=1e-7");
    assert!(tight.steps > 2 * loose.steps);
    assert!(
        3 * loose.factorizations < loose.steps,
        "{} LU, {} steps",
        loose.factorizations,
        loose.steps
    );
    let t = m.train.as_ref().unwrap();
    // The state scale: each mesh's static deflection, its nominal force over its mean
    // stiffness; the smaller one (docs/MODEL.md, the integrator's error weights).
    let (delta, k_mean): (Vec<f64>, Vec<f64>) = t
        .stages
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let f = t.operating.meshes[k].gear_torque_nm / s.pair.gear.base_radius_m;
            let km = s.mesh.mean_stiffness_n_per_m();
            (f / km, km)
        })
        .unzip();
    let scale = delta.iter().copied().fold(f64::INFINITY, f64::min);
    let span = |v: &[f64]| {
        let max = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (max - v.iter().copied().fold(f64::INFINITY, f64::min), max)
    };
    for (k, km) in k_mean.iter().enumerate() {
        let (pp_l, _) = span(&loose.signals.meshes[k].dte_m);
        let (pp_t, _) = span(&tight.signals.meshes[k].dte_m);
        let (_, f_l) = span(&loose.signals.meshes[k].mesh_force_n);
        let (_, f_t) = span(&tight.signals.meshes[k].mesh_force_n);
        println!(
            "mesh {k}: DTE p-p {:.3e} of scale, max force {:.3e} of scale",
            (pp_l - pp_t) / scale,
            (f_l - f_t) / (km * scale)
        );
        assert!(
            (pp_l - pp_t).abs() < 3e-4 * scale,
            "mesh {k}: {pp_l} vs {pp_t} m"
        );
        assert!(
            (f_l - f_t).abs() < 3e-4 * km * scale,
            "mesh {k}: {f_l} vs {f_t} N"
        );
    }
}
