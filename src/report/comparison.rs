//! Our headline numbers beside the paper's (sections 4.1 and 4.2), with the reason for
//! each deviation. The paper's values are quoted from its text (see NOTES.md's table).

use crate::study::paper::PaperStudy;
use serde_json::{json, Value};

/// One compared quantity.
pub struct Compared {
    /// JSON key, e.g. "dte_max_um_at_0.5um_wear".
    pub key: String,
    /// Display name with unit.
    pub quantity: String,
    pub ours: f64,
    pub paper: f64,
    pub explanation: &'static str,
}

impl Compared {
    pub fn relative_deviation(&self) -> f64 {
        (self.ours - self.paper) / self.paper.abs()
    }
}

const DTE_WHY: &str = "The paper gives neither the mesh damping, the speed boundary condition, the viscosity nor the hub bores; with ours (zeta = 0.05, motor slip law, 40 cP, 8/14 mm) the damped mesh pole (the resonance of the mesh with all damping included) sits at ~1250 Hz, zeta ~0.29, so the second harmonic of the 570 Hz mesh frequency lies close below it (docs/MODEL.md, Modes). Our max DTE barely moves with wear: Archard wear vanishes at the pitch point, inside the single-contact zone where the maximum occurs (docs/REPRODUCTION.md).";
const VEL_WHY: &str = "The y velocity is dominated by the response of the damped mesh pole to the stiffness jumps; its size depends on the speed boundary condition and the mesh damping, which the paper does not give (NOTES.md). Our value scales with them as docs/REPRODUCTION.md shows.";
const FORCE_WHY: &str = "In periodic steady state the mean mesh force is fixed by the load torque: r_gb mean(F) + mean friction moment = T_brk (docs/MODEL.md). Ours departs from 60 N m / r_pb = 3361 N only by the friction moment. The paper's 12 % rise of the mean with wear cannot come from a balanced drivetrain (NOTES.md).";
const RATE_WHY: &str = "Ratio of the maximum pinion wear per cycle, dynamic to quasi-static, at 4e4 cycles. It follows the dynamic factor of the mesh force, which depends on the speed boundary condition and damping (docs/REPRODUCTION.md).";
const ACC_WHY: &str = "Ratio of the maximum accumulated pinion wear depth at 4e4 cycles. Our dynamic loads exceed the static ones from the first cycle (dynamic factor ~1.6), so the accumulated ratio is close to the rate ratio; the paper's initial stage is 'quite approximate' (dynamic ~ static), which needs a smaller dynamic factor than our parameters give.";

/// The paper's section 4.1 values at 0.1 / 0.5 / 1 um wear and 4.2 ratios.
pub const PAPER_DTE_MAX_UM: [f64; 3] = [16.70, 18.08, 19.47];
pub const PAPER_VEL_RMS_MM_S: [f64; 3] = [1.10, 1.19, 1.28];
pub const PAPER_FORCE_MEAN_N: [f64; 3] = [3311.2, 3431.9, 3697.6];
pub const PAPER_RATIO_MAX_WEAR: f64 = 1.6;
pub const PAPER_RATIO_ACCUMULATED_WEAR: f64 = 1.2;

/// Ratios of the final state: (max wear rate ratio, max accumulated wear ratio).
pub fn wear_ratios(study: &PaperStudy) -> (f64, f64) {
    let rate = |r: &crate::study::wear_loop::WearRun| {
        r.last().map_or(0.0, |x| {
            x.increment_pinion_m.iter().fold(0.0_f64, |a, b| a.max(*b))
        })
    };
    let acc =
        |r: &crate::study::wear_loop::WearRun| r.last().map_or(0.0, |x| x.wear.max_pinion_m());
    (
        rate(&study.dynamic) / rate(&study.quasi_static),
        acc(&study.dynamic) / acc(&study.quasi_static),
    )
}

/// Every compared number.
pub fn compare(study: &PaperStudy) -> Vec<Compared> {
    let mut out = Vec::new();
    for (i, s) in study.wear_states.iter().enumerate() {
        let w = s.max_wear_um;
        out.push(Compared {
            key: format!("dte_max_um_at_{w}um_wear"),
            quantity: format!("max DTE at {w} um wear (um)"),
            ours: s.summary.dte_max_m * 1e6,
            paper: PAPER_DTE_MAX_UM[i],
            explanation: DTE_WHY,
        });
        out.push(Compared {
            key: format!("velocity_y_pinion_rms_mm_per_s_at_{w}um_wear"),
            quantity: format!("RMS of dy_p/dt at {w} um wear (mm/s)"),
            ours: s.summary.velocity_y_pinion_rms_m_per_s * 1e3,
            paper: PAPER_VEL_RMS_MM_S[i],
            explanation: VEL_WHY,
        });
        out.push(Compared {
            key: format!("mesh_force_mean_n_at_{w}um_wear"),
            quantity: format!("mean mesh force at {w} um wear (N)"),
            ours: s.summary.mesh_force_mean_n,
            paper: PAPER_FORCE_MEAN_N[i],
            explanation: FORCE_WHY,
        });
    }
    let (rate, acc) = wear_ratios(study);
    out.push(Compared {
        key: "ratio_max_wear_rate_dynamic_to_static".into(),
        quantity: "max pinion wear depth per cycle, dynamic / quasi-static, 4e4 cycles (-)".into(),
        ours: rate,
        paper: PAPER_RATIO_MAX_WEAR,
        explanation: RATE_WHY,
    });
    out.push(Compared {
        key: "ratio_max_wear_dynamic_to_static".into(),
        quantity: "max accumulated pinion wear, dynamic / quasi-static, 4e4 cycles (-)".into(),
        ours: acc,
        paper: PAPER_RATIO_ACCUMULATED_WEAR,
        explanation: ACC_WHY,
    });
    out
}

/// The comparison as JSON: key -> {ours, paper, relative_deviation}.
pub fn comparison_json(rows: &[Compared]) -> Value {
    let mut m = serde_json::Map::new();
    for r in rows {
        m.insert(
            r.key.clone(),
            json!({"ours": r.ours, "paper": r.paper, "relative_deviation": r.relative_deviation(), "explanation": r.explanation}),
        );
    }
    Value::Object(m)
}
