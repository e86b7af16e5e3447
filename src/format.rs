//! Numbers as text for files a user reads (CSV cells, TOML values): the shortest decimal
//! that reads back to the same f64, plain (`17.24`, `6`, `0.0031`) where that is short,
//! exponent form (`2.5e-16`) for very small or large magnitudes, which plain notation
//! would pad with zeros. Python, MATLAB, spreadsheets and TOML read both; a whole number
//! is written without a decimal point (TOML then reads an integer, which float keys
//! accept).
//!
//! Numbers for people (standard output, warnings, the HTML report, figure labels) follow
//! one rule, [`shown`]: four significant digits (what the model's inputs and the solver's
//! tolerances support), trailing zeros dropped, plain notation from 0.001 to 9999 and
//! exponent form (`2.16e5`) outside; a whole number below 1e9 (a count, an input given
//! whole, a product of exact inputs such as the mesh frequency) prints whole. Percentages
//! are shown to 0.1 % ([`shown_percent`]). The files keep every digit ([`format_number`]).
//!
//! Pieces of user input echoed in messages are cut by [`clip`].

/// See the module docs.
pub fn format_number(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || (1e-4..1e15).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// Significant digits of a number shown to a person (see the module docs).
pub const SHOWN_DIGITS: i32 = 4;

/// Whole numbers up to this magnitude print whole (see the module docs).
const WHOLE_UP_TO: f64 = 1e9;

/// A number for a person: the rule in the module docs. Non-finite values read `n/a`.
pub fn shown(v: f64) -> String {
    if !v.is_finite() {
        return "n/a".into();
    }
    if v.fract() == 0.0 && v.abs() < WHOLE_UP_TO {
        // `+ 0.0` turns -0 into 0.
        return format!("{}", v + 0.0);
    }
    // Rounded to SHOWN_DIGITS first, so that 9999.7 becomes 1e4 and then takes its form.
    let e = format!("{:.*e}", (SHOWN_DIGITS - 1) as usize, v);
    let (mantissa, exp) = e.split_once('e').unwrap_or((&e, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let trim = |t: &str| -> String {
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            t.to_owned()
        }
    };
    if (-3..SHOWN_DIGITS).contains(&exp) {
        let decimals = (SHOWN_DIGITS - 1 - exp).max(0) as usize;
        let rounded: f64 = e.parse().unwrap_or(v);
        trim(&format!("{rounded:.decimals$}"))
    } else {
        format!("{}e{exp}", trim(mantissa))
    }
}

/// The digits of a percentage: 0.1 % from 0.1 % up (one decimal, fewer digits than
/// [`SHOWN_DIGITS`] below 1000 %), [`shown`] below, so a small share is not shown as 0.
fn percent_digits(p: f64) -> String {
    if !p.is_finite() || p.fract() == 0.0 || p.abs() < 0.1 {
        shown(p)
    } else {
        format!("{p:.1}")
    }
}

/// `fraction` as a percentage for a person: `24.1 %`, `50 %`, `0.0027 %`.
pub fn shown_percent(fraction: f64) -> String {
    format!("{} %", percent_digits(100.0 * fraction))
}

/// A signed percentage for a person, `+33.3 %` / `-12.9 %` (deviations, changes).
pub fn shown_signed_percent(fraction: f64) -> String {
    let p = percent_digits(100.0 * fraction);
    if fraction > 0.0 && p != "0" {
        format!("+{p} %")
    } else {
        format!("{p} %")
    }
}

/// Longest piece of user input echoed in a message, characters.
pub const SHOWN_CHARS: usize = 80;

/// `text` cut to `max` characters, with an ellipsis and the full length when cut.
pub fn clip(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        None => text.to_owned(),
        Some((at, _)) => format!("{}... ({} characters)", &text[..at], text.chars().count()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_where_short_and_read_back_exactly() {
        assert_eq!(format_number(17.24369713551461), "17.24369713551461");
        assert_eq!(format_number(6.0), "6");
        assert_eq!(format_number(-0.0031), "-0.0031");
        assert_eq!(format_number(2.5e-16), "2.5e-16");
        assert_eq!(format_number(4e20), "4e20");
        for v in [1.0 / 3.0, 2.5e-16, 1e-4, 9.99e14, 1e15, -123.456, 0.0] {
            assert_eq!(format_number(v).parse::<f64>().unwrap(), v);
        }
    }

    #[test]
    fn shown_to_four_significant_digits() {
        // The examples: a bin's torque and speed, a report's torque.
        assert_eq!(shown(94.44373932210253), "94.44");
        assert_eq!(shown(35.00863846017447), "35.01");
        assert_eq!(shown(72.61729728691999), "72.62");
        assert_eq!(shown(3373.6408), "3374");
        assert_eq!(shown(1.28456), "1.285");
        assert_eq!(shown(1.600_04), "1.6");
        assert_eq!(shown(-0.0123456), "-0.01235");
        assert_eq!(shown(0.00123456), "0.001235");
        assert_eq!(shown(0.000123456), "1.235e-4");
        assert_eq!(shown(216012.646667), "2.16e5");
        assert_eq!(shown(4.000_912_345_6e8), "4.001e8");
        // A whole number below 1e9 is whole (a count, an exact product).
        assert_eq!(shown(4.0009e8), "400090000");
        // Rounding that carries into the next decade takes that decade's form.
        assert_eq!(shown(9999.7), "1e4");
        assert_eq!(shown(0.99996), "1");
        // Exact values print exactly.
        assert_eq!(shown(570.0), "570");
        assert_eq!(shown(40000.0), "40000");
        assert_eq!(shown(-0.0), "0");
        assert_eq!(shown(f64::NAN), "n/a");
        assert_eq!(shown(f64::INFINITY), "n/a");
        // Never more than four significant digits in a non-whole number: the shown value
        // is within half a unit of the fourth digit.
        for v in [
            1.0 / 3.0,
            2.0f64.sqrt() * 1e3,
            std::f64::consts::PI * 1e-2,
            123.456_789,
        ] {
            let back: f64 = shown(v).parse().unwrap();
            assert!((back - v).abs() <= 0.5e-3 * v.abs(), "{v} -> {}", shown(v));
        }
    }

    #[test]
    fn percentages() {
        assert_eq!(shown_percent(0.24133), "24.1 %");
        assert_eq!(shown_percent(0.5), "50 %");
        // A dust bin's share is not rounded away.
        assert_eq!(shown_percent(2.7e-7), "2.7e-5 %");
        assert_eq!(shown_percent(0.000_274_49), "0.02745 %");
        assert_eq!(shown_signed_percent(0.333), "+33.3 %");
        assert_eq!(shown_signed_percent(-0.12941), "-12.9 %");
        assert_eq!(shown_signed_percent(0.0), "0 %");
    }
}
