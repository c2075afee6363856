//! The lesson file's shape table converted into the physics [`Shape`], and
//! its one-line description for warnings and the trace.

use super::raw::RawShape;
use crate::physics::Shape;

impl From<RawShape> for Shape {
    fn from(raw: RawShape) -> Shape {
        match raw {
            RawShape::Sphere(radius) => Shape::Sphere { radius },
            RawShape::HollowSphere(radius) => Shape::HollowSphere { radius },
            RawShape::Box(sides) => Shape::Box { sides },
            RawShape::Cylinder { radius, height } => Shape::Cylinder { radius, height },
            RawShape::Capsule { radius, height } => Shape::Capsule { radius, height },
            RawShape::HalfSpace => Shape::HalfSpace {
                normal: [0.0, 1.0, 0.0],
            },
        }
    }
}

/// The shape and its inertia formula, in words (numbers through
/// `format::exact`: tiny and huge sizes in scientific notation).
pub fn describe(shape: &Shape) -> String {
    let e = crate::format::exact;
    match *shape {
        Shape::Sphere { radius: r } => format!("solid sphere r = {} (I = 2/5 m r²)", e(r)),
        Shape::HollowSphere { radius: r } => {
            format!("hollow sphere r = {} (I = 2/3 m r²)", e(r))
        }
        Shape::Box { sides: [x, y, z] } => format!(
            "box {} × {} × {} (I_xx = m/12 (y² + z²), …)",
            e(x),
            e(y),
            e(z)
        ),
        Shape::Cylinder { radius, height } => format!(
            "cylinder r = {}, h = {} (I_yy = ½ m r², I_xx = m/12 (3r² + h²))",
            e(radius),
            e(height)
        ),
        Shape::Capsule { radius, height } => format!(
            "capsule r = {}, h = {} (a cylinder and two half balls)",
            e(radius),
            e(height)
        ),
        Shape::HalfSpace { .. } => "half-space".to_string(),
    }
}
