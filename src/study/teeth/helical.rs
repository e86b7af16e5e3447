//! The teeth of a helical pair as contact lines (docs/MODEL.md 11.10): each tooth's flank
//! on the line pair of the planar model (`SliceMeshStiffness::line_model`), so that the
//! spur pair's tooth-resolved mesh (`dynamics::tooth_mesh`) runs it unchanged.
//!
//! Mesh cycle n's contact line is one spring, its trailing end at rho on the line pair
//! [A - L, E]; its slices sit at rho + o_i on the transverse path [A, E] (slice i on face
//! slice j(i), `SliceMeshStiffness::face_slice_of_line_slice`), each of stiffness
//! k_i = k_slice(rho + o_i). A tooth's line thus enters contact at one face end and leaves
//! at the other, one slice at a time. Per tooth, at each sample rho of the line pair:
//! - its errors are the same on every slice of the tooth (a pitch error and a run-out are
//!   rigid displacements of the whole tooth; the profile slope and form deviations are
//!   taken alike on every transverse section, no helix deviation per tooth);
//! - a crack or spall acts on the face slices whose centres y_j lie in its span
//!   [`fault.face_start_mm`, `fault.face_end_mm`] (`ToothFault::face_span_m`), each such
//!   slice carrying the fault's compliance c_i(rho + o_i) of a spur slice of width b/N
//!   (`study::teeth::apply_fault` on the slice's own tooth beams) in series:
//!   k_f,i = 1 / (1/k_i + c_i);
//! - the line's stiffness is K_f = sum_i k_f,i (parallel springs, no coupling between
//!   slices, as in the slice model), given to the tooth-resolved mesh as the compliance
//!   K_f^-1 - K^-1 in series with the healthy line's K = sum_i k_i (the model's line
//!   table), exact at the samples;
//! - the line's gap is the k_f-weighted mean of its slices' gaps (removed material of the
//!   errors and a spall's pit): exact for a gap the same on every slice (pitch errors,
//!   run-out), the line's mean where it varies along the profile (the choice of the worn
//!   slices, docs/MODEL.md 11.3).
//!
//! Samples lie at the wear grid's spacing over the line pair's path, interpolated linearly
//! by the tooth-resolved mesh (as a spur pair's flank tables are).

use super::checks::{geometry_problems, upper_mm};
use super::errors::gear_errors;
use super::helical_tip::{line_limit, max_removed_height_m, TipCut};
use super::line_wear::{LineCell, LineTeeth, SliceFault, ToothSlices};
use super::{apply_fault, flanks_of, ToothInputs};
use crate::config::case::{Case, Member};
use crate::dynamics::tooth_mesh::{Runout, ToothFlank};
use crate::geometry::flank_shape::Side;
use crate::geometry::ProfileGrid;
use crate::stiffness::helical::SliceMeshStiffness;
use crate::stiffness::tooth_faults::deg;

/// The slices of the contact line at each sample of the line pair: (face slice j, their
/// transverse position rho + o_i (m), healthy stiffness k_i (N/m)) of those on the path.
struct LineSamples {
    rho_start_m: f64,
    spacing_m: f64,
    slices: Vec<Vec<(usize, f64, f64)>>,
    /// The line's slices: (face slice j, offset o_i from the trailing end, m).
    offsets: Vec<(usize, f64)>,
    /// The transverse path [A, E], pinion rho1, m.
    path: (f64, f64),
}

impl LineSamples {
    fn of(s: &SliceMeshStiffness, grid: &ProfileGrid) -> Self {
        let lines = s.model_line_grid();
        let t = &s.pair().transverse;
        let spacing = grid.spacing_m;
        let points = ((lines.line.path_length_m() / spacing).ceil() as usize + 1).max(2);
        let slices = (0..points)
            .map(|p| {
                let rho = lines.line.rho_start_m + p as f64 * spacing;
                lines
                    .offsets
                    .iter()
                    .enumerate()
                    .map(|(i, o)| (s.face_slice_of_line_slice(i), rho + o))
                    .filter(|(_, r)| (t.rho_start_m..=t.rho_end_m).contains(r))
                    .map(|(j, r)| (j, r, s.slice().pair_stiffness_n_per_m(r)))
                    .collect()
            })
            .collect();
        Self {
            rho_start_m: lines.line.rho_start_m,
            spacing_m: spacing,
            slices,
            offsets: (lines.offsets.iter().enumerate())
                .map(|(i, o)| (s.face_slice_of_line_slice(i), *o))
                .collect(),
            path: (t.rho_start_m, t.rho_end_m),
        }
    }

    /// What the teeth's wear per face slice needs (`line_wear::LineTeeth`): the slices of
    /// `s` on the wear grid `grid`, with each tooth's sections (pinion, gear).
    fn teeth(
        &self,
        s: &SliceMeshStiffness,
        grid: &ProfileGrid,
        pinion: Vec<ToothSlices>,
        gear: Vec<ToothSlices>,
    ) -> LineTeeth {
        LineTeeth {
            slices: s.slices(),
            cos_base_helix: s.pair().base_helix_angle_rad.cos(),
            grid: grid.clone(),
            cells: self.cells(),
            offsets: self.offsets.clone(),
            path: self.path,
            pinion,
            gear,
        }
    }

    /// The line's slices at each sample for its wear (`line_wear::LineCell`): those on the
    /// path, or, where none is, the nearest one at the path's end.
    fn cells(&self) -> Vec<LineCell> {
        let (start, end) = self.path;
        let off_path = |r: f64| (start - r).max(r - end);
        (self.slices.iter().enumerate())
            .map(|(p, line)| {
                if !line.is_empty() {
                    return LineCell::On(line.clone());
                }
                let rho = self.rho_start_m + p as f64 * self.spacing_m;
                let nearest = (self.offsets.iter())
                    .min_by(|a, b| off_path(rho + a.1).total_cmp(&off_path(rho + b.1)));
                nearest.map_or(LineCell::On(Vec::new()), |&(j, o)| {
                    LineCell::Nearest(j, (rho + o).clamp(start, end))
                })
            })
            .collect()
    }
}

/// Which face slices of `s` carry the fault `f`: those whose centre lies in its span
/// [`fault.face_start_mm`, `fault.face_end_mm`] (docs/MODEL.md 11.10), one flag a slice.
fn covered_slices(f: &crate::config::case::ToothFault, s: &SliceMeshStiffness) -> Vec<bool> {
    let (lo, hi) = f.face_span_m(s.pair().face_width_m);
    s.positions_m()
        .iter()
        .map(|y| (lo..=hi).contains(y))
        .collect()
}

/// The faults of `member`'s tooth `tooth` of `case` on the slices of `s`, each on the wear
/// grid `grid` with the face slices it covers and a broken tip's cut.
fn slice_faults(
    case: &Case,
    s: &SliceMeshStiffness,
    grid: &ProfileGrid,
    (member, tooth): (Member, usize),
) -> Vec<SliceFault> {
    let side = super::sides::side(member);
    let own = match side {
        Side::Pinion => &grid.rho_pinion_m,
        Side::Gear => &grid.rho_gear_m,
    };
    (case.fault.iter())
        .filter(|x| x.gear == member && x.tooth == tooth && x.changes_tooth())
        .map(|x| {
            let mut flank = ToothFlank::perfect(grid.len());
            apply_fault(&mut flank, x, &s.pair().transverse, s.slice(), side, own);
            let covers = covered_slices(x, s);
            let cut = TipCut::of(&flank, side);
            SliceFault { flank, covers, cut }
        })
        .collect()
}

/// A fault whose span across the face (`fault.face_start_mm`, `fault.face_end_mm`) holds
/// no slice centre of `s` would change nothing (each slice carries a fault whose span
/// holds its centre): refused, naming the keys, the slice width and the nearest centres.
fn empty_span_problems(case: &Case, s: &SliceMeshStiffness) -> Vec<String> {
    let b = s.pair().face_width_m;
    let centres = s.positions_m();
    let width_mm = b / centres.len().max(1) as f64 * 1e3;
    case.fault
        .iter()
        .enumerate()
        .filter(|(_, f)| f.changes_tooth() && f.has_face_span())
        .filter_map(|(i, f)| {
            if covered_slices(f, s).contains(&true) {
                return None;
            }
            let (lo, hi) = f.face_span_m(b);
            let below = centres.iter().rev().find(|y| **y < lo).map(|y| y * 1e3);
            let above = centres.iter().find(|y| **y > hi).map(|y| y * 1e3);
            let near = [below, above]
                .iter()
                .flatten()
                .map(|y| format!("{y:.4} mm"))
                .collect::<Vec<_>>()
                .join(" and ");
            Some(format!(
                "`fault.face_start_mm` = {}, `fault.face_end_mm` = {} (fault {i}) hold no slice centre: the {} slices are {width_mm:.4} mm wide, the nearest centres at {near}, and a slice carries the fault when its centre lies in the span; widen the span or give more slices (`stiffness.slices`)",
                lo * 1e3,
                hi * 1e3,
                centres.len()
            ))
        })
        .collect()
}

impl ToothInputs {
    /// The teeth of a helical `case` as contact lines of `s`'s line pair (module docs), or
    /// None when no tooth differs from the new one. `grid`: the transverse wear grid;
    /// `shaft_speeds_rad_s`: pinion and gear, for the run-out. Errors: the geometry
    /// checks of the faults against the slice's teeth.
    pub(crate) fn helical(
        case: &Case,
        s: &SliceMeshStiffness,
        grid: &ProfileGrid,
        shaft_speeds_rad_s: [f64; 2],
    ) -> Result<Option<Self>, Vec<String>> {
        let t = &s.pair().transverse;
        let slice = s.slice();
        let mut problems = geometry_problems(case, t, slice);
        problems.extend(empty_span_problems(case, s));
        if !problems.is_empty() {
            return Err(problems);
        }
        let errors = gear_errors(case, t).map_err(|e| vec![e.to_string()])?;
        let mut healthy = case.clone();
        healthy.fault.clear();
        let samples = LineSamples::of(s, grid);
        let mut problems = Vec::new();
        let mut lines = |member: Member, e| -> (Vec<ToothFlank>, Vec<ToothSlices>) {
            let side = super::sides::side(member);
            flanks_of(&healthy, t, slice, grid, member, e)
                .into_iter()
                .enumerate()
                .map(|(tooth, f)| {
                    let faults = slice_faults(case, s, grid, (member, tooth));
                    let flat = f.removed_m.iter().all(|x| *x == 0.0);
                    let sections = ToothSlices {
                        removed_m: if flat {
                            Vec::new()
                        } else {
                            f.removed_m.clone()
                        },
                        faults,
                    };
                    let line =
                        line_flank(&f, &sections, grid, &samples, side).unwrap_or_else(|()| {
                            problems.extend(resumed_contact_problems(case, s, member, tooth));
                            f
                        });
                    (line, sections)
                })
                .unzip()
        };
        let ((pinion, pinion_sections), (gear, gear_sections)) = (
            lines(Member::Pinion, &errors[0]),
            lines(Member::Gear, &errors[1]),
        );
        if !problems.is_empty() {
            return Err(problems);
        }
        let runout = |e: &super::GearErrors, phase_deg: Option<f64>, speed: f64| Runout {
            eccentricity_m: 0.5 * e.runout_um * 1e-6,
            phase_rad: deg(phase_deg.unwrap_or(0.0)),
            shaft_speed_rad_s: speed,
        };
        let teeth = &case.teeth;
        let me = Self {
            pinion,
            gear,
            runout: [
                runout(
                    &errors[0],
                    teeth.runout_pinion_phase_deg,
                    shaft_speeds_rad_s[0],
                ),
                runout(
                    &errors[1],
                    teeth.runout_gear_phase_deg,
                    shaft_speeds_rad_s[1],
                ),
            ],
            errors,
            faults: case.fault.clone(),
            rho_start_m: samples.rho_start_m,
            spacing_m: samples.spacing_m,
            worn: None,
            lines: Some(Box::new(samples.teeth(
                s,
                grid,
                pinion_sections,
                gear_sections,
            ))),
        };
        let n = samples.slices.len();
        let perfect = |f: &[ToothFlank]| f.iter().all(|t| t == &ToothFlank::perfect(n));
        let trivial = perfect(&me.pinion)
            && perfect(&me.gear)
            && me.runout.iter().all(|r| r.eccentricity_m == 0.0);
        Ok((!trivial).then_some(me))
    }
}

/// The refusal of a tooth whose broken tips would end its line's contact and start it
/// again (`helical_tip` module docs): each tip fault of `member`'s `tooth`, naming the key,
/// its value and the sufficient range of removed heights on this pair and slice count.
fn resumed_contact_problems(
    case: &Case,
    s: &SliceMeshStiffness,
    member: Member,
    tooth: usize,
) -> Vec<String> {
    let grid = s.model_line_grid();
    let spacing = grid.lead / s.slices() as f64;
    let h_max = max_removed_height_m(&s.pair().transverse, super::sides::side(member), spacing);
    case.fault
        .iter()
        .enumerate()
        .filter(|(_, x)| x.gear == member && x.tooth == tooth)
        .filter(|(_, x)| matches!(x.fault, crate::config::case::Fault::BrokenTip { .. }))
        .map(|(i, x)| {
            format!(
                "`fault.removed_height_mm` = {} (fault {i}, {} tooth {tooth}) cuts the tip so close to the start of active profile over part of the face that the tooth's contact line would stop touching and touch again; a helical tooth's line ends its contact once (docs/MODEL.md 11.12): valid (0, {}] mm on this pair with {} slices (`stiffness.slices`): the cut kept one slice spacing above the start of the path of contact",
                x.written("removed_height_mm"),
                member.name(),
                upper_mm(h_max * 1e3),
                s.slices()
            )
        })
        .collect()
}

/// A tooth's flank as its contact line on the line pair (module docs): `f` its flank on
/// the wear grid (its position error kept), `sections` its errors and its faults with the
/// face slices they cover (`line_wear::ToothSlices`), `side` its gear.
/// A broken tip's covered slices beyond its cut carry nothing (docs/MODEL.md 11.12): the
/// line's stiffness and gap are its uncut slices', their share of the line on the path
/// is its width lost, and past the line's limit (`helical_tip::line_limit`) the tooth
/// does not touch, its tables held at the last sample before it. Err(()): the line would
/// stop touching and touch again.
fn line_flank(
    f: &ToothFlank,
    sections: &ToothSlices,
    grid: &ProfileGrid,
    samples: &LineSamples,
    side: Side,
) -> Result<ToothFlank, ()> {
    let n = samples.slices.len();
    let faults = &sections.faults;
    if faults.is_empty() && sections.removed_m.is_empty() {
        return Ok(ToothFlank {
            position_m: f.position_m,
            ..ToothFlank::perfect(n)
        });
    }
    let cuts: Vec<(&[bool], TipCut)> = faults
        .iter()
        .filter_map(|x| x.cut.map(|c| (x.covers.as_slice(), c)))
        .collect();
    let limit = line_limit(
        &samples.offsets,
        samples.path,
        samples.rho_start_m,
        &cuts,
        side,
    )?;
    let rho_at = |p: usize| samples.rho_start_m + p as f64 * samples.spacing_m;
    let touches = |p: usize| match (limit, side) {
        (None, _) => true,
        (Some(l), Side::Pinion) => rho_at(p) <= l,
        (Some(l), Side::Gear) => rho_at(p) >= l,
    };
    let mut removed_m = vec![0.0; n];
    let mut compliance = vec![0.0; n];
    let mut width_loss = vec![0.0; n];
    for (p, line) in samples
        .slices
        .iter()
        .enumerate()
        .filter(|(p, _)| touches(*p))
    {
        let (mut k, mut kf, mut kf_gap, mut cut) = (0.0, 0.0, 0.0, 0usize);
        for &(j, r, ki) in line {
            k += ki;
            let Some((gap, c)) = sections.at(grid, j, r) else {
                cut += 1;
                continue;
            };
            let kfi = if c == 0.0 { ki } else { 1.0 / (1.0 / ki + c) };
            kf += kfi;
            kf_gap += kfi * gap;
        }
        if kf > 0.0 {
            removed_m[p] = kf_gap / kf;
            compliance[p] = 1.0 / kf - 1.0 / k;
            width_loss[p] = cut as f64 / line.len() as f64;
        }
    }
    // Past the limit the tooth does not touch: its tables hold the last touching sample's,
    // so that the interpolation up to the limit takes that sample's values.
    let held = |v: &mut Vec<f64>| {
        let order: Vec<usize> = match side {
            Side::Pinion => (0..n).collect(),
            Side::Gear => (0..n).rev().collect(),
        };
        let mut last = None;
        for p in order {
            if touches(p) {
                last = Some(v[p]);
            } else if let Some(x) = last {
                v[p] = x;
            }
        }
    };
    for v in [&mut removed_m, &mut compliance, &mut width_loss] {
        held(v);
    }
    let table = |v: Vec<f64>| v.iter().any(|c| *c != 0.0).then_some(v);
    Ok(ToothFlank {
        removed_m,
        position_m: f.position_m,
        compliance_m_per_n: table(compliance),
        width_loss: table(width_loss),
        contact_limit_rho1_m: limit,
        ..Default::default()
    })
}
