//! Fuzz target: a dataset record's sidecar (`records/<id>.json`; arbitrary bytes) read as
//! a resume or a merge reads it (`app::dataset::folder::parse_sidecar`), its identity
//! checked against a real dataset's description (`matches_design`), then put in place of
//! that dataset's record of the same id and the index, trends table and trends figure
//! built (`index_tables`, as `stage_index_and_metadata` does). Twice: as parsed, and with
//! the identity (condition, labels, state, speed, load, realisation, seed, file) the
//! design gives its id (with the real channel names where the channel count is the
//! real one), as a forger would write it, so that the free fields (wear, cycles,
//! indicator values) reach the index whatever they are. The
//! recomputation of the record on resume is left out (a record per input).
//! Seeds and fixtures: fuzz/seeds/dataset_sidecar (two real small datasets,
//! `dataset_common`). Run: FUZZ_TARGET=dataset_sidecar scripts/fuzz.sh
//! (docs/RELIABILITY.md).

#![no_main]

mod dataset_common;

use dataset_common::{index_and_trends, real_descriptions, real_sidecars};
use gearwear::app::dataset::folder::{parse_sidecar, Sidecar};
use gearwear::app::dataset::index_files::matches_design;
use libfuzzer_sys::fuzz_target;

/// The real sidecars of the dataset `body` describes, the one of `car`'s id replaced by
/// `car` (a folder holds one sidecar per id).
fn folder_with(car: &Sidecar, key: &str) -> Vec<Sidecar> {
    let mut cars: Vec<Sidecar> = real_sidecars()
        .iter()
        .filter(|s| s.dataset_key == key && s.labels.record_id != car.labels.record_id)
        .cloned()
        .collect();
    cars.push(car.clone());
    cars
}

fuzz_target!(|data: &[u8]| {
    let Some(car) = parse_sidecar(data) else {
        return;
    };
    for body in real_descriptions() {
        let key = body["dataset_key"].as_str().expect("a real key");
        let total = body["records"].as_u64().expect("a real count") as usize;
        let _ = matches_design(&car.labels, body);
        index_and_trends(folder_with(&car, key), body, total);
        // The same free fields under the identity the design gives a real record's id.
        let Some(real) = real_sidecars()
            .iter()
            .filter(|s| s.dataset_key == key)
            .nth(car.labels.record_id % total)
        else {
            continue;
        };
        let mut forged = car.clone();
        forged.dataset_key = key.to_owned();
        let (f, r) = (&mut forged.labels, &real.labels);
        f.record_id = r.record_id;
        f.file = r.file.clone();
        f.condition = r.condition.clone();
        f.fault = r.fault.clone();
        f.severity = r.severity;
        f.trajectory_state = r.trajectory_state;
        f.input_speed_hz = r.input_speed_hz;
        f.load_torque_nm = r.load_torque_nm;
        f.realisation = r.realisation;
        f.noise_seed = r.noise_seed;
        // The channels are the sensors' names (part of the identity): given where the
        // record has as many channels as the real one, the values left as fuzzed.
        let same_count = f.indicators.len() == r.indicators.len();
        if same_count {
            for (c, rc) in f.indicators.iter_mut().zip(&r.indicators) {
                c.channel = rc.channel.clone();
            }
        }
        assert_eq!(matches_design(&forged.labels, body), same_count);
        index_and_trends(folder_with(&forged, key), body, total);
    }
});
