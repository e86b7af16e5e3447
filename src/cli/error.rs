//! Errors of a command, and the exit code each maps to.

use crate::config::ConfigError;
use crate::geometry::GeometryError;
use std::fmt;

#[derive(Debug)]
pub enum CliError {
    /// The input is wrong (case file, overrides, a file argument): exit code 2.
    Input(Vec<String>),
    /// The run failed for another reason (I/O, a solver that did not converge): exit code 1.
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
        CliError::Failed(e)
    }
}

impl From<std::io::Error> for CliError {
    fn from(e: std::io::Error) -> Self {
        CliError::Failed(e.into())
    }
}
