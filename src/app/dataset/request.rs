//! What a dataset step is given (the request) and gives back (the outcome, or why it
//! failed).

use super::index_files::Missing;
use crate::app::JobError;
use crate::remedy::Problem;
use crate::report::figure_output::FigureOutput;
use crate::signals::transfer::TransferPath;
use crate::study::dataset::plan::Shard;
use crate::study::dataset::DatasetDesign;

/// Why a dataset step failed: bad input (the design, its files, the budget) or a run
/// that could not finish.
#[derive(Debug, thiserror::Error)]
pub enum DatasetError {
    /// Bad input, one message per problem.
    #[error("{}", .0.join("\n"))]
    Input(Vec<String>),
    /// A run that could not finish (a file that could not be written, a worker that
    /// failed).
    #[error(transparent)]
    Failed(#[from] anyhow::Error),
}

impl From<DatasetError> for JobError {
    fn from(e: DatasetError) -> Self {
        match e {
            DatasetError::Input(m) => JobError::Input(m.into_iter().map(Problem::new).collect()),
            DatasetError::Failed(e) => JobError::Failed(e),
        }
    }
}

/// What a dataset job did.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DatasetOutcome {
    pub total_records: usize,
    pub shard_records: usize,
    pub computed: usize,
    pub reused: usize,
    /// Physical states that failed (the solver gave up), with the reason.
    pub failures: Vec<String>,
    /// Records missing from the index (an unsharded run or a merge): the count and
    /// the first ids.
    pub missing: Missing,
    pub estimated_bytes: f64,
}

/// A design, its transfer path (read by the caller) and where it goes.
pub struct DatasetRequest<'a> {
    /// The design checked (its conditions, chain and record settings).
    pub design: &'a DatasetDesign,
    /// The transfer path of the signal chain (`None`: the generic housing path,
    /// `TransferPath::generic_housing`).
    pub path: Option<TransferPath>,
    /// Bytes of the transfer-path file (part of the dataset key).
    pub path_bytes: Vec<u8>,
    /// The part of the records this step computes.
    pub shard: Shard,
    /// The formats and size of the dataset's figure.
    pub figures: FigureOutput,
    /// Replace another design's dataset in the folder (else refused).
    pub replace: bool,
}
