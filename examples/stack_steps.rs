//! Runs the 5-box stack for N steps with sleep off (a profiling target):
//! `cargo run --release --features measure --example stack_steps -- 20000 [si|si-warm|dl] [sleep]`
//! (`sleep`: the scene's own sleep settings, on).
use contact_lab::lesson::Lesson;
use contact_lab::physics::step::Simulation;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(10_000);
    let lesson = Lesson::load("stack-5").expect("embedded");
    let mut params = lesson.sim_params().expect("a scene");
    params.sleep.enabled = std::env::args().nth(3).as_deref() == Some("sleep");
    let solver = std::env::args().nth(2).unwrap_or_default();
    if solver.starts_with("si") {
        params.resolver.solver = contact_lab::physics::params::Solver::SequentialImpulse;
        params.resolver.warm_start = solver == "si-warm";
    }
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.expect("scene").materials);
    let t = std::time::Instant::now();
    let mut iterations = [0usize; 2];
    for _ in 0..n {
        let r = sim.advance().expect("no blow-up");
        iterations[0] += r.position_iterations;
        iterations[1] += r.velocity_iterations;
    }
    let us = t.elapsed().as_secs_f64() * 1e6 / n as f64;
    // Standing, the top box's centre is at 4.5 m.
    let top = sim.world.bodies[4].state.position.y;
    println!(
        "{n} steps: {us:.1} µs/step; iterations per step p {:.1} v {:.1}; top box at y = {top:.2} m",
        iterations[0] as f64 / n as f64,
        iterations[1] as f64 / n as f64
    );
}
