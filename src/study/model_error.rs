//! Why a case cannot be modelled: the error the model of a single pair, a helical pair, a
//! train and a planetary set all give. The lower layers' errors (geometry, stiffness, the
//! face load) convert into it with `?`, their problems kept one by one; the application
//! edge (`app::JobError`) turns each problem into a `remedy::Problem`.

use crate::dynamics::assembly::AssemblyError;
use crate::geometry::GeometryError;
use crate::stiffness::face_load::FaceLoadError;
use crate::stiffness::mesh::StiffnessError;

/// A case that cannot be modelled (bad geometry or an unusable combination of settings):
/// every problem found, each naming its key, value and range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", .0.join("; "))]
pub struct ModelError(pub Vec<String>);

impl From<GeometryError> for ModelError {
    fn from(e: GeometryError) -> Self {
        ModelError(e.0)
    }
}

impl From<StiffnessError> for ModelError {
    fn from(e: StiffnessError) -> Self {
        ModelError(e.0)
    }
}

impl From<FaceLoadError> for ModelError {
    fn from(e: FaceLoadError) -> Self {
        ModelError(vec![e.0])
    }
}

impl From<AssemblyError> for ModelError {
    fn from(e: AssemblyError) -> Self {
        ModelError(vec![e.to_string()])
    }
}
