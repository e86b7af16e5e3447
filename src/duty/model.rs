//! The models of a spectrum: one per bin, each the case at the bin's operating point.
//!
//! A bin differs from the case only in its torque, speed and torque shaft
//! (`Case::at_bin`), so every check a case gets (the Hertz pressure the flanks can carry,
//! Xu's friction range, Sainsot's fit) is made for every bin, and a bin equal to the
//! operating point gives the model of the case itself, bit for bit. The bins' models are
//! built in parallel, and all of them before anything is solved: one bad bin refuses the
//! whole spectrum, naming the bin.

use crate::config::{Case, LoadSpectrumSection, SpectrumBin};
use crate::study::model::{Model, ModelError};
use crate::wear::ToothWear;
use rayon::prelude::*;

/// The models of every bin of a case's spectrum and the bins' shares of the cycles.
pub struct SpectrumModel {
    /// The case with its spectrum (or without: one bin, the operating point).
    pub case: Case,
    /// One model per bin, in the spectrum's order.
    pub bins: Vec<Model>,
    /// Share of the load cycles of each bin (sum 1).
    pub shares: Vec<f64>,
    /// Bin at which vibration is observed (0-based).
    pub monitoring: usize,
}

/// A bin in words, for messages: "load_spectrum bin 3 (80 N m, 45 Hz)".
pub(crate) fn bin_label(case: &Case, i: usize) -> String {
    let c = case.at_bin(i);
    format!(
        "load_spectrum bin {} ({} N m, {} Hz)",
        i + 1,
        crate::format::shown(c.operating.load_torque_nm),
        crate::format::shown(c.operating.input_speed_hz)
    )
}

/// A message about bin `i`'s model in the bin's words: the keys of `[operating]` that the
/// bin sets (`Case::at_bin`: the torque and the input speed) are the bin's `torque_nm` and
/// `input_speed_hz`, so the message names those instead.
pub(crate) fn in_bin_words(message: &str) -> String {
    message
        .replace("`operating.load_torque_nm`", "the bin's `torque_nm`")
        .replace("`operating.input_speed_hz`", "the bin's `input_speed_hz`")
}

impl SpectrumModel {
    /// The models of `case`'s bins; a case without a spectrum is one bin of share 1 at its
    /// operating point. Every bin's problems are collected, each naming its bin. Each bin
    /// is `Model::from_case` (a spur pair or a train; a helical case is refused, as the
    /// studies on that constructor refuse it).
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        Self::built_by(case, Model::from_case)
    }

    /// As [`SpectrumModel::from_case`], a single helical pair's bins on its planar model
    /// with its wear per slice (`Model::dynamics_from_case`, docs/MODEL.md 11.7): what
    /// `wear`, `run` and the wear sweeps run. A spur pair or a train is built exactly as
    /// [`SpectrumModel::from_case`] builds it (a helical train keeps that refusal).
    pub fn dynamics_from_case(case: &Case) -> Result<Self, ModelError> {
        // On a spur pair the tilting keys are ignored with a warning, as everywhere (a
        // train refuses them in its own model).
        crate::study::helical_teeth::refuse_for_wear_if_helical(case, "a `[load_spectrum]`")?;
        if case.stage.is_empty() {
            Self::built_by(case, Model::dynamics_from_case)
        } else {
            Self::from_case(case)
        }
    }

    /// The models of `case`'s bins, each built by `build`.
    fn built_by(
        case: &Case,
        build: fn(&Case) -> Result<Model, ModelError>,
    ) -> Result<Self, ModelError> {
        let Some(spectrum) = case.load_spectrum.as_ref() else {
            return Ok(Self {
                case: case.clone(),
                bins: vec![build(case)?],
                shares: vec![1.0],
                monitoring: 0,
            });
        };
        let bins = models_of_bins(case, spectrum.bins.len(), build)?;
        Ok(Self {
            case: case.clone(),
            bins,
            shares: spectrum.bins.iter().map(|b| b.share).collect(),
            monitoring: spectrum.monitoring_index(),
        })
    }

    /// Number of bins.
    pub fn len(&self) -> usize {
        self.bins.len()
    }

    /// Whether the spectrum has no bins (never, for a model built from a case).
    pub fn is_empty(&self) -> bool {
        self.bins.is_empty()
    }

    /// The warnings of every bin, each once (bins share most of them).
    pub fn warnings(&self) -> Vec<String> {
        let mut w: Vec<String> = Vec::new();
        for m in &self.bins {
            for x in &m.warnings {
                if !w.contains(x) {
                    w.push(x.clone());
                }
            }
        }
        w
    }

    /// The axial-shift warning of every bin whose helical pair moves axially by more than
    /// `helical_dynamics::AXIAL_SHIFT_WARNING_SHARE` of the face width with new teeth
    /// (`helical_dynamics::new_teeth_axial_shift_warning`, the bins in parallel), each
    /// naming its bin; none for a spur pair or rigid axial bearings (nothing is solved).
    pub fn axial_shift_warnings(&self) -> Vec<String> {
        use crate::study::helical_dynamics::new_teeth_axial_shift_warning;
        let w: Vec<Option<String>> = self
            .bins
            .par_iter()
            .map(new_teeth_axial_shift_warning)
            .collect();
        w.into_iter()
            .enumerate()
            .filter_map(|(i, w)| match self.case.load_spectrum {
                Some(_) => w.map(|w| format!("{}: {w}", self.label(i))),
                None => w,
            })
            .collect()
    }

    /// The spectrum as used: the case's, or one bin at its operating point.
    pub fn spectrum(&self) -> LoadSpectrumSection {
        self.case.load_spectrum.clone().unwrap_or_else(|| {
            let o = &self.case.operating;
            let mut s = LoadSpectrumSection::of_bins(vec![SpectrumBin {
                torque_nm: o.load_torque_nm,
                input_speed_hz: o.input_speed_hz,
                share: 1.0,
            }]);
            s.torque_shaft = Some(o.load_torque_shaft);
            s
        })
    }

    /// Label of bin `i` for messages.
    pub fn label(&self, i: usize) -> String {
        if self.case.load_spectrum.is_none() {
            return "the operating point".into();
        }
        bin_label(&self.case, i)
    }
}

/// The model of every one of the `bins` bins of `case`'s spectrum (`Case::at_bin`), built
/// by `build` in parallel; every bin's problems named with its bin, all at once.
pub fn models_of_bins<M: Send>(
    case: &Case,
    bins: usize,
    build: impl Fn(&Case) -> Result<M, ModelError> + Sync,
) -> Result<Vec<M>, ModelError> {
    let built: Vec<Result<M, ModelError>> = (0..bins)
        .into_par_iter()
        .map(|i| build(&case.at_bin(i)))
        .collect();
    let mut models = Vec::with_capacity(built.len());
    let mut problems = Vec::new();
    for (i, b) in built.into_iter().enumerate() {
        match b {
            Ok(m) => models.push(m),
            Err(e) => problems.extend(
                e.0.iter()
                    .map(|p| format!("{}: {}", bin_label(case, i), in_bin_words(p))),
            ),
        }
    }
    if problems.is_empty() {
        Ok(models)
    } else {
        Err(ModelError(problems))
    }
}

/// The wear per pinion cycle of a mesh under a spectrum, sum_i s_i inc_i (paper eq. 14-16
/// per bin, mixed by the shares `shares`), m: `per_bin` gives each bin's (pinion, gear)
/// increments per profile point, in bin order (a train's mesh, a planetary set's mesh).
pub fn mixed_increment<'a>(
    per_bin: impl Iterator<Item = (&'a [f64], &'a [f64])>,
    shares: &[f64],
) -> crate::wear::WearIncrement {
    let (mut p, mut g): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    for ((pinion, gear), s) in per_bin.zip(shares) {
        p.resize(pinion.len(), 0.0);
        g.resize(gear.len(), 0.0);
        for (x, d) in p.iter_mut().zip(pinion) {
            *x += s * d;
        }
        for (x, d) in g.iter_mut().zip(gear) {
            *x += s * d;
        }
    }
    crate::wear::WearIncrement {
        pinion_m: p,
        gear_m: g,
        ..Default::default()
    }
}

/// The share-weighted sum sum_i s_i M_i of the bins' per-tooth or per-face-slice maps
/// (`ToothWear`, `SliceWear`: profiles per tooth or face slice), m per pinion cycle, in
/// bin order from zero; None unless every bin has a map (an empty spectrum has none).
/// The mixing rule of [`mixed_increment`] applied to every profile of the map: the
/// single pair's spectrum loop mixes the tooth-resolved mesh's teeth and the helical
/// pair's face slices with it (`duty::wear`).
pub fn mixed_maps<'a>(
    per_bin: impl Iterator<Item = Option<&'a ToothWear>>,
    shares: &[f64],
) -> Option<ToothWear> {
    let mut sum: Option<ToothWear> = None;
    for (map, s) in per_bin.zip(shares) {
        let map = map?;
        let to = sum.get_or_insert_with(|| ToothWear {
            pinion_m: map.pinion_m.iter().map(|p| vec![0.0; p.len()]).collect(),
            gear_m: map.gear_m.iter().map(|p| vec![0.0; p.len()]).collect(),
        });
        for (a, b) in [
            (&mut to.pinion_m, &map.pinion_m),
            (&mut to.gear_m, &map.gear_m),
        ] {
            for (x, d) in a.iter_mut().flatten().zip(b.iter().flatten()) {
                *x += s * d;
            }
        }
    }
    sum
}
