//! The tooth-resolved mesh: every tooth of both gears with its own flank, position,
//! compliance and contact, and which teeth meet in which mesh cycle.
//!
//! Mesh cycle n (the pair that enters contact at pinion rotation n times the mesh angle
//! after t = 0) engages pinion tooth n mod z1 and gear tooth n mod z2. Pair i of the
//! contact set entered i cycles before the current one. Per tooth:
//! - the material removed from its flank along the line of action (m, positive removed:
//!   wear, reliefs, user deviation, minus the slope and form deviations, plus the gap of a
//!   full-width spall), tabulated on the wear grid (`geometry::ProfileGrid`, indexed by
//!   the pair's pinion rho1: a gear tooth's table holds its conjugate points, as the wear
//!   state does) and interpolated linearly;
//! - its position error along the line of action (m, positive proud: earlier contact);
//! - the compliance its faults add (m/N, cracks and spalls), on the same grid;
//! - the share of the face a spall takes from the contact line, on the same grid;
//! - where a broken tip ends its contact (own radius of curvature, m).
//!
//! A pair's gap is its two flanks' removed material minus their position errors, minus
//! the run-out of both gears (a rigid displacement of each gear's base circle, so common
//! to every pair at an instant: e_c cos(Omega t - phi) per gear, e_c = F_r / 2 its
//! eccentricity), with the sign of paper eq. (2) (a positive error adds compression). Its
//! stiffness is the healthy pair's k(rho1) with the fault compliances added in series.
//!
//! The excitation repeats after [`ToothMesh::periods`] mesh periods: lcm(z1, z2) when both
//! gears have teeth that differ (or run out), z1 or z2 when only one does, 1 when every
//! tooth is alike.

pub use super::contact_path::REMOVED_GAP_M;
use super::contact_path::{ContactPath, PairPlace};
use crate::geometry::corner::TipCorner;
use crate::stiffness::mesh::MeshStiffness;

/// One tooth's data (see the module docs).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToothFlank {
    /// Material removed at each grid point, m.
    pub removed_m: Vec<f64>,
    /// Position error along the line of action, m (positive: earlier contact).
    pub position_m: f64,
    /// Compliance added by faults at each grid point, m/N (None: healthy).
    pub compliance_m_per_n: Option<Vec<f64>>,
    /// Share of the face width a spall removes from the contact at each grid point.
    pub width_loss: Option<Vec<f64>>,
    /// A broken tip: the pinion rho1 beyond which this tooth makes no contact (pinion:
    /// rho1 above it; gear: rho1 below it, its own tip side), m.
    pub contact_limit_rho1_m: Option<f64>,
    /// Change of the flank's curvature by its wear at each grid point, 1/m (severe wear,
    /// `wear.worn_geometry = "worn"`; None: the involute's).
    pub curvature_change_per_m: Option<Vec<f64>>,
}

/// Run-out of one gear: an eccentricity e_c of its base circle turning with the shaft
/// (Velex & Maatar, J. Sound Vib. 191 (1996) 629, eccentricity as a displacement of the
/// gear centre). The centre
/// moves by e_c (cos(Omega t - phi'), sin(Omega t - phi')); its component along the line
/// of action, e_c cos(Omega t - phi), moves the base circle and so every pair of that
/// gear at once; the component across it changes the centre distance, which enters the
/// contact ratio and operating pressure angle only to second order in e_c and is left
/// out. A dial or ball probe in the tooth spaces reads e_c cos(theta) about its mean, a
/// range F_r = 2 e_c: the radial run-out a drawing gives (`study::teeth` takes
/// e_c = F_r / 2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Runout {
    /// Eccentricity e_c of the gear's axis, m (half the radial run-out F_r).
    pub eccentricity_m: f64,
    /// Phase phi of the eccentricity, rad.
    pub phase_rad: f64,
    /// Nominal shaft speed, rad/s.
    pub shaft_speed_rad_s: f64,
}

impl Runout {
    /// Displacement along the line of action, e_c cos(Omega t - phi) (m, positive
    /// compresses), and its rate -e_c Omega sin(Omega t - phi) (m/s).
    #[inline]
    pub fn at(&self, t_s: f64) -> (f64, f64) {
        if self.eccentricity_m == 0.0 {
            return (0.0, 0.0);
        }
        let (s, c) = (self.shaft_speed_rad_s * t_s - self.phase_rad).sin_cos();
        (
            self.eccentricity_m * c,
            -self.eccentricity_m * self.shaft_speed_rad_s * s,
        )
    }
}

/// What one pair of teeth is at a contact position.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairProps {
    /// Stiffness of the pair, N/m.
    pub stiffness_n_per_m: f64,
    /// Gap the pair must close, m (flanks and position errors; run-out not included).
    pub gap_m: f64,
    /// d gap / d rho1 (dimensionless).
    pub gap_slope: f64,
    /// Share of the face width missing from the contact line.
    pub width_loss: f64,
    /// Change of 1/R of the Hertz contact by the flanks' wear, 1/m (0: involutes).
    pub curvature_change_per_m: f64,
    /// Index of the pinion's tooth in the pair.
    pub pinion_tooth: usize,
    /// Index of the gear's tooth in the pair.
    pub gear_tooth: usize,
    /// A tip corner touches beyond the path (`dynamics::contact_path`; false: the
    /// involutes on the path, or no contact).
    pub corner: bool,
}

/// The tooth-resolved mesh of one evaluation (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ToothMesh {
    /// Pinion flanks (z1) and gear flanks (z2).
    pub pinion: Vec<ToothFlank>,
    /// Gear flanks, one per tooth (z2).
    pub gear: Vec<ToothFlank>,
    /// Run-out of the pinion and of the gear.
    pub runout: [Runout; 2],
    /// The grid: first pinion rho1 and spacing, m; points per table.
    rho_start_m: f64,
    spacing_m: f64,
    points: usize,
    periods: usize,
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// Least common multiple.
pub fn lcm(a: usize, b: usize) -> usize {
    if a == 0 || b == 0 {
        0
    } else {
        a / gcd(a, b) * b
    }
}

/// The smallest number of teeth d after which a gear's flanks repeat (tooth i + d is
/// tooth i for every i; d divides z), or z when the gear runs out (its run-out turns
/// once per revolution). Mesh cycle n meets pinion tooth n mod z1 and gear tooth
/// n mod z2, so the excitation repeats after lcm(d_pinion, d_gear) mesh periods: 1 for
/// identical teeth, z for a gear whose teeth all differ. Taking the smallest d, not z,
/// keeps the period of a wear study from growing: on a pair with common factors (20/40)
/// the teeth of one gear wear in a pattern that repeats with the other's (gear teeth b
/// and b + 20 meet the same pinion teeth), which would otherwise double it.
pub fn sequence_period(flanks: &[ToothFlank], runout: &Runout) -> usize {
    let z = flanks.len().max(1);
    if runout.eccentricity_m != 0.0 {
        return z;
    }
    (1..=z)
        .filter(|d| z.is_multiple_of(*d))
        .find(|&d| (d..flanks.len()).all(|i| flanks[i] == flanks[i - d]))
        .unwrap_or(z)
}

/// A pair that cannot touch: no stiffness, a gap no deflection closes (its contact
/// tables as they are).
fn removed(p: PairProps) -> PairProps {
    PairProps {
        stiffness_n_per_m: 0.0,
        gap_m: REMOVED_GAP_M,
        gap_slope: 0.0,
        ..p
    }
}

impl ToothMesh {
    /// The mesh from its teeth on the grid `rho_start_m + i spacing_m`, `points` points.
    pub fn new(
        pinion: Vec<ToothFlank>,
        gear: Vec<ToothFlank>,
        runout: [Runout; 2],
        rho_start_m: f64,
        spacing_m: f64,
        points: usize,
    ) -> Self {
        Self {
            periods: lcm(
                sequence_period(&pinion, &runout[0]),
                sequence_period(&gear, &runout[1]),
            ),
            pinion,
            gear,
            runout,
            rho_start_m,
            spacing_m,
            points,
        }
    }

    /// Mesh periods after which the excitation repeats (1: every tooth alike).
    pub fn periods(&self) -> usize {
        self.periods
    }

    /// Teeth of pinion and gear.
    pub fn teeth(&self) -> [usize; 2] {
        [self.pinion.len(), self.gear.len()]
    }

    /// Pinion and gear tooth of mesh cycle n.
    #[inline]
    pub fn teeth_of(&self, cycle: i64) -> (usize, usize) {
        (
            cycle.rem_euclid(self.pinion.len() as i64) as usize,
            cycle.rem_euclid(self.gear.len() as i64) as usize,
        )
    }

    /// Run-out of both gears at time t: displacement along the line of action (m,
    /// positive compresses) and its rate (m/s).
    #[inline]
    pub fn runout_at(&self, t_s: f64) -> (f64, f64) {
        let (a, da) = self.runout[0].at(t_s);
        let (b, db) = self.runout[1].at(t_s);
        (a + b, da + db)
    }

    /// The pair of mesh cycle `cycle` at pinion rho1 (m), meeting on the path of
    /// contact only (a broken tip's contact removed).
    #[inline]
    pub fn pair(&self, mesh: &MeshStiffness, cycle: i64, rho1_m: f64) -> PairProps {
        let (a, b) = self.teeth_of(cycle);
        let (fp, fg) = (&self.pinion[a], &self.gear[b]);
        let cut = fp.contact_limit_rho1_m.is_some_and(|l| rho1_m > l)
            || fg.contact_limit_rho1_m.is_some_and(|l| rho1_m < l);
        let p = self.on_path(mesh, a, b, rho1_m);
        if cut {
            return removed(p);
        }
        p
    }

    /// As [`ToothMesh::pair`] where `path` says the teeth touch: on the path, or by a
    /// tip corner beyond it (each tooth's own corner: a broken tip's cut is its corner).
    /// A helical pair's contact line (`ContactPath::helical_lines`) adds the share of the
    /// face off the path to the width lost.
    pub fn pair_in(
        &self,
        mesh: &MeshStiffness,
        path: &ContactPath,
        cycle: i64,
        rho1_m: f64,
    ) -> PairProps {
        if !path.is_extended() {
            let p = self.pair(mesh, cycle, rho1_m);
            // A helical contact line's part off the path leaves its share of the face out
            // of the Hertz contact, beside the tooth's own (docs/MODEL.md 11.10; 0 on a spur
            // pair, whose loss is then the tooth's bit for bit).
            let line_loss = path.line_width_loss_at(rho1_m);
            if line_loss == 0.0 {
                return p;
            }
            return PairProps {
                width_loss: 1.0 - (1.0 - line_loss) * (1.0 - p.width_loss),
                ..p
            };
        }
        let (a, b) = self.teeth_of(cycle);
        let (fp, fg) = (&self.pinion[a], &self.gear[b]);
        let pinion_tip = fp.contact_limit_rho1_m.map(TipCorner::sharp);
        let gear_tip = fg
            .contact_limit_rho1_m
            .map(|l| TipCorner::sharp(mesh.pair().loa_length_m - l));
        match path.place(rho1_m, pinion_tip, gear_tip) {
            None => removed(self.on_path(mesh, a, b, rho1_m)),
            Some(p) if !p.corner => self.on_path(mesh, a, b, rho1_m),
            Some(p) => self.at_corner(mesh, a, b, &p),
        }
    }

    /// Index and weight of a position on the grid (linear interpolation, clamped).
    #[inline]
    fn cell(&self, rho1_m: f64) -> (usize, f64) {
        let n = self.points;
        let u = ((rho1_m - self.rho_start_m) / self.spacing_m).clamp(0.0, (n - 1) as f64);
        let i = (u as usize).min(n - 2);
        (i, u - i as f64)
    }

    /// Pinion tooth `a` and gear tooth `b` loaded at the pinion's `place.pinion_rho1_m`
    /// and the gear's conjugate of `place.gear_rho1_m`: each flank's tables where it is
    /// touched, the corner's gap added to the flanks', the two teeth's spring
    /// (`MeshStiffness::corner_pair_stiffness_n_per_m`) with their fault compliances in
    /// series.
    fn at_corner(&self, mesh: &MeshStiffness, a: usize, b: usize, place: &PairPlace) -> PairProps {
        let (fp, fg) = (&self.pinion[a], &self.gear[b]);
        let cells = [self.cell(place.pinion_rho1_m), self.cell(place.gear_rho1_m)];
        let rates = [place.pinion_rate, place.gear_rate];
        let lerp = |v: &[f64], (i, w): (usize, f64)| v[i] + (v[i + 1] - v[i]) * w;
        let mut removed = 0.0;
        let mut slope = place.gap_slope;
        let (mut compliance, mut width_loss) = (0.0, 0.0);
        for ((f, c), rate) in [fp, fg].into_iter().zip(cells).zip(rates) {
            let r = &f.removed_m;
            removed += lerp(r, c);
            slope += (r[c.0 + 1] - r[c.0]) / self.spacing_m * rate;
            if let Some(t) = &f.compliance_m_per_n {
                compliance += lerp(t, c);
            }
            if let Some(l) = &f.width_loss {
                width_loss += lerp(l, c);
            }
        }
        let k0 = mesh.corner_pair_stiffness_n_per_m(place.pinion_rho1_m, place.gear_rho1_m);
        // Healthy teeth keep the plain pair's spring bit for bit (as on the path).
        let k = if compliance == 0.0 {
            k0
        } else {
            1.0 / (1.0 / k0 + compliance)
        };
        // The corner's gap plus the flanks' removed material, summed as the plain pair
        // sums them (`ContactPath::plain_pair`), less the position errors.
        let gap = place.gap_m + removed - fp.position_m - fg.position_m;
        PairProps {
            stiffness_n_per_m: k,
            gap_m: gap,
            gap_slope: slope,
            width_loss: width_loss.clamp(0.0, 0.95),
            curvature_change_per_m: 0.0,
            pinion_tooth: a,
            gear_tooth: b,
            corner: true,
        }
    }

    /// Pinion tooth `a` and gear tooth `b` meeting at rho1 on the path.
    #[inline]
    fn on_path(&self, mesh: &MeshStiffness, a: usize, b: usize, rho1_m: f64) -> PairProps {
        let (fp, fg) = (&self.pinion[a], &self.gear[b]);
        let n = self.points;
        let u = ((rho1_m - self.rho_start_m) / self.spacing_m).clamp(0.0, (n - 1) as f64);
        let i = (u as usize).min(n - 2);
        let w = u - i as f64;
        let lerp = |v: &[f64]| v[i] + (v[i + 1] - v[i]) * w;
        let (rp, rg) = (&fp.removed_m, &fg.removed_m);
        let gap = lerp(rp) + lerp(rg) - fp.position_m - fg.position_m;
        let slope = (rp[i + 1] - rp[i] + rg[i + 1] - rg[i]) / self.spacing_m;
        let mut compliance = 0.0;
        let mut width_loss = 0.0;
        let mut curvature = 0.0;
        for f in [fp, fg] {
            if let Some(c) = &f.compliance_m_per_n {
                compliance += lerp(c);
            }
            if let Some(l) = &f.width_loss {
                width_loss += lerp(l);
            }
            if let Some(k) = &f.curvature_change_per_m {
                curvature += lerp(k);
            }
        }
        let k0 = mesh.pair_stiffness_n_per_m(rho1_m);
        let k = if compliance == 0.0 {
            k0
        } else {
            1.0 / (1.0 / k0 + compliance)
        };
        PairProps {
            stiffness_n_per_m: k,
            gap_m: gap,
            gap_slope: slope,
            width_loss: width_loss.clamp(0.0, 0.95),
            curvature_change_per_m: curvature,
            pinion_tooth: a,
            gear_tooth: b,
            corner: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flank(removed: f64, pos: f64) -> ToothFlank {
        ToothFlank {
            removed_m: vec![removed; 3],
            position_m: pos,
            ..Default::default()
        }
    }

    #[test]
    fn periods_follow_the_teeth_that_differ() {
        let same = |z: usize| vec![flank(0.0, 0.0); z];
        let mut one = same(19);
        one[4].position_m = 1e-6;
        let r = [Runout::default(); 2];
        let m = |p: Vec<ToothFlank>, g: Vec<ToothFlank>, r: [Runout; 2]| {
            ToothMesh::new(p, g, r, 0.0, 1.0, 3).periods()
        };
        assert_eq!(m(same(19), same(31), r), 1);
        assert_eq!(m(one.clone(), same(31), r), 19);
        let mut gear_runout = r;
        gear_runout[1].eccentricity_m = 1e-6;
        assert_eq!(m(same(19), same(31), gear_runout), 31);
        assert_eq!(m(one, same(31), gear_runout), 589);
        assert_eq!(lcm(20, 40), 40);
        let tm = ToothMesh::new(same(19), same(31), r, 0.0, 1.0, 3);
        assert_eq!(tm.teeth_of(589 + 20), (1, 20));
        assert_eq!(tm.teeth_of(-1), (18, 30));
    }

    #[test]
    fn the_period_is_the_smallest_shift_that_repeats_every_engagement() {
        // The definition, by brute force: P is the smallest shift after which every mesh
        // cycle over the hunting period meets the same pair of flanks. Pairs with common
        // factors and flank patterns that repeat within a gear (as wear leaves them on
        // a 20/40 pair: gear teeth b and b + 20 alike) give less than lcm(z1, z2).
        let r = [Runout::default(); 2];
        let pattern = |z: usize, d: usize| -> Vec<ToothFlank> {
            (0..z).map(|i| flank((i % d) as f64 * 1e-6, 0.0)).collect()
        };
        for (z1, d1, z2, d2) in [
            (20, 20, 40, 20),
            (20, 20, 40, 40),
            (20, 4, 40, 10),
            (19, 19, 31, 1),
            (12, 6, 18, 9),
            (24, 1, 36, 1),
        ] {
            let (p, g) = (pattern(z1, d1), pattern(z2, d2));
            let tm = ToothMesh::new(p.clone(), g.clone(), r, 0.0, 1.0, 3);
            let hunting = lcm(z1, z2);
            let repeats = |shift: usize| {
                (0..hunting).all(|n| {
                    let (a, b) = tm.teeth_of(n as i64);
                    let (a2, b2) = tm.teeth_of((n + shift) as i64);
                    p[a] == p[a2] && g[b] == g[b2]
                })
            };
            let smallest = (1..=hunting).find(|s| repeats(*s)).unwrap();
            assert_eq!(tm.periods(), smallest, "{z1}/{z2} patterns {d1}, {d2}");
            assert_eq!(hunting % tm.periods(), 0);
        }
        // Run-out turns once per revolution whatever the flanks.
        let mut runout = r;
        runout[0].eccentricity_m = 1e-6;
        let tm = ToothMesh::new(pattern(20, 1), pattern(40, 20), runout, 0.0, 1.0, 3);
        assert_eq!(tm.periods(), 20);
        runout[1].eccentricity_m = 1e-6;
        let tm = ToothMesh::new(pattern(20, 1), pattern(40, 20), runout, 0.0, 1.0, 3);
        assert_eq!(tm.periods(), 40);
    }
}
