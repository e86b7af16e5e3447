//! Reading a transfer-path file (`signals::path_file`: FRF table CSV or modal TOML).

use crate::signals::path_file::parse_transfer_path;
use crate::signals::transfer::TransferPath;
use std::path::Path;

/// The transfer path in `path`; every problem names the file.
pub(crate) fn read_transfer_path(path: &Path) -> Result<TransferPath, Vec<String>> {
    let name = path.display().to_string();
    let text = crate::io::input::read_input_text(
        path,
        "transfer-path file",
        crate::io::input::MAX_TRANSFER_PATH_BYTES,
    )
    .map_err(|e| vec![format!("transfer path file {name}: {}", e.reason)])?;
    parse_transfer_path(&text, &name)
}
