//! The blow-up rules stop a run whose energy comes from nowhere, never one
//! whose energy gravity gave: a ball in free fall with no floor gains
//! kinetic energy without bound, and that is physics.

use contact_lab::physics::step::report::{energy_blown_up, ENERGY_FACTOR};
use contact_lab::physics::step::Simulation;

const FALLING_BALL: &str = r#"
id = "falling-ball"
title = "A ball in free fall with no floor"
source = "test"
summary = "Nothing stops it."

[world]
linear_damping = 1.0
angular_damping = 1.0

[step]
dt = 10.0
steps = 100

[[body]]
name = "ball"
mass = 1.0
shape = { sphere = 0.5 }
position = [0, 0, 0]
"#;

/// 1000 s of free fall in steps of 10 s: the kinetic energy reaches
/// ½ (9.81 × 1000)² ≈ 4.8 × 10⁷ J, 4.9 × 10⁶ times the scene's starting
/// scale of 9.81 J (it used to stop at step 46, at 452 s, "the scene blew
/// up"); gravity released all of it.
#[test]
fn free_fall_is_never_a_blow_up() {
    let lesson = contact_lab::lesson::validate::parse("falling-ball.toml", FALLING_BALL)
        .expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    let scale = sim.energy_scale();
    let mut kinetic = 0.0;
    for step in 1..=100 {
        match sim.advance() {
            Ok(r) => kinetic = r.kinetic_energy,
            Err(e) => panic!("step {step}: {e}"),
        }
    }
    assert!(
        kinetic > ENERGY_FACTOR * scale,
        "{kinetic} J, scale {scale} J"
    );
}

#[test]
fn the_rule_counts_what_gravity_released() {
    // Free fall: the kinetic energy is what gravity released.
    assert!(!energy_blown_up(4.8e7, 9.81, 4.8e7));
    // The same energy from nowhere is a blow-up.
    assert!(energy_blown_up(4.8e7, 9.81, 0.0));
    // Energy given back to the potential (a ball thrown up) allows nothing more.
    assert!(energy_blown_up(1e8, 1.0, -5.0));
    assert!(!energy_blown_up(1e6, 1.0, -5.0));
}
