//! Time-varying mesh stiffness of the spur pair (paper eq. 12-13 as corrected in
//! docs/MODEL.md): the single-pair stiffness along the path of contact, tabulated once and
//! interpolated by a clamped cubic spline (O(1) per call), and the total stiffness of the
//! pairs in contact, which act in parallel.
//!
//! Single pair (paper eq. 12 plus the fillet foundation, Sainsot et al. 2004):
//!   1/k_pair = 1/k_h + sum_{pinion, gear} (1/k_b + 1/k_s + 1/k_a [+ 1/k_f]), m/N.
//! Total: k_m(phase) = sum over pairs in contact of k_pair(rho1) (eq. 13 as printed sums
//! compliances of both pairs in series, which is wrong).

use super::fillet::FilletFoundation;
pub use super::fillet::FilletSettings;
use super::potential_energy::{hertz_stiffness_n_per_m, ElasticPair, ToothBeam, ToothCompliance};
use crate::geometry::GearPair;
use thiserror::Error;

/// Largest ratio of the fillet foundation's compliance to the rest of the pair's (teeth and
/// Hertz) accepted from an extrapolated fit. Inside Sainsot's range the paper's pair has
/// ~0.6-0.8; the peer's pair extrapolated to h_f = 11.5 (0.35 times ISO 6336) about 4;
/// beyond 10 the extrapolated polynomial, not the body, sets the stiffness.
pub const MAX_EXTRAPOLATED_FOUNDATION_RATIO: f64 = 10.0;

/// Inputs the stiffness model cannot use.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("mesh stiffness: {}", .0.join("; "))]
pub struct StiffnessError(pub Vec<String>);

/// The compliances of one tooth pair at one contact position, m/N.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairCompliance {
    /// 1/k_h (paper eq. 11).
    pub hertz_m_per_n: f64,
    /// Bending, shear and axial compliances of the pinion tooth (paper eqs. 8-10).
    pub pinion: ToothCompliance,
    /// Bending, shear and axial compliances of the gear tooth (paper eqs. 8-10).
    pub gear: ToothCompliance,
    /// 1/k_f of the pinion and of the gear; 0 when the fillet foundation is off.
    pub pinion_fillet_m_per_n: f64,
    /// 1/k_f of the gear, m/N; 0 when the fillet foundation is off.
    pub gear_fillet_m_per_n: f64,
}

impl PairCompliance {
    /// 1/k_pair, m/N.
    pub fn total_m_per_n(&self) -> f64 {
        self.hertz_m_per_n
            + self.pinion.total_m_per_n()
            + self.gear.total_m_per_n()
            + self.pinion_fillet_m_per_n
            + self.gear_fillet_m_per_n
    }

    /// k_pair, N/m.
    pub fn stiffness_n_per_m(&self) -> f64 {
        1.0 / self.total_m_per_n()
    }
}

/// Mesh stiffness of a pair, built once. See the module docs.
#[derive(Debug, Clone)]
pub struct MeshStiffness {
    pair: GearPair,
    teeth: [ToothBeam; 2],
    fillets: Option<[FilletFoundation; 2]>,
    hertz_m_per_n: f64,
    /// Grid step along the line of action, m.
    step_m: f64,
    /// k_pair at the grid points, N/m.
    values: Vec<f64>,
    /// Spline second derivatives at the grid points, N/m^3.
    curvature: Vec<f64>,
    /// Each tooth's compliance (beam and fillet foundation) at the grid points, pinion
    /// then gear (the gear's at the conjugate point), m/N, and their spline second
    /// derivatives, m/N/m^2: the pair's parts, for contacts where the two flanks are
    /// loaded at points that are not conjugate ([`MeshStiffness::corner_pair_stiffness_n_per_m`]).
    tooth_compliance: [Vec<f64>; 2],
    tooth_compliance_curvature: [Vec<f64>; 2],
    mean_n_per_m: f64,
    min_n_per_m: f64,
    max_n_per_m: f64,
    warnings: Vec<String>,
}

impl MeshStiffness {
    /// Tabulate k_pair at `n_points` (>= 5) uniform positions on [rho_start, rho_end]
    /// (the path of contact, epsilon_alpha base pitches long; the case's
    /// `stiffness.table_points_per_mesh_period` is the intended value), with the fillet
    /// foundation in the default convention, extrapolated with a warning outside
    /// Sainsot's range (`FilletSettings::lenient`); a case's own settings go through
    /// [`MeshStiffness::with_fillet`].
    pub fn new(
        pair: &GearPair,
        elastic: &ElasticPair,
        n_points: usize,
        include_fillet: bool,
    ) -> Result<Self, StiffnessError> {
        Self::with_fillet(
            pair,
            elastic,
            n_points,
            include_fillet.then(FilletSettings::lenient),
        )
    }

    /// As [`MeshStiffness::new`] with the fillet foundation as `fillet` says (`None`: off).
    /// A fit outside its range that the settings do not allow, or one that gives a
    /// non-positive compliance, is an error.
    pub fn with_fillet(
        pair: &GearPair,
        elastic: &ElasticPair,
        n_points: usize,
        fillet: Option<FilletSettings>,
    ) -> Result<Self, StiffnessError> {
        Self::with_hertz_factor(pair, elastic, n_points, fillet, 1.0)
    }

    /// As [`MeshStiffness::with_fillet`] with the Hertz stiffness of eq. 11 multiplied by
    /// `hertz_factor` (> 0): a helical slice's contact line is inclined on the plane of
    /// action, which makes its Hertz stiffness along the transverse line of action cos(beta_b)
    /// times eq. 11's for the slice width (`stiffness::helical`). 1 is the spur pair, bit
    /// for bit.
    pub(crate) fn with_hertz_factor(
        pair: &GearPair,
        elastic: &ElasticPair,
        n_points: usize,
        fillet: Option<FilletSettings>,
        hertz_factor: f64,
    ) -> Result<Self, StiffnessError> {
        let mut errs = elastic.validate();
        if n_points < 5 {
            errs.push(format!(
                "at least 5 table points are needed, got {n_points}"
            ));
        }
        if !errs.is_empty() {
            return Err(StiffnessError(errs));
        }
        let b = pair.face_width_m;
        let teeth = [
            ToothBeam::new(&pair.pinion, b, elastic.e_pinion_pa, elastic.nu_pinion),
            ToothBeam::new(&pair.gear, b, elastic.e_gear_pa, elastic.nu_gear),
        ];
        let fillets = fillet_foundations(pair, &teeth, fillet)?;
        let warnings = fillets
            .iter()
            .flatten()
            .filter_map(|f| f.warning.clone())
            .collect();
        let mut me = Self {
            pair: pair.clone(),
            teeth,
            fillets,
            hertz_m_per_n: 1.0 / (hertz_stiffness_n_per_m(b, elastic) * hertz_factor),
            step_m: pair.path_length_m() / (n_points - 1) as f64,
            values: Vec::new(),
            curvature: Vec::new(),
            tooth_compliance: [Vec::new(), Vec::new()],
            tooth_compliance_curvature: [Vec::new(), Vec::new()],
            mean_n_per_m: 0.0,
            min_n_per_m: 0.0,
            max_n_per_m: 0.0,
            warnings,
        };
        let (foundation_ratio, teeth_c) = me.tabulate(n_points);
        me.check_usable(foundation_ratio)?;
        me.curvature = clamped_spline_curvature(&me.values, me.step_m);
        me.tooth_compliance_curvature = [
            clamped_spline_curvature(&teeth_c[0], me.step_m),
            clamped_spline_curvature(&teeth_c[1], me.step_m),
        ];
        me.tooth_compliance = teeth_c;
        me.mean_n_per_m = me.path_integral() / pair.base_pitch_m;
        (me.min_n_per_m, me.max_n_per_m) = me.period_extrema(20 * n_points);
        Ok(me)
    }

    /// Fill `values` with k_pair (N/m) at `n_points` uniform positions of the path of
    /// contact; returns the largest ratio of the fillet foundation's compliance to the rest
    /// of the pair's, and each tooth's compliance (teeth plus its fillet, m/N) at the points.
    fn tabulate(&mut self, n_points: usize) -> (f64, [Vec<f64>; 2]) {
        let mut foundation_ratio = 0.0_f64;
        let mut teeth_c = [Vec::with_capacity(n_points), Vec::with_capacity(n_points)];
        let rho_start_m = self.pair.rho_start_m;
        self.values = (0..n_points)
            .map(|i| {
                let c = self.compliances_at(rho_start_m + i as f64 * self.step_m);
                let fillet = c.pinion_fillet_m_per_n + c.gear_fillet_m_per_n;
                foundation_ratio = foundation_ratio.max(fillet / (c.total_m_per_n() - fillet));
                teeth_c[0].push(c.pinion.total_m_per_n() + c.pinion_fillet_m_per_n);
                teeth_c[1].push(c.gear.total_m_per_n() + c.gear_fillet_m_per_n);
                c.stiffness_n_per_m()
            })
            .collect();
        (foundation_ratio, teeth_c)
    }

    /// The tabulated values refused: a pair stiffness not finite and positive, or an
    /// extrapolated fillet fit whose foundation is more than
    /// [`MAX_EXTRAPOLATED_FOUNDATION_RATIO`] times as compliant as the rest of the pair.
    fn check_usable(&self, foundation_ratio: f64) -> Result<(), StiffnessError> {
        let extrapolated = self
            .fillets
            .iter()
            .flatten()
            .any(FilletFoundation::outside_fit);
        let bad = self.values.iter().find(|k| !(k.is_finite() && **k > 0.0));
        if bad.is_some()
            || (extrapolated
                && (foundation_ratio.is_nan()
                    || foundation_ratio > MAX_EXTRAPOLATED_FOUNDATION_RATIO))
        {
            return Err(StiffnessError(vec![format!(
                "Sainsot's fillet-foundation fit, extrapolated to this geometry (h_f = {}), gives no usable compliance ({}); keep the hub bores and the tooth form near the fit's range, or set `stiffness.fillet_foundation` = false",
                self.fillets
                    .iter()
                    .flatten()
                    .map(|f| format!("{:.3}", f.h_f))
                    .collect::<Vec<_>>()
                    .join(" / "),
                match bad {
                    Some(k) => format!("a pair stiffness of {k:e} N/m"),
                    None => format!(
                        "the body would be {foundation_ratio:.3e} times as compliant as tooth and contact together, above {MAX_EXTRAPOLATED_FOUNDATION_RATIO}"
                    ),
                }
            )]));
        }
        Ok(())
    }

    /// A table of given values on `pair`'s path [rho_start, rho_end] (uniform, at least 5
    /// points), interpolated as every pair's (the clamped cubic spline), with `base`'s
    /// teeth, fillets and Hertz term (used by the tip-corner spring only): the helical
    /// pair's contact line as one "pair" (`stiffness::helical`). `extrema_samples`: the
    /// samples per interval of constant contact count for the min and max.
    pub(crate) fn from_table(
        base: &MeshStiffness,
        pair: GearPair,
        values: Vec<f64>,
        extrema_samples: usize,
    ) -> Self {
        let n = values.len();
        let step_m = pair.path_length_m() / (n - 1) as f64;
        let curvature = clamped_spline_curvature(&values, step_m);
        let flat = vec![0.0; n];
        let mut me = Self {
            pair,
            teeth: base.teeth.clone(),
            fillets: base.fillets.clone(),
            hertz_m_per_n: base.hertz_m_per_n,
            step_m,
            values,
            curvature,
            tooth_compliance: [flat.clone(), flat.clone()],
            tooth_compliance_curvature: [flat.clone(), flat],
            mean_n_per_m: 0.0,
            min_n_per_m: 0.0,
            max_n_per_m: 0.0,
            warnings: base.warnings.clone(),
        };
        me.mean_n_per_m = me.path_integral() / me.pair.base_pitch_m;
        (me.min_n_per_m, me.max_n_per_m) = me.period_extrema(extrema_samples);
        me
    }

    /// Direct (not interpolated) compliances of the pair whose contact lies at the pinion
    /// radius of curvature rho1 (m); the gear's is rho2 = N1N2 - rho1.
    pub fn compliances_at(&self, rho1_m: f64) -> PairCompliance {
        let rho = [rho1_m, self.pair.rho_gear(rho1_m)];
        let tooth = |i: usize| self.teeth[i].compliance(rho[i]);
        // u_f: from the root circle along the centreline to the force line's crossing.
        let fil = |i: usize| match &self.fillets {
            Some(f) => {
                let t = &self.teeth[i];
                let u_f = t.force_centreline_crossing_m(rho[i]) - t.root_radius_m;
                f[i].compliance_m_per_n(u_f, t.contact_angle_rad(rho[i]))
            }
            None => 0.0,
        };
        PairCompliance {
            hertz_m_per_n: self.hertz_m_per_n,
            pinion: tooth(0),
            gear: tooth(1),
            pinion_fillet_m_per_n: fil(0),
            gear_fillet_m_per_n: fil(1),
        }
    }

    /// k_pair(rho1), N/m, from the table (cubic spline, O(1)). Positions outside the path
    /// of contact are clamped to its ends: the pair is only defined there.
    pub fn pair_stiffness_n_per_m(&self, rho1_m: f64) -> f64 {
        self.spline_at(&self.values, &self.curvature, rho1_m)
    }

    /// Stiffness of a pair whose pinion flank is loaded at the pinion's radius of
    /// curvature `pinion_rho1_m` and whose gear flank at the point conjugate to
    /// `gear_rho1_m` (both pinion rho1 on the path, clamped to it), each tooth along its
    /// own flank's normal there, N/m: 1/k = 1/k_h + c_pinion + c_gear (the pair's series
    /// springs, section 2 of docs/MODEL.md, each tooth's beam and foundation at its own
    /// load point). With both at rho1 it is k_pair(rho1) (within the splines' 1e-9). The
    /// corner contacts beyond the path (`dynamics::contact_path`) load the corner tooth at
    /// its tip and the mate where the corner touches it.
    pub fn corner_pair_stiffness_n_per_m(&self, pinion_rho1_m: f64, gear_rho1_m: f64) -> f64 {
        let [cp, cg] = &self.tooth_compliance;
        let [mp, mg] = &self.tooth_compliance_curvature;
        1.0 / (self.hertz_m_per_n
            + self.spline_at(cp, mp, pinion_rho1_m)
            + self.spline_at(cg, mg, gear_rho1_m))
    }

    /// The clamped cubic spline through `values` (second derivatives `curvature`) on the
    /// table's grid at rho1 (clamped to the path), O(1).
    fn spline_at(&self, values: &[f64], curvature: &[f64], rho1_m: f64) -> f64 {
        let n = values.len();
        let x = ((rho1_m - self.pair.rho_start_m) / self.step_m).clamp(0.0, (n - 1) as f64);
        let i = (x as usize).min(n - 2);
        let t = x - i as f64;
        let s = 1.0 - t;
        let h2 = self.step_m * self.step_m / 6.0;
        s * values[i]
            + t * values[i + 1]
            + h2 * ((s * s * s - s) * curvature[i] + (t * t * t - t) * curvature[i + 1])
    }

    /// Total mesh stiffness k_m at mesh phase `phase_rad` (pinion rotation since a pair
    /// entered contact), N/m: the pairs in contact act in parallel (docs/MODEL.md).
    pub fn total_stiffness_n_per_m(&self, phase_rad: f64) -> f64 {
        self.pair
            .pairs_in_contact(phase_rad)
            .map(|(_, rho)| self.pair_stiffness_n_per_m(rho))
            .sum()
    }

    /// Mean of k_m over a mesh period, N/m: (1/p_b) int k_pair d rho1 over the path of
    /// contact (each pair sweeps one base pitch per period), exact for the spline.
    pub fn mean_stiffness_n_per_m(&self) -> f64 {
        self.mean_n_per_m
    }

    /// Smallest k_m over a mesh period, N/m.
    pub fn min_stiffness_n_per_m(&self) -> f64 {
        self.min_n_per_m
    }

    /// Largest k_m over a mesh period, N/m.
    pub fn max_stiffness_n_per_m(&self) -> f64 {
        self.max_n_per_m
    }

    /// The tooth beams of pinion (0) and gear (1).
    pub fn tooth_beams(&self) -> &[ToothBeam; 2] {
        &self.teeth
    }

    /// Hertz compliance 1/k_h of a pair over the whole face width (paper eq. 11), m/N.
    pub fn hertz_compliance_m_per_n(&self) -> f64 {
        self.hertz_m_per_n
    }

    /// Warnings from the fillet-foundation fit (validity range).
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The fillet foundations of pinion and gear, when included.
    pub fn fillets(&self) -> Option<&[FilletFoundation; 2]> {
        self.fillets.as_ref()
    }

    /// The pair geometry the table was built for.
    pub fn pair(&self) -> &GearPair {
        &self.pair
    }

    /// The spline: first grid position rho_start (m), grid step (m), values k_pair (N/m)
    /// and second derivatives (N/m^3) at the grid points (for exact integrals of it).
    pub(crate) fn spline(&self) -> (f64, f64, &[f64], &[f64]) {
        (
            self.pair.rho_start_m,
            self.step_m,
            &self.values,
            &self.curvature,
        )
    }

    /// Positions (m) and values (N/m) of the table.
    pub fn table(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let r0 = self.pair.rho_start_m;
        self.values
            .iter()
            .enumerate()
            .map(move |(i, k)| (r0 + i as f64 * self.step_m, *k))
    }

    /// Integral of the spline over the path of contact, N: per interval
    /// h (y_i + y_i+1)/2 - h^3 (M_i + M_i+1)/24.
    fn path_integral(&self) -> f64 {
        let h = self.step_m;
        (0..self.values.len() - 1)
            .map(|i| {
                h * 0.5 * (self.values[i] + self.values[i + 1])
                    - h.powi(3) * (self.curvature[i] + self.curvature[i + 1]) / 24.0
            })
            .sum()
    }

    /// Min and max of k_m over one period, sampling each interval of constant contact
    /// count at `samples` + 1 points including its ends (one-sided limits at the jumps).
    /// Interior extrema are missed by at most ~k'' dx^2 / 8, ~1e-10 relative here.
    fn period_extrema(&self, samples: usize) -> (f64, f64) {
        let p = &self.pair;
        let mut cuts = p.contact_change_phases();
        cuts.push(p.mesh_angle_rad());
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for w in cuts.windows(2).filter(|w| w[1] > w[0]) {
            let ks: Vec<usize> = p
                .pairs_in_contact(0.5 * (w[0] + w[1]))
                .map(|(k, _)| k)
                .collect();
            for s in 0..=samples {
                let phase = w[0] + (w[1] - w[0]) * s as f64 / samples as f64;
                let rho0 = p.rho_start_m + p.pinion.base_radius_m * phase;
                let k: f64 = ks
                    .iter()
                    .map(|&k| self.pair_stiffness_n_per_m(rho0 + k as f64 * p.base_pitch_m))
                    .sum();
                lo = lo.min(k);
                hi = hi.max(k);
            }
        }
        (lo, hi)
    }
}

/// The fillet foundations of pinion and gear (Sainsot et al. 2004) as `fillet` says
/// (`None`: off); a fit the settings refuse (outside its range) is an error naming it.
fn fillet_foundations(
    pair: &GearPair,
    teeth: &[ToothBeam; 2],
    fillet: Option<FilletSettings>,
) -> Result<Option<[FilletFoundation; 2]>, StiffnessError> {
    let b = pair.face_width_m;
    let fillets = fillet.map(|set| {
        [("pinion", &pair.pinion), ("gear", &pair.gear)]
            .iter()
            .zip(teeth)
            .map(|((name, g), t)| {
                let f = FilletFoundation::new(
                    name,
                    g.root_radius_m,
                    g.bore_radius_m,
                    set.root_half_angle_rad(g, t),
                    t.youngs_modulus_pa,
                    b,
                );
                (set.refusal(&f, name), f)
            })
            .collect::<Vec<_>>()
    });
    let refusals: Vec<String> = fillets
        .iter()
        .flatten()
        .filter_map(|(r, _)| r.clone())
        .collect();
    if !refusals.is_empty() {
        return Err(StiffnessError(refusals));
    }
    Ok(fillets.map(|v| {
        let mut it = v.into_iter().map(|(_, f)| f);
        [it.next(), it.next()].map(|f| f.expect("two gears"))
    }))
}

/// Second derivatives of the clamped cubic spline through `y` on a uniform grid of step
/// h. End slopes from the fifth-order one-sided difference
/// (-25 y0 + 48 y1 - 36 y2 + 16 y3 - 3 y4)/(12 h), error O(h^4), so the spline keeps
/// O(h^4) accuracy up to the ends (a natural spline would drop to O(h^2) there).
/// Tridiagonal system solved by the Thomas algorithm (de Boor, *A Practical Guide to
/// Splines*, ch. IV).
fn clamped_spline_curvature(y: &[f64], h: f64) -> Vec<f64> {
    let n = y.len();
    let d0 = (-25.0 * y[0] + 48.0 * y[1] - 36.0 * y[2] + 16.0 * y[3] - 3.0 * y[4]) / (12.0 * h);
    let dn = (25.0 * y[n - 1] - 48.0 * y[n - 2] + 36.0 * y[n - 3] - 16.0 * y[n - 4]
        + 3.0 * y[n - 5])
        / (12.0 * h);
    let (mut diag, mut rhs) = (vec![4.0; n], vec![0.0; n]);
    diag[0] = 2.0;
    diag[n - 1] = 2.0;
    rhs[0] = 6.0 / h * ((y[1] - y[0]) / h - d0);
    rhs[n - 1] = 6.0 / h * (dn - (y[n - 1] - y[n - 2]) / h);
    for i in 1..n - 1 {
        rhs[i] = 6.0 / (h * h) * (y[i + 1] - 2.0 * y[i] + y[i - 1]);
    }
    for i in 1..n {
        let w = 1.0 / diag[i - 1];
        diag[i] -= w;
        rhs[i] -= w * rhs[i - 1];
    }
    let mut m = vec![0.0; n];
    m[n - 1] = rhs[n - 1] / diag[n - 1];
    for i in (0..n - 1).rev() {
        m[i] = (rhs[i] - m[i + 1]) / diag[i];
    }
    m
}

#[cfg(test)]
#[path = "tests_mesh.rs"]
mod tests;
