//! Run-out sidebands against the first-order perturbation solution: the linear
//! time-periodic response to the run-out's modulated transmission error, solved by a
//! second method (exponential propagation of the frozen state matrix and a direct solve
//! of the periodic boundary value problem over the gear's revolution), its lines the exact
//! Fourier coefficients of that solution.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::fourier::HermitePeriod;
use gearwear::dynamics::grid::period_nodes;
use gearwear::dynamics::model::{dof, GearSystem, State, NDOF};
use gearwear::dynamics::spectrum::amplitude_spectrum;
use gearwear::dynamics::summary::{dte_signal, evaluated_periods, velocity_signal};
use gearwear::study::Model;

mod common;
use common::linear::linear_periodic_with_slopes;

/// Line amplitudes 0..=lines of the second method's periodic solution on `grid` (one
/// excitation period) of the quantity `of` (a linear function of the state, so its slope
/// is `of` of the state's derivative): the exact Fourier coefficients of the cubic Hermite
/// interpolant of the node values and the frozen intervals' end slopes.
fn second_method_lines(
    sys: &GearSystem,
    grid: &[f64],
    lines: usize,
    of: &dyn Fn(&State) -> f64,
) -> Vec<f64> {
    let (y, slopes) = linear_periodic_with_slopes(sys, grid, dof::PHI_M);
    let n = grid.len() - 1;
    let h = HermitePeriod {
        t: grid[..n].to_vec(),
        x: (0..n).map(|k| of(&y[k])).collect(),
        slope_start: slopes.iter().map(|(a, _)| of(a)).collect(),
        slope_end: slopes.iter().map(|(_, b)| of(b)).collect(),
        period_s: grid[n] - grid[0],
    };
    h.coefficients(grid[0], lines)
        .iter()
        .map(|c| c.norm())
        .collect()
}
#[test]
fn runout_sidebands_match_the_first_order_perturbation_solution() {
    // Gear run-out F_r = 2 um (eccentricity 1 um), no friction, motor speed imposed:
    // with every pair touching the model is linear time-periodic, and the run-out is a
    // transmission error e(t) = e_c cos(Omega_g t) modulated by the mesh stiffness. The
    // solver's DTE spectrum over the gear's revolution (31 mesh periods, bins of the gear
    // frequency) must show the lines at f_mesh +- f_gear and at f_gear with the
    // amplitudes of the second method's solution within 0.05 %: both sets of lines are the
    // exact Fourier coefficients of their solutions, so what is left is the difference of
    // the solutions (time response 0.02 %).
    // The nominal path: the second method perturbs the linear model of the pairs on the
    // path, which the corner contact (a unilateral contact beyond it) is not.
    let sets: Vec<String> = [
        "contact.path=nominal",
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
    assert_eq!(periods, p);
    let solver = amplitude_spectrum(&dte_signal(&r, 0), periods);
    let solver_v = amplitude_spectrum(&velocity_signal(&r, dof::YP), periods);
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
    let lines = 2 * p + 1;
    let g = sys.mesh_gradient(0);
    let dte = |y: &State| g.dot(&y.rows(0, NDOF));
    // The pinion's y velocity (what an accelerometer on its bearing sees).
    let vy = |y: &State| y[NDOF + dof::YP];
    let richardson = |of: &dyn Fn(&State) -> f64| -> Vec<f64> {
        let (c4, c8) = (
            second_method_lines(&sys, &refine(4), lines, of),
            second_method_lines(&sys, &refine(8), lines, of),
        );
        c4.iter()
            .zip(&c8)
            .map(|(a, b)| (4.0 * b - a) / 3.0)
            .collect()
    };
    let second = richardson(&dte);
    let second_v = richardson(&vy);
    for (signal, a_spec, b_spec, unit) in [
        ("DTE", &solver, &second, "m"),
        ("dy_p/dt", &solver_v, &second_v, "m/s"),
    ] {
        // The run-out's sidebands of the mesh fundamental to 0.05 %. The other lines are
        // small beside the signal (the velocity's f_gear line is 1e-5 of its mesh line,
        // the second harmonic's sideband 1/36 of the DTE's f_gear line): there the two
        // solutions' own errors (the solver's tolerance 1e-7 of the state's scale, the
        // second method's extrapolated discretisation) show, at 0.6 % and 0.1 %.
        let small = if signal == "DTE" { 5e-4 } else { 1e-2 };
        for (name, bin, bound) in [
            ("f_gear", 1, small),
            ("f_mesh - f_gear", p - 1, 5e-4),
            ("f_mesh + f_gear", p + 1, 5e-4),
            ("2 f_mesh - f_gear", 2 * p - 1, 2e-3),
        ] {
            let (a, b) = (a_spec.amplitude[bin], b_spec[bin]);
            println!(
                "{signal} at {name} ({:.2} Hz): solver {a:.5e} {unit}, perturbation solution {b:.5e} {unit}, {:+.3} %",
                a_spec.frequency_hz[bin],
                100.0 * (a / b - 1.0)
            );
            assert!(
                (a / b - 1.0).abs() < bound,
                "{signal} {name}: {a:e} vs {b:e}"
            );
        }
    }
}
