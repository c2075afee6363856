//! Contact generation: which points of two shapes touch, along which normal, how deep.
//!
//! [`collide`] takes two bodies `a` (body 1) and `b` (body 2), each a shape and
//! a [`Pose`], and appends [`ContactPoint`]s to `out`. Conventions, for every
//! pair:
//!
//! - `normal` is unit and points from body B (2) toward body A (1): moving A
//!   along `+normal` by `penetration` (the largest of a contact set's)
//!   separates the pair. For box–box the single contact's penetration is the
//!   overlap on the separating-axis test's axis; a manifold point carries its
//!   own depth, which may be less.
//! - `penetration` is the overlap along `normal`, ≥ 0 (it is negative, the
//!   gap, only when [`Options::tolerance`] asks for contacts that are near).
//! - `point` lies on or between the two surfaces. A contact between the two
//!   deepest features (sphere–sphere, sphere–plane, box–sphere, box–box
//!   vertex–face and edge–edge) lies **midway between the surfaces** along
//!   the normal: A's deepest point into B is `point - ½·penetration·normal`
//!   and B's deepest point into A is `point + ½·penetration·normal`. A point
//!   of a contact set (box or cylinder on a plane, the box–box manifold) is
//!   the penetrating point itself: a vertex or rim point below the plane, a
//!   point of the incident face below the reference face — on its own body's
//!   surface, `penetration` deep in the other. (Midway would leave the body
//!   at every point but the deepest.)
//! - [`Feature`] says what touched, for a trace to explain.
//!
//! Pairs: sphere–sphere, sphere–half-space, box–half-space (every vertex at or
//! below the plane), box–sphere, box–box (separating axes, [`BoxBoxMode`]) and
//! cylinder–half-space (rim points). Box–box single mode follows the
//! reference engine (`boxAndBox` in cyclone's `collide_fine.cpp`) except where
//! its point–face vertex lies beside the reference face (a long edge across a
//! small face, a box hanging over a face's edge; 14 % of the face contacts
//! between randomly placed overlapping boxes): there the deepest point of the clipped incident face is taken
//! (feature `FaceFace`), with the axis overlap as penetration. A hollow sphere collides as a sphere.
//! Every other convex pair (cylinder with a sphere, box or cylinder) runs
//! GJK/EPA and the clipped manifold ([`convex`]), as every convex pair does
//! with [`NarrowPhase::Gjk`]; a half-space pair keeps its analytic routine
//! (a half-space has no support mapping). Two half-spaces generate nothing.
//! A half-space's `normal` is a world vector: its pose's rotation is ignored.
//!
//! The broad phase ([`broad`]; by grid or tree: [`partition`]) finds candidate pairs; [`scene::ContactGenerator`]
//! runs both phases over a set of bodies.

mod bounds;
mod box_box;
mod box_sphere;
pub mod broad;
mod clip;
mod convex;
mod grid;
mod mesh;
pub mod mesh_query;
mod partition;
mod plane;
pub mod record;
pub mod scene;
mod sphere;
mod sweep;
mod tree;

pub use broad::{all_pairs, candidate_pairs, Aabb, BroadPhase};
pub use partition::{BroadCounts, PairFinder};
pub use scene::{BodyContact, ContactGenerator};

use nalgebra::Vector3;

use super::{c, Real, Shape};

/// A body's pose and which of a pair it is (in `physics::pose`, shared with `detect`).
pub use super::pose::{Pose, Side};

/// How many points a box–box pair generates (`[world] box_box`): `Single`, one
/// point–face or edge–edge contact as the reference engine; `Manifold`
/// (default), the clipped faces, up to 4 points.
pub use super::params::BoxBoxMode;

/// How the broad phase finds its pairs (`[world] broad_phase`): `Sweep`
/// (default), `Grid` or `Bvh`; the same pairs whichever.
pub use super::params::BroadPhaseMethod;

/// Which routine a convex pair runs (`[world] narrow_phase`): `Analytic`
/// (default) where one exists, GJK/EPA otherwise; `Gjk` for every pair but
/// a half-space's.
pub use super::params::NarrowPhase;

/// A mesh's normals on internal edges (`[world] internal_edges`).
pub use super::params::InternalEdges;

/// Which part of a box holds the point closest to a sphere's centre.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BoxPart {
    Face,
    Edge,
    Vertex,
    /// The centre is inside the box: pushed out through the nearest face.
    Inside,
}

/// What touched, so that a trace can explain a generated contact. Box axes
/// are numbered 0, 1, 2 (body x, y, z); a box vertex is numbered by bits:
/// bit k set means the +half side along axis k.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Feature {
    /// Two spheres, along the line of centres.
    SphereSphere,
    /// A sphere and a half-space.
    SpherePlane { sphere: Side },
    /// A sphere and a box: the part of the box nearest the sphere's centre.
    SphereBox { sphere: Side, part: BoxPart },
    /// A box vertex at or below a half-space.
    VertexPlane { cuboid: Side, vertex: u8 },
    /// A cylinder's rim point at or below a half-space: cap 0 is at body
    /// -y, cap 1 at +y; `quarter` 0 is the rim point deepest below the plane,
    /// 1–3 the points a quarter turn apart from it.
    RimPlane {
        cylinder: Side,
        cap: u8,
        quarter: u8,
    },
    /// A vertex of one box on face `axis` of the box on side `face`
    /// (the reference engine's point–face contact).
    VertexFace { face: Side, axis: u8, vertex: u8 },
    /// Edge along axis `axis_a` of box A crossing edge along `axis_b` of box B.
    EdgeEdge { axis_a: u8, axis_b: u8 },
    /// A point of the other box's face clipped against face `axis` of the
    /// reference box on side `reference`: a manifold point, or in single mode
    /// the deepest such point when the reference engine's vertex lies beside
    /// the face (its penetration is then the overlap on the axis).
    FaceFace { reference: Side, axis: u8 },
    /// A point of the GJK/EPA manifold: on the incident body, the reference
    /// face being on side `reference`; `None` for EPA's (or the closest
    /// points') single point, midway.
    Convex { reference: Option<Side> },
    /// A contact with triangle `triangle` of the mesh on side `mesh`.
    Triangle { mesh: Side, triangle: usize },
}

impl Feature {
    /// The same feature with bodies A and B exchanged.
    pub fn swapped(self) -> Feature {
        match self {
            Feature::SphereSphere => Feature::SphereSphere,
            Feature::SpherePlane { sphere } => Feature::SpherePlane {
                sphere: sphere.other(),
            },
            Feature::SphereBox { sphere, part } => Feature::SphereBox {
                sphere: sphere.other(),
                part,
            },
            Feature::VertexPlane { cuboid, vertex } => Feature::VertexPlane {
                cuboid: cuboid.other(),
                vertex,
            },
            Feature::RimPlane {
                cylinder,
                cap,
                quarter,
            } => Feature::RimPlane {
                cylinder: cylinder.other(),
                cap,
                quarter,
            },
            Feature::VertexFace { face, axis, vertex } => Feature::VertexFace {
                face: face.other(),
                axis,
                vertex,
            },
            Feature::EdgeEdge { axis_a, axis_b } => Feature::EdgeEdge {
                axis_a: axis_b,
                axis_b: axis_a,
            },
            Feature::FaceFace { reference, axis } => Feature::FaceFace {
                reference: reference.other(),
                axis,
            },
            Feature::Convex { reference } => Feature::Convex {
                reference: reference.map(Side::other),
            },
            Feature::Triangle { mesh, triangle } => Feature::Triangle {
                mesh: mesh.other(),
                triangle,
            },
        }
    }
}

/// One generated contact point between bodies A (1) and B (2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPoint<T: Real> {
    /// On or between the surfaces: midway between them along the normal, or
    /// for a point of a contact set (`VertexPlane`, `RimPlane`, `FaceFace`)
    /// the penetrating point itself.
    pub point: Vector3<T>,
    /// Unit, from B toward A.
    pub normal: Vector3<T>,
    /// Overlap along the normal (≥ 0; the gap, negative, only within a tolerance).
    pub penetration: T,
    pub feature: Feature,
}

/// Choices of the narrow phase.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options<T: Real> {
    /// Box–box contacts (default: manifold).
    pub box_box: BoxBoxMode,
    /// A contact is generated when the gap is at most this (default: 0, i.e.
    /// touching or overlapping). A larger margin finds contacts a step
    /// earlier, at the price of more contacts to resolve.
    pub tolerance: T,
    /// Analytic routines where they exist (default), or GJK/EPA for every
    /// convex pair.
    pub narrow_phase: NarrowPhase,
    /// How the broad phase finds its pairs (default: sweep): the same pairs,
    /// at a different cost.
    pub broad_phase: BroadPhaseMethod,
    /// A mesh's normals on internal edges (default: corrected).
    pub internal_edges: InternalEdges,
}

impl<T: Real> Default for Options<T> {
    fn default() -> Self {
        Options {
            box_box: BoxBoxMode::default(),
            tolerance: T::zero(),
            narrow_phase: NarrowPhase::default(),
            broad_phase: BroadPhaseMethod::default(),
            internal_edges: InternalEdges::default(),
        }
    }
}

impl<T: Real> Options<T> {
    /// Default options with the given box–box mode.
    pub fn with_mode(box_box: BoxBoxMode) -> Self {
        Options {
            box_box,
            ..Options::default()
        }
    }
}

/// Appends the contacts between `a` (body 1) and `b` (body 2) to `out` with
/// no tolerance; returns how many were added.
pub fn collide<T: Real>(
    a: (&Shape, &Pose<T>),
    b: (&Shape, &Pose<T>),
    mode: BoxBoxMode,
    out: &mut Vec<ContactPoint<T>>,
) -> usize {
    collide_with(a, b, &Options::with_mode(mode), out)
}

/// [`collide`] with every option; returns how many contacts were added.
pub fn collide_with<T: Real>(
    a: (&Shape, &Pose<T>),
    b: (&Shape, &Pose<T>),
    options: &Options<T>,
    out: &mut Vec<ContactPoint<T>>,
) -> usize {
    let start = out.len();
    // Same-kind pairs run in a canonical order (so that swapping the bodies
    // flips every normal even where ties are broken); mixed pairs run with the
    // simpler shape second. Either way `swap` says whether to flip back.
    let swap = match (kind(a.0), kind(b.0)) {
        (ka, kb) if ka == kb => precedes(b, a),
        (ka, kb) => ka > kb,
    };
    let (first, second) = if swap { (b, a) } else { (a, b) };
    narrow(first, second, options, out);
    if swap {
        for contact in &mut out[start..] {
            contact.normal = -contact.normal;
            contact.feature = contact.feature.swapped();
        }
    }
    out.len() - start
}

/// Kinds in dispatch order: the pair functions take the lower kind first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Cuboid,
    Cylinder,
    Capsule,
    Hull,
    Sphere,
    Mesh,
    HalfSpace,
}

fn kind(shape: &Shape) -> Kind {
    match shape {
        Shape::Box { .. } => Kind::Cuboid,
        Shape::Cylinder { .. } => Kind::Cylinder,
        Shape::Capsule { .. } => Kind::Capsule,
        Shape::Hull(_) => Kind::Hull,
        Shape::Mesh(_) => Kind::Mesh,
        Shape::Sphere { .. } | Shape::HollowSphere { .. } => Kind::Sphere,
        Shape::HalfSpace { .. } => Kind::HalfSpace,
    }
}

/// Canonical order of two bodies of one kind: by position, then rotation,
/// then size (lexicographic; incomparable values keep the given order). Two
/// equal bodies at one pose have no order: swapping them changes nothing.
fn precedes<T: Real>(x: (&Shape, &Pose<T>), y: (&Shape, &Pose<T>)) -> bool {
    use std::cmp::Ordering;
    let (px, py) = (x.1.position.as_slice(), y.1.position.as_slice());
    let (rx, ry) = (x.1.rotation.as_slice(), y.1.rotation.as_slice());
    for (p, q) in px.iter().zip(py).chain(rx.iter().zip(ry)) {
        match p.partial_cmp(q) {
            Some(Ordering::Less) => return true,
            Some(Ordering::Greater) => return false,
            _ => {}
        }
    }
    size_key(x.0).partial_cmp(&size_key(y.0)) == Some(Ordering::Less)
}

/// A shape's sizes as a fixed array (no allocation), for [`precedes`].
fn size_key(shape: &Shape) -> [f64; 3] {
    match *shape {
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => [radius, 0.0, 0.0],
        Shape::Box { sides } => sides,
        Shape::Cylinder { radius, height } | Shape::Capsule { radius, height } => {
            [radius, height, 0.0]
        }
        // Hulls of one kind at one pose: by volume, then vertex count.
        Shape::Hull(ref hull) => [
            hull.mass_properties().volume,
            hull.vertices().len() as f64,
            0.0,
        ],
        Shape::Mesh(ref mesh) => [mesh.bounding_radius(), mesh.triangles().len() as f64, 0.0],
        Shape::HalfSpace { normal } => normal,
    }
}

/// Runs the pair function for `a`, `b` in dispatch order (`kind(a) ≤ kind(b)`).
fn narrow<T: Real>(
    (sa, pa): (&Shape, &Pose<T>),
    (sb, pb): (&Shape, &Pose<T>),
    options: &Options<T>,
    out: &mut Vec<ContactPoint<T>>,
) {
    let tol = options.tolerance;
    let halfspace = |s: &Shape| matches!(s, Shape::HalfSpace { .. });
    let plane_normal = |n: &[f64; 3]| Vector3::new(c::<T>(n[0]), c::<T>(n[1]), c::<T>(n[2]));
    match (sa, sb) {
        // Two meshes: no triangle-triangle test (a lesson with a moving
        // mesh against another is refused at load).
        (Shape::Mesh(_), Shape::Mesh(_)) => return,
        (Shape::Mesh(m), &Shape::HalfSpace { normal }) => {
            return mesh::mesh_plane(m, pa, &plane_normal(&normal), pb, tol, out)
        }
        (_, Shape::Mesh(m)) => return mesh::convex_mesh((sa, pa), (m, pb), options, out),
        _ => {}
    }
    if options.narrow_phase == NarrowPhase::Gjk && !halfspace(sa) && !halfspace(sb) {
        return convex::convex_pair((sa, pa), (sb, pb), tol, out);
    }
    match (sa, sb) {
        (&Shape::Box { sides: s1 }, &Shape::Box { sides: s2 }) => {
            box_box::box_box(&half(&s1), pa, &half(&s2), pb, options.box_box, tol, out)
        }
        (&Shape::Box { sides }, &Shape::Sphere { radius } | &Shape::HollowSphere { radius }) => {
            box_sphere::box_sphere(&half(&sides), pa, c(radius), pb, tol, out)
        }
        (&Shape::Box { sides }, &Shape::HalfSpace { normal }) => {
            plane::box_plane(&half(&sides), pa, &plane_normal(&normal), pb, tol, out)
        }
        (&Shape::Cylinder { radius, height }, &Shape::HalfSpace { normal }) => {
            plane::cylinder_plane(
                c(radius),
                c(height / 2.0),
                pa,
                &plane_normal(&normal),
                pb,
                tol,
                out,
            )
        }
        (
            &Shape::Sphere { radius: r1 } | &Shape::HollowSphere { radius: r1 },
            &Shape::Sphere { radius: r2 } | &Shape::HollowSphere { radius: r2 },
        ) => sphere::sphere_sphere(c(r1), pa, c(r2), pb, tol, out),
        (
            &Shape::Sphere { radius } | &Shape::HollowSphere { radius },
            &Shape::HalfSpace { normal },
        ) => plane::sphere_plane(c(radius), pa, &plane_normal(&normal), pb, tol, out),
        // Capsule: its two end balls against the plane, as spheres.
        (&Shape::Capsule { radius, height }, &Shape::HalfSpace { normal }) => {
            for end in [-0.5, 0.5] {
                let ball = Pose {
                    position: pa.to_world(&Vector3::new(T::zero(), c(end * height), T::zero())),
                    rotation: pa.rotation,
                };
                plane::sphere_plane(c(radius), &ball, &plane_normal(&normal), pb, tol, out);
            }
        }
        (Shape::Hull(hull), &Shape::HalfSpace { normal }) => {
            plane::hull_plane(hull, pa, &plane_normal(&normal), pb, tol, out)
        }
        // Two half-spaces: nothing (neither has a support mapping).
        (&Shape::HalfSpace { .. }, &Shape::HalfSpace { .. }) => {}
        // Cylinder with box, sphere or cylinder; a capsule with anything but
        // a half-space: GJK/EPA and the manifold.
        _ => convex::convex_pair((sa, pa), (sb, pb), tol, out),
    }
}

/// Half side lengths in the working float type.
fn half<T: Real>(sides: &[f64; 3]) -> Vector3<T> {
    Vector3::new(c(sides[0] / 2.0), c(sides[1] / 2.0), c(sides[2] / 2.0))
}

/// Box vertex `index` in the body frame (bit k set: +h_k along axis k).
fn vertex<T: Real>(h: &Vector3<T>, index: u8) -> Vector3<T> {
    Vector3::from_fn(|k, _| if index >> k & 1 == 1 { h[k] } else { -h[k] })
}
