//! Sphere–sphere contact: along the line of centres.

use nalgebra::Vector3;

use super::{c, ContactPoint, Feature, Pose, Real};

/// Spheres of radii `ra` (body A) and `rb` (body B). Normal `n = (x_A - x_B)/|x_A - x_B|`,
/// penetration `r_A + r_B - |x_A - x_B|`. Coincident centres have no line of
/// centres: the normal is then world +y (by convention) and the penetration
/// `r_A + r_B`.
pub(super) fn sphere_sphere<T: Real>(
    ra: T,
    pa: &Pose<T>,
    rb: T,
    pb: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let d = pa.position - pb.position;
    let reach = ra + rb + tol;
    // Cheap rejection before the square root: |d|² > (r_A + r_B + tol)².
    if reach < T::zero() || d.norm_squared() > reach * reach {
        return;
    }
    let distance = d.norm();
    let penetration = ra + rb - distance;
    if penetration < -tol {
        return;
    }
    let normal = if distance > T::zero() {
        d / distance
    } else {
        Vector3::y()
    };
    // A's deepest point into B is x_A - r_A n; the contact point is half the
    // penetration further along n.
    let deepest_a = pa.position - normal * ra;
    out.push(ContactPoint {
        point: deepest_a + normal * (penetration * c::<T>(0.5)),
        normal,
        penetration,
        feature: Feature::SphereSphere,
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(xa: [f64; 3], ra: f64, xb: [f64; 3], rb: f64) -> Vec<ContactPoint<f64>> {
        let mut out = Vec::new();
        let (pa, pb) = (Pose::at(xa.into()), Pose::at(xb.into()));
        sphere_sphere(ra, &pa, rb, &pb, 0.0, &mut out);
        out
    }

    #[test]
    fn overlap_along_the_line_of_centres() {
        let out = run([3.0, 0.0, 0.0], 2.0, [0.0, 0.0, 0.0], 1.5);
        assert_eq!(out.len(), 1);
        let k = out[0];
        assert_eq!(k.normal, Vector3::x());
        assert!((k.penetration - 0.5).abs() < 1e-15);
        // A's surface at x = 1, B's at 1.5: midway 1.25.
        assert!((k.point - Vector3::new(1.25, 0.0, 0.0)).norm() < 1e-15);
    }

    #[test]
    fn apart_gives_nothing_touching_gives_zero_depth() {
        assert!(run([3.6, 0.0, 0.0], 2.0, [0.0; 3], 1.5).is_empty());
        let touching = run([0.0, 3.5, 0.0], 2.0, [0.0; 3], 1.5);
        assert_eq!(touching.len(), 1);
        assert_eq!(touching[0].penetration, 0.0);
    }

    #[test]
    fn coincident_centres_push_along_plus_y() {
        let out = run([1.0, 2.0, 3.0], 1.0, [1.0, 2.0, 3.0], 0.5);
        assert_eq!(out[0].normal, Vector3::y());
        assert_eq!(out[0].penetration, 1.5);
        // A's deepest point (1, 1, 3) plus 0.75 along y.
        assert!((out[0].point - Vector3::new(1.0, 1.75, 3.0)).norm() < 1e-15);
    }

    #[test]
    fn tolerance_reports_a_near_gap() {
        let mut out: Vec<ContactPoint<f64>> = Vec::new();
        let (pa, pb) = (
            Pose::at(Vector3::new(0.0, 2.1, 0.0)),
            Pose::at(Vector3::zeros()),
        );
        sphere_sphere(1.0, &pa, 1.0, &pb, 0.05, &mut out);
        assert!(out.is_empty());
        sphere_sphere(1.0, &pa, 1.0, &pb, 0.2, &mut out);
        assert!((out[0].penetration + 0.1).abs() < 1e-12);
    }
}
