//! Field-by-field comparison of two values through their serde representation, shared by
//! the deck layer's unit tests (`src/deck/tests.rs`, by `#[path]`) and the integration
//! tests (`tests/common/mod.rs`): it does not go through the deck registry, so it checks
//! the registry rather than trusting it.

/// Paths (from `root`) where `a` and `b` differ: numbers by more than `tol` relative (NaN
/// always differs), everything else by inequality, keys of `a` missing from `b`.
pub fn serde_diff<T: serde::Serialize>(root: &str, a: &T, b: &T, tol: f64) -> Vec<String> {
    fn walk(
        path: &str,
        x: &serde_json::Value,
        y: &serde_json::Value,
        tol: f64,
        out: &mut Vec<String>,
    ) {
        use serde_json::Value as J;
        match (x, y) {
            (J::Object(p), J::Object(q)) => {
                for (k, v) in p {
                    match q.get(k) {
                        Some(w) => walk(&format!("{path}.{k}"), v, w, tol, out),
                        None => out.push(format!("{path}.{k}: missing")),
                    }
                }
            }
            (J::Number(p), J::Number(q)) => {
                let (p, q) = (
                    p.as_f64().unwrap_or(f64::NAN),
                    q.as_f64().unwrap_or(f64::NAN),
                );
                let r = if p == q {
                    0.0
                } else {
                    (p - q).abs() / p.abs().max(q.abs())
                };
                if r.is_nan() || r > tol {
                    out.push(format!("{path}: {p} vs {q}"));
                }
            }
            _ => {
                if x != y {
                    out.push(format!("{path}: {x} vs {y}"));
                }
            }
        }
    }
    let mut out = Vec::new();
    match (serde_json::to_value(a), serde_json::to_value(b)) {
        (Ok(x), Ok(y)) => walk(root, &x, &y, tol, &mut out),
        _ => out.push("not serializable".into()),
    }
    out
}
