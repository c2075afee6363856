//! Reference geometry for the tests: closest points on a triangle and
//! between two segments (Ericson, Real-Time Collision Detection 5.1.5 and
//! 5.1.9), and the distance between polyhedra by an exhaustive search over
//! feature pairs (vertex–triangle both ways, edge–edge).

use nalgebra::Vector3;

use crate::physics::detect::Convex;
use crate::physics::pose::Pose;

type V = Vector3<f64>;

/// The point of triangle abc closest to p.
pub fn closest_on_triangle(p: &V, a: &V, b: &V, c: &V) -> V {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return *a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(&bp), ac.dot(&bp));
    if d3 >= 0.0 && d4 <= d3 {
        return *b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(&cp), ac.dot(&cp));
    if d6 >= 0.0 && d5 <= d6 {
        return *c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = 1.0 / (va + vb + vc);
    a + ab * (vb * denom) + ac * (vc * denom)
}

/// Closest points of segments p1q1 and p2q2.
pub fn closest_segments(p1: &V, q1: &V, p2: &V, q2: &V) -> (V, V) {
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&r));
    let (s, t);
    if a <= 1e-300 && e <= 1e-300 {
        return (*p1, *p2);
    }
    if a <= 1e-300 {
        s = 0.0;
        t = (f / e).clamp(0.0, 1.0);
    } else {
        let c = d1.dot(&r);
        if e <= 1e-300 {
            t = 0.0;
            s = (-c / a).clamp(0.0, 1.0);
        } else {
            let b = d1.dot(&d2);
            let denom = a * e - b * b;
            let s0 = if denom > 0.0 {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let t0 = (b * s0 + f) / e;
            if t0 < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t0 > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            } else {
                t = t0;
                s = s0;
            }
        }
    }
    (p1 + d1 * s, p2 + d2 * t)
}

/// A box's or hull's vertices, boundary triangles and edges in world coordinates.
pub fn mesh(shape: &Convex, pose: &Pose<f64>) -> (Vec<V>, Vec<[V; 3]>, Vec<[V; 2]>) {
    match shape {
        Convex::Cuboid { half } => {
            let pts: Vec<[f64; 3]> = super::box_points(*half);
            let hull = crate::physics::detect::ConvexHull::new(&pts).expect("a box is solid");
            mesh(&Convex::hull(hull), pose)
        }
        Convex::Hull(hull) => {
            let v: Vec<V> = hull.vertices().iter().map(|p| pose.to_world(p)).collect();
            let tris = hull.triangles().iter().map(|t| t.map(|i| v[i])).collect();
            let edges = hull.edges().iter().map(|e| e.map(|i| v[i])).collect();
            (v, tris, edges)
        }
        _ => panic!("not a polyhedron"),
    }
}

/// Distance between two separated polyhedra: the smallest over every vertex
/// against every triangle of the other, and every edge against every edge.
pub fn polyhedron_distance(a: (&Convex, &Pose<f64>), b: (&Convex, &Pose<f64>)) -> f64 {
    let (va, ta, ea) = mesh(a.0, a.1);
    let (vb, tb, eb) = mesh(b.0, b.1);
    let mut best = f64::INFINITY;
    for (verts, tris) in [(&va, &tb), (&vb, &ta)] {
        for p in verts {
            for t in tris {
                best = best.min((closest_on_triangle(p, &t[0], &t[1], &t[2]) - p).norm());
            }
        }
    }
    for e in &ea {
        for f in &eb {
            let (x, y) = closest_segments(&e[0], &e[1], &f[0], &f[1]);
            best = best.min((x - y).norm());
        }
    }
    best
}
