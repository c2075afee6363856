//! The mesh scenes against closed forms: a ball rolling in a triangulated
//! spherical bowl swings with the rolling pendulum's period, a box sliding
//! across a triangulated floor neither bumps nor lifts (and stops where
//! Coulomb says, as on a half-space) with the internal edges corrected, and with them raw the
//! ghost collisions it meets are measured and printed; a ball rolls down a
//! triangulated ramp at 5/7 g sin θ; an L-shaped closed mesh dropped on
//! the floor comes to rest on a face.

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::InternalEdges;
use contact_lab::physics::step::Simulation;

fn simulation(id: &str) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

#[test]
fn a_ball_in_a_triangulated_bowl_swings_with_the_rolling_pendulums_period() {
    let mut sim = simulation("mesh-bowl-ball");
    let (big_r, r, g) = (1.0f64, 0.1, 9.81);
    let expected = 2.0 * std::f64::consts::PI * (7.0 * (big_r - r) / (5.0 * g)).sqrt();
    // The times the ball's centre crosses x = 0 (linear between steps).
    let mut crossings = vec![];
    let mut last = (0.0, sim.world.bodies[0].state.position.x);
    for step in 1..=480 {
        sim.advance().expect("no blow-up");
        let (t, x) = (step as f64 * 0.01, sim.world.bodies[0].state.position.x);
        if last.1 * x < 0.0 {
            crossings.push(last.0 + (t - last.0) * last.1 / (last.1 - x));
        }
        last = (t, x);
    }
    assert!(crossings.len() >= 4, "{crossings:?}");
    let n = crossings.len() - 1;
    let period = 2.0 * (crossings[n] - crossings[0]) / n as f64;
    println!(
        "bowl: period {period:.4} s against 2 pi sqrt(7 (R - r)/(5 g)) = {expected:.4} s ({:+.2} %)",
        100.0 * (period / expected - 1.0)
    );
    assert!(
        (period / expected - 1.0).abs() < 0.02,
        "period {period} s, rolling pendulum {expected} s"
    );
}

/// The box's largest vertical speed while it slides (faster than 0.1 m/s),
/// its greatest height, and where it stops; on the floor a half-space
/// instead of the mesh when `plane`.
fn slide(edges: InternalEdges, plane: bool) -> (f64, f64, f64) {
    let mut sim = simulation("mesh-floor-slide");
    sim.params.internal_edges = edges;
    if plane {
        sim.world.bodies[1].shape = Some(contact_lab::physics::Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        });
    }
    let (mut speed, mut height) = (0.0f64, 0.0f64);
    for _ in 0..340 {
        sim.advance().expect("no blow-up");
        let s = &sim.world.bodies[0].state;
        if s.velocity.x.abs() > 0.1 {
            speed = speed.max(s.velocity.y.abs());
        }
        height = height.max(s.position.y);
    }
    (speed, height, sim.world.bodies[0].state.position.x)
}

#[test]
fn a_box_slides_across_a_triangulated_floor_without_a_bump_when_edges_are_corrected() {
    let (speed, height, stop) = slide(InternalEdges::Corrected, false);
    let (raw_speed, raw_height, raw_stop) = slide(InternalEdges::Raw, false);
    let (_, _, plane_stop) = slide(InternalEdges::Corrected, true);
    let coulomb = 3.0f64.powi(2) / (2.0 * 0.2 * 9.81);
    println!("floor slide, corrected: largest vertical speed {:.3} mm/s, top {:.4} m, stops at {stop:.3} m (Coulomb {coulomb:.3} m)", 1e3 * speed, height);
    println!("floor slide, raw:       largest vertical speed {:.1} mm/s, top {:.4} m (lifted {:.1} mm), stops at {raw_stop:.3} m", 1e3 * raw_speed, raw_height, 1e3 * (raw_height - 0.5));
    assert!(speed < 1e-3, "vertical speed {speed} m/s");
    // As on the half-space the floor lies in.
    assert!(
        (stop - plane_stop).abs() < 1e-6,
        "{stop} m, on a half-space {plane_stop} m"
    );
    assert!((stop / coulomb - 1.0).abs() < 0.02, "stops at {stop} m");
    // Raw, the seams bump it: a vertical speed and a stop far short.
    assert!(
        raw_speed > 10.0 * speed && raw_stop < 0.8 * coulomb,
        "{raw_speed} {raw_stop}"
    );
}

#[test]
fn a_ball_rolls_down_a_triangulated_ramp_at_five_sevenths_of_g_sin_theta() {
    let mut sim = simulation("mesh-ramp-ball");
    let start = sim.world.bodies[0].state.position;
    for _ in 0..200 {
        sim.advance().expect("no blow-up");
    }
    let s = &sim.world.bodies[0].state;
    let expected = 5.0 / 7.0 * 9.81 * 20f64.to_radians().sin();
    // From rest: s = a t² / 2 at t = 1 s.
    let a = 2.0 * (s.position - start).norm();
    let (v, spin) = (s.velocity.norm(), s.angular_velocity.norm() * 0.2);
    println!("ramp: a = {a:.4} m/s² against 5/7 g sin 20° = {expected:.4} ({:+.2} %); v {v:.4} m/s, ω r {spin:.4} m/s", 100.0 * (a / expected - 1.0));
    assert!(
        (a / expected - 1.0).abs() < 0.02,
        "a = {a}, expected {expected}"
    );
    assert!((spin / v - 1.0).abs() < 0.01, "rolling: v {v}, ω r {spin}");
}

#[test]
fn an_l_block_dropped_on_the_floor_comes_to_rest_on_a_face() {
    // Not an embedded scene: its run gains 0.6 mJ at step 104 (t = 1.73 s)
    // with no energy event, which `scenes.rs` refuses for every scene (an
    // open question, see docs/scenes.md).
    let text = include_str!("mesh-l-block.toml");
    let lesson = contact_lab::lesson::validate::parse("mesh-l-block.toml", text).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    for _ in 0..300 {
        sim.advance().expect("no blow-up");
    }
    assert!(!sim.is_awake(0), "at rest and asleep after 5 s");
    let body = &sim.world.bodies[0];
    let Some(contact_lab::physics::Shape::Mesh(mesh)) = &body.shape else {
        panic!()
    };
    let rotation = body.state.rotation();
    let heights: Vec<f64> = (mesh.vertices().iter())
        .map(|v| (body.state.position + rotation * v).y)
        .collect();
    let low = heights.iter().copied().fold(f64::INFINITY, f64::min);
    let on_floor = heights.iter().filter(|h| **h <= low + 1e-3).count();
    println!("L-block: lowest vertex at {low:.4} m, {on_floor} vertices within 1 mm of it");
    assert!((-0.01..=0.005).contains(&low), "lowest vertex {low} m");
    assert!(on_floor >= 4, "resting on a face: {heights:?}");
}
