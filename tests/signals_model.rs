//! The signal chain on the paper's case: a steady state recorded, analysed.

use gearwear::config::Case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::signals::setup::chain_of;
use gearwear::study::signal_record::steady_record;
use gearwear::study::Model;
use gearwear::wear::WearState;

#[test]
fn the_paper_case_records_its_mesh_harmonics_and_a_periodic_tsa() {
    let case = Case::default();
    let model = Model::from_case(&case).unwrap();
    let setup = chain_of(&case, None, case.operating.input_speed_hz).unwrap();
    let rec = steady_record(
        &model,
        &setup,
        &WearState::new(model.grid.len()),
        &ExternalError::none(),
    )
    .unwrap();
    assert_eq!(rec.record.len(), 25_600);
    for ch in &rec.analysis {
        let ind = ch.indicators();
        println!("{}", serde_json::to_string_pretty(&ind).unwrap());
        let p = ind.pinion.unwrap();
        let g = ind.gear.unwrap();
        // 1 s at 30 Hz: 29 complete pinion revolutions after the first pulse, 17 of the gear.
        assert!(
            p.revolutions >= 28 && g.revolutions >= 16,
            "{} {}",
            p.revolutions,
            g.revolutions
        );
        // Identical teeth: the response repeats every mesh period, so the TSA holds mesh
        // harmonics only (no sidebands): the sideband index is round-off of the TSA.
        assert!(p.sideband_index < 1e-6 * p.tsa_rms, "{}", p.sideband_index);
        // The whole TSA is regular meshing components: ER ~ 0.
        assert!(p.energy_ratio < 1e-4, "{}", p.energy_ratio);
    }
}
