//! Continuous detection for every pair kind (issue 39): a bullet of each
//! convex kind (sphere, box, cylinder, capsule, hull) at a half-space floor
//! and at a thin box wall, at 1 mm, 1 m and 1 km, with each search. Against
//! the floor it never ends a step below it and bounces; against the wall it
//! never ends beyond it without a `tunnelled` event; the last `toi` event
//! of a step says the speed the state after the step leaves with.

use contact_lab::lesson::validate::parse;
use contact_lab::physics::step::ccd_mode::Ccd;
use contact_lab::physics::step::{Event, Simulation, StepReport};
use nalgebra::Vector3;

pub(crate) const KINDS: [&str; 5] = ["sphere", "box", "cylinder", "capsule", "hull"];

/// The shape of a bullet of kind `kind` about `l` across.
pub(crate) fn shape(kind: &str, l: f64) -> String {
    let h = l / 2.0;
    match kind {
        "sphere" => format!("{{ sphere = {h} }}"),
        "box" => format!("{{ box = [{l}, {l}, {l}] }}"),
        "cylinder" => format!("{{ cylinder = {{ radius = {h}, height = {l} }} }}"),
        "capsule" => format!("{{ capsule = {{ radius = {}, height = {h} }} }}", l / 4.0),
        // A tetrahedron with a vertex first along the motion.
        _ => format!("{{ convex = [[{l}, 0, 0], [0, {l}, 0], [0, 0, {l}], [-{h}, -{h}, -{h}]] }}"),
    }
}

/// A bullet of `kind` (size l, 10⁴ l/s, so 167 sizes a step) flying along
/// −y at a half-space floor (`floor`) or along +x at a wall 2 l thick.
fn scene(kind: &str, l: f64, floor: bool, ccd: Ccd) -> Simulation<f64> {
    let speed = 1e4 * l;
    let (position, velocity, target) = if floor {
        (
            format!("[0, {}, 0]", 20.0 * l),
            format!("[0, {}, 0]", -speed),
            r#"shape = "half_space"
normal = [0, 1, 0]
position = [0, 0, 0]"#
                .to_string(),
        )
    } else {
        (
            format!("[{}, 0, 0]", -20.0 * l),
            format!("[{speed}, 0, 0]"),
            format!(
                "shape = {{ box = [{}, {}, {}] }}\nposition = [0, 0, 0]",
                2.0 * l,
                200.0 * l,
                200.0 * l
            ),
        )
    };
    let text = format!(
        r#"
id = "ccd-{kind}"
title = "A bullet"
[world]
gravity = [0, 0, 0]
restitution = 0.5
[step]
dt = 0.016666666666666666
steps = 10
[sleep]
enabled = false
[[body]]
name = "bullet"
mass = 1.0
shape = {}
position = {position}
velocity = {velocity}
[[body]]
name = "target"
mass = inf
{target}
"#,
        shape(kind, l)
    );
    let lesson = parse("bullet.toml", &text).expect("a valid scene");
    let mut params = lesson.sim_params().expect("a scene");
    params.ccd = ccd;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

/// The bullet's lowest point along `n` (its support along −n), relative to the origin.
pub(crate) fn lowest(sim: &Simulation<f64>, n: [f64; 3]) -> f64 {
    use contact_lab::physics::detect::{Convex, Support};
    use contact_lab::physics::pose::Pose;
    let b = &sim.world.bodies[0];
    let convex = Convex::from_shape(b.shape.as_ref().unwrap()).unwrap();
    let pose = Pose::new(b.state.position, &b.state.orientation);
    let n = nalgebra::Vector3::from(n);
    n.dot(&convex.support(&pose, &-n))
}

/// The last `toi` event of a step said the bullet left at `separating`:
/// the state after the step must say so too. With no gravity, the bullet's
/// velocities after the step are the ones that collision left it with, and
/// its centre moved straight since: the contact point's velocity there,
/// v + ω × (point − (x_end − v (t_end − t_hit))), along the normal.
pub(crate) fn check_separating(sim: &Simulation<f64>, r: &StepReport, what: &str) {
    let Some(h) = r.events.iter().rev().find_map(|e| match e {
        Event::Toi(h) => Some(*h),
        _ => None,
    }) else {
        return;
    };
    let s = &sim.world.bodies[0].state;
    let centre = s.position - s.velocity * (r.time - h.time);
    let point = Vector3::from(h.point);
    let v = s.velocity + s.angular_velocity.cross(&(point - centre));
    let sign = if h.body1.0 == 0 { 1.0 } else { -1.0 };
    let leaves = sign * v.dot(&Vector3::from(h.normal));
    assert!(
        (leaves - h.separating).abs() <= 1e-6 * h.closing,
        "{what} step {}: the event says {} m/s, the state {leaves} m/s",
        r.step,
        h.separating
    );
}

#[test]
fn every_kind_at_every_scale_bounces_off_a_floor_and_never_ends_below_it() {
    for kind in KINDS {
        for l in [1e-3, 1.0, 1e3] {
            for ccd in [Ccd::Bisection, Ccd::Conservative] {
                let mut sim = scene(kind, l, true, ccd);
                let mut hits = 0;
                for _ in 0..10 {
                    let r = sim.advance().expect("no blow-up");
                    hits += r
                        .events
                        .iter()
                        .filter(|e| matches!(e, Event::Toi(_)))
                        .count();
                    check_separating(&sim, &r, &format!("{kind} {l} {ccd:?}"));
                    let low = lowest(&sim, [0.0, 1.0, 0.0]);
                    assert!(
                        low >= -1e-3 * l,
                        "{kind} {l} {ccd:?} step {}: {low} below the floor",
                        r.step
                    );
                }
                assert!(hits >= 1, "{kind} {l} {ccd:?}: no toi event");
                let v = sim.world.bodies[0].state.velocity.y;
                assert!(v > 0.0, "{kind} {l} {ccd:?}: still falling at {v}");
            }
        }
    }
}

#[test]
fn every_kind_at_every_scale_never_ends_beyond_a_wall_unreported() {
    for kind in KINDS {
        for l in [1e-3, 1.0, 1e3] {
            for ccd in [Ccd::Bisection, Ccd::Conservative] {
                let mut sim = scene(kind, l, false, ccd);
                let mut tunnelled = false;
                for _ in 0..10 {
                    let r = sim.advance().expect("no blow-up");
                    check_separating(&sim, &r, &format!("{kind} {l} {ccd:?}"));
                    tunnelled |= r
                        .events
                        .iter()
                        .any(|e| matches!(e, Event::Tunnelled { .. }));
                }
                // Beyond the wall: its nearest point (its least x) past the far face, x = l.
                let beyond = lowest(&sim, [1.0, 0.0, 0.0]) > l;
                assert!(
                    !beyond || tunnelled,
                    "{kind} {l} {ccd:?}: ends beyond the wall at x = {} unreported",
                    sim.world.bodies[0].state.position.x
                );
            }
        }
    }
}
