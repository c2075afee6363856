//! The input of one contact, a by-value view taken from a world: the two
//! bodies, the contact geometry, its coefficients and parameters.

use nalgebra::{Matrix3, Vector3};

use super::{Real, RigidBody};
use crate::physics::{ContactParams, FrictionModel};

/// The contact as the stages see it. `normal` is unit length and points from
/// body 2 toward body 1.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactInput<T: Real> {
    pub point: Vector3<T>,
    pub normal: Vector3<T>,
    pub penetration: T,
    pub restitution: T,
    pub static_friction: T,
    pub dynamic_friction: T,
    pub friction_model: FrictionModel,
    pub settings: ContactParams<T>,
}

impl<T: Real> ContactInput<T> {
    /// A contact has friction when either coefficient is positive.
    pub fn has_friction(&self) -> bool {
        self.static_friction > T::zero() || self.dynamic_friction > T::zero()
    }
}

/// Everything one contact needs. Slot 0 is body 1, slot 1 is body 2; an
/// absent or immovable body is `None` and contributes nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem<T: Real> {
    pub bodies: [Option<RigidBody<T>>; 2],
    pub contact: ContactInput<T>,
    /// Last frame's duration, for acceleration compensation (a step's parameter).
    pub duration: T,
}

/// Each slot's world inverse inertia `R I_b⁻¹ Rᵀ` (`None` for an empty
/// slot), computed once per solve and handed to the stages that need it.
pub type InverseInertias<T> = [Option<Matrix3<T>>; 2];

impl<T: Real> Problem<T> {
    /// Each slot's world inverse inertia `R I_b⁻¹ Rᵀ`.
    pub fn inverse_inertias(&self) -> InverseInertias<T> {
        // Written out, not `each_ref().map(..)`: the array is then built in place.
        [
            self.bodies[0]
                .as_ref()
                .map(RigidBody::inverse_inertia_world),
            self.bodies[1]
                .as_ref()
                .map(RigidBody::inverse_inertia_world),
        ]
    }

    /// The sign body i takes in the contact: +1 for body 1, -1 for body 2
    /// (the lecture's (-1)^(i+1)).
    pub fn sign(i: usize) -> T {
        if i == 0 {
            T::one()
        } else {
            -T::one()
        }
    }
}
