//! Reading a transfer-path file (`signals::path_file`: FRF table CSV or modal TOML).

use crate::signals::path_file::parse_transfer_path;
use crate::signals::transfer::TransferPath;
use std::path::Path;

/// The transfer path in `path`; every problem names the file.
pub fn read_transfer_path(path: &Path) -> Result<TransferPath, Vec<String>> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| vec![format!("transfer path file {name}: cannot read it: {e}")])?;
    parse_transfer_path(&text, &name)
}
