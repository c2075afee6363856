//! Stage 6: apply the impulse — `Δṗ = g/m`, `Δθ̇ = I⁻¹(r × g)`; body 2 gets `-g`.

use nalgebra::{Matrix3, Vector3};

use super::ContactFrame;
use crate::physics::contact::problem::InverseInertias;
use crate::physics::{Problem, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct BodyVelocityChange<T: Real> {
    /// The impulse this body receives (`±g`).
    pub impulse: Vector3<T>,
    /// `u = r × g`, impulsive torque.
    pub impulsive_torque: Vector3<T>,
    pub dv: Vector3<T>,
    pub dw: Vector3<T>,
    pub v: Vector3<T>,
    pub w: Vector3<T>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct AppliedImpulse<T: Real> {
    pub bodies: [Option<BodyVelocityChange<T>>; 2],
}

/// One body's velocity change from the impulse `impulse_world` (body 1's
/// sign, `sign` = ±1): `Δṗ = ±g/m`, `Δθ̇ = I⁻¹(r × ±g)`, from its velocities `v`, `w`.
#[inline]
pub fn body_velocity_change<T: Real>(
    inverse_mass: T,
    inverse_inertia_world: &Matrix3<T>,
    r: &Vector3<T>,
    impulse_world: &Vector3<T>,
    sign: T,
    (v, w): (&Vector3<T>, &Vector3<T>),
) -> BodyVelocityChange<T> {
    let g = impulse_world * sign;
    let torque = r.cross(&g);
    let dv = g * inverse_mass;
    let dw = inverse_inertia_world * torque;
    BodyVelocityChange {
        impulse: g,
        impulsive_torque: torque,
        dv,
        dw,
        v: v + dv,
        w: w + dw,
    }
}

pub fn apply_impulse<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    impulse_world: &Vector3<T>,
) -> AppliedImpulse<T> {
    apply_impulse_with(problem, &problem.inverse_inertias(), frame, impulse_world)
}

/// [`apply_impulse`] with each slot's world inverse inertia already at hand.
pub fn apply_impulse_with<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    impulse_world: &Vector3<T>,
) -> AppliedImpulse<T> {
    let mut applied = AppliedImpulse {
        bodies: [None, None],
    };
    apply_impulse_into(
        problem,
        inverse_inertias,
        frame,
        impulse_world,
        &mut applied,
    );
    applied
}

/// [`apply_impulse_with`] written into `out` (the stage path's form: each
/// body's change is written into its slot, no array of records built and moved).
#[inline]
pub fn apply_impulse_into<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    impulse_world: &Vector3<T>,
    out: &mut AppliedImpulse<T>,
) {
    for (i, slot) in out.bodies.iter_mut().enumerate() {
        *slot = match (
            problem.bodies[i].as_ref(),
            frame.r[i],
            inverse_inertias[i].as_ref(),
        ) {
            (Some(body), Some(r), Some(inverse_inertia)) => Some(body_velocity_change(
                body.inverse_mass,
                inverse_inertia,
                &r,
                impulse_world,
                Problem::<T>::sign(i),
                (&body.velocity, &body.angular_velocity),
            )),
            _ => None,
        };
    }
}
