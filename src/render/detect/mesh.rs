//! A pair with a mesh on the detection page: the tree's traversal (the
//! query box, each node visited), the candidate triangles, each one's
//! narrow phase with its raw and corrected normal, and the least distance.

use super::blocks::Block;
use crate::format::Fmt;
use crate::trace::detect_mesh::MidPhase;

/// Node rows shown in the text; the rest are counted (JSON has them all).
const NODE_ROWS: usize = 48;

fn v(f: &Fmt, x: &[f64; 3], scale: f64) -> String {
    let parts: Vec<String> = x.iter().map(|c| f.num_at(*c, scale)).collect();
    format!("({})", parts.join(", "))
}

/// The mid phase's blocks.
pub fn blocks(out: &mut Vec<Block>, m: &MidPhase, f: &Fmt, scale: f64) {
    let Some(query) = &m.query else {
        return;
    };
    out.push(Block::Heading(
        3,
        format!("Mid phase: the mesh's tree (body {}'s frame)", m.mesh_body),
    ));
    let pushed = m.nodes.iter().filter(|n| !n.children.is_empty()).count();
    out.push(Block::Para(format!(
        "Query box (the other body's, in the mesh's frame, grown by the contact margin): {} to {}. {} visited ({} overlapping it, {} opened); {} candidate {}: {}.",
        v(f, &query[0], scale),
        v(f, &query[1], scale),
        count(m.nodes.len(), "node", "nodes"),
        m.nodes.iter().filter(|n| n.overlap).count(),
        pushed,
        m.candidates.len(),
        if m.candidates.len() == 1 { "triangle" } else { "triangles" },
        if m.candidates.is_empty() {
            "none".to_string()
        } else {
            m.candidates.iter().map(|t| t.to_string()).collect::<Vec<_>>().join(", ")
        }
    )));
    let rows = (m.nodes.iter().take(NODE_ROWS))
        .map(|n| {
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
                v(f, &n.bounds[0], scale),
                v(f, &n.bounds[1], scale),
                if n.overlap { "yes" } else { "no" }.to_string(),
                what,
            ]
        })
        .collect();
    out.push(Block::Table {
        head: ["node", "box min", "box max", "overlaps the query", "then"]
            .map(String::from)
            .to_vec(),
        rows,
    });
    if m.nodes.len() > NODE_ROWS {
        out.push(Block::Para(format!(
            "… {} more nodes (the JSON lists every one).",
            m.nodes.len() - NODE_ROWS
        )));
    }
    out.push(Block::Heading(
        3,
        "Each candidate triangle's narrow phase".into(),
    ));
    if m.triangles.is_empty() {
        out.push(Block::Para("No candidate: nothing to test.".into()));
        return;
    }
    let rows = (m.triangles.iter())
        .map(|t| {
            vec![
                t.triangle.to_string(),
                f.num_at(t.distance, scale),
                f.num_at(t.penetration, scale),
                v(f, &t.raw_normal, 1.0),
                v(f, &t.normal, 1.0),
                t.rule
                    .map_or("kept".to_string(), |r| format!("corrected: {r}")),
            ]
        })
        .collect();
    out.push(Block::Table {
        head: [
            "triangle",
            "distance",
            "penetration",
            "raw normal",
            "normal",
            "internal edge",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    if let Some(d) = m.distance {
        out.push(Block::Para(format!(
            "Least distance over the candidates: {} m{}.",
            f.num_at(d, scale),
            if d == 0.0 {
                " (touching or overlapping)"
            } else {
                ""
            }
        )));
    }
}

fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}
