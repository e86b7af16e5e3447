//! The checks of an assembly's elements before it is numbered: body indices in range, and
//! the sense and speed ratio of every body from the input (`Assembly::new`).

use super::elements::Elements;
use super::AssemblyError;

/// Every body index an element names lies among the bodies.
pub(super) fn check_indices(e: &Elements) -> Result<(), AssemblyError> {
    let bodies = e.bodies.len();
    let used = e
        .bearings
        .iter()
        .map(|b| b.body)
        .chain(e.axial_bearings.iter().map(|a| a.body))
        .chain(e.tilt_bearings.iter().map(|t| t.body))
        .chain(e.shafts.iter().flat_map(|s| s.ends))
        .chain(e.meshes.iter().flat_map(|m| [m.pinion, m.gear]))
        .chain([e.drive.input, e.drive.output]);
    for index in used {
        if index >= bodies {
            return Err(AssemblyError::NoSuchBody { index, bodies });
        }
    }
    Ok(())
}

/// Sense of rotation and nominal speed ratio of every body, walking from the input
/// through shafts (same sense and speed) and meshes of external gears (opposite sense,
/// speed times z_pinion / z_gear); a body reached twice must agree (to 1e-9).
pub(super) fn kinematics(e: &Elements) -> Result<(Vec<f64>, Vec<f64>), AssemblyError> {
    let n = e.bodies.len();
    let mut spin = vec![0.0; n];
    let mut ratio = vec![0.0; n];
    let input = e.drive.input;
    spin[input] = 1.0;
    ratio[input] = 1.0;
    let mut queue = std::collections::VecDeque::from([input]);
    let links = |b: usize| {
        let shafts = e.shafts.iter().filter_map(move |s| match s.ends {
            [x, y] if x == b => Some((y, 1.0, 1.0)),
            [x, y] if y == b => Some((x, 1.0, 1.0)),
            _ => None,
        });
        let meshes = e.meshes.iter().filter_map(move |m| {
            let [zp, zg] = m.teeth.map(|z| z as f64);
            if m.pinion == b {
                Some((m.gear, -1.0, zp / zg))
            } else if m.gear == b {
                Some((m.pinion, -1.0, zg / zp))
            } else {
                None
            }
        });
        shafts.chain(meshes)
    };
    while let Some(b) = queue.pop_front() {
        for (other, sense, factor) in links(b) {
            let (s, r) = (spin[b] * sense, ratio[b] * factor);
            if spin[other] == 0.0 {
                spin[other] = s;
                ratio[other] = r;
                queue.push_back(other);
            } else if spin[other] != s && sense < 0.0 {
                return Err(AssemblyError::MeshSameSense {
                    first: e.bodies[b].name.clone(),
                    second: e.bodies[other].name.clone(),
                });
            } else if (ratio[other] - r).abs() > 1e-9 * r.abs() || spin[other] != s {
                return Err(AssemblyError::InconsistentSpeeds {
                    body: e.bodies[other].name.clone(),
                    first: ratio[other] * spin[other],
                    second: r * s,
                });
            }
        }
    }
    if let Some(b) = (0..n).find(|b| spin[*b] == 0.0) {
        return Err(AssemblyError::Disconnected {
            body: e.bodies[b].name.clone(),
        });
    }
    Ok((spin, ratio))
}
