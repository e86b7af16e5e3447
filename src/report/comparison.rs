//! Our headline numbers beside the paper's (sections 4.1 and 4.2), with the reason for
//! each deviation. Shown only for the paper's case (`case::is_paper_case`). The paper's
//! values are quoted from its text (docs/PAPER_NOTES.md, "Published numbers"); every
//! number in an explanation comes from the run.
//!
//! `gearwear run` of the paper's case runs it under both contact models (`contact.path`,
//! docs/MODEL.md section 4.2): the nominal path (the paper's own model, so that the
//! reproduction stays checkable) and the extended contact (the default), each beside the
//! paper's value.

use super::case::{cycles_words, load_sentence, open_choices_words, poles_sentence};
use super::wear::{at_cycles, max_rate_at};
use crate::config::case::ContactPathModel;
use crate::study::paper::PaperStudy;
use crate::study::wear_loop::WearRun;
use crate::study::Model;
use serde_json::{json, Value};

/// One compared quantity.
pub struct Compared {
    /// JSON key, e.g. "dte_max_um_at_0.5um_wear".
    pub key: String,
    /// Display name with unit.
    pub quantity: String,
    /// The case's value, under its own `contact.path` ([`Compared::path`]).
    pub ours: f64,
    /// The contact model `ours` was computed with.
    pub path: ContactPathModel,
    /// The same quantity of the case run under the other contact model ([`with_twin`];
    /// `None`: not run).
    pub twin: Option<f64>,
    /// The paper's value.
    pub paper: f64,
    /// Why ours differs from the paper's (numbers from the run).
    pub explanation: String,
}

impl Compared {
    /// `(ours - paper) / |paper|`.
    pub fn relative_deviation(&self) -> f64 {
        (self.ours - self.paper) / self.paper.abs()
    }

    /// The value under `path`: ours or the twin's.
    pub fn under(&self, path: ContactPathModel) -> Option<f64> {
        match path == self.path {
            true => Some(self.ours),
            false => self.twin,
        }
    }
}

/// `rows` of the case with each quantity's value under the other contact model taken
/// from `twin` (the rows of the same case run with the other `contact.path`), matched by
/// key.
pub fn with_twin(mut rows: Vec<Compared>, twin: &[Compared]) -> Vec<Compared> {
    for r in &mut rows {
        r.twin = twin.iter().find(|t| t.key == r.key).map(|t| t.ours);
    }
    rows
}

/// The paper's section 4.1 values at 0.1 / 0.5 / 1 um wear and 4.2 ratios.
pub const PAPER_DTE_MAX_UM: [f64; 3] = [16.70, 18.08, 19.47];
/// The paper's RMS of the pinion's y velocity dy_p/dt at 0.1 / 0.5 / 1 µm wear, mm/s
/// (section 4.1).
pub const PAPER_VEL_RMS_MM_S: [f64; 3] = [1.10, 1.19, 1.28];
/// The paper's mean mesh force at 0.1 / 0.5 / 1 µm wear, N (section 4.1).
pub const PAPER_FORCE_MEAN_N: [f64; 3] = [3311.2, 3431.9, 3697.6];
/// The paper's ratio of the largest pinion wear depth per cycle, dynamic over
/// quasi-static (section 4.2).
pub const PAPER_RATIO_MAX_WEAR: f64 = 1.6;
/// The paper's ratio of the largest accumulated pinion wear, dynamic over quasi-static
/// (section 4.2).
pub const PAPER_RATIO_ACCUMULATED_WEAR: f64 = 1.2;

/// Load cycles both wear runs reached: the case's total unless a run stopped early
/// (then the comparison is at the shorter run's end).
pub fn cycles_reached(study: &PaperStudy) -> f64 {
    let end = |r: &WearRun| r.cycles().last().copied().unwrap_or(0.0);
    end(&study.dynamic).min(end(&study.quasi_static))
}

/// Ratios, dynamic to quasi-static, at the cycles both runs reached: (max wear rate of
/// each run's state there, max accumulated wear).
pub fn wear_ratios(study: &PaperStudy) -> (f64, f64) {
    let end = cycles_reached(study);
    let acc = |r: &WearRun| at_cycles(&r.cycles(), &r.max_wear_pinion_m(), end);
    (
        max_rate_at(&study.dynamic, end) / max_rate_at(&study.quasi_static, end),
        acc(&study.dynamic) / acc(&study.quasi_static),
    )
}

/// Dynamic factor (max / mean mesh force) on new teeth: the first dynamic update.
fn initial_dynamic_factor(study: &PaperStudy) -> f64 {
    study
        .dynamic
        .records
        .first()
        .map_or(f64::NAN, |r| r.summary.dynamic_factor)
}

/// Why our numbers differ from the paper's, quantity by quantity, with this run's numbers.
struct Why {
    dte: String,
    velocity: String,
    force: String,
    rate: String,
    accumulated: String,
}

fn explanations(model: &Model, study: &PaperStudy) -> Why {
    let poles = poles_sentence(model);
    let cycles = cycles_words(cycles_reached(study));
    let df = initial_dynamic_factor(study);
    let states = &study.wear_states;
    let dte_change = match (states.first(), states.last()) {
        (Some(a), Some(b)) => format!(
            "Our max DTE changes by {:+.2} µm between {} and {} µm of wear",
            (b.summary.dte_max_m - a.summary.dte_max_m) * 1e6,
            a.max_wear_um,
            b.max_wear_um
        ),
        _ => "Our max DTE barely moves with wear".into(),
    };
    let paper_rise = 100.0 * (PAPER_FORCE_MEAN_N[2] / PAPER_FORCE_MEAN_N[0] - 1.0);
    Why {
        dte: format!(
            "The paper gives neither the mesh damping, the speed boundary condition, the viscosity nor the hub bores; this run takes {}. {poles} {dte_change}: Archard wear vanishes at the pitch point, inside the single-contact zone where the maximum occurs (docs/REPRODUCTION.md).",
            open_choices_words(model)
        ),
        velocity: format!(
            "The y velocity is dominated by the response of the damped mesh pole to the mesh stiffness's variation (a jump at each pair change on the nominal path, a ramp with the extended contact); its size depends on the speed boundary condition and the mesh damping, which the paper does not give (docs/PAPER_NOTES.md). {poles} docs/REPRODUCTION.md shows how the value moves with those choices."
        ),
        force: format!(
            "In periodic steady state the mean mesh force is fixed by the load torque: r_gb mean(F) + mean friction moment = T_brk (docs/MODEL.md). {} Ours departs from it only by the friction moment. The paper's {paper_rise:.0} % rise of the mean with wear cannot come from a balanced drivetrain (docs/PAPER_NOTES.md).",
            load_sentence(model)
        ),
        rate: format!(
            "Ratio of the maximum pinion wear per cycle, dynamic to quasi-static, at {cycles} cycles. It follows the dynamic factor of the mesh force ({df:.2} on new teeth in this run), which depends on the speed boundary condition and damping (docs/REPRODUCTION.md)."
        ),
        accumulated: format!(
            "Ratio of the maximum accumulated pinion wear depth at {cycles} cycles. Our dynamic loads exceed the static ones from the first cycle (dynamic factor {df:.2}), so the accumulated ratio is close to the rate ratio; the paper's initial stage is 'quite approximate' (dynamic ~ static), which needs a smaller dynamic factor than our parameters give."
        ),
    }
}

/// Every compared number.
pub fn compare(model: &Model, study: &PaperStudy) -> Vec<Compared> {
    let why = explanations(model, study);
    let path = model.case.contact.path;
    let mut out = Vec::new();
    for (i, s) in study.wear_states.iter().enumerate().take(3) {
        let w = s.max_wear_um;
        out.push(Compared {
            key: format!("dte_max_um_at_{w}um_wear"),
            quantity: format!("max DTE at {w} µm wear (µm)"),
            ours: s.summary.dte_max_m * 1e6,
            path,
            twin: None,
            paper: PAPER_DTE_MAX_UM[i],
            explanation: why.dte.clone(),
        });
        out.push(Compared {
            key: format!("velocity_y_pinion_rms_mm_per_s_at_{w}um_wear"),
            quantity: format!("RMS of dy_p/dt at {w} µm wear (mm/s)"),
            ours: s.summary.velocity_y_pinion_rms_m_per_s * 1e3,
            path,
            twin: None,
            paper: PAPER_VEL_RMS_MM_S[i],
            explanation: why.velocity.clone(),
        });
        out.push(Compared {
            key: format!("mesh_force_mean_n_at_{w}um_wear"),
            quantity: format!("mean mesh force at {w} µm wear (N)"),
            ours: s.summary.mesh_force_mean_n,
            path,
            twin: None,
            paper: PAPER_FORCE_MEAN_N[i],
            explanation: why.force.clone(),
        });
    }
    let (rate, acc) = wear_ratios(study);
    let cycles = cycles_words(cycles_reached(study));
    out.push(Compared {
        key: "ratio_max_wear_rate_dynamic_to_static".into(),
        quantity: format!(
            "max pinion wear depth per cycle, dynamic / quasi-static, {cycles} cycles (-)"
        ),
        ours: rate,
        path,
        twin: None,
        paper: PAPER_RATIO_MAX_WEAR,
        explanation: why.rate,
    });
    out.push(Compared {
        key: "ratio_max_wear_dynamic_to_static".into(),
        quantity: format!(
            "max accumulated pinion wear, dynamic / quasi-static, {cycles} cycles (-)"
        ),
        ours: acc,
        path,
        twin: None,
        paper: PAPER_RATIO_ACCUMULATED_WEAR,
        explanation: why.accumulated,
    });
    out
}

/// The comparison as JSON: key -> {ours, paper, relative_deviation, explanation,
/// contact_path (ours'), nominal_path, extended_contact}; the last two: {value,
/// relative_deviation} under each contact model, null where not run.
pub fn comparison_json(rows: &[Compared]) -> Value {
    let mut m = serde_json::Map::new();
    for r in rows {
        let under = |path| match r.under(path) {
            Some(v) => json!({"value": v, "relative_deviation": (v - r.paper) / r.paper.abs()}),
            None => Value::Null,
        };
        m.insert(
            r.key.clone(),
            json!({
                "ours": r.ours,
                "paper": r.paper,
                "relative_deviation": r.relative_deviation(),
                "explanation": r.explanation,
                "contact_path": r.path,
                "nominal_path": under(ContactPathModel::Nominal),
                "extended_contact": under(ContactPathModel::Extended),
            }),
        );
    }
    Value::Object(m)
}
