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
