//! One writer per output set: an advisory lock on a file in the output folder.
//!
//! The lock is the operating system's (`flock` through `File::try_lock`), so it is
//! released when the holder exits, even when it is killed: no stale locks to clean up by
//! hand. The file holds who holds it (process, host, command), so a second writer can be
//! told whom it waits for. It is opened without following a symbolic link.

use super::error::OutputError;
use crate::remedy::{Problem, Remedy};
use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// A held lock; dropping it releases the lock.
#[derive(Debug)]
pub struct OutputLock {
    file: File,
    path: PathBuf,
}

/// Why the lock could not be taken.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    /// Another process holds it.
    #[error("{}", self.problem())]
    Held { path: PathBuf, holder: String },
    #[error(transparent)]
    Io(#[from] OutputError),
}

impl LockError {
    /// The error as a problem of the output folder (`crate::remedy`).
    pub fn problem(&self) -> Problem {
        match self {
            LockError::Held { path, holder } => Problem::new(format!(
                "{} is being written by another gearwear ({holder})",
                path.display()
            ))
            .remedy(Remedy::output(
                "wait for it to finish, or choose another folder",
            )),
            LockError::Io(e) => e.problem(),
        }
    }
}

fn open_no_follow(path: &Path) -> std::io::Result<File> {
    let mut o = OpenOptions::new();
    o.read(true).write(true).create(true).truncate(false);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        o.custom_flags(libc::O_NOFOLLOW);
    }
    o.open(path)
}

fn host_name() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .or_else(|_| std::fs::read_to_string("/etc/hostname"))
        .map(|s| s.trim().to_owned())
        .unwrap_or_else(|_| "unknown host".into())
}

impl OutputLock {
    /// Take the lock at `path` (created if missing) for `command`, without waiting.
    pub fn acquire(path: &Path, command: &str) -> Result<Self, LockError> {
        let mut file =
            open_no_follow(path).map_err(|e| OutputError::io("open the lock file", path, &e))?;
        match file.try_lock() {
            Ok(()) => {}
            Err(std::fs::TryLockError::WouldBlock) => {
                let mut holder = String::new();
                let _ = file.read_to_string(&mut holder);
                let holder = holder.trim();
                return Err(LockError::Held {
                    path: path.to_path_buf(),
                    holder: if holder.is_empty() {
                        "holder unknown".into()
                    } else {
                        holder.chars().take(200).collect()
                    },
                });
            }
            Err(std::fs::TryLockError::Error(e)) => {
                return Err(OutputError::io("lock", path, &e).into());
            }
        }
        let who = format!(
            "process {} on {}, `gearwear {command}`",
            std::process::id(),
            host_name()
        );
        file.set_len(0)
            .and_then(|_| file.seek(SeekFrom::Start(0)))
            .and_then(|_| file.write_all(who.as_bytes()))
            .map_err(|e| OutputError::io("write", path, &e))?;
        Ok(Self {
            file,
            path: path.to_path_buf(),
        })
    }

    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for OutputLock {
    fn drop(&mut self) {
        // Leave the file (deleting a lock file races with a newcomer that opened it);
        // empty it so it names no one once released.
        let _ = self.file.set_len(0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_writer_is_refused_and_told_who_holds_it() {
        let d = tempfile::tempdir().unwrap();
        let p = d.path().join(".lock");
        let first = OutputLock::acquire(&p, "wear").unwrap();
        let e = OutputLock::acquire(&p, "run").unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains("gearwear wear"), "{msg}");
        assert!(msg.contains(&std::process::id().to_string()), "{msg}");
        drop(first);
        OutputLock::acquire(&p, "run").expect("free again once released");
    }

    #[cfg(unix)]
    #[test]
    fn a_planted_link_is_not_followed() {
        let d = tempfile::tempdir().unwrap();
        let outside = d.path().join("outside");
        std::fs::write(&outside, b"keep").unwrap();
        let p = d.path().join(".lock");
        std::os::unix::fs::symlink(&outside, &p).unwrap();
        assert!(OutputLock::acquire(&p, "x").is_err());
        assert_eq!(std::fs::read(&outside).unwrap(), b"keep");
    }
}
