//! Body shapes and the inertia tensors they imply.

use nalgebra::Matrix3;

pub use super::raw::RawShape as Shape;

impl Shape {
    /// Body-frame inertia tensor of a body of mass `m` with this shape, or
    /// `None` for a half-space (which only an immovable body may be).
    pub fn inertia(&self, m: f64) -> Option<Matrix3<f64>> {
        let diag = |a: f64, b: f64, c: f64| Some(Matrix3::from_diagonal(&[a, b, c].into()));
        match *self {
            // Solid sphere: I = 2/5 m r².
            Shape::Sphere(r) => {
                let i = 0.4 * m * r * r;
                diag(i, i, i)
            }
            // Hollow (thin-shelled) sphere: I = 2/3 m r².
            Shape::HollowSphere(r) => {
                let i = 2.0 / 3.0 * m * r * r;
                diag(i, i, i)
            }
            // Solid cuboid with sides x, y, z: I_xx = m/12 (y² + z²), …
            Shape::Box([x, y, z]) => {
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
            Shape::HalfSpace => None,
        }
    }

    /// The formula, for warnings and the trace.
    pub fn describe(&self) -> String {
        let e = crate::format::exact;
        match *self {
            Shape::Sphere(r) => format!("solid sphere r = {} (I = 2/5 m r²)", e(r)),
            Shape::HollowSphere(r) => format!("hollow sphere r = {} (I = 2/3 m r²)", e(r)),
            Shape::Box([x, y, z]) => format!(
                "box {} × {} × {} (I_xx = m/12 (y² + z²), …)",
                e(x),
                e(y),
                e(z)
            ),
            Shape::Cylinder { radius, height } => {
                format!(
                    "cylinder r = {}, h = {} (I_yy = ½ m r², I_xx = m/12 (3r² + h²))",
                    e(radius),
                    e(height)
                )
            }
            Shape::HalfSpace => "half-space".to_string(),
        }
    }

    /// Size numbers that must be positive and finite.
    pub fn dimensions(&self) -> Vec<f64> {
        match *self {
            Shape::Sphere(r) | Shape::HollowSphere(r) => vec![r],
            Shape::Box(s) => s.to_vec(),
            Shape::Cylinder { radius, height } => vec![radius, height],
            Shape::HalfSpace => vec![],
        }
    }
}
