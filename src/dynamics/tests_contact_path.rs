//! Tests of `dynamics::contact_path`.

use super::*;
use crate::config::case::{GearSection, MaterialsSection};
use crate::stiffness::potential_energy::ElasticPair;

fn parts() -> (GearPair, MeshStiffness) {
    let p = GearPair::from_case(&GearSection::default()).unwrap();
    let e = ElasticPair::from_case(&MaterialsSection::default());
    let m = MeshStiffness::new(&p, &e, 400, true).unwrap();
    (p, m)
}

#[test]
fn the_nominal_model_is_the_path_tables_bit_for_bit() {
    let (p, m) = parts();
    let cp = ContactPath::new(&p, ContactPathModel::Nominal, 4);
    assert_eq!(cp.reach(), p.nominal_reach());
    let gap = PairGap::from_flanks(p.rho_start_m, 1e-4, vec![1e-6, 2e-6, 0.5e-6], vec![0.0; 3]);
    for i in 0..=100 {
        // Slightly outside too: positions follow the phase, the set the decision.
        let rho = p.rho_start_m - 1e-9 + (p.path_length_m() + 2e-9) * i as f64 / 100.0;
        let pp = cp.plain_pair(&m, &gap, rho);
        assert_eq!(pp.stiffness_n_per_m, m.pair_stiffness_n_per_m(rho));
        assert_eq!((pp.gap_m, pp.gap_slope), gap.at(rho));
        assert_eq!(pp.contact_rho1_m, rho);
        assert!(!pp.corner);
    }
}

#[test]
fn the_corner_pair_continues_the_path_pair_at_both_ends() {
    // Approaching an end from outside, the corner's gap tends to zero (quadratically: it
    // starts flat) and its spring to the path pair's at that end (the two teeth loaded at
    // the same conjugate point): continuous to the splines' 1e-6.
    let (p, m) = parts();
    let cp = ContactPath::new(&p, ContactPathModel::Extended, 4);
    let gap = PairGap::none();
    for (end, out) in [(p.rho_start_m, -1.0), (p.rho_end_m, 1.0)] {
        let k_end = m.pair_stiffness_n_per_m(end);
        for d in [1e-6, 1e-5, 1e-4] {
            let c = cp.plain_pair(&m, &gap, end + out * d);
            assert!(c.corner);
            // g ~ d^2 / (2 R), R = 5.8 mm (approach) and 9.9 mm (recess) on this pair
            // (geometry::corner tests: 21.7 and 12.7 um at 0.5 mm).
            assert!(c.gap_m > 0.0 && c.gap_m < 100.0 * d * d, "{d}: {}", c.gap_m);
            assert!((c.stiffness_n_per_m / k_end - 1.0).abs() < 1e-6 + 2.0 * d / 1e-3);
            assert_eq!(c.contact_rho1_m, end);
        }
        let on = cp.plain_pair(&m, &gap, end);
        assert!(!on.corner && on.gap_m == 0.0);
    }
}

#[test]
fn the_reach_ends_where_the_corners_stand_a_tenth_of_a_module_off() {
    let (p, m) = parts();
    let cp = ContactPath::new(&p, ContactPathModel::Extended, 4);
    let r = cp.reach();
    let gap = PairGap::none();
    for rho in [r.start_m, r.end_m] {
        let c = cp.plain_pair(&m, &gap, rho);
        assert!(
            (c.gap_m / (0.1 * p.module_m) - 1.0).abs() < 1e-9,
            "{}",
            c.gap_m
        );
    }
    // It holds at most 4 pairs (3 base pitches), and so at most 3 on this pair.
    assert!(r.end_m - r.start_m < 3.0 * p.base_pitch_m);
    // With room for three pairs only, the extension shrinks to fit.
    let small = ContactPath::new(&p, ContactPathModel::Extended, 3).reach();
    let spare = 2.0 * p.base_pitch_m - p.path_length_m();
    assert!(small.end_m - small.start_m <= p.path_length_m() + spare + 1e-12);
}

#[test]
fn a_corner_meets_each_flanks_wear_where_it_touches_it() {
    // Pinion wear growing along its flank, gear wear a different profile: the corner's
    // gap is its geometric gap plus the pinion's wear at the touched point and the gear's
    // at its tip (approach), each read off its own table.
    let (p, m) = parts();
    let cp = ContactPath::new(&p, ContactPathModel::Extended, 4);
    let n = 11;
    let h = p.path_length_m() / (n - 1) as f64;
    let pinion: Vec<f64> = (0..n).map(|i| 1e-6 * i as f64).collect();
    let gear: Vec<f64> = (0..n).map(|i| 3e-6 - 0.2e-6 * i as f64).collect();
    let worn = PairGap::from_flanks(p.rho_start_m, h, pinion.clone(), gear.clone());
    let rho = p.rho_start_m - 0.3e-3;
    let geo = cp.place(rho, None, None).unwrap();
    let c = cp.plain_pair(&m, &worn, rho);
    let u = (geo.pinion_rho1_m - p.rho_start_m) / h;
    let i = u.floor() as usize;
    let pin = pinion[i] + (pinion[i + 1] - pinion[i]) * (u - i as f64);
    assert!((c.gap_m - (geo.gap_m + pin + gear[0])).abs() < 1e-18);
    // Past the end: the pinion's tip (its last point) and the gear's touched point.
    let rho = p.rho_end_m + 0.3e-3;
    let geo = cp.place(rho, None, None).unwrap();
    let c = cp.plain_pair(&m, &worn, rho);
    let u = (geo.gear_rho1_m - p.rho_start_m) / h;
    let i = u.floor() as usize;
    let gr = gear[i] + (gear[i + 1] - gear[i]) * (u - i as f64);
    assert!((c.gap_m - (geo.gap_m + pinion[n - 1] + gr)).abs() < 1e-18);
}

#[test]
fn a_broken_tip_touches_with_its_cut_on_the_extended_model_only() {
    let (p, m) = parts();
    let _ = m;
    let cut = p.rho_end_m - 1.0e-3;
    let tip = Some(TipCorner::sharp(cut));
    let nominal = ContactPath::new(&p, ContactPathModel::Nominal, 4);
    assert!(nominal.place(cut + 0.2e-3, tip, None).is_none());
    assert!(!nominal.place(cut - 0.2e-3, tip, None).unwrap().corner);
    let extended = ContactPath::new(&p, ContactPathModel::Extended, 4);
    let beyond = extended.place(cut + 0.2e-3, tip, None).unwrap();
    assert!(beyond.corner && beyond.pinion_rho1_m == cut);
    // The cut's corner, like the tip's, starts flat from zero at its own end.
    let at = extended.place(cut + 1e-7, tip, None).unwrap();
    assert!(at.gap_m < 1e-12);
}
