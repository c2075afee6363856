//! Continuous detection's collisions told and resolved right (issue 39):
//! a body landing flat at its time of collision leaves flat at e v with no
//! spin whatever the resolver (the manifold is one impact); a bounce's
//! "separating" is the speed the state leaves the pair with; a sleeper
//! struck by a bullet gains no energy that no event names.

use contact_lab::lesson::validate::parse;
use contact_lab::physics::step::ccd_mode::Ccd;
use contact_lab::physics::step::{Event, Simulation};
use contact_lab::physics::Solver;
use nalgebra::Vector3;

const DT: f64 = 1.0 / 60.0;

/// A scene from `bodies` (TOML `[[body]]` tables) with restitution 0.5,
/// friction 0.5, the given gravity and sleep, run under `ccd` and `solver`
/// (sequential impulses warm).
fn scene(bodies: &str, gravity: f64, sleep: bool, ccd: Ccd, solver: Solver) -> Simulation<f64> {
    let text = format!(
        r#"
id = "ccd-manifold"
title = "A collision in the step"
[world]
gravity = [0, {gravity}, 0]
restitution = 0.5
friction = 0.5
[step]
dt = {DT}
steps = 10
[sleep]
enabled = {sleep}
{bodies}
"#
    );
    let lesson = parse("ccd_manifold.rs", &text).expect("a valid scene");
    let mut params = lesson.sim_params().expect("a scene");
    params.ccd = ccd;
    params.resolver.solver = solver;
    params.resolver.warm_start = solver == Solver::SequentialImpulse;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

const FLOOR: &str = r#"
[[body]]
name = "floor"
mass = inf
shape = "half_space"
normal = [0, 1, 0]
position = [0, 0, 0]
"#;

/// A body of `kind` about `l` across lying on a flat face (a box, a
/// cylinder on its cap, a tetrahedron on its face, a capsule on its side):
/// its shape, orientation and the height of its lowest face below its centre.
fn lying(kind: &str, l: f64) -> (String, &'static str, f64) {
    let (h, q) = (l / 2.0, l / 4.0);
    let upright = "[1, 0, 0, 0]";
    match kind {
        "box" => (format!("{{ box = [{l}, {l}, {l}] }}"), upright, h),
        "cylinder" => (
            format!("{{ cylinder = {{ radius = {h}, height = {l} }} }}"),
            upright,
            h,
        ),
        // An equilateral base about the axis at −l/4, the apex at 3l/4: the
        // centre of mass at the origin, above the base's centre.
        "hull" => {
            let (c, s) = (-h / 2.0, h * 0.75f64.sqrt());
            let points = format!(
                "[[{h}, -{q}, 0], [{c}, -{q}, {s}], [{c}, -{q}, -{s}], [0, {}, 0]]",
                3.0 * q
            );
            (format!("{{ convex = {points} }}"), upright, q)
        }
        // Its axis along x (a quarter turn about z).
        _ => (
            format!("{{ capsule = {{ radius = {q}, height = {h} }} }}"),
            "[0.7071067811865476, 0, 0, 0.7071067811865476]",
            q,
        ),
    }
}

#[test]
fn a_flat_landing_at_the_time_of_collision_leaves_flat_at_e_v_without_spin() {
    // Falling fast, the face meets the floor halfway
    // through the first step: one impact of the whole face, so the closed
    // form is v' = e v straight up, ω' = 0 (every point of the face closes
    // at v; impulses through the centre of mass). Taken corner by corner
    // with each restitution from what the others left, the lecture's order
    // left a box at 0.65 e v (deepest first), spinning at 22 rad/s.
    for kind in ["box", "cylinder", "hull", "capsule"] {
        // 10⁴, 100 and 100 sizes a second: fast beside the velocity
        // epsilon (0.01 m/s, unscaled without gravity) at every scale.
        for (l, speed) in [(1e-3, 10.0), (1.0, 100.0), (1e3, 1e5)] {
            for ccd in [Ccd::Bisection, Ccd::Conservative] {
                for solver in [Solver::DeepestFirst, Solver::SequentialImpulse] {
                    let (shape, orientation, below) = lying(kind, l);
                    let body = format!(
                        "[[body]]\nname = \"faller\"\nmass = 1.0\nshape = {shape}\norientation = {orientation}\nposition = [0, {}, 0]\nvelocity = [0, {}, 0]\n{FLOOR}",
                        below + 0.5 * speed * DT,
                        -speed
                    );
                    let mut sim = scene(&body, 0.0, false, ccd, solver);
                    let r = sim.advance().expect("no blow-up");
                    let what = format!("{kind} {l} {ccd:?} {solver:?}");
                    assert!(
                        r.events.iter().any(|e| matches!(e, Event::Toi(_))),
                        "{what}: no toi event"
                    );
                    let s = &sim.world.bodies[0].state;
                    let across = (s.velocity.x.hypot(s.velocity.z)) / speed;
                    let spin = s.angular_velocity.norm() * l / speed;
                    assert!(
                        (s.velocity.y / (0.5 * speed) - 1.0).abs() < 0.01,
                        "{what}: leaves at {} e v",
                        s.velocity.y / (0.5 * speed)
                    );
                    assert!(across < 1e-3, "{what}: leaves sideways at {across} v");
                    assert!(spin < 1e-3, "{what}: spins at {spin} v / size");
                }
            }
        }
    }
}

/// Body 0's lowest point along +y (its support along −y).
fn lowest(sim: &Simulation<f64>) -> f64 {
    use contact_lab::physics::detect::{Convex, Support};
    use contact_lab::physics::pose::Pose;
    let b = &sim.world.bodies[0];
    let convex = Convex::from_shape(b.shape.as_ref().unwrap()).unwrap();
    let pose = Pose::new(b.state.position, &b.state.orientation);
    let up = Vector3::y();
    up.dot(&convex.support(&pose, &-up))
}

#[test]
fn a_bounce_says_the_speed_the_state_leaves_with() {
    // A body of each kind, tilted, skimming a floor at 100 m/s while it
    // lands on it at 6 m/s: friction sets it spinning. Its bounce event's separating speed is the pair's fastest
    // normal speed at its contact points as the resolution left the bodies
    // (no gravity: the velocities at the step's end, about the centre
    // before it moved, x − v Δt). Read at the step's end about the moved
    // centre (ω × v Δt off), the ball's said 367 m/s for a contact
    // closing at 6.1 (the state: 3.05).
    let kinds = ["sphere", "box", "cylinder", "capsule", "hull"];
    let mut seen = 0;
    for kind in kinds {
        for ccd in [Ccd::None, Ccd::Bisection, Ccd::Conservative] {
            for solver in [Solver::DeepestFirst, Solver::SequentialImpulse] {
                let shape = match kind {
                    "sphere" => "{ sphere = 0.05 }".to_string(),
                    _ => lying(kind, 0.1).0,
                };
                let body = format!(
                    "[[body]]\nname = \"skimmer\"\nmass = 0.01\nshape = {shape}\norientation = [0.98, 0.1, 0.05, 0.15]\nposition = [0, 1, 0]\nvelocity = [100, -6.1, 0]\n{FLOOR}"
                );
                let mut sim = scene(&body, 0.0, false, ccd, solver);
                let low = lowest(&sim);
                sim.world.bodies[0].state.position.y -= low + 1e-5;
                for _ in 0..3 {
                    let r = sim.advance().expect("no blow-up");
                    if r.events.iter().any(|e| matches!(e, Event::Toi(_))) {
                        continue;
                    }
                    // Projected, then moved straight: x − v Δt.
                    let s = &sim.world.bodies[0].state;
                    let centre = s.position - s.velocity * DT;
                    for e in &r.events {
                        let Event::Bounce {
                            closing,
                            separating,
                            ..
                        } = e
                        else {
                            continue;
                        };
                        let leaves = sim
                            .world
                            .contacts
                            .iter()
                            .map(|k| {
                                let r = k.input.point - centre;
                                (s.velocity + s.angular_velocity.cross(&r)).dot(&k.input.normal)
                            })
                            .fold(f64::NEG_INFINITY, f64::max);
                        assert!(
                            (separating - leaves).abs() <= 1e-9 * closing,
                            "{kind} {ccd:?} {solver:?} step {}: closing {closing}, the event says separating {separating} m/s, the state {leaves}",
                            r.step
                        );
                        seen += 1;
                    }
                }
            }
        }
    }
    assert!(seen >= 20, "only {seen} bounces");
}

#[test]
fn a_sleeper_struck_by_a_bullet_gains_no_energy_unnamed() {
    // A 1 m box (1 kg) asleep on a floor (a half-space or a big box), a
    // bullet (r 5 cm, 10 g, 100 m/s) shot at it from several heights and
    // angles, each search, each solver. Every rise of the scene's total
    // energy above the documented tolerances is an energy event: the total
    // audit's Σ m (|g| ε_v Δt + ½ ε_v²) and projection's settling of
    // resting contacts, up to lifting every body by the position epsilon
    // (m |g| ε_p, an event beyond it). Measured: the largest unnamed rise
    // is 8.5 mJ (deepest first: the struck box, awake, sinking at 3.6 mm/s
    // below the velocity epsilon and lifted back 1.2 mm by projection),
    // under the settling allowance of 99 mJ.
    let g = 9.81;
    let floors = [
        FLOOR.to_string(),
        "[[body]]\nname = \"floor\"\nmass = inf\nshape = { box = [20, 1, 20] }\nposition = [0, -0.5, 0]\n".to_string(),
    ];
    let shots = [
        (0.6, 0.0),
        (0.06, 0.0),
        (0.2, -10.0),
        (0.95, 0.0),
        (1.1, -5.0),
    ];
    let mut worst: f64 = 0.0;
    for floor in &floors {
        for solver in [Solver::DeepestFirst, Solver::SequentialImpulse] {
            for ccd in [Ccd::Bisection, Ccd::Conservative] {
                for (y, vy) in shots {
                    let bodies = format!(
                        "[[body]]\nname = \"box\"\nmass = 1.0\nshape = {{ box = [1, 1, 1] }}\nposition = [0, 0.5, 0]\n[[body]]\nname = \"bullet\"\nmass = 0.01\nshape = {{ sphere = 0.05 }}\nposition = [-3, {y}, 0]\nvelocity = [100, {vy}, 0]\n{floor}"
                    );
                    let mut sim = scene(&bodies, -g, true, ccd, solver);
                    let (eps_v, eps_p) = (
                        sim.params.resolver.velocity_epsilon,
                        sim.params.resolver.position_epsilon,
                    );
                    let mass = 1.01;
                    let allowed = mass * (g * eps_v * DT + 0.5 * eps_v * eps_v) + mass * g * eps_p;
                    let mut last: Option<f64> = None;
                    for _ in 0..120 {
                        let r = sim.advance().expect("no blow-up");
                        let total = r.kinetic_energy + r.potential_energy;
                        let named = r.events.iter().any(|e| {
                            matches!(
                                e,
                                Event::EnergyRise { .. }
                                    | Event::EnergyGain { .. }
                                    | Event::ProjectionLift { .. }
                            )
                        });
                        if let (Some(before), false) = (last, named) {
                            let rise = total - before;
                            worst = worst.max(rise);
                            assert!(
                                rise <= allowed,
                                "{solver:?} {ccd:?} shot at {y} step {}: {rise} J unnamed",
                                r.step
                            );
                        }
                        last = Some(total);
                    }
                }
            }
        }
    }
    assert!(worst < 0.02, "the largest unnamed rise grew: {worst} J");
}
