//! The text of a tick, on an axis or a colour bar.

/// Tick text: rounded to 9 significant digits (hides float noise such as 0.30000000000000004
/// and "-0.0"), "0" for |v| <= `zero_below` (plotters' ticks at zero can come out as
/// ~1e-16), shortest form, exponent notation outside [1e-3, 1e5).
pub fn tick_label(v: f64, zero_below: f64) -> String {
    let r: f64 = format!("{v:.8e}").parse().unwrap_or(v);
    match r.abs() {
        a if a <= zero_below => "0".to_string(),
        a if (1e-3..1e5).contains(&a) => format!("{r}"),
        _ => format!("{r:e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_hide_float_noise() {
        assert_eq!(tick_label(0.1 + 0.2, 0.0), "0.3");
        assert_eq!(tick_label(-0.0, 0.0), "0");
        assert_eq!(tick_label(500.0, 0.0), "500");
        assert_eq!(tick_label(2.5e-6, 0.0), "2.5e-6");
        assert_eq!(tick_label(2.220446049250313e-16, 1e-9), "0"); // noise on a unit-scale axis
    }
}
