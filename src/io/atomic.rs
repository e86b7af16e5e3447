//! Atomic file writes: a half-written file never replaces a good one, and a write never
//! leaves the folder it was aimed at.
//!
//! The bytes go to a temporary file created exclusively (`O_CREAT | O_EXCL`, a random
//! name: the `tempfile` crate) in the target's own folder, are synced, and the file is
//! renamed over the target. An exclusive create fails on an existing name, so a symbolic
//! link planted under a predictable name cannot redirect the write; rename replaces a link
//! at the target's name by the new file instead of writing through it. The folders on
//! the way must be real folders, not links (`ensure_real_dir`).

use super::error::OutputError;
use crate::remedy::Remedy;
use std::io::Write;
use std::path::Path;

/// Prefix of the temporary files, so that orphans of a killed run can be recognised and
/// removed (`output_dir::remove_orphans`).
pub const TEMP_PREFIX: &str = ".gearwear-tmp-";

/// Create `dir` (and its parents) if missing; refuse when it, or the part of it below
/// `root`, is a symbolic link or not a folder. `root` itself may be a link (the user named
/// it).
pub fn ensure_real_dir(root: &Path, dir: &Path) -> Result<(), OutputError> {
    let rel = dir.strip_prefix(root).unwrap_or(Path::new(""));
    if !root.exists() {
        std::fs::create_dir_all(root)
            .map_err(|e| OutputError::io("create the folder", root, &e))?;
    } else if !root.is_dir() {
        return Err(OutputError::new(
            "use",
            root,
            "it is a file, not a folder",
            Some(Remedy::output("choose another folder")),
        ));
    }
    let mut cur = root.to_path_buf();
    for part in rel.components() {
        cur.push(part);
        match std::fs::symlink_metadata(&cur) {
            Ok(m) if m.file_type().is_symlink() => {
                return Err(OutputError::new(
                    "write into",
                    &cur,
                    "it is a symbolic link; gearwear writes only inside the output folder",
                    Some(Remedy::output("remove the link or choose another folder")),
                ))
            }
            Ok(m) if !m.is_dir() => {
                return Err(OutputError::new(
                    "write into",
                    &cur,
                    "it is a file, not a folder",
                    Some(Remedy::output("move it away or choose another folder")),
                ))
            }
            Ok(_) => {}
            Err(_) => std::fs::create_dir(&cur)
                .map_err(|e| OutputError::io("create the folder", &cur, &e))?,
        }
    }
    Ok(())
}

/// Write `bytes` to `path` atomically (see the module docs). The parent folder must exist.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let mut b = tempfile::Builder::new();
    b.prefix(TEMP_PREFIX);
    #[cfg(unix)]
    {
        // Like any created file: read-write for all, less the user's umask (tempfile's
        // default, owner only, would hide checkpoints from a group sharing the folder).
        use std::os::unix::fs::PermissionsExt;
        b.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut tmp = b
        .tempfile_in(dir)
        .map_err(|e| OutputError::io("create a temporary file in", dir, &e))?;
    tmp.write_all(bytes)
        .and_then(|_| tmp.as_file().sync_all())
        .map_err(|e| OutputError::io("write", path, &e))?;
    tmp.persist(path)
        .map_err(|e| OutputError::io("write", path, &e.error))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    #[test]
    fn replaces_content_and_leaves_no_temp() {
        let d = tempfile::tempdir().unwrap();
        let p = d.path().join("a.txt");
        write_atomic(&p, b"one").unwrap();
        write_atomic(&p, b"two").unwrap();
        assert_eq!(fs::read(&p).unwrap(), b"two");
        let n = fs::read_dir(d.path()).unwrap().count();
        assert_eq!(n, 1, "temporary file left behind");
    }

    #[cfg(unix)]
    #[test]
    fn a_link_at_the_target_is_replaced_not_followed() {
        // A link planted at the target's name must not make us write the file it points to.
        let d = tempfile::tempdir().unwrap();
        let outside = d.path().join("outside.txt");
        fs::write(&outside, b"precious").unwrap();
        let out = d.path().join("out");
        fs::create_dir(&out).unwrap();
        let target = out.join("summary.json");
        std::os::unix::fs::symlink(&outside, &target).unwrap();
        write_atomic(&target, b"new").unwrap();
        assert_eq!(fs::read(&outside).unwrap(), b"precious");
        assert!(!fs::symlink_metadata(&target)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read(&target).unwrap(), b"new");
    }

    #[cfg(unix)]
    #[test]
    fn a_linked_subfolder_is_refused() {
        let d = tempfile::tempdir().unwrap();
        let elsewhere = d.path().join("elsewhere");
        fs::create_dir(&elsewhere).unwrap();
        let out = d.path().join("out");
        fs::create_dir(&out).unwrap();
        std::os::unix::fs::symlink(&elsewhere, out.join("csv")).unwrap();
        let e = ensure_real_dir(&out, &out.join("csv")).unwrap_err();
        assert!(e.to_string().contains("symbolic link"), "{e}");
    }
}
