//! Random bodies for the property tests: mass 10^log_m, a rotated
//! anisotropic inertia (principal moments i, 1.7 i, 2.3 i with i = 10^log_i),
//! a position above the floor, and velocities and last frame's acceleration
//! in the given ranges.

use std::ops::Range;

use contact_lab::physics::RigidBody;
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use proptest::prelude::*;

pub fn body(
    log_m: Range<f64>,
    log_i: Range<f64>,
    acceleration: f64,
) -> impl Strategy<Value = RigidBody<f64>> {
    (
        log_m,
        log_i,
        prop::array::uniform4(-1.0..1.0f64),
        prop::array::uniform3(-2.0..2.0f64),
        prop::array::uniform3(-3.0..3.0f64),
        prop::array::uniform3(-1.0..1.0f64),
        prop::array::uniform3(-acceleration..acceleration),
    )
        .prop_map(|(log_m, log_i, q, p, v, w, a)| {
            let m = 10f64.powf(log_m);
            let i = 10f64.powf(log_i);
            let r = UnitQuaternion::new_normalize(Quaternion::new(q[0] + 1.5, q[1], q[2], q[3]));
            let d = Matrix3::from_diagonal(&Vector3::new(i, i * 1.7, i * 2.3));
            let r = r.to_rotation_matrix().into_inner();
            let inertia = r * d * r.transpose();
            RigidBody {
                mass: m,
                inverse_mass: 1.0 / m,
                inertia_body: inertia,
                inverse_inertia_body: inertia.try_inverse().unwrap(),
                position: Vector3::new(p[0], 1.0 + p[1].abs(), p[2]),
                orientation: Quaternion::identity(),
                velocity: Vector3::from(v),
                angular_velocity: Vector3::from(w),
                acceleration: Vector3::from(a),
            }
        })
}

/// One contact at the origin with normal +y between `b1` and `b2` (or the
/// world), nonlinear projection, restitution `c`, friction `mu.0` static and
/// `mu.0 · mu.1` dynamic under `model`, resolved with frame time `duration`.
pub fn floor_problem(
    b1: RigidBody<f64>,
    b2: Option<RigidBody<f64>>,
    c: f64,
    mu: (f64, f64),
    model: contact_lab::physics::FrictionModel,
    penetration: f64,
    duration: f64,
) -> contact_lab::physics::Problem<f64> {
    use contact_lab::physics::{ContactInput, ContactParams, ProjectionMethod};
    contact_lab::physics::Problem {
        bodies: [Some(b1), b2],
        contact: ContactInput {
            point: Vector3::zeros(),
            normal: Vector3::y(),
            penetration,
            restitution: c,
            static_friction: mu.0,
            dynamic_friction: mu.0 * mu.1,
            friction_model: model,
            settings: ContactParams {
                projection: ProjectionMethod::Nonlinear,
                ..ContactParams::default()
            },
        },
        duration,
    }
}
