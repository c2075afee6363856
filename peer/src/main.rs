//! The peer benchmark: the same scenes in rapier3d (its defaults, f32,
//! single-threaded) and in contact-lab (f64; deepest-first, sequential
//! impulses, sequential impulses with warm start, the soft step with its
//! defaults: 4 substeps, 30 Hz, ζ 10, one relax sweep), sleep off in both,
//! stepped in one process and interleaved: every round runs each engine
//! once per scene, and a scene's figure is the median of the rounds. Time is
//! the thread's CPU time (not wall time), per step, in µs; the load average
//! is printed before and after, because the machine may be shared.
//!
//! The error against the scene's reference: the scene's start is its
//! reference (a stack built at rest, a pile laid out on a grid), and the
//! error is the largest distance any body moved from it by the end of the
//! timed steps (mm), with the highest body's height beside it.
//!
//! `cargo run --release` here (never built by the main crate's tests).
//! `-- --scene stack-5 --config si-warm --runs 1` runs one cell only (for
//! `valgrind --tool=callgrind`).

#[allow(dead_code)]
#[path = "../../benches/common/scenes.rs"]
mod scenes;

mod rapier_scene;

use contact_lab::physics::step::Simulation;
use contact_lab::physics::{ResolverParams, Solver};

/// A scene: how it is built, how many steps warm it up (not timed) and how
/// many are timed.
struct Scene {
    id: &'static str,
    warm: usize,
    timed: usize,
}

const SCENES: [Scene; 5] = [
    Scene {
        id: "stack-5",
        warm: 60,
        timed: 300,
    },
    Scene {
        id: "resting-box",
        warm: 60,
        timed: 300,
    },
    Scene {
        id: "sphere-row-20",
        warm: 0,
        timed: 60,
    },
    Scene {
        id: "pile-200",
        warm: 30,
        timed: 30,
    },
    Scene {
        id: "pile-1000",
        warm: 30,
        timed: 20,
    },
];

/// contact-lab's configurations, as a new user would pick them.
const CONFIGS: [(&str, Solver, bool); 4] = [
    ("deepest-first", Solver::DeepestFirst, false),
    ("si", Solver::SequentialImpulse, false),
    ("si-warm", Solver::SequentialImpulse, true),
    // The soft step warm-starts always (Box2D v3's order); its knobs at
    // their defaults.
    ("soft-step", Solver::SoftStep, false),
];

/// The largest distance (m) between a movable body's position in `now` and
/// in `start` (the same bodies in the same order).
fn drift(start: &[nalgebra::Vector3<f64>], now: &[nalgebra::Vector3<f64>]) -> f64 {
    start
        .iter()
        .zip(now)
        .map(|(a, b)| (a - b).norm())
        .fold(0.0, f64::max)
}

/// The movable bodies' positions (the ones with a shape, as rapier gets them).
fn positions(sim: &Simulation<f64>) -> Vec<nalgebra::Vector3<f64>> {
    sim.world
        .bodies
        .iter()
        .filter(|b| b.movable && b.shape.is_some())
        .map(|b| b.state.position)
        .collect()
}

/// The scene's reference: its bodies' positions as built, before any step
/// (the pile's builder steps 30 times; its grid is rebuilt here).
fn reference(scene: &Scene) -> Vec<nalgebra::Vector3<f64>> {
    match scene.id.strip_prefix("pile-") {
        Some(n) => {
            let n: usize = n.parse().unwrap();
            let side = (n as f64).sqrt().ceil() as usize / 2 + 1;
            (0..n)
                .map(|i| {
                    let layer = i / (side * side);
                    let (x, z) = ((i % side) as f64, ((i / side) % side) as f64);
                    nalgebra::Vector3::new(x * 1.001, 0.5 + layer as f64 * 1.001, z * 1.001)
                })
                .collect()
        }
        None => positions(&contact_lab(scene, Solver::DeepestFirst, false)),
    }
}

/// The contact-lab simulation of `scene` with `solver`, not yet warmed up.
fn contact_lab(scene: &Scene, solver: Solver, warm_start: bool) -> Simulation<f64> {
    // `PEER_SOFT=SUBSTEPS,RELAX` sets the soft step's substeps and relax
    // sweeps (to split its time into a fixed part and a part per sweep).
    let soft: Option<(usize, usize)> = std::env::var("PEER_SOFT").ok().map(|v| {
        let (s, r) = v.split_once(',').expect("PEER_SOFT=SUBSTEPS,RELAX");
        (s.parse().unwrap(), r.parse().unwrap())
    });
    let set = |r: &mut ResolverParams| {
        r.solver = solver;
        r.warm_start = warm_start;
        if let (Solver::SoftStep, Some((substeps, relax))) = (solver, soft) {
            r.substeps = substeps;
            r.soft.relax_iterations = relax;
        }
    };
    match scene.id.strip_prefix("pile-") {
        Some(n) => scenes::pile(n.parse().unwrap(), set),
        None => scenes::scene(scene.id, 0, set),
    }
}

/// CPU time of this thread, seconds.
fn cpu_seconds() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes into the timespec we own.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

/// One timed run of contact-lab: µs per step, the highest body's height
/// after, and the largest drift from the reference (m).
fn run_contact_lab(scene: &Scene, solver: Solver, warm_start: bool) -> (f64, f64, f64) {
    let mut sim = contact_lab(scene, solver, warm_start);
    // The pile is warmed up by its builder; the others here.
    if !scene.id.starts_with("pile-") {
        for _ in 0..scene.warm {
            sim.advance().unwrap();
        }
    }
    let t = cpu_seconds();
    for _ in 0..scene.timed {
        sim.advance().unwrap();
    }
    let us = (cpu_seconds() - t) * 1e6 / scene.timed as f64;
    let top = sim
        .world
        .bodies
        .iter()
        .filter(|b| b.movable)
        .map(|b| b.state.position.y)
        .fold(f64::MIN, f64::max);
    (us, top, drift(&reference(scene), &positions(&sim)))
}

/// One timed run of rapier on the same scene: µs per step, highest body
/// after, largest drift from the reference (m).
fn run_rapier(scene: &Scene) -> (f64, f64, f64) {
    // The same start: contact-lab's scene before its warm-up.
    let start = contact_lab(scene, Solver::DeepestFirst, false);
    // The pile comes warmed up by contact-lab (30 steps); rapier warms up
    // from there by as many steps of its own, so that its broad phase, its
    // contact graph and its warm-start impulses are built before timing.
    let warm = if scene.id.starts_with("pile-") {
        30
    } else {
        scene.warm
    };
    let mut world = rapier_scene::from(&start);
    for _ in 0..warm {
        world.step();
    }
    let t = cpu_seconds();
    for _ in 0..scene.timed {
        world.step();
    }
    let us = (cpu_seconds() - t) * 1e6 / scene.timed as f64;
    let now = rapier_scene::positions(&world);
    (
        us,
        rapier_scene::top(&world),
        drift(&reference(scene), &now),
    )
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let arg = |name: &str| {
        args.iter()
            .position(|a| a == name)
            .and_then(|i| args.get(i + 1).cloned())
    };
    let runs: usize = arg("--runs").map_or(7, |r| r.parse().expect("--runs N"));
    let only_scene = arg("--scene");
    let only_config = arg("--config");
    let scenes: Vec<&Scene> = SCENES
        .iter()
        .filter(|s| only_scene.as_deref().is_none_or(|o| o == s.id))
        .collect();
    let wanted = |name: &str| only_config.as_deref().is_none_or(|o| o == name);
    println!("load average before: {}", load_average());
    println!(
        "CPU µs per step, median of {runs} interleaved runs (ratio to rapier); sleep off, one thread"
    );
    println!(
        "| scene | rapier default | deepest-first | sequential impulses | + warm start | soft step | top body y (rapier / si-warm / soft) | largest drift from the start, mm (rapier / si-warm / soft) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for scene in scenes {
        let mut rapier = Vec::new();
        let mut ours: [Vec<f64>; 4] = Default::default();
        let mut tops = [f64::NAN; 3];
        let mut drifts = [f64::NAN; 3];
        for _ in 0..runs {
            if wanted("rapier") {
                let (us, top, d) = run_rapier(scene);
                rapier.push(us);
                tops[0] = top;
                drifts[0] = d;
            }
            for (i, (name, solver, warm)) in CONFIGS.iter().enumerate() {
                if wanted(name) {
                    let (us, top, d) = run_contact_lab(scene, *solver, *warm);
                    ours[i].push(us);
                    if i >= 2 {
                        tops[i - 1] = top;
                        drifts[i - 1] = d;
                    }
                }
            }
        }
        let r = (!rapier.is_empty()).then(|| median(rapier));
        let cell = |v: &Vec<f64>| match (v.is_empty(), r) {
            (true, _) => "—".to_string(),
            (false, Some(r)) => {
                let m = median(v.clone());
                format!("{m:.1} ({:.2}×)", m / r)
            }
            (false, None) => format!("{:.1}", median(v.clone())),
        };
        println!(
            "| {} | {} | {} | {} | {} | {} | {:.3} / {:.3} / {:.3} | {:.2} / {:.2} / {:.2} |",
            scene.id,
            r.map_or("—".into(), |r| format!("{r:.1}")),
            cell(&ours[0]),
            cell(&ours[1]),
            cell(&ours[2]),
            cell(&ours[3]),
            tops[0],
            tops[1],
            tops[2],
            drifts[0] * 1e3,
            drifts[1] * 1e3,
            drifts[2] * 1e3
        );
    }
    println!("load average after: {}", load_average());
}
