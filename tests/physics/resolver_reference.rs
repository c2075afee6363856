//! The resolver agrees with the reference engine's (Millington's cyclone,
//! `ContactResolver::resolveContacts` in `src/contacts.cpp`) on its own kind
//! of scenes, to 1e-9, configured as that engine is: restitution from the
//! current velocity, epsilons 0.01, velocity limit 0.25, angular limit
//! `(real)0.2f` = 0.20000000298023224, 8 × contacts iterations per phase.
//!
//! How the expected numbers were produced: cyclone's `contacts.cpp`,
//! `body.cpp` and `core.{h,cpp}` (github.com/idmillington/cyclone-physics,
//! double precision) were compiled with g++ 12 (-O2, x86-64) outside this
//! repository, with a small driver of ours that reads each scene below
//! (bodies: inverse mass, body-frame inverse inertia, pose, velocities, last
//! frame's acceleration via `integrate(0)`; contacts: bodies, point, normal,
//! penetration, restitution, friction), calls `resolveContacts` and prints the
//! bodies and each contact's penetration and desired Δv with `%.17g`. Those
//! outputs are pasted below verbatim. One change to cyclone: its tangent typo
//! (`contactTangent[1].x = n.y·t0.x`, wrong when |n.x| > |n.y|) was corrected
//! to the cross product `(n × t0).x`, as contact-lab computes it; only
//! `box-wall-friction` (a friction contact with |n.x| > |n.y|) depends on it.
//! None of cyclone's code is in this repository.

use contact_lab::physics::params::{ResolverParams, RestitutionFrom};
use contact_lab::physics::resolver::{Implementation, Resolver, Silent};
use contact_lab::physics::{
    Body, BodyId, Contact, ContactInput, ContactParams, FrictionModel, ProjectionMethod, RigidBody,
    StepParams, World,
};
use nalgebra::{Matrix3, Quaternion, Vector3};

#[path = "../reference/cyclone_scenes.rs"]
mod scenes;
use scenes::*;

fn numbers(words: &[&str]) -> Vec<f64> {
    words.iter().map(|w| w.parse().unwrap()).collect()
}

fn v3(x: &[f64]) -> Vector3<f64> {
    Vector3::new(x[0], x[1], x[2])
}

/// The scene in the driver's input format, as a world configured like cyclone.
fn world(scene: &str) -> World<f64> {
    let mut w = World {
        bodies: vec![],
        contacts: vec![],
        step: StepParams::default(),
    };
    for line in scene.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.first() {
            Some(&"duration") => w.step.duration = words[1].parse().unwrap(),
            Some(&"body") => {
                let x = numbers(&words[2..]);
                let inverse = Matrix3::from_row_slice(&x[1..10]);
                let q = Quaternion::new(x[13], x[14], x[15], x[16]);
                w.bodies.push(Body {
                    state: RigidBody {
                        mass: 1.0 / x[0],
                        inverse_mass: x[0],
                        inertia_body: inverse.try_inverse().unwrap(),
                        inverse_inertia_body: inverse,
                        position: v3(&x[10..13]),
                        orientation: q.normalize(),
                        velocity: v3(&x[17..20]),
                        angular_velocity: v3(&x[20..23]),
                        acceleration: v3(&x[23..26]),
                    },
                    shape: None,
                    movable: true,
                });
            }
            Some(&"contact") => {
                let b2: i64 = words[2].parse().unwrap();
                let x = numbers(&words[3..]);
                w.contacts.push(Contact {
                    body1: BodyId(words[1].parse().unwrap()),
                    body2: (b2 >= 0).then_some(BodyId(b2 as usize)),
                    input: ContactInput {
                        point: v3(&x[0..3]),
                        normal: v3(&x[3..6]),
                        penetration: x[6],
                        restitution: x[7],
                        static_friction: x[8],
                        dynamic_friction: x[8],
                        friction_model: FrictionModel::Millington,
                        settings: ContactParams {
                            velocity_limit: 0.25,
                            angular_limit: f64::from(0.2f32),
                            relaxation: 1.0,
                            projection: ProjectionMethod::Nonlinear,
                            exact: None,
                        },
                    },
                    duration: None,
                });
            }
            _ => {}
        }
    }
    w
}

/// |a − b| ≤ 1e-9 · max(1, |b|), reporting the largest difference.
fn close(what: &str, ours: &[f64], theirs: &[f64], worst: &mut f64) {
    assert_eq!(ours.len(), theirs.len(), "{what}");
    for (a, b) in ours.iter().zip(theirs) {
        let diff = (a - b).abs() / b.abs().max(1.0);
        *worst = worst.max(diff);
        assert!(
            diff <= 1e-9,
            "{what}: ours {a}, cyclone {b} ({ours:?} vs {theirs:?})"
        );
    }
}

fn agrees_with_cyclone(scene: &(&str, &str, &str)) -> f64 {
    let (name, text, expected) = scene;
    let w = world(text);
    let params = ResolverParams {
        restitution_from: RestitutionFrom::Current,
        ..ResolverParams::default()
    };
    let mut worst = 0.0f64;
    for implementation in [Implementation::Scan, Implementation::Indexed] {
        let (r, [position, velocity]) = Resolver::resolve(&w, &params, implementation, &mut Silent);
        for line in expected.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            match words.first() {
                Some(&"position_iterations") => {
                    assert_eq!(
                        position.iterations_used,
                        words[1].parse::<usize>().unwrap(),
                        "{name}"
                    )
                }
                Some(&"velocity_iterations") => {
                    assert_eq!(
                        velocity.iterations_used,
                        words[1].parse::<usize>().unwrap(),
                        "{name}"
                    )
                }
                Some(&"body") => {
                    // Bodies are numbered in the scene's order; all are movable.
                    let index = text
                        .lines()
                        .filter(|l| l.starts_with("body "))
                        .position(|l| l.split_whitespace().nth(1) == Some(words[1]))
                        .unwrap();
                    let i = r.bodies.iter().position(|b| b.id == BodyId(index)).unwrap();
                    let x = numbers(&words[2..]);
                    let b = &r.bodies[i];
                    let what = format!("{name} {implementation:?} body {}", words[1]);
                    close(
                        &format!("{what} position"),
                        b.position.as_slice(),
                        &x[0..3],
                        &mut worst,
                    );
                    let q = b.unit_orientation();
                    close(
                        &format!("{what} orientation"),
                        &[q.w, q.i, q.j, q.k],
                        &x[3..7],
                        &mut worst,
                    );
                    close(
                        &format!("{what} velocity"),
                        b.velocity.as_slice(),
                        &x[7..10],
                        &mut worst,
                    );
                    close(
                        &format!("{what} rotation"),
                        b.angular_velocity.as_slice(),
                        &x[10..13],
                        &mut worst,
                    );
                }
                Some(&"contact") => {
                    let k: usize = words[1].parse().unwrap();
                    let x = numbers(&words[2..]);
                    let c = &r.contacts[k];
                    let what = format!("{name} {implementation:?} contact {k}");
                    close(&what, &[c.penetration, c.desired], &x, &mut worst);
                }
                _ => {}
            }
        }
    }
    worst
}

#[test]
fn agrees_with_the_reference_engine_on_its_scenes() {
    let mut worst = 0.0f64;
    for scene in [
        BOX_FOUR_CORNERS,
        TURNED_BOX_FRICTION,
        SPHERE_ROW,
        CUBE_STACK,
        NEWTONS_CRADLE,
        BOX_WALL_FRICTION,
        PLANK_ANGULAR_LIMIT,
        RANDOM_HEAP,
    ] {
        let d = agrees_with_cyclone(&scene);
        println!("{:>22}: largest difference {d:.1e}", scene.0);
        worst = worst.max(d);
    }
    println!("largest difference over all scenes: {worst:.1e}");
}
