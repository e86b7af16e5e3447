//! Why a job gave no result: the input to fix (with each problem's remedy), the output
//! folder, a stop on request, or a solver that failed on valid input. Each front end maps
//! these to its own terms: the command line to exit codes 2, 2, 130 and 1, Python to
//! `CaseError` (a `ValueError`), `OSError`, `KeyboardInterrupt` and `StudyError`.

use crate::config::ConfigError;
use crate::geometry::GeometryError;
use crate::io::lock::LockError;
use crate::io::OutputError;
use crate::remedy::{Arg, Problem, Problems, Spelling};
use crate::report::artifacts::WriteError;
use crate::store::checkpoint::CheckpointError;
use crate::store::transmission_error::TransmissionErrorInput;
use crate::study::ModelError;
use std::fmt;

/// See the module docs.
#[derive(Debug)]
pub enum JobError {
    /// The input is wrong (the case, an argument, an input file): the user can fix it.
    Input(Vec<Problem>),
    /// The output folder cannot be used (not writable, locked by another run, full).
    Output(Problem),
    /// Stopped because the observer asked (`Observer::cancelled`).
    Cancelled,
    /// A solver failed on valid input.
    Failed(anyhow::Error),
}

/// The error a job's callbacks return once the observer asks it to stop; the job turns
/// it into [`JobError::Cancelled`].
#[derive(Debug, Clone, Copy, thiserror::Error)]
#[error("stopped on request")]
pub struct Cancelled;

impl JobError {
    /// One input problem.
    pub fn input(p: impl Into<Problem>) -> Self {
        JobError::Input(vec![p.into()])
    }

    /// The messages, arguments spelled by `spell` (one per problem).
    pub fn messages(&self, spell: Spelling) -> Vec<String> {
        match self {
            JobError::Input(p) => p.iter().map(|p| p.render(spell)).collect(),
            JobError::Output(p) => vec![p.render(spell)],
            JobError::Cancelled => vec!["stopped on request".into()],
            JobError::Failed(e) => vec![format!("{e:#}")],
        }
    }

    /// The whole message, arguments spelled by `spell`.
    pub fn render(&self, spell: Spelling) -> String {
        let m = self.messages(spell);
        match self {
            JobError::Input(_) if m.len() > 1 => {
                let mut s = format!("invalid input ({} problems):\n", m.len());
                for line in &m {
                    s.push_str(&format!("  - {line}\n"));
                }
                s
            }
            _ => m.join("\n"),
        }
    }
}

impl fmt::Display for JobError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(Arg::plain))
    }
}

impl std::error::Error for JobError {}

impl From<Problem> for JobError {
    fn from(p: Problem) -> Self {
        JobError::Input(vec![p])
    }
}

impl From<Problems> for JobError {
    fn from(p: Problems) -> Self {
        JobError::Input(p.0)
    }
}

impl From<ConfigError> for JobError {
    fn from(e: ConfigError) -> Self {
        JobError::Input(e.problems.into_iter().map(Problem::new).collect())
    }
}

impl From<ModelError> for JobError {
    fn from(e: ModelError) -> Self {
        JobError::Input(e.0.into_iter().map(Problem::new).collect())
    }
}

impl From<GeometryError> for JobError {
    fn from(e: GeometryError) -> Self {
        JobError::Input(e.0.into_iter().map(Problem::new).collect())
    }
}

impl From<OutputError> for JobError {
    fn from(e: OutputError) -> Self {
        JobError::Output(e.problem())
    }
}

impl From<LockError> for JobError {
    fn from(e: LockError) -> Self {
        JobError::Output(e.problem())
    }
}

impl From<CheckpointError> for JobError {
    fn from(e: CheckpointError) -> Self {
        JobError::input(e.problem())
    }
}

impl From<TransmissionErrorInput> for JobError {
    fn from(e: TransmissionErrorInput) -> Self {
        JobError::input(Problem::of(Arg::TransmissionError, e.to_string()))
    }
}

impl From<WriteError> for JobError {
    fn from(e: WriteError) -> Self {
        match e {
            WriteError::Output(o) => o.into(),
            other => JobError::Failed(other.into()),
        }
    }
}

/// An error raised inside a study's callback: a stop on request, an output problem (a
/// checkpoint write) the user can fix, or a solver failure.
impl From<anyhow::Error> for JobError {
    fn from(e: anyhow::Error) -> Self {
        if e.is::<Cancelled>() {
            return JobError::Cancelled;
        }
        match e.downcast::<OutputError>() {
            Ok(o) => o.into(),
            Err(e) => JobError::Failed(e),
        }
    }
}
