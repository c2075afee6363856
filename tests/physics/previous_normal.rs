//! The `normal_from` knob (issue 25, item 5): the spinning blade's second
//! step generates contacts with its block whose least penetration is
//! sideways (1, 0, 0) while the closest points one frame earlier give
//! (0, 1, 0). With `current` the blade is not closing along the sideways
//! normal and keeps falling at full speed; with `previous` the contact
//! takes (0, 1, 0), the overlap's depth along it, and the impulse takes
//! most of the blade's fall.

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::NormalFrom;
use contact_lab::physics::step::Simulation;

/// Each contact's normal and penetration.
type Contacts = Vec<([f64; 3], f64)>;

/// The blade's contacts' normals and penetrations at step 2, and its
/// velocity and spin after it.
fn second_step(from: NormalFrom) -> (Contacts, [f64; 3], [f64; 3]) {
    let lesson = Lesson::load("spinning-edge").unwrap();
    let mut params = lesson.sim_params().unwrap();
    params.normal_from = from;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    let first = sim.advance().unwrap();
    assert_eq!(first.contacts, 0);
    sim.advance().unwrap();
    let contacts = (sim.world.contacts.iter())
        .map(|k| (k.input.normal.into(), k.input.penetration))
        .collect();
    let s = &sim.world.bodies[0].state;
    (contacts, s.velocity.into(), s.angular_velocity.into())
}

#[test]
fn the_previous_frames_normal_turns_the_blades_sideways_contact_into_a_bounce() {
    let (current, v_current, _) = second_step(NormalFrom::Current);
    assert_eq!(current.len(), 4);
    for (n, depth) in &current {
        assert!((n[0] - 1.0).abs() < 1e-9, "{n:?}");
        assert!(*depth > 0.0 && *depth < 0.0076, "{depth}");
    }
    // Not closing along x: the fall goes on untouched (gravity's 2 steps).
    assert!(
        (v_current[1] + 12.0 + 2.0 * 9.81 / 60.0).abs() < 0.01,
        "{v_current:?}"
    );
    let (previous, v_previous, w_previous) = second_step(NormalFrom::Previous);
    assert_eq!(previous.len(), 4);
    for (n, depth) in &previous {
        assert!((n[1] - 1.0).abs() < 1e-9, "{n:?}");
        // The overlap along y: the blade's low end is centimetres into the top.
        assert!(*depth > 0.03 && *depth < 0.1, "{depth}");
    }
    // The impulse along y at the blade's end: the fall slows by some 5 m/s
    // and the spin changes (the blow is far from the centre).
    assert!(
        v_previous[1] > -8.0 && v_previous[1] < -6.0,
        "{v_previous:?}"
    );
    assert!((w_previous[2] - 10.0).abs() > 1.0, "{w_previous:?}");
}
