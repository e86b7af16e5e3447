//! Reading input files: only regular files, of bounded size.
//!
//! A FIFO, a device (`/dev/zero`, `/dev/stdin`), a socket or a folder named as an input is
//! refused with a message saying what it is: a FIFO would block the run for good (the file
//! is opened non-blocking, so even the open cannot hang), a device can stream without
//! end. A file larger than its kind's limit is refused before it is read; the limits
//! below are far above any valid input, so they only stop a wrong file or an attack from
//! exhausting memory.

use std::fs::{File, OpenOptions};
use std::io::Read;
use std::path::Path;

/// Largest case file (TOML): the largest valid case, every array key at its longest, is
/// a few MB.
pub const MAX_CASE_BYTES: u64 = 16 << 20;
/// Largest observations file: 1e5 rows (`prognostics::observations::MAX_ROWS`) of a few
/// hundred characters.
pub const MAX_OBSERVATIONS_BYTES: u64 = 64 << 20;
/// Largest posterior samples file: 1e6 rows (`prognostics::samples::MAX_ROWS`) of about a
/// hundred characters.
pub const MAX_POSTERIOR_BYTES: u64 = 128 << 20;
/// Largest transmission-error file: 1e6 samples of two numbers.
pub const MAX_TRANSMISSION_ERROR_BYTES: u64 = 64 << 20;
/// Largest transfer-path file (FRF table or modal TOML): 1e5 frequency lines of a few
/// numbers.
pub const MAX_TRANSFER_PATH_BYTES: u64 = 64 << 20;
/// Largest load spectrum file (CSV of bins): 1e5 bins of a few numbers.
pub const MAX_LOAD_SPECTRUM_BYTES: u64 = 64 << 20;
/// Largest load-time history (`load-spectrum` input): 1e7 samples of a few numbers.
pub const MAX_HISTORY_BYTES: u64 = 512 << 20;
/// Largest dataset design file (TOML).
pub const MAX_DESIGN_BYTES: u64 = 16 << 20;
/// Largest sweep case record (`cases/N.json`): one case's results and states, a few kB.
pub const MAX_CASE_RECORD_BYTES: u64 = 16 << 20;
/// Largest sweep table or its JSON (`sweep-merge` inputs): 1e6 cases of a few hundred
/// characters.
pub const MAX_SWEEP_TABLE_BYTES: u64 = 1 << 30;
/// Largest prediction shard (`predict-merge` inputs).
pub const MAX_PREDICT_SHARD_BYTES: u64 = 1 << 30;

/// Why an input file cannot be read; the message names the file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path}: {reason}")]
pub struct InputError {
    /// The file as given.
    pub path: String,
    /// Why it cannot be read.
    pub reason: String,
}

fn kind_words(ft: &std::fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if ft.is_dir() {
        "a folder"
    } else if ft.is_fifo() {
        "a FIFO (named pipe)"
    } else if ft.is_char_device() || ft.is_block_device() {
        "a device"
    } else if ft.is_socket() {
        "a socket"
    } else {
        "not a regular file"
    }
}

/// Open `path` for reading without blocking (a FIFO opens at once) and check that it is
/// a regular file of at most `max_bytes`.
fn open_regular(path: &Path, what: &str, max_bytes: u64) -> Result<File, InputError> {
    use std::os::unix::fs::OpenOptionsExt;
    let err = |reason: String| InputError {
        path: path.display().to_string(),
        reason,
    };
    let f = OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY)
        .open(path)
        .map_err(|e| err(format!("cannot read: {e}")))?;
    let m = f.metadata().map_err(|e| err(format!("cannot read: {e}")))?;
    if !m.is_file() {
        return Err(err(format!(
            "it is {}: gearwear reads a {what} only from a regular file",
            kind_words(&m.file_type())
        )));
    }
    if m.len() > max_bytes {
        return Err(err(format!(
            "it holds {} bytes, more than the {} MiB a {what} may have",
            m.len(),
            max_bytes >> 20
        )));
    }
    Ok(f)
}

/// The bytes of the input file `path` (a `what`, for messages), refused unless it is a
/// regular file of at most `max_bytes`.
pub fn read_input(path: &Path, what: &str, max_bytes: u64) -> Result<Vec<u8>, InputError> {
    let f = open_regular(path, what, max_bytes)?;
    let mut v = Vec::new();
    f.take(max_bytes + 1)
        .read_to_end(&mut v)
        .map_err(|e| InputError {
            path: path.display().to_string(),
            reason: format!("cannot read: {e}"),
        })?;
    if v.len() as u64 > max_bytes {
        return Err(InputError {
            path: path.display().to_string(),
            reason: format!(
                "it grew past the {} MiB a {what} may have while it was read",
                max_bytes >> 20
            ),
        });
    }
    Ok(v)
}

/// As [`read_input`], None when there is no file at `path`.
pub fn read_input_if_present(
    path: &Path,
    what: &str,
    max_bytes: u64,
) -> Result<Option<Vec<u8>>, InputError> {
    match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        _ => read_input(path, what, max_bytes).map(Some),
    }
}

/// As [`read_input`], as UTF-8 text; a file that is not text is refused without quoting it.
pub fn read_input_text(path: &Path, what: &str, max_bytes: u64) -> Result<String, InputError> {
    let b = read_input(path, what, max_bytes)?;
    String::from_utf8(b).map_err(|e| InputError {
        path: path.display().to_string(),
        reason: format!(
            "it is not UTF-8 text (byte {}): not a {what}",
            e.utf8_error().valid_up_to()
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fifos_devices_folders_and_large_files_are_refused_at_once() {
        let d = tempfile::tempdir().unwrap();
        let fifo = d.path().join("fifo");
        rustix::fs::mkfifoat(
            rustix::fs::CWD,
            fifo.as_path(),
            rustix::fs::Mode::from_raw_mode(0o600),
        )
        .unwrap();
        let e = read_input(&fifo, "case file", 100).unwrap_err().to_string();
        assert!(e.contains("FIFO") && e.contains("regular file"), "{e}");
        let e = read_input(Path::new("/dev/zero"), "case file", 100)
            .unwrap_err()
            .to_string();
        assert!(e.contains("a device"), "{e}");
        let e = read_input(d.path(), "case file", 100)
            .unwrap_err()
            .to_string();
        assert!(e.contains("a folder"), "{e}");
        let big = d.path().join("big");
        std::fs::write(&big, vec![b'a'; 3 << 20]).unwrap();
        let e = read_input(&big, "case file", 2 << 20)
            .unwrap_err()
            .to_string();
        assert!(e.contains("3145728 bytes") && e.contains("2 MiB"), "{e}");
        std::fs::write(&big, b"ok").unwrap();
        assert_eq!(read_input_text(&big, "case file", 2 << 20).unwrap(), "ok");
        std::fs::write(&big, [b'a', 0xff, b'b']).unwrap();
        let e = read_input_text(&big, "case file", 10)
            .unwrap_err()
            .to_string();
        assert!(e.contains("not UTF-8") && e.contains("byte 1"), "{e}");
    }
}
