//! Drawing geometry: body outlines projected onto a view plane, convex
//! hulls, and how far the contact point lies from a shape as drawn.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

pub use crate::trace::Plane;
use crate::trace::ShapeView;

pub fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let q = UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3]));
    let r = q.transform_vector(&Vector3::from(v));
    [r.x, r.y, r.z]
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// An outline in view-plane coordinates.
#[derive(Debug, Clone, PartialEq)]
pub enum Outline {
    Polygon(Vec<(f64, f64)>),
    Circle { centre: (f64, f64), radius: f64 },
}

impl Outline {
    pub fn points(&self) -> Vec<(f64, f64)> {
        match self {
            Outline::Polygon(p) => p.clone(),
            Outline::Circle { centre, radius } => vec![
                (centre.0 - radius, centre.1 - radius),
                (centre.0 + radius, centre.1 + radius),
            ],
        }
    }
}

/// The projected outline of a shape at a pose; `None` for a half-space or
/// a body without a shape.
pub fn outline(
    shape: &ShapeView,
    position: [f64; 3],
    q: [f64; 4],
    plane: Plane,
) -> Option<Outline> {
    let world = |local: [f64; 3]| plane.project(add(position, rotate(q, local)));
    match *shape {
        ShapeView::Sphere { radius } => Some(Outline::Circle {
            centre: plane.project(position),
            radius,
        }),
        ShapeView::Box { sides } => {
            let h = sides.map(|s| s / 2.0);
            let corners = (0..8)
                .map(|i| {
                    let s = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
                    world([s(1) * h[0], s(2) * h[1], s(4) * h[2]])
                })
                .collect();
            Some(Outline::Polygon(hull(corners)))
        }
        ShapeView::Cylinder { radius, height } => {
            let points = (0..32)
                .map(|i| {
                    let a = (i % 16) as f64 * std::f64::consts::TAU / 16.0;
                    let y = if i < 16 { height / 2.0 } else { -height / 2.0 };
                    world([radius * a.cos(), y, radius * a.sin()])
                })
                .collect();
            Some(Outline::Polygon(hull(points)))
        }
        ShapeView::HalfSpace | ShapeView::Marker => None,
    }
}

/// A length that stands for the body's size (0 without a finite shape).
pub fn size(shape: &ShapeView) -> f64 {
    match *shape {
        ShapeView::Sphere { radius } => radius,
        ShapeView::Box { sides } => {
            0.5 * (sides[0].powi(2) + sides[1].powi(2) + sides[2].powi(2)).sqrt()
        }
        ShapeView::Cylinder { radius, height } => radius.max(height / 2.0),
        ShapeView::HalfSpace | ShapeView::Marker => 0.0,
    }
}

/// Signed distance from `point` to the shape's surface (negative inside).
pub fn surface_distance(
    shape: &ShapeView,
    position: [f64; 3],
    q: [f64; 4],
    point: [f64; 3],
) -> Option<f64> {
    let rel = [
        point[0] - position[0],
        point[1] - position[1],
        point[2] - position[2],
    ];
    let inverse = [q[0], -q[1], -q[2], -q[3]];
    let local = rotate(inverse, rel);
    let boxed = |d: &[f64]| {
        let outside = d.iter().map(|x| x.max(0.0).powi(2)).sum::<f64>().sqrt();
        let inside = d.iter().copied().fold(f64::NEG_INFINITY, f64::max).min(0.0);
        outside + inside
    };
    match *shape {
        ShapeView::Sphere { radius } => Some(Vector3::from(rel).norm() - radius),
        ShapeView::Box { sides } => {
            let d: Vec<f64> = (0..3).map(|i| local[i].abs() - sides[i] / 2.0).collect();
            Some(boxed(&d))
        }
        ShapeView::Cylinder { radius, height } => {
            let radial = (local[0].powi(2) + local[2].powi(2)).sqrt() - radius;
            Some(boxed(&[radial, local[1].abs() - height / 2.0]))
        }
        ShapeView::HalfSpace | ShapeView::Marker => None,
    }
}

/// Convex hull (Andrew's monotone chain), counter-clockwise.
pub fn hull(mut p: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup_by(|a, b| (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12);
    if p.len() < 3 {
        return p;
    }
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let mut lower: Vec<(f64, f64)> = Vec::new();
    for &pt in &p {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], pt) <= 1e-12
        {
            lower.pop();
        }
        lower.push(pt);
    }
    let mut upper: Vec<(f64, f64)> = Vec::new();
    for &pt in p.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], pt) <= 1e-12
        {
            upper.pop();
        }
        upper.push(pt);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_unit_cube_seen_from_z_is_a_square() {
        let o = outline(
            &ShapeView::Box {
                sides: [2.0, 2.0, 2.0],
            },
            [0.0; 3],
            [1.0, 0.0, 0.0, 0.0],
            Plane::Xy,
        );
        match o {
            Some(Outline::Polygon(p)) => {
                assert_eq!(p, vec![(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)])
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn distance_to_the_surface() {
        let cube = ShapeView::Box { sides: [12.0; 3] };
        let id = [1.0, 0.0, 0.0, 0.0];
        assert!((surface_distance(&cube, [0.0; 3], id, [6.0, 6.0, 0.0]).unwrap()).abs() < 1e-12);
        assert!(
            (surface_distance(&cube, [0.0; 3], id, [0.0, 8.0, 0.0]).unwrap() - 2.0).abs() < 1e-12
        );
        // Turned 45° about z, the corner direction (6√2, 0) is on a vertex.
        let s = std::f64::consts::FRAC_PI_8.sin();
        let c = std::f64::consts::FRAC_PI_8.cos();
        let d = surface_distance(
            &cube,
            [0.0; 3],
            [c, 0.0, 0.0, s],
            [6.0 * 2f64.sqrt(), 0.0, 0.0],
        )
        .unwrap();
        assert!(d.abs() < 1e-9, "{d}");
        let ball = ShapeView::Sphere { radius: 2.0 };
        assert!(
            (surface_distance(&ball, [1.0, 0.0, 0.0], id, [1.0, 1.0, 0.0]).unwrap() + 1.0).abs()
                < 1e-12
        );
    }

    #[test]
    fn views_are_right_handed() {
        for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
            let (u, v, w) = plane.axes();
            assert_eq!((u + 1) % 3, v);
            assert_eq!((v + 1) % 3, w);
        }
    }
}
