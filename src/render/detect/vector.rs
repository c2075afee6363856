//! A vector as the detection's tables show it (a leaf: the page's blocks
//! and the mesh's rows both read it).

use crate::format::Fmt;
use crate::trace::detect::V3;

/// A vector whose components are round-off against `scale` (the pair's
/// size) shown as 0: a touching pair's v_k = (1e-16, 0, 1e-17) is (0, 0, 0).
pub(super) fn v_at(f: &Fmt, x: &V3, scale: f64) -> String {
    let parts: Vec<String> = x.iter().map(|c| f.num_at(*c, scale)).collect();
    format!("({})", parts.join(", "))
}
