//! Scenes in time, checked against what physics predicts in closed form
//! (a bounce's apex, a sliding box's stopping distance, a slope's
//! acceleration), against invariants (energy, momentum), and against what
//! the lecture says about resting contacts and sleep.

use contact_lab::lesson::Lesson;
use contact_lab::physics::step::{Event, Simulation, StepReport};
use contact_lab::physics::BodyId;

/// The scene's simulation with the lesson's parameters.
fn simulation(id: &str) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

/// Runs `steps` steps, handing each report and the simulation to `each`.
fn run(
    sim: &mut Simulation<f64>,
    steps: usize,
    mut each: impl FnMut(&Simulation<f64>, &StepReport),
) {
    for _ in 0..steps {
        let report = sim.advance().expect("the scene does not blow up");
        each(sim, &report);
    }
}

fn body(sim: &Simulation<f64>, i: usize) -> &contact_lab::physics::RigidBody<f64> {
    &sim.world.bodies[i].state
}

#[test]
fn ball_drop_first_apex_is_e_squared_times_the_height() {
    let mut sim = simulation("ball-drop");
    let (mut bounced, mut apex) = (false, 0.0f64);
    run(&mut sim, 1200, |sim, r| {
        bounced |= r.events.iter().any(|e| matches!(e, Event::Bounce { .. }));
        if bounced {
            apex = apex.max(body(sim, 0).position.y - 0.1);
        }
    });
    assert!(bounced);
    let expected = 0.8f64.powi(2) * 1.0;
    assert!(
        (apex - expected).abs() < 0.02 * expected,
        "apex {apex} m, e²h = {expected} m"
    );
}

#[test]
fn resting_box_settles_without_vibrating_and_falls_asleep() {
    let mut sim = simulation("resting-box");
    let (mut asleep_at, mut worst_speed, mut worst_depth) = (None, 0.0f64, 0.0f64);
    run(&mut sim, 240, |sim, r| {
        if r.time > 1.0 {
            worst_speed = worst_speed.max(body(sim, 0).velocity.norm());
            worst_depth = worst_depth.max(r.max_penetration);
        }
        if asleep_at.is_none() && r.events.contains(&Event::FallsAsleep { body: BodyId(0) }) {
            asleep_at = Some(r.time);
        }
    });
    assert!(worst_speed < 0.01, "speed after 1 s: {worst_speed} m/s");
    assert!(worst_depth < 0.01, "penetration after 1 s: {worst_depth} m");
    assert!(
        asleep_at.is_some_and(|t| t < 4.0),
        "asleep at {asleep_at:?}"
    );
}

#[test]
fn without_micro_collisions_the_resting_box_vibrates() {
    // The same box with acceleration compensation and the velocity limit off:
    // restitution 0.4 bounces back the velocity each step of gravity builds.
    let vertical_speed = |compensate: bool| {
        let mut sim = simulation("resting-box");
        sim.params.sleep.enabled = false;
        if !compensate {
            sim.params.acceleration_compensation = false;
            sim.params.contact.velocity_limit = 0.0;
        }
        let mut worst = 0.0f64;
        run(&mut sim, 180, |sim, r| {
            if r.time > 1.0 {
                worst = worst.max(body(sim, 0).velocity.y.abs());
            }
        });
        worst
    };
    let (still, vibrating) = (vertical_speed(true), vertical_speed(false));
    assert!(still < 0.01, "{still}");
    assert!(
        vibrating > 0.05,
        "vertical speed amplitude without compensation {vibrating} m/s"
    );
}

#[test]
fn sliding_box_stops_where_coulomb_says() {
    let mut sim = simulation("sliding-box");
    run(&mut sim, 400, |_, _| {});
    let distance = body(&sim, 0).position.x;
    let expected = 3.0f64.powi(2) / (2.0 * 0.3 * 9.81);
    assert!(
        (distance - expected).abs() < 0.02 * expected,
        "stopped after {distance} m, v₀²/(2 μ_d g) = {expected} m"
    );
    assert!(body(&sim, 0).velocity.norm() < 0.01);
}

#[test]
fn box_slides_down_a_steep_slope_with_coulombs_acceleration() {
    let mut sim = simulation("ramp-slide");
    let dt = sim.params.dt;
    run(&mut sim, 120, |_, _| {});
    let theta = 30f64.to_radians();
    let expected = 9.81 * (theta.sin() - 0.3 * theta.cos());
    let v = body(&sim, 0).velocity;
    let along = (v.x * theta.cos() - v.y * theta.sin()).abs();
    let acceleration = along / (120.0 * dt);
    assert!(
        (acceleration - expected).abs() < 0.02 * expected,
        "{acceleration} m/s² against g(sin θ − μ_d cos θ) = {expected}"
    );
}

#[test]
fn the_cradle_passes_the_velocity_to_the_last_ball() {
    let mut sim = simulation("cradle-over-time");
    run(&mut sim, 200, |_, _| {});
    for i in 0..4 {
        assert!(body(&sim, i).velocity.norm() < 1e-9, "ball {i}");
    }
    assert!((body(&sim, 4).velocity.x - 1.0).abs() < 1e-9);
    let momentum: f64 = (0..5).map(|i| body(&sim, i).velocity.x).sum();
    assert!((momentum - 1.0).abs() < 1e-12);
}

#[test]
fn a_manifold_stack_stands_and_single_contacts_let_it_fall() {
    let top_height = |mode: contact_lab::physics::params::BoxBoxMode| {
        let mut sim = simulation("stack-5");
        sim.params.box_box = mode;
        run(&mut sim, 360, |_, _| {});
        body(&sim, 4).position.y
    };
    let standing = top_height(contact_lab::physics::params::BoxBoxMode::Manifold);
    let single = top_height(contact_lab::physics::params::BoxBoxMode::Single);
    assert!(
        standing > 4.4,
        "manifold: top box at {standing} m after 6 s"
    );
    assert!(single < 3.0, "single: top box at {single} m after 6 s");
}

#[test]
fn sleeping_boxes_wake_when_the_ball_arrives_and_the_floor_wakes_nobody() {
    let mut sim = simulation("sleep-and-wake");
    let (mut asleep, mut woke) = (None, None);
    run(&mut sim, 300, |sim, r| {
        for e in &r.events {
            match e {
                Event::FallsAsleep { body: BodyId(0) } if asleep.is_none() => asleep = Some(r.time),
                Event::Wakes { body, .. } if woke.is_none() => {
                    // Only the ball (body 2) can wake a box.
                    let touching = sim.world.contacts.iter().any(|k| {
                        (k.body1 == *body && k.body2 == Some(BodyId(2)))
                            || (k.body1 == BodyId(2) && k.body2 == Some(*body))
                    });
                    assert!(touching, "{body:?} woke without the ball");
                    woke = Some(r.time);
                }
                _ => {}
            }
        }
    });
    let (asleep, woke) = (
        asleep.expect("box1 falls asleep"),
        woke.expect("the ball wakes a box"),
    );
    assert!(
        asleep < 2.5 && woke > 2.8 && woke < 3.5,
        "asleep {asleep} s, woke {woke} s"
    );
}

/// A sleeper holds still: after every step each sleeping body's velocity is
/// zero. (A sleeper the resolver changed used to keep that velocity asleep —
/// box2 of sleep-and-wake carried 0.2 m/s for dozens of steps, read by its
/// contacts; it is now woken, as the reference engine wakes the bodies of
/// every contact it takes.)
#[test]
fn a_sleeping_body_has_no_velocity() {
    for id in ["sleep-and-wake", "stack-5"] {
        let mut sim = simulation(id);
        let mut slept = 0;
        run(&mut sim, 420, |sim, r| {
            for (i, b) in sim.world.bodies.iter().enumerate() {
                if b.movable && !sim.is_awake(i) {
                    slept += 1;
                    let s = &b.state;
                    assert!(
                        s.velocity.norm() == 0.0 && s.angular_velocity.norm() == 0.0,
                        "{id} step {}: body {i} asleep with v {:?}, ω {:?}",
                        r.step,
                        s.velocity,
                        s.angular_velocity
                    );
                }
            }
        });
        assert!(slept > 100, "{id}: bodies asleep {slept} body-steps");
    }
}

#[test]
fn every_scene_stays_finite_and_energy_rises_only_with_a_cause() {
    use contact_lab::physics::step::audit::EnergyCause;
    for id in contact_lab::lesson::embedded::scene_ids() {
        let mut sim = simulation(id);
        let g = sim.params.world.gravity;
        let mut energy = contact_lab::physics::step::energy::total(&sim.world, &g);
        let mut gaining = false;
        run(&mut sim, 300, |sim, r| {
            let now = r.kinetic_energy + r.potential_energy;
            for e in &r.events {
                if let Event::EnergyGain { cause, .. } = e {
                    assert!(
                        !matches!(cause, EnergyCause::Unexplained { .. }),
                        "{id} step {}: {cause:?}",
                        r.step
                    );
                    gaining = true;
                }
            }
            // Allowed: projection moving bodies out of penetration (work of
            // the position phase, at most m g × the depth resolved), and a
            // velocity-phase gain the run reported with its cause.
            let mass: f64 = sim
                .world
                .bodies
                .iter()
                .filter_map(|b| b.dynamic())
                .map(|b| b.mass)
                .sum();
            let allowance =
                mass * g.norm() * r.max_penetration.max(0.0) + 1e-9 * energy.abs().max(1.0);
            assert!(
                gaining || now <= energy + allowance,
                "{id} step {}: energy rose from {energy} to {now} with no energy event",
                r.step
            );
            energy = now;
        });
    }
}

#[test]
fn the_kane_rod_gains_energy_and_the_run_names_restitution_with_friction() {
    use contact_lab::physics::step::audit::{EnergyCause, Switch, Switches};
    let mut sim = simulation("kane-rod-bounce");
    let before = contact_lab::physics::step::energy::kinetic(&sim.world);
    let mut causes = Vec::new();
    run(&mut sim, 100, |_, r| {
        for e in &r.events {
            if let Event::EnergyGain { gained, cause } = e {
                causes.push((*gained, *cause));
            }
        }
    });
    let after = contact_lab::physics::step::energy::kinetic(&sim.world);
    assert_eq!(causes.len(), 1, "{causes:?}");
    assert_eq!(
        causes[0].1,
        EnergyCause::Each(Switches::one(Switch::RestitutionWithFriction))
    );
    assert!(causes[0].0 > 1.0, "gained {} J", causes[0].0);
    // 2.80 J → 3.98 J: the gain stays (no gravity, damping only).
    assert!(after > 1.4 * before, "{before} J → {after} J");
}

/// What one run of `sleep-modes` shows: when every box is asleep, how many
/// times a box was woken, and the top box's height at the end.
struct SleepRun {
    all_asleep_at: Option<f64>,
    wakes: usize,
    top: f64,
}

fn sleep_modes(configure: impl Fn(&mut Simulation<f64>)) -> SleepRun {
    let mut sim = simulation("sleep-modes");
    configure(&mut sim);
    let (mut all_asleep_at, mut wakes) = (None, 0);
    run(&mut sim, 900, |sim, r| {
        wakes += r
            .events
            .iter()
            .filter(|e| matches!(e, Event::Wakes { .. }))
            .count();
        if all_asleep_at.is_none() && sim.awake() == 0 {
            all_asleep_at = Some(r.time);
        }
    });
    SleepRun {
        all_asleep_at,
        wakes,
        top: body(&sim, 7).position.y,
    }
}

#[test]
fn island_sleep_freezes_the_stack_at_once_per_body_sleep_flaps_and_no_sleep_lets_it_fall() {
    use contact_lab::physics::step::SleepMode;
    let body_mode = sleep_modes(|_| {});
    let island = sleep_modes(|s| s.params.sleep.mode = SleepMode::Island);
    let awake = sleep_modes(|s| s.params.sleep.enabled = false);
    // Island: asleep within a second, nobody woken, the stack where it stood.
    let t = island.all_asleep_at.expect("the island falls asleep");
    assert!(t < 1.0, "island asleep at {t} s");
    assert_eq!(island.wakes, 0);
    assert!(island.top > 7.4, "island: top at {} m", island.top);
    // Per body: many wakes, and all asleep only after several seconds.
    let t = body_mode
        .all_asleep_at
        .expect("every box falls asleep in the end");
    assert!(t > 5.0 && t < 14.0, "per body: all asleep at {t} s");
    assert!(body_mode.wakes >= 10, "per body: {} wakes", body_mode.wakes);
    assert!(body_mode.top > 7.4, "per body: top at {} m", body_mode.top);
    // No sleep: the lecture's resolver lets the stack sag and fall.
    assert!(awake.all_asleep_at.is_none());
    assert!(
        awake.top < 2.0,
        "no sleep: top at {} m after 15 s",
        awake.top
    );
}

#[test]
fn the_one_pass_start_audit_gives_the_separate_audits_bit_for_bit() {
    use contact_lab::physics::resolver::{Implementation, Resolver, Silent};
    use contact_lab::physics::step::{energy, replay, replay::resolved, report};
    let mut sim = simulation("stack-5");
    let (g, dt) = (sim.params.world.gravity, sim.params.dt);
    let (mut speeds, mut inertia) = (Vec::new(), Vec::new());
    for _ in 0..40 {
        sim.advance().unwrap();
        let w = &sim.world;
        let (kinetic, bound) = report::start_of_step(w, g.norm(), dt, &mut speeds, &mut inertia);
        assert_eq!(kinetic.to_bits(), energy::kinetic(w).to_bits());
        assert_eq!(
            bound.to_bits(),
            report::surge_bound(w, g.norm(), dt).to_bits()
        );
        let each: Vec<f64> = w.bodies.iter().map(|b| b.state.velocity.norm()).collect();
        assert_eq!(speeds, each);
        // The resolution's audit with the inertia at hand: the same energies.
        let (r, _) = Resolver::resolve(
            w,
            &sim.params.resolver,
            Implementation::Indexed,
            &mut Silent,
        );
        let mut kinetic_after = Vec::new();
        let with = replay::resolved_with(w, &r, &g, Some(&inertia), &mut kinetic_after);
        assert_eq!(with, resolved(w, &r, &g));
        // The total-energy audit's end from those kinetic energies: the same bits.
        let touched = vec![true; w.bodies.len()];
        let shared = replay::total_after(w, &r, &g, dt, &touched, Some(&kinetic_after));
        let fresh = replay::total_after(w, &r, &g, dt, &touched, None);
        assert_eq!(shared.to_bits(), fresh.to_bits());
    }
}

/// The capsule-on-slope scene with its [world] friction set to `mu`
/// (static and dynamic).
fn capsule_on_slope(mu: Option<f64>) -> Simulation<f64> {
    let text = contact_lab::lesson::embedded::find("capsule-on-slope").unwrap();
    let text = match mu {
        None => text.to_string(),
        Some(mu) => text
            .replace("static_friction = 0.5", &format!("static_friction = {mu}"))
            .replace(
                "dynamic_friction = 0.4",
                &format!("dynamic_friction = {mu}"),
            ),
    };
    let lesson = contact_lab::lesson::validate::parse("capsule-on-slope.toml", &text).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

#[test]
fn a_capsule_down_a_slope_sticks_above_tan_theta_and_slides_coulombs_distance_below() {
    let theta = 20f64.to_radians();
    let down = nalgebra::Vector3::new(theta.cos(), -theta.sin(), 0.0);
    // μ_s = 0.5 > tan 20° = 0.364: it stays, within the position epsilon.
    let mut sim = capsule_on_slope(None);
    let start = body(&sim, 0).position;
    run(&mut sim, 240, |_, _| {});
    let moved = (body(&sim, 0).position - start).dot(&down);
    assert!(moved.abs() < 2e-3, "moved {moved} m down the slope");
    // μ = 0.3 < tan 20°: it slides ½ g (sin θ − μ cos θ) t² in t = 2 s.
    let mut sim = capsule_on_slope(Some(0.3));
    let start = body(&sim, 0).position;
    run(&mut sim, 240, |_, _| {});
    let slid = (body(&sim, 0).position - start).dot(&down);
    let expected = 0.5 * 9.81 * (theta.sin() - 0.3 * theta.cos()) * 4.0;
    assert!(
        (slid - expected).abs() < 0.01 * expected,
        "{slid} m against ½ g (sin θ − μ cos θ) t² = {expected} m"
    );
    // Lying along the fall line it slides without rolling.
    assert!(body(&sim, 0).angular_velocity.norm() < 0.01);
}
