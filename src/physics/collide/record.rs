//! The detection of a set of bodies at their poses, recorded for the
//! `detect` command: the broad phase (each body's bounding box, every pair
//! kept or ruled out and why), the mid phase (bounding spheres; the box a
//! body sweeps over one step), and for each kept pair GJK's and EPA's
//! iterations, the contacts the step generates and the analytic routine's.
//!
//! Physics only: typed records, no text. The fast path (`ContactGenerator`)
//! is untouched; this runs the same functions with recorders attached.

use nalgebra::Vector3;

use super::broad::Aabb;
use super::mesh_query::{mesh_convex, MeshQuery};
use super::partition::{BroadCounts, PairFinder};
use super::{collide_with, ContactPoint, NarrowPhase, Options};
use crate::physics::detect::epa::EpaRecord;
use crate::physics::detect::{
    query, Convex, EpaRecorder, GjkIteration, GjkRecorder, Query, QueryOptions, Support,
};
use crate::physics::pose::Pose;
use crate::physics::{Body, Shape};

/// One body as the broad and mid phase see it.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyBounds {
    /// The shape's box at its pose, grown by half the contact tolerance;
    /// `None` for a half-space or a body without a shape.
    pub aabb: Option<Aabb<f64>>,
    /// The box of the body's motion over one step: the box now, the box
    /// moved by v·dt, grown by |ω|·dt × the bounding radius (a turn's reach).
    pub swept: Option<Aabb<f64>>,
    /// Radius of the bounding sphere about the centre of mass.
    pub radius: Option<f64>,
}

/// Why the broad phase dropped a pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RuledOut {
    /// A body has no shape.
    NoShape,
    /// Neither body can move: the step never resolves such a pair.
    BothImmovable,
    /// Their boxes do not overlap along world axis `axis` (0, 1, 2).
    BoxesApart { axis: usize },
}

/// Which routine gives the pair's contacts in the step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The lecture's routine for the pair (sphere, box, plane pairs).
    Analytic,
    /// GJK, EPA and the clipped manifold.
    Gjk,
    /// A mesh's mid phase (its tree) and each candidate triangle's narrow
    /// phase; against a half-space, its vertices below the plane.
    Mesh,
}

/// A pair with a mesh: the mid phase of the convex body against the mesh
/// (`None` against a half-space), with which body is the mesh. Its normals
/// point from the mesh toward the convex body.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshRecord {
    pub query: Option<MeshQuery>,
    pub mesh_is_body1: bool,
}

/// One pair's detection. Body 1 is the lower index unless only the higher
/// one can move (as the step orders them); normals point from body 2 toward
/// body 1.
#[derive(Debug, Clone, PartialEq)]
pub struct PairRecord {
    pub body1: usize,
    pub body2: usize,
    /// Why the broad phase dropped the pair, when it did (a pair asked for
    /// by name runs anyway).
    pub ruled_out: Option<RuledOut>,
    /// Centre distance and the sum of the bounding radii (`None` with a half-space).
    pub spheres: Option<(f64, f64)>,
    /// Whether the boxes swept over the step overlap (`None` with a half-space).
    pub swept_overlap: Option<bool>,
    pub method: Method,
    /// GJK then EPA (or the margins); `None` for a pair with a half-space,
    /// which has no support mapping.
    pub query: Option<Query<f64>>,
    /// The iterations of the GJK run the result came from.
    pub gjk: Vec<GjkIteration<f64>>,
    pub epa: Vec<EpaRecord<f64>>,
    /// The contacts the step generates for the pair (its narrow phase).
    pub contacts: Vec<ContactPoint<f64>>,
    /// The analytic routine's contacts, where the pair has one.
    pub analytic: Option<Vec<ContactPoint<f64>>>,
    /// A pair with a mesh: its mid phase.
    pub mesh: Option<MeshRecord>,
}

/// A set of bodies' detection.
#[derive(Debug, Clone, PartialEq)]
pub struct DetectRecord {
    pub bounds: Vec<BodyBounds>,
    /// Every pair of bodies the broad phase kept (i < j).
    pub candidates: Vec<(usize, usize)>,
    /// Every pair it dropped (i < j), with the reason.
    pub ruled_out: Vec<((usize, usize), RuledOut)>,
    /// The pairs detected: the candidates, or the one asked for.
    pub pairs: Vec<PairRecord>,
    /// What the step's broad phase (`options.broad_phase`) does to find its
    /// pairs from these boxes, called afresh (a run's later steps reuse
    /// its sweep order or tree).
    pub broad: BroadCounts,
}

/// True when the lecture (and `collide`) has an analytic routine for the
/// pair: box–box, box–sphere, sphere–sphere, and any shape on a half-space.
pub fn has_analytic(a: &Shape, b: &Shape) -> bool {
    use Shape::*;
    let ball = |s: &Shape| matches!(s, Sphere { .. } | HollowSphere { .. });
    let plane = |s: &Shape| matches!(s, HalfSpace { .. });
    match (a, b) {
        _ if plane(a) || plane(b) => true,
        (Box { .. }, Box { .. }) => true,
        (Box { .. }, _) if ball(b) => true,
        (_, Box { .. }) if ball(a) => true,
        _ => ball(a) && ball(b),
    }
}

/// The detection of `bodies` with the step's `options` over a step of `dt`;
/// `only`: the one pair to detect (by index), run even when ruled out.
pub fn detect(
    bodies: &[Body<f64>],
    options: &Options<f64>,
    dt: f64,
    only: Option<(usize, usize)>,
) -> DetectRecord {
    detect_watched(bodies, options, dt, only, &mut |_, _| true).unwrap_or(DetectRecord {
        bounds: vec![],
        candidates: vec![],
        ruled_out: vec![],
        pairs: vec![],
        broad: BroadCounts::default(),
    })
}

/// [`detect`], telling `watch` how many of the pairs to detect are done
/// before each one (done, of how many) and after the last; `None` when
/// `watch` says stop (returns false): a long detection (a pile's 500,000
/// pairs, a hull of 100,000 vertices) shows its progress and can be
/// cancelled between pairs.
pub fn detect_watched(
    bodies: &[Body<f64>],
    options: &Options<f64>,
    dt: f64,
    only: Option<(usize, usize)>,
    watch: &mut dyn FnMut(usize, usize) -> bool,
) -> Option<DetectRecord> {
    let margin = options.tolerance.max(0.0) * 0.5;
    let pose = |b: &Body<f64>| Pose::new(b.state.position, &b.state.orientation);
    let bounds: Vec<BodyBounds> = bodies.iter().map(|b| bounds_of(b, margin, dt)).collect();
    let (mut candidates, mut ruled_out) = (vec![], vec![]);
    for i in 0..bodies.len() {
        for j in i + 1..bodies.len() {
            match broad(bodies, &bounds, i, j) {
                None => candidates.push((i, j)),
                Some(why) => ruled_out.push(((i, j), why)),
            }
        }
    }
    let chosen: Vec<(usize, usize)> = match only {
        Some((i, j)) => vec![(i.min(j), i.max(j))],
        None => candidates.clone(),
    };
    let mut pairs = vec![];
    // The ruled-out pairs by pair, for a pair asked for by name.
    let why: std::collections::HashMap<(usize, usize), RuledOut> = match only {
        Some(_) => ruled_out.iter().copied().collect(),
        None => Default::default(),
    };
    let total = chosen.len();
    for (done, (i, j)) in chosen.into_iter().enumerate() {
        if !watch(done, total) {
            return None;
        }
        let (body1, body2) = if !bodies[i].movable && bodies[j].movable {
            (j, i)
        } else {
            (i, j)
        };
        let (Some(s1), Some(s2)) = (&bodies[body1].shape, &bodies[body2].shape) else {
            continue;
        };
        let (p1, p2) = (pose(&bodies[body1]), pose(&bodies[body2]));
        let mut record = PairRecord {
            body1,
            body2,
            ruled_out: why.get(&(i, j)).copied(),
            spheres: None,
            swept_overlap: None,
            method: Method::Gjk,
            query: None,
            gjk: vec![],
            epa: vec![],
            contacts: vec![],
            analytic: None,
            mesh: None,
        };
        if let (Some(r1), Some(r2)) = (bounds[body1].radius, bounds[body2].radius) {
            record.spheres = Some(((p1.position - p2.position).norm(), r1 + r2));
        }
        if let (Some(a), Some(b)) = (&bounds[body1].swept, &bounds[body2].swept) {
            record.swept_overlap = Some(a.overlaps(b));
        }
        let analytic = has_analytic(s1, s2) && !is_mesh(s1) && !is_mesh(s2);
        record.mesh = mesh_record((s1, &p1), (s2, &p2), options);
        record.method = if record.mesh.is_some() {
            Method::Mesh
        } else if analytic && options.narrow_phase == NarrowPhase::Analytic
            || matches!(s1, Shape::HalfSpace { .. })
            || matches!(s2, Shape::HalfSpace { .. })
        {
            Method::Analytic
        } else {
            Method::Gjk
        };
        if let (Some(a), Some(b)) = (Convex::from_shape(s1), Convex::from_shape(s2)) {
            let (mut g, mut e) = (GjkRecorder::default(), EpaRecorder::default());
            let found = query(&a, &p1, &b, &p2, &QueryOptions::default(), &mut g, &mut e);
            record.query = Some(found);
            record.gjk = g.iterations;
            record.epa = e.iterations;
        }
        collide_with((s1, &p1), (s2, &p2), options, &mut record.contacts);
        if analytic {
            let mut out = vec![];
            let routine = Options {
                narrow_phase: NarrowPhase::Analytic,
                ..*options
            };
            collide_with((s1, &p1), (s2, &p2), &routine, &mut out);
            record.analytic = Some(out);
        }
        pairs.push(record);
    }
    if !watch(total, total) {
        return None;
    }
    let broad = broad_counts(bodies, &bounds, options);
    Some(DetectRecord {
        bounds,
        candidates,
        ruled_out,
        pairs,
        broad,
    })
}

fn is_mesh(s: &Shape) -> bool {
    matches!(s, Shape::Mesh(_))
}

/// The mid phase of a pair with one mesh, as the step runs it (the convex
/// body's box down the mesh's tree, grown by the tolerance).
fn mesh_record(
    (s1, p1): (&Shape, &Pose<f64>),
    (s2, p2): (&Shape, &Pose<f64>),
    options: &Options<f64>,
) -> Option<MeshRecord> {
    let mesh_is_body1 = is_mesh(s1);
    let ((mesh, pm), (other, po)) = match (s1, s2) {
        (Shape::Mesh(m), _) => ((m, p1), (s2, p2)),
        (_, Shape::Mesh(m)) => ((m, p2), (s1, p1)),
        _ => return None,
    };
    let fix = options.internal_edges == super::InternalEdges::Corrected;
    let query = Convex::from_shape(other)
        .map(|convex| mesh_convex(&convex, po, mesh, pm, options.tolerance.max(0.0), fix));
    Some(MeshRecord {
        query,
        mesh_is_body1,
    })
}

/// What the step's broad phase does with these boxes (the same boxes and
/// half-spaces `ContactGenerator` gives it).
fn broad_counts(
    bodies: &[Body<f64>],
    bounds: &[BodyBounds],
    options: &Options<f64>,
) -> BroadCounts {
    let boxes: Vec<Option<Aabb<f64>>> = bounds.iter().map(|b| b.aabb).collect();
    let half_spaces: Vec<usize> = (bodies.iter().enumerate())
        .filter(|(_, b)| matches!(b.shape, Some(Shape::HalfSpace { .. })))
        .map(|(i, _)| i)
        .collect();
    let mut finder = PairFinder::new();
    finder.candidate_pairs(options.broad_phase, &boxes, &half_spaces, &mut vec![]);
    finder.counts()
}

/// The broad phase's verdict on bodies `i` and `j`: `None` keeps the pair.
/// The same pairs as `ContactGenerator` resolves (a half-space meets every
/// body with a shape; two boxes must overlap or touch).
fn broad(bodies: &[Body<f64>], bounds: &[BodyBounds], i: usize, j: usize) -> Option<RuledOut> {
    let (a, b) = (&bodies[i], &bodies[j]);
    if a.shape.is_none() || b.shape.is_none() {
        return Some(RuledOut::NoShape);
    }
    if !a.movable && !b.movable {
        return Some(RuledOut::BothImmovable);
    }
    let (Some(x), Some(y)) = (&bounds[i].aabb, &bounds[j].aabb) else {
        return None;
    };
    (0..3)
        .find(|&k| x.max[k] < y.min[k] || y.max[k] < x.min[k])
        .map(|axis| RuledOut::BoxesApart { axis })
}

fn bounds_of(body: &Body<f64>, margin: f64, dt: f64) -> BodyBounds {
    let Some(shape) = &body.shape else {
        return BodyBounds {
            aabb: None,
            swept: None,
            radius: None,
        };
    };
    let pose = Pose::new(body.state.position, &body.state.orientation);
    let aabb = Aabb::of(shape, &pose, margin);
    let radius = shape.bounding_radius();
    let swept = aabb.as_ref().map(|a| {
        // The box now and at x + v·dt, grown by the farthest a turn of
        // |ω|·dt moves a point within the bounding radius.
        let step = body.state.velocity * dt;
        let turn = body.state.angular_velocity.norm() * dt * radius.unwrap_or(0.0);
        let grow = Vector3::repeat(turn.min(2.0 * radius.unwrap_or(0.0)));
        Aabb {
            min: a.min.inf(&(a.min + step)) - grow,
            max: a.max.sup(&(a.max + step)) + grow,
        }
    });
    BodyBounds {
        aabb,
        swept,
        radius,
    }
}

/// Points of the Minkowski difference A − B's outline seen in the plane of
/// world axes `u` and `v`: w(d) = s_A(d) − s_B(−d) for `n` directions d in
/// that plane (the outline of the projection is exactly these supports).
pub fn minkowski_outline(
    a: (&Shape, &Pose<f64>),
    b: (&Shape, &Pose<f64>),
    axes: (usize, usize),
    n: usize,
) -> Option<Vec<Vector3<f64>>> {
    let (ca, cb) = (Convex::from_shape(a.0)?, Convex::from_shape(b.0)?);
    Some(
        (0..n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / n as f64;
                let mut d = Vector3::zeros();
                d[axes.0] = t.cos();
                d[axes.1] = t.sin();
                ca.support(a.1, &d) - cb.support(b.1, &-d)
            })
            .collect(),
    )
}
