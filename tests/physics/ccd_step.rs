//! Continuous detection in the step (issue 25, docs/ccd.md): the bullet
//! scene tunnels once without it and rebounds with e × its impact speed
//! with either search; sub-stepping adds no energy; the collision found
//! inside a step is a `toi` event.

use contact_lab::lesson::Lesson;
use contact_lab::physics::detect::ToiMethod;
use contact_lab::physics::step::ccd_mode::Ccd;
use contact_lab::physics::step::{energy, Event, Simulation, StepReport, WakeCause};

fn scene(id: &str, ccd: Ccd) -> Simulation<f64> {
    let lesson = Lesson::load(id).expect("an embedded scene");
    let mut params = lesson.sim_params().expect("a scene");
    params.ccd = ccd;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

/// Every step's report and the bullet's (body 0's) x after it.
fn run(sim: &mut Simulation<f64>, steps: usize) -> Vec<(StepReport, f64)> {
    (0..steps)
        .map(|_| {
            let r = sim.advance().expect("no blow-up");
            (r, sim.world.bodies[0].state.position.x)
        })
        .collect()
}

fn events(run: &[(StepReport, f64)]) -> Vec<Event> {
    run.iter().flat_map(|(r, _)| r.events.clone()).collect()
}

#[test]
fn without_ccd_the_bullet_tunnels_exactly_once_and_ends_beyond_the_wall() {
    let mut sim = scene("bullet-wall", Ccd::None);
    let seen = run(&mut sim, 30);
    let all = events(&seen);
    let crossed = all
        .iter()
        .filter(|e| matches!(e, Event::Tunnelled { .. }))
        .count();
    assert_eq!(crossed, 1, "{all:?}");
    assert!(!all.iter().any(|e| matches!(e, Event::Toi(_))), "{all:?}");
    assert!(seen.last().unwrap().1 > 0.01);
}

#[test]
fn with_ccd_the_bullet_rebounds_at_e_times_its_impact_speed_and_never_enters_the_wall() {
    for (ccd, method) in [
        (Ccd::Bisection, ToiMethod::Bisection),
        (Ccd::Conservative, ToiMethod::Conservative),
    ] {
        let mut sim = scene("bullet-wall", ccd);
        let seen = run(&mut sim, 30);
        let all = events(&seen);
        assert!(
            !all.iter().any(|e| matches!(e, Event::Tunnelled { .. })),
            "{ccd:?}: {all:?}"
        );
        let hits: Vec<_> = all
            .iter()
            .filter_map(|e| match e {
                Event::Toi(h) => Some(*h),
                _ => None,
            })
            .collect();
        assert_eq!(hits.len(), 1, "{ccd:?}: {all:?}");
        let h = hits[0];
        assert_eq!(h.method, method);
        // It meets the wall's face (x = −0.01) when it has come 0.48 m.
        assert!((h.time - 0.48 / 100.0).abs() < 1e-5, "{ccd:?}: {}", h.time);
        assert!((h.normal[0] + 1.0).abs() < 1e-9, "{ccd:?}: {:?}", h.normal);
        // e = 0.5 of the impact speed (the speed when it struck, damping included).
        assert!(h.closing > 99.0, "{ccd:?}: {}", h.closing);
        let ratio = h.separating / h.closing;
        assert!((ratio - 0.5).abs() < 0.005, "{ccd:?}: {ratio}");
        // The bullet flies back at that speed, and its surface never passes
        // the wall's face (x = −0.01) at any step's end.
        let v = sim.world.bodies[0].state.velocity.x;
        assert!(
            (-v / (0.5 * h.closing) - 1.0).abs() < 0.01,
            "{ccd:?}: {v} after {}",
            h.closing
        );
        for (r, x) in &seen {
            assert!(*x + 0.01 <= -0.01 + 1e-6, "{ccd:?} step {}: {x}", r.step);
        }
    }
}

#[test]
fn a_collision_inside_the_step_is_a_toi_event_of_that_step() {
    let mut sim = scene("plate-drop", Ccd::Conservative);
    let seen = run(&mut sim, 12);
    let at: Vec<u64> = seen
        .iter()
        .filter(|(r, _)| r.events.iter().any(|e| matches!(e, Event::Toi(_))))
        .map(|(r, _)| r.step)
        .collect();
    assert_eq!(at, vec![7], "{:?}", events(&seen));
    // The ball went back up: it never reached below the plate.
    let y = sim.world.bodies[0].state.position.y;
    let vy = sim.world.bodies[0].state.velocity.y;
    assert!(y > 0.06 && vy > 0.0, "{y} {vy}");
}

/// The largest rise of the mechanical energy from one step to the next,
/// after checking that every resolution at a time of collision kept or
/// lost kinetic energy; and the bodies' states at the end.
fn largest_rise(id: &str, ccd: Ccd, steps: usize) -> (f64, f64, Vec<[f64; 3]>) {
    let mut sim = scene(id, ccd);
    let g = sim.params.world.gravity;
    let e = |s: &Simulation<f64>| energy::kinetic(&s.world) + energy::potential(&s.world, &g);
    let mut last = e(&sim);
    let mut rise = f64::NEG_INFINITY;
    for _ in 0..steps {
        let r = sim.advance().expect("no blow-up");
        for ev in &r.events {
            if let Event::Toi(h) = ev {
                assert!(
                    h.separating <= h.closing * (1.0 + 1e-12),
                    "{id} {ccd:?}: {h:?}"
                );
                assert!(
                    h.kinetic_after <= h.kinetic_before * (1.0 + 1e-12),
                    "{id} {ccd:?}: {h:?}"
                );
            }
        }
        let now = e(&sim);
        rise = rise.max(now - last);
        last = now;
    }
    let states = sim
        .world
        .bodies
        .iter()
        .flat_map(|b| [b.state.position.into(), b.state.velocity.into()])
        .collect();
    (rise, sim.energy_scale(), states)
}

#[test]
fn sub_stepping_gains_no_energy_on_any_scene_of_a_set() {
    // Flights and a bounce: the energy never rises, whatever the mode.
    for id in ["bullet-wall", "plate-drop"] {
        for ccd in Ccd::ALL {
            let (rise, scale, _) = largest_rise(id, ccd, 60);
            assert!(rise <= 1e-9 * scale, "{id} {ccd:?}: +{rise} J");
        }
    }
    // A spinning blade that strikes an edge: every resolution at a time of
    // collision keeps or loses energy (checked in `largest_rise`).
    for ccd in [Ccd::Bisection, Ccd::Conservative] {
        largest_rise("spinning-edge", ccd, 60);
    }
    // Scenes where nothing moves fast enough to tunnel: the run with
    // continuous detection is the run without it, state for state.
    for id in ["ball-drop", "stack-5", "sphere-row-20"] {
        let (_, _, none) = largest_rise(id, Ccd::None, 60);
        for ccd in [Ccd::Bisection, Ccd::Conservative] {
            let (_, _, with) = largest_rise(id, ccd, 60);
            assert_eq!(with, none, "{id} {ccd:?}");
        }
    }
}

/// A box asleep in the bullet's path (zero gravity, sleep on) and the
/// bullet at 100 m/s: a collision resolved inside the step is the bullet's
/// and the box's, so it wakes the box.
fn sleeping_box(ccd: Ccd) -> Simulation<f64> {
    let lesson = contact_lab::lesson::validate::parse(
        "sleeping-box.toml",
        r#"
id = "sleeping-box"
title = "A bullet at a sleeping box"
[world]
gravity = [0, 0, 0]
restitution = 0.5
[step]
dt = 0.016666666666666666
steps = 10
[sleep]
enabled = true
[[body]]
name = "bullet"
mass = 0.01
shape = { sphere = 0.01 }
position = [-0.5, 0, 0]
velocity = [100, 0, 0]
[[body]]
name = "box"
mass = 1.0
shape = { box = [0.02, 0.2, 0.2] }
position = [0, 0, 0]
"#,
    )
    .expect("a valid scene");
    let mut params = lesson.sim_params().expect("a scene");
    params.ccd = ccd;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    sim.sleep[1].awake = false;
    sim
}

#[test]
fn a_sleeping_box_struck_inside_the_step_wakes_and_moves() {
    for ccd in [Ccd::Bisection, Ccd::Conservative] {
        let mut sim = sleeping_box(ccd);
        let r = sim.advance().expect("no blow-up");
        assert!(
            r.events.iter().any(|e| matches!(e, Event::Toi(_))),
            "{ccd:?}: {:?}",
            r.events
        );
        assert!(
            r.events
                .iter()
                .any(|e| matches!(e, Event::Wakes { body, cause: WakeCause::Struck { by } } if body.0 == 1 && by.0 == 0)),
            "{ccd:?}: {:?}",
            r.events
        );
        assert!(sim.sleep[1].awake, "{ccd:?}");
        // Momentum: 0.01 kg × 100 m/s shared at e = 0.5 gives the box
        // (1 + e) m v / (m + M) = 1.4851 m/s, and it has moved this step.
        let (x, v) = (
            sim.world.bodies[1].state.position.x,
            sim.world.bodies[1].state.velocity.x,
        );
        assert!((v - 1.5 / 1.01).abs() < 0.01, "{ccd:?}: {v}");
        assert!(x > 0.0, "{ccd:?}: {x}");
        sim.advance().expect("no blow-up");
        assert!(sim.world.bodies[1].state.position.x > x, "{ccd:?}");
    }
}

#[test]
fn a_fast_ball_onto_a_half_space_floor_rebounds_at_e_times_its_speed_and_never_goes_below() {
    for (ccd, method) in [
        (Ccd::Bisection, ToiMethod::Bisection),
        (Ccd::Conservative, ToiMethod::Conservative),
    ] {
        let mut sim = scene("ball-floor-fast", ccd);
        let mut hits = Vec::new();
        for _ in 0..20 {
            let r = sim.advance().expect("no blow-up");
            let s = &sim.world.bodies[0].state;
            // Its lowest point never below the floor at a step's end (within
            // the search's tolerance, 10⁻⁴ of the radius).
            assert!(
                s.position.y - 0.5 >= -5e-5,
                "{ccd:?} step {}: y = {}",
                r.step,
                s.position.y
            );
            for e in &r.events {
                assert!(!matches!(e, Event::Tunnelled { .. }), "{ccd:?}: {e:?}");
                if let Event::Toi(h) = e {
                    // The speed it leaves with is the state's after the step
                    // (no spin, and gravity is added at the next step's start).
                    assert!(
                        (h.separating - s.velocity.y).abs() <= 1e-9 * h.closing,
                        "{ccd:?}: {h:?} vs {}",
                        s.velocity.y
                    );
                    hits.push((r.step, *h));
                }
            }
        }
        assert_eq!(hits.len(), 1, "{ccd:?}: {hits:?}");
        let (step, h) = hits[0];
        assert_eq!((step, h.method), (3, method));
        assert_eq!(h.normal, [0.0, 1.0, 0.0]);
        // e = 0.5 of the speed it struck at, to 1 %.
        let ratio = h.separating / h.closing;
        assert!((ratio - 0.5).abs() < 0.005, "{ccd:?}: {ratio}");
        assert!(h.closing > 100.0, "{ccd:?}: {}", h.closing);
    }
}
