//! Fuzz target: an observations file for `gearwear calibrate` (arbitrary bytes as CSV).
//! It must parse or be refused with messages, never panic; what parses must satisfy the
//! documented bounds (rows, cycles in order and in range, finite values and sigmas in
//! range), and the budget estimate of a calibration on it must be finite.
//! Run: scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

use gearwear::config::Case;
use gearwear::study::budget::{estimate_calibration, CalibrationJob};
use gearwear::prognostics::observations::{
    parse_observations, MAX_CYCLES, MAX_ROWS, MAX_VALUE, SIGMA_RANGE,
};
use gearwear::prognostics::Prior;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let Ok(obs) = parse_observations(&text, "obs.csv") else {
        return;
    };
    assert!(!obs.is_empty() && obs.len() <= MAX_ROWS * obs.series.len());
    for s in &obs.series {
        assert!(!s.values.is_empty());
        assert!(s.cycles.windows(2).all(|w| w[0] <= w[1]));
        assert!(s.cycles.iter().all(|c| (0.0..=MAX_CYCLES).contains(c)));
        assert!(s.values.iter().all(|v| v.abs() <= MAX_VALUE));
        if let Some(sig) = &s.sigma {
            assert_eq!(sig.len(), s.values.len());
            assert!(sig.iter().all(|x| (SIGMA_RANGE.0..=SIGMA_RANGE.1).contains(x)));
        }
    }
    let case = Case::default();
    let prior = Prior::from_case(&case).expect("the built-in prior");
    let e = estimate_calibration(
        &case,
        &prior,
        &CalibrationJob {
            values: obs.len(),
            quantities: obs.series.len(),
            max_cycles: obs.max_cycles(),
            samples: 2000,
            walkers: 32,
            steps: 2000,
            check_runs: 3,
            check_depth_bound_m: None,
        },
    );
    assert!(e.seconds().is_finite() && e.memory_bytes().is_finite());
});
