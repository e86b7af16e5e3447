//! Masses and polar inertias of the gear blanks, estimated from the geometry (the values
//! a case may ask for with `"derived"`; docs/MODEL.md, section 7).
//!
//! Each gear is a solid disk of the face width b with a central bore r_int, out to its
//! reference (pitch) radius r = m z / 2 (Gere & Goodno, *Mechanics of Materials*,
//! appendix: hollow circular cylinder):
//!   m = rho pi (r^2 - r_int^2) b,   J = m (r^2 + r_int^2) / 2   (kg, kg m^2).
//! Why the pitch radius: the toothed rim between the root and tip circles is about half
//! steel (tooth and space are equally wide at the pitch circle), and half of the ring
//! r_f..r_a has nearly the area of the full ring r_f..r (paper pinion: 84.4 against
//! 88.8 mm^2). The tip radius would count the tooth spaces as steel and overestimate the
//! mass by 15-25 % for usual tooth counts; a test compares the estimate with the blank
//! whose rim carries the real involute teeth.

use super::pair::{Gear, GearPair};
use crate::config::case::BodyValues;
use std::f64::consts::PI;

/// Mass (kg) and polar moment of inertia about the axis (kg m^2) of a solid disk of
/// outer radius `outer_m`, bore radius `bore_m` and width `width_m`, density in kg/m^3.
pub fn disk_with_bore(
    outer_m: f64,
    bore_m: f64,
    width_m: f64,
    density_kg_per_m3: f64,
) -> (f64, f64) {
    let (r2, ri2) = (outer_m * outer_m, bore_m * bore_m);
    let mass = density_kg_per_m3 * PI * (r2 - ri2) * width_m;
    (mass, mass * (r2 + ri2) / 2.0)
}

/// The blank of one gear: (mass, polar inertia).
pub fn blank_of(gear: &Gear, width_m: f64, density_kg_per_m3: f64) -> (f64, f64) {
    disk_with_bore(
        gear.pitch_radius_m,
        gear.bore_radius_m,
        width_m,
        density_kg_per_m3,
    )
}

impl GearPair {
    /// Masses and polar inertias of both blanks (see the module docs).
    pub(crate) fn blank_estimates(&self, density_kg_per_m3: f64) -> BodyValues {
        let (mp, jp) = blank_of(&self.pinion, self.face_width_m, density_kg_per_m3);
        let (mg, jg) = blank_of(&self.gear, self.face_width_m, density_kg_per_m3);
        BodyValues {
            mass_pinion_kg: mp,
            mass_gear_kg: mg,
            inertia_pinion_kg_m2: jp,
            inertia_gear_kg_m2: jg,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::{Derivable, GearSection};

    /// The 25/50-tooth, 3 mm pair of issue 10 (30 mm wide) with derived bores.
    fn pair_25_50() -> GearPair {
        GearPair::from_case(&GearSection {
            module_mm: 3.0,
            teeth_pinion: 25,
            teeth_gear: 50,
            face_width_mm: 30.0,
            hub_bore_radius_pinion_mm: Derivable::Derived,
            hub_bore_radius_gear_mm: Derivable::Derived,
            ..Default::default()
        })
        .unwrap()
    }

    #[test]
    fn estimates_match_hand_formulas_for_a_steel_disk_with_a_bore() {
        // By hand, steel 7850 kg/m^3, b = 30 mm:
        // pinion r = 3 x 25 / 2 = 37.5 mm, r_f = 37.5 - 3.75 = 33.75 mm, r_int = 16.875 mm;
        //   m = 7850 pi (0.0375^2 - 0.016875^2) 0.03 = 7850 pi 1.1214844e-3 0.03 = 0.8297247 kg,
        //   J = m (0.0375^2 + 0.016875^2) / 2 = 0.8297247 x 1.6910156e-3 / 2 = 7.015387e-4 kg m^2;
        // gear r = 75 mm, r_f = 71.25 mm, r_int = 35.625 mm;
        //   m = 7850 pi (0.075^2 - 0.035625^2) 0.03 = 7850 pi 4.3558594e-3 0.03 = 3.222661 kg,
        //   J = 3.222661 x (0.075^2 + 0.035625^2) / 2 = 3.222661 x 6.8941406e-3 / 2 = 1.110874e-2.
        // Tolerance 1e-6: the hand values carry 7 significant digits.
        let e = pair_25_50().blank_estimates(7850.0);
        for (got, hand) in [
            (e.mass_pinion_kg, 0.8297247),
            (e.inertia_pinion_kg_m2, 7.015387e-4),
            (e.mass_gear_kg, 3.222661),
            (e.inertia_gear_kg_m2, 1.110874e-2),
        ] {
            assert!((got / hand - 1.0).abs() < 1e-6, "{got} vs {hand}");
        }
    }

    #[test]
    fn pitch_disk_is_within_a_few_per_cent_of_the_blank_with_real_teeth() {
        // Second method: the body to the root circle plus z teeth whose thickness s(r) is
        // integrated from the root to the tip circle (involute above the base circle, the
        // base-circle thickness below it, as the tooth beam does). 6 % covers the fillets'
        // extra steel, which this integral leaves out.
        let p = pair_25_50();
        for g in [&p.pinion, &p.gear] {
            let rho = 7850.0;
            let b = p.face_width_m;
            let (body, j_body) = disk_with_bore(g.root_radius_m, g.bore_radius_m, b, rho);
            let n = 20_000;
            let dr = (g.tip_radius_m - g.root_radius_m) / n as f64;
            let (mut m_teeth, mut j_teeth) = (0.0, 0.0);
            for i in 0..n {
                let r = g.root_radius_m + (i as f64 + 0.5) * dr;
                let s = g.thickness_at_radius_m(r.max(g.base_radius_m));
                let dm = rho * b * g.teeth as f64 * s * dr;
                m_teeth += dm;
                j_teeth += dm * r * r;
            }
            let (m, j) = blank_of(g, b, rho);
            assert!(((body + m_teeth) / m - 1.0).abs() < 0.06, "mass {m}");
            assert!(((j_body + j_teeth) / j - 1.0).abs() < 0.06, "inertia {j}");
        }
    }
}
