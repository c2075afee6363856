//! Box–sphere contact: the point of the box closest to the sphere's centre
//! (the reference engine's `boxAndSphere`), and a centre inside the box pushed
//! out through the nearest face.

use nalgebra::Vector3;

use super::{c, BoxPart, ContactPoint, Feature, Pose, Real, Side};

/// Box of half sides `h` (body A) and sphere of radius `r` (body B).
///
/// With the centre q (box frame) outside the box, the closest box point is
/// q clamped to the box, b = clamp(q, -h, h); normal n = (b - q)/|b - q|
/// (sphere toward box), penetration r - |b - q|. With q inside (or on the
/// surface), the face with the least h_k - |q_k| is nearest: n is that face's
/// inward normal and the penetration r + h_k - |q_k|.
pub(super) fn box_sphere<T: Real>(
    h: &Vector3<T>,
    cuboid: &Pose<T>,
    r: T,
    sphere: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let q = cuboid.to_local(&sphere.position);
    // Early out per axis: the sphere lies beyond a face's plane.
    if (0..3).any(|k| q[k].abs() - r > h[k] + tol) {
        return;
    }
    let closest = Vector3::from_fn(|k, _| q[k].max(-h[k]).min(h[k]));
    let clamped = (0..3).filter(|&k| q[k].abs() > h[k]).count();
    let half = c::<T>(0.5);
    let (local_normal, penetration, box_point, part) = if clamped == 0 {
        // Inside: the nearest face, first axis on ties; its outward normal o.
        let depth = |k: usize| h[k] - q[k].abs();
        let axis = (1..3).fold(0, |best, k| if depth(k) < depth(best) { k } else { best });
        let sign = if q[axis] < T::zero() {
            -T::one()
        } else {
            T::one()
        };
        let outward = Vector3::from_fn(|k, _| if k == axis { sign } else { T::zero() });
        let face_depth = depth(axis);
        (
            -outward,
            r + face_depth,
            q + outward * face_depth,
            BoxPart::Inside,
        )
    } else {
        let towards_box = closest - q;
        let distance = towards_box.norm();
        let penetration = r - distance;
        if penetration < -tol {
            return;
        }
        let part = [BoxPart::Face, BoxPart::Face, BoxPart::Edge, BoxPart::Vertex][clamped];
        (towards_box / distance, penetration, closest, part)
    };
    // The box's point and the sphere's (q + r n) are `penetration` apart along n.
    let sphere_point = q + local_normal * r;
    out.push(ContactPoint {
        point: cuboid.to_world(&((box_point + sphere_point) * half)),
        normal: cuboid.rotation * local_normal,
        penetration,
        feature: Feature::SphereBox {
            sphere: Side::B,
            part,
        },
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::UnitQuaternion;

    fn run(q: [f64; 3], r: f64) -> Vec<ContactPoint<f64>> {
        let h = Vector3::new(1.0, 2.0, 3.0);
        let mut out = Vec::new();
        box_sphere(
            &h,
            &Pose::at(Vector3::zeros()),
            r,
            &Pose::at(q.into()),
            0.0,
            &mut out,
        );
        out
    }

    #[test]
    fn face_edge_and_vertex_regions() {
        let face = run([1.5, 0.0, 0.0], 1.0);
        assert_eq!(face[0].normal, -Vector3::x());
        assert!((face[0].penetration - 0.5).abs() < 1e-15);
        assert!((face[0].point - Vector3::new(0.75, 0.0, 0.0)).norm() < 1e-15);
        assert!(matches!(
            face[0].feature,
            Feature::SphereBox {
                part: BoxPart::Face,
                ..
            }
        ));

        let edge = run([2.0, 3.0, 0.0], 1.5);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!((edge[0].normal - Vector3::new(-s, -s, 0.0)).norm() < 1e-15);
        assert!((edge[0].penetration - (1.5 - 2f64.sqrt())).abs() < 1e-15);
        assert!(matches!(
            edge[0].feature,
            Feature::SphereBox {
                part: BoxPart::Edge,
                ..
            }
        ));

        let corner = run([2.0, 3.0, 4.0], 1.8);
        assert!((corner[0].penetration - (1.8 - 3f64.sqrt())).abs() < 1e-15);
        assert!(matches!(
            corner[0].feature,
            Feature::SphereBox {
                part: BoxPart::Vertex,
                ..
            }
        ));

        assert!(run([2.0, 3.0, 4.0], 1.7).is_empty());
        assert!(run([2.6, 0.0, 0.0], 1.5).is_empty());
    }

    #[test]
    fn centre_inside_leaves_through_the_nearest_face() {
        // Nearest face: +y (0.5 away; x is 0.9 away, z 2.5).
        let out = run([0.1, 1.5, 0.5], 0.25);
        assert_eq!(out[0].normal, -Vector3::y());
        assert!((out[0].penetration - 0.75).abs() < 1e-15);
        // Box face at y = 2, sphere's deepest point 1.25: midway 1.625.
        assert!((out[0].point - Vector3::new(0.1, 1.625, 0.5)).norm() < 1e-15);
        assert!(matches!(
            out[0].feature,
            Feature::SphereBox {
                part: BoxPart::Inside,
                ..
            }
        ));
    }

    #[test]
    fn turned_box_works_in_its_own_frame() {
        let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2);
        let cuboid = Pose::from_unit(Vector3::new(10.0, 0.0, 0.0), &turn);
        let h = Vector3::new(1.0, 2.0, 3.0);
        // Body x is world y: the +x face is at world y = 1.
        let mut out = Vec::new();
        box_sphere(
            &h,
            &cuboid,
            1.0,
            &Pose::at(Vector3::new(10.0, 1.5, 0.0)),
            0.0,
            &mut out,
        );
        assert!((out[0].normal + Vector3::y()).norm() < 1e-15);
        assert!((out[0].penetration - 0.5).abs() < 1e-15);
    }
}
