//! What a planetary set's run under a spectrum gives per member flank (the sun's; each
//! planet's sun-side and ring-side flank; the ring's, `study::planetary_wear::member_flanks`):
//! the share of its wear volume each bin added, the largest depth each bin added, its
//! life to the spectrum's wear limit (`load_spectrum.life_wear_limit_um`, the flank's
//! largest depth) in input cycles and hours, and the member that limits the set's life.
//!
//! The life is read from the run itself: between updates every flank's depth grows
//! linearly in input cycles at its rate under the spectrum (paper eq. 17; a flank's rate
//! is sum_i s_i of its meshes' increments times their pinion cycles per input cycle), so
//! the crossing within a block is exact, as the single pair's (`duty::life`) and the
//! train's (`duty::train_life`); a flank whose limit is not reached by the end of the
//! run is given as beyond it. Hours are input cycles x sum_i s_i / f_i / 3600.

use super::contribution::share;
use super::life::Life;
use super::planetary::{combined_planetary_run, PlanetarySpectrum, PlanetarySpectrumRun};
use crate::study::planetary_wear::{member_flanks, MemberFlank};
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use crate::wear::WearIncrement;
use serde::Serialize;

/// One member flank's results under the spectrum.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlankUnderSpectrum {
    /// "sun", "planet_N" or "ring".
    pub member: String,
    /// "sun", "sun_side", "ring_side" or "ring" (`MemberFlank::flank`).
    pub flank: String,
    /// Largest wear depth at the end, µm.
    pub max_wear_um: f64,
    /// Wear volume at the end over all the member's teeth, mm^3.
    pub volume_mm3: f64,
    /// Share of the flank's wear volume each bin added (bin order).
    pub share_of_volume_by_bin: Vec<f64>,
    /// Largest depth each bin added, µm (bin order).
    pub max_wear_added_by_bin_um: Vec<f64>,
    /// Life to the wear limit, in input cycles.
    pub life: Life,
    /// The life in hours under the spectrum, when reached.
    pub life_hours: Option<f64>,
}

/// A run's results per member flank and the member that limits the set's life.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SetUnderSpectrum {
    /// Input cycles at the end of the run.
    pub input_cycles: f64,
    /// Hours those cycles take under the spectrum.
    pub hours: f64,
    /// The wear limit of the lives, µm.
    pub life_wear_limit_um: f64,
    /// Per member flank (`member_flanks` order).
    pub flanks: Vec<FlankUnderSpectrum>,
    /// The member whose flank reaches the limit first; when none does, the member with
    /// the deepest wear at the end.
    pub limiting_member: Option<String>,
    /// That member's flank.
    pub limiting_flank: Option<String>,
    /// The set's life: the limiting flank's, in input cycles, when reached.
    pub life_input_cycles: Option<f64>,
    /// The same in hours.
    pub life_hours: Option<f64>,
}

/// Largest entry, 0 for none.
fn max_of(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |a, b| a.max(*b))
}

/// Input cycles at which flank `k`'s largest depth first reaches `limit_m` in the run
/// `run` (read as one run: every update's flanks with their rates under the spectrum),
/// within the run's last input cycles; None if not reached. Within the block after an
/// update of depth h and rate r per input cycle the depth is h + n r (eq. 17), so the
/// crossing is the smallest (L - h) / r over the rising points, when the block reaches
/// it.
pub fn first_crossing(
    model: &crate::study::planetary_wear::PlanetaryWearModel,
    run: &PlanetaryWearRun,
    k: usize,
    limit_m: f64,
) -> Option<f64> {
    let end = run.updates.last()?.input_cycles;
    for (j, u) in run.updates.iter().enumerate() {
        let flanks = u.flanks(model);
        let f = &flanks[k];
        if f.depth_m.iter().any(|h| *h >= limit_m) {
            return Some(u.input_cycles);
        }
        let block_end = run.updates.get(j + 1).map_or(end, |x| x.input_cycles);
        let n = f
            .depth_m
            .iter()
            .zip(&f.rate_m_per_input)
            .filter(|(_, r)| **r > 0.0)
            .map(|(h, r)| (limit_m - h) / r)
            .fold(f64::INFINITY, f64::min);
        if u.input_cycles + n <= block_end {
            return Some(u.input_cycles + n);
        }
    }
    None
}

/// The member flanks each bin's added wear makes by the end of `run` (bin order).
fn added_flanks(ps: &PlanetarySpectrum, run: &PlanetarySpectrumRun) -> Vec<Vec<MemberFlank>> {
    let Some(last) = run.records.last() else {
        return Vec::new();
    };
    let none = vec![WearIncrement::default(); ps.meshes()];
    (0..ps.bins())
        .map(|i| member_flanks(ps.reference(), &last.added_by(i), &none))
        .collect()
}

/// The results of `run` per member flank (see the module docs).
pub fn set_under_spectrum(
    ps: &PlanetarySpectrum,
    run: &PlanetarySpectrumRun,
) -> Option<SetUnderSpectrum> {
    let spc = ps.seconds_per_input_cycle();
    let limit_um = ps.spectrum.life_wear_limit_um;
    let model = ps.reference();
    let combined = combined_planetary_run(run, ps.monitoring);
    let last = combined.updates.last()?;
    let by_bin = added_flanks(ps, run);
    let flanks: Vec<FlankUnderSpectrum> = last
        .flanks(model)
        .into_iter()
        .enumerate()
        .map(|(k, f)| {
            let depth = max_of(&f.depth_m);
            let life = match first_crossing(model, &combined, k, limit_um * 1e-6) {
                Some(n) => Life::Reached { cycles: n },
                None => Life::Beyond {
                    cycles: last.input_cycles,
                    reason: format!(
                        "the largest wear depth of the {} ({} flank) is {:.3} µm at the end of the run, below the limit of {limit_um} µm",
                        f.member.replace('_', " "), f.flank.replace('_', " "), depth * 1e6
                    ),
                },
            };
            FlankUnderSpectrum {
                share_of_volume_by_bin: by_bin
                    .iter()
                    .map(|b| share(b[k].volume_m3, f.volume_m3))
                    .collect(),
                max_wear_added_by_bin_um: by_bin.iter().map(|b| max_of(&b[k].depth_m) * 1e6).collect(),
                member: f.member,
                flank: f.flank.to_string(),
                max_wear_um: depth * 1e6,
                volume_mm3: f.volume_m3 * 1e9,
                life_hours: life.cycles().map(|n| n * spc / 3600.0),
                life,
            }
        })
        .collect();
    let limiting = flanks
        .iter()
        .filter(|f| f.life.cycles().is_some())
        .min_by(|a, b| {
            a.life
                .cycles()
                .unwrap_or(0.0)
                .total_cmp(&b.life.cycles().unwrap_or(0.0))
        })
        // No flank reached the limit: the deepest wear, the life's own measure.
        .or_else(|| {
            flanks
                .iter()
                .max_by(|a, b| a.max_wear_um.total_cmp(&b.max_wear_um))
        });
    Some(SetUnderSpectrum {
        input_cycles: last.input_cycles,
        hours: last.input_cycles * spc / 3600.0,
        life_wear_limit_um: limit_um,
        limiting_member: limiting.map(|f| f.member.clone()),
        limiting_flank: limiting.map(|f| f.flank.clone()),
        life_input_cycles: limiting.and_then(|f| f.life.cycles()),
        life_hours: limiting.and_then(|f| f.life_hours),
        flanks,
    })
}
