//! The process's standard streams, written without ever panicking.
//!
//! `println!` and `eprintln!` panic when their stream fails (standard output sent to
//! `/dev/full`, a closed pipe), which ended a run with exit code 101 after its results
//! were published. Here a failed write is remembered instead: later lines to that stream
//! are dropped, and at the end the command says once, on the other stream if it still
//! works, what happened, and exits with [`STREAM_FAILED_EXIT`].

use std::io::Write;
use std::sync::Mutex;

/// Exit code of a command whose work was done (its outputs written or its error told)
/// but whose standard output or standard error could not be written.
pub const STREAM_FAILED_EXIT: u8 = 3;

/// A standard stream.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stream {
    /// Standard output.
    Out,
    /// Standard error.
    Err,
}

impl Stream {
    fn words(self) -> &'static str {
        match self {
            Stream::Out => "standard output",
            Stream::Err => "standard error",
        }
    }
}

/// The first failure of each stream.
static FAILED: Mutex<[Option<String>; 2]> = Mutex::new([None, None]);

fn slot(s: Stream) -> usize {
    usize::from(s == Stream::Err)
}

fn failed(s: Stream) -> bool {
    FAILED.lock().map_or(true, |f| f[slot(s)].is_some())
}

/// Write `text` and a line break to `stream`, unless it failed before; a failure is
/// remembered, never a panic.
pub fn line(stream: Stream, text: &str) {
    if failed(stream) {
        return;
    }
    let r = match stream {
        Stream::Out => {
            let mut o = std::io::stdout().lock();
            writeln!(o, "{text}").and_then(|_| o.flush())
        }
        Stream::Err => {
            let mut o = std::io::stderr().lock();
            writeln!(o, "{text}").and_then(|_| o.flush())
        }
    };
    if let Err(e) = r {
        if let Ok(mut f) = FAILED.lock() {
            f[slot(stream)].get_or_insert_with(|| e.to_string());
        }
    }
}

/// A line of results on standard output.
pub fn out_line(text: &str) {
    line(Stream::Out, text);
}

/// A line of messages (warnings, notes, errors) on standard error.
pub fn err_line(text: &str) {
    line(Stream::Err, text);
}

/// What failed, as a sentence, if a stream did.
pub fn failure() -> Option<String> {
    let f = FAILED.lock().ok()?;
    let parts: Vec<String> = [Stream::Out, Stream::Err]
        .into_iter()
        .filter_map(|s| f[slot(s)].as_ref().map(|e| format!("{} ({e})", s.words())))
        .collect();
    (!parts.is_empty()).then(|| {
        format!(
            "gearwear could not write to {}; the command itself ran to its end (exit code {STREAM_FAILED_EXIT})",
            parts.join(" nor to ")
        )
    })
}

/// At the end of a command: when a stream failed, say so once (on standard error, or on
/// standard output when standard error is the one that failed) and return the exit code
/// to use instead.
pub fn finish() -> Option<u8> {
    let msg = failure()?;
    if !failed(Stream::Err) {
        err_line(&format!("error: {msg}"));
    } else {
        out_line(&format!("error: {msg}"));
    }
    Some(STREAM_FAILED_EXIT)
}
