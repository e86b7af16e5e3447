//! One writer per output set: an advisory lock on a file in the output folder.
//!
//! The lock is the operating system's (`flock`), so it is released when the holder exits,
//! even when it is killed: no stale locks to clean up by hand. The file holds who holds it
//! (process, host, command), so a second writer can be told whom it waits for.
//!
//! The lock file is opened relative to the folder, without following a link, without
//! truncating and without blocking on a FIFO; it is used only when it is a regular file
//! with one link holding nothing or a holder line gearwear wrote. Anything else at its
//! name (a link, a hard link to a file elsewhere, a user's file) is refused and left as
//! it is.

use super::dir::{check_plain, entry_of_file, Dir};
use super::error::OutputError;
use crate::remedy::{Arg, Problem, Remedy, Words};
use rustix::fs::{self as rfs, Mode, OFlags};
use std::fs::File;
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
    Held {
        /// The lock file.
        path: PathBuf,
        /// The holder line of the lock file ("holder unknown" when empty).
        holder: String,
    },
    /// The folder holds another command's results, and replacing them was not allowed.
    #[error("{}", self.problem())]
    OtherCommand {
        /// The output folder.
        path: PathBuf,
        /// The command whose results the folder holds.
        held: String,
        /// Number of outputs of that command the folder holds.
        files: usize,
    },
    /// A file-system operation on the folder or the lock file failed.
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
            LockError::OtherCommand { path, held, files } => Problem::new(format!(
                "{} holds the results of `gearwear {held}` ({files} files); this command would replace them",
                path.display()
            ))
            .remedy(Remedy::new(
                Words::new()
                    .text("choose another folder (")
                    .arg(Arg::Out)
                    .text("), or allow replacing them (")
                    .arg(Arg::Replace)
                    .text(")"),
            )),
            LockError::Io(e) => e.problem(),
        }
    }
}

/// Longest holder line (a lock file larger than this is not gearwear's).
const MAX_HOLDER_BYTES: u64 = 1024;

/// Whether `text` is what gearwear writes into a lock file (or nothing).
fn is_holder_line(text: &str) -> bool {
    text.is_empty() || (text.starts_with("process ") && text.contains(", `gearwear "))
}

fn host_name() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .or_else(|_| std::fs::read_to_string("/etc/hostname"))
        .map(|s| s.trim().chars().take(100).collect())
        .unwrap_or_else(|_| "unknown host".into())
}

impl OutputLock {
    /// Take the lock `name` in `dir` (created if missing) for `command`, without waiting.
    pub fn acquire(dir: &Dir, name: &str, command: &str) -> Result<Self, LockError> {
        let path = dir.join(name);
        // Not a follow, not a truncate, not a block (FIFO): checked below before use.
        let fd = rfs::openat(
            dir,
            name,
            OFlags::RDWR
                | OFlags::CREATE
                | OFlags::NOFOLLOW
                | OFlags::NONBLOCK
                | OFlags::NOCTTY
                | OFlags::CLOEXEC,
            Mode::from_raw_mode(0o666),
        )
        .map_err(|e| match e {
            rustix::io::Errno::LOOP => super::dir::not_ours(&path, "it is a symbolic link"),
            e => OutputError::io("open the lock file", &path, &e.into()),
        })?;
        let mut file = File::from(fd);
        let e = entry_of_file(&file).map_err(|e| OutputError::io("inspect", &path, &e))?;
        check_plain(&path, &e)?;
        let mut text = String::new();
        let ours = e.bytes <= MAX_HOLDER_BYTES
            && (&file)
                .take(MAX_HOLDER_BYTES)
                .read_to_string(&mut text)
                .is_ok()
            && is_holder_line(text.trim());
        if !ours {
            return Err(super::dir::not_ours(&path, "it is not a gearwear lock file").into());
        }
        match rfs::flock(&file, rfs::FlockOperation::NonBlockingLockExclusive) {
            Ok(()) => {}
            Err(rustix::io::Errno::WOULDBLOCK) => {
                let holder = text.trim();
                return Err(LockError::Held {
                    path,
                    holder: if holder.is_empty() {
                        "holder unknown".into()
                    } else {
                        holder.chars().take(200).collect()
                    },
                });
            }
            Err(e) => return Err(OutputError::io("lock", &path, &e.into()).into()),
        }
        let who = format!(
            "process {} on {}, `gearwear {command}`",
            std::process::id(),
            host_name()
        );
        // Ours (checked above, under the lock now): rewrite the holder line.
        file.set_len(0)
            .and_then(|_| file.seek(SeekFrom::Start(0)))
            .and_then(|_| file.write_all(who.as_bytes()))
            .map_err(|e| OutputError::io("write", &path, &e))?;
        Ok(Self { file, path })
    }

    /// The lock file's path.
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
    use std::os::unix::fs::MetadataExt;

    fn root() -> (tempfile::TempDir, Dir) {
        let d = tempfile::tempdir().unwrap();
        let r = Dir::open_root(d.path()).unwrap();
        (d, r)
    }

    #[test]
    fn a_second_writer_is_refused_and_told_who_holds_it() {
        let (_d, r) = root();
        let first = OutputLock::acquire(&r, ".lock", "wear").unwrap();
        let e = OutputLock::acquire(&r, ".lock", "run").unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains("gearwear wear"), "{msg}");
        assert!(msg.contains(&std::process::id().to_string()), "{msg}");
        drop(first);
        OutputLock::acquire(&r, ".lock", "run").expect("free again once released");
    }

    #[test]
    fn links_hard_links_and_foreign_files_are_refused_and_untouched() {
        let (d, r) = root();
        let outside = d.path().join("outside");
        std::fs::write(&outside, b"keep").unwrap();
        let ino = std::fs::metadata(&outside).unwrap().ino();
        std::os::unix::fs::symlink(&outside, d.path().join(".soft")).unwrap();
        std::fs::hard_link(&outside, d.path().join(".hard")).unwrap();
        std::fs::write(d.path().join(".mine"), b"my notes").unwrap();
        for name in [".soft", ".hard", ".mine"] {
            let e = OutputLock::acquire(&r, name, "x").unwrap_err().to_string();
            assert!(e.contains("gearwear changes only files"), "{name}: {e}");
        }
        assert_eq!(std::fs::read(&outside).unwrap(), b"keep");
        assert_eq!(std::fs::metadata(&outside).unwrap().ino(), ino);
        assert_eq!(std::fs::read(d.path().join(".mine")).unwrap(), b"my notes");
    }
}
