//! Errors of a command, and the exit code each maps to.

use crate::config::ConfigError;
use crate::geometry::GeometryError;
use crate::io::checkpoint::CheckpointError;
use crate::io::lock::LockError;
use crate::io::transmission_error::TransmissionErrorInput;
use crate::io::OutputError;
use crate::report::artifacts::WriteError;
use std::fmt;

#[derive(Debug)]
pub enum CliError {
    /// The input is wrong (case file, overrides, a file argument, the output folder):
    /// exit code 2. The user can fix it.
    Input(Vec<String>),
    /// The run failed for another reason (a solver that did not converge): exit code 1.
    Failed(anyhow::Error),
}

impl CliError {
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) => 2,
            CliError::Failed(_) => 1,
        }
    }

    pub fn input(msg: impl Into<String>) -> Self {
        CliError::Input(vec![msg.into()])
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Input(p) if p.len() == 1 => write!(f, "{}", p[0]),
            CliError::Input(p) => {
                writeln!(f, "invalid input ({} problems):", p.len())?;
                for m in p {
                    writeln!(f, "  - {m}")?;
                }
                Ok(())
            }
            CliError::Failed(e) => write!(f, "{e:#}"),
        }
    }
}

/// A setting's problem as the command line says it: the flag, then the message.
pub fn flag_problem(p: &crate::prognostics::limits::Problem) -> String {
    format!("--{}: {}", p.setting.replace('_', "-"), p.message)
}

impl From<ConfigError> for CliError {
    fn from(e: ConfigError) -> Self {
        CliError::Input(e.problems)
    }
}

impl From<GeometryError> for CliError {
    fn from(e: GeometryError) -> Self {
        CliError::Input(e.0)
    }
}

impl From<anyhow::Error> for CliError {
    fn from(e: anyhow::Error) -> Self {
        // An output problem raised inside a study's callback (a checkpoint write) is still
        // the user's to fix.
        match e.downcast::<OutputError>() {
            Ok(o) => o.into(),
            Err(e) => CliError::Failed(e),
        }
    }
}

/// Problems with the output folder name the path: exit 2.
impl From<OutputError> for CliError {
    fn from(e: OutputError) -> Self {
        CliError::input(e.to_string())
    }
}

impl From<LockError> for CliError {
    fn from(e: LockError) -> Self {
        match e {
            LockError::OtherCommand { .. } => CliError::input(format!("{e} (--replace)")),
            e => CliError::input(e.to_string()),
        }
    }
}

impl From<crate::io::InputError> for CliError {
    fn from(e: crate::io::InputError) -> Self {
        CliError::input(e.to_string())
    }
}

impl From<CheckpointError> for CliError {
    fn from(e: CheckpointError) -> Self {
        CliError::input(e.to_string())
    }
}

impl From<TransmissionErrorInput> for CliError {
    fn from(e: TransmissionErrorInput) -> Self {
        CliError::input(format!("--transmission-error {e}"))
    }
}

impl From<WriteError> for CliError {
    fn from(e: WriteError) -> Self {
        match e {
            WriteError::Output(o) => o.into(),
            other => CliError::Failed(other.into()),
        }
    }
}
