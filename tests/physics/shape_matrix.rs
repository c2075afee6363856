//! The shape matrix: every kind of movable shape (sphere, box, cylinder,
//! capsule, convex hull) on every kind of lower body (half-space, box,
//! cylinder, convex hull, sphere, capsule, a triangulated floor; the round
//! ones large, so that their top is a place to rest), each resting, dropped from 1 m and sliding
//! at 2 m/s, under deepest-first and warm sequential impulses, with the
//! default settings (sleep on; without sleep the deepest-first order leaves
//! a resting body creeping, see `resting_convex.rs`). What every run must keep:
//!
//! - at rest (after a second's settling) the body moves less than 1 mm in
//!   5 s;
//! - after the position phase no contact is deeper than the position
//!   epsilon the step used (the documented slop), and the body's centre
//!   never ends below the lower body's top;
//! - every rise of total energy above the total-energy audit's tolerance
//!   (plus the position phase's settling lift, m |g| × the step's deepest
//!   penetration) comes with an energy event in the run.
//!
//! Scale variants (1 mm and 1 km bodies) run the resting column on a
//! half-space and on a box, the movement bound scaled with the body (1 µm
//! for a 1 mm body). The runs that do not hold today are listed in
//! [`KNOWN`] with their measured figure and why. (Shots at 1e3 m/s with
//! continuous detection are not part of this matrix.)

use contact_lab::lesson::validate::parse;
use contact_lab::physics::step::{total_audit, Event, Simulation, StepReport};
use contact_lab::physics::Solver;
use nalgebra::Vector3;

/// The movable shapes at size `l`: the lesson's shape (and orientation)
/// and the height of the centre (the position) above the top when resting.
const UPPERS: [&str; 5] = ["sphere", "box", "cylinder", "capsule", "hull"];
/// The lower bodies, immovable, their top at y = 0.
const LOWERS: [&str; 7] = [
    "half_space",
    "box",
    "cylinder",
    "hull",
    "sphere",
    "capsule",
    "mesh",
];

/// Quarter turn about z: a body's y axis along world x.
const LYING: &str = "[0.7071067811865476, 0, 0, 0.7071067811865476]";

fn upper(kind: &str, l: f64) -> (String, f64) {
    match kind {
        "sphere" => (format!("shape = {{ sphere = {} }}", 0.5 * l), 0.5 * l),
        "box" => (format!("shape = {{ box = [{l}, {l}, {l}] }}"), 0.5 * l),
        // Standing on its cap.
        "cylinder" => (
            format!("shape = {{ cylinder = [{}, {l}] }}", 0.5 * l),
            0.5 * l,
        ),
        // Lying on its side.
        "capsule" => (
            format!(
                "shape = {{ capsule = [{}, {l}] }}\norientation = {LYING}",
                0.25 * l
            ),
            0.25 * l,
        ),
        // A tetrahedron on its face: the position is the file frame's
        // origin, on the face (the centroid is 0.2 l above it).
        "hull" => {
            let s = |x: f64| x * l;
            (
                format!(
                    "shape = {{ convex = [[{}, 0, 0], [{}, 0, {}], [{}, 0, {}], [0, {}, 0]] }}",
                    s(0.5),
                    s(-0.25),
                    s(0.4330127018922193),
                    s(-0.25),
                    s(-0.4330127018922193),
                    s(0.8)
                ),
                0.0,
            )
        }
        _ => unreachable!("{kind}"),
    }
}

/// The lower body's shape, position and orientation at size `l` (top at y = 0).
fn lower(kind: &str, l: f64) -> String {
    let (w, h) = (8.0 * l, l);
    let big = 50.0 * l;
    match kind {
        "half_space" => "shape = \"half_space\"\nposition = [0, 0, 0]".into(),
        "box" => format!(
            "shape = {{ box = [{w}, {h}, {w}] }}\nposition = [0, {}, 0]",
            -h / 2.0
        ),
        "cylinder" => format!(
            "shape = {{ cylinder = [{}, {h}] }}\nposition = [0, {}, 0]",
            w / 2.0,
            -h / 2.0
        ),
        "hull" => {
            let (a, b) = (w / 2.0, h / 2.0);
            let corners: Vec<String> = (0..8)
                .map(|i| {
                    let sx = if i & 1 == 0 { -a } else { a };
                    let sy = if i & 2 == 0 { -b } else { b };
                    let sz = if i & 4 == 0 { -a } else { a };
                    format!("[{sx}, {sy}, {sz}]")
                })
                .collect();
            format!(
                "shape = {{ convex = [{}] }}\nposition = [0, {}, 0]",
                corners.join(", "),
                -h / 2.0
            )
        }
        "sphere" => format!("shape = {{ sphere = {big} }}\nposition = [0, {}, 0]", -big),
        "capsule" => format!(
            "shape = {{ capsule = [{big}, {w}] }}\nposition = [0, {}, 0]\norientation = {LYING}",
            -big
        ),
        // A triangulated floor: 4 × 4 squares of two triangles, its top y = 0.
        "mesh" => {
            let (n, s) = (4, w / 4.0);
            let at = |i: usize, j: usize| i * (n + 1) + j;
            let vertices: Vec<String> = (0..=n)
                .flat_map(|i| (0..=n).map(move |j| (i, j)))
                .map(|(i, j)| {
                    format!(
                        "[{}, 0, {}]",
                        -w / 2.0 + i as f64 * s,
                        -w / 2.0 + j as f64 * s
                    )
                })
                .collect();
            let triangles: Vec<String> = (0..n)
                .flat_map(|i| (0..n).map(move |j| (i, j)))
                .flat_map(|(i, j)| {
                    let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                    [format!("[{a}, {d}, {c}]"), format!("[{a}, {c}, {b}]")]
                })
                .collect();
            format!(
                "shape = {{ mesh = {{ vertices = [{}], triangles = [{}] }} }}\nposition = [0, 0, 0]",
                vertices.join(", "),
                triangles.join(", ")
            )
        }
        _ => unreachable!("{kind}"),
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Motion {
    Resting,
    Dropped,
    Sliding,
}

/// The scene: `up` on `low` at size `l`, friction 0.5, restitution 0.2.
fn scene(up: &str, low: &str, l: f64, motion: Motion, solver: Solver) -> Simulation<f64> {
    let (shape, rest) = upper(up, l);
    let (y, v) = match motion {
        Motion::Resting => (rest, 0.0),
        Motion::Dropped => (rest + 1.0, 0.0),
        Motion::Sliding => (rest, 2.0),
    };
    let text = format!(
        r#"id = "matrix"
title = "A shape on a lower body"
source = "Lecture IV Collisions"
summary = "One movable shape on an immovable one."

[world]
restitution = 0.2
friction = 0.5

[step]
dt = 0.016666666666666666
steps = 360

[[body]]
name = "upper"
mass = 1.0
{shape}
position = [0, {y}, 0]
velocity = [{v}, 0, 0]

[[body]]
name = "lower"
mass = inf
{}
"#,
        lower(low, l)
    );
    let lesson = parse("shape_matrix.rs", &text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    if solver == Solver::SequentialImpulse {
        sim.params.resolver.solver = Solver::SequentialImpulse;
        sim.params.resolver.warm_start = true;
    }
    if solver == Solver::SoftStep {
        sim.params.resolver.solver = Solver::SoftStep;
    }
    sim
}

/// What a run showed.
#[derive(Debug)]
struct Run {
    /// The centre's largest distance from where it was at 1 s, over 1–6 s.
    moved: f64,
    /// The deepest penetration left by a position phase, over its epsilon.
    deepest_left: f64,
    /// The centre's lowest height (y).
    lowest: f64,
    /// Steps whose total energy rose above the tolerance.
    rises: Vec<(u64, f64)>,
    /// Energy events (gain, rise, projection lift).
    energy_events: usize,
    /// Burial and pass-through events (wholly inside, pushed through,
    /// tunnelled).
    overlap_events: usize,
}

fn run(mut sim: Simulation<f64>, steps: usize) -> Run {
    let g = sim.params.world.gravity;
    let dt = sim.params.dt;
    let mass = sim.world.bodies[0].dynamic().map_or(0.0, |b| b.mass);
    let eps_v = sim.lowered_tolerances();
    let velocity_epsilon = eps_v
        .iter()
        .find(|l| l.which == contact_lab::physics::step::tolerance::Tolerance::VelocityEpsilon)
        .map_or(sim.params.resolver.velocity_epsilon, |l| l.used);
    let position_epsilon = eps_v
        .iter()
        .find(|l| l.which == contact_lab::physics::step::tolerance::Tolerance::PositionEpsilon)
        .map_or(sim.params.resolver.position_epsilon, |l| l.used);
    let tolerance = total_audit::tolerance(mass, g.norm(), velocity_epsilon, dt);
    let energy = |s: &Simulation<f64>| contact_lab::physics::step::energy::total(&s.world, &g);
    let mut before = energy(&sim);
    let mut out = Run {
        moved: 0.0,
        deepest_left: 0.0,
        lowest: f64::INFINITY,
        rises: Vec::new(),
        energy_events: 0,
        overlap_events: 0,
    };
    let mut at_one: Option<Vector3<f64>> = None;
    for _ in 0..steps {
        let r: StepReport = sim.advance().expect("no blow-up");
        let now = energy(&sim);
        let lift = mass * g.norm() * r.max_penetration.max(0.0);
        let rounding = 1e-9 * before.abs().max(1e-12);
        if now - before > tolerance + lift + rounding {
            out.rises.push((r.step, now - before));
        }
        before = now;
        out.energy_events += r
            .events
            .iter()
            .filter(|e| {
                matches!(
                    e,
                    Event::EnergyGain { .. }
                        | Event::EnergyRise { .. }
                        | Event::ProjectionLift { .. }
                )
            })
            .count();
        out.overlap_events += r
            .events
            .iter()
            .filter(|e| {
                matches!(
                    e,
                    Event::WhollyInside { .. }
                        | Event::PushedThrough { .. }
                        | Event::Tunnelled { .. }
                )
            })
            .count();
        out.deepest_left = out
            .deepest_left
            .max(r.max_penetration_after - position_epsilon);
        let x = sim.world.bodies[0].state.position;
        out.lowest = out.lowest.min(x.y);
        if r.time >= 1.0 - 1e-9 {
            let start = *at_one.get_or_insert(x);
            out.moved = out.moved.max((x - start).norm());
        }
    }
    out
}

/// Runs that do not keep the promises today, each with the figure measured
/// (the body's largest movement at rest, m) held as a bound: a change that
/// makes one worse fails, one that mends it fails too (take it off the list).
/// - 1 mm bodies: gravity moves a body 2.7 mm in a step (dt = 1/60 s), more
///   than its half-width, so each step is split into ⌈g Δt² / s⌉ substeps
///   (6 for a 0.5 mm half-width, 11 for the capsule's 0.25 mm radius;
///   src/physics/step/split.rs). Before the split ten runs were on this list
///   (a box or tetrahedron through a 1 mm box, 146–167 m; boxes and cans
///   rocking 1.5 cm on a half-space; sequential impulses moving a can 1.5 mm
///   and a tetrahedron 167 m); with it sequential impulses rest and nothing
///   passes through, but the lecture's order (one contact at a time) still
///   rocked every 1 mm shape by 0.13–0.68 mm. With its velocity epsilon
///   bounded as sequential impulses' is (a corner moved at most a thousandth
///   of the size in a step: 3e-5 m/s here, it was 0.007 m/s) the box on a
///   half-space moves 12 µm (it was 0.68 mm, and now sleeps), the capsules
///   6–7 µm (0.19–0.24 mm), the tetrahedron on a half-space 11 µm (0.13 mm),
///   the box on a box 96 µm (0.38 mm), the can on a box 0.24 mm (0.30 mm);
///   the can on a half-space 0.41 mm (0.33 mm) and the tetrahedron on a box
///   0.17 mm (0.13 mm) rock a little more.
///   A split by the bounding radius instead (4 substeps) left
///   a tetrahedron through a 1 mm box under the lecture's order (45 m).
const KNOWN: [(&str, f64); 8] = [
    ("0.001 m box on half_space, DeepestFirst, resting", 1.227e-5),
    ("0.001 m box on box, DeepestFirst, resting", 9.598e-5),
    (
        "0.001 m cylinder on half_space, DeepestFirst, resting",
        4.073e-4,
    ),
    ("0.001 m cylinder on box, DeepestFirst, resting", 2.363e-4),
    (
        "0.001 m capsule on half_space, DeepestFirst, resting",
        5.650e-6,
    ),
    ("0.001 m capsule on box, DeepestFirst, resting", 6.966e-6),
    (
        "0.001 m hull on half_space, DeepestFirst, resting",
        1.100e-5,
    ),
    ("0.001 m hull on box, DeepestFirst, resting", 1.692e-4),
];

/// A run's broken promises (`rest`: the body should stand still), one
/// line each. A run on the [`KNOWN`] list must move within 10 % of its
/// figure, and where it sinks or passes through, an event must say so.
fn check(name: &str, r: &Run, l: f64, rest: bool, failures: &mut Vec<String>) {
    if let Some(&(_, figure)) = KNOWN.iter().find(|(k, _)| *k == name) {
        if (r.moved - figure).abs() > 0.1 * figure {
            failures.push(format!(
                "{name}: moved {:.3e} m, the known figure is {figure:.3e} m",
                r.moved
            ));
        }
        if r.lowest <= 0.0 && r.overlap_events + r.energy_events == 0 {
            failures.push(format!("{name}: sank to {:.3e} m with no event", r.lowest));
        }
        return;
    }
    if rest && r.moved >= 1e-3 * l {
        failures.push(format!("{name}: moved {:.3e} m at rest", r.moved));
    }
    if r.deepest_left > 1e-9 * l {
        failures.push(format!(
            "{name}: {:.3e} m deeper than the position epsilon after the position phase",
            r.deepest_left
        ));
    }
    if r.lowest <= 0.0 {
        failures.push(format!("{name}: centre down to {:.3e} m", r.lowest));
    }
    if !r.rises.is_empty() && r.energy_events == 0 {
        failures.push(format!("{name}: energy rose with no event: {:?}", r.rises));
    }
}

/// Fails listing every broken promise.
fn verdict(failures: Vec<String>) {
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

fn solvers() -> [Solver; 2] {
    [Solver::DeepestFirst, Solver::SequentialImpulse]
}

/// The soft step's rows (1 m bodies, every upper on every lower, resting,
/// dropped from a metre and sliding at 2 m/s): a soft contact leaves
/// overlap by design (a spring of 30 Hz, its push-out capped at 3 m/s), so
/// the position epsilon is not its promise. Measured (the deepest overlap
/// left at a step's end, m): resting ≤ 2.3e-4 for every pair; dropped
/// 1.5e-3 to 2.2e-3 for a cylinder landing on a box, cylinder or hull,
/// 8.1e-3 for a hull on a hull, 0.086 for a hull on a box and 0.092 on a
/// cylinder (a hull's corner lands first); resting bodies move < 1 mm.
/// The bound held: overlap beyond the position epsilon ≤ 0.1 m, the centre
/// never below the floor, a resting body still. (At 1 mm the soft step
/// leaves 0.14–0.64 mm of overlap: its hertz is not scaled to the size.)
#[test]
fn every_shape_under_the_soft_step_rests_lands_and_slides_within_its_figures() {
    let mut failures = Vec::new();
    for (motion, steps, rest) in [
        (Motion::Resting, 360, true),
        (Motion::Dropped, 150, false),
        (Motion::Sliding, 90, false),
    ] {
        for up in UPPERS {
            for low in LOWERS {
                let name = format!("{up} on {low}, SoftStep, {motion:?}");
                let r = run(scene(up, low, 1.0, motion, Solver::SoftStep), steps);
                if rest && r.moved >= 1e-3 {
                    failures.push(format!("{name}: moved {:.3e} m at rest", r.moved));
                }
                if r.deepest_left > 0.1 {
                    failures.push(format!("{name}: {:.3e} m overlap left", r.deepest_left));
                }
                if r.lowest <= 0.0 {
                    failures.push(format!("{name}: centre down to {:.3e} m", r.lowest));
                }
            }
        }
    }
    verdict(failures);
}

#[test]
fn every_shape_rests_still_on_every_lower_body_under_both_solvers() {
    let mut failures = Vec::new();
    for up in UPPERS {
        for low in LOWERS {
            for solver in solvers() {
                let name = format!("{up} on {low}, {solver:?}, resting");
                let r = run(scene(up, low, 1.0, Motion::Resting, solver), 360);
                check(&name, &r, 1.0, true, &mut failures);
            }
        }
    }
    verdict(failures);
}

#[test]
fn every_shape_dropped_from_a_metre_lands_within_the_slop_under_both_solvers() {
    let mut failures = Vec::new();
    for up in UPPERS {
        for low in LOWERS {
            for solver in solvers() {
                let name = format!("{up} on {low}, {solver:?}, dropped");
                let r = run(scene(up, low, 1.0, Motion::Dropped, solver), 150);
                check(&name, &r, 1.0, false, &mut failures);
            }
        }
    }
    verdict(failures);
}

#[test]
fn every_shape_sliding_at_two_metres_a_second_stays_out_under_both_solvers() {
    let mut failures = Vec::new();
    for up in UPPERS {
        for low in LOWERS {
            for solver in solvers() {
                let name = format!("{up} on {low}, {solver:?}, sliding");
                let r = run(scene(up, low, 1.0, Motion::Sliding, solver), 90);
                check(&name, &r, 1.0, false, &mut failures);
            }
        }
    }
    verdict(failures);
}

#[test]
fn millimetre_and_kilometre_bodies_rest_as_metre_ones() {
    let mut failures = Vec::new();
    for l in [1e-3, 1e3] {
        for up in UPPERS {
            for low in ["half_space", "box"] {
                for solver in solvers() {
                    let name = format!("{l} m {up} on {low}, {solver:?}, resting");
                    let r = run(scene(up, low, l, Motion::Resting, solver), 360);
                    check(&name, &r, l, true, &mut failures);
                }
            }
        }
    }
    verdict(failures);
}

#[test]
fn a_buried_body_is_reported_once_for_its_pair_not_once_per_contact() {
    // Every shape started 2 sizes under a half-space's surface: wholly
    // inside at step 1, an event for the pair (a box has 8 contacts there,
    // a tetrahedron 4; each was its own event before).
    for up in UPPERS {
        let mut sim = scene(up, "half_space", 1.0, Motion::Resting, Solver::DeepestFirst);
        sim.world.bodies[0].state.position.y -= 2.0;
        let r = sim.advance().expect("no blow-up");
        let inside = r
            .events
            .iter()
            .filter(|e| matches!(e, Event::WhollyInside { .. }))
            .count();
        assert_eq!(inside, 1, "{up}: {:?}", r.events);
    }
}

#[test]
fn a_picometre_ball_on_a_terametre_ball_is_found_below_the_rounding_of_its_position() {
    // The ball can only be placed to within 1.2e-4 m of the big ball's
    // top, 1.2e8 of its radii (the run says so in a warning).
    let text = r#"id = "tiny-on-huge"
title = "A picometre ball on a terametre ball"
source = "issue 39"
summary = "Sizes 24 orders of magnitude apart."

[step]
dt = 0.016666666666666666
steps = 10

[[body]]
name = "tiny"
mass = 1.0
shape = { sphere = 1e-12 }
position = [0, 1e12, 0]

[[body]]
name = "huge"
mass = inf
shape = { sphere = 1e12 }
position = [0, 0, 0]
"#;
    let lesson = parse("shape_matrix.rs", text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let sim = Simulation::new(
        lesson.world::<f64>(),
        params,
        lesson.simulation.unwrap().materials,
    );
    let found = sim.below_rounding();
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0].body, 0);
    let ratio = found[0].rounding / found[0].size;
    assert!((ratio / 1.22e8 - 1.0).abs() < 0.01, "{ratio}");
    // A metre ball at 1 km is far above its rounding.
    let fine = text.replace("1e-12", "1").replace("1e12", "1000");
    let lesson = parse("shape_matrix.rs", &fine).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let sim = Simulation::new(
        lesson.world::<f64>(),
        params,
        lesson.simulation.unwrap().materials,
    );
    assert!(sim.below_rounding().is_empty());
}

#[test]
fn a_nanometre_tetrahedron_dropped_a_metre_says_how_long_each_burial_lasts() {
    // Gravity moves it 2.7 mm a step, 3 million of its sizes: it lands
    // buried and stays under the floor (with the matrix's restitution and
    // friction, in one burial to the end). Each burial (the pair wholly inside
    // at a step's contacts) is said when it starts and, when it lasted
    // over a step, when it ends with its length (it was said only at the
    // start: 162 of 200 steps under the floor and 13 events).
    let text = r#"id = "nm-tetrahedron"
title = "A 1 nm tetrahedron dropped 1 m"
source = "issue 39"
summary = "A hull a billionth of a metre across."

[step]
dt = 0.016666666666666666
steps = 200

[[body]]
name = "tetrahedron"
mass = 1.0
shape = { convex = [[0.5e-9, 0, 0], [-0.25e-9, 0, 0.4330127018922193e-9], [-0.25e-9, 0, -0.4330127018922193e-9], [0, 0.8e-9, 0]] }
position = [0, 1, 0]

[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#;
    let lesson = parse("shape_matrix.rs", text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    let (mut run, mut said) = (0u64, 0usize);
    for _ in 0..200 {
        // Wholly inside the floor at the poses this step's contacts are
        // found at: every corner at or below y = 0.
        let body = &sim.world.bodies[0];
        let Some(contact_lab::physics::Shape::Hull(hull)) = body.shape.as_ref() else {
            unreachable!("a hull")
        };
        let turn = body.state.rotation();
        let inside = (hull.vertices().iter()).all(|v| (body.state.position + turn * v).y <= 0.0);
        let r = sim.advance().expect("no blow-up");
        let started = (r.events.iter()).any(|e| matches!(e, Event::WhollyInside { .. }));
        let ended = r.events.iter().find_map(|e| match e {
            Event::WhollyInsideEnded { steps, .. } => Some(*steps),
            _ => None,
        });
        if inside {
            assert_eq!(started, run == 0, "step {}: {:?}", r.step, r.events);
            run += 1;
        } else {
            assert_eq!(ended, (run > 1).then_some(run), "step {}", r.step);
            said += usize::from(run > 1);
            run = 0;
        }
    }
    // (Five or more when the lecture's order kept a velocity epsilon of
    // u / 10 here; with the bound sequential impulses have, fewer burials
    // and longer ones.)
    assert!(said >= 1, "{said} burials said with their length");
    // It ends the run buried: the burial still going is said at the end
    // with its length (it had only its start event).
    assert!(run > 1, "buried at the end");
    let going = sim.burials_going();
    assert_eq!(going.len(), 1, "{going:?}");
    assert!(
        matches!(going[0], Event::StillWhollyInside { steps, .. } if steps == run),
        "{going:?}, {run} steps"
    );
}

#[test]
fn no_embedded_scene_is_split_into_substeps() {
    // The automatic substeps (split.rs) are for bodies smaller than
    // gravity's fall in a step: no embedded scene has one, so their runs
    // and snapshots are as before.
    for (file, text) in contact_lab::lesson::embedded::LESSONS {
        let Ok(lesson) = parse(file, text) else {
            continue;
        };
        let Some(params) = lesson.sim_params() else {
            continue;
        };
        let Some(run) = lesson.simulation.clone() else {
            continue;
        };
        let sim = Simulation::new(lesson.world::<f64>(), params, run.materials);
        assert_eq!(sim.split(), None, "{file}");
    }
}

#[test]
fn a_millimetre_box_is_split_and_rests_under_sequential_impulses() {
    let sim = scene(
        "box",
        "box",
        1e-3,
        Motion::Resting,
        Solver::SequentialImpulse,
    );
    let split = sim.split().expect("a 1 mm box is split");
    // g Δt² = 2.725 mm over a 0.5 mm half-width.
    assert_eq!((split.substeps, split.needed), (6, 6));
    let r = run(sim, 360);
    assert!(r.moved < 1e-6, "{}", r.moved);
}
