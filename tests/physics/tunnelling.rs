//! The tunnelling auditor (issue 25): a bullet at 100 m/s crosses a 2 cm
//! wall inside one 60 Hz step without a contact; the run says so exactly
//! once, and changes nothing (the bullet ends beyond the wall). A ball that
//! hits the same wall at a walking pace is not reported.

use contact_lab::physics::step::{Event, Simulation};
use contact_lab::physics::BodyId;

fn bullet(speed: f64) -> Simulation<f64> {
    let toml = format!(
        r#"
id = "bullet"
title = "A bullet at a thin wall"
source = "issue 25"
summary = "The bullet moves farther in a step than the wall is thick."

[world]
gravity = [0, 0, 0]
restitution = 0.5

[step]
dt = 0.016666666666666666
steps = 30

[[body]]
name = "bullet"
mass = 0.01
shape = {{ sphere = 0.01 }}
position = [-0.5, 0, 0]
velocity = [{speed}, 0, 0]

[[body]]
name = "wall"
mass = inf
shape = {{ box = [0.02, 2, 2] }}
position = [0, 0, 0]
"#
    );
    let lesson = contact_lab::lesson::validate::parse("bullet.toml", &toml).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

fn run(sim: &mut Simulation<f64>, steps: usize) -> Vec<(u64, Event)> {
    let mut seen = Vec::new();
    for _ in 0..steps {
        let r = sim.advance().unwrap();
        seen.extend(r.events.iter().map(|e| (r.step, *e)));
    }
    seen
}

#[test]
fn a_bullet_through_a_thin_wall_is_reported_once_and_not_stopped() {
    let mut sim = bullet(100.0);
    let seen = run(&mut sim, 30);
    let crossed: Vec<_> = seen
        .iter()
        .filter(|(_, e)| matches!(e, Event::Tunnelled { .. }))
        .collect();
    assert_eq!(crossed.len(), 1, "{seen:?}");
    let (step, e) = crossed[0];
    assert_eq!(*step, 1);
    let Event::Tunnelled {
        body1,
        body2,
        time,
        point,
    } = *e
    else {
        unreachable!()
    };
    assert_eq!((body1, body2), (BodyId(0), BodyId(1)));
    // It meets the wall's face (x = −0.01) when it has come 0.5 − 0.02 m.
    let want = (0.5 - 0.02) / 100.0;
    assert!((time - want).abs() < 1e-5, "{time} vs {want}");
    assert!((point[0] + 0.01).abs() < 1e-3, "{point:?}");
    assert!(point[1].abs() < 1e-9 && point[2].abs() < 1e-9);
    // Reported only: the bullet flew on beyond the wall (damping aside, at its speed).
    let b = &sim.world.bodies[0].state;
    assert!(b.position.x > 0.01, "{}", b.position.x);
    assert!(b.velocity.x > 90.0, "{}", b.velocity.x);
}

#[test]
fn a_slow_ball_that_hits_the_wall_is_not_reported() {
    let mut sim = bullet(3.0);
    let seen = run(&mut sim, 30);
    assert!(
        !seen
            .iter()
            .any(|(_, e)| matches!(e, Event::Tunnelled { .. })),
        "{seen:?}"
    );
    // It bounced.
    assert!(sim.world.bodies[0].state.velocity.x < 0.0);
}

/// The audit's set of touching pairs (touching::contact_pairs) holds exactly the
/// pairs of the step's contacts, whether they come pair by pair in order
/// (as generated) or in any other order, each pair in either order.
#[test]
fn the_touching_pairs_are_the_contacts_pairs_in_any_order() {
    use contact_lab::lesson::Lesson;
    use contact_lab::physics::step::touching::{contact_pairs, key};
    use std::collections::BTreeSet;
    let lesson = Lesson::load("stack-5").unwrap();
    let params = lesson.sim_params().expect("a scene");
    let world = lesson.world::<f64>();
    let materials = lesson.simulation.unwrap().materials;
    let mut sim = Simulation::new(world, params, materials);
    for _ in 0..5 {
        sim.advance().unwrap();
    }
    let mut world = sim.world.clone();
    let n = world.bodies.len();
    let naive: BTreeSet<_> = (world.contacts.iter())
        .filter_map(|k| Some(key(k.body1.0, k.body2?.0)))
        .collect();
    assert!(naive.len() >= 5, "a stack of 5 boxes on a floor: {naive:?}");
    let check = |world: &contact_lab::physics::World<f64>| {
        let pairs = contact_pairs(world);
        for i in 0..n {
            for j in 0..n {
                assert_eq!(pairs.contains(&key(i, j)), naive.contains(&key(i, j)));
            }
        }
    };
    check(&world);
    world.contacts.reverse();
    check(&world);
    // By the points' x: the pairs' contacts mixed, a pair's apart.
    (world.contacts).sort_by(|a, b| a.input.point.x.total_cmp(&b.input.point.x));
    check(&world);
}
