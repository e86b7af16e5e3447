//! Reproducible random streams: one ChaCha8 stream per (seed, index), so a draw depends
//! on the sample's index and never on which thread or shard computed it.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};

/// The random stream of item `index` under `seed`.
pub fn stream(seed: u64, index: u64) -> ChaCha8Rng {
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    r.set_stream(index);
    r
}

/// Largest seed accepted by any seed key (2^53, inclusive): every whole number up to it is
/// exact as a float, so a seed survives a JSON or Python writer unchanged.
pub const MAX_SEED: u64 = 1 << 53;

/// A value that is not a seed (outside [0, 2^53] or not a whole number): the key, the
/// value as written and, for a float between 2^52 and 2^53, why it is refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{key}` = {shown} is not a seed: expected a whole number in [0, {MAX_SEED}] (0 to 2^53 inclusive, written as an integer or as a whole float such as 9.007199254740992e15){}", .why.map(|w| format!(" ({w})")).unwrap_or_default())]
pub struct SeedError {
    /// The key (or flag) the value was given for.
    pub key: String,
    /// The value as written.
    pub shown: String,
    /// Why a float in range is refused, when it is.
    pub why: Option<&'static str>,
}

/// The error of a seed outside [0, 2^53] or not a whole number, naming `key` and the
/// value as written.
fn seed_error(key: &str, shown: &str) -> SeedError {
    SeedError {
        key: key.to_string(),
        shown: shown.to_string(),
        why: None,
    }
}

/// A seed given as a float (a TOML or Python float, IEEE 754 binary64): a whole number
/// below 2^52, where a float holds every whole number and a literal with a fraction stays
/// one, or 2^53 itself, the range's inclusive end (issue 33: the message names it, and a
/// design's float of it was refused). Between them the floats are 2 apart, so a literal
/// such as 4503599627370496.5 or 9007199254740991.0 reads as another whole number than
/// the one written: refused, asking for the integer. Err names `key`, the value and the
/// range [0, 2^53].
pub fn seed_from_f64(key: &str, x: f64) -> Result<u64, SeedError> {
    const EXACT: f64 = (1u64 << 52) as f64;
    if x.is_finite() && x.fract() == 0.0 && ((0.0..EXACT).contains(&x) || x == MAX_SEED as f64) {
        Ok(x as u64)
    } else if x.is_finite() && (EXACT..MAX_SEED as f64).contains(&x) {
        Err(SeedError {
            why: Some("a float from 2^52 up may be another number rounded: write it as an integer"),
            ..seed_error(key, &format!("{x:?}"))
        })
    } else {
        Err(seed_error(key, &format!("{x:?}")))
    }
}

/// The whole number a decimal text in float notation (`12.0`, `1.5e3`, `9.007199254740993e15`)
/// is exactly, read digit by digit (no rounding through a float): Some(Ok(n)) for a whole
/// number, Some(Err(())) for one with a fraction or beyond i128, None for text that is not
/// such a number.
fn exact_whole(t: &str) -> Option<Result<i128, ()>> {
    let (mantissa, exp) = match t.find(['e', 'E']) {
        Some(i) => (&t[..i], t[i + 1..].parse::<i32>().ok()?),
        None => (t, 0),
    };
    let (neg, digits) = match mantissa.strip_prefix('-') {
        Some(m) => (true, m),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    if int.is_empty() && frac.is_empty()
        || !int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit())
    {
        return None;
    }
    let all: Vec<u8> = int.bytes().chain(frac.bytes()).map(|b| b - b'0').collect();
    let point = int.len() as i64 + i64::from(exp);
    let mut n: i128 = 0;
    for (k, d) in all.iter().enumerate() {
        if (k as i64) < point {
            n = match n
                .checked_mul(10)
                .and_then(|n| n.checked_add(i128::from(*d)))
            {
                Some(n) => n,
                None => return Some(Err(())),
            };
        } else if *d != 0 {
            return Some(Err(()));
        }
    }
    for _ in all.len() as i64..point.max(0) {
        n = match n.checked_mul(10) {
            Some(n) => n,
            None => return Some(Err(())),
        };
    }
    Some(Ok(if neg { -n } else { n }))
}

/// A seed given as an integer; Err names `key`, the value and the range [0, 2^53].
pub fn seed_from_i128(key: &str, i: i128) -> Result<u64, SeedError> {
    if (0..=MAX_SEED as i128).contains(&i) {
        Ok(i as u64)
    } else {
        Err(seed_error(key, &i.to_string()))
    }
}

/// A seed written as text: an integer, or a whole number in float notation; Err names
/// `key`, the text and the range [0, 2^53].
pub fn parse_seed(key: &str, text: &str) -> Result<u64, SeedError> {
    let t = text.trim();
    if let Ok(i) = t.parse::<i128>() {
        return seed_from_i128(key, i);
    }
    // Float notation read exactly, digit by digit: 9007199254740993.0 is 2^53 + 1 (out
    // of range), not the float 2^53 it would round to.
    match exact_whole(t) {
        Some(Ok(i)) => seed_from_i128(key, i).map_err(|_| seed_error(key, t)),
        Some(Err(())) | None => Err(seed_error(key, &format!("{t:?}"))),
    }
}

/// Uniform on [0, 1).
pub fn uniform(r: &mut ChaCha8Rng) -> f64 {
    r.random::<f64>()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_are_reproducible_and_distinct() {
        let a: Vec<f64> = (0..4).map(|_| uniform(&mut stream(7, 3))).collect();
        assert!(a.windows(2).all(|w| w[0] == w[1]));
        let (x, y) = (uniform(&mut stream(7, 3)), uniform(&mut stream(7, 4)));
        assert_ne!(x, y);
        assert!((0.0..1.0).contains(&x));
    }

    #[test]
    fn seeds_up_to_two_to_the_53_are_accepted_in_either_notation() {
        // 2^53 by hand: 9 007 199 254 740 992, the range's inclusive end.
        assert_eq!(
            parse_seed("seed", "9.007199254740992e15"),
            Ok(9_007_199_254_740_992)
        );
        assert_eq!(
            parse_seed("seed", "9007199254740992"),
            Ok(9_007_199_254_740_992)
        );
        assert_eq!(parse_seed("seed", "0"), Ok(0));
        assert_eq!(parse_seed("seed", "7.0"), Ok(7));
        assert_eq!(parse_seed("seed", "12.50e1"), Ok(125));
        assert_eq!(parse_seed("seed", "+1.5E3"), Ok(1500));
        // One past the end (as an integer; 2^53 + 2 is the next float), a negative, a
        // fraction, text and NaN: refused naming the key, the value and the range.
        for bad in [
            "9007199254740993",
            "9.007199254740994e15",
            // Float notation is read digit by digit, not through a float that would
            // round them onto 2^53 (review finding).
            "9007199254740993.0",
            "9.007199254740993e15",
            "9007199254740991.5",
            "1e400",
            "1.5",
            ".",
            "e5",
            "-1",
            "2.5",
            "x",
            "NaN",
            "18446744073709551616",
        ] {
            let e = parse_seed("the key", bad).unwrap_err().to_string();
            assert!(
                e.contains("`the key`") && e.contains("[0, 9007199254740992]"),
                "{e}"
            );
        }
        assert!(seed_from_f64("k", f64::INFINITY).is_err());
        // A whole float is the integer it is, up to 2^53 inclusive (issue 33: the message
        // names 9.007199254740992e15 as accepted; a design's float seed was refused);
        // the next float, 2^53 + 2, and a fraction are out.
        assert_eq!(seed_from_f64("k", 9.007199254740992e15), Ok(1 << 53));
        // Between 2^52 and 2^53 a float may be another literal rounded (4503599627370496.5
        // reads as 2^52): refused, asking for the integer (review finding).
        for rounded in [4_503_599_627_370_496.0, 9_007_199_254_740_990.0] {
            let e = seed_from_f64("k", rounded).unwrap_err().to_string();
            assert!(e.contains("write it as an integer"), "{e}");
        }
        for bad in [9.007199254740994e15, 0.5, -1.0, f64::NAN] {
            let e = seed_from_f64("k", bad).unwrap_err().to_string();
            assert!(
                e.contains("`k`") && e.contains("[0, 9007199254740992]"),
                "{e}"
            );
        }
        assert_eq!(
            seed_from_f64("k", 4_503_599_627_370_495.0),
            Ok(4_503_599_627_370_495)
        );
    }
}
