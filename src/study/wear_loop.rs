//! The two-way loop of the paper's Figure 3: dynamics -> wear -> gap (transmission
//! error) -> dynamics, and its quasi-static twin.
//!
//! Update scheme (paper eq. 17 and the text around it): the per-cycle wear of the current
//! state is held for a block of m cycles; if the block would add more than the threshold
//! epsilon^m at any point of either profile, it is shortened to the whole number of cycles
//! that adds at most epsilon^m there (at least one cycle); then the gap, the roughness and the response are renewed. The loop
//! runs to the case's total number of cycles (the last block is cut to land on it).
//!
//! Every update is a record; the records are the whole state of the run, so a checkpoint
//! after each update lets an interrupted run resume and reach the same numbers. A record
//! keeps the periodic state its response ended on: the next update starts its search for
//! the periodic orbit there (the gap changes by at most the threshold between updates).
//!
//! The run never aborts for numerical reasons: an update whose steady state is not found
//! is retried from the static equilibrium, then with a ten times tighter integration
//! tolerance, twice the grid nodes and periods. It stops early, keeping every record so
//! far and saying why in [`WearRun::stopped`], when the retries fail too or when the
//! worn teeth leave the model's domain: the mesh out of contact for more than
//! [`MAX_CONTACT_LOSS_FRACTION`] of the mesh period (Archard's law over a steady Hertz
//! contact per pass, and the quasi-static-in-the-gap wear update of eq. 17, no longer
//! describe teeth that mostly fly apart and impact).

use super::model::Model;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::period_search::{DynamicsError, SteadyStateSettings};
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::summary::ResponseSummary;
use crate::geometry::ProfileGrid;
use crate::wear::per_tooth::per_tooth_wear;
use crate::wear::{per_cycle_wear, SliceWear, ToothWear, WearIncrement, WearState};
use serde::{Deserialize, Serialize};

/// Which solver feeds the wear model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum WearMode {
    /// The steady-state dynamic response (the paper's dynamic wear model).
    Dynamic,
    /// The quasi-static load sharing, no dynamics (the paper's comparison).
    QuasiStatic,
}

impl WearMode {
    /// The mode's name in files and columns (`dynamic`, `quasi_static`).
    pub fn name(&self) -> &'static str {
        match self {
            WearMode::Dynamic => "dynamic",
            WearMode::QuasiStatic => "quasi_static",
        }
    }

    /// The mode in words, for figures and messages.
    pub fn label(&self) -> &'static str {
        match self {
            WearMode::Dynamic => "dynamic",
            WearMode::QuasiStatic => "quasi-static",
        }
    }
}

/// One update: the wear state reached, the response computed on it, and the per-cycle
/// wear that response gives (used for the next block).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UpdateRecord {
    /// The wear state reached.
    pub wear: WearState,
    /// Composite RMS roughness at that state, µm.
    pub roughness_um: f64,
    /// Headline numbers of the response on it.
    pub summary: ResponseSummary,
    /// Wear depth per pinion cycle at each pinion grid point, m (paper eq. 14-17).
    pub increment_pinion_m: Vec<f64>,
    /// Wear depth per pinion cycle at each gear grid point, m (paper eq. 14-17).
    pub increment_gear_m: Vec<f64>,
    /// Per-tooth increments of a tooth-resolved mesh (the two above are their means).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub increment_teeth: Option<ToothWear>,
    /// Per-slice increments of a helical pair (docs/MODEL.md 11.3; the two above are their
    /// means over the face slices).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub increment_slices: Option<SliceWear>,
    /// Mesh force and pair load along the path (rho1, load) for the wear-depth figures
    /// (with a tooth-resolved mesh: the mean load over the engagements at the grid points).
    pub path_rho1_m: Vec<f64>,
    /// Pair load at each of those points, N.
    pub path_load_n: Vec<f64>,
    /// Periodic state (SI, `dynamics::model` coordinates) at a mesh-period boundary of the
    /// dynamic response: where the next update's search starts. Absent for the
    /// quasi-static mode and in checkpoints written before it existed (cold start then).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_state: Option<Vec<f64>>,
}

/// A wear profile with its wear per cycle over the block after the record (m, m per cycle).
pub type ProfileAndIncrement<'a> = (&'a [f64], &'a [f64]);

impl UpdateRecord {
    /// The pinion profiles the record holds with their per-cycle wear: every tooth's when
    /// the mesh is tooth-resolved (the deepest wear is on one tooth), every face slice's
    /// of a helical pair, else the common one.
    pub fn pinion_profiles(&self) -> Vec<ProfileAndIncrement<'_>> {
        match (&self.wear.teeth, &self.increment_teeth) {
            (Some(h), Some(d)) => pairs(&h.pinion_m, &d.pinion_m),
            _ => match (&self.wear.slices, &self.increment_slices) {
                (Some(h), Some(d)) => pairs(&h.pinion_m, &d.pinion_m),
                _ => vec![(&self.wear.pinion_m, &self.increment_pinion_m)],
            },
        }
    }

    /// Largest pinion wear per cycle over the block after the record (m per cycle), over
    /// every tooth when the mesh is tooth-resolved: the rate of the fastest-wearing tooth,
    /// consistent with the deepest-tooth maximum wear (the mean tooth's would understate it).
    pub fn max_increment_pinion_m(&self) -> f64 {
        self.pinion_profiles()
            .iter()
            .flat_map(|(_, d)| d.iter())
            .fold(0.0_f64, |a, b| a.max(*b))
    }

    /// The per-cycle wear held over the block after the record.
    pub fn increment(&self) -> WearIncrement {
        WearIncrement {
            pinion_m: self.increment_pinion_m.clone(),
            gear_m: self.increment_gear_m.clone(),
            teeth: self.increment_teeth.clone(),
            slices: self.increment_slices.clone(),
            ..Default::default()
        }
    }

    /// What is wrong with the record's wear profiles and per-cycle wear for a profile grid
    /// of `n` points: one of another length, or holding a value that is not finite and
    /// >= 0 (wear only grows); None when they are sound.
    pub fn profile_problem(&self, n: usize) -> Option<String> {
        for (name, v) in [
            ("pinion wear", &self.wear.pinion_m),
            ("gear wear", &self.wear.gear_m),
            ("pinion wear increment", &self.increment_pinion_m),
            ("gear wear increment", &self.increment_gear_m),
        ] {
            if v.len() != n {
                return Some(format!(
                    "{name} has {} points, the profile grid has {n}",
                    v.len()
                ));
            }
            if let Some(x) = v.iter().find(|x| !x.is_finite() || **x < 0.0) {
                return Some(format!("{name} holds {x}, not a finite value >= 0"));
            }
        }
        let slices = [
            (
                "pinion wear",
                self.wear.slices.as_ref().map(|s| &s.pinion_m),
            ),
            ("gear wear", self.wear.slices.as_ref().map(|s| &s.gear_m)),
            (
                "pinion wear increment",
                self.increment_slices.as_ref().map(|s| &s.pinion_m),
            ),
            (
                "gear wear increment",
                self.increment_slices.as_ref().map(|s| &s.gear_m),
            ),
        ];
        for (name, profiles) in slices {
            for (j, v) in profiles.into_iter().flatten().enumerate() {
                if v.len() != n || v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                    return Some(format!(
                        "{name} of face slice {j} has {} points or a value that is not finite and >= 0 (the profile grid has {n})",
                        v.len()
                    ));
                }
            }
        }
        None
    }

    /// The gear's, as [`Self::pinion_profiles`].
    pub fn gear_profiles(&self) -> Vec<ProfileAndIncrement<'_>> {
        match (&self.wear.teeth, &self.increment_teeth) {
            (Some(h), Some(d)) => pairs(&h.gear_m, &d.gear_m),
            _ => match (&self.wear.slices, &self.increment_slices) {
                (Some(h), Some(d)) => pairs(&h.gear_m, &d.gear_m),
                _ => vec![(&self.wear.gear_m, &self.increment_gear_m)],
            },
        }
    }
}

fn pairs<'a>(h: &'a [Vec<f64>], d: &'a [Vec<f64>]) -> Vec<ProfileAndIncrement<'a>> {
    h.iter()
        .zip(d)
        .map(|(h, d)| (h.as_slice(), d.as_slice()))
        .collect()
}

/// Most of the mesh period the teeth may be apart before a wear run stops (model
/// validity, see the module docs).
pub const MAX_CONTACT_LOSS_FRACTION: f64 = 0.5;

/// Why a wear run stopped before its total cycles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StopKind {
    /// The worn teeth left the model's domain (a result, not a failure).
    ModelValidity,
    /// No steady state even after the retries (a solver limitation).
    Numerical,
}

/// Where and why a wear run stopped early.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WearStop {
    /// Cycles of the update that could not be kept (the last record is before it).
    pub cycles: f64,
    /// Why it stopped.
    pub kind: StopKind,
    /// The stop in words.
    pub reason: String,
}

/// A wear run: its mode and every update so far.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WearRun {
    /// The solver feeding the wear model.
    pub mode: WearMode,
    /// Every update so far, the first on new teeth.
    pub records: Vec<UpdateRecord>,
    /// Set when the run stopped before the case's total cycles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stopped: Option<WearStop>,
}

impl WearRun {
    /// A run of mode `mode` with no update yet.
    pub fn new(mode: WearMode) -> Self {
        Self {
            mode,
            records: Vec::new(),
            stopped: None,
        }
    }

    /// Pinion cycles of each update.
    pub fn cycles(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.cycles).collect()
    }

    /// Deepest pinion wear of each update, m.
    pub fn max_wear_pinion_m(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.max_pinion_m()).collect()
    }

    /// Deepest gear wear of each update, m.
    pub fn max_wear_gear_m(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.max_gear_m()).collect()
    }

    /// The last update, if any.
    pub fn last(&self) -> Option<&UpdateRecord> {
        self.records.last()
    }
}

/// The next block of several meshes or member flanks worn together on one cycle counter
/// (paper eq. 17 for each; trains, spectra on trains, planetary sets): `rates` holds each
/// one's largest wear per counted cycle, m; the fastest cuts m (`wear.block_cycles`) to
/// `wear.threshold_um`, and the total to `remaining`. Returns the block, cycles, and the
/// index of the fastest when the threshold cut it.
pub fn fastest_block(
    rates: impl IntoIterator<Item = f64>,
    wear: &crate::config::case::WearSection,
    remaining: f64,
) -> (f64, Option<usize>) {
    let (lim, rate) = rates
        .into_iter()
        .enumerate()
        .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
    let n = block_length(rate, wear.block_cycles, wear.threshold_um * 1e-6, remaining);
    (n, (n < wear.block_cycles.min(remaining)).then_some(lim))
}

/// Length of the next block, cycles: m, cut to the threshold and to the total.
pub fn block_length(inc_max_m: f64, block_cycles: f64, threshold_m: f64, remaining: f64) -> f64 {
    let mut n = block_cycles.min(remaining);
    if inc_max_m > 0.0 && n * inc_max_m > threshold_m {
        n = (threshold_m / inc_max_m).floor().max(1.0);
    }
    n.min(remaining)
}

/// The response of a wear state: dynamic (warm-started from `start`, retried as the
/// module docs say) or quasi-static.
pub fn solve(
    model: &Model,
    mode: WearMode,
    wear: &WearState,
    start: Option<&[f64]>,
) -> Result<DynamicResponse, DynamicsError> {
    let none = ExternalError::none();
    solve_by(
        &model.settings,
        mode,
        start,
        &|| model.quasi_static(wear, &none),
        &|s, settings| model.dynamic_with(wear, &none, s, settings),
    )
}

/// The quasi-static response (`quasi`), or the dynamic one (`dynamic(start, settings)`)
/// from `start` with `settings`, retried as the module docs say: from the static
/// equilibrium, then with a ten times tighter integration tolerance, twice the grid
/// nodes and periods. The steps of [`solve`], for any system (a single pair, a train).
pub fn solve_by(
    settings: &SteadyStateSettings,
    mode: WearMode,
    start: Option<&[f64]>,
    quasi: &dyn Fn() -> DynamicResponse,
    dynamic: &DynamicSolve<'_>,
) -> Result<DynamicResponse, DynamicsError> {
    if mode == WearMode::QuasiStatic {
        return Ok(quasi());
    }
    let first = dynamic(start, settings);
    if first.is_ok() {
        return first;
    }
    if start.is_some() {
        if let Ok(r) = dynamic(None, settings) {
            return Ok(r);
        }
    }
    let mut tight = *settings;
    tight.integration_tolerance *= 0.1;
    tight.steps_per_mesh_period *= 2;
    tight.max_mesh_periods *= 2;
    dynamic(None, &tight)
}

/// A steady-state solve from a start (`None`: the static equilibrium) with settings.
pub type DynamicSolve<'a> =
    dyn Fn(Option<&[f64]>, &SteadyStateSettings) -> Result<DynamicResponse, DynamicsError> + 'a;

/// The record of a helical pair's response `r` on `wear` from its slices' increments
/// (per slice, or per tooth and slice) and load along the profile, `(inc, load)`.
fn slices_record(
    (model, mode, wear, r): (&Model, WearMode, WearState, &DynamicResponse),
    (inc, load): (WearIncrement, Vec<f64>),
) -> UpdateRecord {
    UpdateRecord {
        roughness_um: model.roughness_for(&wear),
        wear,
        summary: ResponseSummary::of(r),
        increment_pinion_m: inc.pinion_m,
        increment_gear_m: inc.gear_m,
        increment_teeth: inc.teeth,
        increment_slices: inc.slices,
        path_rho1_m: model.grid.rho_pinion_m.clone(),
        path_load_n: load,
        end_state: (mode == WearMode::Dynamic).then(|| r.end_state.to_vec()),
    }
}

/// The record of a response on `wear`: its summary, the per-cycle wear it gives (paper
/// eq. 14-17; per tooth when the mesh is tooth-resolved) and the state the next search
/// starts from.
pub fn record(model: &Model, mode: WearMode, wear: WearState, r: &DynamicResponse) -> UpdateRecord {
    let line_teeth = (model.teeth.as_ref()).and_then(|t| t.line_teeth().map(|l| (t, l)));
    if let (Some(h), Some((teeth, lt))) = (&model.helical, line_teeth) {
        if lt.slices > 1 {
            // A helical pair's teeth worn tooth by tooth and slice by slice
            // (docs/MODEL.md 11.13); one slice is its own line: the spur pair's
            // per-tooth record below.
            let parts = super::helical_tooth_wear::record_parts(model, h, teeth, lt, r, &wear);
            return slices_record((model, mode, wear, r), parts);
        }
    } else if let Some(h) = &model.helical {
        let parts = super::helical_wear::record_parts(model, h, r, &wear);
        return slices_record((model, mode, wear, r), parts);
    }
    let (z1, z2) = (model.pair.pinion.teeth, model.pair.gear.teeth);
    let parts = MeshWearParts {
        grid: &model.grid,
        teeth: [z1, z2],
        coefficient_m2_per_n: model.case.wear.coefficient_m2_per_n,
    };
    let roughness_um = model.roughness_for(&wear);
    let summary = ResponseSummary::of(r);
    if model.teeth.is_none() {
        return mesh_record(&parts, 0, mode, wear, roughness_um, summary, r);
    }
    let periods = r.excitation_periods;
    tooth_record(&parts, (0, periods), mode, wear, roughness_um, summary, r)
}

/// The record of tooth-resolved mesh `m` of a response `r` on its per-tooth wear state
/// `wear`, its path over `periods` of its own mesh periods (the response's excitation
/// period; `PathSample::cycle` its engagement modulo them): each tooth's Archard
/// increments per pinion cycle from the engagements it meets (`wear::per_tooth`), the
/// mean pair load over the engagements at the grid points, `summary`; the periodic end
/// state kept with mesh 0's record. The single pair's (m = 0, `periods` = the response's
/// excitation periods) and a faulty train stage's (docs/MODEL.md 9.10).
pub(crate) fn tooth_record(
    parts: &MeshWearParts,
    (m, periods): (usize, usize),
    mode: WearMode,
    wear: WearState,
    roughness_um: f64,
    summary: ResponseSummary,
    r: &DynamicResponse,
) -> UpdateRecord {
    let [z1, z2] = parts.teeth;
    let path = &r.meshes[m].path;
    let inc = per_tooth_wear(
        parts.grid,
        path,
        periods,
        z1,
        z2,
        parts.coefficient_m2_per_n,
    );
    let (path_rho1_m, path_load_n) = mean_load_along_path(parts.grid, path, periods);
    UpdateRecord {
        roughness_um,
        wear,
        summary,
        increment_pinion_m: inc.pinion_m,
        increment_gear_m: inc.gear_m,
        increment_teeth: inc.teeth,
        increment_slices: None,
        path_rho1_m,
        path_load_n,
        end_state: (mode == WearMode::Dynamic && m == 0).then(|| r.end_state.to_vec()),
    }
}

/// What the wear of one mesh with identical teeth needs: its profile grid, its tooth
/// counts (pinion, gear) and the Archard coefficient k, m^2/N.
pub(crate) struct MeshWearParts<'a> {
    pub grid: &'a ProfileGrid,
    pub teeth: [usize; 2],
    pub coefficient_m2_per_n: f64,
}

/// The record of mesh `m` of a response `r` on its wear state `wear` (every tooth
/// alike): the Archard increments per pinion cycle of its path (paper eq. 14-17), its
/// pair load along the path, `summary`; the periodic end state is kept with mesh 0's
/// record (the whole system's, one per update).
pub(crate) fn mesh_record(
    parts: &MeshWearParts,
    m: usize,
    mode: WearMode,
    wear: WearState,
    roughness_um: f64,
    summary: ResponseSummary,
    r: &DynamicResponse,
) -> UpdateRecord {
    let [z1, z2] = parts.teeth;
    let path = &r.meshes[m].path;
    let inc = per_cycle_wear(
        parts.grid,
        path,
        parts.coefficient_m2_per_n,
        z1 as f64 / z2 as f64,
    );
    UpdateRecord {
        roughness_um,
        wear,
        summary,
        increment_pinion_m: inc.pinion_m,
        increment_gear_m: inc.gear_m,
        increment_teeth: inc.teeth,
        increment_slices: None,
        path_rho1_m: path.iter().map(|p| p.rho1_m).collect(),
        path_load_n: path.iter().map(|p| p.load_n).collect(),
        end_state: (mode == WearMode::Dynamic && m == 0).then(|| r.end_state.to_vec()),
    }
}

/// The pair load at the points of `grid`, averaged over the `periods` engagements of the
/// excitation period (the `path` of a tooth-resolved mesh holds every engagement's
/// samples, tagged with their mesh cycle).
fn mean_load_along_path(
    grid: &ProfileGrid,
    path: &[crate::dynamics::response::PathSample],
    periods: usize,
) -> (Vec<f64>, Vec<f64>) {
    let periods = periods.max(1);
    let mut by: Vec<Vec<crate::dynamics::response::PathSample>> = vec![Vec::new(); periods];
    for s in path {
        by[s.cycle.rem_euclid(periods as i64) as usize].push(*s);
    }
    let rho = grid.rho_pinion_m.clone();
    let load = rho
        .iter()
        .map(|x| {
            by.iter()
                .map(|p| crate::dynamics::response::interpolate_path(p, *x).load_n)
                .sum::<f64>()
                / periods as f64
        })
        .collect();
    (rho, load)
}

/// The warm start a record offers.
pub fn start_of(rec: &UpdateRecord) -> Option<Vec<f64>> {
    let s = rec.end_state.as_ref()?;
    (!s.is_empty()).then(|| s.clone())
}

/// What the update after a record gives.
#[derive(Debug, Clone, PartialEq)]
pub enum Next {
    /// A new record.
    Record(Box<UpdateRecord>),
    /// The run stops before this update (it is not recorded).
    Stop(WearStop),
    /// The total cycles are reached.
    Finished,
}

/// The wear state the update after `last` is solved on (paper eq. 17): `last`'s wear
/// advanced by its per-cycle increment (every face slice or tooth by its own) over the
/// next block, cut to the case's threshold and total ([`block_length`]); None when the
/// total is reached. Also recomputed to check a stored run's chain (`study::wear_check`).
pub fn advanced_state(model: &Model, last: &UpdateRecord) -> Option<WearState> {
    let w = &model.case.wear;
    let threshold_m = w.threshold_um * 1e-6;
    let remaining = w.total_cycles - last.wear.cycles;
    if remaining <= 0.5 {
        return None;
    }
    let inc = last.increment();
    let n = block_length(inc.max_m(), w.block_cycles, threshold_m, remaining);
    let mut state = last.wear.clone();
    state.advance(&inc, n);
    Some(state)
}

/// The update after `last` (`None`: the first update, new teeth at cycle 0), exactly as
/// [`run_wear`] makes it: the loop's one step, also used to verify a checkpoint by
/// recomputing its last update (`study::wear_check`). Only the first update's failure is
/// an error; a later one is a stop.
pub fn next_update(
    model: &Model,
    mode: WearMode,
    last: Option<&UpdateRecord>,
) -> Result<Next, DynamicsError> {
    let Some(last) = last else {
        let state = model.new_wear_state();
        let r = solve(model, mode, &state, None)?;
        return Ok(Next::Record(Box::new(record(model, mode, state, &r))));
    };
    let Some(state) = advanced_state(model, last) else {
        return Ok(Next::Finished);
    };
    let start = start_of(last);
    Ok(match solve(model, mode, &state, start.as_deref()) {
        Ok(r) if r.contact_loss_fraction() > MAX_CONTACT_LOSS_FRACTION => Next::Stop(WearStop {
            cycles: state.cycles,
            kind: StopKind::ModelValidity,
            reason: format!(
                "at {:.0} cycles (maximum pinion wear {:.2} µm) the teeth are out of contact for {:.0} % of the mesh period (more than {:.0} %): the wear model of a steady contact no longer applies",
                state.cycles,
                state.max_pinion_m() * 1e6,
                100.0 * r.contact_loss_fraction(),
                100.0 * MAX_CONTACT_LOSS_FRACTION
            ),
        }),
        Ok(r) => Next::Record(Box::new(record(model, mode, state, &r))),
        Err(e) => Next::Stop(WearStop {
            cycles: state.cycles,
            kind: StopKind::Numerical,
            reason: format!(
                "at {:.0} cycles (maximum pinion wear {:.2} µm) no steady state was found, even from the static equilibrium with a 10x tighter numerics.integration_tolerance and 2x the numerics.steps_per_mesh_period: {e}",
                state.cycles,
                state.max_pinion_m() * 1e6
            ),
        }),
    })
}

/// Run (or continue) a wear study to the case's total cycles. `on_update` is called after
/// every update with the run so far (checkpointing, progress); an error it returns stops
/// the run. The returned run may have stopped early ([`WearRun::stopped`]); only the
/// response of new teeth failing is an error.
pub fn run_wear(
    model: &Model,
    mut run: WearRun,
    on_update: &mut dyn FnMut(&WearRun) -> anyhow::Result<()>,
) -> anyhow::Result<WearRun> {
    if run.records.is_empty() {
        if let Next::Record(r) = next_update(model, run.mode, None)? {
            run.records.push(*r);
        }
        on_update(&run)?;
    }
    while run.stopped.is_none() {
        match next_update(model, run.mode, run.records.last())? {
            Next::Finished => break,
            Next::Stop(s) => run.stopped = Some(s),
            Next::Record(r) => run.records.push(*r),
        }
        on_update(&run)?;
    }
    Ok(run)
}

/// Run (or continue) several wear runs in parallel (e.g. the dynamic study and its
/// quasi-static twin); `on_update(mode, run)` after every update of each. Results in the
/// order of `starts`. When one run fails, the others stop at their next update, so the
/// failure is reported at once rather than after the slower run has finished; the error
/// returned is the first run's own, not a sibling's stop.
pub fn run_wear_modes(
    model: &Model,
    starts: Vec<WearRun>,
    on_update: &(dyn Fn(WearMode, &WearRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<Vec<WearRun>> {
    super::parallel_runs::run_in_parallel(
        starts,
        |r| r.mode,
        &|start, f| run_wear(model, start, f),
        on_update,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_is_cut_to_threshold_and_total() {
        // 1e-10 m per cycle, threshold 0.5 um: 5000 cycles, not the 1e4 of the block.
        assert_eq!(block_length(1e-10, 1e4, 0.5e-6, 4e4), 5000.0);
        // Slow wear: the full block.
        assert_eq!(block_length(1e-12, 1e4, 0.5e-6, 4e4), 1e4);
        // Near the end: what remains.
        assert_eq!(block_length(1e-12, 1e4, 0.5e-6, 300.0), 300.0);
        // No wear at all: the full block (no division by zero).
        assert_eq!(block_length(0.0, 1e4, 0.5e-6, 4e4), 1e4);
    }
}
