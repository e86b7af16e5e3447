//! `gearwear signals`: one record of the case's steady state as a sensor records it.

use super::output::{build_model, finish, open_out};
use super::signals_args::SignalsArgs;
use super::CliError;
use crate::io::transfer_path::read_transfer_path;
use crate::io::RunMetadata;
use crate::report::signals::signals_artifacts;
use crate::signals::setup::chain_of;
use crate::study::signal_record::record_case;
use crate::wear::WearState;

pub fn run(a: &SignalsArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let path = a
        .transfer_path
        .as_deref()
        .map(read_transfer_path)
        .transpose()
        .map_err(CliError::Input)?;
    let setup =
        chain_of(&case, path, case.signals.max_input_speed_hz(&case)).map_err(CliError::Input)?;
    for w in &setup.warnings {
        eprintln!("warning: {w}");
    }
    let out = open_out(&a.out, "signals")?;
    let rec = record_case(&model, &setup, &WearState::new(model.grid.len()))
        .map_err(|e| CliError::Failed(e.into()))?;
    let harmonics = case.signals.mesh_harmonics.max(1) as usize;
    finish(
        out,
        signals_artifacts(&rec, &setup.chain, harmonics, "new teeth"),
        &RunMetadata::new("signals", &case),
    )
}
