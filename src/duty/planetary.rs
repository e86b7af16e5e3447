//! The wear loop of a planetary set (`[planetary]`) under a load spectrum: the set's loop
//! (`study::planetary_wear_loop`) with every bin advancing at every update, as the single
//! pair's (`duty::wear`) and the train's (`duty::train`) spectrum loops do
//! (docs/MODEL.md 12.12).
//!
//! Every bin is the set at the bin's operating point (`Case::at_bin`): the bin's
//! `input_speed_hz` is the input member's speed (`planetary.input`) and its `torque_nm`
//! the input member's torque, exactly as `operating.input_speed_hz` and
//! `operating.load_torque_nm` are for the set; every member's speed and torque follow
//! from Willis' equation and the torque split (docs/MODEL.md 12.6) when the bin's model
//! is built. The meshes' flanks are shared by every bin. Shares are shares of input
//! cycles; mesh j's pinion turns c_j times relative to the carrier per input cycle
//! whatever the bin (c_j is kinematic: `PlanetaryWearModel::pinion_cycles_per_input`,
//! taken from the monitoring bin's model), so a bin of share s_i gives every mesh s_i of
//! its pinion cycles too. At each update:
//!
//! 1. **Block.** Mesh j's wear per pinion cycle under the spectrum is sum_i s_i inc_ij
//!    (inc_ij: its Archard wear per pinion cycle at bin i, paper eq. 14-16); the block of
//!    n input cycles is `wear.block_cycles` cut by the threshold of eq. 17 on the fastest
//!    member flank at those rates (`planetary_wear_loop::next_block`'s rule), and to the
//!    total.
//! 2. **Advance.** Each mesh j gets s_i n c_j pinion cycles of bin i's wear, bins in
//!    their order (paper eq. 17 per bin and mesh), all on the flanks at the start of the
//!    block.
//! 3. **Respond.** Every bin solves the whole set on the new worn flanks (each steady
//!    state from its static deflection, as the set's own loop); the bins run in parallel.
//!
//! A spectrum of one bin at the operating point is the set's loop bit for bit (s = 1
//! makes every product exact). A bin whose response leaves the model's domain, or finds
//! no steady state, stops the run naming the bin.

use super::model::bin_label;
use crate::config::case::TorqueShaft;
use crate::config::{Case, LoadSpectrumSection};
use crate::study::model::ModelError;
use crate::study::parallel_runs::run_in_parallel;
use crate::study::planetary_wear::{new_teeth, PlanetaryWearModel};
use crate::study::planetary_wear_loop::{update_of, PlanetaryUpdate, PlanetaryWearRun};
use crate::study::wear_loop::{fastest_block, WearMode, WearStop};
use crate::wear::{WearIncrement, WearState};
use rayon::prelude::*;

/// A planetary set under its case's spectrum: one wear model per bin.
pub struct PlanetarySpectrum {
    /// The case with its spectrum.
    pub case: Case,
    /// The case's spectrum.
    pub spectrum: LoadSpectrumSection,
    /// The set at every bin's operating point, in the spectrum's order.
    pub models: Vec<PlanetaryWearModel>,
    /// Each bin's share of the input cycles (sum 1).
    pub shares: Vec<f64>,
    /// The bin whose response the set's own tables show (0-based).
    pub monitoring: usize,
}

impl PlanetarySpectrum {
    /// The models of every bin of `case`'s spectrum (in parallel; every bin's problems
    /// collected, each naming its bin). The bins' torques load the input member: a
    /// spectrum whose torques are on the gear shaft is refused, naming the key.
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        let Some(spectrum) = case.load_spectrum.as_ref() else {
            return Err(ModelError(vec![
                "this case has no `[load_spectrum]` section".into(),
            ]));
        };
        if spectrum.shaft(case.operating.load_torque_shaft) == TorqueShaft::Gear {
            let key = match spectrum.torque_shaft {
                Some(_) => "`load_spectrum.torque_shaft`",
                None => {
                    "`operating.load_torque_shaft` (which `load_spectrum.torque_shaft` inherits)"
                }
            };
            return Err(ModelError(vec![format!(
                "{key} = \"gear\" on a planetary set: the spectrum's bins load the set's input member (`planetary.input`), so the valid value is \"pinion\" (the input member); give the bins' torques on the input member"
            )]));
        }
        let models =
            super::model::models_of_bins(case, spectrum.bins.len(), PlanetaryWearModel::from_case)?;
        Ok(Self {
            case: case.clone(),
            spectrum: spectrum.clone(),
            models,
            shares: spectrum.bins.iter().map(|b| b.share).collect(),
            monitoring: spectrum.monitoring_index(),
        })
    }

    /// The monitoring bin's model: its kinematics (c_j, the same at every bin) advance
    /// the shared flanks, and the set's tables read it.
    pub fn reference(&self) -> &PlanetaryWearModel {
        &self.models[self.monitoring]
    }

    /// Number of bins.
    pub fn bins(&self) -> usize {
        self.models.len()
    }

    /// Number of meshes (2 N).
    pub fn meshes(&self) -> usize {
        2 * self.reference().planets()
    }

    /// Seconds per input cycle under the spectrum, sum_i s_i / f_i (f_i: bin i's input
    /// member speed, Hz).
    pub fn seconds_per_input_cycle(&self) -> f64 {
        self.spectrum.seconds_per_cycle()
    }

    /// Bin `i` in words, for messages.
    pub fn label(&self, i: usize) -> String {
        bin_label(&self.case, i)
    }
}

/// One update under the spectrum.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetarySpectrumRecord {
    /// Revolutions of the input member.
    pub input_cycles: f64,
    /// The member flank (`PlanetaryUpdate::flanks` order) whose threshold cut the block
    /// that led here.
    pub limited_by: Option<usize>,
    /// Per bin: the whole set's update on the shared flanks (each mesh's record: the
    /// mesh's shared wear, the bin's response and its wear per pinion cycle there).
    pub bins: Vec<PlanetaryUpdate>,
    /// Wear bin i has added so far to mesh j's pinion flank, per profile point, m
    /// (`[i][j]`).
    pub by_bin_pinion_m: Vec<Vec<Vec<f64>>>,
    /// The same for the gear flank, m.
    pub by_bin_gear_m: Vec<Vec<Vec<f64>>>,
}

impl PlanetarySpectrumRecord {
    /// Mesh `j`'s wear per pinion cycle under the spectrum, sum_i s_i inc_ij, m.
    pub fn increment(&self, shares: &[f64], j: usize) -> WearIncrement {
        let per_bin = self.bins.iter().map(|b| {
            let r = &b.meshes[j];
            (
                r.increment_pinion_m.as_slice(),
                r.increment_gear_m.as_slice(),
            )
        });
        super::model::mixed_increment(per_bin, shares)
    }

    /// The update as one run of the set reads it: bin `observed`'s records with every
    /// mesh's wear per pinion cycle under the spectrum, a faulty member's per tooth too
    /// (so the flanks' rates, the wear between updates and the teeth's, are the
    /// spectrum's).
    pub fn combined(&self, shares: &[f64], observed: usize) -> PlanetaryUpdate {
        let b = &self.bins[observed.min(self.bins.len() - 1)];
        let meshes = b
            .meshes
            .iter()
            .enumerate()
            .map(|(j, m)| {
                let inc = self.increment(shares, j);
                let teeth = self
                    .bins
                    .iter()
                    .map(|b| b.meshes[j].increment_teeth.as_ref());
                crate::study::wear_loop::UpdateRecord {
                    increment_pinion_m: inc.pinion_m,
                    increment_gear_m: inc.gear_m,
                    increment_teeth: super::model::mixed_maps(teeth, shares),
                    ..m.clone()
                }
            })
            .collect();
        PlanetaryUpdate {
            input_cycles: self.input_cycles,
            meshes,
            limited_by: self.limited_by,
        }
    }

    /// Bin `i`'s wear added to every mesh, as wear states (module order).
    pub fn added_by(&self, i: usize) -> Vec<WearState> {
        self.by_bin_pinion_m[i]
            .iter()
            .zip(&self.by_bin_gear_m[i])
            .map(|(p, g)| WearState {
                pinion_m: p.clone(),
                gear_m: g.clone(),
                ..WearState::new(0)
            })
            .collect()
    }
}

/// A set's wear run under a spectrum: its mode, the bins' shares, every update.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetarySpectrumRun {
    /// Dynamic or quasi-static.
    pub mode: WearMode,
    /// Each bin's share of the input cycles (sum 1).
    pub shares: Vec<f64>,
    /// Every update so far.
    pub records: Vec<PlanetarySpectrumRecord>,
    /// Why the run stopped before the case's total, if it did.
    pub stopped: Option<WearStop>,
}

impl PlanetarySpectrumRun {
    /// A run in `mode` with no update yet.
    pub fn new(mode: WearMode, shares: Vec<f64>) -> Self {
        Self {
            mode,
            shares,
            records: Vec::new(),
            stopped: None,
        }
    }
}

/// The wear the block after `last` leads to: its input cycles, the flank that cut it,
/// every mesh's wear at its end, and the record started with the wear each bin added by
/// then (its `bins` empty). None when the total is reached. The replay of checkpoints
/// takes the same step (`duty::planetary_resume`).
pub fn next_spectrum_block(
    ps: &PlanetarySpectrum,
    last: &PlanetarySpectrumRecord,
    shares: &[f64],
) -> Option<(Vec<WearState>, PlanetarySpectrumRecord)> {
    let w = &ps.case.wear;
    let remaining = w.total_cycles - last.input_cycles;
    if remaining <= 0.5 {
        return None;
    }
    let model = ps.reference();
    let combined = last.combined(shares, ps.monitoring);
    let (n, limited_by) = fastest_block(
        combined
            .flanks(model)
            .iter()
            .map(|f| f.rate_m_per_input.iter().fold(0.0_f64, |a, b| a.max(*b))),
        w,
        remaining,
    );
    let mut added = PlanetarySpectrumRecord {
        input_cycles: last.input_cycles + n,
        limited_by,
        bins: Vec::new(),
        by_bin_pinion_m: last.by_bin_pinion_m.clone(),
        by_bin_gear_m: last.by_bin_gear_m.clone(),
    };
    let mut wears: Vec<WearState> = last.bins[0].meshes.iter().map(|r| r.wear.clone()).collect();
    for (j, wj) in wears.iter_mut().enumerate() {
        let c = model.pinion_cycles_per_input[model.kind_of(j).0];
        let start = wj.cycles;
        for (i, (b, s)) in last.bins.iter().zip(shares).enumerate() {
            let r = &b.meshes[j];
            // Paper eq. 17 for bin i on mesh j: s_i n c_j of its pinion cycles.
            let cycles = s * n * c;
            wj.advance(&r.increment(), cycles);
            for (h, d) in added.by_bin_pinion_m[i][j]
                .iter_mut()
                .zip(&r.increment_pinion_m)
            {
                *h += cycles * d;
            }
            for (h, d) in added.by_bin_gear_m[i][j]
                .iter_mut()
                .zip(&r.increment_gear_m)
            {
                *h += cycles * d;
            }
        }
        // The block is n c_j pinion cycles whatever the rounding of sum_i s_i n c_j.
        wj.cycles = start + n * c;
    }
    Some((wears, added))
}

/// Every bin's update of the set with the shared flanks `wears` at `input_cycles` (in
/// parallel), or the first bin's stop (lowest index), its reason naming the bin.
pub fn respond_bins(
    ps: &PlanetarySpectrum,
    mode: WearMode,
    (input_cycles, limited_by): (f64, Option<usize>),
    wears: &[WearState],
) -> Result<Vec<PlanetaryUpdate>, WearStop> {
    let next: Vec<_> = ps
        .models
        .par_iter()
        .map(|m| update_of(m, mode, (input_cycles, limited_by), wears.to_vec()))
        .collect();
    let mut out = Vec::with_capacity(next.len());
    for (i, n) in next.into_iter().enumerate() {
        match n {
            Ok(u) => out.push(u),
            Err((reason, kind)) => {
                return Err(WearStop {
                    cycles: input_cycles,
                    kind,
                    reason: format!("{}: {reason}", ps.label(i)),
                })
            }
        }
    }
    Ok(out)
}

/// The record of new teeth at input cycle 0 before any bin responds (no wear added).
pub fn new_record(ps: &PlanetarySpectrum) -> (Vec<WearState>, PlanetarySpectrumRecord) {
    let wears = new_teeth(ps.reference());
    let zeros: Vec<Vec<f64>> = wears.iter().map(|w| vec![0.0; w.pinion_m.len()]).collect();
    let record = PlanetarySpectrumRecord {
        input_cycles: 0.0,
        limited_by: None,
        bins: Vec::new(),
        by_bin_pinion_m: vec![zeros.clone(); ps.bins()],
        by_bin_gear_m: vec![zeros; ps.bins()],
    };
    (wears, record)
}

/// The first update: new teeth at input cycle 0, every bin's response; a bin that fails
/// is an error naming it.
pub fn first_record(
    ps: &PlanetarySpectrum,
    mode: WearMode,
) -> anyhow::Result<PlanetarySpectrumRecord> {
    let (wears, mut record) = new_record(ps);
    record.bins = respond_bins(ps, mode, (0.0, None), &wears)
        .map_err(|s| anyhow::anyhow!("the new set's response: {}", s.reason))?;
    Ok(record)
}

/// Run (or continue) a set's wear study under the spectrum to the case's total input
/// cycles; `on_update` after every update (an error it returns stops the run).
pub fn run_planetary_spectrum_wear(
    ps: &PlanetarySpectrum,
    mut run: PlanetarySpectrumRun,
    on_update: &mut dyn FnMut(&PlanetarySpectrumRun) -> anyhow::Result<()>,
) -> anyhow::Result<PlanetarySpectrumRun> {
    if run.records.is_empty() {
        run.records.push(first_record(ps, run.mode)?);
        on_update(&run)?;
    }
    while run.stopped.is_none() {
        let last = run.records.last().expect("at least one record");
        let Some((wears, mut next)) = next_spectrum_block(ps, last, &run.shares) else {
            break;
        };
        let at = (next.input_cycles, next.limited_by);
        match respond_bins(ps, run.mode, at, &wears) {
            Ok(bins) => {
                next.bins = bins;
                run.records.push(next);
            }
            Err(s) => run.stopped = Some(s),
        }
        on_update(&run)?;
    }
    Ok(run)
}

/// Run (or continue) runs side by side (the dynamic study and its quasi-static twin,
/// `study::parallel_runs`), `on_update(mode, run)` after every update of each; results
/// in the order of `starts`.
pub fn run_planetary_spectrum_modes(
    ps: &PlanetarySpectrum,
    starts: Vec<PlanetarySpectrumRun>,
    on_update: &(dyn Fn(WearMode, &PlanetarySpectrumRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<Vec<PlanetarySpectrumRun>> {
    run_in_parallel(
        starts,
        |r| r.mode,
        &|start, f| run_planetary_spectrum_wear(ps, start, f),
        on_update,
    )
}

/// The run as one run of the set, for the set's readers (tables, figures, summary):
/// every mesh's shared wear, its wear per pinion cycle under the spectrum and the
/// response of bin `observed` (the monitoring bin).
pub fn combined_planetary_run(run: &PlanetarySpectrumRun, observed: usize) -> PlanetaryWearRun {
    PlanetaryWearRun {
        mode: run.mode,
        updates: run
            .records
            .iter()
            .map(|r| r.combined(&run.shares, observed))
            .collect(),
        stopped: run.stopped.clone(),
    }
}
