//! The time grid of one mesh period.
//!
//! The mesh stiffness jumps where a pair enters or leaves contact, and the friction
//! direction turns where a pair passes the pitch point. A fixed-step integrator that
//! steps across such a kink loses its order there; placing grid nodes exactly on them
//! keeps the full order (the nominal mesh phase Omega_p t fixes their times in advance).
//! Steps are spread over the segments between events in proportion to their length.
//!
//! A train's meshes turn at different speeds: the excitation repeats over the smallest
//! common period of all of them (and of their per-tooth repeats), `excitation`, and the
//! grid of that period holds every mesh's events ([`train_nodes`]).

use super::model::GearSystem;
use crate::geometry::pair::Reach;
use crate::geometry::GearPair;

/// Node times within one mesh period, s, from 0 to the period (both included), for pairs
/// followed on the path of contact only.
pub fn period_nodes(pair: &GearPair, pinion_speed_rad_s: f64, steps: usize) -> Vec<f64> {
    period_nodes_in(pair, pair.nominal_reach(), pinion_speed_rad_s, steps)
}

/// As [`period_nodes`] for pairs followed over `reach` (`dynamics::contact_path`): the
/// phases where a pair enters or leaves the reach are events too (the set of pairs
/// changes there), beside the path's ends (where a corner contact turns into the path's
/// and the pair's stiffness has a kink).
pub fn period_nodes_in(
    pair: &GearPair,
    reach: Reach,
    pinion_speed_rad_s: f64,
    steps: usize,
) -> Vec<f64> {
    let period_rad = pair.mesh_angle_rad();
    let events = period_events(pair, reach);
    let n_seg = events.len() - 1;
    let steps = steps.max(2 * n_seg);
    let mut nodes = Vec::with_capacity(steps + 1);
    nodes.push(0.0);
    let mut used = 0usize;
    for s in 0..n_seg {
        let (a, b) = (events[s], events[s + 1]);
        // Largest-remainder share of the steps, at least 2 per segment.
        let remaining_len = period_rad - a;
        let remaining_steps = steps - used;
        let n = if s + 1 == n_seg {
            remaining_steps
        } else {
            (((b - a) / remaining_len * remaining_steps as f64).round() as usize)
                .clamp(2, remaining_steps - 2 * (n_seg - s - 1))
        };
        for i in 1..=n {
            nodes.push((a + (b - a) * i as f64 / n as f64) / pinion_speed_rad_s);
        }
        used += n;
    }
    nodes
}

/// The mesh events within one mesh period, pinion phase in rad from 0 to the period
/// (both included), sorted: where the number of pairs in contact changes
/// ([`GearPair::contact_change_phases`]) and where a pair passes the pitch point.
fn period_events(pair: &GearPair, reach: Reach) -> Vec<f64> {
    let period_rad = pair.mesh_angle_rad();
    // Where a pair enters or leaves the reach it is followed over (the set of pairs
    // changes), and beyond the nominal path also the path's ends (where a corner contact
    // turns into the path's and the pair's stiffness has a kink).
    let mut events: Vec<f64> = pair.reach_change_phases(reach);
    if reach != pair.nominal_reach() {
        events.extend(pair.contact_change_phases());
    }
    // Pitch-point passages: rho_A + r_b1 phase + k p_b = rho_pitch.
    for k in 0..pair.max_pairs() {
        let ph = (pair.rho_pitch_m - pair.rho_start_m - k as f64 * pair.base_pitch_m)
            / pair.pinion.base_radius_m;
        if ph > 0.0 && ph < period_rad {
            events.push(ph);
        }
    }
    events.push(period_rad);
    events.sort_by(f64::total_cmp);
    events.dedup_by(|a, b| (*a - *b).abs() < 1e-12 * period_rad);
    events
}

/// Greatest common divisor.
fn gcd(a: u128, b: u128) -> u128 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// A mesh's frequency over the input shaft's, as a reduced fraction (numerator,
/// denominator): z_pinion times the product of z_driver / z_driven on the way from the
/// input to the mesh's pinion. None if a number overflows.
pub fn mesh_frequency_fraction(sys: &GearSystem, m: usize) -> Option<(u128, u128)> {
    let asm = sys.assembly();
    let e = &asm.elements;
    // Breadth first from the input: each body's speed as a fraction of the input's.
    let n = e.bodies.len();
    let mut frac: Vec<Option<(u128, u128)>> = vec![None; n];
    frac[e.drive.input] = Some((1, 1));
    let mut queue = std::collections::VecDeque::from([e.drive.input]);
    while let Some(b) = queue.pop_front() {
        let (num, den) = frac[b]?;
        let shafts = e.shafts.iter().filter_map(|s| match s.ends {
            [x, y] if x == b => Some((y, 1, 1)),
            [x, y] if y == b => Some((x, 1, 1)),
            _ => None,
        });
        let meshes = e.meshes.iter().filter_map(|l| {
            let [zp, zg] = l.teeth.map(|z| z as u128);
            if l.pinion == b {
                Some((l.gear, zp, zg))
            } else if l.gear == b {
                Some((l.pinion, zg, zp))
            } else {
                None
            }
        });
        for (other, a, c) in shafts.chain(meshes).collect::<Vec<_>>() {
            if frac[other].is_none() {
                let (p, q) = (num.checked_mul(a)?, den.checked_mul(c)?);
                let g = gcd(p, q);
                frac[other] = Some((p / g, q / g));
                queue.push_back(other);
            }
        }
    }
    let link = &e.meshes[m];
    let (num, den) = frac[link.pinion]?;
    let p = num.checked_mul(link.teeth[0] as u128)?;
    let g = gcd(p, den);
    Some((p / g, den / g))
}

/// The smallest time after which every mesh of `sys` is in the same phase again, in
/// input revolutions as a reduced fraction, each mesh repeating every `repeats[m]` of its
/// own mesh periods (1, or a tooth-resolved mesh's `ToothMesh::periods`): the lcm of the
/// rationals repeats_m / (f_m / f_in), lcm(b_m) / gcd(a_m) for f_m / (f_in repeats_m) =
/// a_m / b_m reduced. None if a number overflows.
pub fn common_period_revolutions(sys: &GearSystem, repeats: &[usize]) -> Option<(u128, u128)> {
    let (mut l, mut g) = (1u128, 0u128);
    for (m, r) in repeats.iter().enumerate() {
        let (a, b) = mesh_frequency_fraction(sys, m)?;
        let b = b.checked_mul(*r as u128)?;
        let d = gcd(a, b);
        let (a, b) = (a / d, b / d);
        l = (l / gcd(l, b)).checked_mul(b)?;
        g = gcd(g, a);
    }
    let d = gcd(l, g.max(1));
    Some((l / d, g.max(1) / d))
}

/// Mesh periods of each mesh of a chain of stages (each stage's gear on the next stage's
/// pinion's shaft; `teeth[k]` = [z_pinion, z_gear]) in the train's base period: with
/// f_k / f_in = z_p,k prod_{j<k} z_p,j / z_g,j = a_k / b_k reduced, the base period is
/// lcm(b_k) / gcd(a_k) input revolutions (as [`common_period_revolutions`]). The single
/// pair: `[1]`. None if a number overflows.
pub fn chain_mesh_counts(teeth: &[[usize; 2]]) -> Option<Vec<u128>> {
    let (mut num, mut den) = (1u128, 1u128);
    let mut fracs = Vec::with_capacity(teeth.len());
    for [zp, zg] in teeth {
        let (zp, zg) = (*zp as u128, *zg as u128);
        let a = num.checked_mul(zp)?;
        let g = gcd(a, den);
        fracs.push((a / g, den / g));
        let (n2, d2) = (num.checked_mul(zp)?, den.checked_mul(zg)?);
        let g = gcd(n2, d2);
        (num, den) = (n2 / g, d2 / g);
    }
    let (mut l, mut g) = (1u128, 0u128);
    for (a, b) in &fracs {
        l = (l / gcd(l, *b)).checked_mul(*b)?;
        g = gcd(g, *a);
    }
    let g = g.max(1);
    fracs
        .iter()
        .map(|(a, b)| {
            // (l / g) (a / b), an integer.
            let num = l.checked_mul(*a)?;
            let den = g.checked_mul(*b)?;
            (num % den == 0).then_some(num / den)
        })
        .collect()
}

/// Base periods of a chain of stages ([`chain_mesh_counts`]) after which every mesh is
/// at the same phase and the same teeth again, mesh k's teeth repeating every
/// `repeats[k]` of its mesh periods (1 when its teeth are alike; z of a gear with a
/// faulty tooth): the smallest m with m N_k a multiple of r_k for every k,
/// m = lcm_k(r_k / gcd(r_k, N_k)), N_k the mesh periods of mesh k in one base period.
/// The same number as [`excitation_periods`] of the built train, from the teeth alone
/// (the run budget's, before the model is built). None if a number overflows.
pub fn chain_excitation_periods(teeth: &[[usize; 2]], repeats: &[usize]) -> Option<u128> {
    let counts = chain_mesh_counts(teeth)?;
    let mut m = 1u128;
    for (n, r) in counts.iter().zip(repeats) {
        let r = (*r).max(1) as u128;
        let need = r / gcd(r, *n);
        m = (m / gcd(m, need)).checked_mul(need)?;
    }
    Some(m)
}

/// Mesh periods of mesh `m` in `revolutions` (a reduced fraction) of the input.
pub fn mesh_periods_in(sys: &GearSystem, m: usize, revolutions: (u128, u128)) -> Option<u128> {
    let (a, b) = mesh_frequency_fraction(sys, m)?;
    let num = revolutions.0.checked_mul(a)?;
    let den = revolutions.1.checked_mul(b)?;
    (num % den == 0).then_some(num / den)
}

/// The excitation of `sys` with all teeth alike: its common period (s) and the number of
/// mesh periods of each mesh in it. The single pair: one mesh period.
pub fn base_period(sys: &GearSystem) -> Option<(f64, Vec<usize>)> {
    let ones = vec![1; sys.meshes.len()];
    let revs = common_period_revolutions(sys, &ones)?;
    let counts = (0..sys.meshes.len())
        .map(|m| mesh_periods_in(sys, m, revs).and_then(|c| usize::try_from(c).ok()))
        .collect::<Option<Vec<usize>>>()?;
    let mesh0 = sys.mesh(0);
    let t0 = mesh0.parts.pair.mesh_angle_rad() / mesh0.operating.speeds_rad_s[0];
    Some((t0 * counts[0] as f64, counts))
}

/// Base periods ([`base_period`]) after which a train with tooth-resolved meshes repeats
/// (each mesh's teeth repeat after `ToothMesh::periods` of its mesh periods): 1 when every
/// tooth is alike. None if a number overflows.
pub fn excitation_periods(sys: &GearSystem) -> Option<usize> {
    let repeats: Vec<usize> = sys
        .meshes
        .iter()
        .map(|m| m.parts.teeth.map_or(1, |tm| tm.periods()))
        .collect();
    let ones = vec![1; repeats.len()];
    let (p0, q0) = common_period_revolutions(sys, &ones)?;
    let (p, q) = common_period_revolutions(sys, &repeats)?;
    // (p / q) / (p0 / q0), an integer.
    let num = p.checked_mul(q0)?;
    let den = q.checked_mul(p0)?;
    (num % den == 0)
        .then_some(num / den)
        .and_then(|k| usize::try_from(k).ok())
}

/// Node times within one base period of a train ([`base_period`]), s, from 0 to the
/// period. The single pair: its [`period_nodes`] exactly. A train: every mesh's events
/// (`period_events`: pair changes and pitch passages) over its mesh periods in the base
/// period, merged (events of two meshes closer than 1e-9 of the shortest mesh period are
/// one), and each gap between events filled with ceil(gap / h_max) equal intervals,
/// h_max = the shortest mesh period / `steps`. Equal intervals keep the step length of
/// the implicit integrator, and with it its factorised iteration matrix, along a gap;
/// spreading each mesh's `steps` nodes per mesh period instead would make every interval
/// of the merged set a different length.
pub fn train_nodes(sys: &GearSystem, steps: usize) -> Option<Vec<f64>> {
    if sys.meshes.len() == 1 {
        let m = sys.mesh(0);
        return Some(period_nodes_in(
            m.parts.pair,
            m.parts.contact.reach(),
            m.operating.speeds_rad_s[0],
            steps,
        ));
    }
    let (period, counts) = base_period(sys)?;
    let mut events = Vec::new();
    let mut shortest = f64::INFINITY;
    for (mesh, count) in sys.meshes.iter().zip(&counts) {
        let w = mesh.operating.speeds_rad_s[0];
        let one = period_events(mesh.parts.pair, mesh.parts.contact.reach());
        let t_mesh = period / *count as f64;
        shortest = shortest.min(t_mesh);
        for k in 0..*count {
            let base = k as f64 * t_mesh;
            events.extend(one[..one.len() - 1].iter().map(|ph| base + ph / w));
        }
    }
    events.push(period);
    events.sort_by(f64::total_cmp);
    let tol = 1e-9 * shortest;
    events.dedup_by(|a, b| (*a - *b).abs() < tol);
    // The period's end stays exact.
    if let Some(last) = events.last_mut() {
        *last = period;
    }
    let h_max = shortest / steps.max(1) as f64;
    let mut nodes = Vec::with_capacity(events.len() + (period / h_max) as usize + 1);
    nodes.push(events[0]);
    for w in events.windows(2) {
        let (a, b) = (w[0], w[1]);
        let n = ((b - a) / h_max).ceil().max(1.0) as usize;
        nodes.extend((1..n).map(|i| a + (b - a) * i as f64 / n as f64));
        nodes.push(b);
    }
    Some(nodes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;

    #[test]
    fn nodes_hit_every_event_and_span_the_period() {
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let w = 100.0;
        let nodes = period_nodes(&p, w, 200);
        assert_eq!(nodes.len(), 201);
        let period = p.mesh_angle_rad() / w;
        assert!((nodes[200] - period).abs() < 1e-15);
        assert!(nodes.windows(2).all(|x| x[1] > x[0]));
        // The pair-leaves event (eps - 1) T and the pitch passages are nodes.
        let leave = (p.contact_ratio - 1.0) * period;
        assert!(nodes.iter().any(|t| (t - leave).abs() < 1e-12 * period));
        let pitch = (p.rho_pitch_m - p.rho_start_m) / p.pinion.base_radius_m / w;
        let pitch = if pitch > period {
            pitch - p.base_pitch_m / p.pinion.base_radius_m / w
        } else {
            pitch
        };
        assert!(
            nodes.iter().any(|t| (t - pitch).abs() < 1e-12 * period),
            "pitch {pitch}"
        );
    }
}
