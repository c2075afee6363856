//! Properties of every stage over random scenes (proptest). Momentum and the
//! restitution target are recomputed here, independently of `physics::checks`.

use contact_lab::physics::checks::CheckKind;
use contact_lab::physics::frame::contact_basis;
use contact_lab::physics::stages::FrictionRegime;
use contact_lab::physics::{
    solve, ContactInput, ContactParams, FrictionModel, Problem, ProjectionMethod, RigidBody,
};
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use proptest::prelude::*;

fn vec3(range: f64) -> impl Strategy<Value = Vector3<f64>> {
    prop::array::uniform3(-range..range).prop_map(Vector3::from)
}

fn unit_quaternion() -> impl Strategy<Value = UnitQuaternion<f64>> {
    prop::array::uniform4(-1.0..1.0f64)
        .prop_filter("non-degenerate", |q| {
            q.iter().map(|x| x * x).sum::<f64>() > 1e-3
        })
        .prop_map(|q| UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3])))
}

/// Normals along each axis, at the basis switch |d.x| = |d.y|, or random.
fn normal() -> impl Strategy<Value = Vector3<f64>> {
    prop_oneof![
        prop::sample::select(vec![
            Vector3::x(),
            -Vector3::x(),
            Vector3::y(),
            -Vector3::y(),
            Vector3::z(),
            -Vector3::z(),
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::new(1.0, -1.0, 0.5),
            Vector3::new(-2.0, 2.0, 1.0),
        ])
        .prop_map(|v| v.normalize()),
        vec3(1.0)
            .prop_filter("non-zero", |v| v.norm() > 1e-3)
            .prop_map(|v| v.normalize()),
    ]
}

/// A body with a full (non-diagonal) physical inertia tensor: a random box's
/// principal moments in a random principal frame, at a random orientation.
fn body() -> impl Strategy<Value = RigidBody<f64>> {
    (
        -2.0..3.0f64,
        prop::array::uniform3(0.1..5.0f64),
        unit_quaternion(),
        unit_quaternion(),
        vec3(20.0),
        vec3(10.0),
        vec3(10.0),
    )
        .prop_map(
            |(log_m, sides, principal, orientation, position, velocity, spin)| {
                let m = 10f64.powf(log_m);
                let [x, y, z] = sides;
                let d = Matrix3::from_diagonal(&Vector3::new(
                    y * y + z * z,
                    x * x + z * z,
                    x * x + y * y,
                )) * (m / 12.0);
                let r = principal.to_rotation_matrix().into_inner();
                let inertia = r * d * r.transpose();
                RigidBody {
                    mass: m,
                    inverse_mass: 1.0 / m,
                    inertia_body: inertia,
                    inverse_inertia_body: inertia.try_inverse().unwrap(),
                    position,
                    orientation: *orientation.quaternion(),
                    velocity,
                    angular_velocity: spin,
                    acceleration: Vector3::zeros(),
                }
            },
        )
}

fn problem() -> impl Strategy<Value = Problem<f64>> {
    (
        body(),
        prop::option::of(body()),
        vec3(20.0),
        normal(),
        (0.0..1.0f64, 0.0..1.5f64, 0.0..1.0f64, 0.0..2.0f64),
        (
            0.05..1.0f64,
            prop::sample::select(vec![0.2, 1.0, f64::INFINITY]),
        ),
        prop::bool::ANY,
    )
        .prop_map(
            |(b1, b2, point, normal, (c, mu, pen, speed), (relaxation, angular_limit), linear)| {
                // Make body 1 approach along −d so that most scenes collide.
                let mut b1 = b1;
                b1.velocity -= normal * speed * 5.0;
                Problem {
                    bodies: [Some(b1), b2],
                    contact: ContactInput {
                        point,
                        normal,
                        penetration: pen,
                        restitution: c,
                        static_friction: mu,
                        dynamic_friction: mu * 0.8,
                        friction_model: FrictionModel::Millington,
                        settings: ContactParams {
                            relaxation,
                            angular_limit,
                            projection: if linear {
                                ProjectionMethod::Linear
                            } else {
                                ProjectionMethod::Nonlinear
                            },
                            ..ContactParams::default()
                        },
                    },
                    duration: 0.01,
                }
            },
        )
}

fn rel_close(a: Vector3<f64>, b: Vector3<f64>, scale: f64) -> bool {
    (a - b).norm() <= 1e-9 * scale.max(1e-300)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn basis_is_orthonormal_and_right_handed(d in normal()) {
        let (c, _) = contact_basis(&d);
        prop_assert!((c.transpose() * c - Matrix3::identity()).norm() < 1e-14);
        prop_assert!((c.determinant() - 1.0).abs() < 1e-14);
        prop_assert!((c.column(0) - d).norm() == 0.0);
        prop_assert!((c.column(0).cross(&c.column(1)) - c.column(2)).norm() < 1e-14);
    }

    #[test]
    fn friction_matrix_is_symmetric_positive_definite(p in problem()) {
        let s = solve(&p);
        let m = s.unit.matrix.expect("friction builds the matrix");
        prop_assert!((m - m.transpose()).norm() <= 1e-12 * m.norm());
        prop_assert!(m.symmetric_eigenvalues().min() >= s.unit.linear * (1.0 - 1e-9));
        prop_assert!((m[(0, 0)] - s.unit.total).abs() <= 1e-12 * s.unit.total);
    }

    #[test]
    fn momentum_is_conserved_and_the_normal_target_met(p in problem()) {
        let s = solve(&p);
        let Some(applied) = &s.applied else { return Ok(()) };
        let q = p.contact.point;
        let mut linear_before = Vector3::zeros();
        let mut linear_after = Vector3::zeros();
        let mut scale = 0.0;
        let mut separating = 0.0;
        for i in 0..2 {
            let (Some(b), Some(a)) = (&p.bodies[i], &applied.bodies[i]) else { continue };
            linear_before += b.velocity * b.mass;
            linear_after += a.v * b.mass;
            scale += (b.velocity * b.mass).norm() + a.impulse.norm();
            // Angular momentum about the contact point: I ω + (p − q) × m v.
            let l = |v: &Vector3<f64>, w: &Vector3<f64>| b.inertia_world() * w + (b.position - q).cross(&(v * b.mass));
            let (before, after) = (l(&b.velocity, &b.angular_velocity), l(&a.v, &a.w));
            let lscale = before.norm() + after.norm() + (b.position - q).norm() * a.impulse.norm();
            prop_assert!(rel_close(before, after, lscale), "body {i}: {before} → {after}");
            let r = q - b.position;
            let sign = if i == 0 { 1.0 } else { -1.0 };
            separating += sign * (a.w.cross(&r) + a.v).dot(&p.contact.normal);
        }
        if p.bodies[1].is_some() {
            prop_assert!(rel_close(linear_before, linear_after, scale));
        }
        let jammed = s.friction.as_ref().is_some_and(|f| f.issue.is_some());
        if !jammed {
            let target = s.desired.separating() + s.desired.desired;
            prop_assert!((separating - target).abs() <= 1e-8 * (target.abs() + s.desired.contact_velocity.norm() + 1.0),
                "separating {separating} vs target {target}");
        }
    }

    #[test]
    fn the_clamped_impulse_stays_in_the_cone(p in problem()) {
        let s = solve(&p);
        let Some(f) = &s.friction else { return Ok(()) };
        let g = f.impulse_contact;
        let gt = (g.y * g.y + g.z * g.z).sqrt();
        prop_assert!(g.x >= 0.0, "g_n = {}", g.x);
        prop_assert!(gt <= p.contact.static_friction * g.x * (1.0 + 1e-12) + 1e-12 * g.norm());
        if f.regime == FrictionRegime::Dynamic && f.issue.is_none() {
            prop_assert!((gt - p.contact.dynamic_friction * g.x).abs() <= 1e-9 * g.norm());
        }
        prop_assert!(s.checks.get(CheckKind::FrictionCone).is_some_and(|c| c.passed == Some(true)));
    }

    #[test]
    fn projection_sums_to_the_depth_within_the_limit(p in problem()) {
        let s = solve(&p);
        let Some(proj) = &s.projection else { return Ok(()) };
        let mut sum = 0.0;
        for (i, b) in proj.bodies.iter().enumerate() {
            let Some(b) = b else { continue };
            let sign = if i == 0 { 1.0 } else { -1.0 };
            sum += sign * (b.linear_move + b.angular_move);
            prop_assert!(b.angular_move.abs() <= b.angular_limit * (1.0 + 1e-15));
            if p.contact.settings.projection == ProjectionMethod::Linear {
                prop_assert!(b.angular_move == 0.0 && b.angular_change == Vector3::zeros());
            }
        }
        let depth = p.contact.penetration * p.contact.settings.relaxation;
        prop_assert!((sum - depth).abs() <= 1e-12 * depth.max(1e-300), "{sum} vs {depth}");
        if let Some(o) = &s.orientation {
            for b in o.bodies.iter().flatten() {
                prop_assert!((b.normalised.norm() - 1.0).abs() <= 1e-14);
            }
        }
    }

    #[test]
    fn frictionless_contacts_never_gain_energy(mut p in problem()) {
        p.contact.static_friction = 0.0;
        p.contact.dynamic_friction = 0.0;
        let s = solve(&p);
        prop_assert!(s.unit.matrix.is_none(), "a frictionless contact builds no 3×3 matrix");
        if let Some(e) = s.checks.get(CheckKind::Energy) {
            prop_assert_eq!(e.passed, Some(true));
        }
    }

    #[test]
    fn every_value_is_finite(p in problem()) {
        let s = solve(&p);
        // `angular_limit: inf` is the setting "no limit"; nothing else may be inf or NaN.
        let debug = format!("{s:?}").replace("angular_limit: inf", "");
        prop_assert!(!debug.contains("NaN") && !debug.contains("inf"), "{debug}");
    }
}
