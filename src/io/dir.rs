//! Folder handles: every file operation of an output set is made relative to an open
//! folder (a file descriptor), never through a path looked up again, so swapping a
//! folder for a symbolic link half-way cannot redirect a write (the `*at` system calls,
//! through the `rustix` crate).
//!
//! Rules kept here, for every folder below the one the user named:
//! - a sub-folder is opened with `O_NOFOLLOW | O_DIRECTORY`: a link is refused, never
//!   descended into;
//! - a new file is created with `O_CREAT | O_EXCL | O_NOFOLLOW` under a fresh name and
//!   renamed into place (`renameat`), so no existing file is ever opened for writing by
//!   name and nothing is truncated;
//! - an existing file is opened with `O_NOFOLLOW | O_NONBLOCK` (a FIFO cannot block the
//!   open) and used only when it is a regular file with one link: a hard link to a file
//!   elsewhere is refused.

use super::error::OutputError;
use crate::remedy::Remedy;
use rustix::fs::{self as rfs, AtFlags, FileType, Mode, OFlags};
use serde::{Deserialize, Serialize};
use std::fs::File;
use std::os::fd::OwnedFd;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Prefix of the temporary files gearwear creates (inside its own staging folders).
pub const TEMP_PREFIX: &str = ".gearwear-tmp-";

/// Where a file lives: its device and inode numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Inode {
    /// Device number (`st_dev`).
    pub dev: u64,
    /// Inode number (`st_ino`).
    pub ino: u64,
}

/// What kind of entry a name holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A regular file.
    File,
    /// A folder (directory).
    Folder,
    /// A symbolic link.
    Link,
    /// A FIFO, device or socket (named).
    Special(&'static str),
}

impl Kind {
    /// The kind in words for messages ("a file", "a folder", ...).
    pub fn words(&self) -> &'static str {
        match self {
            Kind::File => "a file",
            Kind::Folder => "a folder",
            Kind::Link => "a symbolic link",
            Kind::Special(s) => s,
        }
    }
}

/// An entry's kind, place, link count and size (from `lstat`/`fstat`, links not
/// followed).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Entry {
    /// What kind of entry it is.
    pub kind: Kind,
    /// Its device and inode.
    pub inode: Inode,
    /// Number of hard links (`st_nlink`).
    pub links: u64,
    /// Size, bytes.
    pub bytes: u64,
}

// The casts matter on other Unixes (st_dev is i32 on macOS, st_nlink u16).
#[allow(clippy::unnecessary_cast)]
fn entry_of(st: &rfs::Stat) -> Entry {
    let kind = match FileType::from_raw_mode(st.st_mode as _) {
        FileType::RegularFile => Kind::File,
        FileType::Directory => Kind::Folder,
        FileType::Symlink => Kind::Link,
        FileType::Fifo => Kind::Special("a FIFO (named pipe)"),
        FileType::CharacterDevice | FileType::BlockDevice => Kind::Special("a device"),
        FileType::Socket => Kind::Special("a socket"),
        FileType::Unknown => Kind::Special("a special file"),
    };
    Entry {
        kind,
        inode: Inode {
            dev: st.st_dev as u64,
            ino: st.st_ino as u64,
        },
        links: st.st_nlink as u64,
        bytes: st.st_size.max(0) as u64,
    }
}

/// The entry of an open file.
pub fn entry_of_file(f: &File) -> std::io::Result<Entry> {
    Ok(entry_of(&rfs::fstat(f)?))
}

/// A fresh name with `prefix`: process, a counter and the clock, so names do not repeat
/// within a process and rarely across processes (an exclusive create retries anyway).
fn fresh_name(prefix: &str) -> String {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let t = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    format!("{prefix}{}-{n}-{t:x}", std::process::id())
}

/// How many fresh names an exclusive create tries before giving up (a name is taken
/// only if something planted it).
const CREATE_TRIES: usize = 64;

/// An open folder (see the module docs). `path` is for messages only.
#[derive(Debug)]
pub struct Dir {
    fd: OwnedFd,
    path: PathBuf,
}

impl std::os::fd::AsFd for Dir {
    fn as_fd(&self) -> std::os::fd::BorrowedFd<'_> {
        self.fd.as_fd()
    }
}

/// A name inside a folder: one plain component.
fn check_name(name: &str, at: &Path) -> Result<(), OutputError> {
    let ok = !name.is_empty() && name != "." && name != ".." && !name.contains('/');
    if ok {
        Ok(())
    } else {
        Err(OutputError::new(
            "use",
            &at.join(name),
            "not a plain name inside the output folder",
            None,
        ))
    }
}

impl Dir {
    /// Open the folder the user named (created with its parents if missing). It may be a
    /// link: the user chose it.
    pub fn open_root(path: &Path) -> Result<Self, OutputError> {
        match std::fs::metadata(path) {
            Ok(m) if !m.is_dir() => {
                return Err(OutputError::new(
                    "use",
                    path,
                    "it is a file, not a folder",
                    Some(Remedy::output("choose another folder")),
                ))
            }
            Ok(_) => {}
            Err(_) => std::fs::create_dir_all(path)
                .map_err(|e| OutputError::io("create the folder", path, &e))?,
        }
        let fd = rfs::open(
            path,
            OFlags::RDONLY | OFlags::DIRECTORY | OFlags::CLOEXEC,
            Mode::empty(),
        )
        .map_err(|e| OutputError::io("open the folder", path, &e.into()))?;
        Ok(Self {
            fd,
            path: path.to_path_buf(),
        })
    }

    /// The folder's path (as named; for messages).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Path of `name` in this folder (for messages).
    pub fn join(&self, name: &str) -> PathBuf {
        self.path.join(name)
    }

    /// The folder's own entry.
    pub fn entry_self(&self) -> Result<Entry, OutputError> {
        rfs::fstat(&self.fd)
            .map(|s| entry_of(&s))
            .map_err(|e| OutputError::io("inspect", &self.path, &e.into()))
    }

    /// The entry `name` holds, links not followed; None when the name is free.
    pub fn entry(&self, name: &str) -> Result<Option<Entry>, OutputError> {
        check_name(name, &self.path)?;
        match rfs::statat(&self.fd, name, AtFlags::SYMLINK_NOFOLLOW) {
            Ok(s) => Ok(Some(entry_of(&s))),
            Err(rustix::io::Errno::NOENT) => Ok(None),
            Err(e) => Err(OutputError::io("inspect", &self.join(name), &e.into())),
        }
    }

    /// The sub-folder `name`, created if missing and `create`; a link or anything else
    /// that is not a folder is refused.
    pub fn sub(&self, name: &str, create: bool) -> Result<Self, OutputError> {
        check_name(name, &self.path)?;
        let path = self.join(name);
        if create {
            match rfs::mkdirat(&self.fd, name, Mode::from_raw_mode(0o777)) {
                Ok(()) | Err(rustix::io::Errno::EXIST) => {}
                Err(e) => return Err(OutputError::io("create the folder", &path, &e.into())),
            }
        }
        let flags = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::NOFOLLOW | OFlags::CLOEXEC;
        match rfs::openat(&self.fd, name, flags, Mode::empty()) {
            Ok(fd) => Ok(Self { fd, path }),
            Err(e) => Err(match self.entry(name) {
                Ok(Some(x)) if x.kind != Kind::Folder => OutputError::new(
                    "write into",
                    &path,
                    format!(
                        "it is {}, not a folder; gearwear never follows links inside the output folder",
                        x.kind.words()
                    ),
                    Some(Remedy::output("move it away or choose another folder")),
                ),
                _ => OutputError::io("open the folder", &path, &e.into()),
            }),
        }
    }

    /// The folder holding `rel` (a `/`-separated path of plain names) and the file name,
    /// every folder on the way opened as [`Dir::sub`] does.
    pub fn descend(&self, rel: &str, create: bool) -> Result<(Self, String), OutputError> {
        let parts: Vec<&str> = rel.split('/').collect();
        let (name, folders) = parts.split_last().unwrap_or((&"", &[]));
        check_name(name, &self.path)?;
        let mut dir = self.try_clone()?;
        for f in folders {
            dir = dir.sub(f, create)?;
        }
        Ok((dir, (*name).to_owned()))
    }

    /// A second handle on this folder.
    pub fn try_clone(&self) -> Result<Self, OutputError> {
        let fd = self
            .fd
            .try_clone()
            .map_err(|e| OutputError::io("open the folder", &self.path, &e))?;
        Ok(Self {
            fd,
            path: self.path.clone(),
        })
    }

    /// Create a new file under a fresh name starting with `prefix` (exclusive create, no
    /// link followed), open for writing; returns it with its name.
    pub fn create_new(&self, prefix: &str) -> Result<(File, String), OutputError> {
        let flags =
            OFlags::WRONLY | OFlags::CREATE | OFlags::EXCL | OFlags::NOFOLLOW | OFlags::CLOEXEC;
        for _ in 0..CREATE_TRIES {
            let name = fresh_name(prefix);
            match rfs::openat(&self.fd, name.as_str(), flags, Mode::from_raw_mode(0o666)) {
                Ok(fd) => return Ok((File::from(fd), name)),
                Err(rustix::io::Errno::EXIST) => continue,
                Err(e) => return Err(OutputError::io("create a file in", &self.path, &e.into())),
            }
        }
        Err(OutputError::new(
            "create a file in",
            &self.path,
            format!("{CREATE_TRIES} fresh names were all taken"),
            None,
        ))
    }

    /// Create a private sub-folder (mode 0700) under a fresh name starting with `prefix`.
    pub fn create_private_folder(&self, prefix: &str) -> Result<(Self, String), OutputError> {
        for _ in 0..CREATE_TRIES {
            let name = fresh_name(prefix);
            match rfs::mkdirat(&self.fd, name.as_str(), Mode::from_raw_mode(0o700)) {
                Ok(()) => return Ok((self.sub(&name, false)?, name)),
                Err(rustix::io::Errno::EXIST) => continue,
                Err(e) => return Err(OutputError::io("create a folder in", &self.path, &e.into())),
            }
        }
        Err(OutputError::new(
            "create a folder in",
            &self.path,
            format!("{CREATE_TRIES} fresh names were all taken"),
            None,
        ))
    }

    /// Open the existing file `name` without following a link and without blocking on a
    /// FIFO: None when the name is free; an error when it is not a regular file, or has
    /// more than one link (a hard link to a file elsewhere). `write` opens it read-write.
    pub fn open_existing(
        &self,
        name: &str,
        write: bool,
    ) -> Result<Option<(File, Entry)>, OutputError> {
        check_name(name, &self.path)?;
        let path = self.join(name);
        let mode = if write { OFlags::RDWR } else { OFlags::RDONLY };
        let flags = mode | OFlags::NOFOLLOW | OFlags::NONBLOCK | OFlags::NOCTTY | OFlags::CLOEXEC;
        let fd = match rfs::openat(&self.fd, name, flags, Mode::empty()) {
            Ok(fd) => fd,
            Err(rustix::io::Errno::NOENT) => return Ok(None),
            Err(rustix::io::Errno::LOOP) => return Err(not_ours(&path, "it is a symbolic link")),
            Err(e) => return Err(OutputError::io("open", &path, &e.into())),
        };
        let file = File::from(fd);
        let e = entry_of_file(&file).map_err(|e| OutputError::io("inspect", &path, &e))?;
        check_plain(&path, &e)?;
        Ok(Some((file, e)))
    }

    /// Move `from` (in this folder) to `to` in `dest`, replacing what `to` held.
    pub fn rename_to(&self, from: &str, dest: &Dir, to: &str) -> Result<(), OutputError> {
        check_name(from, &self.path)?;
        check_name(to, &dest.path)?;
        rfs::renameat(&self.fd, from, &dest.fd, to)
            .map_err(|e| OutputError::io("write", &dest.join(to), &e.into()))
    }

    /// Remove the file (or link) `name`.
    pub fn remove_file(&self, name: &str) -> Result<(), OutputError> {
        check_name(name, &self.path)?;
        rfs::unlinkat(&self.fd, name, AtFlags::empty())
            .map_err(|e| OutputError::io("remove", &self.join(name), &e.into()))
    }

    /// Remove the empty folder `name`.
    pub fn remove_folder(&self, name: &str) -> Result<(), OutputError> {
        check_name(name, &self.path)?;
        rfs::unlinkat(&self.fd, name, AtFlags::REMOVEDIR)
            .map_err(|e| OutputError::io("remove", &self.join(name), &e.into()))
    }

    /// Names of the entries of this folder (not `.` and `..`).
    pub fn names(&self) -> Result<Vec<String>, OutputError> {
        let d = rfs::Dir::read_from(&self.fd)
            .map_err(|e| OutputError::io("list", &self.path, &e.into()))?;
        let mut out = Vec::new();
        for e in d {
            let e = e.map_err(|e| OutputError::io("list", &self.path, &e.into()))?;
            let n = e.file_name().to_string_lossy().into_owned();
            if n != "." && n != ".." {
                out.push(n);
            }
        }
        Ok(out)
    }

    /// Flush the folder's entries (renames) to disk.
    pub fn sync(&self) -> Result<(), OutputError> {
        rfs::fsync(&self.fd).map_err(|e| OutputError::io("write", &self.path, &e.into()))
    }

    /// Write `bytes` to a new file created under a fresh name in `scratch` (a folder on
    /// the same file system) and move it to `name` here; returns the new file's entry.
    /// Whatever `name` held is replaced, so the caller checks first that it may be.
    pub fn write_new(&self, scratch: &Dir, name: &str, bytes: &[u8]) -> Result<Entry, OutputError> {
        use std::io::Write;
        let (mut f, tmp) = scratch.create_new(TEMP_PREFIX)?;
        let r = f
            .write_all(bytes)
            .and_then(|_| f.sync_all())
            .and_then(|_| entry_of_file(&f));
        let e = match r {
            Ok(e) => e,
            Err(e) => {
                let _ = scratch.remove_file(&tmp);
                return Err(OutputError::io("write", &self.join(name), &e));
            }
        };
        scratch.rename_to(&tmp, self, name).inspect_err(|_| {
            let _ = scratch.remove_file(&tmp);
        })?;
        Ok(e)
    }
}

/// Remove the folder `name` of `parent` and everything in it, never following a link
/// (links inside are removed as names). For gearwear's own staging folders only.
pub fn remove_tree(parent: &Dir, name: &str) -> Result<(), OutputError> {
    let d = parent.sub(name, false)?;
    for n in d.names()? {
        match d.entry(&n)? {
            Some(e) if e.kind == Kind::Folder => remove_tree(&d, &n)?,
            Some(_) => d.remove_file(&n)?,
            None => {}
        }
    }
    parent.remove_folder(name)
}

/// Refuse an entry that is not a regular file with one link.
pub fn check_plain(path: &Path, e: &Entry) -> Result<(), OutputError> {
    if e.kind != Kind::File {
        return Err(not_ours(
            path,
            &format!("it is {}, not a regular file", e.kind.words()),
        ));
    }
    if e.links > 1 {
        return Err(not_ours(
            path,
            &format!(
                "it has {} hard links: it may be a file elsewhere, which gearwear will not change",
                e.links
            ),
        ));
    }
    Ok(())
}

/// An entry gearwear will not use, change or remove.
pub fn not_ours(path: &Path, why: &str) -> OutputError {
    OutputError::new(
        "use",
        path,
        format!("{why}; gearwear changes only files it created itself in the output folder"),
        Some(Remedy::output("move it away or choose another folder")),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;
    use std::os::unix::fs::MetadataExt;

    #[test]
    fn a_linked_subfolder_is_refused_and_its_target_untouched() {
        let d = tempfile::tempdir().unwrap();
        let elsewhere = d.path().join("elsewhere");
        fs::create_dir(&elsewhere).unwrap();
        fs::write(elsewhere.join("thesis.tex"), b"mine").unwrap();
        let out = d.path().join("out");
        fs::create_dir(&out).unwrap();
        std::os::unix::fs::symlink(&elsewhere, out.join("csv")).unwrap();
        let root = Dir::open_root(&out).unwrap();
        let e = root.descend("csv/a.csv", true).unwrap_err().to_string();
        assert!(e.contains("symbolic link"), "{e}");
        assert_eq!(fs::read(elsewhere.join("thesis.tex")).unwrap(), b"mine");
    }

    #[test]
    fn hard_links_fifos_and_links_are_not_opened_as_ours() {
        let d = tempfile::tempdir().unwrap();
        let outside = d.path().join("outside.txt");
        fs::write(&outside, b"keep").unwrap();
        let ino = fs::metadata(&outside).unwrap().ino();
        let out = d.path().join("out");
        fs::create_dir(&out).unwrap();
        fs::hard_link(&outside, out.join("hard")).unwrap();
        std::os::unix::fs::symlink(&outside, out.join("soft")).unwrap();
        rfs::mkfifoat(
            rfs::CWD,
            out.join("fifo").as_path(),
            Mode::from_raw_mode(0o600),
        )
        .unwrap();
        let root = Dir::open_root(&out).unwrap();
        for (name, needle) in [
            ("hard", "hard links"),
            ("soft", "symbolic link"),
            ("fifo", "FIFO"),
        ] {
            let e = root.open_existing(name, true).unwrap_err().to_string();
            assert!(e.contains(needle), "{name}: {e}");
        }
        assert!(root.open_existing("none", false).unwrap().is_none());
        assert_eq!(fs::read(&outside).unwrap(), b"keep");
        assert_eq!(fs::metadata(&outside).unwrap().ino(), ino);
    }

    #[test]
    fn a_new_file_replaces_a_planted_link_without_following_it() {
        let d = tempfile::tempdir().unwrap();
        let outside = d.path().join("outside.txt");
        fs::write(&outside, b"keep").unwrap();
        let out = d.path().join("out");
        fs::create_dir(&out).unwrap();
        std::os::unix::fs::symlink(&outside, out.join("a.txt")).unwrap();
        let root = Dir::open_root(&out).unwrap();
        let (scratch, _) = root.create_private_folder(".s-").unwrap();
        let e = root.write_new(&scratch, "a.txt", b"new").unwrap();
        assert_eq!(e.kind, Kind::File);
        assert_eq!(fs::read(out.join("a.txt")).unwrap(), b"new");
        assert_eq!(fs::read(&outside).unwrap(), b"keep");
    }
}
