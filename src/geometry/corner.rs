//! Contact beyond the nominal path of contact: the tip corner of one tooth against the
//! flank of its mate (extended, or corner, contact).
//!
//! Perfect involutes meet only on the line of action, between the points A and E where
//! the tips cross it. A pair just before A (or just past E) is not conjugate: the driven
//! gear's tip corner (the driving pinion's, past E) stands off the mate's flank by a gap
//! that grows from zero at A (E). Under load the mesh deflects; where the deflection
//! exceeds that gap the corner touches early (or leaves late), so the load passes from pair
//! to pair gradually. This is the premature and prolonged contact of loaded spur gears
//! (Lin, Oswald & Townsend, Mech. Mach. Theory 29 (1994) 1115; Munro, Palmer & Morrish,
//! Proc. IMechE C 215 (2001) 793, measured beyond the path of contact), the extended tooth
//! contact of Ma, Song, Pang & Wen (Eng. Fail. Anal. 44 (2014) 179) and Ma, Pang, Feng,
//! Song & Wen (Eng. Fail. Anal. 48 (2015) 105). This module gives its geometry exactly;
//! `stiffness::mesh` its compliance and `dynamics::contact_path` its use in the mesh.
//!
//! Frame (this module only): pinion centre O1 at the origin, gear centre O2 = (a, 0); the
//! line of action runs from N1 = r_b1 (cos aw, sin aw) to N2 = O2 - r_b2 (cos aw, sin aw)
//! along u = (sin aw, -cos aw), length L = a sin(aw). The pinion turns clockwise, the gear
//! counterclockwise. The pair "at rho1" has its pinion flank crossing the line of action
//! rho1 from N1 and its gear flank crossing it rho2 = L - rho1 from N2 (on the path, both
//! at the same point: they touch there).
//!
//! Involute coordinates: every point X outside the pinion's base circle lies on exactly one
//! pinion drive-side involute; its *pinion label* is where that involute crosses the line
//! of action (m from N1): l1(X) = r_b1 (aw - arg X - atan(s/r_b1)) + s, s = sqrt(|X|^2 -
//! r_b1^2) the roll length of X. The involutes of one base circle are parallel curves whose
//! common normals are the base tangents, so the distance from X to the pinion flank of the
//! pair at rho1, along that flank's normal, is exactly l1(X) - rho1 (positive on the gear's
//! side), and the gradient of l1 is that unit normal, (X s - r_b1 perp(X)) / |X|^2. The
//! same holds for the gear with l2 measured from N2 (positive on the pinion's side). A
//! rounding of radius r_t is a circle: its distance to a flank is its centre's minus r_t.
//! Rotating the flank's gear alone by d theta moves the flank along its normal by
//! r_b d theta, so the gap is also the mesh deflection (along the line of action) at which
//! the corner touches when that gear alone turns.

use super::GearPair;

/// The corner where a tooth's involute ends: at its tip (sharp), at the start of a tip
/// rounding, or at the cut of a broken tip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TipCorner {
    /// Roll length (the tooth's own radius of curvature) where its involute ends, m.
    pub involute_end_rho_m: f64,
    /// Radius of the rounding between the involute and the tip land, m (0: a sharp edge).
    pub edge_radius_m: f64,
}

impl TipCorner {
    /// A sharp corner where the involute ends at roll length `rho_m` (m).
    pub fn sharp(rho_m: f64) -> Self {
        Self {
            involute_end_rho_m: rho_m,
            edge_radius_m: 0.0,
        }
    }

    /// The corner of a tooth of base radius `base_m` and tip radius `tip_m` rounded with
    /// radius `edge_m` (m): a circle tangent to the tip circle (its centre at radius
    /// r_a - r_t) and to the involute, whose tangency lies on the base tangent through the
    /// centre, r_t beyond it: rho_end = sqrt((r_a - r_t)^2 - r_b^2) + r_t.
    pub fn rounded(base_m: f64, tip_m: f64, edge_m: f64) -> Self {
        let centre = tip_m - edge_m;
        Self {
            involute_end_rho_m: (centre * centre - base_m * base_m).max(0.0).sqrt() + edge_m,
            edge_radius_m: edge_m,
        }
    }

    /// Roll length of the rounding's centre on its own involute (parallel to the flank,
    /// r_t inside the tooth), m.
    fn centre_roll_m(&self) -> f64 {
        self.involute_end_rho_m - self.edge_radius_m
    }
}

/// A corner standing off its mate's flank at one position of the pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CornerContact {
    /// Distance from the corner (its rounding) to the mate's flank along that flank's
    /// normal with the gears at their rigid positions, m: 0 at the end of the path,
    /// growing beyond it.
    pub gap_m: f64,
    /// d gap / d rho1 (dimensionless).
    pub gap_slope: f64,
    /// Where the mate's flank is touched: the mate's own radius of curvature, m.
    pub mate_rho_m: f64,
    /// d mate_rho / d rho1 (dimensionless).
    pub mate_rho_slope: f64,
}

/// A point's involute coordinate for one gear: its label (m on the line of action), roll
/// length (m) and the unit normal of the involute through it (the label's gradient).
#[derive(Debug, Clone, Copy)]
struct Label {
    value_m: f64,
    roll_m: f64,
    normal: [f64; 2],
}

/// The geometry of corner contact of one pair (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct CornerGeometry {
    rb: [f64; 2],
    centre_distance_m: f64,
    pressure_angle_rad: f64,
    loa_m: f64,
    /// Lowest and highest generated involute point of each flank (own rho), m: a contact
    /// outside leaves the involute (undercut or fillet, or past the mate's tip).
    flank_rho_m: [(f64, f64); 2],
}

/// Angular slack of the test whether a contact direction lies on a corner's arc, rad.
const ARC_SLACK_RAD: f64 = 1e-12;

fn wrap(x: f64) -> f64 {
    use std::f64::consts::PI;
    (x + PI).rem_euclid(2.0 * PI) - PI
}

/// A point relative to the gear's centre (a, 0).
fn radial_of(x: [f64; 2], centre_distance_m: f64) -> [f64; 2] {
    [x[0] - centre_distance_m, x[1]]
}

fn perp(x: [f64; 2]) -> [f64; 2] {
    [-x[1], x[0]]
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

impl CornerGeometry {
    /// The corner geometry of `pair`: its base radii, centre distance and operating
    /// pressure angle; each flank's involute from its lowest generated point to the end
    /// of its involute on the path (`pair.rho_start_m`, `pair.rho_end_m`).
    pub fn new(pair: &GearPair) -> Self {
        let l = pair.loa_length_m;
        Self {
            rb: [pair.pinion.base_radius_m, pair.gear.base_radius_m],
            centre_distance_m: pair.centre_distance_m,
            pressure_angle_rad: pair.operating_pressure_angle_rad,
            loa_m: l,
            flank_rho_m: [
                (pair.pinion.form_rho_m.max(0.0), pair.rho_end_m),
                (pair.gear.form_rho_m.max(0.0), l - pair.rho_start_m),
            ],
        }
    }

    /// Length N1N2 of the line of action, m.
    pub fn loa_length_m(&self) -> f64 {
        self.loa_m
    }

    fn gear_centre(&self) -> [f64; 2] {
        [self.centre_distance_m, 0.0]
    }

    /// Involute coordinate of X for gear `g` (0 pinion, 1 gear).
    fn label(&self, g: usize, x: [f64; 2]) -> Label {
        use std::f64::consts::PI;
        let (y, start) = match g {
            0 => (x, self.pressure_angle_rad),
            _ => {
                let c = self.gear_centre();
                ([x[0] - c[0], x[1] - c[1]], PI + self.pressure_angle_rad)
            }
        };
        let rb = self.rb[g];
        let r2 = dot(y, y);
        let s = (r2 - rb * rb).max(0.0).sqrt();
        let angle = wrap(start - y[1].atan2(y[0]) - (s / rb).atan());
        let p = perp(y);
        Label {
            value_m: rb * angle + s,
            roll_m: s,
            normal: [(y[0] * s - rb * p[0]) / r2, (y[1] * s - rb * p[1]) / r2],
        }
    }

    /// The point of gear `g`'s involute with label `label_m` at roll length `roll_m`.
    fn point(&self, g: usize, label_m: f64, roll_m: f64) -> [f64; 2] {
        use std::f64::consts::PI;
        let rb = self.rb[g];
        let (t, c) = match g {
            0 => (
                self.pressure_angle_rad - (label_m - roll_m) / rb,
                [0.0, 0.0],
            ),
            _ => (
                PI + self.pressure_angle_rad - (label_m - roll_m) / rb,
                self.gear_centre(),
            ),
        };
        let (sn, cs) = t.sin_cos();
        [c[0] + rb * cs + roll_m * sn, c[1] + rb * sn - roll_m * cs]
    }

    /// The gear's tip `corner` against the pinion flank of the pair at `rho1_m` (before
    /// the start of the path: approach). None where the touching point would leave the
    /// rounding (or the sharp corner's range of normals) or the pinion's involute.
    pub fn approach(&self, corner: TipCorner, rho1_m: f64) -> Option<CornerContact> {
        self.corner_contact(1, corner, rho1_m)
    }

    /// The pinion's tip `corner` against the gear flank of the pair at `rho1_m` (past the
    /// end of the path: recess). None as for [`CornerGeometry::approach`].
    pub fn recess(&self, corner: TipCorner, rho1_m: f64) -> Option<CornerContact> {
        self.corner_contact(0, corner, rho1_m)
    }

    /// How far beyond each end of the path the corners `gear_tip` (approach, before
    /// `start_m`) and `pinion_tip` (recess, past `end_m`) are followed: until their gap
    /// reaches `gap_limit_m`, or where they stop touching the mate's involute, whichever
    /// comes first, and never more than `max_extension_m` (m).
    pub fn reach(
        &self,
        gear_tip: TipCorner,
        pinion_tip: TipCorner,
        (start_m, end_m): (f64, f64),
        gap_limit_m: f64,
        max_extension_m: f64,
    ) -> super::pair::Reach {
        let approach = |d: f64| self.approach(gear_tip, start_m - d).map(|c| c.gap_m);
        let recess = |d: f64| self.recess(pinion_tip, end_m + d).map(|c| c.gap_m);
        super::pair::Reach {
            start_m: start_m - extension(approach, gap_limit_m, max_extension_m),
            end_m: end_m + extension(recess, gap_limit_m, max_extension_m),
        }
    }

    /// Corner of gear `g` (0 pinion, 1 gear) against the flank of the other, `m`.
    fn corner_contact(&self, g: usize, corner: TipCorner, rho1_m: f64) -> Option<CornerContact> {
        let m = 1 - g;
        let r_t = corner.edge_radius_m;
        // Own label of the corner's flank (pinion: rho1; gear: L - rho1); the rounding's
        // centre lies on the parallel involute r_t inside the tooth.
        let (own, mate) = match g {
            0 => (rho1_m, self.loa_m - rho1_m),
            _ => (self.loa_m - rho1_m, rho1_m),
        };
        let centre = self.point(g, own - r_t, corner.centre_roll_m());
        let on_mate = self.label(m, centre);
        let gap = on_mate.value_m - mate - r_t;
        // The point of the rounding nearest the mate's flank lies along -(mate normal);
        // it must lie on the arc from the involute's tangency (direction: the corner's own
        // involute normal) to the tip land's (radial). A sharp corner has the same range of
        // normals.
        let own_normal = self.label(g, centre).normal;
        let radial = match g {
            0 => centre,
            _ => radial_of(centre, self.centre_distance_m),
        };
        let towards = [-on_mate.normal[0], -on_mate.normal[1]];
        let r = dot(radial, radial).sqrt();
        let radial_unit = [radial[0] / r, radial[1] / r];
        // Directions within ARC_SLACK_RAD of the arc's ends count as on it (round-off at
        // the end of the path, where the direction is the involute's normal exactly).
        let span = cross(own_normal, radial_unit);
        let inside = cross(own_normal, towards) * span.signum() >= -ARC_SLACK_RAD
            && cross(towards, radial_unit) * span.signum() >= -ARC_SLACK_RAD
            && dot(towards, own_normal) > 0.0;
        let mate_rho = on_mate.roll_m - (on_mate.value_m - mate);
        let (lo, hi) = self.flank_rho_m[m];
        if !inside || mate_rho < lo || mate_rho > hi {
            return None;
        }
        // The centre turns with its gear: pinion clockwise (d theta / d rho1 = -1/r_b1),
        // gear counterclockwise (+1/r_b2), about its own centre; d(mate label)/d rho1 is
        // -1 for the gear's flank label (L - rho1), +1 for the pinion's.
        let arm = match g {
            0 => {
                let p = perp(centre);
                [-p[0] / self.rb[0], -p[1] / self.rb[0]]
            }
            _ => {
                let p = perp(radial);
                [p[0] / self.rb[1], p[1] / self.rb[1]]
            }
        };
        let d_mate = if g == 0 { -1.0 } else { 1.0 };
        let gap_slope = dot(on_mate.normal, arm) - d_mate;
        // mate_rho = s - gap - r_t, s the centre's roll length on the mate's base circle:
        // ds/d rho1 = (Y . dY/d rho1) / s, Y the centre about the mate's axis.
        let y = match m {
            0 => centre,
            _ => radial_of(centre, self.centre_distance_m),
        };
        Some(CornerContact {
            gap_m: gap,
            gap_slope,
            mate_rho_m: mate_rho,
            mate_rho_slope: dot(y, arm) / on_mate.roll_m - gap_slope,
        })
    }
}

/// The distance d in [0, max_m] beyond a path end up to which `gap(d)` is defined and at
/// most `limit_m`: marched in steps of max_m / 256, then bisected (60 halvings) in the
/// step that leaves.
fn extension(gap: impl Fn(f64) -> Option<f64>, limit_m: f64, max_m: f64) -> f64 {
    let within = |d: f64| gap(d).is_some_and(|g| g <= limit_m);
    let steps = 256;
    let h = max_m / steps as f64;
    let Some(i) = (1..=steps).find(|i| !within(*i as f64 * h)) else {
        return max_m;
    };
    let (mut a, mut b) = ((i - 1) as f64 * h, i as f64 * h);
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if within(m) {
            a = m;
        } else {
            b = m;
        }
    }
    a
}

#[cfg(test)]
#[path = "tests_corner.rs"]
mod tests;
