//! The tabulated line force against the slice springs summed one by one
//! (`SliceMeshStiffness::add_line_slices`, a second route through the same slices).

use super::*;
use crate::config::case::{GearSection, MaterialsSection};
use crate::geometry::helical::{Hand, HelicalPair, HelixSpec};
use crate::stiffness::face_load::LeadGap;
use crate::stiffness::mesh::FilletSettings;
use crate::stiffness::potential_energy::ElasticPair;

fn model(hand: Hand, slices: usize) -> SliceMeshStiffness {
    let h = HelixSpec {
        helix_angle_deg: 15.0,
        hand_pinion: hand,
    };
    let p = HelicalPair::from_case(&GearSection::default(), &h).unwrap();
    let e = ElasticPair::from_case(&MaterialsSection::default());
    SliceMeshStiffness::new(&p, &e, slices, 200, Some(FilletSettings::lenient())).unwrap()
}

/// sum_j k_j (c - g_j)+ over the line's slices at trailing end rho, summed slice by slice.
fn direct(m: &SliceMeshStiffness, gaps: &[f64], rho: f64, c: f64) -> (f64, f64) {
    let mut k = vec![0.0; m.slices()];
    m.add_line_slices(&m.line_grid(), rho, &mut k);
    let f = k.iter().zip(gaps).map(|(k, g)| k * (c - g).max(0.0)).sum();
    let kt = k
        .iter()
        .zip(gaps)
        .filter(|(_, g)| **g < c)
        .map(|(k, _)| k)
        .sum();
    (f, kt)
}

#[test]
fn the_table_is_the_slice_sum_at_its_samples_and_close_between() {
    // A linear gap of 10 um with a 4 um crowning over the face; compressions across the
    // gaps' range. At the samples the table holds the same terms summed in gap order:
    // equal to 1e-12 relative (rounding of up to N additions). Between samples linear
    // interpolation spreads the one slice entering or leaving the path there (a step of
    // one slice's stiffness, 1/N of a line's) over the interval, and the slices' own
    // variation over L/N is smaller still: the error stays below 1.5 slices' force, so
    // 1.5 / N of the line's force at full contact.
    for hand in [Hand::Right, Hand::Left] {
        let m = model(hand, 80);
        let gap = LeadGap {
            crowning_m: 4e-6,
            slope_m: 10e-6,
            ..Default::default()
        };
        let gaps = gap.gaps_m(m.positions_m(), m.pair().face_width_m);
        let table = LineGapTable::new(&m, &gaps);
        let grid = m.line_grid();
        let full = direct(&m, &gaps, m.pair().transverse.rho_start_m, 20e-6).0;
        for i in (0..table.points()).step_by(7) {
            for c in [1e-6, 5e-6, 9e-6, 20e-6] {
                let rho = grid.line.rho_start_m + i as f64 * table.step_m;
                let (f, k) = table.force(rho, c, false);
                let (fd, kd) = direct(&m, &gaps, rho, c);
                assert!((f - fd).abs() <= 1e-12 * full, "{hand:?} rho {rho} c {c}");
                assert!((k - kd).abs() <= 1e-12 * kd.max(1.0));
                let mid = rho + 0.5 * table.step_m;
                if i + 1 < table.points() {
                    let (f, _) = table.force(mid, c, false);
                    let (fd, _) = direct(&m, &gaps, mid, c);
                    assert!((f - fd).abs() <= 1.5 / 80.0 * full, "{f} {fd}");
                }
            }
        }
    }
}

#[test]
fn below_the_first_gap_a_line_carries_nothing_unless_held_in_contact() {
    let m = model(Hand::Right, 40);
    let gap = LeadGap {
        slope_m: 10e-6,
        ..Default::default()
    };
    let gaps = gap.gaps_m(m.positions_m(), m.pair().face_width_m);
    let table = LineGapTable::new(&m, &gaps);
    let rho = m.pair().transverse.rho_start_m;
    assert_eq!(table.force(rho, -1e-6, false), (0.0, 0.0));
    // Held in contact: the first slice's spring continues below its gap (0 here).
    let (f, k) = table.force(rho, -1e-6, true);
    assert!(k > 0.0 && (f + 1e-6 * k).abs() <= 1e-12 * k);
}
