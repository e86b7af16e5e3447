//! The power balance of a two-stage reducer over a steady period: what the motor puts in
//! leaves through the brake, the friction of each mesh, every damper, and the work of the
//! meshes' time-varying springs on the vibration (the stiffness follows the nominal
//! angle, docs/MODEL.md section 4.1, so its change exchanges energy with no torque on the
//! rotation: -10.5 W here, against 160 W of losses). Every term is
//! computed here from the case's values and the hand-assembled matrices
//! (`common::train`), on the solver's own solution between its samples.

use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::model::ContactFrame;
use gearwear::dynamics::steady::solve_steady_state_from;
use gearwear::wear::WearState;
use std::f64::consts::PI;

mod common;
use common::train::{model, two_stage_parts_by_hand, TWO_STAGE};

/// Mean powers over one period, W.
#[derive(Debug, Default, Clone, Copy)]
struct Powers {
    /// Motor torque T_0 - c_slip dphi_m/dt times the motor's speed.
    input: f64,
    /// Brake torque times the brake's speed.
    output: f64,
    /// Bearings, shaft and couplings: v^T C v.
    dampers: f64,
    /// Each mesh's normal force on its deflection rate, F d(delta)/dt: its damper's
    /// c_m (d delta/dt)^2 and the work of its time-varying spring.
    mesh_force: f64,
    mesh_dampers: f64,
    /// Each mesh's friction: sum_i f_i u_s,i, and f e . (v_p - v_g) of the laterals.
    friction: f64,
}

impl Powers {
    fn add(&mut self, w: f64, p: Powers) {
        self.input += w * p.input;
        self.output += w * p.output;
        self.dampers += w * p.dampers;
        self.mesh_force += w * p.mesh_force;
        self.mesh_dampers += w * p.mesh_dampers;
        self.friction += w * p.friction;
    }
}

#[test]
fn input_power_is_output_power_plus_friction_and_damper_losses() {
    // Over a periodic orbit the kinetic energy and the energy of the constant springs
    // return, so the mean power of every force on the full motion (nominal rotation plus
    // vibration) sums to zero. The nominal speeds do no work on the shaft, the couplings
    // and the meshes' normal forces (each mesh's r_p Omega_p = r_g Omega_g), which is
    // what a train with wrong speeds would break; the friction's work is its force times
    // the sliding speed of the contact kinematics. Each mean is Simpson's rule on every
    // step of the solver with the step's own cubic Hermite midpoint (fourth order), so
    // the balance closes to the solver's tolerance: measured 4e-4 W of 11.5 kW input
    // (4e-8), asserted to 1e-6 (the steady-state tolerance 1e-6 bounds the periodicity of
    // the kinetic and spring energies whose means are taken as zero).
    let m = model(TWO_STAGE, &["numerics.evaluated_mesh_periods=62"]);
    let hand = two_stage_parts_by_hand(&m);
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let wear = WearState::new(m.grid.len());
    let sys = m.system(&gap, &ext, m.roughness_for(&wear));
    let r = solve_steady_state_from(&sys, &m.settings, None).unwrap();
    // By hand: the motor's 60 N m and speed, each shaft's speed by the teeth, the brake's
    // torque by the base radii (the teeth ratios: one module and pressure angle a stage).
    let t_in = 60.0;
    let c_slip = m.case.operating.motor_slip_damping_nm_s_per_rad;
    let w_in = 2.0 * PI * 30.0;
    let (i1, i2) = (31.0 / 19.0, 47.0 / 23.0);
    let t_out = t_in * i1 * i2;
    let mut w_nom = [0.0; 14];
    w_nom[8] = w_in;
    w_nom[9] = w_in;
    w_nom[10] = w_in / i1;
    w_nom[11] = w_in / i1;
    w_nom[12] = w_in / i1 / i2;
    w_nom[13] = w_in / i1 / i2;

    let power = |t: f64, y: &[f64], frame: ContactFrame| -> Powers {
        let (_, meshes) = sys.derivative(frame, t, y);
        let v = &y[14..];
        let mut p = Powers {
            input: (t_in - c_slip * v[8]) * (w_nom[8] + v[8]),
            output: t_out * (w_nom[13] + v[13]),
            ..Powers::default()
        };
        for i in 0..14 {
            for j in 0..14 {
                p.dampers += v[i] * hand.c_fixed[(i, j)] * v[j];
            }
        }
        for (ms, hm) in meshes.iter().zip(&hand.meshes) {
            let g = &hm.gradient;
            let rate: f64 = (0..14).map(|i| g[i] * v[i]).sum();
            p.mesh_force += ms.force_n * rate;
            if ms.pushing {
                p.mesh_dampers += hm.damper_n_s_per_m * rate * rate;
            }
            let n = ms.n_pairs;
            // The friction force f_i on the pinion along e, -f_i e on the gear, at the
            // contact whose surfaces slide at u_s,i: its power on both bodies is
            // -f_i u_s,i + f_i e . (v_p - v_g) with the laterals' velocities.
            let f_sum: f64 = ms.friction_n[..n].iter().sum();
            let [xp, xg] = hm.lateral;
            let e = hm.tangent;
            let slide_lateral = e[0] * (v[xp] - v[xg]) + e[1] * (v[xp + 1] - v[xg + 1]);
            p.friction += (0..n)
                .map(|i| ms.friction_n[i] * ms.sliding_m_per_s[i])
                .sum::<f64>()
                - f_sum * slide_lateral;
        }
        p
    };
    let s = &r.signals;
    let period = r.mesh_period_s;
    let t0 = s.time_s[0];
    let steps = s
        .time_s
        .iter()
        .filter(|t| **t < t0 + period * (1.0 - 1e-9))
        .count();
    assert!(s.time_s.len() > steps, "the window holds a second period");
    let state = |k: usize| -> Vec<f64> {
        s.displacement[k]
            .iter()
            .chain(&s.velocity[k])
            .copied()
            .collect()
    };
    let mut mean = Powers::default();
    for j in 0..steps {
        let (ta, tb) = (s.time_s[j], s.time_s[j + 1]);
        let h = tb - ta;
        let (y0, y1) = (state(j), state(j + 1));
        // Slopes at the step's ends: the velocities and the step's own accelerations.
        let f0: Vec<f64> = s.velocity[j]
            .iter()
            .chain(&s.step_acceleration[0][j])
            .copied()
            .collect();
        let f1: Vec<f64> = s.velocity[j + 1]
            .iter()
            .chain(&s.step_acceleration[1][j])
            .copied()
            .collect();
        let y_mid: Vec<f64> = (0..28)
            .map(|i| 0.5 * (y0[i] + y1[i]) + (f0[i] - f1[i]) * h / 8.0)
            .collect();
        // The step's pairs, decided at its middle (as the solver's step had them).
        let frame = ContactFrame::decided_at(ta + 0.5 * h);
        for (w, t, y) in [(1.0, ta, &y0), (4.0, ta + 0.5 * h, &y_mid), (1.0, tb, &y1)] {
            mean.add(w * h / 6.0 / period, power(t, y, frame));
        }
    }
    let losses = mean.dampers + mean.mesh_force + mean.friction;
    let closure = mean.input - mean.output - losses;
    println!("{mean:#?}\nclosure {closure:e} W");
    // The friction and the dampers are real losses here, not round-off.
    assert!(mean.friction > 10.0 && mean.dampers > 0.0 && mean.mesh_dampers > 0.0);
    assert!(
        closure.abs() < 1e-6 * mean.input,
        "input {} W, output {} W, losses {losses} W: closure {closure:e} W",
        mean.input,
        mean.output
    );
}
