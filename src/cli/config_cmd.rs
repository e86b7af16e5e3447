//! `gearwear config`: print the (resolved) case as commented TOML.

use super::args::ConfigArgs;
use super::CliError;
use crate::config::{commented_template, markdown_reference};

pub fn run(a: &ConfigArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    if a.markdown {
        print!("{}", markdown_reference(&case));
    } else {
        print!("{}", commented_template(&case));
    }
    Ok(())
}
