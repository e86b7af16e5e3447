//! The vocabulary of the key table ([`super::schema::KEYS`]): what a key's valid values
//! are ([`Valid`], over a [`Range`] of numbers) and what is said about it ([`KeySpec`]).

/// An interval of numbers; `open_lo` / `open_hi` exclude an end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Whether the lower end is excluded.
    pub open_lo: bool,
    /// Whether the upper end is excluded.
    pub open_hi: bool,
}

impl Range {
    /// [lo, hi].
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: false,
            open_hi: false,
        }
    }

    /// (lo, hi].
    pub const fn above(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: true,
            open_hi: false,
        }
    }

    /// [lo, hi).
    pub const fn below(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: false,
            open_hi: true,
        }
    }

    /// (lo, hi).
    pub const fn open(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: true,
            open_hi: true,
        }
    }

    /// Whether `x` is a normal (finite, not subnormal) number inside the interval. Zero
    /// is normal here; subnormal numbers (below 2.2e-308 in magnitude) are not: no
    /// quantity of a gear case lies there, and they overflow the solvers' divisions.
    pub fn contains(&self, x: f64) -> bool {
        let normal = x == 0.0 || x.is_normal();
        let lo_ok = if self.open_lo {
            x > self.lo
        } else {
            x >= self.lo
        };
        let hi_ok = if self.open_hi {
            x < self.hi
        } else {
            x <= self.hi
        };
        normal && lo_ok && hi_ok
    }

    /// "[0.1, 50]", "(0, 0.5)", ...
    pub fn describe(&self) -> String {
        format!(
            "{}{}, {}{}",
            if self.open_lo { "(" } else { "[" },
            number(self.lo),
            number(self.hi),
            if self.open_hi { ")" } else { "]" }
        )
    }
}

/// A number as people write it: 0.1, 50, 1e-11, 1e6.
pub fn number(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// What values a key accepts.
#[derive(Debug, Clone, Copy)]
pub enum Valid {
    /// A finite number in the range.
    Num(Range),
    /// A number in the range, or the string "derived" (the model computes it from the
    /// geometry).
    NumOrDerived(Range),
    /// A whole number in [lo, hi] (written 25 or 25.0).
    Int(i64, i64),
    /// One of these strings.
    Choice(&'static [&'static str]),
    /// true or false.
    Bool,
    /// A non-empty array of numbers, each in the range.
    NumArray(Range),
}

impl Valid {
    /// Human text of the valid values, used in messages and docs.
    pub fn describe(&self) -> String {
        match self {
            Valid::Num(r) => format!("a number in {}", r.describe()),
            Valid::NumOrDerived(r) => format!("a number in {}, or \"derived\"", r.describe()),
            Valid::Int(a, b) => format!("a whole number in [{a}, {}]", number(*b as f64)),
            Valid::Choice(c) => format!(
                "one of {}",
                c.iter()
                    .map(|s| format!("\"{s}\""))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            Valid::Bool => "true or false".into(),
            Valid::NumArray(r) => format!("an array of numbers in {}", r.describe()),
        }
    }
}

/// One key of the case file.
#[derive(Debug, Clone, Copy)]
pub struct KeySpec {
    /// Dotted path, `section.key`.
    pub key: &'static str,
    /// Unit ("-" for dimensionless).
    pub unit: &'static str,
    /// What it is, and the source of its default.
    pub doc: &'static str,
    /// The values it accepts.
    pub valid: Valid,
    /// Why the valid range is what it is.
    pub reason: &'static str,
}

pub(super) const fn k(
    key: &'static str,
    unit: &'static str,
    valid: Valid,
    doc: &'static str,
    reason: &'static str,
) -> KeySpec {
    KeySpec {
        key,
        unit,
        doc,
        valid,
        reason,
    }
}
