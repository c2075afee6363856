//! The description of a scene's detection (`contact-lab detect`): the broad
//! phase's boxes and verdicts, the mid phase's spheres and swept boxes, each
//! pair's GJK and EPA iterations, and the contacts, in words and numbers.
//! Built from the physics record (`physics::collide::record`) and the
//! bodies' names, nothing else; renderers in `render/detect/` show it.

use nalgebra::Vector3;

use super::Plane;
use crate::physics::collide::record::{
    minkowski_outline, DetectRecord, Method, PairRecord, RuledOut,
};
use crate::physics::collide::{ContactPoint, NarrowPhase, Pose};
use crate::physics::detect::epa::EpaRecord;
use crate::physics::detect::{GjkEnd, GjkIteration, GjkVerdict};
use crate::physics::{Body, Shape};

pub type V3 = [f64; 3];

/// One body's bounds.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyBox {
    pub name: String,
    /// `None`: a half-space (unbounded) or no shape.
    pub aabb: Option<[V3; 2]>,
    pub swept: Option<[V3; 2]>,
    pub radius: Option<f64>,
}

/// A pair the broad phase dropped, and why, in words.
#[derive(Debug, Clone, PartialEq)]
pub struct Dropped {
    pub a: String,
    pub b: String,
    pub reason: String,
}

/// One GJK iteration: everything in it belongs to the same pass, which
/// starts from v_k (docs/detect.md, "one rule for a row").
#[derive(Debug, Clone, PartialEq)]
pub struct GjkStep {
    /// v_k, the closest point the pass starts from.
    pub v: V3,
    /// d_k = -v_k.
    pub direction: V3,
    /// w_k = s_A(d_k) - s_B(-d_k), and the two shape points.
    pub support: V3,
    pub support_a: V3,
    pub support_b: V3,
    /// |v_k|² - v_k·w_k and its limit ε|v_k|².
    pub bound: f64,
    pub bound_limit: f64,
    /// The simplex with w_k added, and which of its points were kept
    /// (the simplex unchanged when the pass stopped at the bound).
    pub simplex: Vec<V3>,
    pub kept: Vec<usize>,
    /// v_{k+1}, the kept simplex's closest point (the next pass's v);
    /// `None` when the pass stopped at the bound.
    pub next: Option<V3>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct GjkTrace {
    /// "separated" or "intersecting".
    pub result: &'static str,
    /// Why it ended (`GjkEnd::json_name`) and in words.
    pub end: &'static str,
    pub end_words: String,
    pub distance: f64,
    /// On A and on B (world), when separated.
    pub closest: Option<[V3; 2]>,
    pub iterations: Vec<GjkStep>,
}

/// One EPA split.
#[derive(Debug, Clone, PartialEq)]
pub struct EpaStep {
    /// The face closest to the origin, its outward normal n_k and distance δ_k.
    pub face: [V3; 3],
    pub normal: V3,
    pub distance: f64,
    pub support: V3,
    pub support_a: V3,
    pub support_b: V3,
    /// n_k·w_k - δ_k = |v_k - w_k| along n_k.
    pub gap: f64,
    pub removed: usize,
    pub added: usize,
}

#[derive(Debug, Clone, PartialEq)]
pub struct EpaTrace {
    pub depth: f64,
    pub normal: V3,
    pub point: V3,
    pub point_a: V3,
    pub point_b: V3,
    pub feature: &'static str,
    pub end: &'static str,
    /// "epa" or "margins" (a sphere's or capsule's radius on its core's distance).
    pub source: &'static str,
    pub gap: f64,
    pub tolerance: f64,
    pub iterations: Vec<EpaStep>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLine {
    pub point: V3,
    pub normal: V3,
    pub penetration: f64,
    /// The mesh triangle the contact is on, in a pair with a mesh.
    pub triangle: Option<usize>,
}

/// One pair's detection.
#[derive(Debug, Clone, PartialEq)]
pub struct PairTrace {
    pub a: String,
    pub b: String,
    /// Set when the broad phase dropped the pair and it ran because asked for.
    pub forced: Option<String>,
    /// Mid phase: centre distance, the sum of the bounding radii, and the
    /// verdict of the boxes swept over the step.
    pub spheres: Option<(f64, f64)>,
    pub swept_overlap: Option<bool>,
    /// "analytic" or "gjk".
    pub method: &'static str,
    pub gjk: Option<GjkTrace>,
    pub epa: Option<EpaTrace>,
    pub contacts: Vec<ContactLine>,
    pub analytic: Option<Vec<ContactLine>>,
    /// The Minkowski difference A - B's outline in the figure's plane
    /// (world coordinates), for the SVG.
    pub minkowski: Vec<V3>,
    pub notes: Vec<String>,
    /// A pair with a mesh: its mid phase (the tree's traversal, the
    /// candidate triangles and each one's narrow phase).
    pub mid_phase: Option<super::detect_mesh::MidPhase>,
}

/// A scene's detection.
#[derive(Debug, Clone, PartialEq)]
pub struct DetectTrace {
    pub lesson: String,
    pub title: String,
    pub step: u64,
    pub time: f64,
    /// "analytic" or "gjk".
    pub narrow_phase: &'static str,
    pub plane: Plane,
    pub bodies: Vec<BodyBox>,
    /// Each body's shape and pose, for the figure.
    pub drawn: Vec<Drawn>,
    pub candidate_pairs: usize,
    /// The step's broad phase on these boxes: method, visits, tests, pairs.
    pub search: super::broad_search::BroadSearch,
    pub dropped: Vec<Dropped>,
    pub pairs: Vec<PairTrace>,
    /// With continuous detection on, each body's movement bounds over the
    /// next step (empty when it is off; set by the session).
    pub movement: Vec<Option<super::movement::Movement>>,
}

/// Where the trace's bodies are, for the figure: shape and pose of each.
#[derive(Debug, Clone, PartialEq)]
pub struct Drawn {
    pub name: String,
    pub shape: Option<Shape>,
    pub position: V3,
    pub orientation: [f64; 4],
}

/// The bodies as drawn.
pub fn drawn(bodies: &[Body<f64>], names: &[String]) -> Vec<Drawn> {
    bodies
        .iter()
        .zip(names)
        .map(|(b, name)| {
            let q = b.state.orientation;
            Drawn {
                name: name.clone(),
                shape: b.shape.clone(),
                position: v(&b.state.position),
                orientation: [q.w, q.i, q.j, q.k],
            }
        })
        .collect()
}

/// What the trace needs besides the record.
pub struct Context<'a> {
    pub lesson: &'a str,
    pub title: &'a str,
    pub step: u64,
    pub time: f64,
    pub narrow_phase: NarrowPhase,
    pub plane: Plane,
    pub names: &'a [String],
    pub bodies: &'a [Body<f64>],
}

/// The trace of a record.
pub fn build(cx: &Context, record: &DetectRecord) -> DetectTrace {
    let name = |i: usize| cx.names[i].clone();
    let bodies = record
        .bounds
        .iter()
        .enumerate()
        .map(|(i, b)| BodyBox {
            name: name(i),
            aabb: b.aabb.as_ref().map(|a| [v(&a.min), v(&a.max)]),
            swept: b.swept.as_ref().map(|a| [v(&a.min), v(&a.max)]),
            radius: b.radius,
        })
        .collect();
    let dropped = record
        .ruled_out
        .iter()
        .map(|&((i, j), why)| Dropped {
            a: name(i),
            b: name(j),
            reason: reason(why),
        })
        .collect();
    DetectTrace {
        lesson: cx.lesson.to_string(),
        title: cx.title.to_string(),
        step: cx.step,
        time: cx.time,
        narrow_phase: match cx.narrow_phase {
            NarrowPhase::Analytic => "analytic",
            NarrowPhase::Gjk => "gjk",
        },
        plane: cx.plane,
        bodies,
        drawn: drawn(cx.bodies, cx.names),
        candidate_pairs: record.candidates.len(),
        search: super::broad_search::BroadSearch::of(&record.broad),
        dropped,
        pairs: record.pairs.iter().map(|p| pair(cx, p)).collect(),
        movement: Vec::new(),
    }
}

/// The broad phase's reason in words.
pub fn reason(why: RuledOut) -> String {
    match why {
        RuledOut::NoShape => "a body has no shape".into(),
        RuledOut::BothImmovable => "both bodies are immovable".into(),
        RuledOut::BoxesApart { axis } => format!(
            "their bounding boxes are apart along {}",
            ["x", "y", "z"][axis]
        ),
    }
}

/// Why GJK ended, in words.
pub fn gjk_end_words(end: GjkEnd) -> &'static str {
    match end {
        GjkEnd::Converged => "the bounds met: |v|² - v·w ≤ ε|v|², v is the closest point",
        GjkEnd::NoProgress => "no progress: w was already in the simplex or v did not shrink",
        GjkEnd::OriginInside => "the origin is inside the tetrahedron: the shapes intersect",
        GjkEnd::Touching => "|v| within the touching tolerance: the origin is on the simplex",
        GjkEnd::IterationCap => "the iteration cap was reached",
    }
}

fn pair(cx: &Context, p: &PairRecord) -> PairTrace {
    let (a, b) = (cx.names[p.body1].clone(), cx.names[p.body2].clone());
    let mut notes = vec![];
    let gjk = p.query.as_ref().map(|q| {
        let g = &q.gjk;
        let separated = g.verdict == GjkVerdict::Separated;
        GjkTrace {
            result: g.verdict.json_name(),
            end: g.end.json_name(),
            end_words: gjk_end_words(g.end).to_string(),
            distance: if separated { g.distance } else { 0.0 },
            closest: separated.then(|| [v(&g.closest_a), v(&g.closest_b)]),
            iterations: p.gjk.iter().map(gjk_step).collect(),
        }
    });
    if p.query
        .as_ref()
        .is_some_and(|q| q.gjk.margins != [0.0, 0.0])
    {
        notes.push(
            "GJK runs on the cores (a sphere's centre, a capsule's segment) and adds the radii at the end"
                .into(),
        );
    }
    let epa = p.query.as_ref().and_then(|q| {
        let pen = q.penetration.as_ref()?;
        let found = q.epa.as_ref();
        Some(EpaTrace {
            depth: pen.depth,
            normal: v(&pen.normal),
            point: v(&pen.point),
            point_a: v(&pen.point_a),
            point_b: v(&pen.point_b),
            feature: pen.feature.json_name(),
            end: found.map_or("margins", |e| e.end.json_name()),
            source: pen.source.json_name(),
            gap: found.map_or(0.0, |e| e.gap),
            tolerance: found.map_or(0.0, |e| e.tolerance),
            iterations: p.epa.iter().map(epa_step).collect(),
        })
    });
    let mid_phase = p.mesh.as_ref().map(super::detect_mesh::mid_phase);
    if let Some(m) = &mid_phase {
        notes.push(match m.query {
            Some(_) => "a mesh is not convex: its tree gives the candidate triangles, and each triangle (a convex shape) runs GJK/EPA against the other body".into(),
            None => "a mesh against a half-space: the mesh's vertices at or below the plane".into(),
        });
    } else if p.query.is_none() {
        notes.push(
            "a half-space has no support mapping: the plane routine takes the other shape's deepest points"
                .into(),
        );
    }
    let forced = p.ruled_out.map(|why| {
        format!(
            "the broad phase rules this pair out ({}); its narrow phase runs because it was asked for",
            reason(why)
        )
    });
    let (s1, s2) = (&cx.bodies[p.body1], &cx.bodies[p.body2]);
    let axes = {
        let (u, w, _) = cx.plane.axes();
        (u, w)
    };
    let minkowski = match (&s1.shape, &s2.shape) {
        (Some(x), Some(y)) => minkowski_outline(
            (x, &Pose::new(s1.state.position, &s1.state.orientation)),
            (y, &Pose::new(s2.state.position, &s2.state.orientation)),
            axes,
            72,
        )
        .map(|pts| pts.iter().map(v).collect())
        .unwrap_or_default(),
        _ => vec![],
    };
    PairTrace {
        a,
        b,
        forced,
        spheres: p.spheres,
        swept_overlap: p.swept_overlap,
        method: match p.method {
            Method::Analytic => "analytic",
            Method::Gjk => "gjk",
            Method::Mesh => "mesh",
        },
        gjk,
        epa,
        contacts: p.contacts.iter().map(contact).collect(),
        analytic: p.analytic.as_ref().map(|c| c.iter().map(contact).collect()),
        minkowski,
        notes,
        mid_phase,
    }
}

fn gjk_step(it: &GjkIteration<f64>) -> GjkStep {
    GjkStep {
        v: v(&it.v),
        direction: v(&it.direction),
        support: v(&it.support.w),
        support_a: v(&it.support.a),
        support_b: v(&it.support.b),
        simplex: it.simplex[..it.simplex_len].iter().map(v).collect(),
        kept: (0..it.simplex_len)
            .filter(|i| it.kept >> i & 1 == 1)
            .collect(),
        next: it.next.as_ref().map(v),
        bound: it.bound,
        bound_limit: it.bound_limit,
    }
}

fn epa_step(r: &EpaRecord<f64>) -> EpaStep {
    let it = &r.iteration;
    EpaStep {
        face: it.face.map(|p| v(&p)),
        normal: v(&it.normal),
        distance: it.distance,
        support: v(&it.support.w),
        support_a: v(&it.support.a),
        support_b: v(&it.support.b),
        gap: it.gap,
        removed: it.removed,
        added: it.added,
    }
}

fn contact(c: &ContactPoint<f64>) -> ContactLine {
    ContactLine {
        point: v(&c.point),
        normal: v(&c.normal),
        penetration: c.penetration,
        triangle: match c.feature {
            crate::physics::collide::Feature::Triangle { triangle, .. } => Some(triangle),
            _ => None,
        },
    }
}

fn v(x: &Vector3<f64>) -> V3 {
    [x.x, x.y, x.z]
}
