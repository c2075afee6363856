//! Issue 39's resting cases not in the shape matrix: a hull cube on a
//! floor, the same with a non-normalised orientation ([2, 0, 0, 0]), and
//! two hull cubes stacked exactly touching, each under deepest-first and
//! warm sequential impulses with the default settings: after a second's
//! settling the upper body moves less than 1 mm in 5 s, and the total
//! energy never ends a step above its start without an energy event (they
//! used to sink slowly, be popped up and gain 1–3 % of the energy with none).

use contact_lab::lesson::validate::parse;
use contact_lab::physics::step::{energy, total_audit, Event, Simulation};
use contact_lab::physics::Solver;

const CUBE: &str = "{ convex = [[-0.5, -0.5, -0.5], [-0.5, -0.5, 0.5], [-0.5, 0.5, -0.5], [-0.5, 0.5, 0.5], [0.5, -0.5, -0.5], [0.5, -0.5, 0.5], [0.5, 0.5, -0.5], [0.5, 0.5, 0.5]] }";

fn scene(bodies: &str, solver: Solver) -> Simulation<f64> {
    let text = format!(
        "id = \"resting-hulls\"\ntitle = \"t\"\nsource = \"issue 39\"\nsummary = \"t\"\n\n\
         [world]\nrestitution = 0.5\nfriction = 0.5\n\n[step]\ndt = 0.016666666666666666\nsteps = 360\n\n\
         {bodies}\n[[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nposition = [0, 0, 0]\n"
    );
    let lesson = parse("resting_hulls.rs", &text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    sim.params.resolver.solver = solver;
    sim.params.resolver.warm_start = solver == Solver::SequentialImpulse;
    sim
}

/// (largest move of body `top` from 1 s to 6 s, steps whose total energy
/// ends above the start by more than one step's audit tolerance with no
/// energy event so far).
fn run(mut sim: Simulation<f64>, top: usize) -> (f64, Vec<u64>) {
    let g = sim.params.world.gravity;
    let start = energy::total(&sim.world, &g);
    // One step's tolerance of the total-energy audit, for every body.
    let mass: f64 = (sim.world.bodies.iter())
        .filter_map(|b| b.dynamic().map(|d| d.mass))
        .sum();
    let slack = total_audit::tolerance(
        mass,
        g.norm(),
        sim.params.resolver.velocity_epsilon,
        sim.params.dt,
    );
    let (mut at_one, mut moved, mut unnamed, mut named) = (None, 0.0f64, Vec::new(), false);
    for _ in 0..360 {
        let r = sim.advance().expect("no blow-up");
        named |= (r.events.iter()).any(|e| {
            matches!(
                e,
                Event::EnergyGain { .. } | Event::EnergyRise { .. } | Event::ProjectionLift { .. }
            )
        });
        if energy::total(&sim.world, &g) > start + slack && !named {
            unnamed.push(r.step);
        }
        let x = sim.world.bodies[top].state.position;
        if r.time >= 1.0 - 1e-9 {
            let x0 = *at_one.get_or_insert(x);
            moved = moved.max((x - x0).norm());
        }
    }
    (moved, unnamed)
}

#[test]
fn hull_cubes_rest_still_alone_unnormalised_and_stacked_under_both_solvers() {
    let one = |orientation: &str| {
        format!("[[body]]\nname = \"cube\"\nmass = 1.0\nshape = {CUBE}\nposition = [0, 0.5, 0]\norientation = {orientation}\n")
    };
    let cases = [
        ("a hull cube", one("[1, 0, 0, 0]"), 0),
        ("orientation [2, 0, 0, 0]", one("[2, 0, 0, 0]"), 0),
        (
            "two hull cubes touching exactly",
            format!(
                "[[body]]\nname = \"a\"\nmass = 1.0\nshape = {CUBE}\nposition = [0, 0.5, 0]\n\n\
                 [[body]]\nname = \"b\"\nmass = 1.0\nshape = {CUBE}\nposition = [0, 1.5, 0]\n"
            ),
            1,
        ),
    ];
    let mut failures = Vec::new();
    for (name, bodies, top) in &cases {
        for solver in [Solver::DeepestFirst, Solver::SequentialImpulse] {
            let (moved, unnamed) = run(scene(bodies, solver), *top);
            if moved >= 1e-3 {
                failures.push(format!("{name}, {solver:?}: moved {moved:.3e} m at rest"));
            }
            if !unnamed.is_empty() {
                failures.push(format!(
                    "{name}, {solver:?}: energy above the start with no event at {unnamed:?}"
                ));
            }
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}
