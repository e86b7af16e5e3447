//! The studies of a duty cycle: the wear study under the spectrum in both modes (what
//! `wear` computes), and with it the paper's section 4 read at the monitoring bin and the
//! life table (what `run` computes).

use super::contribution::combined_run;
use super::life::{life_table, LifeTable};
use super::model::SpectrumModel;
use super::wear::{run_spectrum_modes, SpectrumRun};
use crate::config::Case;
use crate::study::paper::{paper_wear_states, PaperStudy};
use crate::study::sweep::{wear_results, CaseError, CaseOutcome, SweepRun};
use crate::study::wear_loop::WearMode;

/// Life runs stop here at the latest: 1e15 pinion revolutions are 30 000 years at 1 kHz,
/// beyond any machine's life, so a bin that has not worn to the limit by then never will.
pub(crate) const LIFE_CYCLE_CAP: f64 = 1e15;

/// The wear study under the spectrum and what `run` adds to it.
pub struct DutyStudy {
    /// The spectrum runs, in the order of the modes asked for.
    pub runs: Vec<SpectrumRun>,
    /// The paper's section 4 on the spectrum runs, responses at the monitoring bin.
    pub paper: Option<PaperStudy>,
    /// Lives to `load_spectrum.life_wear_limit_um` (dynamic), under the spectrum and at
    /// each bin alone.
    pub life: Option<LifeTable>,
}

impl DutyStudy {
    /// The spectrum run of wear mode `mode`, if it was asked for.
    pub fn run(&self, mode: WearMode) -> Option<&SpectrumRun> {
        self.runs.iter().find(|r| r.mode == mode)
    }
}

/// `run` under a spectrum: the dynamic and quasi-static spectrum runs in parallel
/// (continuing `starts`), then the wear states of section 4.1 on the dynamic run's
/// profile at the monitoring bin, and the life table.
pub fn run_duty_study(
    sm: &SpectrumModel,
    starts: Vec<SpectrumRun>,
    on_update: &(dyn Fn(WearMode, &SpectrumRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<DutyStudy> {
    let runs = run_spectrum_modes(sm, starts, on_update)?;
    let (Some(d), Some(q)) = (
        runs.iter().find(|r| r.mode == WearMode::Dynamic),
        runs.iter().find(|r| r.mode == WearMode::QuasiStatic),
    ) else {
        anyhow::bail!("the duty-cycle study needs a dynamic and a quasi-static run");
    };
    let (d, q) = (
        combined_run(d, sm.monitoring),
        combined_run(q, sm.monitoring),
    );
    let monitor = &sm.bins[sm.monitoring];
    let wear_states = paper_wear_states(monitor, &d)?;
    let life = spectrum_life(sm, WearMode::Dynamic)?;
    Ok(DutyStudy {
        runs,
        paper: Some(PaperStudy {
            dynamic: d,
            quasi_static: q,
            wear_states,
        }),
        life: Some(life),
    })
}

/// The life table of `sm`'s case in `mode`: runs to `load_spectrum.life_wear_limit_um`
/// under the spectrum and at each bin alone (capped at `LIFE_CYCLE_CAP`); what `run`
/// and `wear` both report.
pub fn spectrum_life(sm: &SpectrumModel, mode: WearMode) -> anyhow::Result<LifeTable> {
    let limit = sm
        .case
        .load_spectrum
        .as_ref()
        .map_or(10.0, |s| s.life_wear_limit_um);
    life_table(&sm.case, mode, limit, LIFE_CYCLE_CAP).map_err(|e| anyhow::anyhow!("{e}"))
}

/// A case of a sweep: under the case's spectrum when it has one and the sweep runs wear
/// studies (so `load_spectrum.torque_scale` and `speed_scale` are sweep axes), else the
/// single-point case ([`crate::study::sweep::run_case`]). The row is read as the
/// spectrum's single-point view: the dynamics columns are the monitoring bin's new-teeth
/// response, the wear columns those of the shared wear state.
pub(crate) fn run_sweep_case(case: &Case, run: SweepRun) -> Result<CaseOutcome, CaseError> {
    if run != SweepRun::Wear || case.load_spectrum.is_none() {
        return crate::study::sweep::run_case(case, run);
    }
    if case.planetary.is_some() {
        return planetary_sweep_case(case);
    }
    let sm = SpectrumModel::dynamics_from_case(case).map_err(CaseError::Model)?;
    let starts = vec![
        SpectrumRun::new(WearMode::Dynamic, sm.shares.clone()),
        SpectrumRun::new(WearMode::QuasiStatic, sm.shares.clone()),
    ];
    let runs = run_spectrum_modes(&sm, starts, &|_, _| Ok(())).map_err(CaseError::Solve)?;
    // A run the solver gave up on is a failed case; one that left the model's domain is a
    // result (its cycles column says where it stopped), as for one operating point.
    for r in &runs {
        crate::study::sweep::case_run::numerical_stop(r.mode, r.stopped.as_ref())?;
    }
    let (d, q) = (
        combined_run(&runs[0], sm.monitoring),
        combined_run(&runs[1], sm.monitoring),
    );
    let mut results = wear_results(&d, &q);
    // A helical pair's columns: the monitoring bin's new teeth and the spectrum's wear
    // maps (docs/MODEL.md 11.7); its axial shift at every bin.
    let monitor = &sm.bins[sm.monitoring];
    results.helical = crate::study::sweep::case_run::helical_wear_row(monitor, &d, &q)?;
    let mut warnings = sm.warnings();
    warnings.extend(sm.axial_shift_warnings());
    Ok(CaseOutcome { results, warnings })
}

/// A wear sweep's case of a planetary set under its spectrum: the spectrum's loop of the
/// set (`super::planetary`, as `gearwear wear` runs it) in both modes, each read as one
/// run of the set at the monitoring bin (`combined_planetary_run`), reduced to the set's
/// wear row (`study::sweep::planetary_wear_row`; docs/MODEL.md 12.17).
fn planetary_sweep_case(case: &Case) -> Result<CaseOutcome, CaseError> {
    use super::planetary::{
        combined_planetary_run, run_planetary_spectrum_modes, PlanetarySpectrum,
        PlanetarySpectrumRun,
    };
    use crate::study::sweep::planetary_wear_row::planetary_wear_row;
    let ps = PlanetarySpectrum::from_case(case).map_err(CaseError::Model)?;
    // Every bin's set must have a quasi-static equilibrium (`gearwear wear` runs both
    // modes at every bin), refused before any bin runs.
    let problems: Vec<String> = ps
        .models
        .iter()
        .filter_map(|m| m.quasi_static_problem())
        .collect();
    if !problems.is_empty() {
        return Err(CaseError::Model(crate::study::ModelError(problems)));
    }
    let starts = [WearMode::Dynamic, WearMode::QuasiStatic]
        .map(|m| PlanetarySpectrumRun::new(m, ps.shares.clone()))
        .to_vec();
    let runs =
        run_planetary_spectrum_modes(&ps, starts, &|_, _| Ok(())).map_err(CaseError::Solve)?;
    for r in &runs {
        crate::study::sweep::case_run::numerical_stop(r.mode, r.stopped.as_ref())?;
    }
    let (d, q) = (
        combined_planetary_run(&runs[0], ps.monitoring),
        combined_planetary_run(&runs[1], ps.monitoring),
    );
    let row = planetary_wear_row(ps.reference(), &d, &q);
    // Every bin's warnings, each once (as `gearwear wear` under the spectrum prints them).
    let mut warnings: Vec<String> = Vec::new();
    for w in ps.models.iter().flat_map(|m| &m.dynamics.study.warnings) {
        if !warnings.contains(w) {
            warnings.push(w.clone());
        }
    }
    Ok(CaseOutcome {
        results: crate::study::sweep::CaseResults::with_planetary_wear(row),
        warnings,
    })
}
