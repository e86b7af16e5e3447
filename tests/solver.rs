//! The steady-state solver checked against independent facts: convergence with the step,
//! a second method for the linear limit (exponential propagation and a direct solve of
//! the periodic boundary value problem), contact loss through a resonance, warm starts,
//! and load shares at the recorded samples.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::grid::period_nodes;
use gearwear::dynamics::model::{ContactFrame, State, NDOF};
use gearwear::dynamics::response::DynamicResponse;
use gearwear::dynamics::spectrum::time_rms;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;
use gearwear::wear::WearState;
mod common;
use common::linear::linear_periodic;

fn model(sets: &[String]) -> Model {
    Model::from_case(&load_case("", sets).expect("valid case")).expect("valid model")
}

fn sets(s: &[&str]) -> Vec<String> {
    s.iter().map(|x| x.to_string()).collect()
}

fn new_teeth(m: &Model) -> WearState {
    WearState::new(m.grid.len())
}

fn dynamic(m: &Model) -> DynamicResponse {
    m.dynamic(&new_teeth(m), &ExternalError::none())
        .expect("steady state")
}

/// Index of the recorded sample at time `t` (every grid node is one, with its exact time).
fn sample_at(r: &DynamicResponse, t: f64) -> usize {
    r.signals
        .time_s
        .iter()
        .position(|s| *s == t)
        .expect("a grid node")
}

/// Max DTE, DTE RMS, dynamic factor, RMS pinion y velocity.
fn headline(m: &Model, r: &DynamicResponse) -> [f64; 4] {
    let s = ResponseSummary::of(r);
    let window = r.mesh_period_s * m.settings.evaluated_mesh_periods as f64;
    [
        s.dte_max_m,
        time_rms(&r.signals.time_s, &r.signals.meshes[0].dte_m, window),
        s.dynamic_factor,
        s.velocity_y_pinion_rms_m_per_s,
    ]
}

#[test]
fn default_steps_agree_with_a_step_converged_solution_at_every_speed() {
    // The reference takes a 1e-4 times tighter local error tolerance: steps ~20 times
    // shorter where the error control sets them (third-order method), all grid nodes
    // kept. Measured, it agrees with the old fixed-step SDIRK3 at 16x its default steps
    // to 1e-4 wherever that one had converged (docs/MODEL.md). The requirement is 0.5 %;
    // the measured differences are below 1e-3.
    for f in ["0.5", "2", "5", "10", "30", "60", "150"] {
        let base = format!("operating.input_speed_hz={f}");
        let m = model(&sets(&[&base]));
        let fine = model(&sets(&[&base, "numerics.integration_tolerance=1e-9"]));
        let (a, b) = (headline(&m, &dynamic(&m)), headline(&fine, &dynamic(&fine)));
        for (name, (x, y)) in ["max DTE", "DTE RMS", "dynamic factor", "RMS vy"]
            .iter()
            .zip(a.iter().zip(&b))
        {
            let rel = (x - y).abs() / y.abs();
            assert!(rel < 5e-3, "{f} Hz, {name}: {x:e} vs {y:e} ({rel:.1e})");
        }
    }
}

#[test]
fn linear_limit_equals_a_direct_periodic_solution() {
    // Frictionless, light mesh damping, 20 Hz input: the mesh never opens, so the model is
    // linear and time-periodic. Second method: linear_periodic on the solver's grid and
    // on the grid with every interval halved, combined by Richardson extrapolation (the
    // exponential midpoint rule is second order: the combination removes the h^2 term).
    // The nominal path: with corner contact a corner touches only where the deflection
    // exceeds its gap, a unilateral contact the linear reference does not have.
    let m = model(&sets(&[
        "contact.path=nominal",
        "friction.model=none",
        "dynamics.mesh_damping_ratio=0.02",
        "operating.input_speed_hz=20",
        "operating.speed_boundary=motor_speed_imposed",
    ]));
    let r = dynamic(&m);
    assert!(
        ResponseSummary::of(&r).mesh_force_min_n > 0.0,
        "contact must hold"
    );
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = m.system(&gap, &ext, 0.2);
    let grid = period_nodes(&m.pair, m.params.operating.pinion_speed_rad_s, 200);
    // Every interval of the solver's grid cut into `n` equal ones.
    let refine = |n: usize| -> Vec<f64> {
        grid.windows(2)
            .flat_map(|w| (0..n).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / n as f64))
            .chain([*grid.last().unwrap()])
            .collect()
    };
    let held = gearwear::dynamics::model::dof::PHI_M;
    let (coarse_y, fine_y) = (
        linear_periodic(&sys, &refine(4), held),
        linear_periodic(&sys, &refine(8), held),
    );
    let g = sys.mesh_gradient(0);
    let dte = |y: &State| g.dot(&y.rows(0, NDOF));
    let vy = |y: &State| y[NDOF + gearwear::dynamics::model::dof::YP];
    let (mut err_dte, mut err_v, mut peak_dte, mut peak_v) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for (k, t) in grid.iter().enumerate().take(grid.len() - 1) {
        let (c, f) = (&coarse_y[4 * k], &fine_y[8 * k]);
        let ref_dte = (4.0 * dte(f) - dte(c)) / 3.0;
        let ref_v = (4.0 * vy(f) - vy(c)) / 3.0;
        let j = sample_at(&r, *t);
        err_dte = err_dte.max((r.signals.meshes[0].dte_m[j] - ref_dte).abs());
        err_v =
            err_v.max((r.signals.velocity[j][gearwear::dynamics::model::dof::YP] - ref_v).abs());
        peak_dte = peak_dte.max(ref_dte.abs());
        peak_v = peak_v.max(ref_v.abs());
    }
    println!(
        "linear limit: DTE {:.2e}, vy {:.2e} of the peak",
        err_dte / peak_dte,
        err_v / peak_v
    );
    // 1e-4 of the peak, the requirement; measured 9e-6 (DTE) and 2.5e-5 (velocity), and
    // 1.5e-6 with a 1e-4 times tighter integration tolerance: the two methods agree to
    // the accuracy of the reference.
    assert!(err_dte < 1e-4 * peak_dte, "DTE {err_dte:e} of {peak_dte:e}");
    assert!(err_v < 1e-4 * peak_v, "vy {err_v:e} of {peak_v:e}");
}

/// Mesh force the linear model (every pair pushing, F = k(t) delta + c_m d delta/dt, N)
/// predicts at the solver's grid nodes, from its periodic solution; with the node times.
fn linear_forces(m: &Model, held: usize) -> Vec<(f64, f64)> {
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = m.system(&gap, &ext, 0.2);
    let grid = period_nodes(&m.pair, m.params.operating.pinion_speed_rad_s, 200);
    let ys = linear_periodic(&sys, &grid, held);
    let g = sys.mesh_gradient(0);
    grid.iter()
        .zip(&ys)
        .take(grid.len() - 1)
        .map(|(t, y)| {
            let (q, v) = (y.rows(0, NDOF), y.rows(NDOF, NDOF));
            // The pairs just after the node, as the solver records a mesh event.
            let frame = ContactFrame::decided_at(t + 1e-9 * grid[grid.len() - 1]);
            let k = sys
                .mesh(0)
                .mesh_state(frame.mesh(0), *t, q.as_slice(), v.as_slice())
                .stiffness_total_n_per_m;
            (
                *t,
                k * g.dot(&q) + sys.mesh(0).mesh_damping_n_s_per_m * g.dot(&v),
            )
        })
        .collect()
}

#[test]
fn contact_loss_resonance_is_solved_at_every_point() {
    // brake_speed_imposed puts the damped mesh pole near 1140 Hz, crossed by the mesh
    // frequency (19 x input) near 55-60 Hz: a softening resonance where the teeth
    // separate. Every point of a 0.5 Hz sweep must have a steady state. Where the linear
    // model (second method above, frictionless) needs a pulling mesh (its force below
    // -5 % of the load), the mesh must open: minimum force 0; where it stays above +5 %,
    // the mesh stays closed and the frictionless solution is the linear one. The nominal
    // path, as the linear reference (above) assumes.
    let held = gearwear::dynamics::model::dof::PHI_B;
    let (mut opened, mut closed, mut worst) = (0, 0, 0.0_f64);
    for i in 0..=52 {
        let f = 40.0 + 0.5 * i as f64;
        for friction in ["xu2007", "none"] {
            let m = model(&sets(&[
                &format!("operating.input_speed_hz={f}"),
                "operating.speed_boundary=brake_speed_imposed",
                &format!("friction.model={friction}"),
                "contact.path=nominal",
            ]));
            let r = m
                .dynamic(&new_teeth(&m), &ExternalError::none())
                .unwrap_or_else(|e| panic!("{f} Hz, friction {friction}: {e}"));
            let s = ResponseSummary::of(&r);
            let load = m.params.operating.brake_torque_nm / m.pair.gear.base_radius_m;
            if friction == "none" {
                let lin = linear_forces(&m, held);
                let lin_min = lin.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
                if lin_min < -0.05 * load {
                    assert_eq!(s.mesh_force_min_n, 0.0, "{f} Hz: the mesh must open");
                    opened += 1;
                } else if lin_min > 0.05 * load {
                    // The periodic solution is the linear one, at every grid node (measured:
                    // within 1e-5 of the load).
                    for (t, f_lin) in &lin {
                        let j = sample_at(&r, *t);
                        let f_dyn = r.signals.meshes[0].mesh_force_n[j];
                        worst = worst.max((f_dyn - f_lin).abs() / load);
                        assert!(
                            (f_dyn - f_lin).abs() < 1e-4 * load,
                            "{f} Hz, t = {t}: force {f_dyn} vs linear {f_lin}"
                        );
                    }
                    closed += 1;
                }
            }
        }
    }
    println!("contact loss sweep: {opened} opened, {closed} closed, worst {worst:.1e} of the load");
    // The sweep crosses the resonance: both kinds of points occur.
    assert!(
        opened >= 5 && closed >= 20,
        "opened {opened}, closed {closed}"
    );
}

#[test]
fn every_speed_boundary_and_friction_has_a_steady_state_from_5_to_400_hz() {
    // A coarse grid (25 Hz); a 2.5 Hz grid over the same range and a 0.5 Hz grid over
    // 40-66 Hz were checked the same way by hand (docs/MODEL.md).
    for boundary in ["motor_slip", "motor_speed_imposed", "brake_speed_imposed"] {
        for friction in ["xu2007", "none"] {
            for i in 0..=16 {
                let f = 5.0 + 25.0 * i as f64;
                let f = f.min(400.0);
                let m = model(&sets(&[
                    &format!("operating.input_speed_hz={f}"),
                    &format!("operating.speed_boundary={boundary}"),
                    &format!("friction.model={friction}"),
                ]));
                let r = m.dynamic(&new_teeth(&m), &ExternalError::none());
                let r = r.unwrap_or_else(|e| panic!("{boundary}, {friction}, {f} Hz: {e}"));
                // Periodic to the steady-state tolerance over the recorded period.
                assert!(
                    r.periodicity_error < 1e-5,
                    "{boundary} {friction} {f}: {r:?}",
                    r = r.periodicity_error
                );
            }
        }
    }
}

#[test]
fn warm_start_from_a_periodic_state_converges_at_once() {
    // Both contact models: the shooting starts from the monodromy at the mean loaded
    // mesh stiffness (with corner contact the corners the load closes count).
    for path in ["nominal", "extended"] {
        warm_start_converges_at_once(&model(&sets(&[&format!("contact.path={path}")])));
    }
}

/// |a - b| within `rel` of b for the headline numbers that are of the order of their
/// state's scale (DTE max, DTE RMS, dynamic factor), and within 1e-5 of the velocity scale
/// for the pinion's lateral velocity RMS: two periodic solutions integrated with other step
/// sequences differ by the integrator's local error, 1e-5 of the state scales
/// (`numerics.integration_tolerance`), and that velocity is only about 5 % of its scale.
fn same_headline(m: &Model, a: &DynamicResponse, b: &DynamicResponse, rel: f64) {
    let scales = gearwear::dynamics::state_scales::state_scales(&m.system(
        &PairGap::none(),
        &ExternalError::none(),
        0.0,
    ));
    let v_scale = scales[NDOF + gearwear::dynamics::model::dof::YP];
    let (ha, hb) = (headline(m, a), headline(m, b));
    for i in 0..3 {
        assert!(
            (ha[i] - hb[i]).abs() < rel * hb[i].abs(),
            "{i}: {} vs {}",
            ha[i],
            hb[i]
        );
    }
    assert!(
        (ha[3] - hb[3]).abs() < 1e-5 * v_scale,
        "{} vs {} (scale {v_scale})",
        ha[3],
        hb[3]
    );
}

fn warm_start_converges_at_once(m: &Model) {
    let none = ExternalError::none();
    let cold = dynamic(m);
    // From the orbit itself: one period shows it periodic.
    let warm = m
        .dynamic_from(&new_teeth(m), &none, Some(&cold.end_state))
        .unwrap();
    assert!(
        warm.periods_to_converge <= 2,
        "{}",
        warm.periods_to_converge
    );
    assert!(cold.periods_to_converge > warm.periods_to_converge);
    // The same response (see `same_headline` for the tolerances).
    same_headline(m, &cold, &warm, 1e-5);
    // A wear update (the gap changes by the 0.5 um threshold): from the previous orbit it
    // takes at most 3 periods, and the same response as from the static equilibrium.
    let inc = gearwear::wear::per_cycle_wear(
        &m.grid,
        &cold.meshes[0].path,
        m.case.wear.coefficient_m2_per_n,
        m.pair.pinion.teeth as f64 / m.pair.gear.teeth as f64,
    );
    let mut worn = new_teeth(m);
    worn.advance(&inc, 0.5e-6 / inc.max_m());
    let from_cold = m.dynamic(&worn, &none).unwrap();
    let from_warm = m.dynamic_from(&worn, &none, Some(&cold.end_state)).unwrap();
    assert!(
        from_warm.periods_to_converge <= 3,
        "{}",
        from_warm.periods_to_converge
    );
    same_headline(m, &from_cold, &from_warm, 1e-5);
}

/// Largest |sum of the pair loads / mesh force - 1| over the samples that carry load.
fn share_sum_error(r: &DynamicResponse) -> f64 {
    let s = &r.signals;
    (0..s.time_s.len())
        .filter(|k| s.meshes[0].mesh_force_n[*k] > 0.0)
        .map(|k| {
            ((s.meshes[0].pair_load_n[0][k] + s.meshes[0].pair_load_n[1][k])
                / s.meshes[0].mesh_force_n[k]
                - 1.0)
                .abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn load_shares_sum_to_one_at_every_recorded_sample() {
    // The samples include every mesh event (pair entry and exit), where the pairs' share
    // of eq. (7) changes branch; the paper's contact ratio is below 2, so at most two
    // pairs carry load and the two recorded pair loads hold it all. Round-off only.
    // The nominal path: eq. (7) is defined there only, and with corner contact the
    // recorded pair loads are the pairs on the path, not the corners beyond it.
    for law in ["pedrero", "stiffness"] {
        let m = model(&sets(&[
            &format!("contact.load_sharing={law}"),
            "contact.path=nominal",
        ]));
        let none = ExternalError::none();
        assert!(share_sum_error(&dynamic(&m)) < 1e-12, "{law} dynamic");
        assert!(
            share_sum_error(&m.quasi_static(&new_teeth(&m), &none)) < 1e-12,
            "{law} quasi-static"
        );
    }
}
