//! Every convex pair without an analytic routine (cylinder with a box, a
//! sphere or a cylinder), and every convex pair when `[world] narrow_phase =
//! "gjk"`: GJK, then EPA (or the margins) for the penetration, then the
//! clipped support faces for a manifold (`physics::detect`).
//!
//! A gap within the tolerance: GJK's closest points give the normal
//! n = (a − b)/δ; the manifold is clipped at the touching pose (A moved by
//! −δ·n) and moved back, each point's penetration less δ (negative: a gap).

use nalgebra::Vector3;

use super::{ContactPoint, Feature, Pose, Side};
use crate::physics::detect::{
    manifold_within, query, Convex, EpaOptions, GjkOptions, GjkVerdict, Penetration, QueryOptions,
};
use crate::physics::detect::{FeatureKind, FeaturePair, ManifoldPoint, PenetrationSource};
use crate::physics::{Real, Shape};

/// Appends the contacts of two convex shapes (neither a half-space) to `out`.
pub(super) fn convex_pair<T: Real>(
    (sa, pa): (&Shape, &Pose<T>),
    (sb, pb): (&Shape, &Pose<T>),
    tolerance: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let (Some(a), Some(b)) = (Convex::from_shape(sa), Convex::from_shape(sb)) else {
        return;
    };
    let options = QueryOptions {
        gjk: GjkOptions::default(),
        epa: EpaOptions::default(),
    };
    let found = query(&a, pa, &b, pb, &options, &mut (), &mut ());
    let (pen, gap) = match found.penetration {
        Some(pen) => (pen, T::zero()),
        None if found.gjk.verdict == GjkVerdict::Separated && found.gjk.distance <= tolerance => {
            let g = &found.gjk;
            let Some(normal) = (g.closest_a - g.closest_b).try_normalize(T::zero()) else {
                return;
            };
            let pen = Penetration {
                depth: T::zero(),
                normal,
                point_a: g.closest_a - normal * g.distance,
                point_b: g.closest_b,
                point: g.closest_b,
                feature: FeaturePair {
                    a: FeatureKind::Point,
                    b: FeatureKind::Point,
                },
                source: PenetrationSource::Epa,
            };
            (pen, g.distance)
        }
        None => return,
    };
    // The manifold at the touching pose: A moved by −gap·n; points up to
    // the tolerance less the gap above the reference face are kept (their
    // penetration less the gap is then at least −tolerance).
    let touching = Pose {
        position: pa.position - pen.normal * gap,
        rotation: pa.rotation,
    };
    let mut points = manifold_within(&a, &touching, &b, pb, &pen, tolerance - gap);
    // A cylinder's cap is a polygon of `CAP_SIDES` sides starting at the
    // rim's deepest point; where clipping loses that point (a cap as the
    // reference face, or hanging over the other face's edge), EPA's point
    // joins the manifold, so that its deepest contact is the pair's depth.
    let deepest = points
        .iter()
        .map(|m| m.penetration)
        .fold(T::min_value().unwrap_or(-T::one()), T::max);
    let size = crate::physics::c::<T>(1e-9 * (a.bounding_radius() + b.bounding_radius()));
    if deepest < pen.depth - size {
        // One normal per pair: the manifold's (the reference face's).
        let normal = points.first().map_or(pen.normal, |m| m.normal);
        points.push(ManifoldPoint {
            point: pen.point,
            normal,
            penetration: pen.depth,
            reference: None,
        });
    }
    for m in points {
        // A point on A (B's face is the reference) moves back with A; a
        // point on B, or the midway point, moves back by half the gap.
        let back: Vector3<T> = match m.reference {
            Some(Side::B) => pen.normal * gap,
            Some(Side::A) => Vector3::zeros(),
            None => pen.normal * (gap * crate::physics::c::<T>(0.5)),
        };
        out.push(ContactPoint {
            point: m.point + back,
            normal: m.normal,
            penetration: m.penetration - gap,
            feature: Feature::Convex {
                reference: m.reference,
            },
        });
    }
}
