//! Numbers as text for files a user reads (CSV cells, TOML values): the shortest decimal
//! that reads back to the same f64, plain (`17.24`, `6`, `0.0031`) where that is short,
//! exponent form (`2.5e-16`) for very small or large magnitudes, which plain notation
//! would pad with zeros. Python, MATLAB, spreadsheets and TOML read both; a whole number
//! is written without a decimal point (TOML then reads an integer, which float keys
//! accept).
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
}
