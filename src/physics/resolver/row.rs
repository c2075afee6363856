//! A row of touching spheres on a floor: the resolver's benchmark and the
//! scene of the iterations-against-row-length study. Deterministic: the same
//! `n` gives the same world.

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::physics::{
    c, Body, BodyId, Contact, ContactInput, ContactParams, FrictionModel, Real, RigidBody,
    StepParams, World,
};

/// A number in [0, 1) from an index (a fixed scramble, not a random generator).
fn spread(i: usize, salt: u64) -> f64 {
    let mut x = (i as u64)
        .wrapping_add(salt)
        .wrapping_mul(0x9E37_79B9_7F4A_7C15);
    x ^= x >> 31;
    x = x.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x ^= x >> 29;
    (x >> 11) as f64 / (1u64 << 53) as f64
}

/// `n` spheres (radius 0.5, mass 1) in a row along x, each sunk 0.005–0.05
/// into the floor and overlapping its neighbours by about 0.005–0.04 (the
/// normal between neighbours is along their line of centres), falling at
/// 1–1.5 and drifting along the row: `n` floor contacts and `n - 1` contacts
/// between neighbours (2n - 1 in all), in the order floor 0, pair 0–1,
/// floor 1, pair 1–2, …. Frictionless; restitution 0.3 on the floor, 0.5
/// between spheres; the reference engine's velocity limit 0.25.
pub fn sphere_row<T: Real>(n: usize) -> World<T> {
    let radius = 0.5;
    let inertia = 0.4 * radius * radius;
    let overlap: Vec<f64> = (0..n).map(|i| 0.005 + 0.035 * spread(i, 1)).collect();
    let sink: Vec<f64> = (0..n).map(|i| 0.005 + 0.045 * spread(i, 2)).collect();
    let mut x = 0.0;
    let mut bodies = Vec::with_capacity(n);
    let mut centres = Vec::with_capacity(n);
    for i in 0..n {
        if i > 0 {
            x += 2.0 * radius - overlap[i - 1];
        }
        centres.push(x);
        let drift = 0.4 * (spread(i, 3) - 0.5);
        let fall = -1.0 - 0.5 * spread(i, 4);
        bodies.push(Body {
            state: RigidBody {
                mass: T::one(),
                inverse_mass: T::one(),
                inertia_body: Matrix3::identity() * c::<T>(inertia),
                inverse_inertia_body: Matrix3::identity() * c::<T>(1.0 / inertia),
                position: Vector3::new(c(x), c(radius - sink[i]), T::zero()),
                orientation: Quaternion::identity(),
                velocity: Vector3::new(c(drift), c(fall), T::zero()),
                angular_velocity: Vector3::zeros(),
                acceleration: Vector3::zeros(),
            },
            shape: None,
            movable: true,
        });
    }
    let settings = ContactParams {
        velocity_limit: c(0.25),
        ..ContactParams::default()
    };
    let contact = |body1: usize,
                   body2: Option<usize>,
                   point: [f64; 3],
                   normal: [f64; 3],
                   pen: f64,
                   e: f64| Contact {
        body1: BodyId(body1),
        body2: body2.map(BodyId),
        input: ContactInput {
            point: Vector3::from(point.map(c)),
            normal: Vector3::from(normal.map(c)),
            penetration: c(pen),
            restitution: c(e),
            static_friction: T::zero(),
            dynamic_friction: T::zero(),
            friction_model: FrictionModel::Millington,
            settings,
        },
        duration: None,
    };
    let mut contacts = Vec::with_capacity(2 * n);
    for i in 0..n {
        contacts.push(contact(
            i,
            None,
            [centres[i], 0.0, 0.0],
            [0.0, 1.0, 0.0],
            sink[i],
            0.3,
        ));
        if i + 1 < n {
            // Normal from body 2 (sphere i) toward body 1 (sphere i + 1),
            // along the line of centres; the point midway between them.
            let (a, b) = (
                [centres[i], radius - sink[i]],
                [centres[i + 1], radius - sink[i + 1]],
            );
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let length = (dx * dx + dy * dy).sqrt();
            contacts.push(contact(
                i + 1,
                Some(i),
                [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.0],
                [dx / length, dy / length, 0.0],
                2.0 * radius - length,
                0.5,
            ));
        }
    }
    World {
        bodies,
        contacts,
        step: StepParams::default(),
    }
}
