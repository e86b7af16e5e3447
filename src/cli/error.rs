//! Errors of a command, worded with the command line's flags, and the exit code each maps
//! to.

use crate::app::JobError;
use crate::config::ConfigError;
use std::fmt;

pub(crate) use super::flag::flag;

#[derive(Debug)]
pub(crate) enum CliError {
    /// The input is wrong (case file, overrides, a file argument, the output folder):
    /// exit code 2. The user can fix it.
    Input(Vec<String>),
    /// The run failed for another reason (a solver that did not converge): exit code 1.
    Failed(anyhow::Error),
}

impl CliError {
    pub(crate) fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) => 2,
            CliError::Failed(_) => 1,
        }
    }

    pub(crate) fn input(msg: impl Into<String>) -> Self {
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

impl From<ConfigError> for CliError {
    fn from(e: ConfigError) -> Self {
        CliError::Input(e.problems.iter().map(|w| w.render(flag)).collect())
    }
}

impl From<JobError> for CliError {
    fn from(e: JobError) -> Self {
        match e {
            JobError::Input(_) | JobError::Output(_) => CliError::Input(e.messages(flag)),
            JobError::Cancelled => CliError::Failed(anyhow::anyhow!("stopped on request")),
            JobError::Failed(e) => CliError::Failed(e),
        }
    }
}
