//! Stage 3: closing velocity at the contact and the desired change in velocity
//! `Δv = −v_acc − (1+c)(v_s − v_acc)` (lecture: "Remove Accelerated Velocity";
//! with no acceleration this is `Δv = −(1+c) v_s`).

use nalgebra::Vector3;

use super::ContactFrame;
use crate::physics::{Problem, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct DesiredVelocity<T: Real> {
    /// Velocity of each body's contact point, `ω × r + v`.
    pub point_velocity: [Option<Vector3<T>>; 2],
    /// `q̇₁ − q̇₂` in world coordinates.
    pub contact_velocity_world: Vector3<T>,
    /// The same in contact coordinates; `.x` is `v_s` (negative when closing).
    pub contact_velocity: Vector3<T>,
    /// Restitution as given.
    pub restitution_given: T,
    /// Restitution as applied (0 below the velocity limit).
    pub restitution: T,
    /// True when the velocity limit forced restitution to 0.
    pub restitution_limited: bool,
    /// `(a₁ − a₂)·d · duration`, velocity built up by last frame's acceleration.
    pub velocity_from_acceleration: T,
    /// Δv along the normal.
    pub desired: T,
}

impl<T: Real> DesiredVelocity<T> {
    /// `v_s`, the separating velocity along the normal.
    pub fn separating(&self) -> T {
        self.contact_velocity.x
    }
}

pub fn desired_delta_velocity<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
) -> DesiredVelocity<T> {
    let contact = &problem.contact;
    let d = frame.normal();
    let point_velocity =
        [0, 1].map(|i| Some(problem.bodies[i].as_ref()?.point_velocity(&frame.r[i]?)));
    let contact_velocity_world = point_velocity[0].unwrap_or_else(Vector3::zeros)
        - point_velocity[1].unwrap_or_else(Vector3::zeros);
    let contact_velocity = frame.to_contact(&contact_velocity_world);
    let v_s = contact_velocity.x;

    let mut acceleration = Vector3::zeros();
    for (i, body) in problem.bodies.iter().enumerate() {
        if let Some(b) = body {
            acceleration += b.acceleration * Problem::<T>::sign(i);
        }
    }
    let velocity_from_acceleration = acceleration.dot(&d) * problem.duration;

    // Lower the restitution: a slow (resting) contact does not bounce.
    let restitution_limited = v_s.abs() < contact.settings.velocity_limit;
    let restitution = if restitution_limited {
        T::zero()
    } else {
        contact.restitution
    };

    let desired =
        -velocity_from_acceleration - (T::one() + restitution) * (v_s - velocity_from_acceleration);
    DesiredVelocity {
        point_velocity,
        contact_velocity_world,
        contact_velocity,
        restitution_given: contact.restitution,
        restitution,
        restitution_limited,
        velocity_from_acceleration,
        desired,
    }
}
