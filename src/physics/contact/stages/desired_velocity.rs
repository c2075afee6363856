//! Stage 3: closing velocity at the contact and the desired change in velocity
//! `Δv = -v_acc - (1+c)(v_s - v_acc)` (lecture: "Remove Accelerated Velocity";
//! with no acceleration this is `Δv = -(1+c) v_s`).
//!
//! As the reference engine does, the contact velocity also carries the planar
//! part of last frame's acceleration × duration (`Cᵀ(a₁ - a₂)Δt` with its
//! normal component zeroed): static friction then removes the sliding that one
//! frame of acceleration built up. The small pieces are functions of their own
//! so the resolver (`physics::resolver`) uses the same formulas.

use nalgebra::{Matrix3, Vector3};

use super::ContactFrame;
use crate::physics::{Problem, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct DesiredVelocity<T: Real> {
    /// Velocity of each body's contact point, `ω × r + v`.
    pub point_velocity: [Option<Vector3<T>>; 2],
    /// `q̇₁ - q̇₂` in world coordinates.
    pub contact_velocity_world: Vector3<T>,
    /// `Cᵀ(q̇₁ - q̇₂)` plus [`DesiredVelocity::planar_from_acceleration`];
    /// `.x` is `v_s` (negative when closing).
    pub contact_velocity: Vector3<T>,
    /// `(0, y, z)` of `Cᵀ(a₁ - a₂)Δt`: the sliding velocity last frame's
    /// acceleration built up (zero without acceleration).
    pub planar_from_acceleration: Vector3<T>,
    /// Restitution as given.
    pub restitution_given: T,
    /// Restitution as applied (0 below the velocity limit).
    pub restitution: T,
    /// True when the velocity limit forced restitution to 0.
    pub restitution_limited: bool,
    /// `(a₁ - a₂)·d · duration`, velocity built up by last frame's acceleration.
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

/// `a₁ - a₂` of the movable bodies (an absent body contributes nothing).
pub fn relative_acceleration<T: Real>(accelerations: [Option<Vector3<T>>; 2]) -> Vector3<T> {
    let mut acceleration = Vector3::zeros();
    for (i, a) in accelerations.iter().enumerate() {
        if let Some(a) = a {
            acceleration += a * Problem::<T>::sign(i);
        }
    }
    acceleration
}

/// `v_acc = (a₁ - a₂)·d Δt`, the normal velocity one frame of acceleration built up.
pub fn velocity_from_acceleration<T: Real>(
    acceleration: &Vector3<T>,
    d: &Vector3<T>,
    duration: T,
) -> T {
    acceleration.dot(d) * duration
}

/// `(0, y, z)` of `Cᵀ (a₁ - a₂)Δt` (the reference engine's `accVelocity` with x zeroed).
pub fn planar_from_acceleration<T: Real>(
    acceleration: &Vector3<T>,
    contact_to_world: &Matrix3<T>,
    duration: T,
) -> Vector3<T> {
    let mut planar = contact_to_world.transpose() * (acceleration * duration);
    planar.x = T::zero();
    planar
}

/// `(q̇₁ - q̇₂, Cᵀ(q̇₁ - q̇₂) + planar)`: the contact velocity in world and in
/// contact coordinates from each slot's point velocity `ω × r + v`, with the
/// planar acceleration term added where it is non-zero.
pub fn contact_velocity<T: Real>(
    point_velocity: &[Option<Vector3<T>>; 2],
    contact_to_world: &Matrix3<T>,
    planar: &Vector3<T>,
) -> (Vector3<T>, Vector3<T>) {
    let world = point_velocity[0].unwrap_or_else(Vector3::zeros)
        - point_velocity[1].unwrap_or_else(Vector3::zeros);
    let mut contact = contact_to_world.transpose() * world;
    if *planar != Vector3::zeros() {
        contact += planar;
    }
    (world, contact)
}

/// `(v_acc, planar)` of a contact from `a₁ - a₂`: both zero without acceleration.
#[inline]
pub fn acceleration_terms<T: Real>(
    acceleration: &Vector3<T>,
    contact_to_world: &Matrix3<T>,
    duration: T,
) -> (T, Vector3<T>) {
    let d = contact_to_world.column(0).into_owned();
    let v_acc = velocity_from_acceleration(acceleration, &d, duration);
    let planar = if *acceleration == Vector3::zeros() {
        Vector3::zeros()
    } else {
        planar_from_acceleration(acceleration, contact_to_world, duration)
    };
    (v_acc, planar)
}

/// Restitution as applied: 0 when the closing speed |v_s| is below the velocity limit.
/// Returns `(c, limited)`.
pub fn applied_restitution<T: Real>(v_s: T, restitution: T, velocity_limit: T) -> (T, bool) {
    // Lower the restitution: a slow (resting) contact does not bounce.
    if v_s.abs() < velocity_limit {
        (T::zero(), true)
    } else {
        (restitution, false)
    }
}

/// `Δv = -v_acc - (1 + c)(v_s - v_acc)`, restitution applied to the velocity `v_s` itself.
pub fn desired_from<T: Real>(v_s: T, restitution: T, v_acc: T) -> T {
    -v_acc - (T::one() + restitution) * (v_s - v_acc)
}

/// `Δv = -v - c(v₀ - v_acc)`: the velocity now is `v`, the bounce is taken from
/// an earlier velocity `v₀` (the resolver's `restitution_from = "initial"`).
pub fn desired_toward_bounce<T: Real>(v: T, v_initial: T, restitution: T, v_acc: T) -> T {
    -v - restitution * (v_initial - v_acc)
}

pub fn desired_delta_velocity<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
) -> DesiredVelocity<T> {
    let mut desired = DesiredVelocity::empty();
    desired_delta_velocity_into(problem, frame, &mut desired);
    desired
}

impl<T: Real> DesiredVelocity<T> {
    /// A record to be written by [`desired_delta_velocity_into`].
    pub fn empty() -> Self {
        DesiredVelocity {
            point_velocity: [None, None],
            contact_velocity_world: Vector3::zeros(),
            contact_velocity: Vector3::zeros(),
            planar_from_acceleration: Vector3::zeros(),
            restitution_given: T::zero(),
            restitution: T::zero(),
            restitution_limited: false,
            velocity_from_acceleration: T::zero(),
            desired: T::zero(),
        }
    }
}

/// [`desired_delta_velocity`] written into `out` (the stage path's form).
#[inline]
pub fn desired_delta_velocity_into<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    out: &mut DesiredVelocity<T>,
) {
    let contact = &problem.contact;
    for (i, slot) in out.point_velocity.iter_mut().enumerate() {
        *slot = match (problem.bodies[i].as_ref(), frame.r[i]) {
            (Some(body), Some(r)) => Some(body.point_velocity(&r)),
            _ => None,
        };
    }
    let acceleration = relative_acceleration([
        problem.bodies[0].as_ref().map(|b| b.acceleration),
        problem.bodies[1].as_ref().map(|b| b.acceleration),
    ]);
    let (velocity_from_acceleration, planar_from_acceleration) =
        acceleration_terms(&acceleration, &frame.contact_to_world, problem.duration);
    let (contact_velocity_world, contact_velocity) = contact_velocity(
        &out.point_velocity,
        &frame.contact_to_world,
        &planar_from_acceleration,
    );
    let v_s = contact_velocity.x;

    let (restitution, restitution_limited) =
        applied_restitution(v_s, contact.restitution, contact.settings.velocity_limit);
    out.contact_velocity_world = contact_velocity_world;
    out.contact_velocity = contact_velocity;
    out.planar_from_acceleration = planar_from_acceleration;
    out.restitution_given = contact.restitution;
    out.restitution = restitution;
    out.restitution_limited = restitution_limited;
    out.velocity_from_acceleration = velocity_from_acceleration;
    out.desired = desired_from(v_s, restitution, velocity_from_acceleration);
}
