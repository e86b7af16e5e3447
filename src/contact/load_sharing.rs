//! Load sharing between the tooth pairs in contact.
//!
//! Paper eq. (7), Pedrero's piecewise-linear model (Pedrero, Pleguezuelos & Muñoz,
//! Mech. Mach. Theory 46 (2011) 1197, simplified to 1/3 - 2/3 ramps): with
//! zeta = z1 rho1 / (2 pi r_b1) = rho1 / p_b the contact position in base pitches,
//! zeta_ini its value at the start of contact and zeta_a = zeta_ini + epsilon,
//!
//! kappa = 1/3 (1 + (zeta - zeta_ini)/(zeta_a - zeta_ini - 1))  zeta_ini <= zeta <= zeta_a - 1
//! kappa = 1                                                    zeta_a - 1 <= zeta <= zeta_ini + 1
//! kappa = 1/3 (1 + (zeta - zeta_a)/(zeta_ini + 1 - zeta_a))    zeta_ini + 1 <= zeta <= zeta_a
//!
//! It satisfies kappa(zeta) + kappa(zeta + 1) = 1 in double contact (a test checks it).
//! It is defined for 1 < epsilon < 2 only.

use crate::geometry::GearPair;

/// Share of the mesh force of the pair in its approach ramp (the pair that entered
/// contact last, in double contact), paper eq. (7) first line:
/// kappa = 1/3 (1 + (zeta - zeta_ini) / (epsilon - 1)), from 1/3 at entry to 2/3.
fn approach_share(pair: &GearPair, rho1_m: f64) -> f64 {
    let zeta = (rho1_m - pair.rho_start_m) / pair.base_pitch_m;
    (1.0 + zeta / (pair.contact_ratio - 1.0)) / 3.0
}

/// Share of the pair in its recess ramp (the pair about to leave, in double contact),
/// paper eq. (7) third line: kappa = 1/3 (1 + (zeta - zeta_a) / (1 - epsilon)), from 2/3
/// down to 1/3 at exit.
fn recess_share(pair: &GearPair, rho1_m: f64) -> f64 {
    let zeta_to_exit = (rho1_m - pair.rho_end_m) / pair.base_pitch_m;
    (1.0 + zeta_to_exit / (1.0 - pair.contact_ratio)) / 3.0
}

/// Share of a pair at position `rho1_m` along the path of contact, by position alone
/// (paper eq. 7 as a function of zeta): the profile's view, used where no contact set is
/// decided (nominal load along the path). At the two zone boundaries, where a set would
/// decide, it gives the single-pair value 1. Dimensionless.
pub fn pedrero_share_at(pair: &GearPair, rho1_m: f64) -> f64 {
    let zeta = (rho1_m - pair.rho_start_m) / pair.base_pitch_m;
    if zeta < pair.contact_ratio - 1.0 {
        approach_share(pair, rho1_m)
    } else if zeta <= 1.0 {
        1.0
    } else {
        recess_share(pair, rho1_m)
    }
}

/// Shares of the mesh force of the pairs in contact at one instant, paper eq. (7).
///
/// `rho1_m` lists the positions of the pairs of the contact set actually decided, from
/// the pair that entered last (smallest rho1) to the one ahead of it; the shares are
/// written to `out` (dimensionless). The set decides the branch of eq. (7), not the
/// positions: one pair carries the whole load (the middle line), of two pairs the one
/// behind is on the approach ramp and the one ahead on the recess ramp. At a mesh event
/// (pair entry or exit) the positions sit exactly on the boundary between two branches
/// and round-off would otherwise pick either; by the set, the shares always sum to 1
/// (kappa(zeta) + kappa(zeta + 1) = 1 holds identically for the two ramps).
/// Defined for 1 < epsilon < 2, so at most two pairs (`study::Model` rejects other pairs
/// for this law).
pub fn pedrero_shares(pair: &GearPair, rho1_m: &[f64], out: &mut [f64]) {
    match rho1_m.len() {
        0 => {}
        1 => out[0] = 1.0,
        2 => {
            out[0] = approach_share(pair, rho1_m[0]);
            out[1] = recess_share(pair, rho1_m[1]);
        }
        n => {
            // Outside eq. (7)'s range: an equal split keeps the sum (never reached).
            for o in out.iter_mut().take(n) {
                *o = 1.0 / n as f64;
            }
        }
    }
}

/// Shares of pairs with stiffness `k[i]` and gap `gap[i]` (m, e.g. wear) deflected by
/// the common mesh deflection `delta_m`: load_i = k_i max(delta - gap_i, 0)
/// (springs in parallel, each closing its own gap). Writes the shares into `out` and
/// returns the total elastic force, N. All shares are zero when no pair touches.
pub fn stiffness_shares(k: &[f64], gap_m: &[f64], delta_m: f64, out: &mut [f64]) -> f64 {
    let mut total = 0.0;
    for i in 0..k.len() {
        out[i] = k[i] * (delta_m - gap_m[i]).max(0.0);
        total += out[i];
    }
    for o in out.iter_mut().take(k.len()) {
        *o = if total > 0.0 { *o / total } else { 0.0 };
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;

    fn pair() -> GearPair {
        GearPair::from_case(&GearSection::default()).unwrap()
    }

    /// Pedrero shares of the contact set at `phase` decided at `decide` (rad).
    fn shares_at(p: &GearPair, phase: f64, decide: f64) -> Vec<f64> {
        let rho: Vec<f64> = p
            .pairs_in_contact_decided(phase, decide)
            .map(|(_, r)| r)
            .collect();
        let mut out = vec![0.0; rho.len()];
        pedrero_shares(p, &rho, &mut out);
        out
    }

    #[test]
    fn pedrero_shares_sum_to_one_everywhere_including_mesh_events() {
        // Invariant of eq. (7): the pairs in contact carry the whole load. The mesh events
        // (entry at phase 0, exit at (eps - 1) period) are checked exactly, with the set
        // decided on either side of them, as the solvers record them.
        let p = pair();
        let period = p.mesh_angle_rad();
        let exit = (p.contact_ratio - 1.0) * period;
        let d = 1e-9 * period;
        let mut phases: Vec<(f64, f64)> = (0..=200)
            .map(|i| period * i as f64 / 200.0)
            .map(|ph| (ph, ph))
            .collect();
        for ev in [0.0, exit, period] {
            phases.extend([(ev, ev - d), (ev, ev + d), (ev, ev)]);
        }
        for (phase, decide) in phases {
            let s: f64 = shares_at(&p, phase, decide).iter().sum();
            assert!((s - 1.0).abs() < 1e-12, "phase {phase}: {s}");
        }
    }

    #[test]
    fn share_by_position_is_complementary_one_base_pitch_apart() {
        // Eq. (7)'s invariant kappa(zeta) + kappa(zeta + 1) = 1 inside the first double
        // contact zone, 1 in single contact, 1/3 at the very start of contact.
        let p = pair();
        let pb = p.base_pitch_m;
        let double = (p.contact_ratio - 1.0) * pb;
        for i in 1..50 {
            let rho = p.rho_start_m + double * i as f64 / 50.0;
            let sum = pedrero_share_at(&p, rho) + pedrero_share_at(&p, rho + pb);
            assert!((sum - 1.0).abs() < 1e-12, "{rho}: {sum}");
        }
        let single = p.rho_start_m + 0.5 * (double + pb);
        assert_eq!(pedrero_share_at(&p, single), 1.0);
        assert!((pedrero_share_at(&p, p.rho_start_m) - 1.0 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn pedrero_end_values() {
        // 1/3 where a pair enters and leaves, 2/3 at the inner ends of double contact,
        // 1 in single contact.
        let p = pair();
        let period = p.mesh_angle_rad();
        let exit = (p.contact_ratio - 1.0) * period;
        let d = 1e-9 * period;
        // Right after entry: the new pair 1/3, the pair ahead 2/3.
        let s = shares_at(&p, 0.0, d);
        assert!((s[0] - 1.0 / 3.0).abs() < 1e-12 && (s[1] - 2.0 / 3.0).abs() < 1e-12);
        // Right before exit: 2/3 and 1/3; right after it one pair carries all.
        let s = shares_at(&p, exit, exit - d);
        assert!((s[0] - 2.0 / 3.0).abs() < 1e-12 && (s[1] - 1.0 / 3.0).abs() < 1e-12);
        assert_eq!(shares_at(&p, exit, exit + d), vec![1.0]);
    }

    #[test]
    fn stiffness_shares_equal_gaps_follow_stiffness() {
        let mut out = [0.0; 2];
        let f = stiffness_shares(&[1e8, 3e8], &[0.0, 0.0], 1e-5, &mut out);
        assert!((f - 4e3).abs() < 1e-9);
        assert!((out[0] - 0.25).abs() < 1e-15 && (out[1] - 0.75).abs() < 1e-15);
    }

    #[test]
    fn stiffness_shares_open_gap_carries_nothing() {
        // A worn pair whose gap exceeds the deflection does not touch.
        let mut out = [0.0; 2];
        let f = stiffness_shares(&[2e8, 2e8], &[0.0, 2e-5], 1e-5, &mut out);
        assert!((f - 2e3).abs() < 1e-9);
        assert_eq!(out, [1.0, 0.0]);
    }
}
