//! `gearwear config`: print the (resolved) case as commented TOML, the key reference, or
//! a starting case for a new pair.

use super::args::ConfigArgs;
use super::error::CliError;
use crate::config::{commented_template, markdown_reference, new_pair_template};

pub(crate) fn run(a: &ConfigArgs) -> Result<(), CliError> {
    if a.new_pair {
        if a.case.config.is_some() || !a.case.set.is_empty() {
            return Err(CliError::input(
                "--new-pair prints a fixed starting case: give it no --config or --set (edit the printed file instead)",
            ));
        }
        print!("{}", new_pair_template());
        return Ok(());
    }
    let case = a.case.load()?;
    if a.markdown {
        print!("{}", markdown_reference(&case));
    } else {
        print!("{}", commented_template(&case));
    }
    Ok(())
}
