//! Simultaneous impact (the lcp solver) against the closed forms, beside the
//! lecture's sequence (deepest-first): rows of touching balls, Poisson's
//! law, two balls dropped together; degenerate and inconsistent systems
//! reported, never looped on.

use contact_lab::lesson::Lesson;
use contact_lab::physics::lcp::{Failure, Stage};
use contact_lab::physics::resolver::{Implementation, Resolver, Silent};
use contact_lab::physics::{LcpRestitution, ResolverParams, Solver, World};
use nalgebra::Vector3;

const TOL: f64 = 1e-12;

fn run(world: &World<f64>, params: &ResolverParams) -> Resolver<f64> {
    Resolver::resolve(world, params, Implementation::Indexed, &mut Silent).0
}

/// The bodies' velocities along `axis` after the lesson resolved under `solver`.
fn after(id: &str, solver: Solver, axis: usize) -> Vec<f64> {
    let lesson = Lesson::load(id).unwrap();
    let params = ResolverParams {
        solver,
        ..lesson.resolver
    };
    let r = run(&lesson.world(), &params);
    r.bodies.iter().map(|b| b.velocity[axis]).collect()
}

fn assert_close(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < TOL, "{what}: {got:?} against {want:?}");
    }
}

#[test]
fn rows_of_touching_balls_simultaneously_and_in_sequence() {
    let v = 1.0;
    assert_close(
        &after("impact-row-3", Solver::Lcp, 0),
        &[-v / 3.0, 2.0 * v / 3.0, 2.0 * v / 3.0],
        "N = 3 simultaneous",
    );
    assert_close(
        &after("impact-row-5", Solver::Lcp, 0),
        &[-0.6 * v, 0.4 * v, 0.4 * v, 0.4 * v, 0.4 * v],
        "N = 5 simultaneous",
    );
    assert_close(
        &after("impact-row-3", Solver::DeepestFirst, 0),
        &[0.0, 0.0, v],
        "N = 3 sequence",
    );
    assert_close(
        &after("impact-row-5", Solver::DeepestFirst, 0),
        &[0.0, 0.0, 0.0, 0.0, v],
        "N = 5 sequence",
    );
}

#[test]
fn poisson_row_matches_its_closed_form() {
    let (n, e, v) = (5.0, 0.5, 1.0);
    let striker = v * (1.0 - (n - 1.0) * (1.0 + e) / n);
    let other = v * (1.0 + e) / n;
    assert_close(
        &after("impact-row-poisson", Solver::Lcp, 0),
        &[striker, other, other, other, other],
        "Poisson e = 0.5",
    );
    // Poisson's law solved a compression LCP: every ball at v/N, then e·P_c added.
    let lesson = Lesson::load("impact-row-poisson").unwrap();
    assert_eq!(lesson.resolver.lcp_restitution, LcpRestitution::Poisson);
    let r = run(&lesson.world(), &lesson.resolver);
    let rec = r.lcp.as_ref().unwrap();
    assert_eq!(rec.problems[0].stage, Stage::Compression);
    let pc = rec.problems[0].result.as_ref().unwrap();
    for (k, p) in pc.iter().enumerate() {
        // The compression impulse of contact k carries balls k+1.. to v/N.
        assert!((p - v * (n - 1.0 - k as f64) / n).abs() < TOL, "{pc:?}");
        assert!((rec.impulses[k] - (1.0 + e) * p).abs() < TOL);
    }
}

#[test]
fn stacked_drop_sequence_launches_the_top_ball_simultaneous_does_not() {
    for (id, ratio) in [("impact-stack-r01", 0.1), ("impact-stack-r05", 0.5)] {
        let v = 1.0;
        let seq = after(id, Solver::DeepestFirst, 1);
        assert!(
            (seq[1] - (3.0 - ratio) / (1.0 + ratio) * v).abs() < TOL,
            "{id} sequence: {seq:?}"
        );
        assert_close(&after(id, Solver::Lcp, 1), &[v, v], id);
    }
}

#[test]
fn the_matrix_is_the_unit_impulse_responses() {
    let lesson = Lesson::load("impact-row-3").unwrap();
    let r = run(&lesson.world(), &lesson.resolver);
    let rec = r.lcp.as_ref().unwrap();
    assert_eq!(rec.matrix, vec![vec![2.0, -1.0], vec![-1.0, 2.0]]);
    // The diagonal is each contact's Δq̇_t (the lecture's stage 2).
    for (k, s) in r.setups.iter().enumerate() {
        assert!((rec.matrix[k][k] - s.unit_total).abs() < TOL);
    }
    assert_eq!(rec.problems[0].b, vec![-2.0, 0.0]);
    let names: Vec<_> = rec
        .pivots()
        .map(|(_, p)| (p.entering.name(), p.leaving.name()))
        .collect();
    assert_eq!(names[0], ("z0".to_string(), "w0".to_string()));
    assert_eq!(names.last().unwrap().1, "z0");
    assert!(rec.failure().is_none() && rec.degenerate().is_none());
}

#[test]
fn two_identical_contacts_are_reported_degenerate_and_solved() {
    let lesson = Lesson::load("impact-stack-r01").unwrap();
    let mut w: World<f64> = lesson.world();
    w.contacts.truncate(1);
    w.contacts.push(w.contacts[0].clone());
    let r = run(&w, &lesson.resolver);
    let rec = r.lcp.as_ref().unwrap();
    assert_eq!(rec.rank, 1);
    assert!(rec.degenerate().unwrap().contains("singular"));
    assert!(rec.failure().is_none());
    // The bottom ball rebounds at v whichever way the impulse is shared.
    assert!((r.bodies[0].velocity.y - 1.0).abs() < TOL);
    assert!((rec.impulses[0] + rec.impulses[1] - 2.0).abs() < TOL);
}

#[test]
fn an_inconsistent_system_is_reported_not_looped_on() {
    // The bottom ball between the floor and a ceiling touching its top, e = 1:
    // no impulses make it bounce off the floor without closing on the ceiling.
    let lesson = Lesson::load("impact-stack-r01").unwrap();
    let mut w: World<f64> = lesson.world();
    w.contacts.truncate(1);
    let mut ceiling = w.contacts[0].clone();
    ceiling.input.point = Vector3::new(0.0, 1.0, 0.0);
    ceiling.input.normal = Vector3::new(0.0, -1.0, 0.0);
    w.contacts.push(ceiling);
    let before = w.bodies.clone();
    let r = run(&w, &lesson.resolver);
    let rec = r.lcp.as_ref().unwrap();
    assert!(
        matches!(rec.failure(), Some(Failure::Ray(_))),
        "{:?}",
        rec.problems
    );
    assert!(rec.pivots().count() <= 4);
    assert_eq!(rec.impulses, vec![0.0, 0.0]);
    assert_eq!(r.bodies[0].velocity, before[1].state.velocity);
}

/// The balls' velocities along x after `steps` steps of a scene under `solver`.
fn simulated(id: &str, solver: Solver, steps: usize) -> Vec<f64> {
    let lesson = Lesson::load(id).unwrap();
    let mut p = lesson.sim_params().unwrap();
    p.resolver.solver = solver;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim =
        contact_lab::physics::step::Simulation::new(world, p, lesson.simulation.unwrap().materials);
    for _ in 0..steps {
        sim.advance().unwrap();
    }
    sim.world
        .bodies
        .iter()
        .map(|b| b.state.velocity.x)
        .collect()
}

#[test]
fn a_cradle_with_gaps_agrees_with_the_sequence_a_touching_one_does_not() {
    // With gaps the simultaneous solve meets one contact at a time.
    let gaps = simulated("cradle-gaps", Solver::Lcp, 200);
    assert_close(&gaps, &[0.0, 0.0, 0.0, 0.0, 1.0], "cradle with gaps, lcp");
    assert_close(
        &simulated("cradle-gaps", Solver::DeepestFirst, 200),
        &[0.0, 0.0, 0.0, 0.0, 1.0],
        "cradle with gaps, sequence",
    );
    // Touching: the simultaneous answer of the row of five.
    let touching = simulated("cradle-over-time", Solver::Lcp, 200);
    assert_close(
        &touching,
        &[-0.6, 0.4, 0.4, 0.4, 0.4],
        "touching cradle, lcp",
    );
}

/// The basis replayed from the recorded pivots (what the TUI shows as
/// λ so far): after a problem's last pivot it is that problem's answer,
/// and a pivot row's value is its ratio.
#[test]
fn lambda_replayed_after_the_last_pivot_is_the_problems_answer() {
    for id in [
        "impact-row-3",
        "impact-row-5",
        "impact-row-poisson",
        "impact-stack-r01",
        "impact-stack-r05",
    ] {
        let lesson = Lesson::load(id).unwrap();
        let r = run(&lesson.world(), &lesson.resolver);
        let rec = r.lcp.as_ref().unwrap();
        for p in &rec.problems {
            let Some(last) = p.pivots.len().checked_sub(1) else {
                continue;
            };
            let lambda = p.result.as_ref().unwrap();
            assert_close(&p.lambda_after(last), lambda, id);
            for (k, pivot) in p.pivots.iter().enumerate() {
                let (var, x) = p.basis_after(k)[pivot.row];
                assert_eq!(var, pivot.entering, "{id} pivot {k}");
                assert!((x - pivot.ratio).abs() < TOL, "{id} pivot {k}");
                if let Some(next) = p.pivots.get(k + 1) {
                    let values: Vec<f64> = p.basis_after(k).iter().map(|v| v.1).collect();
                    assert_close(&values, &next.rhs, id);
                }
            }
        }
    }
}

/// A ball (1 kg, radius 0.5 m, solid: I = 2/5 m r²) striking a floor at
/// (vt, -1, 0) m/s, e = 0.5, with friction μ_s, μ_d; resolved under `solver`.
fn oblique(vt: f64, mu_s: f64, mu_d: f64, solver: Solver) -> Resolver<f64> {
    let text = format!(
        r#"id = "oblique"
title = "A ball striking a floor obliquely"
[settings]
solver = "lcp"
[[body]]
name = "floor"
mass = inf
shape = "half_space"
normal = [0.0, 1.0, 0.0]
position = [0.0, 0.0, 0.0]
[[body]]
name = "ball"
mass = 1.0
shape = {{ sphere = 0.5 }}
position = [0.0, 0.5, 0.0]
velocity = [{vt}, -1.0, 0.0]
[[contact]]
bodies = ["ball", "floor"]
point = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
restitution = 0.5
static_friction = {mu_s}
dynamic_friction = {mu_d}
"#
    );
    let dir = std::env::temp_dir().join(format!("contact-lab-oblique-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("oblique-{vt}-{mu_s}-{mu_d}.toml"));
    std::fs::write(&path, text).unwrap();
    let lesson = Lesson::load(&path).unwrap();
    let params = ResolverParams {
        solver,
        ..lesson.resolver
    };
    run(&lesson.world(), &params)
}

/// Issue 43, friction in the LCP: the simultaneous phase's friction pass
/// gives a ball striking a floor obliquely the single-contact closed form:
/// with μ large it sticks (the contact point stops: v_t' = 5/7 v_t for a
/// solid ball), with μ small it slides (Δv_t = μ_d (1 + e) v_n); and the
/// lecture's single contact (deepest-first) agrees.
#[test]
fn an_oblique_strike_under_lcp_sticks_or_slides_as_the_closed_form() {
    let (vn, e, vt) = (1.0, 0.5, 2.0);
    // Sticking: the sticking impulse 2/7 vt = 0.571 is inside μ_s (1 + e) vn = 1.5.
    for solver in [Solver::Lcp, Solver::DeepestFirst] {
        let r = oblique(vt, 1.0, 1.0, solver);
        let ball = &r.bodies[0];
        assert!(
            (ball.velocity.x - 5.0 / 7.0 * vt).abs() < TOL,
            "{solver:?}: {:?}",
            ball.velocity
        );
        assert!((ball.velocity.y - e * vn).abs() < TOL, "{solver:?}");
        // The contact point (0, -0.5, 0) from the centre: v + ω × r has no x.
        let point = ball.velocity + ball.angular_velocity.cross(&Vector3::new(0.0, -0.5, 0.0));
        assert!(point.x.abs() < TOL, "{solver:?}: slip {point:?}");
    }
    let rec = oblique(vt, 1.0, 1.0, Solver::Lcp).lcp.unwrap();
    let f = rec.friction.as_ref().expect("a friction pass");
    assert!(f.converged && !f.rows[0].sliding, "{f:?}");
    // Sliding: μ_d (1 + e) vn = 0.15 < 2/7 vt.
    let (mu_s, mu_d) = (0.12, 0.1);
    for solver in [Solver::Lcp, Solver::DeepestFirst] {
        let r = oblique(vt, mu_s, mu_d, solver);
        let ball = &r.bodies[0];
        let dvt = vt - ball.velocity.x;
        assert!(
            (dvt - mu_d * (1.0 + e) * vn).abs() < TOL,
            "{solver:?}: {:?}",
            ball.velocity
        );
        assert!((ball.velocity.y - e * vn).abs() < TOL, "{solver:?}");
    }
    let rec = oblique(vt, mu_s, mu_d, Solver::Lcp).lcp.unwrap();
    let row = &rec.friction.as_ref().unwrap().rows[0];
    assert!(row.sliding, "{row:?}");
    assert!((row.normal - (1.0 + e) * vn).abs() < TOL);
    let t = (row.tangential[0].powi(2) + row.tangential[1].powi(2)).sqrt();
    assert!((t - mu_d * row.normal).abs() < TOL, "{row:?}");
}

/// The compliant reference's closed form: two balls head-on through a Hertz
/// contact (e = 1) conserve momentum and energy to 1e-9, and (elastic, 1D)
/// leave with the rigid two-body answer.
#[test]
fn hertz_two_balls_head_on_conserve_momentum_and_energy() {
    use contact_lab::physics::lcp::hertz::Chain;
    let (m1, m2, v1) = (1.0, 0.3, 1.0);
    let chain = Chain {
        inverse_mass: vec![1.0 / m1, 1.0 / m2],
        position: vec![0.0, 1.0],
        velocity: vec![v1, 0.0],
        rest: vec![1.0],
        stiffness: 1e7,
    };
    let out = chain.impact(1e-7, 1_000_000);
    assert!(out.ended, "{out:?}");
    let (p0, e0) = (
        chain.momentum(&chain.velocity),
        chain.energy(&chain.position, &chain.velocity),
    );
    let p1 = chain.momentum(&out.velocity);
    // After the impact no contact is compressed: the energy is kinetic.
    let e1: f64 = out
        .velocity
        .iter()
        .zip([m1, m2])
        .map(|(v, m)| 0.5 * m * v * v)
        .sum();
    assert!((p1 - p0).abs() < 1e-9 * p0.abs(), "momentum {p0} -> {p1}");
    assert!((e1 - e0).abs() < 1e-9 * e0, "energy {e0} -> {e1}");
    let rigid = [(m1 - m2) / (m1 + m2) * v1, 2.0 * m1 / (m1 + m2) * v1];
    for (got, want) in out.velocity.iter().zip(rigid) {
        assert!(
            (got - want).abs() < 1e-9,
            "{:?} against {rigid:?}",
            out.velocity
        );
    }
}
