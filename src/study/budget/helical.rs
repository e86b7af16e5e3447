//! What a helical pair's wear study adds to its estimate (`study::helical_wear`,
//! docs/MODEL.md 11.3): every update spreads the response over the face slices, N slice
//! contacts per tooth pair in the transverse section at every sample of one period, each
//! with its Hertz contact, Xu's coefficient and its place in the slice's sorted history;
//! every record holds a wear map and an increment map of N profiles per flank, and the
//! checkpoints write them. Per-tooth inputs (docs/MODEL.md 11.13) spread every mesh
//! period of the excitation, and each record holds every tooth's N profiles.

use crate::config::case::Case;
use crate::geometry::helical::HelicalPair;
use crate::study::budget::cost::Term;
use crate::study::helical::helix_of;

/// One slice of one sample of a tooth's contact line when a helical pair's teeth are built
/// as lines (`study::teeth::ToothInputs::helical`: its stiffness, the fault compliances
/// and gaps interpolated, the weighted sums), s: measured 0.3 s for 50 teeth x 198 samples
/// x 10 000 slices (about 3e-9 s each, half the slices on the path) on the 2-core machine
/// under load, times the [`super::evaluation::SLOWER_MACHINE_FACTOR`] 2 and a margin of
/// 2 for slices all on the path, rounded up.
pub const SECONDS_PER_LINE_SLICE: f64 = 2e-8;

/// One slice contact of an update (its stiffness, Hertz contact, Xu's coefficient, its
/// sorting and its share of the slice's Archard bookkeeping; the lines' wear gap adds
/// 1.5 % more), s: measured 4.7e-7 s on the 2-core machine under load (400 slices, 122 515
/// contacts in 58 ms), times the [`super::evaluation::SLOWER_MACHINE_FACTOR`] 2, rounded up.
pub const SECONDS_PER_SLICE_CONTACT: f64 = 1e-6;
/// Bytes of one slice contact in flight (`PathSample`, 72 bytes, and its sorted copy).
const BYTES_PER_SLICE_CONTACT: f64 = 144.0;

/// The product of `counts` in checked integer arithmetic, as a float: a count that
/// overflows (a huge spectrum times slices times grid points) is infinite, an estimate
/// every budget refuses, never a wrapped small number.
fn checked_count(counts: &[usize]) -> f64 {
    counts
        .iter()
        .try_fold(1_usize, |a, b| a.checked_mul(*b))
        .map_or(f64::INFINITY, |n| n as f64)
}

/// Bins of the case's load spectrum (1 without one).
fn bins_of(case: &Case) -> usize {
    case.load_spectrum.as_ref().map_or(1, |s| s.bins.len())
}

/// The slice count and the most tooth pairs in contact in the transverse section,
/// ceil(epsilon_alpha), of a helical case (None for a spur pair or a geometry that fails,
/// which the model refuses before any update).
fn slices_and_pairs(case: &Case) -> Option<(f64, f64)> {
    if case.gear.helix_angle_deg == 0.0 || !case.stage.is_empty() {
        return None;
    }
    let pair = HelicalPair::from_case(&case.gear, &helix_of(&case.gear)).ok()?;
    let slices = usize::try_from(case.stiffness.slices.max(1)).unwrap_or(usize::MAX);
    let pairs = pair.transverse_contact_ratio.ceil().max(1.0) as usize;
    Some((
        slices as f64,
        // N ceil(epsilon_alpha), checked, over N: the pairs (infinite on overflow).
        checked_count(&[slices, pairs]) / slices as f64,
    ))
}

/// The most slice contacts of one update of a helical case with `samples` samples in a
/// period: N slices, each on at most ceil(epsilon_alpha) tooth pairs at a time; None for a
/// spur pair.
pub fn slice_contacts_per_update(case: &Case, samples: f64) -> Option<f64> {
    slices_and_pairs(case).map(|(n, pairs)| samples * n * pairs)
}

/// Numbers one wear record of a helical case adds: the wear and increment maps, N
/// profiles of G points on each flank (0 for a spur pair).
pub fn record_numbers(case: &Case) -> f64 {
    let points = usize::try_from(case.wear.points_per_profile.max(0)).unwrap_or(usize::MAX);
    slices_and_pairs(case).map_or(0.0, |(n, _)| checked_count(&[4, n as usize, points]))
}

/// Whether `gearwear wear` and `gearwear run` wear `case`'s helical teeth tooth by tooth
/// and slice by slice (docs/MODEL.md 11.13): per-tooth inputs at one operating point (the
/// other wear studies refuse them).
fn teeth_resolved(case: &Case) -> bool {
    crate::study::helical_teeth::has_tooth_inputs(case) && case.load_spectrum.is_none()
}

/// [`record_numbers`] of `gearwear wear` and `gearwear run`: with per-tooth inputs at one
/// operating point every tooth's face slices, (z1 + z2) N profiles of G points in the wear
/// and in the increment (docs/MODEL.md 11.13).
pub fn wear_record_numbers(case: &Case) -> f64 {
    let Some((n, _)) = slices_and_pairs(case).filter(|_| teeth_resolved(case)) else {
        return record_numbers(case);
    };
    let points = usize::try_from(case.wear.points_per_profile.max(0)).unwrap_or(usize::MAX);
    let teeth = [case.gear.teeth_pinion, case.gear.teeth_gear]
        .iter()
        .map(|z| usize::try_from((*z).max(1)).unwrap_or(usize::MAX))
        .try_fold(0_usize, |a, b| a.checked_add(b))
        .unwrap_or(usize::MAX);
    checked_count(&[2, teeth, n as usize, points])
}

/// How many times one period's slice contacts an update of `gearwear wear` or `gearwear
/// run` spreads: 1 for identical teeth (the last mesh period); with per-tooth inputs the
/// excitation's P mesh periods (`super::teeth::excitation_periods_of`), each contact
/// computed twice (the mesh force's share over every line, then each engagement's
/// slices, `study::helical_tooth_wear`).
fn contact_passes(case: &Case) -> f64 {
    if teeth_resolved(case) {
        2.0 * super::teeth::excitation_periods_of(case) as f64
    } else {
        1.0
    }
}

/// The helical wear's term: `updates` = (dynamic, quasi-static) updates over every mode,
/// `records` the records kept, `samples` = (dynamic, quasi-static) samples of a period
/// held at once, `dynamic_samples` those a dynamic update spreads at most (its time:
/// `super::steady_states::samples_per_period`, the steps of a worn period at the case's
/// speed),
/// `checkpoint` the bytes per number written and the disk's rate (bytes/s); None for a
/// spur pair. Under a load spectrum (docs/MODEL.md 11.7) `updates` and `records` count
/// every bin's (each bin's response spreads its own slice contacts), and the bins of an
/// update respond together, so B times one bin's contacts are in flight at once (B N
/// ceil(epsilon_alpha) counted in checked integer arithmetic). `wear_or_run`: the job is
/// `gearwear wear` or `gearwear run`, which wear per-tooth inputs tooth by tooth
/// ([`wear_record_numbers`]; a wear sweep refuses them).
pub fn budget_term(
    case: &Case,
    wear_or_run: bool,
    updates: (f64, f64),
    records: f64,
    samples: (f64, f64),
    dynamic_samples: f64,
    checkpoint: (f64, f64),
) -> Option<Term> {
    let per_dyn = slice_contacts_per_update(case, samples.0)?;
    let per_quasi = slice_contacts_per_update(case, samples.1)?;
    let spread_dyn = slice_contacts_per_update(case, dynamic_samples)?;
    let passes = if wear_or_run {
        contact_passes(case)
    } else {
        1.0
    };
    let contacts = (updates.0 * spread_dyn + updates.1 * per_quasi) * passes;
    let in_flight = [(updates.0, per_dyn), (updates.1, per_quasi)]
        .iter()
        .filter(|(u, _)| *u > 0.0)
        .map(|(_, c)| c)
        .sum::<f64>()
        * checked_count(&[bins_of(case)]);
    let numbers = records
        * if wear_or_run {
            wear_record_numbers(case)
        } else {
            record_numbers(case)
        };
    Some(Term {
        what: "the helical pair's wear per slice (contacts, wear maps, their checkpoints)",
        seconds: contacts * SECONDS_PER_SLICE_CONTACT + numbers * checkpoint.0 / checkpoint.1,
        bytes: numbers * 8.0 + in_flight * BYTES_PER_SLICE_CONTACT,
        keys: &[
            "stiffness.slices",
            "wear.points_per_profile",
            "numerics.steps_per_mesh_period",
            "wear.total_cycles",
            "wear.threshold_um",
        ],
    })
}

/// The building of a helical pair's teeth as contact lines (docs/MODEL.md 11.10) when the
/// case gives per-tooth inputs: every tooth of both gears, at each of the line pair's
/// samples (G (epsilon_alpha + epsilon_beta) / epsilon_alpha + 1 at the wear grid's
/// spacing, G = `wear.points_per_profile`), each of the N slices (an upper bound: about
/// epsilon_alpha / (epsilon_alpha + epsilon_beta) of them lie on the path). None for a spur
/// pair, a train, or new teeth. The tooth-resolved mesh's own cost over the hunting period
/// is `super::teeth`'s, as for a spur pair.
pub fn tooth_lines_term(case: &Case) -> Option<Term> {
    if !crate::study::helical_teeth::has_tooth_inputs(case) {
        return None;
    }
    let (n, _) = slices_and_pairs(case)?;
    let pair = HelicalPair::from_case(&case.gear, &helix_of(&case.gear)).ok()?;
    let g = case.wear.points_per_profile.max(2) as f64;
    let eps_a = pair.transverse_contact_ratio.max(1e-3);
    let samples = g * (eps_a + pair.overlap_ratio) / eps_a + 2.0;
    let teeth = (case.gear.teeth_pinion.max(1) + case.gear.teeth_gear.max(1)) as f64;
    Some(Term {
        what: "the helical teeth as contact lines (every tooth's slices at every sample)",
        seconds: teeth * samples * n * SECONDS_PER_LINE_SLICE,
        // Three tables (removed material, compliance, the healthy flank) per tooth, and
        // the samples' slices (face slice, rho, k: 24 bytes each).
        bytes: teeth * samples * 3.0 * 8.0 + samples * n * 24.0,
        keys: &[
            "stiffness.slices",
            "wear.points_per_profile",
            "gear.teeth_pinion",
            "gear.teeth_gear",
        ],
    })
}
