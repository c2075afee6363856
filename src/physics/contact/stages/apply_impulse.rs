//! Stage 6: apply the impulse — `Δṗ = g/m`, `Δθ̇ = I⁻¹(r × g)`; body 2 gets `−g`.

use nalgebra::Vector3;

use super::ContactFrame;
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

pub fn apply_impulse<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    impulse_world: &Vector3<T>,
) -> AppliedImpulse<T> {
    let bodies = [0, 1].map(|i| {
        let body = problem.bodies[i].as_ref()?;
        let r = frame.r[i]?;
        let g = impulse_world * Problem::<T>::sign(i);
        let torque = r.cross(&g);
        let dv = g * body.inverse_mass;
        let dw = body.inverse_inertia_world() * torque;
        Some(BodyVelocityChange {
            impulse: g,
            impulsive_torque: torque,
            dv,
            dw,
            v: body.velocity + dv,
            w: body.angular_velocity + dw,
        })
    });
    AppliedImpulse { bodies }
}
