//! The running-in of a spur pair as the run budget counts it: the largest wear rate of the
//! profiles as a function of the cycles run, from the case's own load sharing, so that
//! the wear updates of a run-to-failure job (`prognostics::surrogate`, `forward`) are
//! counted as the loop's threshold and block rule cuts them (issue 33: with the initial
//! rate held for the whole run the count was 2.4-3.5 times the updates made).
//!
//! # Model (docs/RELIABILITY.md, "Run budget")
//!
//! - **Wear per cycle at a contact** (Archard, paper eq. 14, with the Hertz band of
//!   docs/MODEL.md section 3): a flank point wears k p0 s per pass, s = 2 a |u_p - u_g| / u
//!   its sliding distance; since p0 2 a = 4 F / (pi b) for a line load F / b, the depth
//!   per pinion cycle is k alpha F, alpha = 4 |u_p - u_g| max(1 / u_p, (z_p / z_g) / u_g)
//!   / (pi b) (m per N and unit k; the pinion's flank or the gear's, whichever is faster
//!   per pinion cycle, as `super::evaluation::nominal_wear_per_cycle_m` takes it). Linear
//!   in the load.
//! - **Single contact** (one pair carries the mesh force F): the rate stays k alpha F.
//! - **Double contact**: a point A of the approach (x from the start of the path, x <
//!   (epsilon - 1) p_b) meets with the point B one base pitch ahead (recess). Each pair
//!   carries its stiffness K_i times its compression less its gap (docs/MODEL.md 9.2), so
//!   with the wear depths g_A, g_B (both flanks) and Delta = g_A - g_B, F_A = F_A0 - K_t
//!   Delta and F_B = F_B0 + K_t Delta, K_t = K_A K_B / (K_A + K_B) = s_A s_B K_mesh (s_i
//!   the pairs' shares of paper eq. 7, K_mesh the double-contact mesh stiffness, bounded
//!   below by ISO 6336-1's mean mesh stiffness c'_gamma b: a softer mesh passes the load
//!   on more slowly, which counts more updates). So d Delta / dN = k [(r_A - r_B) -
//!   K_t (alpha_A + alpha_B) Delta]: Delta relaxes exponentially, with the rate lambda = k
//!   K_t (alpha_A + alpha_B) per cycle, towards the state where both points wear alike,
//!   at (alpha_B r_A + alpha_A r_B) / (alpha_A + alpha_B): the faster point of the pair
//!   loses load to the slower one. Under a load spectrum each bin's share weights alpha
//!   and r (the relaxation stays linear in Delta).
//! - **The rate the loop cuts its blocks by** is the largest over the single-contact points
//!   and the double-contact pairs, times the dynamic margin
//!   [`super::evaluation::DYNAMIC_WEAR_FACTOR`] 1.5; the relaxation is taken without it
//!   (dynamic loads would pass the load on faster: a slower running-in counts more
//!   updates). It never falls below [`WORN_RATE_MARGIN`] times the largest settled rate
//!   (at most the initial one): deep worn profiles wear faster than the relaxed nominal
//!   one (measured).
//!
//! A pair outside eq. (7)'s domain (contact ratio not in (1, 2)), a helical pair and a
//! gear train keep their initial rate for the whole run (no running-in counted).

use crate::config::case::Case;
use crate::contact::load_sharing::pedrero_share_at;
use crate::dynamics::params::OperatingPoint;
use crate::geometry::GearPair;

/// How much faster than the settled rate a worn pair may wear, at most up to its initial
/// rate: the runs of `tests/budget_chains.rs` that wore deepest (k = 1.4e-14 and 2.5e-14
/// m^2/N, 62-63 um in 2e4-3.6e4 cycles) made 1.17-1.21 times the updates the settled
/// rate (with the dynamic margin) gives: the deep worn profile is not the nominal one
/// this model relaxes (its dynamic loads, the contact moving along the worn flank), not
/// modelled; 1.5 covers it.
pub const WORN_RATE_MARGIN: f64 = 1.5;

/// Points sampled along each zone of the path of contact.
const SAMPLES: usize = 48;

/// ISO 6336-1 mean mesh stiffness per face width c'_gamma ~ 20 N/(mm um), N/m^2: a lower
/// bound of the double-contact mesh stiffness (the mean over single and double contact).
const MESH_STIFFNESS_PER_WIDTH: f64 = 2e10;

/// Wear per pinion cycle per newton and unit k of the flank point at `rho1_m` (m per N
/// per m^2/N: module docs), 0 where a flank does not move forward (at the base circle).
fn alpha(pair: &GearPair, op: &OperatingPoint, rho1_m: f64) -> f64 {
    let rho2 = pair.rho_gear(rho1_m);
    let (up, ug) = (op.pinion_speed_rad_s * rho1_m, op.gear_speed_rad_s * rho2);
    if !(up > 0.0 && ug > 0.0) {
        return 0.0;
    }
    let ratio = pair.pinion.teeth as f64 / pair.gear.teeth as f64;
    4.0 * (up - ug).abs() * (1.0 / up).max(ratio / ug) / (std::f64::consts::PI * pair.face_width_m)
}

/// One approach point and the recess point a base pitch ahead, under a duty: their
/// initial rates (m per cycle and unit k, at the duty's shares), their alphas weighted
/// alike, and the transfer stiffness K_t (N/m).
#[derive(Debug, Clone, Copy, Default)]
struct Coupled {
    rate_a: f64,
    rate_b: f64,
    alpha_a: f64,
    alpha_b: f64,
    k_t: f64,
}

impl Coupled {
    /// The rate of relaxation of Delta per cycle and unit k, 1/(cycles m^2/N).
    fn lambda(&self) -> f64 {
        self.k_t * (self.alpha_a + self.alpha_b)
    }

    /// Delta to which the pair relaxes, m.
    fn settled(&self) -> f64 {
        let l = self.lambda();
        if l > 0.0 {
            (self.rate_a - self.rate_b) / l
        } else {
            0.0
        }
    }

    /// Delta after `kn` (k times cycles, m^2/N) from `delta0`, m.
    fn delta_after(&self, delta0: f64, kn: f64) -> f64 {
        let s = self.settled();
        s + (delta0 - s) * (-self.lambda() * kn).exp()
    }

    /// The rate both points settle at, m per cycle and unit k.
    fn settled_rate(&self) -> f64 {
        self.rate_at(self.settled())
    }

    /// The larger of the two points' rates at `delta`, m per cycle and unit k.
    fn rate_at(&self, delta: f64) -> f64 {
        let a = self.rate_a - self.k_t * self.alpha_a * delta;
        let b = self.rate_b + self.k_t * self.alpha_b * delta;
        a.max(b).max(0.0)
    }
}

/// The running-in of a duty (module docs): the single-contact points' largest rate and
/// the double-contact pairs, or a constant rate.
#[derive(Debug, Clone, Default)]
pub struct RunningIn {
    /// Largest rate of the single-contact points (or the constant rate), m per cycle and
    /// unit k, with the dynamic margin.
    single: f64,
    /// The double-contact pairs (without the margin; `margin` applies to their rates).
    pairs: Vec<Coupled>,
    /// The dynamic margin on the rates.
    margin: f64,
    /// The floor of the largest rate (margin included): [`WORN_RATE_MARGIN`] times the
    /// largest settled rate, at most the initial rate.
    floor: f64,
}

/// The state a run has reached: each double-contact pair's Delta (m), in the order of
/// [`RunningIn`]'s pairs (the same positions under every duty of one pair).
pub type Gaps = Vec<f64>;

impl RunningIn {
    /// A rate that does not change with wear, m per cycle and unit k (margin included).
    pub fn constant(rate_per_k: f64) -> RunningIn {
        RunningIn {
            single: rate_per_k,
            pairs: Vec::new(),
            margin: 1.0,
            floor: rate_per_k,
        }
    }

    /// The running-in of the duty of `bins` (share, the bin's case) on `pair` with the
    /// dynamic margin `margin`, or None when it does not apply (module docs).
    pub fn of_bins(pair: &GearPair, bins: &[(f64, Case)], margin: f64) -> Option<RunningIn> {
        let eps = pair.contact_ratio;
        if !(eps > 1.0 && eps < 2.0) {
            return None;
        }
        let pb = pair.base_pitch_m;
        let double = (eps - 1.0) * pb;
        let k_mesh = MESH_STIFFNESS_PER_WIDTH * pair.face_width_m;
        let mut pairs = vec![Coupled::default(); SAMPLES + 1];
        let mut singles = vec![0.0; SAMPLES + 1];
        for (share, c) in bins {
            let op = OperatingPoint::of(&c.operating, pair);
            let f = op.static_mesh_force_n;
            for (j, p) in pairs.iter_mut().enumerate() {
                let rho_a = pair.rho_start_m + double * j as f64 / SAMPLES as f64;
                let rho_b = rho_a + pb;
                let s_a = pedrero_share_at(pair, rho_a);
                let s_b = 1.0 - s_a;
                let (al_a, al_b) = (alpha(pair, &op, rho_a), alpha(pair, &op, rho_b));
                p.rate_a += share * al_a * f * s_a;
                p.rate_b += share * al_b * f * s_b;
                p.alpha_a += share * al_a;
                p.alpha_b += share * al_b;
                p.k_t = s_a * s_b * k_mesh;
            }
            for (i, r) in singles.iter_mut().enumerate() {
                let rho = pair.rho_start_m + double + (pb - double) * i as f64 / SAMPLES as f64;
                *r += share * alpha(pair, &op, rho) * f;
            }
        }
        // Every pair kept, even one slower than the single contact, so that the pairs of
        // two duties of one pair stay at the same positions (a run's gaps carry over).
        let single = singles.iter().fold(0.0, |a: f64, b| a.max(*b));
        let settled = pairs
            .iter()
            .map(Coupled::settled_rate)
            .fold(single, f64::max);
        let initial = pairs
            .iter()
            .map(|p| p.rate_a.max(p.rate_b))
            .fold(single, f64::max);
        Some(RunningIn {
            single: margin * single,
            pairs,
            margin,
            floor: margin * (WORN_RATE_MARGIN * settled).min(initial),
        })
    }

    /// New teeth: every pair's Delta 0.
    pub fn new_teeth(&self) -> Gaps {
        vec![0.0; self.pairs.len()]
    }

    /// Gaps reached after `kn` (k times cycles) from `from` under this duty.
    pub fn gaps_after(&self, from: &[f64], kn: f64) -> Gaps {
        self.pairs
            .iter()
            .enumerate()
            .map(|(j, p)| p.delta_after(from.get(j).copied().unwrap_or(0.0), kn))
            .collect()
    }

    /// The largest rate of the profiles after `kn` (k times cycles) from `from`, m per
    /// cycle and unit k.
    pub fn rate_after(&self, from: &[f64], kn: f64) -> f64 {
        self.pairs
            .iter()
            .enumerate()
            .map(|(j, p)| {
                self.margin * p.rate_at(p.delta_after(from.get(j).copied().unwrap_or(0.0), kn))
            })
            .fold(self.single.max(self.floor), f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::budget::evaluation::nominal_wear_per_cycle_m;

    fn built_in() -> (Case, GearPair) {
        let mut c = Case::default();
        c.wear.coefficient_m2_per_n = 1.0;
        let p = GearPair::from_case(&c.gear).unwrap();
        (c, p)
    }

    #[test]
    fn new_teeth_wear_at_the_nominal_rate_of_the_hertz_band() {
        // A second method: Archard's k p0 s with the Hertz band (`nominal_wear_per_cycle_m`,
        // p0 and a from Johnson's formulas) against alpha F (p0 2a = 4 F / (pi b)). The
        // two sample the path at other points (65 even points against each zone's 49), so
        // they agree to the rate's change between neighbouring samples: 2 %.
        let (c, p) = built_in();
        let r = RunningIn::of_bins(&p, &[(1.0, c.clone())], 1.0).unwrap();
        let nominal = nominal_wear_per_cycle_m(&c, &p);
        let initial = r.rate_after(&r.new_teeth(), 0.0);
        assert!(
            (initial / nominal - 1.0).abs() < 0.02,
            "{initial} vs {nominal}"
        );
    }

    #[test]
    fn a_pair_in_double_contact_settles_where_both_points_wear_alike() {
        // The closed form's settled Delta makes the two rates equal (the faster point has
        // passed load to the slower), at the alpha-weighted mean of the initial rates.
        let p = Coupled {
            rate_a: 3.0,
            rate_b: 1.0,
            alpha_a: 2.0,
            alpha_b: 0.5,
            k_t: 4.0,
        };
        let d = p.settled();
        let a = p.rate_a - p.k_t * p.alpha_a * d;
        let b = p.rate_b + p.k_t * p.alpha_b * d;
        assert!((a - b).abs() < 1e-12, "{a} {b}");
        assert!((a - (0.5 * 3.0 + 2.0 * 1.0) / 2.5).abs() < 1e-12);
        // Half-way in Delta after ln 2 / lambda.
        let half = p.delta_after(0.0, std::f64::consts::LN_2 / p.lambda());
        assert!((half / d - 0.5).abs() < 1e-12);
    }

    #[test]
    fn the_built_in_pair_runs_in_to_its_single_contact_rate() {
        // The largest rate never rises, and ends at or above the single contact's rate;
        // on the built-in pair it falls (the pinion's root in double contact is the
        // fastest point of new teeth, issue 33: 1.08 to 0.31 um per 1000 cycles over
        // the first 10 um at k = 2.5e-15 m^2/N in the quasi-static wear study).
        let (c, p) = built_in();
        let r = RunningIn::of_bins(&p, &[(1.0, c)], 1.0).unwrap();
        let new = r.new_teeth();
        let rates: Vec<f64> = (0..60)
            .map(|i| r.rate_after(&new, 1e-12 * 1.5f64.powi(i)))
            .collect();
        assert!(rates.windows(2).all(|w| w[1] <= w[0] * (1.0 + 1e-12)));
        let (first, last) = (r.rate_after(&new, 0.0), rates[rates.len() - 1]);
        assert!(last >= r.single * (1.0 - 1e-12));
        eprintln!(
            "built-in: {:.3e} to {:.3e} m per cycle per unit k ({:.2})",
            first,
            last,
            last / first
        );
        assert!(last < 0.8 * first, "{first} {last}");
    }
}
