//! The text of a tick, on an axis or a colour bar.

/// The minus sign of typeset numbers (U+2212, in the embedded DejaVu Sans): a hyphen is
/// shorter and reads as a dash beside a tick.
const MINUS: &str = "\u{2212}";

/// Tick text: rounded to 9 significant digits (hides float noise such as 0.30000000000000004
/// and "-0.0"), "0" for |v| <= `zero_below` (plotters' ticks at zero can come out as
/// ~1e-16), shortest form, exponent notation outside [1e-3, 1e5), negative values and
/// exponents with a real minus sign.
pub fn tick_label(v: f64, zero_below: f64) -> String {
    let r: f64 = format!("{v:.8e}").parse().unwrap_or(v);
    let text = match r.abs() {
        a if a <= zero_below => "0".to_string(),
        a if (1e-3..1e5).contains(&a) => format!("{r}"),
        _ => format!("{r:e}"),
    };
    text.replace('-', MINUS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_hide_float_noise() {
        assert_eq!(tick_label(0.1 + 0.2, 0.0), "0.3");
        assert_eq!(tick_label(-0.0, 0.0), "0");
        assert_eq!(tick_label(500.0, 0.0), "500");
        assert_eq!(tick_label(2.5e-6, 0.0), "2.5e\u{2212}6");
        assert_eq!(tick_label(-10.6, 0.0), "\u{2212}10.6");
        assert_eq!(tick_label(2.220446049250313e-16, 1e-9), "0"); // noise on a unit-scale axis
    }
}
