//! The worlds the lean-path tests (tests/physics/lean_prepare.rs,
//! lean_position.rs) hold the fast paths to the full ones on: lessons with
//! contacts of every kind, and the contacts of stepped scenes step by step.

use contact_lab::lesson::Lesson;
use contact_lab::physics::step::Simulation;
use contact_lab::physics::{ResolverParams, Solver, World};

/// Lessons with resolver contacts: frictionless, friction, several bodies,
/// a stack, corners, a spinning ball.
pub const LESSONS: [&str; 8] = [
    "lecture-1",
    "lecture-2",
    "lecture-3",
    "friction-cube",
    "two-boxes",
    "box-stack",
    "box-four-corners",
    "spinning-ball",
];

/// Calls `each` with the world of every step (its contacts generated) of
/// 25 steps of five scenes — a stack, a ramp sliding and sticking, a
/// spinning edge, a stack of hulls — run with `solver` (warm-started or
/// not), sleep off, the resolver params they run with and the step's
/// number in its scene (from 0).
pub fn each_stepped_world(
    solver: Solver,
    warm_start: bool,
    mut each: impl FnMut(&World<f64>, &ResolverParams, usize),
) {
    for id in [
        "stack-5",
        "ramp-slide",
        "ramp-stick",
        "spinning-edge",
        "hull-stack",
    ] {
        let mut sim = stepped(id, solver, warm_start);
        let params = sim.params.resolver;
        for step in 0..25 {
            sim.advance().unwrap();
            each(&sim.world, &params, step);
        }
    }
}

/// The embedded scene `id` as a simulation under `solver` (warm-started or
/// not), sleep off, from its start.
pub fn stepped(id: &str, solver: Solver, warm_start: bool) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let mut p = lesson.sim_params().unwrap();
    p.resolver.solver = solver;
    p.resolver.warm_start = warm_start;
    p.sleep.enabled = false;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, p, lesson.simulation.unwrap().materials)
}
