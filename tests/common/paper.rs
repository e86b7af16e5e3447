//! The built-in (paper's) case and its whole study, computed once per test binary
//! (4e4 cycles: ~0.2 s of CPU in release), with the paper's own contact model
//! (`contact.path` = "nominal"), whose figures these tests set beside the paper's.

use std::sync::OnceLock;

use gearwear::config::case::ContactPathModel;
use gearwear::config::Case;
use gearwear::study::paper::{run_paper_study, PaperStudy};
use gearwear::study::wear_loop::{WearMode, WearRun};
use gearwear::study::Model;

pub fn paper() -> &'static (Model, PaperStudy) {
    static CELL: OnceLock<(Model, PaperStudy)> = OnceLock::new();
    CELL.get_or_init(|| {
        let mut case = Case::default();
        case.contact.path = ContactPathModel::Nominal;
        let model = Model::from_case(&case).expect("the built-in case builds");
        let (d, q) = (
            WearRun::new(WearMode::Dynamic),
            WearRun::new(WearMode::QuasiStatic),
        );
        let study = run_paper_study(&model, d, q, &|_, _| Ok(())).expect("the study runs");
        (model, study)
    })
}
