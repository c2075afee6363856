//! The sequential-impulse solver (projected Gauss–Seidel with accumulated,
//! clamped impulses): one contact gets the lecture's impulse, the clamps
//! hold, free bodies keep their momentum, and a box on a slope sticks.

use contact_lab::lesson::Lesson;
use contact_lab::physics::resolver::{Implementation, Observer, Resolver, Silent, VelocityImpulse};
use contact_lab::physics::step::Simulation;
use contact_lab::physics::{ResolverParams, Solver, World};
use nalgebra::Vector3;

/// The impulses a velocity phase applied, in order.
#[derive(Default)]
struct Impulses(Vec<(usize, Vector3<f64>)>);

impl Observer<f64> for Impulses {
    fn velocity_taken(&mut self, _: usize, k: usize, _: f64, i: &VelocityImpulse<f64>) {
        self.0.push((k, i.impulse_world));
    }
}

fn params(solver: Solver) -> ResolverParams {
    ResolverParams {
        solver,
        ..ResolverParams::default()
    }
}

/// The lesson's world with only contact `k`.
fn one_contact(id: &str, k: usize) -> World<f64> {
    let mut w = Lesson::load(id).unwrap().world::<f64>();
    let contact = w.contacts[k].clone();
    w.contacts = vec![contact];
    w
}

fn first_impulse(w: &World<f64>, solver: Solver) -> (Vector3<f64>, Resolver<f64>) {
    let mut log = Impulses::default();
    let (r, _) = Resolver::resolve(w, &params(solver), Implementation::Indexed, &mut log);
    (log.0[0].1, r)
}

fn assert_close(a: &Vector3<f64>, b: &Vector3<f64>, what: &str) {
    assert!(
        (a - b).norm() <= 1e-12 * b.norm().max(1.0),
        "{what}: {a:?} against {b:?}"
    );
}

#[test]
fn one_frictionless_contact_gets_the_lectures_impulse() {
    let w = one_contact("lecture-2", 0);
    let (lecture, df) = first_impulse(&w, Solver::DeepestFirst);
    let (si, r) = first_impulse(&w, Solver::SequentialImpulse);
    // The lecture's printed impulse, (0, 18.7337, 0).
    assert!((lecture.y - 18.7337).abs() < 1e-4);
    assert_close(&si, &lecture, "impulse");
    assert_close(
        &r.bodies[0].velocity,
        &df.bodies[0].velocity,
        "velocity after",
    );
    assert_close(
        &r.bodies[0].angular_velocity,
        &df.bodies[0].angular_velocity,
        "angular velocity after",
    );
}

#[test]
fn one_sticking_contact_gets_the_lectures_sticking_impulse() {
    // friction-cube contact 0 sticks: |g_planar| = 10.72 ≤ μ g_n = 15.26.
    let w = one_contact("friction-cube", 0);
    let (lecture, _) = first_impulse(&w, Solver::DeepestFirst);
    let (si, r) = first_impulse(&w, Solver::SequentialImpulse);
    assert_close(&si, &lecture, "sticking impulse");
    assert!(lecture.x.abs() > 1.0, "the impulse has a tangential part");
    // A second sweep finds nothing left to do: the accumulated impulse is the lecture's.
    let total = r.contacts[0].basis * r.sequential.accumulated[0];
    assert_close(&total, &lecture, "accumulated");
}

#[test]
fn normal_impulses_stay_non_negative_and_friction_inside_the_cone() {
    for id in [
        "box-four-corners",
        "box-stack",
        "friction-cube",
        "two-boxes",
    ] {
        let w = Lesson::load(id).unwrap().world::<f64>();
        let (r, _) = Resolver::resolve(
            &w,
            &params(Solver::SequentialImpulse),
            Implementation::Indexed,
            &mut Silent,
        );
        for (k, g) in r.sequential.accumulated.iter().enumerate() {
            assert!(g.x >= 0.0, "{id} contact {k}: normal impulse {}", g.x);
            let mu = w.contacts[k].input.static_friction;
            let planar = (g.y * g.y + g.z * g.z).sqrt();
            assert!(
                planar <= mu * g.x * (1.0 + 1e-12) + 1e-15,
                "{id} contact {k}: |g_t| = {planar} > μ g_n = {}",
                mu * g.x
            );
        }
        assert!(
            r.sequential.accumulated.iter().any(|g| g.x > 0.0),
            "{id}: some contact pushes"
        );
    }
}

fn momentum(bodies: &[contact_lab::physics::resolver::ResolverBody<f64>]) -> Vector3<f64> {
    bodies
        .iter()
        .map(|b| b.velocity / b.inverse_mass)
        .fold(Vector3::zeros(), |s, p| s + p)
}

#[test]
fn free_bodies_keep_their_momentum() {
    // The cradle's balls touch nothing immovable: only internal impulses.
    let w = Lesson::load("newtons-cradle").unwrap().world::<f64>();
    let before = Resolver::prepare(&w, &params(Solver::SequentialImpulse));
    let (after, [_, velocity]) = Resolver::resolve(
        &w,
        &params(Solver::SequentialImpulse),
        Implementation::Indexed,
        &mut Silent,
    );
    assert!(velocity.iterations_used > 0);
    let (p0, p1) = (momentum(&before.bodies), momentum(&after.bodies));
    assert!(
        (p0 - p1).norm() < 1e-12 * p0.norm().max(1.0),
        "{p0:?} → {p1:?}"
    );
    assert!(
        (after.bodies[0].velocity - before.bodies[0].velocity).norm() > 0.1,
        "the impulses changed the velocities"
    );
}

#[test]
fn equal_limits_mean_equal_contact_visits() {
    let w = Lesson::load("sphere-row").unwrap().world::<f64>();
    for limit in [1usize, 7, 15, 40] {
        let p = ResolverParams {
            position_iterations: Some(limit),
            velocity_iterations: Some(limit),
            ..params(Solver::SequentialImpulse)
        };
        let (_, [position, velocity]) =
            Resolver::resolve(&w, &p, Implementation::Indexed, &mut Silent);
        assert_eq!(position.iterations_used, limit, "position, limit {limit}");
        assert_eq!(velocity.iterations_used, limit, "velocity, limit {limit}");
    }
}

/// How far the box on the 20° slope moves in 5 s, under a solver.
fn ramp_drift(solver: Solver, warm_start: bool) -> f64 {
    let lesson = Lesson::load("ramp-stick").unwrap();
    let mut p = lesson.sim_params().unwrap();
    p.resolver.solver = solver;
    p.resolver.warm_start = warm_start;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, p, lesson.simulation.unwrap().materials);
    let start = sim.world.bodies[0].state.position;
    for _ in 0..300 {
        sim.advance().unwrap();
    }
    (sim.world.bodies[0].state.position - start).norm()
}

#[test]
fn ramp_stick_sticks_under_sequential_impulses_and_creeps_under_the_lecture() {
    let lecture = ramp_drift(Solver::DeepestFirst, false);
    let si = ramp_drift(Solver::SequentialImpulse, false);
    let warm = ramp_drift(Solver::SequentialImpulse, true);
    // Measured: deepest-first 2.12 m, sequential impulses 1.1e-5 m, warm-started 3.5e-8 m.
    assert!(lecture > 1.0, "deepest-first creeps: {lecture} m");
    assert!(si < 1e-3, "sequential impulses stick: {si} m");
    assert!(
        warm < 1e-3,
        "warm-started sequential impulses stick: {warm} m"
    );
}

/// stack-5 with sleep off under `solver`.
fn stack(solver: Solver, warm_start: bool) -> Simulation<f64> {
    crate::common::resolver_worlds::stepped("stack-5", solver, warm_start)
}

/// Velocity-phase visits over steps 31–90 of stack-5 under sequential impulses.
fn stack_visits(warm_start: bool) -> usize {
    let mut sim = stack(Solver::SequentialImpulse, warm_start);
    (0..90)
        .map(|_| sim.advance().unwrap().velocity_iterations)
        .skip(30)
        .sum()
}

#[test]
fn warm_starting_a_resting_stack_needs_fewer_visits() {
    let (cold, warm) = (stack_visits(false), stack_visits(true));
    // Measured: 9 600 cold (8 sweeps of 20 contacts, the limit, every step), 1 600 warm.
    assert!(warm * 3 < cold, "warm {warm} visits against cold {cold}");
}

/// The benches time stack-5 over steps 61–660 (sleep off): the figures are
/// a standing stack's for the lecture's order and warm-started sequential
/// impulses, a falling one's for cold sequential impulses.
#[test]
fn the_stack_the_benches_time_stands_under_two_solvers_and_falls_under_one() {
    let top_after = |solver, warm| {
        let mut sim = stack(solver, warm);
        for _ in 0..660 {
            sim.advance().unwrap();
        }
        sim.world.bodies[4].state.position.y
    };
    // Measured: 4.47 m, 4.49 m, and 0.50 m (the top box on the floor).
    let lecture = top_after(Solver::DeepestFirst, false);
    let warm = top_after(Solver::SequentialImpulse, true);
    let cold = top_after(Solver::SequentialImpulse, false);
    assert!(lecture > 4.4, "deepest-first: top box at {lecture} m");
    assert!(
        warm > 4.4,
        "warm-started sequential impulses: top box at {warm} m"
    );
    assert!(cold < 1.0, "cold sequential impulses: top box at {cold} m");
}

/// Relative closeness for the rows' checks (the rows reorder the stage
/// maths' arithmetic: equal to the last bits, not to the bit).
fn near(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-12 * scale.max(1.0)
}

#[test]
fn the_solver_rows_give_the_stage_maths_velocities_matrices_and_impulses() {
    use contact_lab::physics::resolver::sequential::body_velocity;
    use contact_lab::physics::resolver::velocity::apply_impulse;
    // Two-body contacts (two-boxes, box-stack, the cradle) and one-body ones.
    for id in [
        "two-boxes",
        "box-stack",
        "friction-cube",
        "newtons-cradle",
        "box-four-corners",
    ] {
        let w = Lesson::load(id).unwrap().world::<f64>();
        let si = Resolver::prepare(&w, &params(Solver::SequentialImpulse));
        let df = Resolver::prepare(&w, &params(Solver::DeepestFirst));
        let (rows, solver) = (&si.sequential.rows, &si.sequential.solver);
        assert_eq!(rows.len(), w.contacts.len(), "{id}");
        if id == "two-boxes" {
            assert!(
                w.contacts.iter().any(|c| c.body2.is_some()),
                "a two-body contact"
            );
        }
        for (k, row) in rows.iter().enumerate() {
            let contact = &df.contacts[k];
            // Contact velocity: the rows against Cᵀ Σ s (v + ω × r), with the
            // bodies given a made-up motion so every row is read.
            let mut moved = si.bodies.clone();
            for (b, body) in moved.iter_mut().enumerate() {
                let t = b as f64 + 1.0;
                body.velocity = Vector3::new(0.3 * t, -1.1, 0.7 / t);
                body.angular_velocity = Vector3::new(-0.4, 0.9 * t, 0.25);
            }
            let mut arrays = solver.clone();
            for (s, b) in arrays.iter_mut().zip(&moved) {
                s.v = b.velocity;
                s.w = b.angular_velocity;
            }
            let stage = body_velocity(contact, &moved);
            let from_rows = row.velocity(&arrays) - row.offset;
            for a in 0..3 {
                assert!(
                    near(from_rows[a], stage[a], stage.norm()),
                    "{id} contact {k} axis {a}: {from_rows:?} against {stage:?}"
                );
            }
            // M from the rows against the lecture's Cᵀ W C + Σ m⁻¹ 𝟙.
            if let (Some(fs), Some(fd)) = (si.setups[k].friction, df.setups[k].friction) {
                let (m_si, m_df) = (
                    &si.friction[fs].matrix.matrix,
                    &df.friction[fd].matrix.matrix,
                );
                for (x, y) in m_si.iter().zip(m_df.iter()) {
                    assert!(
                        near(*x, *y, m_df.norm()),
                        "{id} contact {k}: M {m_si} against {m_df}"
                    );
                }
            }
            // One impulse through the rows against the stage maths' velocity change.
            let g = Vector3::new(2.5, -0.75, 1.25);
            let mut stage_bodies = moved.clone();
            apply_impulse(contact, &mut stage_bodies, g, None);
            row.apply(&mut arrays, &g);
            for (b, body) in stage_bodies.iter().enumerate() {
                for (x, y) in [
                    (arrays[b].v, body.velocity),
                    (arrays[b].w, body.angular_velocity),
                ] {
                    assert!(
                        (x - y).norm() <= 1e-12 * y.norm().max(1.0),
                        "{id} contact {k} body {b}: {x:?} against {y:?}"
                    );
                }
            }
            // The world's entry never moves.
            assert_eq!(
                arrays.last().unwrap().v,
                Vector3::zeros(),
                "{id} contact {k}"
            );
        }
    }
}

#[test]
fn sequential_impulses_on_the_rows_end_where_the_stage_maths_do() {
    // A resolution's every visit, replayed with the stage maths (the old
    // path: contact velocity from the bodies, M⁻¹ of the lecture's M, the
    // lecture's velocity change), ends at the same body velocities.
    for id in ["two-boxes", "box-stack", "newtons-cradle"] {
        let w = Lesson::load(id).unwrap().world::<f64>();
        let (r, _) = Resolver::resolve(
            &w,
            &params(Solver::SequentialImpulse),
            Implementation::Indexed,
            &mut Silent,
        );
        // Replay the accumulated impulses with the stage maths from the
        // prepared velocities: the result is the same linear map.
        let df = Resolver::prepare(&w, &params(Solver::DeepestFirst));
        let mut bodies = df.bodies.clone();
        for (k, g) in r.sequential.accumulated.iter().enumerate() {
            apply_impulse_of(&df, k, &mut bodies, *g);
        }
        for (b, body) in bodies.iter().enumerate() {
            let got = &r.bodies[b];
            for (x, y) in [
                (got.velocity, body.velocity),
                (got.angular_velocity, body.angular_velocity),
            ] {
                assert!(
                    (x - y).norm() <= 1e-12 * y.norm().max(1.0),
                    "{id} body {b}: {x:?} against {y:?}"
                );
            }
        }
    }
}

fn apply_impulse_of(
    r: &Resolver<f64>,
    k: usize,
    bodies: &mut [contact_lab::physics::resolver::ResolverBody<f64>],
    g: Vector3<f64>,
) {
    contact_lab::physics::resolver::velocity::apply_impulse(&r.contacts[k], bodies, g, None);
}
