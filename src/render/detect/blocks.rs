//! The detection as a page of headings, paragraphs and tables, numbers
//! through the one formatter; `text`, `markdown` and `latex` each lay the
//! same page out.

use super::mesh_rows::{node_row, triangle_row, NODE_HEAD, TRIANGLE_HEAD};
use super::vector::v_at;
use crate::format::Fmt;
use crate::trace::detect::{ContactLine, DetectTrace, EpaTrace, GjkTrace, PairTrace, V3};
use crate::trace::detect_mesh::MidPhase;

/// One piece of the page.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// Level 1 (the scene), 2 (a phase or a pair), 3 (a pair's part).
    Heading(u8, String),
    Para(String),
    Table {
        head: Vec<String>,
        rows: Vec<Vec<String>>,
    },
}

/// The page of a detection.
pub fn page(t: &DetectTrace, f: &Fmt) -> Vec<Block> {
    let mut out = vec![Block::Heading(
        1,
        format!("Detection — {} ({})", t.title, t.lesson),
    )];
    out.push(Block::Para(format!(
        "Step {}, t = {} s; narrow phase: {}.",
        t.step,
        f.num(t.time),
        if t.narrow_phase == "gjk" {
            "GJK/EPA for every pair but a half-space's"
        } else {
            "the analytic routine where one exists, GJK/EPA for every other convex pair"
        }
    )));
    broad(&mut out, t, f);
    for p in &t.pairs {
        pair(&mut out, p, f);
    }
    if t.pairs.is_empty() {
        out.push(Block::Para(
            "No pair reaches the narrow phase: nothing touches.".into(),
        ));
    }
    out
}

fn v(f: &Fmt, x: &V3) -> String {
    format!("({})", f.list(x))
}

fn broad(out: &mut Vec<Block>, t: &DetectTrace, f: &Fmt) {
    out.push(Block::Heading(2, "Broad phase: bounding boxes".into()));
    let rows = t
        .bodies
        .iter()
        .map(|b| {
            let or = |x: &Option<[V3; 2]>, k: usize| {
                x.as_ref().map_or("unbounded".to_string(), |a| v(f, &a[k]))
            };
            vec![
                b.name.clone(),
                or(&b.aabb, 0),
                or(&b.aabb, 1),
                b.radius.map_or("–".into(), |r| f.num(r)),
                or(&b.swept, 0),
                or(&b.swept, 1),
            ]
        })
        .collect();
    out.push(Block::Table {
        head: [
            "body",
            "box min (m)",
            "box max (m)",
            "sphere r (m)",
            "swept min (m)",
            "swept max (m)",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    out.push(Block::Para(format!(
        "{}, {} kept, {} ruled out.",
        count(t.bodies.len(), "body", "bodies"),
        count(t.candidate_pairs, "pair", "pairs"),
        t.dropped.len()
    )));
    out.push(Block::Para(t.search.words(f)));
    if !t.dropped.is_empty() {
        out.push(Block::Table {
            head: ["pair", "ruled out because"].map(String::from).to_vec(),
            rows: t
                .dropped
                .iter()
                .map(|d| vec![format!("{} – {}", d.a, d.b), d.reason.clone()])
                .collect(),
        });
    }
}

/// The size against which a pair's round-off shows as 0 (its radii sum).
pub fn pair_scale(p: &PairTrace) -> f64 {
    p.spheres.map_or(1.0, |s| s.1)
}

/// The mid phase's paragraph: bounding spheres, boxes swept over the step.
pub fn mid_phase(p: &PairTrace, f: &Fmt) -> Option<String> {
    let mut mid = vec![];
    if let Some((d, r)) = p.spheres {
        mid.push(format!(
            "bounding spheres: centres {} m apart, radii sum {} m: {}",
            f.num(d),
            f.num(r),
            if d <= r { "they overlap" } else { "apart" }
        ));
    }
    if let Some(o) = p.swept_overlap {
        mid.push(format!(
            "boxes swept over the step: {}",
            if o { "overlap" } else { "apart" }
        ));
    }
    (!mid.is_empty()).then(|| format!("Mid phase — {}.", mid.join("; ")))
}

fn pair(out: &mut Vec<Block>, p: &PairTrace, f: &Fmt) {
    let scale = pair_scale(p);
    out.push(Block::Heading(
        2,
        format!("Pair {} – {} ({})", p.a, p.b, p.method),
    ));
    if let Some(why) = &p.forced {
        out.push(Block::Para(why.clone()));
    }
    if let Some(mid) = mid_phase(p, f) {
        out.push(Block::Para(mid));
    }
    for n in &p.notes {
        out.push(Block::Para(format!("Note: {n}.")));
    }
    if let Some(m) = &p.mid_phase {
        mesh(out, m, f, scale);
    }
    if let Some(g) = &p.gjk {
        gjk(out, g, f, scale);
    }
    if let Some(e) = &p.epa {
        epa(out, e, f, scale);
    }
    out.push(Block::Heading(3, "Contacts to the resolver".into()));
    contacts(out, &p.contacts, f, scale);
    if let Some(a) = &p.analytic {
        out.push(Block::Heading(3, "The analytic routine gives".into()));
        contacts(out, a, f, scale);
    }
}

/// The GJK table's head. A row is one pass of the loop (docs/detect.md,
/// "one rule for a row"): it starts from v_k, and its d_k, w_k and bound
/// are that v_k's; the simplex with w_k added gives v_{k+1}, the next row's v_k.
pub const GJK_HEAD: [&str; 7] = [
    "k",
    "v_k",
    "d_k = -v_k",
    "w_k = s_A(d_k) - s_B(-d_k)",
    "|v_k|² - v_k·w_k",
    "simplex + w_k (✗ dropped)",
    "v_k+1",
];

/// Row `k` (0-based) of the GJK table.
pub fn gjk_row(g: &GjkTrace, k: usize, f: &Fmt, scale: f64) -> Vec<String> {
    let v = |f: &Fmt, x: &V3| v_at(f, x, scale);
    let it = &g.iterations[k];
    let simplex: Vec<String> = it
        .simplex
        .iter()
        .enumerate()
        .map(|(i, w)| {
            let mark = if it.kept.contains(&i) { "" } else { "✗" };
            format!("{}{mark}", v(f, w))
        })
        .collect();
    vec![
        (k + 1).to_string(),
        v(f, &it.v),
        v(f, &it.direction),
        format!(
            "{} = {} - {}",
            v(f, &it.support),
            v(f, &it.support_a),
            v(f, &it.support_b)
        ),
        format!("{} (ε {})", f.num(it.bound), f.num(it.bound_limit)),
        if it.next.is_some() {
            simplex.join(" ")
        } else {
            format!("{} (w_k not added)", simplex.join(" "))
        },
        it.next
            .as_ref()
            .map_or("– (stopped)".to_string(), |x| v(f, x)),
    ]
}

/// How GJK ended and its result, as the text's paragraph says it.
pub fn gjk_result(g: &GjkTrace, f: &Fmt, scale: f64) -> String {
    let verdict = match &g.closest {
        Some([a, b]) => format!(
            "separated at distance {}; closest points {} on A, {} on B",
            f.num_at(g.distance, scale),
            v_at(f, a, scale),
            v_at(f, b, scale)
        ),
        None => "intersecting".into(),
    };
    format!("Ended ({}): {}. Result: {}.", g.end, g.end_words, verdict)
}

fn gjk(out: &mut Vec<Block>, g: &GjkTrace, f: &Fmt, scale: f64) {
    out.push(Block::Heading(3, "GJK".into()));
    let rows = (0..g.iterations.len())
        .map(|k| gjk_row(g, k, f, scale))
        .collect();
    out.push(Block::Table {
        head: GJK_HEAD.map(String::from).to_vec(),
        rows,
    });
    out.push(Block::Para(gjk_result(g, f, scale)));
}

/// The EPA table's head.
pub const EPA_HEAD: [&str; 6] = ["k", "closest face", "δ_k", "w_k", "|v_k - w_k|", "faces"];

/// Row `k` (0-based) of the EPA table.
pub fn epa_row(e: &EpaTrace, k: usize, f: &Fmt, scale: f64) -> Vec<String> {
    let v = |f: &Fmt, x: &V3| v_at(f, x, scale);
    let it = &e.iterations[k];
    vec![
        (k + 1).to_string(),
        it.face
            .iter()
            .map(|p| v(f, p))
            .collect::<Vec<_>>()
            .join(" "),
        f.num_at(it.distance, scale),
        v(f, &it.support),
        f.num_at(it.gap, scale),
        if it.removed + it.added == 0 {
            "none (ended)".to_string()
        } else {
            format!("-{} +{}", it.removed, it.added)
        },
    ]
}

/// The depth's paragraph: EPA's result, or the depth from the radii.
pub fn epa_result(e: &EpaTrace, f: &Fmt, scale: f64) -> String {
    let v = |f: &Fmt, x: &V3| v_at(f, x, scale);
    if e.source == "margins" {
        return format!(
            "No EPA: the cores are apart, so the depth is the radii less the cores' distance (exact): {} m along normal {} (from B toward A), contact point {} m (A's deepest {} m, B's {} m); features {}.",
            f.num_at(e.depth, scale),
            v(f, &e.normal),
            v(f, &e.point),
            v(f, &e.point_a),
            v(f, &e.point_b),
            e.feature
        );
    }
    format!(
        "Ended ({}): depth {} m along normal {} (from B toward A), contact point {} m (A's deepest {} m, B's {} m); features {}.",
        e.end,
        f.num_at(e.depth, scale),
        v(f, &e.normal),
        v(f, &e.point),
        v(f, &e.point_a),
        v(f, &e.point_b),
        e.feature
    )
}

fn epa(out: &mut Vec<Block>, e: &EpaTrace, f: &Fmt, scale: f64) {
    if e.source == "margins" {
        out.push(Block::Heading(3, "Depth from the radii".into()));
        out.push(Block::Para(epa_result(e, f, scale)));
        return;
    }
    out.push(Block::Heading(3, "EPA".into()));
    if e.iterations.is_empty() {
        out.push(Block::Para(
            "No EPA iterations: GJK's simplex could not be grown into a solid.".into(),
        ));
    } else {
        let rows = (0..e.iterations.len())
            .map(|k| epa_row(e, k, f, scale))
            .collect();
        out.push(Block::Table {
            head: EPA_HEAD.map(String::from).to_vec(),
            rows,
        });
    }
    out.push(Block::Para(epa_result(e, f, scale)));
}

fn contacts(out: &mut Vec<Block>, c: &[ContactLine], f: &Fmt, scale: f64) {
    let v = |f: &Fmt, x: &V3| v_at(f, x, scale);
    if c.is_empty() {
        out.push(Block::Para("none".into()));
        return;
    }
    let mesh = c.iter().any(|c| c.triangle.is_some());
    let mut head = ["point", "normal", "penetration"]
        .map(String::from)
        .to_vec();
    if mesh {
        head.push("triangle".into());
    }
    out.push(Block::Table {
        head,
        rows: c
            .iter()
            .map(|c| {
                let mut row = vec![
                    v(f, &c.point),
                    v(f, &c.normal),
                    f.num_at(c.penetration, scale),
                ];
                if mesh {
                    row.push(c.triangle.map_or("-".into(), |t| t.to_string()));
                }
                row
            })
            .collect(),
    });
}

fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// Node rows shown in the text; the rest are counted (JSON has them all).
const NODE_ROWS: usize = 48;

/// A pair with a mesh: the tree's traversal (the query box, each node
/// visited), the candidate triangles, each one's narrow phase with its raw
/// and corrected normal, and the least distance.
fn mesh(out: &mut Vec<Block>, m: &MidPhase, f: &Fmt, scale: f64) {
    let v = |f: &Fmt, x: &V3, scale: f64| v_at(f, x, scale);
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
        .map(|n| node_row(n, f, scale))
        .collect();
    out.push(Block::Table {
        head: NODE_HEAD.map(String::from).to_vec(),
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
        .map(|t| triangle_row(t, f, scale))
        .collect();
    out.push(Block::Table {
        head: TRIANGLE_HEAD.map(String::from).to_vec(),
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
