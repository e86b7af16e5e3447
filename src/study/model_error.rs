//! Why a case cannot be modelled: the error the model of a single pair and of a train
//! (`study::train`) both give.

/// A case that cannot be modelled (bad geometry or an unusable combination of settings).
#[derive(Debug, Clone, PartialEq)]
pub struct ModelError(pub Vec<String>);

impl std::fmt::Display for ModelError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0.join("; "))
    }
}

impl std::error::Error for ModelError {}
