//! I/O errors that name the path and say what to do.

use std::path::{Path, PathBuf};

/// A file-system operation on a path failed.
#[derive(Debug, thiserror::Error)]
#[error("cannot {action} {path}: {reason}{hint}")]
pub struct OutputError {
    /// What was being done ("write", "create the directory", ...).
    pub action: &'static str,
    pub path: PathBuf,
    /// The operating system's words, or ours.
    pub reason: String,
    /// What the user can do about it, with a leading "; ".
    pub hint: String,
}

impl OutputError {
    /// An error of `action` on `path` from an `std::io::Error`, with a hint chosen by the
    /// kind of error.
    pub fn io(action: &'static str, path: &Path, e: &std::io::Error) -> Self {
        use std::io::ErrorKind as K;
        let hint = match e.kind() {
            K::PermissionDenied | K::ReadOnlyFilesystem => {
                "; choose a folder you can write to with --out"
            }
            K::StorageFull | K::QuotaExceeded => "; free some space or choose another --out",
            K::NotADirectory | K::AlreadyExists => {
                "; a file stands where a folder is needed: move it away or choose another --out"
            }
            _ => "",
        };
        Self {
            action,
            path: path.to_path_buf(),
            reason: e.to_string(),
            hint: hint.to_owned(),
        }
    }

    /// An error with our own reason and hint.
    pub fn new(action: &'static str, path: &Path, reason: impl Into<String>, hint: &str) -> Self {
        Self {
            action,
            path: path.to_path_buf(),
            reason: reason.into(),
            hint: if hint.is_empty() {
                String::new()
            } else {
                format!("; {hint}")
            },
        }
    }
}
