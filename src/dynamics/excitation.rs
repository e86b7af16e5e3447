//! Geometric excitation of the mesh: the gap each tooth pair must close before it
//! carries load (from wear), and an optional external transmission error e(theta).
//!
//! A worn pair whose pinion flank lost h_p at rho1 and whose gear flank lost h_g at the
//! conjugate point rho2 = N1N2 - rho1 touches only after the mesh has closed
//! g = h_p + h_g along the line of action (wear is measured normal to the involute, which
//! is the line of action at the contact). The pair force is k_i max(delta - g_i, 0).
//! This is paper eq. (2) with e_t = -g, generalised to one gap per pair (the paper's
//! single e_t is the stiffness-weighted mean gap when all pairs touch).

/// Gap along the line of action as a function of the contact position rho1, tabulated on
/// a uniform grid (piecewise linear). Zero everywhere when empty. Built from the two
/// flanks' wear, it keeps each flank's table too, for contacts whose two flanks meet at
/// points that are not conjugate (corner contact, `dynamics::contact_path`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PairGap {
    rho_start_m: f64,
    spacing_m: f64,
    gap_m: Vec<f64>,
    /// Pinion and gear wear (the gear's at the conjugate points), m; None: only the sum
    /// is known.
    flanks: Option<[Vec<f64>; 2]>,
}

impl PairGap {
    /// No gap (new teeth), as a constant (a train's unworn meshes borrow it).
    pub const NONE: PairGap = PairGap {
        rho_start_m: 0.0,
        spacing_m: 0.0,
        gap_m: Vec::new(),
        flanks: None,
    };

    /// No gap (new teeth).
    pub fn none() -> Self {
        Self::default()
    }

    /// Gap values `gap_m[i]` at rho1 = rho_start + i spacing (m).
    pub fn new(rho_start_m: f64, spacing_m: f64, gap_m: Vec<f64>) -> Self {
        Self {
            rho_start_m,
            spacing_m,
            gap_m,
            flanks: None,
        }
    }

    /// The gap of a pinion flank that lost `pinion_m[i]` and a gear flank that lost
    /// `gear_m[i]` at the conjugate points of rho1 = rho_start + i spacing (m): their sum,
    /// with each flank kept.
    pub fn from_flanks(
        rho_start_m: f64,
        spacing_m: f64,
        pinion_m: Vec<f64>,
        gear_m: Vec<f64>,
    ) -> Self {
        let gap_m = pinion_m.iter().zip(&gear_m).map(|(a, b)| a + b).collect();
        Self {
            rho_start_m,
            spacing_m,
            gap_m,
            flanks: Some([pinion_m, gear_m]),
        }
    }

    /// Whether the gap is zero everywhere (new teeth).
    pub fn is_zero(&self) -> bool {
        self.gap_m.iter().all(|g| *g == 0.0)
    }

    /// Gap (m) and its slope d gap / d rho1 (dimensionless) at rho1 (clamped to the table).
    #[inline]
    pub fn at(&self, rho1_m: f64) -> (f64, f64) {
        let n = self.gap_m.len();
        if n < 2 {
            return (0.0, 0.0);
        }
        let u = ((rho1_m - self.rho_start_m) / self.spacing_m).clamp(0.0, (n - 1) as f64);
        let i = (u as usize).min(n - 2);
        let t = u - i as f64;
        let (a, b) = (self.gap_m[i], self.gap_m[i + 1]);
        (a + (b - a) * t, (b - a) / self.spacing_m)
    }

    /// The tabulated gaps, m, on the uniform rho1 grid.
    pub fn values_m(&self) -> &[f64] {
        &self.gap_m
    }

    /// Gap (m) of a contact that loads the pinion flank at `pinion_rho1_m` and the gear
    /// flank at the point conjugate to `gear_rho1_m`, and its slopes along each (d gap /d
    /// pinion_rho1, d gap / d gear_rho1): each flank's wear where it is touched. With only
    /// the sum known, the sum at the pinion's point. Clamped to the table.
    pub fn at_flanks(&self, pinion_rho1_m: f64, gear_rho1_m: f64) -> (f64, f64, f64) {
        match &self.flanks {
            None => {
                let (g, s) = self.at(pinion_rho1_m);
                (g, s, 0.0)
            }
            Some([p, g]) => {
                let (a, sa) = lerp_table(p, self.rho_start_m, self.spacing_m, pinion_rho1_m);
                let (b, sb) = lerp_table(g, self.rho_start_m, self.spacing_m, gear_rho1_m);
                (a + b, sa, sb)
            }
        }
    }
}

/// Value and slope of a table on the grid rho_start + i spacing at rho (clamped; linear).
fn lerp_table(v: &[f64], rho_start_m: f64, spacing_m: f64, rho_m: f64) -> (f64, f64) {
    let n = v.len();
    if n < 2 {
        return (0.0, 0.0);
    }
    let u = ((rho_m - rho_start_m) / spacing_m).clamp(0.0, (n - 1) as f64);
    let i = (u as usize).min(n - 2);
    let t = u - i as f64;
    (v[i] + (v[i + 1] - v[i]) * t, (v[i + 1] - v[i]) / spacing_m)
}

/// An external transmission error e(theta) over one mesh period (periodic), m, with the
/// sign of paper eq. (2): positive e adds to the mesh compression.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ExternalError {
    /// Mesh phases, rad of pinion rotation, ascending, within [0, mesh angle).
    phase_rad: Vec<f64>,
    error_m: Vec<f64>,
    period_rad: f64,
}

impl ExternalError {
    /// No error, as a constant.
    pub const NONE: ExternalError = ExternalError {
        phase_rad: Vec::new(),
        error_m: Vec::new(),
        period_rad: 0.0,
    };

    /// No external error (e = 0).
    pub fn none() -> Self {
        Self::default()
    }

    /// From samples (phase in rad, error in m) over one mesh period `period_rad`.
    /// Phases are reduced modulo the period and sorted.
    pub fn new(samples: &[(f64, f64)], period_rad: f64) -> Self {
        let mut s: Vec<(f64, f64)> = samples
            .iter()
            .map(|(p, e)| (p.rem_euclid(period_rad), *e))
            .collect();
        s.sort_by(|a, b| a.0.total_cmp(&b.0));
        Self {
            phase_rad: s.iter().map(|p| p.0).collect(),
            error_m: s.iter().map(|p| p.1).collect(),
            period_rad,
        }
    }

    /// e (m) and de/dphase (m/rad) at a mesh phase, periodic linear interpolation.
    #[inline]
    pub fn at(&self, phase_rad: f64) -> (f64, f64) {
        let n = self.phase_rad.len();
        match n {
            0 => (0.0, 0.0),
            1 => (self.error_m[0], 0.0),
            _ => {
                let p = phase_rad.rem_euclid(self.period_rad);
                let j = self.phase_rad.partition_point(|x| *x <= p);
                // Segment from sample i0 to i1, wrapping around the period.
                let (i0, i1) = if j == 0 || j == n {
                    (n - 1, 0)
                } else {
                    (j - 1, j)
                };
                let mut p0 = self.phase_rad[i0];
                let mut p1 = self.phase_rad[i1];
                let mut pp = p;
                if i1 == 0 {
                    p1 += self.period_rad;
                    if pp < p0 {
                        pp += self.period_rad;
                    }
                }
                if p1 <= p0 {
                    p0 -= self.period_rad;
                }
                let slope = (self.error_m[i1] - self.error_m[i0]) / (p1 - p0);
                (self.error_m[i0] + slope * (pp - p0), slope)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gap_interpolates_and_clamps() {
        let g = PairGap::new(1.0, 0.5, vec![0.0, 1.0, 3.0]);
        assert_eq!(g.at(1.25), (0.5, 2.0));
        assert_eq!(g.at(1.75).0, 2.0);
        assert_eq!(g.at(-5.0).0, 0.0);
        assert_eq!(g.at(9.0).0, 3.0);
        assert_eq!(PairGap::none().at(3.0), (0.0, 0.0));
    }

    #[test]
    fn external_error_is_periodic_and_exact_on_a_triangle() {
        // Triangle wave over period 4: 0 at 0, 2 at 2; linear pieces reproduced exactly.
        let e = ExternalError::new(&[(0.0, 0.0), (2.0, 2.0)], 4.0);
        assert!((e.at(1.0).0 - 1.0).abs() < 1e-15);
        assert!((e.at(3.0).0 - 1.0).abs() < 1e-15); // descending half, wraps to 0 at 4
        assert!((e.at(5.0).0 - 1.0).abs() < 1e-15); // next period
        assert!((e.at(3.0).1 + 1.0).abs() < 1e-15);
    }
}
