//! A train's steady state is recorded from two integrations joined at a node (the
//! search's splice, docs/MODEL.md "Steady state of a train"). Checked against a second
//! method: a plain forward integration of one base period from the orbit's state, with
//! its own steps and no search.

use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::grid::train_nodes;
use gearwear::dynamics::period::period_stepper;
use gearwear::dynamics::period_search::SteadyStateSettings;
use gearwear::dynamics::recorder::Recorder;
use gearwear::dynamics::steady::{solve_steady_state, solve_steady_state_from};

mod common;
use common::train::{model, TWO_STAGE};

#[test]
fn a_spliced_train_record_is_the_orbit_a_plain_integration_traces() {
    let m = model(TWO_STAGE, &["numerics.evaluated_mesh_periods=1"]);
    let t = m.train.as_ref().unwrap();
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = m.system(&gap, &ext, 0.2);
    let settings = SteadyStateSettings::from_case(&m.case.numerics);
    let r = solve_steady_state(&sys, &settings).unwrap();

    // The second method: one base period integrated from the response's end state (on
    // the orbit), recorded at the same grid nodes, in its own free steps.
    let nodes = train_nodes(&sys, settings.steps_per_mesh_period).unwrap();
    let period = *nodes.last().unwrap();
    let mut ps = period_stepper(&sys, nodes.clone(), settings.integration_tolerance).unwrap();
    let mut y = r.end_state.clone();
    let mut rec = Recorder::new(&sys, 1);
    ps.integrate(0.0, &mut y, &mut rec).unwrap();
    let (plain, _) = rec.window(period, 1, &r.end_state, &y);
    let plain_steps = ps.counts().accepted;

    // Both record a point at every node but the last, at bit-equal times (0 + node).
    let at_nodes = |times: &[f64]| -> Vec<usize> {
        nodes[..nodes.len() - 1]
            .iter()
            .map(|tn| {
                times
                    .iter()
                    .position(|t| t.to_bits() == tn.to_bits())
                    .unwrap()
            })
            .collect()
    };
    let (a, b) = (at_nodes(&r.signals.time_s), at_nodes(&plain.time_s));
    assert!(
        r.signals.time_s.windows(2).all(|w| w[0] < w[1]),
        "one time axis"
    );
    // Scale: the smaller static deflection and the force it takes (as the tolerance test
    // of tests/train.rs). The error control chooses the same steps from nearly the same
    // states, so the two differ by what their starts differ by: the orbit's state at the
    // splice node, which the search checks to its steady tolerance (1e-6 of the state
    // scales, of which this scale is one), carried along by the damped dynamics. 1e-5
    // leaves a factor 10 for the other state scales; a splice before the start's
    // difference had decayed errs by up to the warm start's 4e-2.
    let scale = t
        .stages
        .iter()
        .enumerate()
        .map(|(k, s)| {
            t.operating.meshes[k].gear_torque_nm
                / s.pair.gear.base_radius_m
                / s.mesh.mean_stiffness_n_per_m()
        })
        .fold(f64::INFINITY, f64::min);
    for (k, s) in t.stages.iter().enumerate() {
        let km = s.mesh.mean_stiffness_n_per_m();
        let (ra, pb) = (&r.signals.meshes[k], &plain.meshes[k]);
        let worst = a.iter().zip(&b).fold((0.0_f64, 0.0_f64), |(d, f), (i, j)| {
            (
                d.max((ra.dte_m[*i] - pb.dte_m[*j]).abs() / scale),
                f.max((ra.mesh_force_n[*i] - pb.mesh_force_n[*j]).abs() / (km * scale)),
            )
        });
        println!(
            "mesh {k}: DTE {:.2e}, force {:.2e} of the scale",
            worst.0, worst.1
        );
        assert!(worst.0 < 1e-5 && worst.1 < 1e-5, "mesh {k}: {worst:?}");
    }
    // The displacements run on without a jump (the motor-slip boundary of this case lets
    // the drivetrain's rigid rotation drift, which no force feels and no decay removes):
    // every sample follows from the one before by the step's cubic Hermite rule,
    // x1 - x0 = h (v0 + v1) / 2 + h^2 (a0 - a1) / 12 (exact for a cubic; a0, a1 the step's
    // own accelerations at its ends), to within the steps' local errors (1e-5 of the
    // state scales, which for an angle is at most its static twist, ~1e-4 rad: a bound of
    // 1e-8 rad; the largest found, 9e-9, is such a step). The split without the rigid
    // shift jumped by 7e-5 rad there: 1e-6 lies a factor 100 from both.
    let sig = &r.signals;
    let [a_start, a_end] = &sig.step_acceleration;
    let mut jump = 0.0_f64;
    for k in 0..sig.time_s.len() - 1 {
        let h = sig.time_s[k + 1] - sig.time_s[k];
        let (x0, x1) = (&sig.displacement[k], &sig.displacement[k + 1]);
        let (v0, v1) = (&sig.velocity[k], &sig.velocity[k + 1]);
        for i in 0..x0.len() {
            let hermite = h * (v0[i] + v1[i]) / 2.0 + h * h * (a_start[k][i] - a_end[k][i]) / 12.0;
            jump = jump.max((x1[i] - x0[i] - hermite).abs());
        }
    }
    println!("largest step residual of the displacements {jump:.2e}");
    assert!(jump < 1e-6, "{jump:e}");
    // The work: the search from the static equilibrium took one base period and the
    // splice's first W mesh periods (W = 8 of 31 here), recorded; without the splice it
    // takes a period, a period to confirm and a recorded one (3 periods' steps).
    println!("search {} steps, one plain period {plain_steps}", r.steps);
    assert!(
        (r.steps as f64) < 1.5 * plain_steps as f64,
        "{} steps against {plain_steps} for one period",
        r.steps
    );

    // Warm from the orbit itself: the first period is already periodic, so its record
    // (its two parts joined, nothing spliced) is kept: the plain integration's from the
    // same state, at every node to the steps' round-off.
    let w = solve_steady_state_from(&sys, &settings, Some(&r.end_state)).unwrap();
    assert!(w.periodicity_error < settings.tolerance);
    let c = at_nodes(&w.signals.time_s);
    assert!(
        w.signals.time_s.windows(2).all(|p| p[0] < p[1]),
        "one time axis"
    );
    for (k, s) in t.stages.iter().enumerate() {
        let km = s.mesh.mean_stiffness_n_per_m();
        let (wa, pb) = (&w.signals.meshes[k], &plain.meshes[k]);
        for (i, j) in c.iter().zip(&b) {
            assert!(
                (wa.dte_m[*i] - pb.dte_m[*j]).abs() < 1e-8 * scale,
                "mesh {k} node at {i}"
            );
            assert!((wa.mesh_force_n[*i] - pb.mesh_force_n[*j]).abs() < 1e-8 * km * scale);
        }
    }
}
