//! Scenes that never lie (issue 23): every energy event's cause verified by
//! re-running the step with that cause switched off, blow-ups that stop the
//! run, bodies pushed through or wholly inside others reported, and sleep
//! that needs a contact.

use contact_lab::lesson::Lesson;
use contact_lab::physics::step::audit::{gain, EnergyCause, Switches};
use contact_lab::physics::step::{Event, Simulation};
use contact_lab::physics::Solver;

/// The simulation of an embedded scene or of a file in tests/truth/.
fn simulation(id: &str) -> Simulation<f64> {
    let path = format!("{}/tests/truth/{id}.toml", env!("CARGO_MANIFEST_DIR"));
    let name = if std::path::Path::new(&path).exists() {
        path
    } else {
        id.to_string()
    };
    let lesson = Lesson::load(&name).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

/// One energy event and what re-running its step showed.
#[derive(Debug)]
struct Verified {
    step: u64,
    cause: EnergyCause,
}

/// Runs `steps` steps; at every energy event, re-runs the step from its
/// inputs: as it was (the gain must come back) and with the named causes
/// switched off (the gain must go). Returns the events.
fn verified_run(sim: &mut Simulation<f64>, steps: usize, what: &str) -> Vec<Verified> {
    let mut found = Vec::new();
    for _ in 0..steps {
        let before = sim.clone();
        let report = match sim.advance() {
            Ok(r) => r,
            Err(e) => panic!("{what}: {e}"),
        };
        for e in &report.events {
            if let Event::ProjectionLift { gained } = *e {
                // The lift comes back in a replay, and goes without projection.
                use contact_lab::physics::step::audit::Switch;
                let again = before.replay_next(Switches::empty());
                assert_eq!(again.potential_rise, gained, "{what} step {}", report.step);
                let without = before.replay_next(Switches::one(Switch::Projection));
                assert_eq!(without.potential_rise, 0.0, "{what} step {}", report.step);
            }
            let Event::EnergyGain { gained, cause } = *e else {
                continue;
            };
            let scale = sim.energy_scale();
            let again = before.replay_next(Switches::empty());
            let regained = gain(again.kinetic_before, again.kinetic_after, scale);
            assert_eq!(
                regained,
                Some(gained),
                "{what} step {}: the replay does not reproduce the gain",
                report.step
            );
            let checks: Vec<Switches> = match cause {
                EnergyCause::Each(s) => s.iter().map(Switches::one).collect(),
                EnergyCause::Together(s) => vec![s],
                EnergyCause::Unexplained { .. } => vec![],
            };
            for off in checks {
                let e = before.replay_next(off);
                assert_eq!(
                    gain(e.kinetic_before, e.kinetic_after, scale),
                    None,
                    "{what} step {}: {off:?} switched off, the step still gains ({} → {} J)",
                    report.step,
                    e.kinetic_before,
                    e.kinetic_after
                );
            }
            found.push(Verified {
                step: report.step,
                cause,
            });
        }
    }
    found
}

#[test]
fn every_scene_under_every_solver_names_only_causes_its_switches_confirm() {
    for id in contact_lab::lesson::embedded::scene_ids() {
        // Each scene for its default length, at most 600 steps (10 s).
        let steps = Lesson::load(id).unwrap().simulation.unwrap().steps.min(600) as usize;
        for solver in [Solver::DeepestFirst, Solver::SequentialImpulse] {
            for warm in [false, true] {
                if warm && solver == Solver::DeepestFirst {
                    continue;
                }
                for compensation in [true, false] {
                    let mut sim = simulation(id);
                    sim.params.resolver.solver = solver;
                    sim.params.resolver.warm_start = warm;
                    sim.params.acceleration_compensation = compensation;
                    let what = format!("{id} {solver:?} warm {warm} compensation {compensation}");
                    for v in verified_run(&mut sim, steps, &what) {
                        assert!(
                            !matches!(v.cause, EnergyCause::Unexplained { .. }),
                            "{what} step {}: {:?}",
                            v.step,
                            v.cause
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_rod_gaining_under_a_friction_model_blames_the_model_not_compensation() {
    use contact_lab::physics::step::audit::Switch;
    for (id, model) in [
        ("rod-velocity-scaling", Switch::VelocityScaling),
        ("rod-kinetic-direction", Switch::KineticDirection),
    ] {
        for compensation in [true, false] {
            let mut sim = simulation(id);
            sim.params.acceleration_compensation = compensation;
            let events = verified_run(&mut sim, 180, id);
            let blamed: Vec<_> = events
                .iter()
                .filter(|v| v.cause.switches().contains(model))
                .collect();
            assert!(!blamed.is_empty(), "{id}: {events:?}");
            for v in &events {
                assert!(
                    !v.cause
                        .switches()
                        .contains(Switch::AccelerationCompensation),
                    "{id} step {}: {:?}",
                    v.step,
                    v.cause
                );
                assert!(!matches!(v.cause, EnergyCause::Unexplained { .. }));
            }
        }
    }
}

/// The simulation of a lesson given as TOML text.
fn scene(toml: &str) -> Simulation<f64> {
    let lesson = contact_lab::lesson::validate::parse("test.toml", toml).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

const BALL_IN_THE_AIR: &str = r#"
id = "ball-in-the-air"
title = "A ball dropped from 10 m"
[world]
[step]
steps = 60
[[body]]
name = "ball"
mass = 1.0
shape = { sphere = 0.1 }
position = [0, 10, 0]
[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#;

#[test]
fn island_sleep_with_no_wait_does_not_stop_a_ball_in_mid_air() {
    use contact_lab::physics::step::SleepMode;
    let mut sim = scene(BALL_IN_THE_AIR);
    sim.params.sleep.mode = SleepMode::Island;
    sim.params.sleep.island_time = 0.0;
    for _ in 0..60 {
        let r = sim.advance().unwrap();
        assert!(
            !r.events
                .iter()
                .any(|e| matches!(e, Event::FallsAsleep { .. })),
            "step {}: the ball falls asleep in the air",
            r.step
        );
    }
    // One second of free fall: 4.9 m, and still falling.
    let ball = &sim.world.bodies[0].state;
    assert!(
        (ball.position.y - (10.0 - 4.9)).abs() < 0.1,
        "{}",
        ball.position.y
    );
    assert!(ball.velocity.y < -9.0, "{}", ball.velocity.y);
}

#[test]
fn a_ball_coasting_slowly_in_free_space_reaches_the_wall() {
    let mut sim = scene(
        r#"
id = "coasting-ball"
title = "A ball coasts at 0.5 m/s toward a wall 2 m away (the lecture's per-body sleep stopped it 0.6 m short)"
[world]
gravity = [0, 0, 0]
[step]
steps = 120
[[body]]
name = "ball"
mass = 1.0
shape = { sphere = 0.1 }
position = [0.3, 0, 0]
velocity = [0.5, 0, 0]
[[body]]
name = "wall"
mass = inf
shape = "half_space"
normal = [-1, 0, 0]
position = [2.4, 0, 0]
"#,
    );
    assert!(sim.params.sleep.enabled);
    let mut reached = None;
    for _ in 0..300 {
        let r = sim.advance().unwrap();
        if reached.is_none()
            && r.events
                .iter()
                .any(|e| matches!(e, Event::ContactMade { .. }))
        {
            reached = Some(r.time);
        }
        assert!(
            !r.events
                .iter()
                .any(|e| matches!(e, Event::FallsAsleep { .. }))
                || reached.is_some(),
            "step {}: the ball falls asleep in free space at x = {}",
            r.step,
            sim.world.bodies[0].state.position.x
        );
    }
    let t = reached.expect("the ball reaches the wall");
    // 2 m at 0.5 m/s, a little slower with the default damping.
    assert!(t > 4.0 && t < 4.2, "reached at {t} s");
}

/// Every event of `steps` steps of a scene, with its step.
fn events(sim: &mut Simulation<f64>, steps: usize) -> Vec<(u64, Event)> {
    let mut all = Vec::new();
    for _ in 0..steps {
        let r = sim.advance().unwrap();
        all.extend(r.events.iter().map(|e| (r.step, *e)));
    }
    all
}

#[test]
fn a_millimetre_ball_dropped_from_ten_centimetres_rests_on_the_floor() {
    let mut sim = simulation("millimetre-ball");
    let lowered = sim.lowered_tolerances();
    assert_eq!(lowered.len(), 4, "{lowered:?}");
    // Gravity moves it 2.7 mm a step, over its 0.5 mm radius: each step is
    // split into 6 substeps (split.rs).
    assert_eq!(sim.split().map(|s| s.substeps), Some(6));
    let seen = events(&mut sim, 120);
    let ball = &sim.world.bodies[0].state;
    // Resting on the floor: its centre one radius up, give or take a tenth.
    assert!(
        (ball.position.y - 0.0005).abs() < 0.00005,
        "the ball's centre at {} m",
        ball.position.y
    );
    // Whole steps had it arrive 2.3 cm deep (over twice its width, a
    // wholly-inside event); substeps of a sixth land it touching.
    assert!(
        !seen
            .iter()
            .any(|(_, e)| matches!(e, Event::WhollyInside { .. })),
        "{seen:?}"
    );
}

#[test]
fn a_ball_pushed_out_through_the_far_side_of_a_thin_slab_is_reported() {
    use contact_lab::physics::BodyId;
    let mut sim = simulation("slab-tunnel");
    let seen = events(&mut sim, 10);
    assert!(
        seen.contains(&(
            2,
            Event::PushedThrough {
                body: BodyId(0),
                through: BodyId(1)
            }
        )),
        "{seen:?}"
    );
    // It did go through: past the slab, still flying.
    assert!(sim.world.bodies[0].state.position.x > 4.0);
}

#[test]
fn a_speck_inside_a_planet_is_reported_wholly_inside() {
    use contact_lab::physics::BodyId;
    let mut sim = simulation("sphere-in-sphere");
    let seen = events(&mut sim, 3);
    let inside: Vec<_> = seen
        .iter()
        .filter_map(|(step, e)| match *e {
            Event::WhollyInside {
                body1,
                body2,
                penetration,
                width,
            } => Some((*step, body1, body2, penetration, width)),
            _ => None,
        })
        .collect();
    // Once, when it starts; 6e8 radii deep against a width of 2e-12 m.
    assert_eq!(inside.len(), 1, "{seen:?}");
    let (step, a, b, penetration, width) = inside[0];
    assert_eq!((step, a, b), (1, BodyId(0), Some(BodyId(1))));
    assert!(
        penetration > 5e-4 && (width - 2e-12).abs() < 1e-24,
        "{penetration} {width}"
    );
}

#[test]
fn a_surge_far_beyond_what_the_step_can_give_stops_the_run_where_the_old_guard_did_not() {
    use contact_lab::physics::step::BlowUp;
    let mut sim = simulation("runaway-friction");
    let scale = sim.energy_scale();
    match sim.advance() {
        Err(BlowUp::Surge {
            step,
            before,
            after,
            bound,
            bodies,
        }) => {
            assert_eq!(step, 1);
            assert_eq!(before, 2.0);
            assert!(after > 1000.0 * bound, "{after} {bound}");
            // Below the 10⁶ × energy-scale guard: only the new rule catches it.
            assert!(after < 1e6 * scale, "{after} {scale}");
            assert_eq!(bodies[0].0, 0);
            assert!(bodies[0].1 == 2.0 && bodies[0].2 > 100.0, "{bodies:?}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_run_that_blows_up_writes_what_it_computed_and_exits_1() {
    use assert_cmd::Command;
    let file = "tests/truth/runaway-friction.toml";
    let run = |format: &str| {
        let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["simulate", file, "--format", format])
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        )
    };
    let (code, stdout, stderr) = run("json");
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("step 1:") && stderr.contains("'box' 2 → 315 m/s"),
        "{stderr}"
    );
    let json: serde_json::Value = serde_json::from_str(&stdout).expect("valid JSON");
    assert_eq!(
        json["steps"].as_array().unwrap().len(),
        1,
        "the initial frame"
    );
    assert!(json["stopped"].as_str().unwrap().contains("blew up"));
    let (code, stdout, _) = run("text");
    assert_eq!(code, Some(1));
    assert!(
        stdout.contains("\nstopped: ") && stdout.contains("step 1:"),
        "{stdout}"
    );
}
