//! Tests of `geometry::corner` against a direct construction: the two involutes placed at
//! the pair's position from their polar form, the tip (and its rounding, found as the
//! circle tangent to the tip circle and the involute by bisection), and the smallest
//! distance between corner and flank found numerically. Nothing here uses the module's
//! involute labels.

use super::*;
use crate::config::case::GearSection;

type P = [f64; 2];

fn dist(a: P, b: P) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// One involute placed in the plane: centre, base radius, the polar angle of its start
/// and the sense in which its polar angle grows with the roll length.
#[derive(Clone, Copy)]
struct Involute {
    centre: P,
    rb: f64,
    start: f64,
    sense: f64,
}

impl Involute {
    /// Point at roll length s (radius sqrt(rb^2 + s^2), polar angle start +- inv).
    fn at(&self, s: f64) -> P {
        let r = self.rb.hypot(s);
        let a = self.start + self.sense * (s / self.rb - (s / self.rb).atan());
        [self.centre[0] + r * a.cos(), self.centre[1] + r * a.sin()]
    }

    /// The involute of (centre, rb) through `x` at roll length `s`, in the sense whose
    /// normal there is along `normal` (the line of action): the other sense is rejected
    /// by its tangent.
    fn through(centre: P, rb: f64, x: P, s: f64, normal: P) -> Self {
        let arg = (x[1] - centre[1]).atan2(x[0] - centre[0]);
        let inv = s / rb - (s / rb).atan();
        [1.0, -1.0]
            .into_iter()
            .map(|sense| Involute {
                centre,
                rb,
                start: arg - sense * inv,
                sense,
            })
            .min_by(|a, b| {
                let t = |i: &Involute| {
                    let (p, q) = (i.at(s + 1e-7), i.at(s - 1e-7));
                    ((p[0] - q[0]) * normal[0] + (p[1] - q[1]) * normal[1]).abs()
                };
                t(a).total_cmp(&t(b))
            })
            .unwrap()
    }

    /// Unit normal at roll length s from the curve's tangent, turned towards `side`.
    fn normal_towards(&self, s: f64, side: P) -> P {
        let (p, q) = (self.at(s + 1e-8), self.at(s - 1e-8));
        let t = [p[0] - q[0], p[1] - q[1]];
        let n = t[0].hypot(t[1]);
        let mut nn = [-t[1] / n, t[0] / n];
        if nn[0] * side[0] + nn[1] * side[1] < 0.0 {
            nn = [-nn[0], -nn[1]];
        }
        nn
    }
}

/// Minimum of a unimodal f on [a, b] by golden section, to the last bit of b - a.
fn golden(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let x = 0.5 * (a + b);
    (x, f(x))
}

/// Smallest distance from point c to the involute over rolls [0, s_max]: a scan, then
/// golden section around the best sample.
fn distance_to(inv: &Involute, c: P, s_max: f64) -> (f64, f64) {
    let n = 4000;
    let f = |s: f64| dist(inv.at(s), c);
    let best = (0..=n)
        .min_by(|i, j| f(*i as f64 * s_max / n as f64).total_cmp(&f(*j as f64 * s_max / n as f64)))
        .unwrap();
    let h = s_max / n as f64;
    golden(f, (best as f64 - 1.0).max(0.0) * h, (best as f64 + 1.0) * h)
}

struct Placed {
    pinion: Involute,
    gear: Involute,
    loa_dir: P,
}

/// Both flanks of the pair at rho1, placed from the frame's definition: line of action
/// from N1 along u, the pinion involute and the gear involute through the point rho1
/// from N1 at rolls rho1 and L - rho1.
fn place(p: &GearPair, rho1: f64) -> Placed {
    let aw = p.operating_pressure_angle_rad;
    let (rb1, rb2) = (p.pinion.base_radius_m, p.gear.base_radius_m);
    let o2 = [p.centre_distance_m, 0.0];
    let n1 = [rb1 * aw.cos(), rb1 * aw.sin()];
    let u = [aw.sin(), -aw.cos()];
    let x = [n1[0] + rho1 * u[0], n1[1] + rho1 * u[1]];
    Placed {
        pinion: Involute::through([0.0, 0.0], rb1, x, rho1, u),
        gear: Involute::through(o2, rb2, x, p.loa_length_m - rho1, u),
        loa_dir: u,
    }
}

/// Centre of the rounding of radius r_t tangent to the tip circle (radius ra about the
/// involute's centre) and to the involute, inside the tooth (away from `mate_side`):
/// bisection on the roll length where the inward offset point lies at ra - r_t.
fn rounding_centre(inv: &Involute, ra: f64, r_t: f64, mate_side: P) -> P {
    let offset = |s: f64| {
        let q = inv.at(s);
        let n = inv.normal_towards(s, mate_side);
        [q[0] - r_t * n[0], q[1] - r_t * n[1]]
    };
    let f = |s: f64| dist(offset(s), inv.centre) - (ra - r_t);
    let (mut a, mut b) = (0.01 * inv.rb, 1.05 * (ra * ra - inv.rb * inv.rb).sqrt());
    assert!(f(a) < 0.0 && f(b) > 0.0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if f(m) < 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    offset(0.5 * (a + b))
}

fn pairs() -> Vec<GearPair> {
    let shifted = GearSection {
        profile_shift_pinion: 0.3,
        profile_shift_gear: -0.1,
        ..Default::default()
    };
    let other = GearSection {
        teeth_pinion: 24,
        teeth_gear: 57,
        pressure_angle_deg: 25.0,
        centre_distance_mm: Some(81.6),
        ..Default::default()
    };
    [GearSection::default(), shifted, other]
        .iter()
        .map(|g| GearPair::from_case(g).unwrap())
        .collect()
}

#[test]
fn corner_gap_is_the_smallest_distance_between_corner_and_flank() {
    // The direct construction's distance agrees with the module's closed form to 1e-9 m
    // (the bound; the golden section resolves the minimum's value to ~1e-15 m
    // since the distance is flat there), for sharp and rounded tips, on both sides of the
    // path, over 0-1.5 mm beyond its ends, on three pairs.
    for p in pairs() {
        let cg = CornerGeometry::new(&p);
        let (rb1, rb2) = (p.pinion.base_radius_m, p.gear.base_radius_m);
        for r_t in [0.0, 0.1 * p.module_m, 0.25 * p.module_m] {
            let gear_tip = TipCorner::rounded(rb2, p.gear.tip_radius_m, r_t);
            let pinion_tip = TipCorner::rounded(rb1, p.pinion.tip_radius_m, r_t);
            // The rounding shortens the involute: the path ends where it starts.
            let start = p.loa_length_m - gear_tip.involute_end_rho_m;
            let end = pinion_tip.involute_end_rho_m;
            for d_mm in [0.02, 0.1, 0.3, 0.7, 1.5] {
                let d = d_mm * 1e-3;
                // Approach: the gear's rounding against the pinion flank.
                let pl = place(&p, start - d);
                let away = [-pl.loa_dir[0], -pl.loa_dir[1]];
                let c = rounding_centre(&pl.gear, p.gear.tip_radius_m, r_t, away);
                let (_, direct) = distance_to(&pl.pinion, c, p.pinion.tip_rho_m());
                let got = cg.approach(gear_tip, start - d).expect("within the corner");
                assert!(
                    (got.gap_m - (direct - r_t)).abs() < 1e-9,
                    "approach r_t {r_t} d {d}: {} vs {}",
                    got.gap_m,
                    direct - r_t
                );
                // Recess: the pinion's rounding against the gear flank.
                let pl = place(&p, end + d);
                let c = rounding_centre(&pl.pinion, p.pinion.tip_radius_m, r_t, pl.loa_dir);
                let (_, direct) = distance_to(&pl.gear, c, p.gear.tip_rho_m());
                let got = cg.recess(pinion_tip, end + d).expect("within the corner");
                assert!(
                    (got.gap_m - (direct - r_t)).abs() < 1e-9,
                    "recess r_t {r_t} d {d}: {} vs {}",
                    got.gap_m,
                    direct - r_t
                );
                assert!(got.gap_m > 0.0);
            }
        }
    }
}

#[test]
fn the_gap_closes_at_the_ends_of_the_path_and_the_mate_is_touched_where_it_is_found() {
    for p in pairs() {
        let cg = CornerGeometry::new(&p);
        let gear_tip = TipCorner::sharp(p.gear.tip_rho_m());
        let pinion_tip = TipCorner::sharp(p.pinion.tip_rho_m());
        let a = cg.approach(gear_tip, p.rho_start_m).unwrap();
        let e = cg.recess(pinion_tip, p.rho_end_m).unwrap();
        // At A the gear tip lies on the line of action, on the pinion flank at rho_A.
        assert!(
            a.gap_m.abs() < 1e-15 && e.gap_m.abs() < 1e-15,
            "{a:?} {e:?}"
        );
        assert!((a.mate_rho_m - p.rho_start_m).abs() < 1e-12);
        assert!((e.mate_rho_m - p.rho_gear(p.rho_end_m)).abs() < 1e-12);
        // The tip slides along its mate: the gap starts flat (no first-order term).
        assert!(a.gap_slope.abs() < 1e-9 && e.gap_slope.abs() < 1e-9);
        // Beyond, the touched point is the flank point nearest the corner (scan).
        let d = 0.4e-3;
        let pl = place(&p, p.rho_start_m - d);
        let c = pl.gear.at(p.gear.tip_rho_m());
        let (s, _) = distance_to(&pl.pinion, c, p.pinion.tip_rho_m());
        let got = cg.approach(gear_tip, p.rho_start_m - d).unwrap();
        assert!(
            (got.mate_rho_m - s).abs() < 1e-7,
            "{} vs {s}",
            got.mate_rho_m
        );
    }
}

#[test]
fn gap_slope_is_the_derivative_of_the_gap() {
    // Central differences with h = 1e-7 m: truncation ~h^2 g''' ~ 1e-12, round-off
    // ~1e-16 m / h = 1e-9; bound 1e-6. Likewise the touched point's rate.
    let p = GearPair::from_case(&GearSection::default()).unwrap();
    let cg = CornerGeometry::new(&p);
    let h = 1e-7;
    for r_t in [0.0, 0.2e-3] {
        let gt = TipCorner::rounded(p.gear.base_radius_m, p.gear.tip_radius_m, r_t);
        let pt = TipCorner::rounded(p.pinion.base_radius_m, p.pinion.tip_radius_m, r_t);
        for d in [0.05e-3, 0.5e-3, 1.5e-3] {
            let fd = |f: &dyn Fn(f64) -> f64, rho: f64| (f(rho + h) - f(rho - h)) / (2.0 * h);
            let rho = p.rho_start_m - d;
            let c = cg.approach(gt, rho).unwrap();
            assert!((c.gap_slope - fd(&|r| cg.approach(gt, r).unwrap().gap_m, rho)).abs() < 1e-6);
            let mate = fd(&|r| cg.approach(gt, r).unwrap().mate_rho_m, rho);
            assert!(
                (c.mate_rho_slope - mate).abs() < 1e-6,
                "{} {mate}",
                c.mate_rho_slope
            );
            let rho = p.rho_end_m + d;
            let c = cg.recess(pt, rho).unwrap();
            assert!((c.gap_slope - fd(&|r| cg.recess(pt, r).unwrap().gap_m, rho)).abs() < 1e-6);
            let mate = fd(&|r| cg.recess(pt, r).unwrap().mate_rho_m, rho);
            assert!(
                (c.mate_rho_slope - mate).abs() < 1e-6,
                "{} {mate}",
                c.mate_rho_slope
            );
        }
    }
}

#[test]
fn the_reach_ends_where_the_gap_reaches_its_limit() {
    let p = GearPair::from_case(&GearSection::default()).unwrap();
    let cg = CornerGeometry::new(&p);
    let gt = TipCorner::sharp(p.gear.tip_rho_m());
    let pt = TipCorner::sharp(p.pinion.tip_rho_m());
    let ends = (p.rho_start_m, p.rho_end_m);
    let r = cg.reach(gt, pt, ends, 200e-6, p.base_pitch_m);
    let a = cg.approach(gt, r.start_m).unwrap().gap_m;
    let e = cg.recess(pt, r.end_m).unwrap().gap_m;
    assert!(
        (a - 200e-6).abs() < 1e-12 && (e - 200e-6).abs() < 1e-12,
        "{a} {e}"
    );
    // The gap grows monotonically over the reach (bisection was valid).
    for i in 1..100 {
        let d = |i: usize| (p.rho_start_m - r.start_m) * i as f64 / 100.0;
        let g = |i: usize| cg.approach(gt, p.rho_start_m - d(i)).unwrap().gap_m;
        assert!(g(i) > g(i - 1));
    }
    // A short cap wins.
    let r = cg.reach(gt, pt, ends, 200e-6, 0.1e-3);
    assert!((p.rho_start_m - r.start_m - 0.1e-3).abs() < 1e-15);
    assert!((r.end_m - p.rho_end_m - 0.1e-3).abs() < 1e-15);
}
