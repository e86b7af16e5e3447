//! I/O errors that name the path and say what to do.

use crate::remedy::{Problem, Remedy, Spelling};
use std::path::{Path, PathBuf};

/// A file-system operation on a path failed.
#[derive(Debug, thiserror::Error)]
#[error("{}", self.problem())]
pub struct OutputError {
    /// What was being done ("write", "create the directory", ...).
    pub action: &'static str,
    /// The path operated on.
    pub path: PathBuf,
    /// The operating system's words, or ours.
    pub reason: String,
    /// What the user can do about it (`crate::remedy`: each front end names the output
    /// folder its own way). Boxed, so that results stay small.
    pub remedy: Option<Box<Remedy>>,
}

impl OutputError {
    /// An error of `action` on `path` from an `std::io::Error`, with a hint chosen by the
    /// kind of error.
    pub fn io(action: &'static str, path: &Path, e: &std::io::Error) -> Self {
        use std::io::ErrorKind as K;
        let remedy = match e.kind() {
            K::PermissionDenied | K::ReadOnlyFilesystem => {
                Some(Remedy::output("choose a folder you can write to"))
            }
            K::StorageFull | K::QuotaExceeded => {
                Some(Remedy::output("free some space or choose another folder"))
            }
            K::NotADirectory | K::AlreadyExists => Some(Remedy::output(
                "a file stands where a folder is needed: move it away or choose another folder",
            )),
            _ => None,
        };
        Self {
            action,
            path: path.to_path_buf(),
            reason: e.to_string(),
            remedy: remedy.map(Box::new),
        }
    }

    /// An error with our own reason and remedy (`None`: nothing to suggest).
    pub fn new(
        action: &'static str,
        path: &Path,
        reason: impl Into<String>,
        remedy: Option<Remedy>,
    ) -> Self {
        Self {
            action,
            path: path.to_path_buf(),
            reason: reason.into(),
            remedy: remedy.map(Box::new),
        }
    }

    /// The error as a [`Problem`] of the output folder, path in the text.
    pub fn problem(&self) -> Problem {
        let p = Problem::new(format!(
            "cannot {} {}: {}",
            self.action,
            self.path.display(),
            self.reason
        ));
        match &self.remedy {
            Some(r) => p.remedy((**r).clone().path(&self.path)),
            None => p,
        }
    }

    /// The message with the output folder's argument spelled by `spell`.
    pub fn render(&self, spell: Spelling) -> String {
        self.problem().render(spell)
    }
}
