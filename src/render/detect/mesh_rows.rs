//! A mesh pair's mid phase as rows: one per tree node visited, one per
//! candidate triangle's narrow phase. The `detect` text's tables and the
//! TUI's detection screen (a node or a triangle a stop) read these, so the
//! two say the same cells.

use super::vector::v_at;
use crate::format::Fmt;
use crate::trace::detect_mesh::{NodeLine, TriangleLine};

/// The node table's head.
pub const NODE_HEAD: [&str; 5] = ["node", "box min", "box max", "overlaps the query", "then"];

/// The candidate triangles' table head.
pub const TRIANGLE_HEAD: [&str; 6] = [
    "triangle",
    "distance",
    "penetration",
    "raw normal",
    "normal",
    "internal edge",
];

/// One visited node's row.
pub fn node_row(n: &NodeLine, f: &Fmt, scale: f64) -> Vec<String> {
    let what = match (n.triangle, n.children.as_slice()) {
        (Some(t), _) if n.overlap => format!("leaf: triangle {t} is a candidate"),
        (Some(t), _) => format!("leaf: triangle {t}"),
        (None, []) => "-".to_string(),
        (None, c) => format!(
            "push {}",
            c.iter()
                .map(|k| k.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    vec![
        n.node.to_string(),
        v_at(f, &n.bounds[0], scale),
        v_at(f, &n.bounds[1], scale),
        if n.overlap { "yes" } else { "no" }.to_string(),
        what,
    ]
}

/// One candidate triangle's row.
pub fn triangle_row(t: &TriangleLine, f: &Fmt, scale: f64) -> Vec<String> {
    vec![
        t.triangle.to_string(),
        f.num_at(t.distance, scale),
        f.num_at(t.penetration, scale),
        v_at(f, &t.raw_normal, 1.0),
        v_at(f, &t.normal, 1.0),
        t.rule
            .map_or("kept".to_string(), |r| format!("corrected: {r}")),
    ]
}
