//! Sleep that holds: a body resting alone on a floor falls asleep once and
//! stays asleep under every solver (warm starting included), and every
//! `wakes` event names its cause.

use contact_lab::lesson::Lesson;
use contact_lab::physics::step::{Event, Simulation, SleepMode, WakeCause};
use contact_lab::physics::{BodyId, Solver};

fn simulation(id: &str) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

/// The solvers a step can run: (solver, warm start).
const SOLVERS: [(Solver, bool); 3] = [
    (Solver::DeepestFirst, false),
    (Solver::SequentialImpulse, false),
    (Solver::SequentialImpulse, true),
];

/// The 1 m box of `resting-box` on its floor for 6 s (it used to fall
/// asleep at step 61 and wake at step 62, five times, under warm
/// sequential impulses: the warm-start impulse of its floor contacts gave
/// the sleeper a velocity and the step woke it for that).
#[test]
fn a_box_resting_alone_sleeps_once_and_stays_asleep_under_every_solver() {
    for mode in [SleepMode::Body, SleepMode::Island] {
        for (solver, warm) in SOLVERS {
            let mut sim = simulation("resting-box");
            sim.params.resolver.solver = solver;
            sim.params.resolver.warm_start = warm;
            sim.params.sleep.mode = mode;
            let (mut asleep, mut wakes) = (Vec::new(), Vec::new());
            for _ in 0..360 {
                let r = sim.advance().expect("no blow-up");
                for e in &r.events {
                    match e {
                        Event::FallsAsleep { .. } => asleep.push(r.step),
                        Event::Wakes { .. } => wakes.push((r.step, *e)),
                        _ => {}
                    }
                }
            }
            let what = format!("{solver:?}, warm {warm}, {mode:?}");
            assert_eq!(asleep.len(), 1, "{what}: asleep at {asleep:?}");
            assert!(wakes.is_empty(), "{what}: {wakes:?}");
            assert!(!sim.is_awake(0), "{what}: awake at the end");
            assert!(asleep[0] < 120, "{what}: asleep only at step {}", asleep[0]);
        }
    }
}

/// Every wake in `sleep-and-wake` (a ball thrown at a sleeping stack) names
/// an awake body that touched the sleeper or shared a contact with it.
#[test]
fn every_wake_names_its_cause() {
    for (solver, warm) in SOLVERS {
        let mut sim = simulation("sleep-and-wake");
        sim.params.resolver.solver = solver;
        sim.params.resolver.warm_start = warm;
        let mut wakes = 0;
        for _ in 0..300 {
            // The contacts the step's wakes read are the step's own.
            let r = sim.advance().expect("no blow-up");
            for e in &r.events {
                let Event::Wakes { body, cause } = *e else {
                    continue;
                };
                wakes += 1;
                let by = match cause {
                    WakeCause::Touched { by } => by,
                    WakeCause::Impulse { contact, with } => {
                        let k = &sim.world.contacts[contact];
                        let pair = [Some(k.body1), k.body2];
                        assert!(
                            pair.contains(&Some(body)) && pair.contains(&Some(with)),
                            "{solver:?} step {}: contact {contact} is {pair:?}",
                            r.step
                        );
                        with
                    }
                    other => panic!("{solver:?} step {}: {other:?}", r.step),
                };
                assert!(by != body && sim.world.bodies[by.0].movable, "{cause:?}");
                // A box is woken by the ball or by the other box, never the floor.
                assert!(by != BodyId(3), "{solver:?}: the floor woke {body:?}");
            }
        }
        assert!(wakes > 0, "{solver:?}: the ball wakes a box");
    }
}

/// An edit wakes the sleepers it changes, and the next step's events say so.
#[test]
fn a_sleeper_an_edit_wakes_says_so() {
    let mut sim = simulation("resting-box");
    while sim.is_awake(0) {
        sim.advance().expect("no blow-up");
    }
    sim.wake_for_edit(0);
    assert!(sim.is_awake(0));
    let r = sim.advance().expect("no blow-up");
    let wakes: Vec<_> = (r.events.iter())
        .filter(|e| matches!(e, Event::Wakes { .. }))
        .collect();
    assert_eq!(
        wakes,
        vec![&Event::Wakes {
            body: BodyId(0),
            cause: WakeCause::Edit
        }]
    );
    // An awake body an edit changes has nothing to wake from.
    sim.wake_for_edit(0);
    let r = sim.advance().expect("no blow-up");
    assert!(!r.events.iter().any(|e| matches!(e, Event::Wakes { .. })));
}

/// A box of side `l` resting on a half-space floor (sleep on, defaults).
fn box_on_a_floor(l: f64) -> Simulation<f64> {
    let text = format!(
        r#"id = "box-at-scale"
title = "A box resting alone on a floor"
source = "Lecture IV Collisions"
summary = "One box at rest on a half-space."

[world]
restitution = 0.2
friction = 0.5

[step]
dt = 0.016666666666666666
steps = 360

[[body]]
name = "box"
mass = 1.0
shape = {{ box = [{l}, {l}, {l}] }}
position = [0, {}, 0]

[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#,
        0.5 * l
    );
    let lesson = contact_lab::lesson::validate::parse("sleep_holds.rs", &text).expect("valid");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

/// Sleep at every scale: a 1 mm, a 1 m and a 1 km box resting alone on a
/// floor fall asleep once and are asleep at the end of 6 s, under
/// deepest-first and warm sequential impulses (the 1 mm box is split into
/// substeps, the 1 km one rests under scaled tolerances).
#[test]
fn a_box_resting_alone_sleeps_once_at_a_millimetre_a_metre_and_a_kilometre() {
    for l in [1e-3, 1.0, 1e3] {
        for (solver, warm) in [
            (Solver::DeepestFirst, false),
            (Solver::SequentialImpulse, true),
        ] {
            let mut sim = box_on_a_floor(l);
            sim.params.resolver.solver = solver;
            sim.params.resolver.warm_start = warm;
            let (mut asleep, mut wakes) = (Vec::new(), Vec::new());
            for _ in 0..360 {
                let r = sim.advance().expect("no blow-up");
                for e in &r.events {
                    match e {
                        Event::FallsAsleep { .. } => asleep.push(r.step),
                        Event::Wakes { .. } => wakes.push((r.step, *e)),
                        _ => {}
                    }
                }
            }
            let what = format!("{l} m box, {solver:?}, warm {warm}");
            assert_eq!(asleep.len(), 1, "{what}: asleep at {asleep:?}");
            assert!(wakes.is_empty(), "{what}: {wakes:?}");
            assert!(!sim.is_awake(0), "{what}: awake at the end");
            let y = sim.world.bodies[0].dynamic().unwrap().position.y;
            assert!(
                (y - 0.5 * l).abs() < 0.01 * l,
                "{what}: the centre at {y}, not near {}",
                0.5 * l
            );
        }
    }
}
