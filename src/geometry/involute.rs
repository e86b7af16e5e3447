//! Involute function and its inverse.

/// inv(alpha) = tan(alpha) - alpha, alpha in rad.
pub fn inv(alpha_rad: f64) -> f64 {
    alpha_rad.tan() - alpha_rad
}

/// Inverse involute: the alpha in [0, pi/2) with inv(alpha) = y (y >= 0).
///
/// Newton on f(a) = tan a - a - y, f' = tan^2 a, started from Cheng's closed-form
/// approximation a0 = (3y)^(1/3) which is within 1e-3 rad for alpha < 40 deg.
pub fn inv_inverse(y: f64) -> f64 {
    if y <= 0.0 {
        return 0.0;
    }
    let mut a = (3.0 * y).cbrt().min(1.5);
    for _ in 0..50 {
        let t = a.tan();
        let step = (t - a - y) / (t * t);
        a -= step;
        if step.abs() < 1e-15 {
            break;
        }
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_round_trips() {
        // Round trip to machine precision over the pressure angles gears use.
        for deg in [1.0_f64, 10.0, 20.0, 25.0, 35.0, 50.0] {
            let a = deg.to_radians();
            assert!((inv_inverse(inv(a)) - a).abs() < 1e-12, "{deg}");
        }
    }

    #[test]
    fn inv_20_deg_matches_table() {
        // Published involute tables: inv 20 deg = 0.014904.
        assert!((inv(20f64.to_radians()) - 0.014904).abs() < 5e-7);
    }
}
