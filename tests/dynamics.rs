//! The tribo-dynamic model checked against facts independent of the code: force balance,
//! the quasi-static limit, periodicity of the spectrum, an independent eigen-solution,
//! energy conservation and dissipation, and step convergence.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::integrator::{Rk4, Stepper};
use gearwear::dynamics::modal::{linearised_matrices, modes};
use gearwear::dynamics::model::{dof, ContactFrame, GearSystem, State, NDOF};
use gearwear::dynamics::summary::{velocity_y_spectrum, ResponseSummary};
use gearwear::study::Model;
use gearwear::wear::WearState;
use nalgebra::DMatrix;
use nalgebra::Dyn;

fn model(sets: &[&str]) -> Model {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    Model::from_case(&load_case("", &sets).expect("valid case")).expect("valid model")
}

fn dynamic(m: &Model) -> gearwear::dynamics::response::DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .expect("steady state")
}

#[test]
fn without_friction_mean_mesh_force_is_load_over_base_radius() {
    // Periodic steady state: every mean acceleration vanishes, so the brake coupling carries
    // T_brk and the gear balances r_gb mean(F) = T_brk exactly. Tolerance 1e-5: the
    // steady-state criterion is 1e-6 per period and the midpoint-rule mean is second order.
    for (shaft, boundary) in [
        ("pinion", "motor_speed_imposed"),
        ("gear", "brake_speed_imposed"),
    ] {
        let m = model(&[
            "friction.model=none",
            &format!("operating.load_torque_shaft={shaft}"),
            &format!("operating.speed_boundary={boundary}"),
        ]);
        let r = dynamic(&m);
        let rb = if shaft == "pinion" {
            m.pair.pinion.base_radius_m
        } else {
            m.pair.gear.base_radius_m
        };
        let expected = 60.0 / rb;
        let got = r.meshes[0].mean_mesh_force_n;
        assert!(
            ((got - expected) / expected).abs() < 1e-5,
            "{shaft}/{boundary}: mean force {got} vs {expected}"
        );
    }
}

#[test]
fn at_very_low_speed_dte_matches_quasi_static_te() {
    // 0.2 Hz input: mesh frequency 3.8 Hz against a lowest mode of ~500 Hz, so inertia and
    // damping forces are ~(3.8/500)^2 ~ 6e-5 of the elastic ones. The stiffness jumps start
    // free vibrations that decay in ~1/(zeta omega) = 3 ms, 0.6 % of the 0.5 s mesh period:
    // compare nodes more than 5 % of a period away from any mesh event. The events listed
    // are the nominal path's (contact.path = "nominal"); with corner contact the corners
    // touch at load-dependent phases, and tests/corner_contact.rs compares that model
    // with its quasi-static twin.
    let m = model(&[
        "contact.path=nominal",
        "operating.input_speed_hz=0.2",
        "friction.model=none",
        "dynamics.mesh_damping_ratio=0.1",
        "numerics.steps_per_mesh_period=400",
    ]);
    let w = WearState::new(m.grid.len());
    let dynr = m.dynamic(&w, &ExternalError::none()).unwrap();
    let qs = m.quasi_static(&w, &ExternalError::none());
    let period = m.pair.mesh_angle_rad();
    let events = [0.0, (m.pair.contact_ratio - 1.0) * period, period];
    let n = qs.signals.meshes[0].dte_m.len();
    let mut compared = 0;
    for k in 0..n {
        let ph = qs.signals.meshes[0].phase_rad[k];
        if events.iter().any(|e| (ph - e).abs() < 0.05 * period) {
            continue;
        }
        // The dynamic samples hold every grid node (and the steps between them).
        let t = qs.signals.time_s[k];
        let j = dynr
            .signals
            .time_s
            .iter()
            .position(|s| *s == t)
            .expect("a node");
        let (a, b) = (
            dynr.signals.meshes[0].dte_m[j],
            qs.signals.meshes[0].dte_m[k],
        );
        // 1e-3: the inertia share above, plus the residual of the decayed transients.
        assert!(((a - b) / b).abs() < 1e-3, "node {k}: {a} vs {b}");
        compared += 1;
    }
    assert!(compared > n / 2);
}

#[test]
fn spectrum_of_the_periodic_response_sits_on_mesh_harmonics() {
    // A mesh-periodic response has energy only at multiples of the mesh frequency: the
    // bins between harmonics hold only the response's departure from periodicity. The
    // steady state is declared when a period changes the signals by less than 1e-6 of
    // their peak, so the recorded periods differ by about that much and the energy off
    // the harmonics is of order (1e-6)^2 of the total: 1e-9 leaves a wide margin (with
    // the former Hann window it was 1/3: side lines at +-f_mesh / P of half height).
    let m = model(&[]);
    let r = dynamic(&m);
    let s = velocity_y_spectrum(&r);
    let b = s.bins_per_harmonic;
    assert!(b >= 2);
    let total: f64 = s.amplitude.iter().map(|a| a * a).sum();
    let off: f64 = s
        .amplitude
        .iter()
        .enumerate()
        .filter(|(k, _)| k % b != 0)
        .map(|(_, a)| a * a)
        .sum();
    assert!(
        off / total < 1e-9,
        "share off the harmonics {:e}",
        off / total
    );
    // The largest peak is at a mesh harmonic bin.
    let kmax = (1..s.amplitude.len())
        .max_by(|x, y| s.amplitude[*x].total_cmp(&s.amplitude[*y]))
        .unwrap();
    assert_eq!(kmax % b, 0, "peak at bin {kmax}");
    let f_mesh = m.params.operating.mesh_frequency_hz;
    assert!((s.frequency_hz[b] - f_mesh).abs() < 1e-9 * f_mesh);
}

#[test]
fn natural_frequencies_match_dense_first_order_eigenvalues() {
    // Independent method: eigenvalues of the undamped first-order matrix
    // [[0, I], [-M^-1 K, 0]] (non-symmetric, Schur-based) are +-i omega.
    for boundary in ["motor_speed_imposed", "brake_speed_imposed", "motor_slip"] {
        let m = model(&[&format!("operating.speed_boundary={boundary}")]);
        let gap = PairGap::none();
        let ext = ExternalError::none();
        let sys = m.system(&gap, &ext, 0.2);
        let (mass, k, _) = linearised_matrices(&sys);
        let n = mass.len();
        let a = DMatrix::from_fn(2 * n, 2 * n, |i, j| {
            if i < n {
                if j == n + i {
                    1.0
                } else {
                    0.0
                }
            } else if j < n {
                -k[(i - n, j)] / mass[i - n]
            } else {
                0.0
            }
        });
        let mut omegas: Vec<f64> = a
            .complex_eigenvalues()
            .iter()
            // One of each conjugate pair; the rigid-body pair may come out as +-tiny real
            // numbers instead: keep one of those too.
            .filter(|z| z.im > 0.0 || (z.im == 0.0 && z.re >= 0.0))
            .map(|z| z.im / (2.0 * std::f64::consts::PI))
            .collect();
        omegas.sort_by(f64::total_cmp);
        let modes = modes(&sys);
        assert_eq!(omegas.len(), modes.frequency_hz.len(), "{boundary}");
        for (a, b) in omegas.iter().zip(&modes.frequency_hz) {
            // Both are double-precision eigen-solvers of a matrix with entries spanning
            // 12 decades: agree to 1e-5 relative (or 1e-2 Hz for the rigid-body zero;
            // measured up to 1.5e-6 on the ~29 kHz mode).
            assert!((a - b).abs() < 1e-5 * b.max(1e3), "{boundary}: {a} vs {b}");
        }
    }
}

/// Total energy of the linear, time-invariant conservative system: kinetic + bearing and
/// coupling springs + mesh spring - work potential of the constant torques.
fn energy(sys: &GearSystem, y: &State, k_mesh: f64) -> f64 {
    let (k_lin, _, inv_mass) = sys.linear_parts();
    let q = y.rows(0, NDOF).into_owned();
    let v = y.rows(NDOF, NDOF).into_owned();
    let mut e = 0.5 * (q.transpose() * k_lin * &q)[(0, 0)] - sys.external_forces().dot(&q);
    for i in 0..NDOF {
        if inv_mass[i] > 0.0 {
            e += 0.5 * v[i] * v[i] / inv_mass[i];
        }
    }
    let delta = sys.mesh_gradient(0).dot(&q);
    e + 0.5 * k_mesh * delta * delta
}

#[test]
fn undamped_frictionless_model_conserves_energy() {
    // All damping off, no friction, and so slow a rotation that the stiffness is constant
    // over the test: the equations must then be conservative (symmetric stiffness, mesh
    // force derived from its potential). RK4 at h = 2e-8 s against a fastest mode of
    // ~66 kHz (omega h ~ 0.008): energy error per step ~ (omega h)^6 ~ 3e-13, far below 1e-9.
    let m = model(&[
        "operating.input_speed_hz=1e-6",
        // The motor's slip law is a damper; an imposed motor angle is conservative.
        "operating.speed_boundary=motor_speed_imposed",
        "friction.model=none",
        "dynamics.mesh_damping_ratio=0",
        "dynamics.bearing_damping_pinion_n_s_per_m=0",
        "dynamics.bearing_damping_gear_n_s_per_m=0",
        "dynamics.coupling_damping_motor_nm_s_per_rad=0",
        "dynamics.coupling_damping_brake_nm_s_per_rad=0",
    ]);
    let gap = PairGap::none();
    let ext = ExternalError::none();
    let sys = m.system(&gap, &ext, 0.2);
    let mut y = sys.static_equilibrium();
    // Kick it: velocities on every free coordinate.
    y[NDOF + dof::YP] = 1e-3;
    y[NDOF + dof::XG] = -2e-3;
    y[NDOF + dof::PHI_P] = 0.05;
    y[NDOF + dof::PHI_B] = -0.01;
    let k_mesh =
        sys.derivative(ContactFrame::NATURAL, 0.0, y.as_slice()).1[0].stiffness_total_n_per_m;
    let e0 = energy(&sys, &y, k_mesh);
    let mut rk = Rk4::<Dyn>::new(2e-8).unwrap();
    let mut f = |t: f64, y: &State| sys.derivative(ContactFrame::NATURAL, t, y.as_slice()).0;
    let mut t = 0.0;
    let mut drift: f64 = 0.0;
    let scale = e0.abs().max(1e-30);
    for _ in 0..50 {
        rk.advance(&mut f, &mut t, &mut y, 1000).unwrap();
        let ms = sys.derivative(ContactFrame::NATURAL, t, y.as_slice()).1[0];
        assert!(ms.force_n > 0.0, "contact must hold for a linear test");
        drift = drift.max((energy(&sys, &y, k_mesh) - e0).abs() / scale);
    }
    assert!(drift < 1e-9, "relative energy drift {drift}");
}

#[test]
fn friction_forces_only_dissipate() {
    // Power of the friction forces on the whole system (with the nominal rotation added to
    // the angular velocities) must equal -sum f_i u_s,i <= 0 (paper eq. 3-6 derived).
    let m = model(&[]);
    let gap = PairGap::none();
    let ext = ExternalError::none();
    let sys = m.system(&gap, &ext, 0.21);
    let y = sys.static_equilibrium();
    let mut checked = 0;
    for i in 0..50 {
        let t = i as f64 / 50.0 * m.pair.mesh_angle_rad() / m.params.operating.pinion_speed_rad_s;
        let mut ms = sys.derivative(ContactFrame::NATURAL, t, y.as_slice()).1[0];
        let expected: f64 = (0..ms.n_pairs)
            .map(|j| -ms.friction_n[j] * ms.sliding_m_per_s[j])
            .sum();
        ms.force_n = 0.0; // keep only friction in the generalised forces
        let mut qf = [0.0; NDOF];
        sys.mesh(0).add_forces(&ms, &mut qf);
        let mut v = [0.0; NDOF];
        v[dof::PHI_M] = m.params.operating.pinion_speed_rad_s;
        v[dof::PHI_P] = m.params.operating.pinion_speed_rad_s;
        v[dof::PHI_G] = m.params.operating.gear_speed_rad_s;
        v[dof::PHI_B] = m.params.operating.gear_speed_rad_s;
        let power: f64 = (0..NDOF).map(|k| qf[k] * v[k]).sum();
        assert!(power <= 1e-12, "friction power {power} > 0");
        assert!((power - expected).abs() <= 1e-9 * expected.abs().max(1.0));
        checked += (expected < 0.0) as usize;
    }
    assert!(checked > 40, "friction must act somewhere");
}

#[test]
fn halving_the_step_changes_max_dte_by_less_than_a_thousandth() {
    let a = ResponseSummary::of(&dynamic(&model(&["numerics.steps_per_mesh_period=200"])));
    let b = ResponseSummary::of(&dynamic(&model(&["numerics.steps_per_mesh_period=400"])));
    let rel = ((a.dte_max_m - b.dte_max_m) / b.dte_max_m).abs();
    assert!(
        rel < 1e-3,
        "max DTE {} vs {}: {rel}",
        a.dte_max_m,
        b.dte_max_m
    );
    let rel_f = ((a.mesh_force_mean_n - b.mesh_force_mean_n) / b.mesh_force_mean_n).abs();
    assert!(rel_f < 1e-3, "mean force: {rel_f}");
}
