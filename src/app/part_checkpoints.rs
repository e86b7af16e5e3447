//! Where the wear runs of a job kept as several logs per mode start (`store::part_logs`:
//! a train's meshes, a train's bins and meshes under a load spectrum, a planetary set's
//! meshes): afresh, or resumed from their logs, each mode's read back, replayed and
//! recomputed by the study's own check before anything else is computed.

use super::observer::Observer;
use super::JobError;
use crate::io::OutputDir;
use crate::remedy::{Arg, Problem, Remedy};
use crate::store::part_logs::load_parts;
use crate::study::wear_loop::{WearMode, WearRun};

/// The logs of a job's parts: what they are, their names per mode and how they are shown.
pub(crate) struct Parts<'a> {
    /// What the logs keep, e.g. "the train's meshes".
    pub what: &'a str,
    /// A mode's log names, in the order the replay takes them.
    pub names: &'a dyn Fn(WearMode) -> Vec<String>,
    /// How a mode's logs are named in messages.
    pub shown: &'a dyn Fn(WearMode) -> String,
    /// The part a missing log is, e.g. "a stage".
    pub part: &'a str,
    /// Largest size of a log of a mode, bytes (`budget::max_checkpoint_bytes`).
    pub max_bytes: &'a dyn Fn(WearMode) -> u64,
}

/// A mode's run read back from its logs (in `Parts::names`' order) by the study's replay
/// and recomputation, or why they are not this case's run.
pub(crate) type Replay<'a, R> = dyn Fn(WearMode, Vec<WearRun>) -> Result<R, String> + 'a;

/// A refusal to resume from the logs of `mode` in `dir`, saying why.
fn refused(dir: &std::path::Path, parts: &Parts, mode: WearMode, why: &str) -> JobError {
    Problem::of(
        Arg::Resume,
        format!(
            "{}: the {} checkpoints of {} ({}): {why}; they cannot be resumed",
            dir.display(),
            mode.label(),
            parts.what,
            (parts.shown)(mode),
        ),
    )
    .remedy(Remedy::start_afresh().path(dir))
    .into()
}

/// The run of each of `modes`: `fresh`, or (resuming from `resume_from`) read back from
/// its logs, which must belong to this case and mode (their headers) and pass `replay`
/// (the study's replay and recomputation, an error saying why they are not this case's
/// run). A mode without logs, or with only their headers, starts afresh with a note;
/// finding none at all is an error, as is a mode with some of its logs missing.
pub(crate) fn starting_part_runs<R>(
    resume_from: Option<&OutputDir>,
    modes: &[WearMode],
    parts: &Parts,
    case_sha256: &str,
    (fresh, replay): (&dyn Fn(WearMode) -> R, &Replay<'_, R>),
    observer: &dyn Observer,
) -> Result<Vec<R>, JobError> {
    let Some(out) = resume_from else {
        return Ok(modes.iter().map(|m| fresh(*m)).collect());
    };
    let dir = out.root();
    let mut starts = Vec::new();
    let mut found = false;
    for m in modes {
        let logs = load_parts(
            out,
            &(parts.names)(*m),
            *m,
            case_sha256,
            (parts.max_bytes)(*m),
        )
        .map_err(|e| JobError::from(e.problem()))?;
        if logs.iter().flatten().all(|l| l.records.is_empty()) {
            observer.note(&format!(
                "note: no {} checkpoint: that run starts afresh",
                m.label()
            ));
            starts.push(fresh(*m));
            continue;
        }
        found = true;
        let Some(logs) = logs.into_iter().collect::<Option<Vec<WearRun>>>() else {
            let why = format!("the log of {} is missing", parts.part);
            return Err(refused(dir, parts, *m, &why));
        };
        starts.push(replay(*m, logs).map_err(|e| refused(dir, parts, *m, &e))?);
    }
    if !found {
        return Err(Problem::of(
            Arg::Resume,
            format!(
                "no checkpoint to resume from in {} (looked for {} and their .partial files)",
                dir.display(),
                modes
                    .first()
                    .map_or_else(String::new, |m| (parts.shown)(*m))
            ),
        )
        .remedy(Remedy::start_afresh().path(dir))
        .into());
    }
    Ok(starts)
}
