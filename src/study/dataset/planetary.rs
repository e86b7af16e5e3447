//! A planetary set's run-to-failure records (`[planetary]`, docs/MODEL.md 12.10): its
//! trajectory is the set's own wear loop (`study::planetary_wear_loop`, dynamic mode),
//! each state's record is what `gearwear signals` gives for the set (the ring sensor,
//! `study::planetary_signals`) from the steady state of the set with every mesh's wear gap
//! at the state (`planetary_wear::wear_gaps`), and its labels are per member.
//!
//! The trajectory keeps every mesh's update records (planet 1's sun mesh first, in the
//! loop's order), each mesh's pinion turns per input turn c_j (relative to the carrier:
//! `PlanetaryWearModel::pinion_cycles_per_input`) and the input cycles of every update,
//! the axis of its states (revolutions of the input member). The state at x input cycles
//! is each mesh's record advanced by c_j times the input cycles since, as the loop
//! advances it (`planetary_wear_loop::next_block`).
//!
//! Members' wear, as `gearwear wear` states it (`planetary_wear::member_flanks`): the sun's
//! loaded flank carries the sum of its N meshes' pinion wear, the ring's the sum of its N
//! meshes' gear wear, each planet's two flanks (sun side: its sun mesh's gear wear; ring
//! side: its ring mesh's pinion wear) never add. A member's deepest wear is its deepest
//! flank's deepest point; failure is the deepest member reaching the limit.

use super::trajectory::{member_depths_m, members_deepest_m, Trajectory};
use crate::config::case::Case;
use crate::study::planetary_signals::{ring_sensor_record, RingSensor, RingSensorRecord};
use crate::study::planetary_wear::{wear_gaps, PlanetaryWearModel};
use crate::study::planetary_wear_check::{planetary_run_from_logs, verify_planetary_resumable};
use crate::study::planetary_wear_loop::{next_block, run_planetary_wear, PlanetaryWearRun};
use crate::study::wear_check::StoredRunError;
use crate::study::wear_loop::{UpdateRecord, WearMode};
use crate::wear::WearState;
use serde::{Deserialize, Serialize};

/// A member's name in labels and columns: `sun`, `planet<n>` (1-based) or `ring`, for
/// member `i` of [`member_depths_m`]'s order.
pub fn member_name(i: usize, planets: usize) -> String {
    match i {
        0 => "sun".into(),
        i if i <= planets => format!("planet{i}"),
        _ => "ring".into(),
    }
}

/// The deepest wear of the meshes' driving flanks (the sun's, each planet's ring side)
/// and of their driven flanks (each planet's sun side, the ring's), m, from the meshes'
/// states `states` (module order, `planets` N): a set's `max_wear_pinion_um` and
/// `max_wear_gear_um` (the meshes' convention: the pinion is the sun in a sun mesh, the
/// planet in a ring mesh), the deeper of which is its deepest member's.
pub fn mesh_sides_m(states: &[WearState], planets: usize) -> (f64, f64) {
    let n = planets.min(states.len() / 2);
    let depths = member_depths_m(states, n);
    let max = |p: &Vec<f64>| p.iter().fold(0.0_f64, |a, b| a.max(*b));
    let ring_side = states[n..].iter().map(|w| max(&w.pinion_m));
    let sun_side = states[..n].iter().map(|w| max(&w.gear_m));
    (
        ring_side.fold(depths[0], f64::max),
        sun_side.fold(depths[n + 1], f64::max),
    )
}

/// One member of a planetary set in a record's labels: its deepest wear at the state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MemberLabels {
    /// `sun`, `planet<n>` or `ring`.
    pub member: String,
    /// The member's deepest wear (its deepest flank), µm.
    pub wear_max_um: f64,
    /// Load cycles of one of the member's teeth at the state: its tooth contacts (a
    /// planet's: per flank) over the state's input cycles, the input cycles times its
    /// contacts per input revolution (a sun tooth meets every planet once per sun turn
    /// relative to the carrier, a ring tooth every planet: `planetary_wear::contacts_per_input`).
    pub tooth_contacts: f64,
}

/// The members' labels at the meshes' states `states` (module order) of the set `model`
/// at `input_cycles`,
/// and the limiting member: the deepest-worn (the last of equals, 1-based in
/// [`member_depths_m`]'s order, as `study::train_wear::limiting_of` names a train's),
/// absent while nothing has worn.
pub fn member_labels(
    model: &PlanetaryWearModel,
    states: &[WearState],
    input_cycles: f64,
) -> (Vec<MemberLabels>, Option<String>) {
    let n = model.planets();
    let depths = member_depths_m(states, n);
    let [sun, planet, ring] = crate::study::planetary_wear::contacts_per_input(model);
    let labels: Vec<MemberLabels> = depths
        .iter()
        .enumerate()
        .map(|(i, d)| MemberLabels {
            member: member_name(i, n),
            wear_max_um: d * 1e6,
            tooth_contacts: input_cycles
                * match i {
                    0 => sun,
                    i if i <= n => planet,
                    _ => ring,
                },
        })
        .collect();
    let limiting = depths
        .iter()
        .enumerate()
        .filter(|(_, d)| **d > 0.0)
        .fold(None::<(usize, f64)>, |best, (i, d)| match best {
            Some((_, b)) if b > *d => best,
            _ => Some((i, *d)),
        })
        .map(|(i, _)| member_name(i, n));
    (labels, limiting)
}

/// Marks the early stop of a run at the wear limit (not an error).
#[derive(Debug, thiserror::Error)]
#[error("the wear limit was reached")]
struct LimitReached;

/// The wear model of a planetary `case` whose loop runs to `max_cycles` input cycles.
pub fn trajectory_wear_model(
    case: &Case,
    max_cycles: f64,
) -> anyhow::Result<(PlanetaryWearModel, crate::config::case::WearSection)> {
    let mut c = case.clone();
    c.wear.total_cycles = max_cycles;
    let m = PlanetaryWearModel::from_case(&c).map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok((m, c.wear))
}

/// The trajectory of the set of `case` (module docs): its dynamic wear loop run to
/// `max_cycles` input cycles or until its deepest member reaches `limit_m`.
pub fn run_planetary_trajectory(
    case: &Case,
    max_cycles: f64,
    limit_m: f64,
) -> anyhow::Result<Trajectory> {
    let (model, wear) = trajectory_wear_model(case, max_cycles)?;
    let n = model.planets();
    let mut last = PlanetaryWearRun::new(WearMode::Dynamic);
    let result = run_planetary_wear(
        &model,
        &wear,
        PlanetaryWearRun::new(WearMode::Dynamic),
        &mut |r| {
            last = r.clone();
            match r.updates.last() {
                Some(u) if members_deepest_m(&states_of(&u.meshes), n) >= limit_m => {
                    Err(LimitReached.into())
                }
                _ => Ok(()),
            }
        },
    );
    let run = match result {
        Ok(run) => run,
        Err(e) if e.is::<LimitReached>() => last,
        Err(e) => return Err(e),
    };
    Ok(trajectory_of_run(&model, &run, limit_m))
}

/// The wear states of an update's mesh records.
fn states_of(meshes: &[UpdateRecord]) -> Vec<WearState> {
    meshes.iter().map(|m| m.wear.clone()).collect()
}

/// Each mesh's pinion turns per input turn (module order).
fn cycle_factors(model: &PlanetaryWearModel) -> Vec<f64> {
    (0..2 * model.planets())
        .map(|j| model.pinion_cycles_per_input[model.kind_of(j).0])
        .collect()
}

/// The trajectory of a planetary wear run (its updates and where it stopped).
fn trajectory_of_run(
    model: &PlanetaryWearModel,
    run: &PlanetaryWearRun,
    limit_m: f64,
) -> Trajectory {
    let meshes: Vec<Vec<UpdateRecord>> = (0..2 * model.planets())
        .map(|j| run.updates.iter().map(|u| u.meshes[j].clone()).collect())
        .collect();
    let input_cycles = run.updates.iter().map(|u| u.input_cycles).collect();
    Trajectory::from_planetary(
        meshes,
        (cycle_factors(model), input_cycles),
        run.stopped.as_ref().map(|s| s.reason.clone()),
        limit_m,
    )
}

/// Check a kept planetary trajectory `t` against the set of `case` under `max_cycles` and
/// the limit `limit_m`, as a planetary set's wear checkpoints are checked
/// (`study::planetary_wear_check`): its meshes' records replayed block by block (the input
/// cycles recomputed by the loop's own step, which the kept ones must equal), a sample of
/// updates recomputed with the whole set's response, its end recomputed (the loop must
/// stop where it stops), its cycle factors the set's, its failure derived again.
pub fn verify_planetary_trajectory(
    case: &Case,
    max_cycles: f64,
    limit_m: f64,
    t: &Trajectory,
) -> Result<(), StoredRunError> {
    let mismatch = StoredRunError::Mismatch;
    let (model, wear) = trajectory_wear_model(case, max_cycles)
        .map_err(|e| StoredRunError::Model(e.to_string()))?;
    let n = t.records.len();
    if n == 0 || t.planets != model.planets() {
        return Err(mismatch(format!(
            "it holds {} updates of a set of {} planets, for a set of {} planets",
            n,
            t.planets,
            model.planets()
        )));
    }
    let logs = t.mesh_logs();
    if logs.iter().any(|l| l.records.len() != n) || t.input_cycles.len() != n {
        return Err(mismatch(
            "its meshes (or its input cycles) hold different numbers of updates".into(),
        ));
    }
    let run = planetary_run_from_logs(&model, &wear, WearMode::Dynamic, &logs).map_err(mismatch)?;
    if run.updates.len() != n {
        return Err(mismatch("its meshes' updates do not replay".into()));
    }
    if let Some(i) = (0..n).find(|i| run.updates[*i].input_cycles != t.input_cycles[*i]) {
        return Err(mismatch(format!(
            "update {i}: its input cycles {} are not the loop's step from the update before ({})",
            t.input_cycles[i], run.updates[i].input_cycles
        )));
    }
    verify_planetary_resumable(&model, &run).map_err(mismatch)?;
    if t.cycle_factors != cycle_factors(&model) {
        return Err(mismatch(format!(
            "its meshes' pinion turns per input turn (`cycle_factors` {:?}) are not the set's ({:?})",
            t.cycle_factors,
            cycle_factors(&model)
        )));
    }
    let deepest = |i: usize| members_deepest_m(&states_of(&run.updates[i].meshes), t.planets);
    if let Some(i) = (0..n - 1).find(|i| deepest(*i) >= limit_m) {
        return Err(mismatch(format!(
            "update {i} already reaches the wear limit, yet the trajectory goes on: the run stops there"
        )));
    }
    let mut again_run = run.clone();
    if deepest(n - 1) < limit_m && next_block(&model, &wear, &run.updates[n - 1]).is_some() {
        // The loop goes on from the last update: only a stop there (a response not
        // found, a mesh out of contact) ends it, which recomputing that step tells.
        let (cycles, by, wears) = next_block(&model, &wear, &run.updates[n - 1])
            .ok_or_else(|| mismatch("no next block".into()))?;
        match crate::study::planetary_wear_loop::update_of(&model, WearMode::Dynamic, (cycles, by), wears) {
            Ok(_) => {
                return Err(mismatch(format!(
                    "it ends at {} input cycles, below the wear limit and before `run_to_failure.max_cycles` = {max_cycles}, where the wear loop goes on: cut short",
                    t.input_cycles[n - 1]
                )))
            }
            Err((reason, _)) => {
                again_run.stopped = Some(crate::study::wear_loop::WearStop {
                    cycles,
                    kind: crate::study::wear_loop::StopKind::Numerical,
                    reason,
                })
            }
        }
    }
    let again = trajectory_of_run(&model, &again_run, limit_m);
    if again != *t {
        return Err(mismatch(format!(
            "its end ({} input cycles, failure {:?}, stopped {:?}) is not what its updates give ({} input cycles, failure {:?}, stopped {:?})",
            t.end_cycles, t.failure_cycles, t.stopped.is_some(), again.end_cycles, again.failure_cycles, again.stopped.is_some()
        )));
    }
    Ok(())
}

/// The ring sensor's record of the set `model` at its meshes' states `states` (module
/// order): the steady state of the set's dynamic model with every mesh's wear gap
/// (`planetary_wear::wear_gaps`), solved as `gearwear signals` solves it
/// (`PlanetaryDynamics::solve`), heard by `sensor` (`study::planetary_signals`). New
/// teeth give exactly the `signals` command's record.
pub fn ring_record_at(
    model: &PlanetaryWearModel,
    states: &[WearState],
    sensor: RingSensor,
) -> anyhow::Result<RingSensorRecord> {
    let mut d = model.dynamics.clone();
    let gaps = wear_gaps(model, states);
    if gaps.iter().any(|g| !g.is_zero()) {
        d.model.set_wear_gaps(gaps);
    }
    let r = d.solve().map_err(|e| anyhow::anyhow!("{e}"))?;
    ring_sensor_record(&d, &r, sensor).map_err(|e| anyhow::anyhow!("{e}"))
}

/// The trajectory of a condition whose case is `case` (module docs of
/// `super::trajectory`): a planetary set's ([`run_planetary_trajectory`]), else the
/// single pair's or the train's (`super::trajectory::run_trajectory`).
pub fn run_case_trajectory(
    case: &Case,
    max_cycles: f64,
    limit_m: f64,
) -> anyhow::Result<Trajectory> {
    if case.planetary.is_some() {
        return run_planetary_trajectory(case, max_cycles, limit_m);
    }
    let model = crate::study::Model::from_case(case).map_err(|e| anyhow::anyhow!("{e}"))?;
    super::trajectory::run_trajectory(&model, max_cycles, limit_m)
}

/// Check the kept trajectory `t` of a condition whose case is `case`: a planetary set's
/// ([`verify_planetary_trajectory`]), else the pair's or the train's
/// (`super::verify::verify_trajectory`). A set's trajectory kept for a pair or a train,
/// or the reverse, is refused.
pub fn verify_case_trajectory(
    case: &Case,
    max_cycles: f64,
    limit_m: f64,
    t: &Trajectory,
) -> Result<(), StoredRunError> {
    if case.planetary.is_some() {
        return verify_planetary_trajectory(case, max_cycles, limit_m, t);
    }
    if t.planets > 0 || !t.input_cycles.is_empty() {
        return Err(StoredRunError::Mismatch(
            "it holds a planetary set's meshes, but the condition's case is not a planetary set"
                .into(),
        ));
    }
    let model =
        crate::study::Model::from_case(case).map_err(|e| StoredRunError::Model(e.to_string()))?;
    super::verify::verify_trajectory(&model, max_cycles, limit_m, t)
}
