//! One case of a sweep: build the model, run it, reduce it to the headline numbers of a
//! sweep row (the record it leaves on disk is [`super::case_record`]).

use super::helical_row::{helical_columns, HelicalRow};
use super::mesh_row::{MeshRow, MeshWear, TrainWearEnd, MESH_COLUMNS};
use super::planetary_row::{
    planetary_columns, run_planetary_dynamics, PlanetaryRow, PlanetaryRunError,
};
use super::planetary_wear_row::{planetary_wear_row, run_planetary_wear_modes, PlanetaryWearRow};
pub use super::row::{DynamicsRow, SweepRun, WearEnd};
use super::row::{DYNAMICS_COLUMNS, WEAR_COLUMNS};
use crate::config::Case;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::summary::ResponseSummary;
use crate::study::model::{Model, ModelError};
use crate::study::train::TrainModel;
use crate::study::train_wear::{run_train_wear, TrainWearRun};
use crate::study::wear_loop::{run_wear, StopKind, WearMode, WearRun, WearStop};
use crate::wear::WearState;

/// The results of one sweep case: a row of the sweep table after its varied values.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResults {
    /// The new teeth's response (of the dynamic wear run's first update for a wear row;
    /// of the first mesh of a train).
    pub dynamics: DynamicsRow,
    /// The ends of the dynamic and quasi-static wear runs (a `wear` sweep).
    pub wear: Option<[WearEnd; 2]>,
    /// Each mesh of a gear train, stage by stage (of the new teeth); empty for a single
    /// pair.
    pub meshes: Vec<MeshRow>,
    /// Each mesh's wear at the end of the runs (a `wear` sweep of a gear train).
    pub train_wear: Option<TrainWearEnd>,
    /// What a helical pair adds (`super::helical_row`); also the empty columns of a spur
    /// case in a table that has them.
    pub helical: Option<HelicalRow>,
    /// Each mesh's force and each planet's load sharing (a sweep of a planetary set,
    /// [`super::planetary_row`]), and in a `wear` sweep every member flank's wear
    /// ([`super::planetary_wear_row`]).
    pub planetary: Option<PlanetaryRow>,
}

impl CaseResults {
    /// What the case ran.
    pub fn run(&self) -> SweepRun {
        if self.wear.is_some() {
            SweepRun::Wear
        } else {
            SweepRun::Dynamics
        }
    }

    /// The pair's columns at the front of a row's numbers `v` (at least the run's own):
    /// the dynamics row, and for a wear run each mode's wear end (dynamic, quasi-static).
    fn pair_values(run: SweepRun, v: &[f64]) -> (DynamicsRow, Option<[WearEnd; 2]>) {
        let (d, w) = (DYNAMICS_COLUMNS.len(), WEAR_COLUMNS.len() / 2);
        let wear = (run == SweepRun::Wear).then(|| {
            [
                WearEnd::from_values(&v[d..d + w]),
                WearEnd::from_values(&v[d + w..d + 2 * w]),
            ]
        });
        (DynamicsRow::from_values(&v[..d]), wear)
    }

    /// A planetary set's dynamics row: the pair's columns `dynamics`, then the set's.
    pub fn with_planetary(dynamics: DynamicsRow, row: PlanetaryRow) -> Self {
        Self {
            dynamics,
            wear: None,
            meshes: Vec::new(),
            train_wear: None,
            helical: None,
            planetary: Some(row),
        }
    }

    /// A planetary set's wear row ([`super::planetary_wear_row`]).
    pub fn with_planetary_wear(row: PlanetaryWearRow) -> Self {
        Self {
            wear: Some(row.wear),
            ..Self::with_planetary(row.dynamics, row.set)
        }
    }

    /// The names of [`CaseResults::values`]: the run's columns, then each mesh's (a
    /// train's), a helical pair's or the set's (a planetary set's).
    pub fn columns(&self) -> Vec<String> {
        let mut c = self.run().columns_for(self.meshes.len());
        if self.helical.is_some() {
            c.extend(helical_columns(self.wear.is_some()));
        }
        if let Some(p) = &self.planetary {
            c.extend(planetary_columns(p.planets(), p.has_wear()));
        }
        c
    }

    /// The same results with a helical pair's columns when `helical` (empty for a spur
    /// case, [`HelicalRow::empty`]): a row of a table that has them.
    pub fn with_helical_columns(mut self, helical: bool) -> Self {
        if helical && self.helical.is_none() {
            self.helical = Some(HelicalRow::empty(self.wear.is_some()));
        }
        self
    }

    /// The numbers in [`CaseResults::columns`] order.
    pub fn values(&self) -> Vec<f64> {
        let mut v = self.dynamics.values().to_vec();
        for w in self.wear.iter().flatten() {
            v.extend(w.values());
        }
        for m in &self.meshes {
            v.extend(m.values());
        }
        if let Some(t) = &self.train_wear {
            v.extend(t.values());
        }
        if let Some(h) = &self.helical {
            v.extend(h.values());
        }
        if let Some(p) = &self.planetary {
            v.extend(p.values());
        }
        v
    }

    /// From numbers in the column order of `run` with `stages` train meshes and a set of
    /// `planets` planets (0: none; only a row of a single set has them, with the flanks'
    /// wear in a wear row); `None` when their count is not it.
    pub fn from_values_of(run: SweepRun, stages: usize, planets: usize, v: &[f64]) -> Option<Self> {
        if planets == 0 {
            return Self::from_values(run, stages, v);
        }
        let own = run.columns().len();
        if stages != 0 || v.len() < own {
            return None;
        }
        let wear = run == SweepRun::Wear;
        let row = PlanetaryRow::from_values(planets, wear, &v[own..])?;
        let (dynamics, wear_ends) = Self::pair_values(run, v);
        let mut r = Self::with_planetary(dynamics, row);
        r.wear = wear_ends;
        Some(r)
    }

    /// From numbers in the column order of `run` with `stages` train meshes (0: a single
    /// pair; a single pair's numbers with [`helical_columns`]' more are a helical pair's
    /// row); `None` when their count is not it.
    pub fn from_values(run: SweepRun, stages: usize, v: &[f64]) -> Option<Self> {
        let own = run.columns().len();
        let meshes_end = own + stages * MESH_COLUMNS.len();
        let plain = run.columns_for(stages).len();
        let wear = run == SweepRun::Wear;
        if stages == 0 && v.len() == plain + helical_columns(wear).len() {
            let mut r = Self::from_values(run, 0, &v[..plain])?;
            r.helical = Some(HelicalRow::from_values(wear, &v[plain..])?);
            return Some(r);
        }
        if v.len() != plain {
            return None;
        }
        let train_wear = match (run, stages) {
            (SweepRun::Wear, 1..) => Some(TrainWearEnd::from_values(stages, &v[meshes_end..])?),
            _ => None,
        };
        let (dynamics, wear) = Self::pair_values(run, v);
        Some(Self {
            dynamics,
            wear,
            meshes: v[own..meshes_end]
                .chunks_exact(MESH_COLUMNS.len())
                .map(MeshRow::from_values)
                .collect(),
            train_wear,
            helical: None,
            planetary: None,
        })
    }

    /// The number of column `name`, if the row has it.
    pub fn get(&self, name: &str) -> Option<f64> {
        let i = self.columns().iter().position(|c| c == name)?;
        self.values().get(i).copied()
    }

    /// Whether both rows hold the same numbers, bit for bit (NaN equal to NaN).
    pub fn same_as(&self, o: &CaseResults) -> bool {
        let (a, b) = (self.values(), o.values());
        a.len() == b.len()
            && a.iter()
                .zip(&b)
                .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()))
    }
}

/// Why a case produced no row.
#[derive(Debug)]
pub enum CaseError {
    /// The case cannot be modelled (geometry, settings): an input problem.
    Model(ModelError),
    /// A solver failed.
    Solve(anyhow::Error),
}

impl std::fmt::Display for CaseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CaseError::Model(e) => write!(f, "{e}"),
            CaseError::Solve(e) => write!(f, "{e:#}"),
        }
    }
}

/// Results of one case and the model's warnings.
pub struct CaseOutcome {
    /// The case's results.
    pub results: CaseResults,
    /// The model's warnings (non-fatal findings).
    pub warnings: Vec<String>,
}

/// A planetary set's dynamics row: the set's columns, and the pair's with the first
/// sun-planet mesh's forces (the set's summary has no DTE or pinion velocity: empty).
fn planetary_outcome(case: &Case) -> Result<CaseOutcome, CaseError> {
    let (row, warnings) = run_planetary_dynamics(case).map_err(|e| match e {
        PlanetaryRunError::Model(m) => CaseError::Model(m),
        PlanetaryRunError::Solve(s) => CaseError::Solve(s),
    })?;
    let mut pair = [f64::NAN; 9];
    pair[2..5].copy_from_slice(&row.meshes[0]);
    Ok(CaseOutcome {
        results: CaseResults::with_planetary(DynamicsRow::from_values(&pair), row),
        warnings,
    })
}

/// A planetary set's wear row ([`super::planetary_wear_row`]): its wear study in both
/// modes, as `gearwear wear` runs it, with the model's warnings.
fn planetary_wear_outcome(case: &Case) -> Result<CaseOutcome, CaseError> {
    let (model, [d, q]) = run_planetary_wear_modes(case).map_err(|e| match e {
        PlanetaryRunError::Model(m) => CaseError::Model(m),
        PlanetaryRunError::Solve(s) => CaseError::Solve(s),
    })?;
    for r in [&d, &q] {
        numerical_stop(r.mode, r.stopped.as_ref())?;
    }
    Ok(CaseOutcome {
        results: CaseResults::with_planetary_wear(planetary_wear_row(&model, &d, &q)),
        warnings: model.dynamics.study.warnings.clone(),
    })
}

/// Build the model of `case` and run it.
pub fn run_case(case: &Case, run: SweepRun) -> Result<CaseOutcome, CaseError> {
    if case.planetary.is_some() {
        return match run {
            SweepRun::Dynamics => planetary_outcome(case),
            SweepRun::Wear => planetary_wear_outcome(case),
        };
    }
    match run {
        SweepRun::Dynamics => run_dynamics_from(case, None).map(|(o, _)| o),
        SweepRun::Wear => {
            // A train's wear takes spur stages only (`Model::from_case` refuses a
            // helical stage, naming its key); a single helical pair wears per slice.
            // On a spur pair the tilting keys are ignored with a warning, as everywhere.
            crate::study::helical_teeth::refuse_for_wear_if_helical(case, "a wear sweep")
                .map_err(CaseError::Model)?;
            let build = if case.stage.is_empty() {
                Model::dynamics_from_case
            } else {
                Model::from_case
            };
            let model = build(case).map_err(CaseError::Model)?;
            if let Some(train) = &model.train {
                let results = run_train_wear_case(&model, train)?;
                return Ok(CaseOutcome {
                    results,
                    warnings: model.warnings,
                });
            }
            let one = |mode| run_wear(&model, WearRun::new(mode), &mut |_| Ok(()));
            let (d, q) = rayon::join(|| one(WearMode::Dynamic), || one(WearMode::QuasiStatic));
            let (d, q) = (d.map_err(CaseError::Solve)?, q.map_err(CaseError::Solve)?);
            for r in [&d, &q] {
                numerical_stop(r.mode, r.stopped.as_ref())?;
            }
            let mut results = wear_results(&d, &q);
            results.helical = helical_wear_row(&model, &d, &q)?;
            let mut warnings = model.warnings.clone();
            // On axial bearings: its axial shift with new teeth (docs/MODEL.md 11.6).
            warnings.extend(crate::study::helical_dynamics::new_teeth_axial_shift_warning(&model));
            Ok(CaseOutcome { results, warnings })
        }
    }
}

/// The helical columns of a wear row (None for a spur pair): the new teeth's as the
/// dynamic run's first update has them (its mean mesh force), with the dynamic face load
/// of one more steady state of the new teeth when the pair has lead gaps (the wear records
/// keep no slice loads; the same solve as `gearwear dynamics`), then the wear maps.
pub(crate) fn helical_wear_row(
    model: &Model,
    d: &WearRun,
    q: &WearRun,
) -> Result<Option<HelicalRow>, CaseError> {
    let Some(h) = &model.helical else {
        return Ok(None);
    };
    let mean_force = d
        .records
        .first()
        .map_or(f64::NAN, |r| r.summary.mesh_force_mean_n);
    let face = match h.lead {
        Some(_) => {
            let r = model
                .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
                .map_err(|e| CaseError::Solve(e.into()))?;
            crate::study::face_load_dynamic::DynamicFaceLoad::of(model, &r, &ExternalError::none())
        }
        None => None,
    };
    Ok(HelicalRow::of_dynamics(model, mean_force, face.as_ref())
        .map(|r| r.with_wear_maps(model, d, q)))
}

/// A run the solver gave up on is a failed case; one that left the model's domain is a
/// result (its cycles column says where it stopped).
pub(crate) fn numerical_stop(mode: WearMode, stop: Option<&WearStop>) -> Result<(), CaseError> {
    match stop.filter(|s| s.kind == StopKind::Numerical) {
        Some(stop) => Err(CaseError::Solve(anyhow::anyhow!(
            "the {} wear run stopped early: {}",
            mode.name(),
            stop.reason
        ))),
        None => Ok(()),
    }
}

/// The wear study of a gear train in both modes (as `gearwear wear --mode both` on it,
/// `study::train_wear`), reduced to a row: the pair's columns are its first mesh's (the
/// new teeth's response of the dynamic run's first update; its end of each run, with
/// the run's updates and input cycles), then each mesh's new-teeth columns, each mesh's
/// wear at the end, and the stage that limits each mode's life.
fn run_train_wear_case(model: &Model, train: &TrainModel) -> Result<CaseResults, CaseError> {
    let one = |mode| run_train_wear(model, train, TrainWearRun::new(mode), &mut |_| Ok(()));
    let (d, q) = rayon::join(|| one(WearMode::Dynamic), || one(WearMode::QuasiStatic));
    let (d, q) = (d.map_err(CaseError::Solve)?, q.map_err(CaseError::Solve)?);
    for r in [&d, &q] {
        numerical_stop(r.mode, r.stopped.as_ref())?;
    }
    let first = d.updates.first();
    let dynamics = first.map_or(DynamicsRow::from_values(&[f64::NAN; 9]), |u| {
        DynamicsRow::of(&u.meshes[0].summary)
    });
    let freq = |m: usize| train.operating.meshes[m].mesh_frequency_hz;
    let meshes = (0..train.stages.len())
        .map(|m| match first {
            Some(u) => MeshRow::of(&u.meshes[m].summary, freq(m)),
            None => MeshRow::from_values(&[freq(m), f64::NAN, f64::NAN, f64::NAN, f64::NAN]),
        })
        .collect();
    // Flank depths of mesh m at the run's end, um (NaN without a record).
    let depths = |r: &TrainWearRun, m: usize| {
        r.updates.last().map_or([f64::NAN; 2], |u| {
            let w = &u.meshes[m].wear;
            [w.max_pinion_m() * 1e6, w.max_gear_m() * 1e6]
        })
    };
    let end = |r: &TrainWearRun| WearEnd {
        max_wear_pinion_um: depths(r, 0)[0],
        max_wear_gear_um: depths(r, 0)[1],
        updates: r.updates.len().saturating_sub(1) as f64,
        cycles: r.updates.last().map_or(f64::NAN, |u| u.input_cycles),
    };
    let limiting = |r: &TrainWearRun| r.limiting_mesh().map_or(f64::NAN, |(m, _)| (m + 1) as f64);
    Ok(CaseResults {
        dynamics,
        wear: Some([end(&d), end(&q)]),
        meshes,
        planetary: None,
        train_wear: Some(TrainWearEnd {
            meshes: (0..train.stages.len())
                .map(|m| MeshWear {
                    dynamic_um: depths(&d, m),
                    quasi_static_um: depths(&q, m),
                })
                .collect(),
            limiting_stage: [limiting(&d), limiting(&q)],
        }),
        helical: None,
    })
}

/// One steady-state evaluation of `case` with new teeth (a dynamics row), started
/// from `start` (a periodic state of a neighbouring case, [`DynamicResponse::end_state`])
/// or, with `None`, from the static equilibrium; also returns the end state.
///
/// [`DynamicResponse::end_state`]: crate::dynamics::response::DynamicResponse::end_state
pub fn run_dynamics_from(
    case: &Case,
    start: Option<&[f64]>,
) -> Result<(CaseOutcome, Vec<f64>), CaseError> {
    let model = Model::dynamics_from_case(case).map_err(CaseError::Model)?;
    let wear = WearState::new(model.grid.len());
    let r = model
        .dynamic_from(&wear, &ExternalError::none(), start)
        .map_err(|e| CaseError::Solve(e.into()))?;
    let results = match &model.train {
        // A train: the first mesh's summary as the pair's columns (as the top level of
        // `gearwear dynamics`' summary.json), then every mesh's columns.
        Some(t) => {
            let s: Vec<ResponseSummary> = (0..t.operating.meshes.len())
                .map(|m| t.mesh_summary(&r, m))
                .collect();
            let f = t.operating.meshes.iter().map(|p| p.mesh_frequency_hz);
            CaseResults {
                dynamics: DynamicsRow::of(&s[0]),
                wear: None,
                meshes: s.iter().zip(f).map(|(s, f)| MeshRow::of(s, f)).collect(),
                train_wear: None,
                helical: None,
                planetary: None,
            }
        }
        None => CaseResults {
            dynamics: DynamicsRow::of(&ResponseSummary::of(&r)),
            wear: None,
            meshes: Vec::new(),
            train_wear: None,
            helical: HelicalRow::of_response(&model, &r),
            planetary: None,
        },
    };
    let mut warnings = model.warnings.clone();
    warnings.extend(crate::study::helical_dynamics::axial_shift_warning(
        &model, &r,
    ));
    let outcome = CaseOutcome { results, warnings };
    Ok((outcome, r.end_state))
}

/// Dynamics columns of the dynamic run's first update (new teeth), then the wear columns.
pub fn wear_results(d: &WearRun, q: &WearRun) -> CaseResults {
    let dynamics = d
        .records
        .first()
        .map_or(DynamicsRow::from_values(&[f64::NAN; 9]), |r| {
            DynamicsRow::of(&r.summary)
        });
    CaseResults {
        dynamics,
        wear: Some([WearEnd::of(d), WearEnd::of(q)]),
        meshes: Vec::new(),
        train_wear: None,
        helical: None,
        planetary: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_match_results() {
        let s = ResponseSummary {
            dte_max_m: 2e-5,
            velocity_y_pinion_harmonics_m_per_s: [1e-3, 2e-3, 3e-3, 4e-3],
            ..Default::default()
        };
        let r = CaseResults {
            dynamics: DynamicsRow::of(&s),
            wear: None,
            meshes: Vec::new(),
            train_wear: None,
            helical: None,
            planetary: None,
        };
        let v = r.values();
        assert_eq!(v.len(), SweepRun::Dynamics.columns().len());
        // 2e-5 m is 20 um; 4e-3 m/s is 4 mm/s (to rounding of the unit factors).
        assert!((v[0] - 20.0).abs() < 1e-12 && (v[8] - 4.0).abs() < 1e-12);
        assert_eq!(r.get("mesh_harmonic4_mm_per_s"), Some(v[8]));
        assert_eq!(
            CaseResults::from_values(SweepRun::Dynamics, 0, &v),
            Some(r.clone())
        );
        let (d, q) = (
            WearRun::new(WearMode::Dynamic),
            WearRun::new(WearMode::QuasiStatic),
        );
        let w = wear_results(&d, &q);
        assert_eq!(SweepRun::Wear.columns().len(), w.values().len());
        assert_eq!(w.run(), SweepRun::Wear);
        assert!(CaseResults::from_values(SweepRun::Wear, 0, &w.values())
            .unwrap()
            .same_as(&w));
        assert_eq!(
            SweepRun::of_columns(&SweepRun::Wear.columns()),
            Some((SweepRun::Wear, 0))
        );
        // A train's row: the pair's columns, then two meshes' sets; read back exactly.
        let t = CaseResults {
            meshes: vec![MeshRow::of(&s, 570.0), MeshRow::of(&s, 423.0)],
            ..r
        };
        let cols = t.columns();
        assert_eq!(cols.len(), 9 + 2 * MESH_COLUMNS.len());
        assert_eq!(SweepRun::of_columns(&cols), Some((SweepRun::Dynamics, 2)));
        assert_eq!(t.get("stage2_mesh_frequency_hz"), Some(423.0));
        assert_eq!(
            CaseResults::from_values(SweepRun::Dynamics, 2, &t.values()),
            Some(t.clone())
        );
        // A train's wear row: the wear columns, two meshes' sets, then each mesh's four
        // wear columns and the two limiting stages (9 + 8 + 2 x 5 + 2 x 4 + 2 = 37).
        let mut tw = CaseResults {
            wear: w.wear,
            planetary: None,
            train_wear: Some(TrainWearEnd {
                meshes: vec![
                    MeshWear::from_values(&[1.0, 2.0, 3.0, 4.0]),
                    MeshWear::from_values(&[5.0, 6.0, 7.0, 8.0]),
                ],
                limiting_stage: [2.0, 1.0],
            }),
            ..t
        };
        let cols = tw.columns();
        assert_eq!(cols.len(), 37);
        assert_eq!(tw.values().len(), 37);
        assert_eq!(SweepRun::of_columns(&cols), Some((SweepRun::Wear, 2)));
        assert_eq!(tw.get("stage2_wear_max_gear_dynamic_um"), Some(6.0));
        assert_eq!(tw.get("stage1_wear_max_gear_quasi_static_um"), Some(4.0));
        assert_eq!(tw.get("wear_limiting_stage_quasi_static"), Some(1.0));
        assert!(CaseResults::from_values(SweepRun::Wear, 2, &tw.values())
            .unwrap()
            .same_as(&tw));
        // Without its wear columns the row is no train wear row.
        assert_eq!(SweepRun::of_columns(&cols[..27]), None);
        tw.train_wear = None;
        assert_eq!(
            CaseResults::from_values(SweepRun::Wear, 2, &tw.values()),
            None
        );
    }
}
