//! The time grid of one mesh period.
//!
//! The mesh stiffness jumps where a pair enters or leaves contact, and the friction
//! direction turns where a pair passes the pitch point. A fixed-step integrator that
//! steps across such a kink loses its order there; placing grid nodes exactly on them
//! keeps the full order (the nominal mesh phase Omega_p t fixes their times in advance).
//! Steps are spread over the segments between events in proportion to their length.

use crate::geometry::GearPair;

/// Node times within one mesh period, s, from 0 to the period (both included).
pub fn period_nodes(pair: &GearPair, pinion_speed_rad_s: f64, steps: usize) -> Vec<f64> {
    let period_rad = pair.mesh_angle_rad();
    let mut events: Vec<f64> = pair.contact_change_phases();
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
