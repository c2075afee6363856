//! Helpers for the contact generation tests: poses, and the conventions
//! every generated contact must keep, checked independently of the library.
#![allow(dead_code)]

use contact_lab::physics::collide::{collide, BoxBoxMode, ContactPoint, Pose};
use contact_lab::physics::Shape;
use nalgebra::{UnitQuaternion, Vector3};

/// The floor y = 0, solid below.
pub const FLOOR: Shape = Shape::HalfSpace {
    normal: [0.0, 1.0, 0.0],
};

pub fn pose(position: [f64; 3], orientation: UnitQuaternion<f64>) -> Pose<f64> {
    Pose::from_unit(Vector3::from(position), &orientation)
}

/// The pose translated by `delta`.
pub fn moved(p: &Pose<f64>, delta: &Vector3<f64>) -> Pose<f64> {
    Pose {
        position: p.position + delta,
        rotation: p.rotation,
    }
}

pub fn collide_all(
    a: (&Shape, &Pose<f64>),
    b: (&Shape, &Pose<f64>),
    mode: BoxBoxMode,
) -> Vec<ContactPoint<f64>> {
    let mut out = Vec::new();
    let n = collide(a, b, mode, &mut out);
    assert_eq!(n, out.len(), "returned count");
    out
}

/// Signed distance from a world point to a body's surface.
pub fn surface_distance(body: (&Shape, &Pose<f64>), point: &Vector3<f64>) -> f64 {
    body.0.surface_distance(&body.1.shape_frame(body.0, point))
}

/// A length scale of the pair (for tolerances).
fn scale(a: &Shape, b: &Shape) -> f64 {
    let r = |s: &Shape| s.bounding_radius().unwrap_or(1.0);
    r(a).max(r(b)).max(1.0)
}

/// Thickness of a shape: the least width across it (a half-space: infinite).
fn thickness(s: &Shape) -> f64 {
    match *s {
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => 2.0 * radius,
        Shape::Box { sides } => sides.iter().copied().fold(f64::INFINITY, f64::min),
        Shape::Cylinder { radius, height } => (2.0 * radius).min(height),
        Shape::Capsule { radius, .. } => 2.0 * radius,
        Shape::Hull(ref hull) => 2.0 * hull.inner_radius(),
        // An open mesh is a surface: no thickness to pass through.
        Shape::Mesh(ref mesh) => mesh.inner_radius().map_or(0.0, |r| 2.0 * r),
        Shape::HalfSpace { .. } => f64::INFINITY,
    }
}

/// Generates the contacts of `a` and `b` and checks the conventions:
/// finite; unit normal; penetration ≥ 0; each point on or between the
/// surfaces (its distance to each surface within [−penetration, 0] up to
/// round-off) while the penetration is at most the thinner body's thickness
/// (deeper, one body is through the other and the point midway between the
/// surface points along the normal may lie beyond the thin one); swapping the bodies flips every normal and keeps points,
/// depths and (swapped) features; moving A along the normal by the
/// penetration plus a hair separates the pair.
pub fn check_pair(
    a: (&Shape, &Pose<f64>),
    b: (&Shape, &Pose<f64>),
    mode: BoxBoxMode,
    extra: f64,
) -> Vec<ContactPoint<f64>> {
    let out = collide_all(a, b, mode);
    let eps = 1e-9 * scale(a.0, b.0) + extra;
    for k in &out {
        let finite = k.point.iter().chain(k.normal.iter()).all(|x| x.is_finite());
        assert!(finite && k.penetration.is_finite(), "{k:?}");
        assert!((k.normal.norm() - 1.0).abs() < 1e-12, "unit normal {k:?}");
        assert!(k.penetration >= 0.0, "penetration {k:?}");
        let shallow = k.penetration <= thickness(a.0).min(thickness(b.0));
        for body in [a, b].into_iter().filter(|_| shallow) {
            let d = surface_distance(body, &k.point);
            assert!(
                d >= -k.penetration - eps && d <= eps,
                "point {:?} is {d} from the surface of {:?} (penetration {})",
                k.point,
                body.0,
                k.penetration
            );
        }
    }
    let back = collide_all(b, a, mode);
    assert_eq!(back.len(), out.len(), "swapped count");
    for (k, j) in out.iter().zip(&back) {
        assert!(
            (k.point - j.point).norm() <= 1e-12 * scale(a.0, b.0),
            "{k:?} {j:?}"
        );
        assert!((k.normal + j.normal).norm() <= 1e-12, "{k:?} {j:?}");
        assert_eq!(k.penetration, j.penetration);
        assert_eq!(k.feature.swapped(), j.feature);
    }
    if let Some(first) = out.first() {
        let n = first.normal;
        assert!(
            out.iter().all(|k| (k.normal - n).norm() < 1e-12),
            "one normal per pair"
        );
        // Boxes: the single contact's penetration is the overlap on the axis
        // (a manifold point's own depth may be less).
        let both_boxes = matches!((a.0, b.0), (Shape::Box { .. }, Shape::Box { .. }));
        let depth = if both_boxes {
            collide_all(a, b, BoxBoxMode::Single)[0].penetration
        } else {
            out.iter().map(|k| k.penetration).fold(0.0, f64::max)
        };
        assert!(out.iter().all(|k| k.penetration <= depth + eps));
        let away = moved(a.1, &(n * (depth + 1e-7 * scale(a.0, b.0))));
        let after = collide_all((a.0, &away), b, mode);
        assert!(
            after.is_empty(),
            "still touching after moving A by {depth}: {after:?}"
        );
    }
    out
}
