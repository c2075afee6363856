//! Rigid body state as the stages see it.

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::Real;

/// One movable body of a contact. Immovable bodies are not represented: a
/// contact slot holding `None` contributes nothing and costs nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody<T: Real> {
    pub mass: T,
    pub inverse_mass: T,
    /// Body-frame inertia tensor (needed for momentum and energy checks).
    pub inertia_body: Matrix3<T>,
    /// Body-frame inverse inertia tensor.
    pub inverse_inertia_body: Matrix3<T>,
    pub position: Vector3<T>,
    /// Orientation `[w, x, y, z]`, unit length.
    pub orientation: Quaternion<T>,
    pub velocity: Vector3<T>,
    pub angular_velocity: Vector3<T>,
    /// Last frame's acceleration, for the micro-collision compensation.
    pub acceleration: Vector3<T>,
}

impl<T: Real> RigidBody<T> {
    /// Rotation matrix R of the body's orientation.
    pub fn rotation(&self) -> Matrix3<T> {
        UnitQuaternion::new_normalize(self.orientation)
            .to_rotation_matrix()
            .into_inner()
    }

    /// World inverse inertia `I_w⁻¹ = R I_b⁻¹ Rᵀ`.
    pub fn inverse_inertia_world(&self) -> Matrix3<T> {
        to_world(&self.rotation(), &self.inverse_inertia_body)
    }

    /// World inertia `I_w = R I_b Rᵀ`.
    pub fn inertia_world(&self) -> Matrix3<T> {
        to_world(&self.rotation(), &self.inertia_body)
    }

    /// Velocity of the material point at offset `r` from the centre: `ω × r + v` (lecture eq. A).
    pub fn point_velocity(&self, r: &Vector3<T>) -> Vector3<T> {
        self.angular_velocity.cross(r) + self.velocity
    }

    /// Kinetic energy `½ m v·v + ½ ωᵀ I ω`.
    pub fn kinetic_energy(&self, velocity: &Vector3<T>, angular_velocity: &Vector3<T>) -> T {
        self.kinetic_energy_with(&self.inertia_world(), velocity, angular_velocity)
    }

    /// [`RigidBody::kinetic_energy`] with the world inertia `I` already at hand.
    pub fn kinetic_energy_with(
        &self,
        inertia_world: &Matrix3<T>,
        velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
    ) -> T {
        let half = super::c::<T>(0.5);
        half * self.mass * velocity.dot(velocity)
            + half * angular_velocity.dot(&(inertia_world * angular_velocity))
    }

    /// Angular momentum about the world point `q`: `I ω + (p - q) × m v`.
    pub fn angular_momentum_about(
        &self,
        q: &Vector3<T>,
        velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
    ) -> Vector3<T> {
        self.angular_momentum_about_with(&self.inertia_world(), q, velocity, angular_velocity)
    }

    /// [`RigidBody::angular_momentum_about`] with the world inertia `I` already at hand.
    pub fn angular_momentum_about_with(
        &self,
        inertia_world: &Matrix3<T>,
        q: &Vector3<T>,
        velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
    ) -> Vector3<T> {
        inertia_world * angular_velocity + (self.position - q).cross(&(velocity * self.mass))
    }
}

/// `R A Rᵀ` for a symmetric `A`, made exactly symmetric, with entries at
/// round-off level (below 8ε of the largest) set to zero: a turned cube's
/// isotropic tensor stays diagonal instead of growing ±1e-19 noise.
fn to_world<T: Real>(r: &Matrix3<T>, a: &Matrix3<T>) -> Matrix3<T> {
    let m = r * a * r.transpose();
    let m = (m + m.transpose()) * super::c::<T>(0.5);
    let floor = m.amax() * T::default_epsilon() * super::c::<T>(8.0);
    m.map(|x| if x.abs() <= floor { T::zero() } else { x })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn momentum_with_the_inertia_at_hand_is_the_same_bit_for_bit() {
        let body = RigidBody {
            mass: 2.0,
            inverse_mass: 0.5,
            inertia_body: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
            inverse_inertia_body: Matrix3::from_diagonal(&Vector3::new(1.0, 0.5, 1.0 / 3.0)),
            position: Vector3::new(0.1, 0.2, 0.3),
            orientation: Quaternion::new(0.9, 0.1, -0.3, 0.2),
            velocity: Vector3::new(1.0, -2.0, 0.5),
            angular_velocity: Vector3::new(0.3, 0.7, -1.1),
            acceleration: Vector3::zeros(),
        };
        let inertia = body.inertia_world();
        assert_ne!(inertia, body.inertia_body, "the rotation turns the tensor");
        let q = Vector3::new(-0.4, 0.0, 0.9);
        let (v, w) = (body.velocity, body.angular_velocity);
        assert_eq!(
            body.angular_momentum_about_with(&inertia, &q, &v, &w),
            body.angular_momentum_about(&q, &v, &w)
        );
    }
}
