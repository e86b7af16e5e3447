//! How one tooth pair takes up and gives off the load (`gearwear stiffness`,
//! `pair_load.csv` and `pair_load.png`): the quasi-static share of the mesh force that a
//! pair carries at each position of its engagement, for the case's contact model and the
//! other one beside it (docs/MODEL.md, section 4.2).
//!
//! With identical teeth every pair at the position rho1 carries what any other pair at
//! rho1 carries, so the pairs of the quasi-static equilibria over one mesh period, taken
//! together and ordered by rho1, trace one pair through its whole engagement: on the
//! nominal path its share jumps at the path's ends (the involutes meet with full
//! stiffness at once), with corner contact it rises from zero as the corner's gap closes.

use super::artifacts::Artifacts;
use super::figures::{panel, Curve};
use super::plot::Figure;
use crate::config::case::ContactPathModel;
use crate::dynamics::contact_path::ContactPath;
use crate::dynamics::model::{GearSystem, MAX_PAIRS};
use crate::dynamics::quasi_static::equilibrium;
use crate::io::Table;
use crate::study::Model;

/// Mesh phases sampled over one mesh period: each gives one point per pair in the
/// reach, so the curve has about this many points per base pitch of engagement.
const PHASES: usize = 720;

/// One pair through its engagement: positions rho1 (m, along the line of action from the
/// pinion's base tangent point; beyond the path's ends where a corner touches) and the
/// share of the mesh force carried there (1), in ascending rho1.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PairLoadCurve {
    /// Contact positions rho1, m, ascending.
    pub rho1_m: Vec<f64>,
    /// Share of the mesh force carried at each position (1: all of it).
    pub share: Vec<f64>,
}

/// The curve of [`PairLoadCurve`] from the quasi-static equilibria of `sys`'s mesh 0 (a
/// single pair whose contact follows `contact`) at `PHASES` phases over one mesh
/// period (quasi-static: the pairs' springs alone carry the static mesh force;
/// `dynamics::quasi_static`). The position is the pair's place in the reach, where a
/// corner pair stands beyond the path (the equilibrium's rho1 is where its Hertz contact
/// is taken, the path's end); the pairs come in the equilibrium's order.
pub fn pair_load_curve(model: &Model, contact: &ContactPath, sys: &GearSystem) -> PairLoadCurve {
    let mut points: Vec<(f64, f64)> = Vec::with_capacity(PHASES * MAX_PAIRS);
    for i in 0..PHASES {
        let phase = model.pair.mesh_angle_rad() * i as f64 / PHASES as f64;
        let eq = equilibrium(sys, 0, phase);
        if eq.force_n.is_nan() || eq.force_n <= 0.0 {
            continue;
        }
        let places = model
            .pair
            .pairs_in_reach_decided(contact.reach(), phase, phase);
        for ((_, rho1), load) in places.into_iter().zip(&eq.load_n[..eq.n_pairs]) {
            points.push((rho1, load / eq.force_n));
        }
    }
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    PairLoadCurve {
        rho1_m: points.iter().map(|p| p.0).collect(),
        share: points.iter().map(|p| p.1).collect(),
    }
}

/// The curves of the case's contact model and of the other one, named by their key:
/// [(path, curve); 2], the case's first.
fn both_curves(model: &Model) -> [(ContactPathModel, PairLoadCurve); 2] {
    let roughness = model.roughness.rms_um(0.0);
    let own = model.case.contact.path;
    let other = if model.contact.is_extended() {
        ContactPathModel::Nominal
    } else {
        ContactPathModel::Extended
    };
    let other_contact = ContactPath::new(&model.pair, other, MAX_PAIRS);
    let own_curve = pair_load_curve(
        model,
        &model.contact,
        &model.system_with_contact(&model.contact, roughness),
    );
    let other_curve = pair_load_curve(
        model,
        &other_contact,
        &model.system_with_contact(&other_contact, roughness),
    );
    [(own, own_curve), (other, other_curve)]
}

fn label(path: ContactPathModel) -> &'static str {
    if path.is_extended() {
        "corner contact beyond the path (contact.path = \"extended\")"
    } else {
        "nominal path only (contact.path = \"nominal\")"
    }
}

/// `pair_load.csv` (for each contact model its own two columns, `rho1_KEY_mm` and
/// `load_share_KEY`, KEY `extended` or `nominal`: the curves have their own points; the
/// nominal curve begins and ends with no load at A and E, the pair just before it enters
/// the path and just after it leaves, so that its jumps show) and `pair_load.png`, for a
/// single pair of identical teeth (a tooth-resolved or train case has no single curve:
/// nothing added).
pub fn add_pair_load_artifacts(model: &Model, a: &mut Artifacts) {
    if model.train.is_some() || model.teeth.is_some() {
        return;
    }
    let mut t = Table::new();
    let mut drawn = Vec::new();
    for (path, c) in both_curves(model) {
        let mut x: Vec<f64> = c.rho1_m.iter().map(|r| r * 1e3).collect();
        let mut y = c.share;
        if !path.is_extended() && !x.is_empty() {
            x.insert(0, x[0]);
            y.insert(0, 0.0);
            x.push(x[x.len() - 1]);
            y.push(0.0);
        }
        let key = if path.is_extended() {
            "extended"
        } else {
            "nominal"
        };
        t = t
            .col(&format!("rho1_{key}_mm"), x.clone())
            .col(&format!("load_share_{key}"), y.clone());
        drawn.push(Curve::new(label(path), x, y));
    }
    let p = &model.pair;
    let figure = Figure {
        title: format!(
            "Share of the mesh force one pair carries (quasi-static, {:.0} N); nominal path {:.2} to {:.2} mm",
            model.params.operating.static_mesh_force_n,
            p.rho_start_m * 1e3,
            p.rho_end_m * 1e3
        ),
        panels: vec![panel(
            "position of the pair on the line of action rho1 (mm)",
            "share of the mesh force (1)",
            drawn,
        )],
    };
    a.figure("pair_load.png", figure);
    if let Some(f) = a.figures.last_mut() {
        f.data = Some("pair_load.csv".into());
    }
    a.table("pair_load.csv", t);
}
