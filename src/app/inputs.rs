//! Input tables of a job (observations, posterior samples): a CSV file, or columns handed
//! over in memory (the Python binding's numpy arrays and DataFrames). Both are read by the
//! same parser through the same CSV text (the columns written as the command line writes
//! its tables, every number in its shortest exact form), so a table gives the same
//! numbers, the same checks and the same identity (the SHA-256 of its text) whichever way
//! it came.

use super::JobError;
use crate::io::Table;
use crate::remedy::{Arg, Problem};
use std::path::PathBuf;

/// See the module docs.
#[derive(Debug, Clone)]
pub enum TableSource {
    /// A CSV file.
    File(PathBuf),
    /// Named columns; a NaN is an empty cell (not measured).
    Columns(Table),
}

impl TableSource {
    /// The table's name in messages and its CSV text. `arg` is the job argument it was
    /// given as (named in a problem with the file).
    /// A file is read only if it is a regular file of at most `max_bytes`
    /// (`io::read_input_text`: a FIFO or a device is refused at once).
    pub fn read(&self, arg: Arg, max_bytes: u64) -> Result<(String, String), JobError> {
        match self {
            TableSource::File(p) => {
                let src = p.display().to_string();
                let text = crate::io::read_input_text(p, arg.plain(), max_bytes)
                    .map_err(|e| JobError::input(Problem::of(arg, e.to_string())))?;
                Ok((src, text))
            }
            TableSource::Columns(t) => {
                if let Some(i) =
                    (1..t.columns.len()).find(|i| t.columns[*i].len() != t.columns[0].len())
                {
                    return Err(JobError::input(Problem::of(
                        arg,
                        format!(
                            "column `{}` has {} values, column `{}` {}: every column needs one value per row",
                            t.names[i],
                            t.columns[i].len(),
                            t.names[0],
                            t.columns[0].len()
                        ),
                    )));
                }
                // The CSV leaves a non-finite number's cell empty: only NaN may mean that.
                for (name, c) in t.names.iter().zip(&t.columns) {
                    if let Some(r) = c.iter().position(|x| x.is_infinite()) {
                        return Err(JobError::input(Problem::of(
                            arg,
                            format!("row {}: column `{name}`: {} is not finite", r + 1, c[r]),
                        )));
                    }
                }
                let bytes = t.to_csv().map_err(|e| JobError::Failed(e.into()))?;
                if bytes.len() as u64 > max_bytes {
                    return Err(JobError::input(Problem::of(
                        arg,
                        format!(
                            "the table's text is {} bytes, more than the {max_bytes} a file may have",
                            bytes.len()
                        ),
                    )));
                }
                let text = String::from_utf8(bytes).map_err(|e| JobError::Failed(e.into()))?;
                Ok((arg.plain().to_owned(), text))
            }
        }
    }
}
