//! Mesh stiffness of a helical pair by the slice method: the face width b is cut into N
//! slices of width b/N; each slice is a spur pair in the transverse section, staggered
//! along the path of contact by its axial position times tan(beta_b), and the slices in
//! contact act in parallel.
//!
//! Sources: the thin-slice model of a helical gear as staggered spur slices (Flodin &
//! Andersson, Wear 249 (2001) 285, for wear); the mesh stiffness by the potential energy
//! method summed over slices (Wan, Cao, Zi, He & Chen, Mech. Mach. Theory 92 (2015) 447).
//!
//! Slice j (0 <= j < N) sits at y_j = (j + 1/2) b / N across the face (the midpoint rule;
//! y along the pinion's angular velocity, `geometry::helical`). At pinion rotation phi its
//! transverse section is the spur section at phi + s y_j tan(beta_b) / r_b1 (s = +1 right,
//! -1 left hand): the same contact positions, shifted along the path by s y_j tan(beta_b).
//! Its stiffness along the transverse line of action is the spur pair's (`stiffness::mesh`:
//! bending, shear, axial compression and fillet foundation of both teeth, Hertz) for the
//! transverse tooth form and the width b/N, with one change: the slice's contact line is
//! inclined at beta_b on the plane of action, b/(N cos beta_b) long, and a normal approach
//! delta_n = delta_t cos(beta_b) under a normal force F_n = F_t / cos(beta_b) gives, along
//! the transverse line of action, k_h,t = cos^2(beta_b) k_h,n = cos(beta_b) k_h(b/N)
//! (eq. 11 is linear in the contact length). The tooth beam takes the transverse force
//! component in the transverse section; the axial component's bending across the face is
//! neglected (a tooth is far stiffer across the face than along the profile).
//!
//! Coupling between neighbouring slices: none (the slices are independent springs, each
//! deflected by the same rigid-body approach delta_t). Effect: a loaded slice is not
//! stiffened by its unloaded neighbours, so the stiffness near the zone's corners (short
//! contact lines entering at a tip or a face end) is somewhat low and changes in N steps
//! of one slice each instead of smoothly (a coupled, elastic-foundation model would round
//! those steps off; not quantified here). The load per slice is
//! then its stiffness times delta_t, so the centre of pressure across the face is the
//! stiffness-weighted mean of the y_j in contact.
//!
//! Mesh stiffness k_m(phi) = sum_j k_slice(phi + s y_j tan(beta_b) / r_b1), N/m, along the
//! transverse line of action (the planar model's direction). Its mean over a mesh period is
//! exactly the transverse spur pair's with the Hertz term scaled (every slice has the same
//! period mean), whatever N. beta = 0 gives N identical slices of width b/N: the spur pair.

use super::iso6336::Iso6336Input;
use super::mesh::{FilletSettings, MeshStiffness, StiffnessError};
use super::potential_energy::ElasticPair;
use crate::geometry::helical::HelicalPair;
use crate::geometry::GearPair;

/// Largest slice count accepted. 10 000 slices of a 1 m face are 0.1 mm wide.
pub const MAX_SLICES: usize = 10_000;

/// One point of the slice model's mesh-stiffness curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlicePoint {
    /// Pinion rotation since pair 0 entered contact at the face y = 0, rad.
    pub phase_rad: f64,
    /// Mesh stiffness along the transverse line of action, N/m.
    pub stiffness_n_per_m: f64,
    /// Centre of pressure across the face (stiffness-weighted mean of the loaded slices'
    /// positions y_j), m from the face y = 0.
    pub centre_of_pressure_m: f64,
    /// Number of (slice, tooth pair) contacts.
    pub slice_contacts: usize,
    /// Length of the contact lines the slices in contact represent, each b/(N cos beta_b), m.
    pub contact_length_m: f64,
}

/// The slice model of a helical pair's mesh stiffness, built once. See the module docs.
#[derive(Debug, Clone)]
pub struct SliceMeshStiffness {
    pair: HelicalPair,
    /// One slice: the transverse section with face width b/N and the inclined Hertz term.
    slice: MeshStiffness,
    /// Slice positions y_j across the face, m.
    positions_m: Vec<f64>,
    /// Phase lead of slice j over the section at y = 0: s y_j tan(beta_b) / r_b1, rad.
    phase_leads_rad: Vec<f64>,
    /// Exact integral of the slice's spline along the path, for the N -> infinity limit.
    integral: SplineIntegral,
}

/// Exact integral of a slice's clamped cubic spline from the path's start A to rho1.
#[derive(Debug, Clone)]
struct SplineIntegral {
    rho_start_m: f64,
    step_m: f64,
    values: Vec<f64>,
    curvature: Vec<f64>,
    /// Integral up to each grid point, N.
    cumulative: Vec<f64>,
}

impl SplineIntegral {
    fn new(m: &MeshStiffness) -> Self {
        let (rho_start_m, step_m, values, curvature) = m.spline();
        let mut me = Self {
            rho_start_m,
            step_m,
            values: values.to_vec(),
            curvature: curvature.to_vec(),
            cumulative: vec![0.0],
        };
        for i in 0..values.len() - 1 {
            let whole = me.partial(i, 1.0);
            me.cumulative.push(me.cumulative[i] + whole);
        }
        me
    }

    /// Integral over the first fraction tau of interval i, N: with s = 1 - t, the spline
    /// S = s y_i + t y_i+1 + h^2/6 [(s^3 - s) M_i + (t^3 - t) M_i+1] integrates to
    /// h [y_i (tau - tau^2/2) + y_i+1 tau^2/2 + h^2/6 (M_i (-(1-tau)^4/4 + (1-tau)^2/2 - 1/4)
    ///   + M_i+1 (tau^4/4 - tau^2/2))].
    fn partial(&self, i: usize, tau: f64) -> f64 {
        let h = self.step_m;
        let r = 1.0 - tau;
        let (t2, r2) = (tau * tau, r * r);
        h * (self.values[i] * (tau - 0.5 * t2)
            + self.values[i + 1] * 0.5 * t2
            + h * h / 6.0
                * (self.curvature[i] * (-0.25 * r2 * r2 + 0.5 * r2 - 0.25)
                    + self.curvature[i + 1] * (0.25 * t2 * t2 - 0.5 * t2)))
    }

    /// Integral of k_slice from A to rho1 (clamped to the path), N.
    fn at(&self, rho1_m: f64) -> f64 {
        let n = self.values.len();
        let x = ((rho1_m - self.rho_start_m) / self.step_m).clamp(0.0, (n - 1) as f64);
        let i = (x as usize).min(n - 2);
        self.cumulative[i] + self.partial(i, x - i as f64)
    }
}

impl SliceMeshStiffness {
    /// Build the model with `slices` slices (1..=[`MAX_SLICES`]) and each slice's table of
    /// `table_points` along the path of contact (as [`MeshStiffness::with_fillet`]).
    pub fn new(
        pair: &HelicalPair,
        elastic: &ElasticPair,
        slices: usize,
        table_points: usize,
        fillet: Option<FilletSettings>,
    ) -> Result<Self, StiffnessError> {
        if !(1..=MAX_SLICES).contains(&slices) {
            return Err(StiffnessError(vec![format!(
                "the slice count {slices} is invalid: it must lie in [1, {MAX_SLICES}]"
            )]));
        }
        let n = slices as f64;
        let mut section = pair.transverse.clone();
        section.face_width_m = pair.face_width_m / n;
        let hertz_factor = pair.base_helix_angle_rad.cos();
        let slice = MeshStiffness::with_hertz_factor(
            &section,
            elastic,
            table_points,
            fillet,
            hertz_factor,
        )?;
        let positions_m: Vec<f64> = (0..slices)
            .map(|j| pair.face_width_m * (j as f64 + 0.5) / n)
            .collect();
        let rb1 = pair.transverse.pinion.base_radius_m;
        let phase_leads_rad = positions_m
            .iter()
            .map(|&y| pair.stagger_m(y) / rb1)
            .collect();
        Ok(Self {
            pair: pair.clone(),
            integral: SplineIntegral::new(&slice),
            slice,
            positions_m,
            phase_leads_rad,
        })
    }

    /// The pair the model was built for.
    pub fn pair(&self) -> &HelicalPair {
        &self.pair
    }

    /// The single slice's model (transverse section, width b/N).
    pub fn slice(&self) -> &MeshStiffness {
        &self.slice
    }

    /// Number of slices N.
    pub fn slices(&self) -> usize {
        self.positions_m.len()
    }

    /// Slice positions y_j across the face, m.
    pub fn positions_m(&self) -> &[f64] {
        &self.positions_m
    }

    /// Stiffness of each slice at pinion rotation `phase_rad` (all its pairs in contact),
    /// N/m, into `out` (length N).
    pub fn slice_stiffnesses(&self, phase_rad: f64, out: &mut [f64]) {
        for (k, lead) in out.iter_mut().zip(&self.phase_leads_rad) {
            *k = self.slice.total_stiffness_n_per_m(phase_rad + lead);
        }
    }

    /// Mesh stiffness k_m at pinion rotation `phase_rad`, N/m.
    pub fn stiffness_n_per_m(&self, phase_rad: f64) -> f64 {
        self.phase_leads_rad
            .iter()
            .map(|lead| self.slice.total_stiffness_n_per_m(phase_rad + lead))
            .sum()
    }

    /// The slice model's limit as N grows without bound, N/m: the stiffness per unit
    /// face width N k_slice / b integrated along each exact contact line
    /// (`HelicalPair::contact_lines`),
    ///   k_m(phi) = N / (b tan beta_b) sum over lines of int_{rho_lo}^{rho_hi} k_slice d rho1
    /// (d rho1 = tan(beta_b) dy along a line), with the spline integrated exactly. A
    /// second route to the same quantity: the slice sum converges to it as 1/N.
    pub fn continuous_stiffness_n_per_m(&self, phase_rad: f64) -> f64 {
        let n = self.slices() as f64;
        let slope = self.pair.base_helix_angle_rad.tan();
        let rho_a = self.pair.transverse.rho_start_m;
        let lines = self.pair.contact_lines(phase_rad);
        if slope == 0.0 {
            let k = |u: f64| self.slice.pair_stiffness_n_per_m(rho_a + u);
            return n * lines.iter().map(|l| k(l.path_m.0)).sum::<f64>();
        }
        let sum: f64 = lines
            .iter()
            .map(|l| {
                let (u0, u1) = l.path_m;
                self.integral.at(rho_a + u0.max(u1)) - self.integral.at(rho_a + u0.min(u1))
            })
            .sum();
        n * sum / (self.pair.face_width_m * slope)
    }

    /// Stiffness, centre of pressure and contacts at pinion rotation `phase_rad`.
    pub fn point(&self, phase_rad: f64) -> SlicePoint {
        let (mut k, mut moment, mut contacts) = (0.0, 0.0, 0);
        let tp = self.slice.pair();
        for (y, lead) in self.positions_m.iter().zip(&self.phase_leads_rad) {
            for (_, rho) in tp.pairs_in_contact(phase_rad + lead) {
                let kj = self.slice.pair_stiffness_n_per_m(rho);
                k += kj;
                moment += kj * y;
                contacts += 1;
            }
        }
        let width = self.pair.face_width_m / self.slices() as f64;
        SlicePoint {
            phase_rad,
            stiffness_n_per_m: k,
            centre_of_pressure_m: moment / k,
            slice_contacts: contacts,
            contact_length_m: contacts as f64 * width / self.pair.base_helix_angle_rad.cos(),
        }
    }

    /// The curve over one mesh period at `n` uniform phases (i / n of the period, i < n).
    pub fn table(&self, n: usize) -> Vec<SlicePoint> {
        let period = self.pair.transverse.mesh_angle_rad();
        (0..n)
            .map(|i| self.point(period * i as f64 / n as f64))
            .collect()
    }

    /// Mean of k_m over a mesh period, N/m: N times the slice's period mean (each slice
    /// sweeps the same curve, shifted in phase), exact for the slice's spline.
    pub fn mean_stiffness_n_per_m(&self) -> f64 {
        self.slices() as f64 * self.slice.mean_stiffness_n_per_m()
    }

    /// The moments int_A^E k(rho) rho^n drho (n = 0, 1, 2; N, N m, N m^2) of one slice's
    /// tooth-pair stiffness k (N/m) over the transverse path of contact [A, E], rho the
    /// distance along the line of action from the pinion's base-circle tangency point N1
    /// (m): composite Simpson's rule on [`PATH_MOMENT_INTERVALS`] intervals. Each tooth
    /// pair sweeps the path once per base pitch p_b, so the period mean of any slice sum
    /// sum_i k(rho_i) f(rho_i) is (1/p_b) int k f drho (its n = 0 moment times N / p_b is
    /// the mean mesh stiffness); the tilting degrees of freedom take their mean lever and
    /// tilting stiffness from them (docs/MODEL.md 11.8).
    pub fn path_moments(&self) -> [f64; 3] {
        let t = &self.pair.transverse;
        let (a, e) = (t.rho_start_m, t.rho_end_m);
        let n = PATH_MOMENT_INTERVALS;
        let h = (e - a) / n as f64;
        let mut m = [0.0; 3];
        for i in 0..=n {
            let w = match i {
                0 => 1.0,
                i if i == n => 1.0,
                i if i % 2 == 1 => 4.0,
                _ => 2.0,
            };
            let r = a + i as f64 * h;
            let k = self.slice.pair_stiffness_n_per_m(r);
            m[0] += w * k;
            m[1] += w * k * r;
            m[2] += w * k * r * r;
        }
        m.map(|x| x * h / 3.0)
    }

    /// Smallest and largest k_m over `n` uniform phases of a mesh period, N/m.
    pub fn sampled_extrema_n_per_m(&self, n: usize) -> (f64, f64) {
        let period = self.pair.transverse.mesh_angle_rad();
        (0..n)
            .map(|i| self.stiffness_n_per_m(period * i as f64 / n as f64))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), k| {
                (lo.min(k), hi.max(k))
            })
    }
}

/// Intervals of [`SliceMeshStiffness::path_moments`]' Simpson rule (even): the slice's
/// stiffness is a spline on the slice table's own spacing, finer than this only for
/// tables above 4000 points, and its integral then converges as h^4 still.
pub const PATH_MOMENT_INTERVALS: usize = 4000;

/// Most table points of the contact line's stiffness (a helix angle near 0 would ask for
/// ever finer ones: its slices' stagger vanishes).
const MAX_LINE_POINTS: usize = 100_000;

impl SliceMeshStiffness {
    /// The slice model as one spring per tooth pair, for the planar dynamics
    /// (`study::helical_dynamics`, docs/MODEL.md section 11.1): the pair's whole contact
    /// line, placed by the position rho of its trailing end on the transverse path (the
    /// face end furthest back: y = 0 for a right-hand pinion, y = b for a left-hand one).
    /// Its slices sit at rho + o_j, o_j = (j + 1/2) L / N with L = b tan(beta_b) (either
    /// hand: the set of staggers is the same), so the line's stiffness is
    ///   K(rho) = sum_j k_slice(rho + o_j),  the sum over the slices on the path [A, E],
    /// N/m, and the line is in contact for rho in [A - L, E]. Returned: the "line pair" (the
    /// transverse pair whose path starts at A - L, so its contact ratio is
    /// epsilon_alpha + epsilon_beta) and K tabulated on it at the slice spacing L / N (no
    /// coarser than the slice's own table; each sample lies between two slice entries) and
    /// interpolated by the clamped cubic spline, which rounds off the steps of one slice
    /// (1/N of a full line). The line pair at phase phi is the slice model at
    /// phi - L / r_b1 (the time origin shifts). Returned last: the line's extent L, m.
    ///
    /// A line whose slice spacing L / N is below the table's finest spacing (the path over
    /// `MAX_LINE_POINTS`: a helix angle below about 0.03 deg on the paper's 20 mm face
    /// with 100 slices) cannot be resolved: several of its slices meet the path within one
    /// table step, down to a whole pair's jump, which rings in the spline (measured on the
    /// paper's pair with 100 slices: a dynamic factor of 1.623 at 1e-4 deg and 1.6145 at
    /// 5e-4 deg against 1.600 at 0). Such a line is taken as its N slices in phase, L = 0:
    /// the transverse pair with N times the slice's own table, the spur pair of the whole
    /// face (its stagger is then under 1/1000 of the path).
    ///
    /// One slice is its own line: the slice model itself, L = 0 (a jump of a whole pair's
    /// stiffness would ring in the spline; with N >= 2 each step is 1/N of a line).
    pub fn line_model(&self) -> (GearPair, MeshStiffness, f64) {
        let t = &self.pair.transverse;
        if self.slices() == 1 {
            return (t.clone(), self.slice.clone(), 0.0);
        }
        let LineGrid {
            line,
            lead,
            points,
            step_m: h,
            offsets,
        } = self.line_grid();
        let n = self.slices() as f64;
        if lead / n < h {
            let (_, _, values, _) = self.slice.spline();
            let k: Vec<f64> = values.iter().map(|v| n * v).collect();
            let extrema = (20 * k.len()).min(20_000);
            let mesh = MeshStiffness::from_table(&self.slice, t.clone(), k, extrema);
            return (t.clone(), mesh, 0.0);
        }
        let on_path = |r: &f64| (t.rho_start_m..=t.rho_end_m).contains(r);
        let k: Vec<f64> = (0..points)
            .map(|i| {
                let rho = line.rho_start_m + i as f64 * h;
                offsets
                    .iter()
                    .map(|o| rho + o)
                    .filter(on_path)
                    .map(|r| self.slice.pair_stiffness_n_per_m(r))
                    .sum()
            })
            .collect();
        let extrema = (20 * points).min(20_000);
        let mesh = MeshStiffness::from_table(&self.slice, line.clone(), k, extrema);
        (line, mesh, lead)
    }
}

/// Where the contact line of [`SliceMeshStiffness::line_model`] is sampled.
#[derive(Debug, Clone)]
pub(crate) struct LineGrid {
    /// The line pair: the transverse pair with its path start moved to A - L.
    pub(crate) line: GearPair,
    /// The line's extent L = b tan(beta_b) along the path, m.
    pub(crate) lead: f64,
    /// Samples over the line pair's path and their spacing, m.
    pub(crate) points: usize,
    pub(crate) step_m: f64,
    /// The slices' offsets o_j = (j + 1/2) L / N from the line's trailing end, m.
    pub(crate) offsets: Vec<f64>,
}

impl SliceMeshStiffness {
    /// The line pair and its samples (N >= 2): at the slice spacing L / N, no coarser than
    /// the slice's own table, at most [`MAX_LINE_POINTS`] of them.
    pub(crate) fn line_grid(&self) -> LineGrid {
        let t = &self.pair.transverse;
        let lead = self.pair.face_width_m * self.pair.base_helix_angle_rad.tan();
        let mut line = t.clone();
        line.rho_start_m = t.rho_start_m - lead;
        line.contact_ratio = line.path_length_m() / line.base_pitch_m;
        let n = self.slices() as f64;
        let (_, slice_step, values, _) = self.slice.spline();
        let span = line.path_length_m();
        let step = slice_step.min(lead / n).max(span / MAX_LINE_POINTS as f64);
        let points = ((span / step).ceil() as usize + 1).max(values.len());
        let h = span / (points - 1) as f64;
        let offsets: Vec<f64> = (0..self.slices())
            .map(|j| lead * (j as f64 + 0.5) / n)
            .collect();
        LineGrid {
            line,
            lead,
            points,
            step_m: h,
            offsets,
        }
    }

    /// The contact line of the model's line pair as [`SliceMeshStiffness::line_model`]
    /// builds it: [`SliceMeshStiffness::line_grid`], or, where that takes the slices in
    /// phase (one slice, or a stagger below the table's spacing), the transverse pair with
    /// every slice at offset 0 and L = 0.
    pub(crate) fn model_line_grid(&self) -> LineGrid {
        let g = self.line_grid();
        if self.slices() > 1 && g.lead / self.slices() as f64 >= g.step_m {
            return g;
        }
        LineGrid {
            line: self.pair.transverse.clone(),
            lead: 0.0,
            offsets: vec![0.0; self.slices()],
            ..g
        }
    }

    /// The face slice (index j of `positions_m`) that the line's slice at offset o_i sits
    /// on: the line's trailing end is the face end y = 0 of a right-hand pinion (slice i is
    /// face slice i), y = b of a left-hand one (face slice N - 1 - i).
    pub(crate) fn face_slice_of_line_slice(&self, i: usize) -> usize {
        match self.pair.hand_pinion {
            crate::geometry::helical::Hand::Right => i,
            crate::geometry::helical::Hand::Left => self.slices() - 1 - i,
        }
    }

    /// Adds the stiffness (N/m) of each slice of the contact line whose trailing end is at
    /// `rho_m` on the line pair (docs/MODEL.md 11.1) to `out[j]`, j the face slice it sits
    /// on (slices off the transverse path [A, E] add nothing). `grid` is
    /// [`SliceMeshStiffness::line_grid`]'s.
    pub(crate) fn add_line_slices(&self, grid: &LineGrid, rho_m: f64, out: &mut [f64]) {
        let t = &self.pair.transverse;
        for (i, o) in grid.offsets.iter().enumerate() {
            let r = rho_m + o;
            if (t.rho_start_m..=t.rho_end_m).contains(&r) {
                out[self.face_slice_of_line_slice(i)] += self.slice.pair_stiffness_n_per_m(r);
            }
        }
    }
}

/// ISO 6336-1 Method B inputs for a helical pair: the normal section's rack (alpha_n,
/// h_fP / m_n = (r - r_f) / m_n + x_n from each gear's root radius), beta, x_n, and the
/// transverse contact ratio epsilon_alpha. `Iso6336Input::evaluate` then applies the helical
/// factors: z_n = z / (cos^2(beta_b) cos(beta)) in q', cos(beta) in c'.
pub fn iso6336_input(
    pair: &HelicalPair,
    blank_factor: f64,
    line_load_n_per_mm: Option<f64>,
) -> Iso6336Input {
    let t = &pair.transverse;
    let mn = pair.normal_module_m;
    // x_n m_n = x_t m_t: the rack's displacement in length.
    let shift = |g: &crate::geometry::Gear| g.profile_shift * t.module_m / mn;
    let dedendum = |g: &crate::geometry::Gear| (g.pitch_radius_m - g.root_radius_m) / mn + shift(g);
    Iso6336Input {
        teeth_pinion: t.pinion.teeth as f64,
        teeth_gear: t.gear.teeth as f64,
        profile_shift_pinion: shift(&t.pinion),
        profile_shift_gear: shift(&t.gear),
        helix_angle_rad: pair.helix_angle_rad,
        normal_pressure_angle_rad: pair.normal_pressure_angle_rad,
        dedendum_coefficient_pinion: dedendum(&t.pinion),
        dedendum_coefficient_gear: dedendum(&t.gear),
        transverse_contact_ratio: pair.transverse_contact_ratio,
        blank_factor,
        line_load_n_per_mm,
    }
}

#[cfg(test)]
#[path = "tests_helical.rs"]
mod tests;
