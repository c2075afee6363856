//! The detection as JSON (docs/detect.md): the shape scripts rely on, full
//! f64 numbers.

use serde_json::{json as j, Value};

use crate::trace::detect::{ContactLine, DetectTrace, EpaTrace, GjkTrace, PairTrace};

/// The JSON text of a detection.
pub fn json(t: &DetectTrace) -> String {
    let v = j!({
        "lesson": t.lesson,
        "step": t.step,
        "time": t.time,
        "narrow_phase": t.narrow_phase,
        "broad_phase": {
            "bodies": t.bodies.len(),
            "candidate_pairs": t.candidate_pairs,
            "pairs_ruled_out": t.dropped.len(),
            "method": t.search.method,
            "tests": t.search.tests,
            "visited": t.search.visited,
            "visited_what": t.search.visited_what,
            "kept": t.search.kept,
            "loose": t.search.loose,
            "cell": t.search.cell,
            "height": t.search.height,
            "boxes": t.bodies.iter().map(|b| j!({
                "body": b.name,
                "min": b.aabb.map(|a| a[0]),
                "max": b.aabb.map(|a| a[1]),
                "swept_min": b.swept.map(|a| a[0]),
                "swept_max": b.swept.map(|a| a[1]),
                "radius": b.radius,
            })).collect::<Vec<_>>(),
            "ruled_out": t.dropped.iter().map(|d| j!({
                "a": d.a, "b": d.b, "reason": d.reason,
            })).collect::<Vec<_>>(),
        },
        "pairs": t.pairs.iter().map(pair).collect::<Vec<_>>(),
    });
    serde_json::to_string_pretty(&v).expect("finite JSON") + "\n"
}

fn pair(p: &PairTrace) -> Value {
    let mut v = j!({
        "a": p.a,
        "b": p.b,
        "method": p.method,
        "ruled_out": p.forced,
        "mid_phase": {
            "centre_distance": p.spheres.map(|s| s.0),
            "radius_sum": p.spheres.map(|s| s.1),
            "swept_overlap": p.swept_overlap,
        },
        "gjk": p.gjk.as_ref().map(gjk),
        "epa": p.epa.as_ref().map(epa),
        "contacts": contacts(&p.contacts),
        "analytic": p.analytic.as_deref().map(contacts),
    });
    if let Some(m) = &p.mid_phase {
        // The mesh contract (docs/detect.md): the tree's nodes, the candidates, how many were tested;
        // the pair's least distance and each triangle's narrow phase.
        v["mid_phase"]["mesh_body"] = j!(m.mesh_body);
        v["mid_phase"]["query"] = j!(m.query);
        v["mid_phase"]["nodes"] = (m.nodes.iter())
            .map(|n| {
                j!({ "node": n.node, "bounds": n.bounds, "overlap": n.overlap,
                     "children": n.children, "triangle": n.triangle })
            })
            .collect();
        v["mid_phase"]["candidates"] = j!(m.candidates);
        v["mid_phase"]["tested"] = j!(m.triangles.len());
        v["distance"] = j!(m.distance);
        v["triangles"] = (m.triangles.iter())
            .map(|t| {
                j!({ "triangle": t.triangle, "distance": t.distance,
                     "penetration": t.penetration, "normal": t.normal,
                     "raw_normal": t.raw_normal, "corrected": t.rule.is_some(),
                     "rule": t.rule })
            })
            .collect();
    }
    v
}

fn gjk(g: &GjkTrace) -> Value {
    j!({
        "result": g.result,
        "end": g.end,
        "distance": g.distance,
        "closest": g.closest,
        "iterations": g.iterations.iter().map(|it| j!({
            "v": it.v,
            "direction": it.direction,
            "support": it.support,
            "support_a": it.support_a,
            "support_b": it.support_b,
            "bound": it.bound,
            "bound_limit": it.bound_limit,
            "simplex": it.simplex,
            "kept": it.kept,
            "next": it.next,
        })).collect::<Vec<_>>(),
    })
}

fn epa(e: &EpaTrace) -> Value {
    j!({
        "depth": e.depth,
        "normal": e.normal,
        "point": e.point,
        "point_a": e.point_a,
        "point_b": e.point_b,
        "feature": e.feature,
        "end": e.end,
        "source": e.source,
        "gap": e.gap,
        "tolerance": e.tolerance,
        "iterations": e.iterations.iter().map(|it| j!({
            "face": it.face,
            "normal": it.normal,
            "distance": it.distance,
            "support": it.support,
            "support_a": it.support_a,
            "support_b": it.support_b,
            "gap": it.gap,
            "removed": it.removed,
            "added": it.added,
        })).collect::<Vec<_>>(),
    })
}

fn contacts(c: &[ContactLine]) -> Value {
    c.iter()
        .map(|c| {
            let mut v = j!({ "point": c.point, "normal": c.normal, "penetration": c.penetration });
            if let Some(t) = c.triangle {
                v["triangle"] = j!(t);
            }
            v
        })
        .collect()
}
