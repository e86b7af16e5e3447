//! The run budget's view of a tooth-resolved case: the mesh periods its excitation
//! repeats over, read from the case alone before any model is built, and the cost that
//! period adds to a run ([`super::case_jobs::estimate`] adds the term).

use super::cost::Term;
use super::evaluation::SECONDS_PER_QUASI_STATIC_STEP;
use crate::config::case::{Case, Member};

/// Bytes of one recorded sample of the response alone (280 bytes, doubled for vector
/// growth), without the output tables counted in
/// [`BYTES_PER_SAMPLE`](super::case_jobs::BYTES_PER_SAMPLE): the periods a tooth-resolved
/// response records beyond `numerics.evaluated_mesh_periods`. Measured peaks of the
/// paper's pair at `teeth.accuracy_grade = 5` (589 periods): `dynamics` 258 MB, `run`
/// 417 MB.
pub const RESPONSE_BYTES_PER_SAMPLE: f64 = 560.0;

/// Whether the values of a per-tooth array differ from tooth to tooth.
fn differ(v: &Option<Vec<f64>>) -> bool {
    v.as_ref().is_some_and(|v| v.iter().any(|x| *x != v[0]))
}

/// Mesh periods the excitation of `case` repeats over, from the case alone (the run
/// budget's estimate, before any model is built): z of each gear whose teeth differ
/// (errors given or drawn, a fault on one of its teeth, run-out), their lcm. An ISO grade
/// draws only the error arrays a gear does not give (`study::teeth::errors`), so a gear
/// that gives all three arrays alike keeps its teeth alike under a grade. Modified or
/// worn teeth alike on a gear keep it at one. The model's period is the smallest shift
/// that repeats every engagement (`dynamics::tooth_mesh::sequence_period`), which
/// divides this; per-tooth wear never lengthens it (a tooth's wear follows the
/// engagements it meets, which repeat with the period), so this bounds the period over
/// the whole wear study.
///
/// A gear train (`[[stage]]`): base periods of the train (`dynamics::grid::base_period`)
/// its excitation repeats over, each faulty stage's teeth repeating over z of its faulty
/// gear (`dynamics::grid::chain_excitation_periods`, docs/MODEL.md 9.10); 1 without a
/// fault; `usize::MAX` (refused by the budget) when a number overflows.
pub fn excitation_periods_of(case: &Case) -> usize {
    if !case.stage.is_empty() {
        return train_excitation_periods(case);
    }
    let t = &case.teeth;
    let drawn = t.accuracy_grade.is_some();
    let fault_on = |m: Member| case.fault.iter().any(|f| f.gear == m);
    let varies = |arrays: [&Option<Vec<f64>>; 3], runout: Option<f64>, m: Member| {
        arrays.iter().any(|a| differ(a) || (drawn && a.is_none()))
            || runout.is_some_and(|r| r > 0.0)
            || fault_on(m)
    };
    let pinion = varies(
        [
            &t.pitch_error_pinion_um,
            &t.profile_slope_pinion_um,
            &t.profile_form_pinion_um,
        ],
        t.runout_pinion_um,
        Member::Pinion,
    );
    let gear = varies(
        [
            &t.pitch_error_gear_um,
            &t.profile_slope_gear_um,
            &t.profile_form_gear_um,
        ],
        t.runout_gear_um,
        Member::Gear,
    );
    let z = |varies: bool, z: i64| if varies { z.max(1) as usize } else { 1 };
    crate::dynamics::tooth_mesh::lcm(
        z(pinion, case.gear.teeth_pinion),
        z(gear, case.gear.teeth_gear),
    )
}

/// [`excitation_periods_of`] a gear train.
fn train_excitation_periods(case: &Case) -> usize {
    let (teeth, repeats) = stage_teeth_and_repeats(case);
    crate::dynamics::grid::chain_excitation_periods(&teeth, &repeats)
        .and_then(|p| usize::try_from(p).ok())
        .unwrap_or(usize::MAX)
}

/// Each stage's teeth (pinion, gear; at least 1) and the mesh periods its teeth repeat
/// over: the lcm of its faulty gears' teeth (`fault.stage`), 1 for a healthy stage.
fn stage_teeth_and_repeats(case: &Case) -> (Vec<[usize; 2]>, Vec<usize>) {
    let mut teeth = Vec::with_capacity(case.stage.len());
    let mut repeats = Vec::with_capacity(case.stage.len());
    for (k, st) in case.stage.iter().enumerate() {
        let g = st.gear_section(&case.gear);
        let z = [g.teeth_pinion.max(1) as usize, g.teeth_gear.max(1) as usize];
        let faulty = |m: Member| {
            case.fault
                .iter()
                .any(|f| f.stage_index() == Some(k) && f.gear == m && f.changes_tooth())
        };
        let r = |m: Member, z: usize| if faulty(m) { z } else { 1 };
        teeth.push(z);
        repeats.push(crate::dynamics::tooth_mesh::lcm(
            r(Member::Pinion, z[0]),
            r(Member::Gear, z[1]),
        ));
    }
    (teeth, repeats)
}

/// Stages of a train whose teeth differ (a fault on one of them): 0 for a single pair.
pub fn faulty_train_stages(case: &Case) -> usize {
    if case.stage.is_empty() {
        return 0;
    }
    stage_teeth_and_repeats(case)
        .1
        .iter()
        .filter(|r| **r > 1)
        .count()
}

/// `gearwear stiffness` of a train with a tooth fault: each faulty stage's static
/// transmission error over its own repeat (its pair alone, over the mesh periods its
/// faulty teeth repeat over) at a single pair's cost, `s` quasi-static steps a mesh
/// period; None without a fault. (The train's dynamic period does not enter: the
/// stiffness study solves each stage's pair by itself.)
pub fn train_stiffness_term(case: &Case, s: f64) -> Option<Term> {
    let periods: f64 = stage_teeth_and_repeats(case)
        .1
        .iter()
        .filter(|r| **r > 1)
        .map(|r| *r as f64)
        .sum();
    (periods > 0.0).then_some(Term {
        what: "the static transmission error of each faulty train stage over its teeth",
        seconds: s * periods * SECONDS_PER_QUASI_STATIC_STEP,
        bytes: s * periods * (RESPONSE_BYTES_PER_SAMPLE + PATH_BYTES_PER_SAMPLE),
        keys: &[
            "fault.stage",
            "fault.gear",
            "stage.teeth_pinion",
            "stage.teeth_gear",
        ],
    })
}

/// Mesh periods of run-in the budget allows a tooth-resolved evaluation at the default
/// `numerics.steady_state_tolerance` 1e-6 and 30 Hz (the measured run-in of the paper's
/// case is 8; slow decay at high speed raises it).
const RUN_IN_PERIODS: f64 = 30.0;
/// Mesh frequency of the paper's pair at 30 Hz, where `RUN_IN_PERIODS` was measured, Hz.
const RUN_IN_MESH_HZ: f64 = 570.0;

/// Periods of run-in of a tooth-resolved evaluation (`dynamics::hunting::run_in_periods`:
/// W = 1.2 ln(1 / tol) / (sigma T), T the mesh period and sigma the model's slowest decay
/// rate): `RUN_IN_PERIODS` at 1e-6 and 570 Hz, scaled as W with ln(1 / tol) and with the
/// mesh frequency (sigma held), never below it, at most P.
fn run_in_periods(case: &Case, p: f64) -> f64 {
    let decades = (1.0 / case.numerics.steady_state_tolerance).log10() / 6.0;
    let mesh_hz = case.operating.input_speed_hz * super::evaluation::input_pinion_teeth(case);
    let speed = if mesh_hz.is_finite() {
        mesh_hz / RUN_IN_MESH_HZ
    } else {
        1.0
    };
    (RUN_IN_PERIODS * decades.max(1.0) * speed.max(1.0)).min(p)
}

/// Bytes of the path samples of a recorded sample (two pairs of 72 bytes, doubled for
/// growth), on top of the response's [`RESPONSE_BYTES_PER_SAMPLE`].
const PATH_BYTES_PER_SAMPLE: f64 = 300.0;

/// The run budget's term for a tooth-resolved case (None when every tooth is alike):
/// every dynamic evaluation, cold or warm, integrates P - 1 more mesh periods and a
/// run-in (`run_in_periods`) at `period_s` CPU seconds a period
/// (`super::steady_states::period_seconds`), each quasi-static one solves P - 1 more
/// periods, a kept response records P periods instead of
/// `numerics.evaluated_mesh_periods` (with its contacts' path), and each wear record
/// holds every tooth's profile and increment. `(dyn_evals, quasi_evals)`: evaluations;
/// `kept`: responses kept at once; `records`: wear records; `(s_dyn, s)`: steps of a
/// dynamic and a quasi-static mesh period.
pub fn budget_term(
    case: &Case,
    (dyn_evals, quasi_evals): (f64, f64),
    kept: f64,
    records: f64,
    (s_dyn, s): (f64, f64),
    period_s: f64,
) -> Option<Term> {
    if !case.has_per_tooth_inputs() {
        return None;
    }
    let p = excitation_periods_of(case) as f64;
    let extra = (p - 1.0).max(0.0);
    // A train: P and the run-in counted in its base periods (run-in at most P,
    // `dynamics::hunting::run_in_periods`), each costing `train_factor` single-pair mesh
    // periods (in `period_s`); its wear records hold every tooth of each faulty stage.
    let train = !case.stage.is_empty();
    let run_in = if p > 1.0 {
        run_in_periods(case, p)
    } else {
        0.0
    };
    let scale = super::evaluation::train_factor(case);
    // Periods the response records without the fault: a train's in base periods, as P is.
    let p_e =
        super::evaluation::recorded_periods(case, case.numerics.evaluated_mesh_periods as f64);
    // Whole excitation periods: a window of P_e just over P records 2 P
    // (`period_search::window_repeats`), so P ceil(P_e / P), not max(P, P_e).
    let recorded = s_dyn * p * (p_e / p.max(1.0)).ceil().max(1.0);
    let grid = case.wear.points_per_profile as f64;
    if train {
        let (teeth, repeats) = stage_teeth_and_repeats(case);
        let faulty_teeth: f64 = teeth
            .iter()
            .zip(&repeats)
            .filter(|(_, r)| **r > 1)
            .map(|(z, _)| (z[0] + z[1]) as f64)
            .sum();
        return Some(Term {
            what:
                "the tooth fault of a train stage (the faulty gear's teeth over the train's period)",
            // `period_s` is of a base period already (`train_factor` in it).
            seconds: dyn_evals * (extra + run_in) * period_s
                + quasi_evals * s * extra * SECONDS_PER_QUASI_STATIC_STEP * scale,
            bytes: kept
                * (recorded * (RESPONSE_BYTES_PER_SAMPLE + PATH_BYTES_PER_SAMPLE)
                    - s_dyn * p_e * RESPONSE_BYTES_PER_SAMPLE)
                * super::evaluation::train_record_factor(case)
                + records * faulty_teeth * grid * 2.0 * 8.0,
            keys: &[
                "fault.stage",
                "fault.gear",
                "stage.teeth_pinion",
                "stage.teeth_gear",
                "numerics.steps_per_mesh_period",
            ],
        });
    }
    let teeth = (case.gear.teeth_pinion + case.gear.teeth_gear) as f64;
    Some(Term {
        what: "the tooth-resolved mesh (every tooth's own excitation over its period)",
        seconds: dyn_evals * (extra + run_in) * period_s
            + quasi_evals * s * extra * SECONDS_PER_QUASI_STATIC_STEP,
        bytes: kept
            * (recorded * (RESPONSE_BYTES_PER_SAMPLE + PATH_BYTES_PER_SAMPLE)
                - s_dyn * p_e * RESPONSE_BYTES_PER_SAMPLE)
            + records * teeth * grid * 2.0 * 8.0,
        keys: &[
            "teeth.pitch_error_pinion_um",
            "teeth.pitch_error_gear_um",
            "teeth.accuracy_grade",
            "teeth.runout_pinion_um",
            "teeth.runout_gear_um",
            "fault.tooth",
            "numerics.steps_per_mesh_period",
        ],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::budget::{estimate, Budget, Job};

    /// The paper's gear's 31 pitch errors, all zero.
    const GEAR_PITCH_ZEROS: &str = "teeth.pitch_error_gear_um=[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]";

    fn case(sets: &[&str]) -> Case {
        crate::config::load::default_with(sets)
    }

    #[test]
    fn excitation_periods_follow_the_inputs_and_the_model() {
        for (sets, want) in [
            (vec![], 1),
            (
                vec![
                    "modification.tip_relief_um=5",
                    "modification.tip_relief_length_mm=1",
                ],
                1,
            ),
            (vec!["teeth.runout_gear_um=3"], 31),
            (vec!["teeth.accuracy_grade=5"], 589),
            // The grade draws only what a gear does not give: the gear's three arrays
            // given alike leave the pinion's 19 teeth the only ones that differ.
            (
                vec![
                    "teeth.accuracy_grade=6",
                    GEAR_PITCH_ZEROS,
                    "teeth.profile_slope_gear_um=[0.0]",
                    "teeth.profile_form_gear_um=[0.0]",
                ],
                19,
            ),
            // Two of the three given: the third is still drawn.
            (
                vec![
                    "teeth.accuracy_grade=6",
                    "teeth.profile_slope_gear_um=[0.0]",
                    "teeth.profile_form_gear_um=[0.0]",
                ],
                589,
            ),
            (
                vec![
                    "fault.kind=crack",
                    "fault.gear=pinion",
                    "fault.tooth=3",
                    "fault.crack_depth_mm=1",
                ],
                19,
            ),
        ] {
            let c = case(&sets);
            assert_eq!(excitation_periods_of(&c), want, "{sets:?}");
            let m = crate::study::Model::from_case(&c).unwrap();
            let p = m.tooth_mesh(&m.new_wear_state()).map_or(1, |t| t.periods());
            assert_eq!(p, want, "model, {sets:?}");
        }
    }

    #[test]
    fn the_budget_counts_the_excitation_period() {
        // The paper's pair with every tooth drawn (589 periods) fits the default budget;
        // a 97/101 pair (9797 periods) does not, and the message names the teeth keys.
        let g5 = case(&["teeth.accuracy_grade=5"]);
        assert!(estimate(&g5, Job::Run).check(&Budget::DEFAULT).is_ok());
        let plain = estimate(&case(&[]), Job::Dynamics).memory_bytes();
        assert!(
            estimate(&g5, Job::Dynamics).memory_bytes()
                > 50.0 * (plain - crate::study::budget::cost::BASE_BYTES)
        );
        let big = case(&[
            "teeth.accuracy_grade=5",
            "gear.teeth_pinion=97",
            "gear.teeth_gear=101",
            "gear.module_mm=1",
        ]);
        assert_eq!(excitation_periods_of(&big), 9797);
        let e = estimate(&big, Job::Run)
            .check(&Budget::DEFAULT)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("tooth-resolved") && e.contains("teeth.accuracy_grade"),
            "{e}"
        );
    }
}
