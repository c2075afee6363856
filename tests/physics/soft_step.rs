//! The soft step (`solver = "soft-step"`, Box2D v3's solver): a slender box
//! resting on a box stands still, a stack of five stands, a ball dropped on
//! the floor bounces above the restitution threshold and not below it, and
//! the coefficients a traced step records are those of f, ζ and h.

use contact_lab::lesson::validate::parse;
use contact_lab::physics::params::Softness;
use contact_lab::physics::step::soft::SoftTrace;
use contact_lab::physics::step::Simulation;
use contact_lab::physics::Solver;

/// A scene's `bodies` with `world` settings, sleep off, at 60 Hz, solved
/// with the soft step.
fn soft(world: &str, bodies: &str) -> Simulation<f64> {
    let text = format!(
        r#"id = "soft"
title = "A soft step"
source = "Lecture IV Collisions"
summary = "A soft step."

[world]
{world}

[sleep]
sleep = false

[step]
dt = 0.016666666666666666
steps = 120

[settings]
solver = "soft-step"

{bodies}
[[body]]
name = "floor"
mass = inf
shape = {{ box = [2, 1, 2] }}
position = [0, 0, 0]
"#
    );
    let lesson = parse("soft_step.rs", &text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    assert_eq!(params.resolver.solver, Solver::SoftStep);
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

fn body(name: &str, shape: &str, y: f64) -> String {
    format!("[[body]]\nname = \"{name}\"\nmass = 1.0\nshape = {shape}\nposition = [0, {y}, 0]\n\n")
}

const SLENDER: &str = "{ box = [0.42, 0.8, 0.42] }";

#[test]
fn a_slender_box_on_a_box_stands_still_under_the_soft_step() {
    // Measured: |ω| after the first second below 1e-3 rad/s.
    let mut sim = soft(
        "restitution = 0.2\nfriction = 0.5",
        &body("post", SLENDER, 0.9),
    );
    let mut w = 0.0f64;
    for step in 0..120 {
        sim.advance().expect("no blow-up");
        if step >= 60 {
            w = w.max(sim.world.bodies[0].state.angular_velocity.norm());
        }
    }
    assert!(w < 0.01, "rocking: |ω| up to {w} rad/s after 1 s");
    let y = sim.world.bodies[0].state.position.y;
    assert!((y - 0.9).abs() < 0.01, "the box sank or rose to {y}");
}

#[test]
fn a_stack_of_five_stands_under_the_soft_step() {
    let bodies: String = (0..5)
        .map(|i| body(&format!("box{i}"), "{ box = [1, 1, 1] }", 1.0 + i as f64))
        .collect();
    let mut sim = soft("friction = 0.6", &bodies);
    for _ in 0..300 {
        sim.advance().expect("no blow-up");
    }
    for i in 0..5 {
        let p = sim.world.bodies[i].state.position;
        let drift = ((p.y - (1.0 + i as f64)).powi(2) + p.x * p.x + p.z * p.z).sqrt();
        assert!(drift < 0.02, "box {i} moved {drift} m");
    }
}

#[test]
fn a_ball_bounces_above_the_threshold_and_not_below_it() {
    let ball = "[[body]]\nname = \"ball\"\nmass = 1.0\nshape = { sphere = 0.25 }\nposition = [0, 0.76, 0]\nvelocity = [0, -4, 0]\n\n";
    let mut sim = soft("restitution = 0.5", ball);
    let mut up = 0.0f64;
    for _ in 0..10 {
        sim.advance().expect("no blow-up");
        up = up.max(sim.world.bodies[0].state.velocity.y);
    }
    assert!((up - 2.0).abs() < 0.25, "bounced at {up} m/s, e·v = 2");
    let slow = "[[body]]\nname = \"ball\"\nmass = 1.0\nshape = { sphere = 0.25 }\nposition = [0, 0.76, 0]\nvelocity = [0, -0.5, 0]\n\n";
    let mut sim = soft("restitution = 0.5", slow);
    let mut up = 0.0f64;
    for _ in 0..10 {
        sim.advance().expect("no blow-up");
        up = up.max(sim.world.bodies[0].state.velocity.y);
    }
    assert!(up < 0.05, "bounced at {up} m/s below the threshold");
}

#[test]
fn the_traced_coefficients_are_those_of_f_zeta_and_h() {
    let mut sim = soft("friction = 0.5", &body("post", SLENDER, 0.9));
    sim.params.resolver.substeps = 4;
    sim.params.resolver.soft.contact_hertz = 30.0;
    sim.params.resolver.soft.contact_damping_ratio = 10.0;
    sim.advance().expect("no blow-up");
    sim.soft_trace = Some(SoftTrace::default());
    sim.advance().expect("no blow-up");
    let trace = sim.soft_trace.take().expect("recorded");
    assert!(!trace.contacts.is_empty());
    // By hand: h = Δt/4, ω = 2π·30, a₁ = 2ζ + hω, a₂ = hω·a₁, a₃ = 1/(1 + a₂).
    let h = (1.0 / 60.0) / 4.0;
    let omega = 2.0 * std::f64::consts::PI * 30.0;
    let a1 = 2.0 * 10.0 + h * omega;
    let a2 = h * omega * a1;
    let a3 = 1.0 / (1.0 + a2);
    assert!((trace.h - h).abs() < 1e-15);
    for k in &trace.contacts {
        assert!((k.bias_rate - omega / a1).abs() < 1e-12, "{}", k.bias_rate);
        assert!((k.mass_scale - a2 * a3).abs() < 1e-12, "{}", k.mass_scale);
        assert!((k.impulse_scale - a3).abs() < 1e-12, "{}", k.impulse_scale);
        assert_eq!(k.substep_impulses.len(), 4);
    }
    let s = Softness::new(30.0, 10.0, h);
    assert_eq!(s.bias_rate, trace.contacts[0].bias_rate);
}

/// The verdict matrix's own slender box (`study --verdicts`, scene
/// `slender-box`: its scene text, not a copy), under the soft step with its
/// default knobs: still (|ω| < 0.01 rad/s at every step after 1 s) and not
/// sunk, over the matrix's 2 s.
#[test]
fn the_verdict_matrix_slender_box_stays_still_under_the_soft_step() {
    use contact_lab::study::verdicts::{criteria, scenes, Size};
    let text = scenes::slender(Size::Full, 2.0);
    let lesson = parse("verdict-slender", &text).expect("the matrix's scene parses");
    let mut params = lesson.sim_params().expect("a scene");
    assert!(!params.sleep.enabled, "the matrix runs it awake");
    params.resolver.solver = Solver::SoftStep;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    let y0 = sim.world.bodies[0].state.position.y;
    let mut w = 0.0f64;
    while sim.time < 2.0 - 1e-9 {
        sim.advance().expect("no blow-up");
        if sim.time > criteria::STILL_FROM + 1e-9 {
            w = w.max(sim.world.bodies[0].state.angular_velocity.norm());
        }
    }
    assert!(w < 0.01, "rocking: |ω| up to {w} rad/s after 1 s");
    let y = sim.world.bodies[0].state.position.y;
    assert!((y - y0).abs() < 0.01, "moved from {y0} to {y}");
}
