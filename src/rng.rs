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

/// The message of a seed outside [0, 2^53] or not a whole number, naming `key` and the
/// value as written.
fn seed_error(key: &str, shown: &str) -> String {
    format!("`{key}` = {shown} is not a seed: expected a whole number in [0, {MAX_SEED}] (0 to 2^53 inclusive, written as an integer or as a whole float such as 9.007199254740992e15)")
}

/// A seed given as a number (a whole float such as 9.007199254740992e15 reads as the
/// integer it is); Err names `key`, the value and the range [0, 2^53].
pub fn seed_from_f64(key: &str, x: f64) -> Result<u64, String> {
    if x.is_finite() && x.fract() == 0.0 && (0.0..=MAX_SEED as f64).contains(&x) {
        Ok(x as u64)
    } else {
        Err(seed_error(key, &format!("{x:?}")))
    }
}

/// A seed given as an integer; Err names `key`, the value and the range [0, 2^53].
pub fn seed_from_i128(key: &str, i: i128) -> Result<u64, String> {
    if (0..=MAX_SEED as i128).contains(&i) {
        Ok(i as u64)
    } else {
        Err(seed_error(key, &i.to_string()))
    }
}

/// A seed written as text: an integer, or a whole number in float notation; Err names
/// `key`, the text and the range [0, 2^53].
pub fn parse_seed(key: &str, text: &str) -> Result<u64, String> {
    let t = text.trim();
    if let Ok(i) = t.parse::<i128>() {
        return seed_from_i128(key, i);
    }
    match t.parse::<f64>() {
        Ok(x) => seed_from_f64(key, x),
        Err(_) => Err(seed_error(key, &format!("{t:?}"))),
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
        // One past the end (as an integer; 2^53 + 2 is the next float), a negative, a
        // fraction, text and NaN: refused naming the key, the value and the range.
        for bad in [
            "9007199254740993",
            "9.007199254740994e15",
            "-1",
            "2.5",
            "x",
            "NaN",
            "18446744073709551616",
        ] {
            let e = parse_seed("the key", bad).unwrap_err();
            assert!(
                e.contains("`the key`") && e.contains("[0, 9007199254740992]"),
                "{e}"
            );
        }
        assert!(seed_from_f64("k", f64::INFINITY).is_err());
    }
}
