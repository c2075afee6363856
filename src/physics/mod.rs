//! Pure maths of one contact: no I/O, no formatting.
//!
//! A [`Problem`] holds the two bodies of a contact (either may be absent or
//! immovable, written `None`) and the contact itself. [`solve::solve`] runs the
//! stages of `stages/` in the lecture's order and returns a [`solve::Solution`]
//! with one typed record per stage. Everything is generic over the float type
//! so that f32 and f64 runs can be compared.

pub mod body;
pub mod causes;
pub mod checks;
pub mod frame;
pub mod problem;
pub mod scale;
pub mod shape;
pub mod solve;
pub mod stages;

pub use body::RigidBody;
pub use shape::Shape;
pub use problem::{ContactInput, FrictionModel, Problem, ProjectionMethod, Settings};
pub use solve::{solve, Solution};

use nalgebra::RealField;

/// The float types the stage maths runs on (f32 and f64).
pub trait Real: RealField + Copy {}
impl<T: RealField + Copy> Real for T {}

/// Converts an f64 constant into the working float type.
pub fn c<T: Real>(x: f64) -> T {
    nalgebra::convert(x)
}

/// Converts a working float back to f64 (for the trace and comparisons).
pub fn to_f64<T: Real>(x: T) -> f64 {
    nalgebra::try_convert(x).unwrap_or(f64::NAN)
}
