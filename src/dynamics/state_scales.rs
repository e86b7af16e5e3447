//! The scales of the gear model's state that the integrator's error control and the
//! period search measure against: a displacement of one static mesh deflection, a velocity
//! of that deflection at the mesh frequency.

use super::assembly::Dof;
use super::model::{GearSystem, State};

/// Scales of the state of the gear model, SI: the mesh deflection under the nominal load
/// (m) for every displacement along a line of action, and the same at the mesh frequency
/// (m/s) for the velocities; angles through their body's base radius. In a train, the
/// smallest static deflection and the highest mesh frequency of its meshes, and a body
/// with no mesh (a motor, a load) takes the lever of the gear its shaft joins.
pub fn state_scales(sys: &GearSystem) -> State {
    let (mut delta_ref, mut omega_mesh) = (f64::INFINITY, 0.0_f64);
    for m in &sys.meshes {
        let f_nominal = m.operating.torques_nm[1] / m.parts.pair.gear.base_radius_m;
        delta_ref = delta_ref.min(f_nominal / m.parts.mesh.mean_stiffness_n_per_m());
        let w = m.operating.speeds_rad_s[0] * m.parts.pair.pinion.teeth as f64;
        omega_mesh = omega_mesh.max(w);
    }
    let levers = rotation_levers(sys);
    let asm = sys.assembly();
    let n = sys.dofs();
    let mut s = State::zeros(2 * n);
    for i in 0..n {
        let lever = match asm.describe(i) {
            (_, Dof::Rotation) => levers[i],
            _ => 1.0,
        };
        s[i] = delta_ref / lever;
        s[n + i] = delta_ref * omega_mesh / lever;
    }
    s
}

/// The base radius through which each rotation coordinate moves a line of action (1 for
/// the lateral ones): a gear's in its first mesh, a body without one that of the nearest
/// gear along its shafts.
fn rotation_levers(sys: &GearSystem) -> Vec<f64> {
    let asm = sys.assembly();
    let e = &asm.elements;
    let mut lever = vec![0.0; e.bodies.len()];
    for link in e.meshes.iter().rev() {
        lever[link.pinion] = link.base_radius_m[0];
        lever[link.gear] = link.base_radius_m[1];
    }
    // Spread along shafts until every body has one (a connected train: at most n sweeps).
    for _ in 0..e.bodies.len() {
        for s in &e.shafts {
            let [a, b] = s.ends;
            if lever[a] == 0.0 && lever[b] > 0.0 {
                lever[a] = lever[b];
            } else if lever[b] == 0.0 && lever[a] > 0.0 {
                lever[b] = lever[a];
            }
        }
    }
    let mut out = vec![1.0; sys.dofs()];
    for (b, l) in lever.iter().enumerate() {
        if let Some(i) = asm.index(b, Dof::Rotation) {
            out[i] = if *l > 0.0 { *l } else { 1.0 };
        }
    }
    out
}
