//! Body shapes: inertia tensors, sizes, support points and surface distance.
//!
//! Dimensions are `f64` as read from a lesson; the float type of a run only
//! matters for the state that changes. A half-space is the solid side of the
//! plane through the body's position, opposite its world `normal`.

use std::sync::Arc;

use nalgebra::{Matrix3, Vector3};

use crate::physics::hull::ConvexHull;
use crate::physics::mesh::TriMesh;

/// The shape of a body, in the body frame.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Solid sphere.
    Sphere { radius: f64 },
    /// Thin-shelled sphere (same surface as a solid one, other inertia).
    HollowSphere { radius: f64 },
    /// Cuboid with full side lengths along the body axes.
    Box { sides: [f64; 3] },
    /// Solid cylinder, axis along body y.
    Cylinder { radius: f64, height: f64 },
    /// Solid capsule: the points within `radius` of the segment of length
    /// `height` along body y through the origin (`height` is between the two
    /// hemispheres' centres).
    Capsule { radius: f64, height: f64 },
    /// The convex hull of points given in the body frame, re-centred on the
    /// hull's centroid (the body's centre of mass) when the lesson is loaded.
    Hull(Arc<ConvexHull>),
    /// A triangle mesh in the body frame: open (terrain, a bowl) only when
    /// immovable; a movable one is closed and re-centred on its solid's
    /// centroid when the lesson is loaded.
    Mesh(Arc<TriMesh>),
    /// The plane through the body's position with unit world `normal`; the
    /// solid side is opposite the normal. Immovable bodies only.
    HalfSpace { normal: [f64; 3] },
}

impl Shape {
    /// Body-frame inertia tensor of a body of mass `m` with this shape, or
    /// `None` for a half-space (which only an immovable body may be).
    pub fn inertia(&self, m: f64) -> Option<Matrix3<f64>> {
        let diag = |a: f64, b: f64, c: f64| Some(Matrix3::from_diagonal(&[a, b, c].into()));
        match *self {
            // Solid sphere: I = 2/5 m r².
            Shape::Sphere { radius: r } => {
                let i = 0.4 * m * r * r;
                diag(i, i, i)
            }
            // Hollow (thin-shelled) sphere: I = 2/3 m r².
            Shape::HollowSphere { radius: r } => {
                let i = 2.0 / 3.0 * m * r * r;
                diag(i, i, i)
            }
            // Solid cuboid with sides x, y, z: I_xx = m/12 (y² + z²), …
            Shape::Box { sides: [x, y, z] } => {
                let k = m / 12.0;
                diag(
                    k * (y * y + z * z),
                    k * (x * x + z * z),
                    k * (x * x + y * y),
                )
            }
            // Solid cylinder, axis along body y: I_yy = ½ m r², I_xx = I_zz = m/12 (3r² + h²).
            Shape::Cylinder { radius, height } => {
                let side = m / 12.0 * (3.0 * radius * radius + height * height);
                diag(side, 0.5 * m * radius * radius, side)
            }
            // Solid capsule: a cylinder (mass m_c = m·πr²h/V) and two half
            // balls (m_s = m·4/3πr³/V): I_yy = ½ m_c r² + 2/5 m_s r²,
            // I_xx = m_c (h²/12 + r²/4) + m_s (2/5 r² + h²/4 + 3/8 h r).
            Shape::Capsule {
                radius: r,
                height: h,
            } => {
                let (vc, vs) = (r * r * h, 4.0 / 3.0 * r * r * r);
                let (mc, ms) = (m * vc / (vc + vs), m * vs / (vc + vs));
                let axial = 0.5 * mc * r * r + 0.4 * ms * r * r;
                let side = mc * (h * h / 12.0 + r * r / 4.0)
                    + ms * (0.4 * r * r + h * h / 4.0 + 0.375 * h * r);
                diag(side, axial, side)
            }
            // Convex hull: the polyhedron's integrals, about its centroid.
            Shape::Hull(ref hull) => Some(hull.inertia(m)),
            // Closed mesh: the solid's integrals by the divergence theorem;
            // an open mesh has none (it may only be immovable).
            Shape::Mesh(ref mesh) => mesh
                .mass_properties()
                .map(|p| p.unit_inertia * (m / p.volume)),
            Shape::HalfSpace { .. } => None,
        }
    }

    /// Size numbers that must be positive and finite.
    pub fn dimensions(&self) -> Vec<f64> {
        match *self {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => vec![radius],
            Shape::Box { sides } => sides.to_vec(),
            Shape::Cylinder { radius, height } | Shape::Capsule { radius, height } => {
                vec![radius, height]
            }
            Shape::Hull(ref hull) => vec![hull.mass_properties().volume],
            Shape::Mesh(ref mesh) => vec![mesh.bounding_radius()],
            Shape::HalfSpace { .. } => vec![],
        }
    }

    /// True for shapes of finite size (everything but the half-space).
    pub fn is_finite(&self) -> bool {
        !matches!(self, Shape::HalfSpace { .. })
    }

    /// Radius of the smallest sphere about the centre that holds the shape
    /// (`None` for a half-space): the bound the broad phase uses.
    pub fn bounding_radius(&self) -> Option<f64> {
        match *self {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => Some(radius),
            Shape::Box { sides } => {
                Some(0.5 * (sides[0].powi(2) + sides[1].powi(2) + sides[2].powi(2)).sqrt())
            }
            Shape::Cylinder { radius, height } => Some(radius.hypot(height / 2.0)),
            Shape::Capsule { radius, height } => Some(radius + height / 2.0),
            Shape::Hull(ref hull) => {
                Some(hull.vertices().iter().map(|v| v.norm()).fold(0.0, f64::max))
            }
            Shape::Mesh(ref mesh) => Some(mesh.bounding_radius()),
            Shape::HalfSpace { .. } => None,
        }
    }

    /// Half side lengths of a box, `None` for other shapes.
    pub fn half_extents(&self) -> Option<Vector3<f64>> {
        match *self {
            Shape::Box { sides } => Some(Vector3::from(sides) / 2.0),
            _ => None,
        }
    }

    /// The body-frame point of the shape farthest along body-frame `direction`
    /// (the support mapping), `None` for a half-space.
    pub fn support(&self, direction: &Vector3<f64>) -> Option<Vector3<f64>> {
        let sign = |x: f64| if x < 0.0 { -1.0 } else { 1.0 };
        match *self {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => {
                let n = direction.norm();
                Some(if n > 0.0 {
                    direction * (radius / n)
                } else {
                    Vector3::new(radius, 0.0, 0.0)
                })
            }
            Shape::Box { sides } => Some(Vector3::new(
                sign(direction.x) * sides[0] / 2.0,
                sign(direction.y) * sides[1] / 2.0,
                sign(direction.z) * sides[2] / 2.0,
            )),
            Shape::Cylinder { radius, height } => {
                let radial = direction.x.hypot(direction.z);
                let (x, z) = if radial > 0.0 {
                    (direction.x * radius / radial, direction.z * radius / radial)
                } else {
                    (radius, 0.0)
                };
                Some(Vector3::new(x, sign(direction.y) * height / 2.0, z))
            }
            // The segment's end on the side of d, pushed out by r along d̂.
            Shape::Capsule { radius, height } => {
                let end = Vector3::new(0.0, sign(direction.y) * height / 2.0, 0.0);
                let n = direction.norm();
                Some(if n > 0.0 {
                    end + direction * (radius / n)
                } else {
                    end + Vector3::new(radius, 0.0, 0.0)
                })
            }
            Shape::Hull(ref hull) => Some(hull.vertices()[hull.support_index(direction)]),
            // A mesh's support is its hull's: the vertex farthest along d.
            Shape::Mesh(ref mesh) => mesh
                .vertices()
                .iter()
                .copied()
                .max_by(|p, q| p.dot(direction).total_cmp(&q.dot(direction))),
            Shape::HalfSpace { .. } => None,
        }
    }

    /// Signed distance from a body-frame point to the surface (negative
    /// inside). For a half-space the point is taken relative to the plane's
    /// point and measured along its normal.
    pub fn surface_distance(&self, local: &Vector3<f64>) -> f64 {
        // Distance to a box of half sizes h given |local| - h per axis.
        let boxed = |d: &[f64]| {
            let outside = d.iter().map(|x| x.max(0.0).powi(2)).sum::<f64>().sqrt();
            let inside = d.iter().copied().fold(f64::NEG_INFINITY, f64::max).min(0.0);
            outside + inside
        };
        match *self {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => local.norm() - radius,
            Shape::Box { sides } => {
                let d: Vec<f64> = (0..3).map(|i| local[i].abs() - sides[i] / 2.0).collect();
                boxed(&d)
            }
            Shape::Cylinder { radius, height } => {
                let radial = local.x.hypot(local.z) - radius;
                boxed(&[radial, local.y.abs() - height / 2.0])
            }
            // Distance to the segment, less the radius.
            Shape::Capsule { radius, height } => {
                let y = local.y.clamp(-height / 2.0, height / 2.0);
                (local - Vector3::new(0.0, y, 0.0)).norm() - radius
            }
            // Convex hull: the largest signed distance to a face plane
            // (exact inside and over a face; a lower bound near edges).
            Shape::Hull(ref hull) => hull
                .faces()
                .iter()
                .map(|f| f.normal.dot(local) - f.offset)
                .fold(f64::NEG_INFINITY, f64::max),
            // Mesh: the distance to the nearest triangle, negative inside a
            // closed mesh (by the nearest triangle's side; an open mesh's
            // inside is behind its normals).
            Shape::Mesh(ref mesh) => mesh.signed_distance(local),
            Shape::HalfSpace { normal } => local.dot(&Vector3::from(normal)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inertia_formulas() {
        let cube = Shape::Box { sides: [12.0; 3] };
        assert_eq!(cube.inertia(10.0).unwrap()[(0, 0)], 240.0);
        let ball = Shape::Sphere { radius: 6.0 };
        assert!((ball.inertia(20.0).unwrap()[(1, 1)] - 288.0).abs() < 1e-12);
        let shell = Shape::HollowSphere { radius: 3.0 };
        assert!((shell.inertia(3.0).unwrap()[(2, 2)] - 18.0).abs() < 1e-12);
        let can = Shape::Cylinder {
            radius: 1.0,
            height: 2.0,
        };
        let i = can.inertia(12.0).unwrap();
        assert!((i[(1, 1)] - 6.0).abs() < 1e-12 && (i[(0, 0)] - 7.0).abs() < 1e-12);
        assert!(Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0]
        }
        .inertia(1.0)
        .is_none());
    }

    #[test]
    fn support_points_lie_on_the_surface_and_farthest_along_the_direction() {
        let shapes = [
            Shape::Sphere { radius: 2.0 },
            Shape::Box {
                sides: [2.0, 4.0, 6.0],
            },
            Shape::Cylinder {
                radius: 1.5,
                height: 3.0,
            },
        ];
        let dirs = [
            Vector3::new(1.0, 0.3, -0.2),
            Vector3::new(-0.4, -1.0, 0.7),
            Vector3::new(0.0, 0.0, 1.0),
        ];
        for shape in shapes {
            for d in dirs {
                let s = shape.support(&d).unwrap();
                assert!(shape.surface_distance(&s).abs() < 1e-12, "{shape:?} {d}");
                // No vertex of a fine sample of the surface lies farther along d.
                let bound = shape.bounding_radius().unwrap();
                assert!(s.norm() <= bound + 1e-12);
                assert!(s.dot(&d) >= -1e-12);
            }
        }
    }

    #[test]
    fn capsule_inertia_meets_the_sphere_and_the_cylinder_limits() {
        // h = 0: a solid ball, 2/5 m r² about every axis.
        let ball = Shape::Capsule {
            radius: 2.0,
            height: 0.0,
        };
        let i = ball.inertia(5.0).unwrap();
        assert!((i[(0, 0)] - 8.0).abs() < 1e-12 && (i[(1, 1)] - 8.0).abs() < 1e-12);
        // r = 1, h = 2, m = 10: m_c = 10·2/(2 + 4/3) = 6, m_s = 4;
        // I_yy = 3 + 1.6, I_xx = 6·(4/12 + 1/4) + 4·(0.4 + 1 + 0.75).
        let pill = Shape::Capsule {
            radius: 1.0,
            height: 2.0,
        };
        let i = pill.inertia(10.0).unwrap();
        assert!((i[(1, 1)] - 4.6).abs() < 1e-12, "{i}");
        assert!((i[(0, 0)] - (3.5 + 8.6)).abs() < 1e-12, "{i}");
        let s = pill.support(&Vector3::new(1.0, 1.0, 0.0)).unwrap();
        assert!(pill.surface_distance(&s).abs() < 1e-12);
        assert!((pill.bounding_radius().unwrap() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn distance_to_the_surface() {
        let cube = Shape::Box { sides: [12.0; 3] };
        assert!(cube.surface_distance(&Vector3::new(6.0, 6.0, 0.0)).abs() < 1e-12);
        assert!((cube.surface_distance(&Vector3::new(0.0, 8.0, 0.0)) - 2.0).abs() < 1e-12);
        assert!((cube.surface_distance(&Vector3::zeros()) + 6.0).abs() < 1e-12);
        let ball = Shape::Sphere { radius: 2.0 };
        assert!((ball.surface_distance(&Vector3::new(0.0, 1.0, 0.0)) + 1.0).abs() < 1e-12);
        let floor = Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        };
        assert_eq!(floor.surface_distance(&Vector3::new(3.0, -0.5, 1.0)), -0.5);
    }

    #[test]
    fn bounding_radius_holds_every_corner() {
        let b = Shape::Box {
            sides: [2.0, 4.0, 4.0],
        };
        assert!((b.bounding_radius().unwrap() - 3.0).abs() < 1e-12);
        assert_eq!(b.half_extents().unwrap(), Vector3::new(1.0, 2.0, 2.0));
    }
}
