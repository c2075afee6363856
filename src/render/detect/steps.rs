//! One pair's narrow phase a stop at a time, for the TUI's detection
//! screen: a mesh pair's tree nodes visited then its candidate triangles,
//! a convex pair's GJK iterations then its EPA iterations, each as the
//! `detect` text's table row (`head: value` lines, the same cells), and the
//! result paragraphs as the text ends each part.

use super::blocks::{
    epa_result, epa_row, gjk_result, gjk_row, mid_phase, pair_scale, EPA_HEAD, GJK_HEAD,
};
use super::mesh_rows::{node_row, triangle_row, NODE_HEAD, TRIANGLE_HEAD};
use crate::format::Fmt;
use crate::trace::detect::PairTrace;

/// A stop of the pair's narrow phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// GJK iteration k (0-based).
    Gjk(usize),
    Epa(usize),
    /// The mesh's tree: the k-th node the traversal visited (0-based).
    Node(usize),
    /// The mesh's k-th candidate triangle tested (0-based).
    Triangle(usize),
}

/// The pair's stops in order: a mesh's tree nodes and candidate
/// triangles, then GJK's iterations, then EPA's.
pub fn stops(p: &PairTrace) -> Vec<Stop> {
    let (n, t) = p
        .mid_phase
        .as_ref()
        .map_or((0, 0), |m| (m.nodes.len(), m.triangles.len()));
    let g = p.gjk.as_ref().map_or(0, |g| g.iterations.len());
    let e = p.epa.as_ref().map_or(0, |e| e.iterations.len());
    (0..n)
        .map(Stop::Node)
        .chain((0..t).map(Stop::Triangle))
        .chain((0..g).map(Stop::Gjk))
        .chain((0..e).map(Stop::Epa))
        .collect()
}

/// The stop's title (`GJK iteration 2 of 3`) and its lines.
pub fn stop_lines(p: &PairTrace, stop: Stop, f: &Fmt) -> (String, Vec<String>) {
    let scale = pair_scale(p);
    if let Some(lines) = mesh_stop(p, stop, f, scale) {
        return lines;
    }
    let (title, head, row) = match (stop, &p.gjk, &p.epa) {
        (Stop::Gjk(k), Some(g), _) => (
            format!("GJK iteration {} of {}", k + 1, g.iterations.len()),
            &GJK_HEAD[..],
            gjk_row(g, k, f, scale),
        ),
        (Stop::Epa(k), _, Some(e)) => (
            format!("EPA iteration {} of {}", k + 1, e.iterations.len()),
            &EPA_HEAD[..],
            epa_row(e, k, f, scale),
        ),
        _ => return (String::new(), vec![]),
    };
    let lines = head
        .iter()
        .zip(row)
        .skip(1)
        .map(|(h, v)| format!("{h}: {v}"))
        .collect();
    (title, lines)
}

/// A mesh stop's title and lines (`None`: not a mesh stop).
fn mesh_stop(p: &PairTrace, stop: Stop, f: &Fmt, scale: f64) -> Option<(String, Vec<String>)> {
    let m = p.mid_phase.as_ref()?;
    let (title, head, row): (String, &[&str], Vec<String>) = match stop {
        Stop::Node(k) => (
            format!("tree node {} of {} visited", k + 1, m.nodes.len()),
            &NODE_HEAD,
            node_row(m.nodes.get(k)?, f, scale),
        ),
        Stop::Triangle(k) => (
            format!("candidate triangle {} of {}", k + 1, m.triangles.len()),
            &TRIANGLE_HEAD,
            triangle_row(m.triangles.get(k)?, f, scale),
        ),
        _ => return None,
    };
    let lines = head
        .iter()
        .zip(row)
        .map(|(h, v)| format!("{h}: {v}"))
        .collect();
    Some((title, lines))
}

/// The pair's results: the mid phase's verdict, GJK's verdict, the depth (EPA or the radii), the
/// contacts handed to the resolver.
pub fn result_lines(p: &PairTrace, f: &Fmt) -> Vec<String> {
    let scale = pair_scale(p);
    let mut out: Vec<String> = mid_phase(p, f).into_iter().collect();
    if let Some(m) = p.mid_phase.as_ref().filter(|m| m.query.is_some()) {
        out.push(format!(
            "Mesh tree: {} node(s) visited, {} candidate triangle(s) tested; least distance {}.",
            m.nodes.len(),
            m.triangles.len(),
            m.distance
                .map_or("- (no candidate)".to_string(), |d| format!(
                    "{} m",
                    f.num_at(d, scale)
                ))
        ));
    }
    if let Some(g) = &p.gjk {
        out.push(format!("GJK: {}", gjk_result(g, f, scale)));
    }
    if let Some(e) = &p.epa {
        out.push(format!("Depth: {}", epa_result(e, f, scale)));
    }
    for n in &p.notes {
        out.push(format!("Note: {n}."));
    }
    out.push(match p.contacts.len() {
        0 => "Contacts to the resolver: none.".to_string(),
        n => format!(
            "Contacts to the resolver: {n}; the deepest {} m.",
            f.num_at(
                p.contacts
                    .iter()
                    .map(|c| c.penetration)
                    .fold(f64::NEG_INFINITY, f64::max),
                scale
            )
        ),
    });
    out
}
