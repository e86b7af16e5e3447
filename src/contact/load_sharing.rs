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

/// Share of the mesh force carried by the pair at LOA position `rho1_m`, paper eq. (7).
///
/// Positions outside the path of contact return 0. Dimensionless, in [1/3, 1].
pub fn pedrero_share(pair: &GearPair, rho1_m: f64) -> f64 {
    let pb = pair.base_pitch_m;
    let zeta = rho1_m / pb;
    let zeta_ini = pair.rho_start_m / pb;
    let zeta_a = zeta_ini + pair.contact_ratio;
    let eps = pair.contact_ratio;
    let tol = 1e-12;
    if zeta < zeta_ini - tol || zeta > zeta_a + tol {
        0.0
    } else if zeta <= zeta_a - 1.0 {
        (1.0 + (zeta - zeta_ini) / (eps - 1.0)) / 3.0
    } else if zeta <= zeta_ini + 1.0 {
        1.0
    } else {
        (1.0 + (zeta - zeta_a) / (1.0 - eps)) / 3.0
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

    #[test]
    fn pedrero_shares_sum_to_one_in_double_contact() {
        // Invariant of eq. (7): the two pairs carry the whole load.
        let p = pair();
        let n = 200;
        for i in 0..=n {
            let phase = p.mesh_angle_rad() * i as f64 / n as f64;
            let s: f64 = p
                .pairs_in_contact(phase)
                .map(|(_, r)| pedrero_share(&p, r))
                .sum();
            assert!((s - 1.0).abs() < 1e-9, "phase {phase}: {s}");
        }
    }

    #[test]
    fn pedrero_end_values() {
        // 1/3 where a pair enters and leaves, 2/3 at the inner ends of double contact.
        let p = pair();
        assert!((pedrero_share(&p, p.rho_start_m) - 1.0 / 3.0).abs() < 1e-12);
        assert!((pedrero_share(&p, p.rho_end_m) - 1.0 / 3.0).abs() < 1e-12);
        let inner = p.rho_end_m - p.base_pitch_m;
        assert!((pedrero_share(&p, inner - 1e-12) - 2.0 / 3.0).abs() < 1e-9);
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
