//! One pair's share of the mesh force through its engagement (`report::pair_load`,
//! `gearwear stiffness`'s `pair_load.csv`): the nominal path's jumps and the corner
//! contact's continuous take-up, each against a fact that does not come from the curve's
//! own code.

use gearwear::config::case::ContactPathModel;
use gearwear::config::Case;
use gearwear::dynamics::contact_path::ContactPath;
use gearwear::dynamics::model::MAX_PAIRS;
use gearwear::report::pair_load::{pair_load_curve, PairLoadCurve};
use gearwear::study::Model;

fn curve(model: &Model, path: ContactPathModel) -> PairLoadCurve {
    let contact = ContactPath::new(&model.pair, path, MAX_PAIRS);
    let sys = model.system_with_contact(&contact, model.roughness.rms_um(0.0));
    pair_load_curve(model, &contact, &sys)
}

fn model(path: ContactPathModel) -> Model {
    let mut case = Case::default();
    case.contact.path = path;
    Model::from_case(&case).unwrap()
}

/// Largest change of the share between neighbouring positions (the points lie 1/720 of
/// a base pitch apart, 8 µm on the paper's pair).
fn largest_step(c: &PairLoadCurve) -> f64 {
    c.share
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .fold(0.0, f64::max)
}

#[test]
fn the_nominal_path_jumps_to_pedreros_third_at_both_ends() {
    // Pedrero's law (paper eq. 7) gives a pair 1/3 of the load at both ends of the path,
    // whatever the pair's geometry: the first and the last point of the nominal curve.
    // The equilibrium divides the force by the shares of eq. 7 and multiplies back: a few
    // ulps.
    let m = model(ContactPathModel::Nominal);
    let c = curve(&m, ContactPathModel::Nominal);
    let (first, last) = (c.share[0], c.share[c.share.len() - 1]);
    assert!((first - 1.0 / 3.0).abs() < 1e-12, "{first}");
    assert!((last - 1.0 / 3.0).abs() < 1e-3, "{last}");
    // The positions are the path's: A and E (the last sample stands 1/720 of a base pitch
    // short of E).
    assert!((c.rho1_m[0] - m.pair.rho_start_m).abs() < 1e-12);
    let pitch_step = m.pair.base_pitch_m / 720.0;
    assert!((m.pair.rho_end_m - c.rho1_m[c.rho1_m.len() - 1]).abs() <= pitch_step * (1.0 + 1e-9));
    // A jump of a third of the load from no load: the paper's model.
    assert!(largest_step(&c) > 0.3);
}

#[test]
fn corner_contact_takes_the_load_up_from_zero_before_a_and_gives_it_off_after_e() {
    let m = model(ContactPathModel::Extended);
    let c = curve(&m, ContactPathModel::Extended);
    let touching: Vec<(f64, f64)> = c
        .rho1_m
        .iter()
        .zip(&c.share)
        .filter(|p| *p.1 > 0.0)
        .map(|(r, s)| (*r, *s))
        .collect();
    let (first, last) = (touching[0], touching[touching.len() - 1]);
    // The corners touch beyond both ends of the path.
    assert!(first.0 < m.pair.rho_start_m, "{first:?}");
    assert!(last.0 > m.pair.rho_end_m, "{last:?}");
    // From zero: the first and the last touching points carry little (the gap closes
    // continuously; one 8 µm step of roll at the corner's steepest rise, 0.4 of the load
    // over about 0.3 mm, moves the share by about 0.01).
    assert!(first.1 < 0.02 && last.1 < 0.02, "{first:?} {last:?}");
    // Continuous everywhere: no step as large as the nominal path's third (the steepest
    // continuous part moves about 0.02 per point, see above; 0.05 leaves room and stays
    // far below 1/3).
    assert!(largest_step(&c) < 0.05, "{}", largest_step(&c));
    // Single contact in the middle carries everything.
    let max = c.share.iter().fold(0.0_f64, |a, b| a.max(*b));
    assert!((max - 1.0).abs() < 1e-9, "{max}");
}

#[test]
fn the_other_contact_model_of_a_model_is_that_model_built_on_its_own() {
    // The figure's second curve comes from the case's model with the other contact path:
    // it must be the curve of a model built with that path (same tables, same law).
    let ext = model(ContactPathModel::Extended);
    let nom = model(ContactPathModel::Nominal);
    assert_eq!(
        curve(&ext, ContactPathModel::Nominal),
        curve(&nom, ContactPathModel::Nominal)
    );
    assert_eq!(
        curve(&nom, ContactPathModel::Extended),
        curve(&ext, ContactPathModel::Extended)
    );
}
