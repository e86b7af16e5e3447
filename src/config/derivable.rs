//! A case value the geometry can supply: a number, or the string `"derived"`.

use serde::de::{self, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// A number the case gives, or `"derived"`: computed from the geometry when the model is
/// built (hub bores in `geometry::GearPair`, masses and inertias in
/// `geometry::blank`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Derivable {
    /// A value the case gives, in the unit of its key.
    Given(f64),
    /// `"derived"`: computed from the geometry when the model is built.
    Derived,
}

impl Derivable {
    /// The given number, if any.
    pub fn given(self) -> Option<f64> {
        match self {
            Derivable::Given(x) => Some(x),
            Derivable::Derived => None,
        }
    }

    /// The given number, or `estimate` when derived.
    pub(crate) fn or_derived(self, estimate: f64) -> f64 {
        self.given().unwrap_or(estimate)
    }
}

impl Serialize for Derivable {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Derivable::Given(x) => s.serialize_f64(*x),
            Derivable::Derived => s.serialize_str("derived"),
        }
    }
}

impl<'de> Deserialize<'de> for Derivable {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Derivable;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or \"derived\"")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> Result<Derivable, E> {
                Ok(Derivable::Given(x))
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> Result<Derivable, E> {
                Ok(Derivable::Given(x as f64))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> Result<Derivable, E> {
                Ok(Derivable::Given(x as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Derivable, E> {
                if v == "derived" {
                    Ok(Derivable::Derived)
                } else {
                    Err(E::invalid_value(de::Unexpected::Str(v), &self))
                }
            }
        }
        d.deserialize_any(V)
    }
}
