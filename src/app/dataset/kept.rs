//! What a verification compares kept dataset files with their recomputation by: which
//! records of a state it takes, and the first field in which two JSON values differ.

/// Which kept records of a state a verification (`super::verify::verify_states`,
/// `super::label_check`) compares, and what its message advises.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Kept {
    /// A resume: a state whose records are all finished (an unfinished state is
    /// recomputed whole by the run); delete the record to recompute it.
    WholeStates,
    /// A merge's input: every finished record of the state (each is copied); the shard
    /// is refused.
    Finished,
    /// A whole folder's check (`verify_folder`): every finished record of the state;
    /// delete the record to recompute it.
    InFolder,
}

/// The first field (dotted path from `at`) where `a` and `b` differ, with both values.
pub(crate) fn first_difference(
    a: &serde_json::Value,
    b: &serde_json::Value,
    at: &str,
) -> Option<(String, String, String)> {
    use serde_json::Value;
    let join = |k: &str| {
        if at.is_empty() {
            k.to_owned()
        } else {
            format!("{at}.{k}")
        }
    };
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => x
            .iter()
            .find_map(|(k, v)| match y.get(k) {
                Some(w) => first_difference(v, w, &join(k)),
                None => Some((join(k), v.to_string(), "absent".into())),
            })
            .or_else(|| {
                y.iter()
                    .find(|(k, _)| !x.contains_key(*k))
                    .map(|(k, w)| (join(k), "absent".into(), w.to_string()))
            }),
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => x
            .iter()
            .zip(y)
            .enumerate()
            .find_map(|(i, (v, w))| first_difference(v, w, &join(&i.to_string()))),
        _ if a == b => None,
        _ => Some((at.to_owned(), shorten(a), shorten(b))),
    }
}

/// A JSON value for a message, cut at 60 characters.
fn shorten(v: &serde_json::Value) -> String {
    let s = v.to_string();
    match s.char_indices().nth(60) {
        Some((i, _)) => format!("{}...", &s[..i]),
        None => s,
    }
}
