//! Stage 8: orientation update `θ' = θ + ½ [0, Δθ] θ`, then normalise.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::Projection;
use crate::physics::scale::stable_norm;
use crate::physics::{c, Problem, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct BodyOrientation<T: Real> {
    pub before: Quaternion<T>,
    /// The rotation vector Δθ applied.
    pub rotation: Vector3<T>,
    pub unnormalised: Quaternion<T>,
    pub normalised: Quaternion<T>,
}

/// The turn an orientation update makes, in degrees: what the trace shows
/// of it (computed there, from the record, never on the stage path).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turn<T: Real> {
    /// Angle of the rotation from `before` to `normalised`, in degrees (≥ 0).
    pub angle_degrees: T,
    /// Unit axis of that rotation (zero when there is none).
    pub axis: Vector3<T>,
    /// `|Δθ|` in degrees: the small-angle estimate of the same angle.
    pub rotation_vector_degrees: T,
    /// Tait–Bryan angles of the new orientation, intrinsic z-y′-x″ (yaw, pitch, roll), degrees.
    pub euler_zyx_degrees: Vector3<T>,
}

impl<T: Real> BodyOrientation<T> {
    /// The turn from `before` to `normalised`: `δ = θ′ θ⁻¹` as angle and
    /// axis, `|Δθ|`, and the new orientation's Euler angles, in degrees.
    pub fn turn(&self) -> Turn<T> {
        let degrees = c::<T>(180.0) / T::pi();
        let unit = UnitQuaternion::new_unchecked(self.normalised);
        let delta = unit * UnitQuaternion::new_normalize(self.before).inverse();
        let (axis, angle) = delta
            .axis_angle()
            .map(|(a, ang)| (a.into_inner(), ang))
            .unwrap_or((Vector3::zeros(), T::zero()));
        let (roll, pitch, yaw) = unit.euler_angles();
        Turn {
            angle_degrees: angle * degrees,
            axis,
            rotation_vector_degrees: stable_norm(&self.rotation) * degrees,
            euler_zyx_degrees: Vector3::new(yaw, pitch, roll) * degrees,
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct OrientationUpdate<T: Real> {
    pub bodies: [Option<BodyOrientation<T>>; 2],
}

/// `θ + ½ [0, Δθ] θ` (lecture, "Nonlinear Projection"), not normalised.
#[inline]
pub fn add_scaled_rotation<T: Real>(theta: &Quaternion<T>, rotation: &Vector3<T>) -> Quaternion<T> {
    let spin = Quaternion::new(T::zero(), rotation.x, rotation.y, rotation.z);
    theta + (spin * theta) * c::<T>(0.5)
}

pub fn orientation_update<T: Real>(
    problem: &Problem<T>,
    projection: &Projection<T>,
) -> OrientationUpdate<T> {
    let mut update = OrientationUpdate {
        bodies: [None, None],
    };
    orientation_update_into(problem, projection, &mut update);
    update
}

/// [`orientation_update`] written into `out` (the stage path's form).
#[inline]
pub fn orientation_update_into<T: Real>(
    problem: &Problem<T>,
    projection: &Projection<T>,
    out: &mut OrientationUpdate<T>,
) {
    for (i, slot) in out.bodies.iter_mut().enumerate() {
        *slot = match (problem.bodies[i].as_ref(), projection.bodies[i].as_ref()) {
            (Some(body), Some(moved)) if moved.angular_change != Vector3::zeros() => {
                let before = body.orientation;
                let unnormalised = add_scaled_rotation(&before, &moved.angular_change);
                Some(BodyOrientation {
                    before,
                    rotation: moved.angular_change,
                    unnormalised,
                    normalised: UnitQuaternion::new_normalize(unnormalised).into_inner(),
                })
            }
            _ => None,
        };
    }
}
