//! What the resolver does, checked on small scenes: one contact resolved
//! together is the single-contact solution; restitution from the current or
//! the initial velocity; the velocity limit; last frame's acceleration; what
//! immovable bodies and frictionless contacts cost; how the row's iterations grow.

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::{ResolverParams, RestitutionFrom};
use contact_lab::physics::resolver::{row::sphere_row, Implementation, Resolver, Silent};
use contact_lab::physics::World;
use nalgebra::Vector3;

fn resolve(world: &World<f64>, params: &ResolverParams) -> Resolver<f64> {
    Resolver::resolve(world, params, Implementation::Indexed, &mut Silent).0
}

fn close(a: &Vector3<f64>, b: &Vector3<f64>) -> bool {
    (a - b).norm() <= 1e-12 * (1.0 + b.norm())
}

/// A lesson with one contact: resolving it "together" is the single-contact
/// worked solution (its projection and its impulse, from the same geometry).
#[test]
fn one_contact_resolved_together_is_the_single_contact_solution() {
    for id in [
        "lecture-1",
        "lecture-2",
        "lecture-3",
        "two-boxes",
        "kane-energy-gain",
    ] {
        let lesson = Lesson::load(id).unwrap();
        let world = lesson.world::<f64>();
        let r = resolve(&world, &ResolverParams::default());
        let solution = contact_lab::physics::solve(&world.problem(0));
        let problem = world.problem(0);
        for b in &r.bodies {
            let slot = [
                world.contacts[0].body1,
                world.contacts[0].body2.unwrap_or(b.id),
            ]
            .iter()
            .position(|id| *id == b.id)
            .unwrap();
            let after = solution.after(&problem, slot).unwrap();
            assert!(
                close(&b.velocity, &after.velocity),
                "{id}: {:?} vs {:?}",
                b.velocity,
                after.velocity
            );
            assert!(close(&b.angular_velocity, &after.angular_velocity), "{id}");
            let moved = problem.contact.penetration > 0.01;
            if moved {
                assert!(close(&b.position, &after.position), "{id}");
                assert!(
                    (b.unit_orientation().coords - after.orientation.coords).norm() < 1e-12,
                    "{id}"
                );
            }
        }
    }
}

fn cradle(from: RestitutionFrom) -> Resolver<f64> {
    let lesson = Lesson::load("newtons-cradle").unwrap();
    let params = ResolverParams {
        restitution_from: from,
        ..lesson.resolver
    };
    resolve(&lesson.world(), &params)
}

#[test]
fn restitution_from_the_current_velocity_makes_a_cradle() {
    let r = cradle(RestitutionFrom::Current);
    let v: Vec<f64> = r.bodies.iter().map(|b| b.velocity.x).collect();
    assert_eq!(v, [0.0, 0.0, 0.0, 0.0, 2.0]);
}

#[test]
fn restitution_from_the_initial_velocity_aims_at_the_velocities_before_the_phase() {
    let r = cradle(RestitutionFrom::Initial);
    let v: Vec<f64> = r.bodies.iter().map(|b| b.velocity.x).collect();
    // Ball 0 bounces back; momentum (2) is kept; the others drift together.
    assert!((v[0] + 1.17046).abs() < 1e-5, "{v:?}");
    assert!((v.iter().sum::<f64>() - 2.0).abs() < 1e-12, "{v:?}");
    assert!(v[1..].iter().all(|x| (0.7..0.85).contains(x)), "{v:?}");
    // Contact 0 was closing at 2 before the phase: with e = 1 its target is
    // +2 apart, and the bookkeeping says it got there.
    assert!((r.contacts[0].velocity.x - 2.0).abs() < 1e-12);
}

/// One ball dropping on the floor with e = 1 at `speed`, the velocity limit 0.25.
fn drop(speed: f64) -> f64 {
    let text = format!(
        r#"
id = "drop"
title = "drop"
[[body]]
name = "ball"
mass = 1.0
shape = {{ sphere = 0.5 }}
position = [0.0, 0.5, 0.0]
velocity = [0.0, {}, 0.0]
[[contact]]
bodies = ["ball"]
point = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
restitution = 1.0
[settings]
velocity_limit = 0.25
"#,
        -speed
    );
    let lesson = contact_lab::lesson::validate::parse("drop.toml", &text).unwrap();
    let r = resolve(&lesson.world(), &lesson.resolver);
    r.bodies[0].velocity.y
}

#[test]
fn below_the_velocity_limit_a_contact_does_not_bounce() {
    assert_eq!(drop(0.2), 0.0);
    assert_eq!(drop(0.3), 0.3);
}

#[test]
fn last_frames_acceleration_adds_its_planar_part_and_is_noted() {
    // A box on a 30° slope that gravity accelerated for one frame (v = a Δt):
    // the contact velocity gains Cᵀ(a Δt) again with its normal part zeroed.
    let text = r#"
id = "slope"
title = "slope"
[[body]]
name = "box"
mass = 2.0
shape = { box = [1.0, 1.0, 1.0] }
position = [0.0, 0.5, 0.0]
velocity = [0.0, -0.1962, 0.0]
acceleration = [0.0, -9.81, 0.0]
[[contact]]
bodies = ["box"]
point = [0.0, 0.0, 0.0]
normal = [-0.5, 0.8660254037844386, 0.0]
restitution = 0.0
friction = 0.8
[settings]
duration = 0.02
"#;
    let lesson = contact_lab::lesson::validate::parse("slope.toml", text).unwrap();
    let problem = lesson.problem::<f64>(0);
    let s = contact_lab::physics::solve(&problem);
    let planar = s.desired.planar_from_acceleration;
    let c = s.frame.contact_to_world;
    let expected = c.transpose() * Vector3::new(0.0, -9.81 * 0.02, 0.0);
    assert_eq!(planar.x, 0.0);
    assert!((planar.y - expected.y).abs() < 1e-15 && (planar.z - expected.z).abs() < 1e-15);
    assert!(planar.norm() > 0.09, "{planar:?}");
    let v = c.transpose() * Vector3::new(0.0, -0.1962, 0.0);
    assert_eq!(s.desired.contact_velocity, v + planar);
    // Its normal part is v_acc, which restitution does not bounce.
    assert!(
        (s.desired.velocity_from_acceleration - (-9.81 * 0.02 * 0.8660254037844386)).abs() < 1e-15
    );
    let trace = contact_lab::worked_solution(&lesson, 0);
    let notes = &trace.stage("desired_delta_velocity").unwrap().notes;
    assert!(
        notes.iter().any(|n| n.contains("Cᵀ(a₁ - a₂)Δt")),
        "{notes:?}"
    );
    // Friction (μ = 0.8 > tan 30°) removes that sliding: the box sticks.
    assert_eq!(
        s.regime(),
        Some(contact_lab::physics::stages::FrictionRegime::Static)
    );
    // The resolver prepares the same contact velocity.
    let r = Resolver::prepare(&lesson.world::<f64>(), &lesson.resolver);
    assert_eq!(r.contacts[0].velocity, s.desired.contact_velocity);
    // Without acceleration no note is added.
    let still = contact_lab::worked_solution(&Lesson::load("friction-cube").unwrap(), 0);
    let notes = &still.stage("desired_delta_velocity").unwrap().notes;
    assert!(!notes.iter().any(|n| n.contains("Cᵀ(a₁ - a₂)Δt")));
}

#[test]
fn the_world_and_immovable_bodies_link_nothing_and_frictionless_contacts_build_no_matrix() {
    let world = sphere_row::<f64>(200);
    let r = Resolver::prepare(&world, &ResolverParams::default());
    // 200 floor contacts share the world, yet each ball touches at most 3 contacts.
    assert_eq!(r.bodies.len(), 200);
    for b in 0..r.bodies.len() {
        assert!(
            r.adjacency.of(b).len() <= 3,
            "ball {b}: {:?}",
            r.adjacency.of(b)
        );
    }
    assert_eq!(r.adjacency.contacts.len(), 200 + 2 * 199);
    assert!(r.friction.is_empty(), "no friction, no 3×3 matrix");
    let stack = Lesson::load("box-stack").unwrap();
    let r = Resolver::prepare(&stack.world::<f64>(), &stack.resolver);
    assert_eq!(
        r.friction.len(),
        12,
        "every contact of the stack has friction"
    );
}

/// The deepest-first order passes penetration along a row: the iterations
/// the position phase needs to get under epsilon grow faster than the row.
#[test]
fn iterations_to_epsilon_grow_with_the_row() {
    let unlimited = ResolverParams {
        position_iterations: Some(1_000_000_000),
        velocity_iterations: Some(1_000_000_000),
        ..ResolverParams::default()
    };
    let needed: Vec<f64> = [5, 10, 20, 40]
        .iter()
        .map(|&n| {
            let world = sphere_row::<f64>(n);
            let (_, [p, v]) =
                Resolver::resolve(&world, &unlimited, Implementation::Indexed, &mut Silent);
            assert!(p.max_after <= 0.01 && v.max_after <= 0.01);
            p.iterations_used as f64 / world.contacts.len() as f64
        })
        .collect();
    assert!(
        needed.windows(2).all(|w| w[1] > w[0]),
        "per contact: {needed:?}"
    );
    // With the default limit (8 × contacts) a row of 40 is left penetrating.
    let (_, [p, _]) = Resolver::resolve(
        &sphere_row::<f64>(40),
        &ResolverParams::default(),
        Implementation::Indexed,
        &mut Silent,
    );
    assert!(p.limit_reached && p.max_after > 0.02, "{p:?}");
}
