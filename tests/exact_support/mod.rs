//! Random single contacts for the impact-integration tests, drawn with a
//! SplitMix64 so every run sees the same cases.
#![allow(dead_code)]

use contact_lab::exercise::rng::SplitMix64;
use contact_lab::physics::{ContactInput, ContactParams, FrictionModel, Problem, RigidBody};
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};

/// Uniform in [lo, hi).
pub fn uniform(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

pub fn vector(rng: &mut SplitMix64, size: f64) -> Vector3<f64> {
    Vector3::from_fn(|_, _| uniform(rng, -size, size))
}

pub fn rotation(rng: &mut SplitMix64) -> UnitQuaternion<f64> {
    loop {
        let q = Quaternion::new(
            uniform(rng, -1.0, 1.0),
            uniform(rng, -1.0, 1.0),
            uniform(rng, -1.0, 1.0),
            uniform(rng, -1.0, 1.0),
        );
        if q.norm() > 0.1 {
            return UnitQuaternion::new_normalize(q);
        }
    }
}

/// A random symmetric positive-definite matrix with condition number up to ~1e3.
pub fn spd(rng: &mut SplitMix64) -> Matrix3<f64> {
    let r = rotation(rng).to_rotation_matrix().into_inner();
    let d = Matrix3::from_diagonal(&Vector3::from_fn(|_, _| {
        10f64.powf(uniform(rng, -1.5, 1.5))
    }));
    let k = r * d * r.transpose();
    (k + k.transpose()) * 0.5
}

/// A box body: mass 0.1–10, sides 0.2–3, at a random orientation.
pub fn body(rng: &mut SplitMix64, planar: bool) -> RigidBody<f64> {
    let mass = 10f64.powf(uniform(rng, -1.0, 1.0));
    let s = Vector3::from_fn(|_, _| uniform(rng, 0.2, 3.0));
    let moments = Vector3::new(
        s.y * s.y + s.z * s.z,
        s.x * s.x + s.z * s.z,
        s.x * s.x + s.y * s.y,
    ) * (mass / 12.0);
    let inertia = Matrix3::from_diagonal(&moments);
    let orientation = if planar {
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), uniform(rng, -3.0, 3.0))
    } else {
        rotation(rng)
    };
    let (velocity, angular_velocity) = if planar {
        let v = vector(rng, 3.0);
        (
            Vector3::new(v.x, v.y, 0.0),
            Vector3::new(0.0, 0.0, uniform(rng, -5.0, 5.0)),
        )
    } else {
        (vector(rng, 3.0), vector(rng, 5.0))
    };
    RigidBody {
        mass,
        inverse_mass: 1.0 / mass,
        inertia_body: inertia,
        inverse_inertia_body: inertia.try_inverse().unwrap(),
        position: Vector3::zeros(),
        orientation: *orientation.quaternion(),
        velocity,
        angular_velocity,
        acceleration: Vector3::zeros(),
    }
}

/// How a random contact is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// One or two bodies, any normal, any motion: the slip direction turns.
    General,
    /// One body in the xy plane on a floor (normal y): slip keeps its line.
    Planar,
    /// As General or Planar, with the tangential contact velocity removed.
    AtRest { planar: bool },
}

/// A closing contact with friction μ_s 0.05–1.2, μ_d = (0.7–1) μ_s, e 0–1.
pub fn contact(rng: &mut SplitMix64, family: Family) -> Problem<f64> {
    let planar = matches!(family, Family::Planar | Family::AtRest { planar: true });
    let normal = if planar {
        Vector3::y()
    } else {
        loop {
            let n = vector(rng, 1.0);
            if n.norm() > 0.1 {
                break n.normalize();
            }
        }
    };
    let mut first = body(rng, planar);
    let arm = if planar {
        Vector3::new(uniform(rng, -1.5, 1.5), uniform(rng, -1.5, -0.1), 0.0)
    } else {
        vector(rng, 1.5) - normal * 0.5
    };
    first.position = -arm;
    let second = (!planar && rng.coin()).then(|| {
        let mut b = body(rng, false);
        b.position = vector(rng, 1.5) + normal * 0.5;
        b
    });
    let mu_s = uniform(rng, 0.05, 1.2);
    let mut problem = Problem {
        bodies: [Some(first), second],
        contact: ContactInput {
            point: Vector3::zeros(),
            normal,
            penetration: 0.0,
            restitution: uniform(rng, 0.0, 1.0),
            static_friction: mu_s,
            dynamic_friction: mu_s * uniform(rng, 0.7, 1.0),
            friction_model: FrictionModel::Millington,
            settings: ContactParams::default(),
        },
        duration: 0.01,
    };
    let u = contact_velocity(&problem);
    if matches!(family, Family::AtRest { .. }) {
        // Remove the tangential contact velocity through body 1's velocity.
        let tangential = u - normal * u.dot(&normal);
        problem.bodies[0].as_mut().unwrap().velocity -= tangential;
    }
    if contact_velocity(&problem).dot(&normal) >= -1e-3 {
        // Closing: reverse every motion (u ↦ −u), and make sure it closes.
        for b in problem.bodies.iter_mut().flatten() {
            b.velocity = -b.velocity;
            b.angular_velocity = -b.angular_velocity;
        }
        let b1 = problem.bodies[0].as_mut().unwrap();
        b1.velocity -= normal * uniform(rng, 0.1, 2.0);
    }
    problem
}

/// World contact velocity `q̇₁ − q̇₂` at the contact point.
pub fn contact_velocity(p: &Problem<f64>) -> Vector3<f64> {
    let mut u = Vector3::zeros();
    for (i, b) in p.bodies.iter().enumerate() {
        if let Some(b) = b {
            let r = p.contact.point - b.position;
            let v = b.velocity + b.angular_velocity.cross(&r);
            u += if i == 0 { v } else { -v };
        }
    }
    u
}

/// Rotation about z by `angle` as a `[w, x, y, z]` quaternion.
pub fn about_z(angle: f64) -> Quaternion<f64> {
    *UnitQuaternion::from_rotation_matrix(&Rotation3::from_axis_angle(&Vector3::z_axis(), angle))
        .quaternion()
}

/// `½ u0ᵀ K⁻¹ u0`: the contact-space kinetic energy a perfectly plastic,
/// sticking impact would remove (the scale of energy differences).
pub fn collision_energy(k: &Matrix3<f64>, u0: &Vector3<f64>) -> f64 {
    0.5 * u0.dot(&k.cholesky().unwrap().solve(u0))
}

/// Median of a list (0 when empty).
pub fn median(xs: &mut [f64]) -> f64 {
    if xs.is_empty() {
        return 0.0;
    }
    xs.sort_by(|a, b| a.total_cmp(b));
    xs[xs.len() / 2]
}
