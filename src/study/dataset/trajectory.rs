//! A run-to-failure trajectory: the dynamic wear loop of a condition's case, run until
//! the deepest wear reaches the limit (failure) or to the largest cycle count asked for,
//! and the wear state at any cycle count along it.
//!
//! Between two updates the loop holds the per-cycle wear of the earlier one (paper eq.
//! 17), so the state at c cycles is the earlier record advanced by its increment for
//! the cycles since: exactly what the loop itself would have reached at c. The failure
//! cycle count is where the deepest wear (pinion or gear profile) reaches the limit,
//! found the same way (linear within the block). A run that stops before (at the edge
//! of the model's domain, or at the largest cycle count) leaves the failure unobserved:
//! its remaining life is right-censored at the trajectory's end.
//!
//! A gear train's trajectory (`[[stage]]`) is its own wear loop (`study::train_wear`):
//! every mesh wears at its own cycle count, mesh k's pinion turning c_k times per input
//! cycle (the revolutions of stage 1's pinion). Its state is a wear state per mesh; the
//! records are stage 1's (whose cycles are the input cycles) and each later stage's,
//! one per update, and the state at c input cycles is each mesh's record advanced by
//! c_k times the input cycles since, as the train's loop advances them
//! (`train_wear::next_block`). Failure is the deepest wear of any mesh reaching the
//! limit. A single pair is the one-mesh case with c_1 = 1.

use crate::study::train_wear::{run_train_wear, TrainWearRun};
use crate::study::wear_loop::{run_wear, UpdateRecord, WearMode, WearRun};
use crate::study::Model;
use crate::wear::{WearIncrement, WearState};
use serde::{Deserialize, Serialize};

/// The updates of a trajectory and where it ended.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Trajectory {
    /// The wear run's updates, in order of cycles (a train: stage 1's records, whose
    /// cycles are the input cycles).
    pub records: Vec<UpdateRecord>,
    /// A train's later stages' records (stage 2 first), one per update as `records`;
    /// empty for a single pair (and a one-stage train).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub later_stages: Vec<Vec<UpdateRecord>>,
    /// A train's pinion revolutions of each stage per input cycle (c_k,
    /// `TrainModel::cycle_factors`, stage order); empty for a single pair (c = 1).
    /// Checked against the model's own on reuse (`super::verify`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cycle_factors: Vec<f64>,
    /// A planetary set's planets N (`super::planetary`): its 2 N meshes' records are
    /// `records` (planet 1's sun mesh) and `later_stages`, and its failure measure is the
    /// deepest member flank (`super::planetary::members_deepest_m`); 0 otherwise.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub planets: usize,
    /// A planetary set's input cycles (revolutions of its input member) at each update,
    /// the axis of its states (its meshes' own counts are their pinions' revolutions
    /// relative to the carrier); empty otherwise (the first mesh's cycles are the axis).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub input_cycles: Vec<f64>,
    /// Cycle count at which the deepest wear reached the limit, if it did.
    pub failure_cycles: Option<f64>,
    /// Last cycle count the trajectory covers.
    pub end_cycles: f64,
    /// Why the wear loop stopped before `end_cycles` asked for, if it did.
    pub stopped: Option<String>,
}

/// Whether a count is 0 (serde: a field absent unless set).
fn is_zero(n: &usize) -> bool {
    *n == 0
}

/// Deepest wear of a state (pinion or gear), m.
pub fn deepest_m(w: &WearState) -> f64 {
    w.max_pinion_m().max(w.max_gear_m())
}

/// Deepest wear of every mesh's state (the train's failure measure), m.
pub fn deepest_of(states: &[WearState]) -> f64 {
    states.iter().map(deepest_m).fold(0.0, f64::max)
}

/// Deepest point of a profile, m (0 for an empty one).
fn max_of(p: &[f64]) -> f64 {
    p.iter().fold(0.0_f64, |a, b| a.max(*b))
}

/// Point-wise sum of profiles (the longest's length).
fn summed<'a>(profiles: impl Iterator<Item = &'a Vec<f64>>) -> Vec<f64> {
    let mut s: Vec<f64> = Vec::new();
    for p in profiles {
        if s.len() < p.len() {
            s.resize(p.len(), 0.0);
        }
        for (a, b) in s.iter_mut().zip(p) {
            *a += b;
        }
    }
    s
}

/// Every member's deepest wear, m, from the set's meshes' states `states` (module order,
/// `planets` N): the sun, planets 1..N (their deeper flank), the ring (module docs).
pub fn member_depths_m(states: &[WearState], planets: usize) -> Vec<f64> {
    let n = planets.min(states.len() / 2);
    let (sun_meshes, ring_meshes) = states.split_at(n);
    let sun = max_of(&summed(sun_meshes.iter().map(|w| &w.pinion_m)));
    let ring = max_of(&summed(ring_meshes.iter().map(|w| &w.gear_m)));
    let planets = (0..n).map(|p| max_of(&states[p].gear_m).max(max_of(&states[n + p].pinion_m)));
    std::iter::once(sun)
        .chain(planets)
        .chain(std::iter::once(ring))
        .collect()
}

/// The set's failure measure: its deepest member's wear, m (module docs).
pub fn members_deepest_m(states: &[WearState], planets: usize) -> f64 {
    member_depths_m(states, planets)
        .into_iter()
        .fold(0.0, f64::max)
}

/// The per-cycle wear the loop held after update `r` (every tooth's own with a
/// tooth-resolved mesh, every face slice's own on a helical pair, so that a state between
/// updates advances each tooth or slice: `UpdateRecord::increment`).
fn increment(r: &UpdateRecord) -> WearIncrement {
    r.increment()
}

/// Marks the early stop of a run at the wear limit (not an error).
#[derive(Debug, thiserror::Error)]
#[error("the wear limit was reached")]
struct LimitReached;

/// The model a condition's trajectory runs: its case with `wear.total_cycles` set to
/// the design's `max_cycles`, built as `model` was (a helical pair's planar model with
/// its wear per slice, `Model::rebuilt_like`; warnings dropped: the dataset reports its
/// own).
pub fn trajectory_model(model: &Model, max_cycles: f64) -> anyhow::Result<Model> {
    let mut m2 = model
        .rebuilt_like(&{
            let mut c = model.case.clone();
            c.wear.total_cycles = max_cycles;
            c
        })
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    m2.warnings.clear();
    Ok(m2)
}

/// Run the trajectory of `model` (its case at its operating point) up to `max_cycles`
/// or until the deepest wear reaches `limit_m`.
pub fn run_trajectory(model: &Model, max_cycles: f64, limit_m: f64) -> anyhow::Result<Trajectory> {
    let m2 = trajectory_model(model, max_cycles)?;
    if m2.train.is_some() {
        return run_train_trajectory(&m2, limit_m);
    }
    let mut last = WearRun::new(WearMode::Dynamic);
    let result = run_wear(&m2, WearRun::new(WearMode::Dynamic), &mut |r| {
        last = r.clone();
        match r.last() {
            Some(rec) if deepest_m(&rec.wear) >= limit_m => Err(LimitReached.into()),
            _ => Ok(()),
        }
    });
    let run = match result {
        Ok(run) => run,
        Err(e) if e.is::<LimitReached>() => last,
        Err(e) => return Err(e),
    };
    Ok(Trajectory::from_records(
        run.records,
        run.stopped.map(|s| s.reason),
        limit_m,
    ))
}

/// The trajectory of the train of `m2` (the trajectory's model, `wear.total_cycles` at
/// the design's `max_cycles`): its wear loop run until the deepest wear of any mesh
/// reaches `limit_m` (see the module docs).
fn run_train_trajectory(m2: &Model, limit_m: f64) -> anyhow::Result<Trajectory> {
    let train = m2
        .train
        .as_ref()
        .ok_or_else(|| anyhow::anyhow!("not a train"))?;
    let mut last = TrainWearRun::new(WearMode::Dynamic);
    let result = run_train_wear(m2, train, TrainWearRun::new(WearMode::Dynamic), &mut |r| {
        last = r.clone();
        match r.updates.last() {
            Some(u) if u.meshes.iter().any(|m| deepest_m(&m.wear) >= limit_m) => {
                Err(LimitReached.into())
            }
            _ => Ok(()),
        }
    });
    let run = match result {
        Ok(run) => run,
        Err(e) if e.is::<LimitReached>() => last,
        Err(e) => return Err(e),
    };
    let mut meshes: Vec<Vec<UpdateRecord>> = (0..train.stages.len())
        .map(|m| run.mesh_records(m))
        .collect();
    let first = meshes.remove(0);
    Ok(Trajectory::from_meshes(
        (first, meshes),
        train.cycle_factors(),
        run.stopped.map(|s| s.reason),
        limit_m,
    ))
}

impl Trajectory {
    /// Each mesh's updates as a dynamic wear run's log (the first mesh's `records`, then
    /// `later_stages`: a train's stages or a set's further meshes), for the wear loops'
    /// checks.
    pub(crate) fn mesh_logs(&self) -> Vec<WearRun> {
        std::iter::once(&self.records)
            .chain(&self.later_stages)
            .map(|r| WearRun {
                mode: WearMode::Dynamic,
                records: r.clone(),
                stopped: None,
            })
            .collect()
    }

    /// The trajectory of the wear loop's `records` (and why it stopped early, if it did)
    /// under the wear limit `limit_m`: its end and failure cycles derived from the
    /// records (so a kept trajectory's derived fields can be checked by deriving them
    /// again, `super::verify`).
    pub fn from_records(records: Vec<UpdateRecord>, stopped: Option<String>, limit_m: f64) -> Self {
        Self::from_meshes((records, Vec::new()), Vec::new(), stopped, limit_m)
    }

    /// As [`Trajectory::from_records`] for a train: stage 1's records and the later
    /// stages', each stage's pinion revolutions per input cycle `cycle_factors` (empty:
    /// a single pair), the failure where the deepest wear of any mesh reaches the limit.
    pub fn from_meshes(
        (records, later_stages): (Vec<UpdateRecord>, Vec<Vec<UpdateRecord>>),
        cycle_factors: Vec<f64>,
        stopped: Option<String>,
        limit_m: f64,
    ) -> Self {
        let mut t = Trajectory {
            stopped,
            end_cycles: records.last().map_or(0.0, |r| r.wear.cycles),
            failure_cycles: None,
            records,
            later_stages,
            cycle_factors,
            planets: 0,
            input_cycles: Vec::new(),
        };
        t.derive_failure(limit_m);
        t
    }

    /// A planetary set's trajectory (`super::planetary`): its meshes' records in the
    /// loop's order (`meshes[0]` planet 1's sun mesh), their pinion turns per input turn
    /// `cycle_factors`, the updates' `input_cycles`, and its failure where the deepest
    /// member flank reaches `limit_m`.
    pub fn from_planetary(
        mut meshes: Vec<Vec<UpdateRecord>>,
        (cycle_factors, input_cycles): (Vec<f64>, Vec<f64>),
        stopped: Option<String>,
        limit_m: f64,
    ) -> Self {
        let planets = meshes.len() / 2;
        let records = if meshes.is_empty() {
            Vec::new()
        } else {
            meshes.remove(0)
        };
        let mut t = Trajectory {
            stopped,
            end_cycles: input_cycles.last().copied().unwrap_or(0.0),
            failure_cycles: None,
            planets,
            records,
            later_stages: meshes,
            cycle_factors,
            input_cycles,
        };
        t.derive_failure(limit_m);
        t
    }

    /// Set the failure cycles from the updates (see [`Trajectory::from_meshes`]).
    fn derive_failure(&mut self, limit_m: f64) {
        let t = &*self;
        let n = t.records.len();
        // Failure inside the last block: where the deepest wear crossed the limit.
        let failure_cycles = (1..n).find_map(|i| {
            let (a, b) = (t.deepest_at(i - 1), t.deepest_at(i));
            (a < limit_m && b >= limit_m).then(|| {
                // Per point the wear is linear in cycles within the block; the deepest point
                // may change inside it, so bisect on the state itself.
                let (mut lo, mut hi) = (t.cycles_at(i - 1), t.cycles_at(i));
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if t.deepest_of_states(&t.advanced(i - 1, mid)) >= limit_m {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                hi
            })
        });
        let at_start = n > 0 && t.deepest_at(0) >= limit_m;
        self.failure_cycles = failure_cycles.or_else(|| at_start.then_some(0.0));
    }

    /// Cycles of update `i` on the trajectory's axis: a planetary set's input cycles, else
    /// the first mesh's (a train's stage 1 pinion's are its input cycles).
    pub fn cycles_at(&self, i: usize) -> f64 {
        match self.input_cycles.get(i) {
            Some(c) if self.planets > 0 => *c,
            _ => self.records[i].wear.cycles,
        }
    }

    /// Failure measure of the meshes' states `states` (module order): the deepest member
    /// flank of a planetary set, else the deepest wear of any mesh, m.
    pub fn deepest_of_states(&self, states: &[WearState]) -> f64 {
        if self.planets > 0 {
            members_deepest_m(states, self.planets)
        } else {
            deepest_of(states)
        }
    }

    /// Meshes of the trajectory (1 for a single pair).
    pub fn mesh_count(&self) -> usize {
        1 + self.later_stages.len()
    }

    /// Mesh `m`'s record of update `i` (mesh 0: `records`).
    pub fn record(&self, m: usize, i: usize) -> Option<&UpdateRecord> {
        match m {
            0 => self.records.get(i),
            _ => self.later_stages.get(m - 1)?.get(i),
        }
    }

    /// Deepest wear of any mesh at update `i`, m.
    fn deepest_at(&self, i: usize) -> f64 {
        let states: Vec<WearState> = (0..self.mesh_count())
            .filter_map(|m| self.record(m, i))
            .map(|r| r.wear.clone())
            .collect();
        self.deepest_of_states(&states)
    }

    /// Every mesh's state at `cycles` (input cycles) from update `i`: each mesh's record
    /// advanced by its pinion's cycles since, c_k (`cycles` - the update's), as the
    /// train's loop advances it (c = 1 for a single pair).
    fn advanced(&self, i: usize, cycles: f64) -> Vec<WearState> {
        let extra = cycles - self.cycles_at(i);
        // Indexed by the mesh itself, so that each mesh takes its own c_k.
        (0..self.mesh_count())
            .filter_map(|m| self.record(m, i).map(|r| (m, r)))
            .map(|(m, r)| {
                let mut s = r.wear.clone();
                if extra > 0.0 {
                    match self.cycle_factors.get(m) {
                        Some(c) => s.advance(&increment(r), extra * c),
                        None => s.advance(&increment(r), extra),
                    }
                }
                s
            })
            .collect()
    }

    /// The wear state at `cycles` (at most the trajectory's end; see the module docs); a
    /// train's: its first stage's ([`Trajectory::states_at`] gives every mesh's).
    pub fn state_at(&self, cycles: f64) -> Option<WearState> {
        self.states_at(cycles).map(|mut s| s.swap_remove(0))
    }

    /// Every mesh's wear state at `cycles` (input cycles of a train; at most the
    /// trajectory's end; see the module docs), stage order.
    pub fn states_at(&self, cycles: f64) -> Option<Vec<WearState>> {
        if cycles > self.end_cycles * (1.0 + 1e-12) || self.records.is_empty() {
            return None;
        }
        // The last update at or before `cycles` (the axis ascends).
        let (mut lo, mut hi) = (0, self.records.len());
        while lo < hi {
            let mid = (lo + hi) / 2;
            if self.cycles_at(mid) <= cycles {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        let i = lo.saturating_sub(1);
        Some(self.advanced(i, cycles))
    }

    /// The cycle counts of `count` states evenly spaced from 0 to the trajectory's end
    /// (to the failure, when it was reached).
    pub fn even_states(&self, count: usize) -> Vec<f64> {
        let end = self
            .failure_cycles
            .unwrap_or(self.end_cycles)
            .min(self.end_cycles);
        if count <= 1 {
            return vec![0.0];
        }
        (0..count)
            .map(|i| (end * i as f64 / (count - 1) as f64).round())
            .collect()
    }

    /// Remaining cycles to failure from `cycles`, and whether that is censored (the
    /// failure not reached: the remaining cycles to the trajectory's end, a lower bound).
    pub fn remaining(&self, cycles: f64) -> (f64, bool) {
        match self.failure_cycles {
            Some(f) => ((f - cycles).max(0.0), false),
            None => ((self.end_cycles - cycles).max(0.0), true),
        }
    }
}
