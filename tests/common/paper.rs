//! The built-in (paper's) case and its whole study, computed once per test binary
//! (4e4 cycles: ~0.2 s of CPU in release).

use std::sync::OnceLock;

use gearwear::config::Case;
use gearwear::study::paper::{run_paper_study, PaperStudy};
use gearwear::study::wear_loop::{WearMode, WearRun};
use gearwear::study::Model;

pub fn paper() -> &'static (Model, PaperStudy) {
    static CELL: OnceLock<(Model, PaperStudy)> = OnceLock::new();
    CELL.get_or_init(|| {
        let model = Model::from_case(&Case::default()).expect("the built-in case builds");
        let (d, q) = (
            WearRun::new(WearMode::Dynamic),
            WearRun::new(WearMode::QuasiStatic),
        );
        let study = run_paper_study(&model, d, q, &|_, _| Ok(())).expect("the study runs");
        (model, study)
    })
}
