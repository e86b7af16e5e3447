//! The cost of a planetary set's wear study (`[planetary]`, `study::planetary_wear_loop`):
//! its updates counted from the set's own first wear rate, each a response of the whole
//! set at a measured rate.

use super::cost::{Estimate, Term};
use super::evaluation::SLOWER_MACHINE_FACTOR;
use crate::config::case::WearSection;
use crate::study::planetary_teeth::faulty_member;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use crate::study::wear_loop::{block_length, WearMode};

/// CPU seconds of one dynamic update of a four-planet set (its steady state from rest,
/// the meshes' paths and increments): measured 0.19 s (the default set's study to 4e4
/// carrier revolutions, 19 updates in 3.7 s; the bench's 0.32 s a cold update was under
/// load 7), counted 0.25 s, times the planets over four and [`SLOWER_MACHINE_FACTOR`].
const SECONDS_PER_DYNAMIC_UPDATE_4: f64 = 0.25;
/// CPU seconds of one quasi-static update of a four-planet set: measured 1.5 ms (the
/// default set's study, 28.6 ms in the bench), counted 2 ms.
const SECONDS_PER_QUASI_STATIC_UPDATE_4: f64 = 2e-3;
/// The dynamic loads' margin on the quasi-static wear rate: Archard's wear per contact
/// is k p s, with the Hertz pressure p and the sliding distance s = 2 a |du| / u each
/// growing as F^(1/2) through the half-width a, so the wear grows as the load F; the
/// dynamic factor of a set is about 1.1-1.5 at the built-in speeds, and 2 covers one up
/// to 2.
const RATE_MARGIN: f64 = 2.0;
/// Bytes a kept update holds per mesh and profile point: a mesh's two profiles, each
/// with its wear, increment and path samples (about 6 numbers of 8 bytes a point,
/// doubled for vector growth).
const BYTES_PER_MESH_POINT: f64 = 2.0 * 6.0 * 8.0 * 2.0;

/// The estimate of a planetary wear study in the given modes: the updates U = 1 +
/// ceil(C / n), n being `wear.block_cycles` cut by `wear.threshold_um` over the set's
/// first quasi-static wear rate per input cycle (its deepest member flank) times
/// `RATE_MARGIN` (paper eq. 17, as the loop cuts it); each update at the measured
/// rates. The first rate is computed here (one quasi-static response, milliseconds).
/// Not counted: a set whose steady state is hard to find (a lightly loaded mesh near
/// contact loss took 40 s of CPU an update against 0.2 s; docs/MODEL.md 12.9).
pub fn estimate_planetary_wear(
    model: &PlanetaryWearModel,
    wear: &WearSection,
    modes: &[WearMode],
) -> Estimate {
    let updates = planetary_wear_updates(model, wear);
    let meshes = 2.0 * model.planets() as f64;
    let points = wear.points_per_profile.max(2) as f64;
    let mut terms = vec![Term {
        what: "the planetary set's wear updates (a response of the whole set each)",
        seconds: updates * seconds_per_update(model, modes),
        bytes: modes.len() as f64 * updates * meshes * points * BYTES_PER_MESH_POINT,
        keys: &[
            "wear.total_cycles",
            "wear.block_cycles",
            "wear.threshold_um",
            "wear.points_per_profile",
            "planetary.planets",
        ],
    }];
    terms.extend(wear_fault_term(model, modes, updates));
    Estimate::of_terms(terms)
}

/// The wear study's term for a set with a tooth fault (docs/MODEL.md 12.15; None
/// without one): each dynamic update integrates, beyond the healthy set's search, a
/// run-in and at least one pass over the fault's period P mesh periods, counted 3 P
/// periods (as [`fault_term`]) of S_d steps (`evaluation::dynamic_steps_per_period`,
/// from the model's settings) at [`SECONDS_PER_STEP_4`] times the planets' share and
/// [`SLOWER_MACHINE_FACTOR`]; each quasi-static update P times the healthy one's
/// equilibria; each mode's response of P periods (its states, [q, q'] of the 3 (N + 3)
/// coordinates, and 2 N mesh forces per sample) held at once while its meshes wear.
/// Measured on the built-in set with a sun tooth crack (P = 24, 2026-11-30): a dynamic
/// update took 1.3 s of CPU more than the healthy one (47 913 steps, 47 mesh periods),
/// counted here 4.0 s.
fn wear_fault_term(model: &PlanetaryWearModel, modes: &[WearMode], updates: f64) -> Option<Term> {
    let p = model.periods();
    if p <= 1 {
        return None;
    }
    let s = &model.dynamics.settings;
    let s_dyn = (s.samples_per_period as f64).max(super::evaluation::adaptive_steps_per_period(
        s.integration_tolerance,
    ));
    let planets = model.planets() as f64;
    let per_step = SECONDS_PER_STEP_4 * (planets + 3.0) / 7.0 * SLOWER_MACHINE_FACTOR;
    let scale = planets / 4.0 * SLOWER_MACHINE_FACTOR;
    let per_update: f64 = modes
        .iter()
        .map(|m| match m {
            WearMode::Dynamic => 3.0 * p as f64 * s_dyn * per_step,
            WearMode::QuasiStatic => (p - 1) as f64 * SECONDS_PER_QUASI_STATIC_UPDATE_4 * scale,
        })
        .sum();
    // The dynamic retry (`PlanetaryWearModel::force_history`) records twice the samples.
    let values = 6.0 * (planets + 3.0) + 2.0 * planets + 1.0;
    let samples = 2.0 * p as f64 * s.samples_per_period as f64;
    let modes_n = modes.len() as f64;
    Some(Term {
        what: "the planetary set's tooth fault in its wear (every update's response over the fault's period, z_s, z_p or z_r mesh periods)",
        seconds: updates * per_update,
        bytes: modes_n * samples * values * BYTES_PER_SAMPLE_VALUE
            + modes_n * updates * tooth_profile_numbers(model) * 8.0 * 2.0,
        keys: &[
            "planetary.fault.gear",
            "planetary.teeth_sun",
            "planetary.teeth_planet",
            "planetary.teeth_ring",
            "numerics.steps_per_mesh_period",
            "wear.total_cycles",
        ],
    })
}

/// CPU seconds of one update of the set in every one of `modes`, at the measured rates
/// scaled by the planets over four and [`SLOWER_MACHINE_FACTOR`].
fn seconds_per_update(model: &PlanetaryWearModel, modes: &[WearMode]) -> f64 {
    let scale = model.planets() as f64 / 4.0 * SLOWER_MACHINE_FACTOR;
    modes
        .iter()
        .map(|m| match m {
            WearMode::Dynamic => SECONDS_PER_DYNAMIC_UPDATE_4,
            WearMode::QuasiStatic => SECONDS_PER_QUASI_STATIC_UPDATE_4,
        })
        .sum::<f64>()
        * scale
}

/// The updates U a planetary wear study makes at most (see [`estimate_planetary_wear`]).
pub fn planetary_wear_updates(model: &PlanetaryWearModel, wear: &WearSection) -> f64 {
    // A set whose first response fails stops at once in the run, which names why
    // (contact loss, no steady state): counted at the blocks' length alone.
    let rate = first_flank_rates(model, wear).map_or(0.0, |flanks| {
        flanks.iter().flatten().fold(0.0_f64, |a, b| a.max(*b))
    });
    updates_at_rate(rate, wear)
}

/// Every member flank's wear per input cycle at every point with new teeth, from one
/// quasi-static response of the set (milliseconds); None when it fails.
fn first_flank_rates(model: &PlanetaryWearModel, wear: &WearSection) -> Option<Vec<Vec<f64>>> {
    let first = WearSection {
        total_cycles: 0.0,
        ..wear.clone()
    };
    run_planetary_wear(
        model,
        &first,
        PlanetaryWearRun::new(WearMode::QuasiStatic),
        &mut |_| Ok(()),
    )
    .ok()
    .and_then(|r| r.updates.first().map(|u| u.flanks(model)))
    .map(|flanks| flanks.into_iter().map(|f| f.rate_m_per_input).collect())
}

/// U = 1 + ceil(C / n), the block n cut by the threshold over `RATE_MARGIN` times the
/// deepest flank's first rate `rate` (m per input cycle).
fn updates_at_rate(rate: f64, wear: &WearSection) -> f64 {
    let block = block_length(
        RATE_MARGIN * rate,
        wear.block_cycles,
        wear.threshold_um * 1e-6,
        wear.total_cycles,
    )
    .max(1.0);
    1.0 + (wear.total_cycles / block).ceil()
}

/// The updates U a planetary set's wear study under a load spectrum makes at most: as
/// [`planetary_wear_updates`], with the spectrum's first rate at every flank point,
/// sum_i s_i r_i (the loop's block rule, docs/MODEL.md 12.12), `models[i]` the set at
/// bin i and `shares[i]` its share.
pub fn planetary_spectrum_wear_updates(
    models: &[PlanetaryWearModel],
    shares: &[f64],
    wear: &WearSection,
) -> f64 {
    let mut rate: Vec<Vec<f64>> = Vec::new();
    for (m, s) in models.iter().zip(shares) {
        let Some(r) = first_flank_rates(m, wear) else {
            continue;
        };
        if rate.is_empty() {
            rate = r.iter().map(|f| vec![0.0; f.len()]).collect();
        }
        for (a, b) in rate.iter_mut().flatten().zip(r.iter().flatten()) {
            *a += s * b;
        }
    }
    updates_at_rate(rate.iter().flatten().fold(0.0_f64, |a, b| a.max(*b)), wear)
}

/// The estimate of a planetary set's wear study under a load spectrum in `modes`
/// (`models[i]` the set at bin i, `shares[i]` its share): the updates of
/// [`planetary_spectrum_wear_updates`], each a response of the whole set at every bin
/// (at the rates of [`estimate_planetary_wear`]), every bin's records kept. The bins are
/// counted in checked integer arithmetic: a count that overflows is an infinite estimate,
/// refused by any budget.
pub fn estimate_planetary_spectrum_wear(
    models: &[PlanetaryWearModel],
    shares: &[f64],
    wear: &WearSection,
    modes: &[WearMode],
) -> Estimate {
    let Some(first) = models.first() else {
        return Estimate::of_terms(Vec::new());
    };
    let per_update = seconds_per_update(first, modes);
    let updates = planetary_spectrum_wear_updates(models, shares, wear);
    let meshes = 2 * first.planets();
    let points = wear.points_per_profile.max(2) as usize;
    // Responses per update, and profile points kept per update and mode, over all bins.
    let counts = models.len().checked_mul(meshes).and_then(|x| {
        x.checked_mul(points)
            .and_then(|p| p.checked_mul(modes.len()))
            .map(|p| (models.len() as f64, p as f64))
    });
    let (bins, kept) = counts.unwrap_or((f64::INFINITY, f64::INFINITY));
    // A tooth fault's cost at every bin's response (the bins' sets share the fault).
    let fault = wear_fault_term(first, modes, updates * bins);
    let mut terms = vec![Term {
        what: "the planetary set's wear updates under the load spectrum (a response of the whole set at every bin each)",
        seconds: updates * bins * per_update,
        bytes: updates * kept * BYTES_PER_MESH_POINT,
        keys: &[
            "load_spectrum.bins",
            "wear.total_cycles",
            "wear.block_cycles",
            "wear.threshold_um",
            "wear.points_per_profile",
            "planetary.planets",
        ],
    }];
    terms.extend(fault);
    Estimate::of_terms(terms)
}

/// Largest size a bin's mesh log of a planetary study under a spectrum may have when
/// read back, bytes: as [`max_planetary_checkpoint_bytes`] with the spectrum's updates.
pub fn max_planetary_spectrum_checkpoint_bytes(
    models: &[PlanetaryWearModel],
    shares: &[f64],
    wear: &WearSection,
) -> u64 {
    let teeth = models.first().map_or(0.0, tooth_numbers_per_log);
    checkpoint_bytes(
        planetary_spectrum_wear_updates(models, shares, wear),
        wear,
        teeth,
    )
}

/// Largest size a mesh's checkpoint log of a planetary wear study may have when read
/// back, bytes: 16 times (the margin `budget::max_checkpoint_bytes` takes for a pair) the
/// study's updates ([`planetary_wear_updates`]) of 4 G + 16 numbers each (a mesh's wear
/// and increment on both flanks over its G grid points, its summary), and z G more with a
/// tooth fault (the faulty member's z teeth's rates, docs/MODEL.md 12.16), at 32 bytes a
/// number in JSON with its checksum, and at least 64 MiB.
pub fn max_planetary_checkpoint_bytes(model: &PlanetaryWearModel, wear: &WearSection) -> u64 {
    checkpoint_bytes(
        planetary_wear_updates(model, wear),
        wear,
        tooth_numbers_per_log(model),
    )
}

/// Numbers the faulty member's teeth add to one update (docs/MODEL.md 12.16): each mesh
/// that meets the member keeps every tooth's rate over the profile grid (z G on each of
/// those meshes), and the run their depths (z G per flank); 0 without a fault.
fn tooth_profile_numbers(model: &PlanetaryWearModel) -> f64 {
    tooth_rate_numbers(model)
        + faulty_member(model).map_or(0.0, |(_, _, z, flanks)| {
            flanks.len() as f64 * z as f64 * grid_points(model)
        })
}

/// Numbers the faulty member's teeth's rates add to one update's records: z G on each
/// mesh that meets the member (docs/MODEL.md 12.16); 0 without a fault.
pub(crate) fn tooth_rate_numbers(model: &PlanetaryWearModel) -> f64 {
    faulty_member(model).map_or(0.0, |(_, _, z, flanks)| {
        let meshes: usize = flanks.iter().map(|f| f.meshes.len()).sum();
        meshes as f64 * z as f64 * grid_points(model)
    })
}

/// Points of the set's larger profile grid.
fn grid_points(model: &PlanetaryWearModel) -> f64 {
    model.grids[0].len().max(model.grids[1].len()) as f64
}

/// The faulty member's numbers in one mesh log's record: every tooth's rate over the
/// profile grid (z G), 0 without a fault.
fn tooth_numbers_per_log(model: &PlanetaryWearModel) -> f64 {
    faulty_member(model).map_or(0.0, |(_, _, z, _)| z as f64 * grid_points(model))
}

/// The bound of [`max_planetary_checkpoint_bytes`] for `updates` updates, the mesh logs
/// of a set with a tooth fault holding the faulty member's teeth too.
fn checkpoint_bytes(updates: f64, wear: &WearSection, tooth_numbers: f64) -> u64 {
    let numbers = 4.0 * wear.points_per_profile.max(2) as f64 + 16.0 + tooth_numbers;
    let bytes = 16.0 * updates * numbers * 32.0;
    bytes.clamp(64.0 * 1024.0 * 1024.0, 1e15) as u64
}

/// CPU seconds of one integrator step of a four-planet set's dynamic model: measured
/// 29 us (the default set with a sun tooth crack, 47 891 steps in 1.38 s, 2026-11-30),
/// counted 40 us, times the planets' share of the model ((N + 3) / 7 of its coordinates)
/// and [`SLOWER_MACHINE_FACTOR`].
const SECONDS_PER_STEP_4: f64 = 40e-6;

/// Bytes a recorded sample of a set's response holds per coordinate or mesh force: the
/// number, its copies in the mesh-force and motion tables and their CSV text (about 48).
const BYTES_PER_SAMPLE_VALUE: f64 = 48.0;

/// Time factor of a planetary set's integrator step over the pair's
/// ([`super::evaluation::SECONDS_PER_STEP`]), 1 for any other case: the set's step is
/// [`SECONDS_PER_STEP_4`] times its coordinates' share, (N + 3) / 7 (the healthy built-in
/// set took 0.15 s of CPU for 5 118 steps, 29 us each, against the 0.075 s estimated
/// from the pair's step before this factor, 2026-11-30). The step count stays the pair's
/// (the set's own search needs fewer: the healthy set's estimate is then about 6 times
/// its CPU time, on the safe side).
pub(crate) fn step_factor(case: &crate::config::Case) -> f64 {
    case.planetary.as_ref().map_or(1.0, |p| {
        let planets = p.planets.max(1) as f64;
        (SECONDS_PER_STEP_4 * (planets + 3.0) / 7.0 / super::evaluation::SECONDS_PER_STEP).max(1.0)
    })
}

/// The ring sensor's record of a planetary set in `gearwear signals`
/// (`study::planetary_signals::ring_sensor_record`): lcm(P, z_r) mesh periods of the
/// case's steps (P the fault's period, 1 healthy), its revolution, spectrum and record.
/// Measured 39-40 bytes and 0.09 us of CPU per sample (the sun tooth crack of a
/// 331 / 333 / 997 set, lcm = 330 007 periods at 50 and 100 steps: 0.65 and 1.28 GB and
/// 1.4 and 3.0 s above its dynamics, 2026-11-30); counted 48 bytes and 0.1 us times
/// [`SLOWER_MACHINE_FACTOR`]. A record beyond the limits costs without bound (refused by
/// the job with its own message when the budget is off). None without a set.
pub fn ring_record_term(case: &crate::config::Case) -> Option<Term> {
    let section = case.planetary.as_ref()?;
    let steps = case.numerics.steps_per_mesh_period.max(8) as u64;
    let zr = section.teeth_ring.max(1) as f64;
    let samples = match crate::study::planetary_fault::fault_periods(section, steps) {
        // Healthy: one carrier revolution relative to the ring, z_r mesh periods.
        Ok((1, _)) => zr * steps as f64,
        Ok((_, record)) => record as f64 * steps as f64,
        Err(_) => f64::INFINITY,
    };
    Some(Term {
        what: "the ring sensor's record (lcm(P, z_r) mesh periods of the set's response)",
        seconds: samples * 0.1e-6 * SLOWER_MACHINE_FACTOR,
        bytes: samples * 48.0,
        keys: &[
            "planetary.teeth_ring",
            "planetary.fault.gear",
            "numerics.steps_per_mesh_period",
        ],
    })
}

/// The run budget's term for a planetary set with a tooth fault (`[[planetary.fault]]`,
/// docs/MODEL.md 12.13; None without one): each dynamic evaluation integrates its run-in
/// and at least one pass over the fault's period P mesh periods (`study::planetary_fault::
/// fault_period`, in checked arithmetic) beyond the healthy set's search, each period at
/// `s_dyn` steps, and a kept response records P periods of its 3 (N + 3) coordinates and
/// 2 N mesh forces. A period beyond the limits costs without bound (the term names the
/// keys; the model refuses it with its own message when the budget is off).
/// `evals`: dynamic evaluations; `kept`: responses kept at once.
pub fn fault_term(case: &crate::config::Case, evals: f64, kept: f64, s_dyn: f64) -> Option<Term> {
    let section = case.planetary.as_ref()?;
    section.active_fault()?;
    let steps = case.numerics.steps_per_mesh_period.max(8) as u64;
    let planets = section.planets.max(1) as f64;
    let (seconds, bytes) = match crate::study::planetary_fault::fault_period(section, steps) {
        Ok(p) => {
            // The run-in is at most P (`planetary_steady::run_in_periods`) and one pass
            // settles (its map contracts by e^(-sigma P T_m)): 2 P, one pass more of margin.
            let periods = 3.0 * p as f64;
            let per_step = SECONDS_PER_STEP_4 * (planets + 3.0) / 7.0 * SLOWER_MACHINE_FACTOR;
            let values = 3.0 * (planets + 3.0) + 2.0 * planets + 1.0;
            (
                evals.max(1.0) * periods * s_dyn * per_step,
                kept.max(1.0) * p as f64 * steps as f64 * values * BYTES_PER_SAMPLE_VALUE,
            )
        }
        Err(_) => (f64::INFINITY, f64::INFINITY),
    };
    Some(Term {
        what: "the planetary set's tooth fault (its response over the fault's period, z_s, z_p or z_r mesh periods)",
        seconds,
        bytes,
        keys: &[
            "planetary.fault.gear",
            "planetary.teeth_sun",
            "planetary.teeth_planet",
            "planetary.teeth_ring",
            "numerics.steps_per_mesh_period",
        ],
    })
}

/// The cost of a wear sweep's case of a planetary set (`study::sweep::planetary_wear_row`,
/// docs/MODEL.md 12.17): the set's wear study in both modes, [`estimate_planetary_wear`],
/// or under its `[load_spectrum]` [`estimate_planetary_spectrum_wear`] over every bin's
/// set (`Case::at_bin`). None for a case without a set, or whose set (or a bin's) has no
/// model: the sweep names that problem itself before any case runs.
pub fn sweep_wear_estimate(case: &crate::config::Case) -> Option<Estimate> {
    case.planetary.as_ref()?;
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    match &case.load_spectrum {
        None => {
            let model = PlanetaryWearModel::from_case(case).ok()?;
            Some(estimate_planetary_wear(&model, &case.wear, &modes))
        }
        Some(s) => {
            let models = (0..s.bins.len())
                .map(|i| PlanetaryWearModel::from_case(&case.at_bin(i)).ok())
                .collect::<Option<Vec<_>>>()?;
            let shares: Vec<f64> = s.bins.iter().map(|b| b.share).collect();
            Some(estimate_planetary_spectrum_wear(
                &models, &shares, &case.wear, &modes,
            ))
        }
    }
}
