//! Is a stored wear run one that this model could have produced? Checked before a run is
//! resumed from a checkpoint, so an edited, truncated, reordered or foreign file is an
//! error rather than a silently wrong result.
//!
//! The facts checked follow from the update scheme (`wear_loop`, paper eq. 17): a run
//! starts with new teeth at cycle 0; every profile has one value per grid point; cycles
//! increase and stay within the study's total; wear and per-cycle increments are finite
//! and non-negative; each record's wear is the previous record's wear advanced by the
//! previous increment over the cycles between them; the roughness is the case's law at
//! the record's wear depth; a dynamic record holds its periodic end state (16 finite
//! numbers) and a quasi-static one none, so records of one mode cannot pass for the other;
//! a helical pair's record holds N face slices' wear, each exactly its previous wear
//! advanced over the recomputed block (docs/MODEL.md 11.3).

use super::model::Model;
use super::wear_loop::{advanced_state, next_update, Next, UpdateRecord, WearMode, WearRun};

/// Relative tolerance of the chain check: the advance is recomputed with the same
/// floating-point operations, so only the rounding of the cycle difference (exact for
/// whole cycles below 2^53) can differ; 1e-9 leaves room for that and still catches any
/// edit of a value by more than a part in a billion.
const CHAIN_TOL: f64 = 1e-9;

/// Why a stored run cannot be taken as this model's: its records are not ones the model
/// could have produced (the message says which record and what differs), or the model to
/// check them against could not be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StoredRunError {
    /// The records differ from what the model gives (which record, what differs).
    #[error("{0}")]
    Mismatch(String),
    /// The model the records are checked against cannot be built (its message).
    #[error("{0}")]
    Model(String),
}

impl StoredRunError {
    /// The message with each "line " (of a checkpoint's log) spelled `spelled` instead: a
    /// dataset's trajectories name their lines "record line ".
    pub fn lines_named(self, spelled: &str) -> Self {
        match self {
            StoredRunError::Mismatch(m) => StoredRunError::Mismatch(m.replace("line ", spelled)),
            e => e,
        }
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= CHAIN_TOL * a.abs().max(b.abs()) + 1e-30
}

/// Check `run` against `model` (see the module docs); the error says which record and
/// what is wrong.
pub fn check_wear_run(run: &WearRun, model: &Model) -> Result<(), StoredRunError> {
    check_records(run, model, true)
}

/// [`check_wear_run`] of a spectrum's run read as one run (`duty::contribution::
/// combined_run`), without a helical pair's per-slice chain: under a spectrum each face
/// slice advances by every bin's share in turn, not by the mixed rate over the block, so
/// the chain is the spectrum loop's own, replayed bit for bit by `duty::resume`.
pub(crate) fn check_spectrum_view(run: &WearRun, model: &Model) -> Result<(), StoredRunError> {
    check_records(run, model, false)
}

/// [`check_wear_run`], with the per-slice chain when `slice_chain`.
fn check_records(run: &WearRun, model: &Model, slice_chain: bool) -> Result<(), StoredRunError> {
    let Some(first) = run.records.first() else {
        return Err(StoredRunError::Mismatch("holds no update".into()));
    };
    if first.wear.cycles != 0.0
        || first.wear.max_pinion_m() != 0.0
        || first.wear.max_gear_m() != 0.0
    {
        return Err(StoredRunError::Mismatch(
            "its first update is not the new teeth at cycle 0".into(),
        ));
    }
    for (i, r) in run.records.iter().enumerate() {
        let at = |what: String| StoredRunError::Mismatch(format!("update {i}: {what}"));
        record_problem(run.mode, r, model).map_err(at)?;
        if i > 0 {
            step_problem(&run.records[i - 1], r).map_err(at)?;
            let chain = slice_chain.then(|| slice_chain_problem(model, &run.records[i - 1], r));
            if let Some(p) = chain.flatten() {
                return Err(StoredRunError::Mismatch(format!(
                    "line {} (update {i}): {p}",
                    i + 2
                )));
            }
        }
    }
    Ok(())
}

/// The first problem of record `r` of a run in `mode` on its own: wear and increments on
/// the case's grid, finite and >= 0, the per-tooth state, the end state the mode keeps,
/// cycles within the case's total, the roughness the case's law gives at its wear.
fn record_problem(mode: WearMode, r: &UpdateRecord, model: &Model) -> Result<(), String> {
    let n = model.grid.len();
    let total = model.case.wear.total_cycles;
    if let Some(problem) = r.profile_problem(n) {
        return Err(problem);
    }
    if let Some(problem) = tooth_problem(model, r) {
        return Err(problem);
    }
    if let Some(problem) = slice_problem(model, r) {
        return Err(problem);
    }
    if r.path_rho1_m.len() != r.path_load_n.len() {
        return Err("path positions and loads differ in length".into());
    }
    // A dynamic update keeps the periodic state its response ended on (the next
    // update's warm start); a quasi-static one has none.
    match (mode, &r.end_state) {
        (WearMode::Dynamic, Some(y)) if y.len() == model.state_len() && y.iter().all(|v| v.is_finite()) => {}
        (WearMode::Dynamic, _) => {
            return Err(format!(
                "a dynamic update must hold its periodic end state ({} finite numbers): this is not a dynamic run's record",
                model.state_len()
            ))
        }
        (WearMode::QuasiStatic, None) => {}
        (WearMode::QuasiStatic, Some(_)) => {
            return Err(
                "holds a dynamic end state: this is a dynamic run's record, not a quasi-static one".into(),
            )
        }
    }
    if !(r.wear.cycles.is_finite() && r.wear.cycles <= total + 0.5) {
        return Err(format!(
            "cycles {} outside 0..{total} (wear.total_cycles)",
            r.wear.cycles
        ));
    }
    if !close(r.roughness_um, model.roughness_for(&r.wear)) {
        return Err(format!(
            "roughness {} µm is not the case's {} µm at this wear depth",
            r.roughness_um,
            model.roughness_for(&r.wear)
        ));
    }
    Ok(())
}

/// The first problem of record `r` against the record `prev` before it: cycles that do
/// not increase, or a wear (overall or per tooth) that is not the previous wear plus the
/// cycles between them times the previous increment.
fn step_problem(prev: &UpdateRecord, r: &UpdateRecord) -> Result<(), String> {
    let dn = r.wear.cycles - prev.wear.cycles;
    if dn <= 0.0 {
        return Err(format!(
            "cycles {} do not follow the previous update's {}",
            r.wear.cycles, prev.wear.cycles
        ));
    }
    let advanced = |h0: &[f64], d: &[f64], h1: &[f64]| {
        h0.iter()
            .zip(d)
            .zip(h1)
            .position(|((a, d), b)| !close(a + dn * d, *b))
    };
    if let Some(j) = advanced(
        &prev.wear.pinion_m,
        &prev.increment_pinion_m,
        &r.wear.pinion_m,
    )
    .or_else(|| advanced(&prev.wear.gear_m, &prev.increment_gear_m, &r.wear.gear_m))
    {
        return Err(format!(
            "the wear at point {j} is not the previous wear plus {dn} cycles of the previous increment"
        ));
    }
    if let (Some(t0), Some(d), Some(t1)) = (&prev.wear.teeth, &prev.increment_teeth, &r.wear.teeth)
    {
        let teeth = |a: &[Vec<f64>], d: &[Vec<f64>], b: &[Vec<f64>]| {
            (0..a.len()).find_map(|t| advanced(&a[t], &d[t], &b[t]).map(|j| (t, j)))
        };
        let bad = teeth(&t0.pinion_m, &d.pinion_m, &t1.pinion_m)
            .map(|(t, j)| ("pinion", t, j))
            .or_else(|| teeth(&t0.gear_m, &d.gear_m, &t1.gear_m).map(|(t, j)| ("gear", t, j)));
        if let Some((g, t, j)) = bad {
            return Err(format!(
                "the wear of {g} tooth {t} at point {j} is not its previous wear plus {dn} cycles of its previous increment"
            ));
        }
    }
    Ok(())
}

/// A helical pair's per-slice chain (docs/MODEL.md 11.3): record `r`'s wear must be, bit
/// for bit, the state the wear loop makes from `prev` (each face slice's wear advanced by
/// its own increment over the block the case's threshold and total give,
/// `wear_loop::advanced_state`), recomputed here from `prev` rather than read from `r`
/// (its cycles included), so an edited slice value of any record is refused, not only of
/// the records the resume recomputes. None for a spur pair (its chain is
/// [`step_problem`]'s).
fn slice_chain_problem(model: &Model, prev: &UpdateRecord, r: &UpdateRecord) -> Option<String> {
    model.helical.as_ref()?;
    let Some(want) = advanced_state(model, prev) else {
        return Some(format!(
            "follows an update at {} cycles, where the case's wear.total_cycles {} is reached",
            prev.wear.cycles, model.case.wear.total_cycles
        ));
    };
    let block = want.cycles - prev.wear.cycles;
    if let (Some(a), Some(b)) = (&want.slices, &r.wear.slices) {
        for (flank, wa, wb) in [
            ("pinion", &a.pinion_m, &b.pinion_m),
            ("gear", &a.gear_m, &b.gear_m),
        ] {
            for (j, (pa, pb)) in wa.iter().zip(wb).enumerate() {
                if let Some(i) = pa.iter().zip(pb).position(|(x, y)| x != y) {
                    return Some(format!(
                        "the {flank} wear of face slice {j} at point {i} is {:e} m, not the previous update's plus {block} cycles of its increment ({:e} m, recomputed): the per-slice chain is broken",
                        pb[i], pa[i]
                    ));
                }
            }
        }
    }
    (want != r.wear).then(|| {
        format!(
            "its wear (at {} cycles) is not the previous update's advanced over the block to {} cycles at the previous rates, slice by slice",
            r.wear.cycles, want.cycles
        )
    })
}

/// Most records recomputed when a checkpoint is resumed (the first, the last, and a
/// random sample of the others): each costs one update, so resuming costs at most this
/// many updates whatever the run's length.
pub const MAX_RECOMPUTED: usize = 16;

/// `k` distinct indices of `0..n` drawn from the operating system's randomness (a forger
/// cannot know which), always including those in `always`; all of them when `n <= k`.
/// In increasing order.
pub fn random_sample(n: usize, k: usize, always: &[usize]) -> Vec<usize> {
    if n <= k {
        return (0..n).collect();
    }
    use std::hash::{BuildHasher, Hasher};
    let seed = std::collections::hash_map::RandomState::new();
    let mut picked: std::collections::BTreeSet<usize> =
        always.iter().copied().filter(|i| *i < n).collect();
    let mut j = 0u64;
    while picked.len() < k {
        let mut h = seed.build_hasher();
        h.write_u64(j);
        j += 1;
        picked.insert((h.finish() % n as u64) as usize);
    }
    picked.into_iter().collect()
}

/// Which records to recompute: all of a run of at most [`MAX_RECOMPUTED`] records, else
/// the first, the last and a random sample of the others.
fn records_to_recompute(n: usize) -> Vec<usize> {
    random_sample(n, MAX_RECOMPUTED, &[0, n.saturating_sub(1)])
}

/// Check `run` as [`check_wear_run`] does, then recompute records from the record before
/// each (the first from new teeth) and require each recomputed record to equal the stored
/// one bit for bit (compared as their JSON, which carries every double exactly): every
/// record of a run of up to [`MAX_RECOMPUTED`] records, else the first, the last and a
/// random sample. A record that this case's model does not reproduce (an edit with
/// recomputed checksums, a record of another case under this case's header, a spliced
/// tail) is refused, naming its line in the checkpoint (the header is line 1).
pub fn verify_resumable(run: &WearRun, model: &Model) -> Result<(), StoredRunError> {
    check_wear_run(run, model)?;
    for i in records_to_recompute(run.records.len()) {
        let prev = i.checked_sub(1).map(|j| &run.records[j]);
        let line = i + 2;
        let again = match next_update(model, run.mode, prev) {
            Ok(Next::Record(r)) => *r,
            Ok(_) | Err(_) => {
                return Err(StoredRunError::Mismatch(format!(
                    "line {line} (update {i}): this case's model makes no such update when it is recomputed from the record before it: the record is not this case's"
                )))
            }
        };
        let same =
            serde_json::to_string(&again).ok() == serde_json::to_string(&run.records[i]).ok();
        if !same {
            return Err(StoredRunError::Mismatch(format!(
                "line {line} (update {i}) is not what this case's model computes from the record before it (recomputed: max pinion wear {:.6e} m, mean mesh force {:.6} N; stored: {:.6e} m, {:.6} N): the record is not this case's, or was edited",
                again.wear.max_pinion_m(),
                again.summary.mesh_force_mean_n,
                run.records[i].wear.max_pinion_m(),
                run.records[i].summary.mesh_force_mean_n,
            )));
        }
    }
    Ok(())
}

/// A record's per-slice wear against the case: present (wear and increment) exactly when
/// the case is a helical pair that wears per slice (`Model::helical`), and then N profiles
/// on each flank (`HelicalDynamics::slices`); their lengths and values are
/// `UpdateRecord::profile_problem`'s.
fn slice_problem(model: &Model, r: &super::wear_loop::UpdateRecord) -> Option<String> {
    // A helical pair's resolved teeth keep their face slices per tooth
    // (`tooth_problem`, docs/MODEL.md 11.13), not a common per-slice state.
    let resolved = model.helical.is_some() && model.teeth.is_some();
    let n = (model.helical.as_ref())
        .filter(|_| !resolved)
        .map(|h| h.slices);
    for (what, s) in [("wear", &r.wear.slices), ("increment", &r.increment_slices)] {
        match (n, s) {
            (None, Some(_)) if resolved => {
                return Some(format!(
                    "holds per-slice {what} common to every tooth, but the case's per-tooth inputs wear each tooth's face slices on their own"
                ))
            }
            (None, Some(_)) => {
                return Some(format!(
                    "holds per-slice {what}, but the case is a spur pair"
                ))
            }
            (Some(_), None) => {
                return Some(format!(
                    "holds no per-slice {what}, but the case is a helical pair worn slice by slice"
                ))
            }
            (Some(n), Some(s)) if s.pinion_m.len() != n || s.gear_m.len() != n => {
                return Some(format!(
                    "per-slice {what} is not {n} profiles on each flank"
                ))
            }
            _ => {}
        }
    }
    None
}

/// The per-tooth profiles of a record against the model: present exactly when the model
/// resolves the teeth, one profile per tooth of the grid's length, finite and >= 0.
fn tooth_problem(model: &Model, r: &super::wear_loop::UpdateRecord) -> Option<String> {
    // A helical pair's: every tooth's face slices, tooth t's slice j at t N + j
    // (docs/MODEL.md 11.13).
    let n = model.helical.as_ref().map_or(1, |h| h.slices);
    let teeth = [model.pair.pinion.teeth * n, model.pair.gear.teeth * n];
    let resolved = model.teeth.is_some().then_some(teeth);
    let whose = ("the case", "per-tooth inputs");
    tooth_problem_of(resolved, model.grid.len(), r, whose)
}

/// The per-tooth profiles of a record of a mesh whose teeth are resolved with `resolved`
/// = Some([z1, z2]) (None: alike) on a grid of `n` points: present exactly when it
/// resolves them, one profile per tooth of the grid's length, finite and >= 0. The single
/// pair's check and a train stage's (`study::train_wear_check`); `whose`: who resolves
/// the teeth and why, for the message ("the case", "per-tooth inputs").
pub(crate) fn tooth_problem_of(
    resolved: Option<[usize; 2]>,
    n: usize,
    r: &super::wear_loop::UpdateRecord,
    (who, why): (&str, &str),
) -> Option<String> {
    let has = r.wear.teeth.is_some() || r.increment_teeth.is_some();
    let Some([z1, z2]) = resolved else {
        return has.then(|| format!("holds per-tooth wear, but {who}'s teeth are all alike"));
    };
    if r.wear.teeth.is_none() || r.increment_teeth.is_none() {
        return Some(format!(
            "holds no per-tooth wear, but {who} resolves the teeth ({why})"
        ));
    }
    for (what, t) in [("wear", &r.wear.teeth), ("increment", &r.increment_teeth)] {
        let Some(t) = t else { continue };
        for (g, profiles, z) in [("pinion", &t.pinion_m, z1), ("gear", &t.gear_m, z2)] {
            if profiles.len() != z || profiles.iter().any(|p| p.len() != n) {
                return Some(format!(
                    "per-tooth {g} {what} is not {z} profiles of {n} points"
                ));
            }
            if profiles
                .iter()
                .flatten()
                .any(|x| !x.is_finite() || *x < 0.0)
            {
                return Some(format!(
                    "per-tooth {g} {what} holds a value that is not finite and >= 0"
                ));
            }
        }
    }
    None
}
