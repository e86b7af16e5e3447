//! Fuzz target over the values of a case: the input picks keys of the schema and values
//! for them (mostly inside the key's range, log-uniform where it spans decades; sometimes
//! any 64-bit float, or "derived"), so most inputs are valid cases and reach the model:
//! every combination of valid values must give finite results or a message.
//!
//! Input: 10-byte records (key index, mode, 8 bytes of value), up to 24.
//! Run: FUZZ_TARGET=case_values scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

mod common;

use gearwear::config::schema::{Range, Valid, KEYS};
use libfuzzer_sys::fuzz_target;

/// A number of `r` at fraction `f` of the way: log-uniform when the range spans decades
/// of positive numbers, linear otherwise.
fn within(r: Range, f: f64) -> f64 {
    if r.lo > 0.0 && r.hi / r.lo > 100.0 {
        (r.lo.ln() + f * (r.hi / r.lo).ln()).exp()
    } else {
        r.lo + f * (r.hi - r.lo)
    }
}

fn number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:e}")
    }
}

fuzz_target!(|data: &[u8]| {
    let mut sets = Vec::new();
    for rec in data.chunks_exact(10).take(24) {
        let spec = &KEYS[rec[0] as usize % KEYS.len()];
        let mode = rec[1] % 16;
        let bits = u64::from_le_bytes(rec[2..10].try_into().unwrap());
        let f = (bits >> 11) as f64 / (1u64 << 53) as f64;
        let raw = f64::from_bits(bits);
        let value = match spec.valid {
            Valid::Num(r) | Valid::NumOrDerived(r) => match mode {
                0 => number(raw),
                1 if matches!(spec.valid, Valid::NumOrDerived(_)) => "derived".into(),
                _ => number(within(r, f)),
            },
            Valid::Int(lo, hi) => match mode {
                0 => number(raw),
                _ => {
                    let r = Range::closed(lo as f64, hi as f64);
                    format!("{}", within(r, f).round() as i64)
                }
            },
            Valid::Choice(c) => format!("\"{}\"", c[bits as usize % c.len()]),
            Valid::Bool => format!("{}", bits % 2 == 0),
            Valid::NumArray(r) => {
                let n = 1 + (mode as usize % 4);
                let v: Vec<String> = (0..n)
                    .map(|i| number(within(r, ((f * (i + 1) as f64) / n as f64).min(1.0))))
                    .collect();
                format!("[{}]", v.join(", "))
            }
        };
        sets.push(format!("{}={value}", spec.key));
    }
    common::check_case("", &sets);
});
