//! Run-out sidebands against the first-order perturbation solution: the linear
//! time-periodic response to the run-out's modulated transmission error, solved by a
//! second method (exponential propagation of the frozen state matrix and a direct solve
//! of the periodic boundary value problem over the gear's revolution).

use gearwear::config::load_case;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::grid::period_nodes;
use gearwear::dynamics::model::{dof, State, NDOF};
use gearwear::dynamics::spectrum::amplitude_spectrum;
use gearwear::dynamics::summary::evaluated_periods;
use gearwear::study::Model;

mod common;
use common::linear::linear_periodic;

#[test]
fn runout_sidebands_match_the_first_order_perturbation_solution() {
    // Gear run-out F_r = 2 um (eccentricity 1 um), no friction, motor speed imposed:
    // with every pair touching the model is linear time-periodic, and the run-out is a
    // transmission error e(t) = e_c cos(Omega_g t) modulated by the mesh stiffness. The
    // solver's DTE spectrum over the gear's revolution (31 mesh periods, bins of the gear
    // frequency) must show the lines at f_mesh +- f_gear and at f_gear with the
    // amplitudes of the second method's solution within 2 %.
    let sets: Vec<String> = [
        "friction.model=none",
        "operating.speed_boundary=motor_speed_imposed",
        "teeth.runout_gear_um=2",
        "numerics.integration_tolerance=1e-7",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let m = Model::from_case(&load_case("", &sets).unwrap()).unwrap();
    let wear = m.new_wear_state();
    let r = m.dynamic(&wear, &ExternalError::none()).unwrap();
    let p = r.excitation_periods;
    assert_eq!(p, 31);
    assert!(
        r.signals.meshes[0].mesh_force_n.iter().all(|f| *f > 0.0),
        "contact must hold"
    );
    let periods = evaluated_periods(&r);
    let solver = amplitude_spectrum(
        &r.signals.time_s,
        &r.signals.meshes[0].dte_m,
        r.mesh_period_s,
        periods,
    );
    assert_eq!(solver.bins_per_harmonic, p);

    // The second method on the solver's node grid, every interval cut in 4 and in 8,
    // combined by Richardson extrapolation (second-order method).
    let teeth = m.tooth_mesh(&wear).unwrap();
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = m.system_for(&gap, &ext, m.roughness.rms_um(0.0), Some(&teeth));
    let one = period_nodes(&m.pair, m.params.operating.pinion_speed_rad_s, 200);
    let t_mesh = *one.last().unwrap();
    let mut grid = one.clone();
    for c in 1..p {
        grid.extend(one[1..].iter().map(|t| c as f64 * t_mesh + t));
    }
    let refine = |n: usize| -> Vec<f64> {
        grid.windows(2)
            .flat_map(|w| (0..n).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / n as f64))
            .chain([*grid.last().unwrap()])
            .collect()
    };
    let (c4, c8) = (
        linear_periodic(&sys, &refine(4), dof::PHI_M),
        linear_periodic(&sys, &refine(8), dof::PHI_M),
    );
    let g = sys.mesh_gradient(0);
    let dte = |y: &State| g.dot(&y.rows(0, NDOF));
    let t_nodes: Vec<f64> = grid[..grid.len() - 1].to_vec();
    let d_nodes: Vec<f64> = (0..t_nodes.len())
        .map(|k| (4.0 * dte(&c8[8 * k]) - dte(&c4[4 * k])) / 3.0)
        .collect();
    let second = amplitude_spectrum(&t_nodes, &d_nodes, t_mesh, p);
    // The pinion's y velocity (what an accelerometer on its bearing sees), same way.
    let vy = |y: &State| y[NDOF + dof::YP];
    let v_nodes: Vec<f64> = (0..t_nodes.len())
        .map(|k| (4.0 * vy(&c8[8 * k]) - vy(&c4[4 * k])) / 3.0)
        .collect();
    let v_solver: Vec<f64> = r.signals.velocity.iter().map(|v| v[dof::YP]).collect();
    let solver_v = amplitude_spectrum(&r.signals.time_s, &v_solver, r.mesh_period_s, periods);
    let second_v = amplitude_spectrum(&t_nodes, &v_nodes, t_mesh, p);
    for (signal, a_spec, b_spec, unit) in [
        ("DTE", &solver, &second, "m"),
        ("dy_p/dt", &solver_v, &second_v, "m/s"),
    ] {
        for (name, bin) in [
            ("f_gear", 1),
            ("f_mesh - f_gear", p - 1),
            ("f_mesh + f_gear", p + 1),
            ("2 f_mesh - f_gear", 2 * p - 1),
        ] {
            let (a, b) = (a_spec.amplitude[bin], b_spec.amplitude[bin]);
            println!(
                "{signal} at {name} ({:.2} Hz): solver {a:.5e} {unit}, perturbation solution {b:.5e} {unit}, {:+.3} %",
                a_spec.frequency_hz[bin],
                100.0 * (a / b - 1.0)
            );
            assert!(
                (a / b - 1.0).abs() < 0.02,
                "{signal} {name}: {a:e} vs {b:e}"
            );
        }
    }
}
