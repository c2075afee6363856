//! The peer benchmark: the same scenes in rapier3d (its defaults, f32,
//! single-threaded) and in contact-lab (f64; deepest-first, sequential
//! impulses, sequential impulses with warm start), sleep off in both,
//! stepped in one process and interleaved: every round runs each engine
//! once per scene, and a scene's figure is the median of the rounds. Time is
//! the thread's CPU time (not wall time), per step, in µs; the load average
//! is printed before and after, because the machine may be shared.
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
const CONFIGS: [(&str, Solver, bool); 3] = [
    ("deepest-first", Solver::DeepestFirst, false),
    ("si", Solver::SequentialImpulse, false),
    ("si-warm", Solver::SequentialImpulse, true),
];

/// The contact-lab simulation of `scene` with `solver`, not yet warmed up.
fn contact_lab(scene: &Scene, solver: Solver, warm_start: bool) -> Simulation<f64> {
    let set = |r: &mut ResolverParams| {
        r.solver = solver;
        r.warm_start = warm_start;
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

/// One timed run of contact-lab: µs per step, and the highest body's height after.
fn run_contact_lab(scene: &Scene, solver: Solver, warm_start: bool) -> (f64, f64) {
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
    (us, top)
}

/// One timed run of rapier on the same scene: µs per step, highest body after.
fn run_rapier(scene: &Scene) -> (f64, f64) {
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
    (us, rapier_scene::top(&world))
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
        "| scene | rapier default | deepest-first | sequential impulses | + warm start | top body y (rapier / si-warm) |"
    );
    println!("|---|---|---|---|---|---|");
    for scene in scenes {
        let mut rapier = Vec::new();
        let mut ours: [Vec<f64>; 3] = Default::default();
        let mut tops = (0.0, 0.0);
        for _ in 0..runs {
            if wanted("rapier") {
                let (us, top) = run_rapier(scene);
                rapier.push(us);
                tops.0 = top;
            }
            for (i, (name, solver, warm)) in CONFIGS.iter().enumerate() {
                if wanted(name) {
                    let (us, top) = run_contact_lab(scene, *solver, *warm);
                    ours[i].push(us);
                    if i == 2 {
                        tops.1 = top;
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
            "| {} | {} | {} | {} | {} | {:.2} / {:.2} |",
            scene.id,
            r.map_or("—".into(), |r| format!("{r:.1}")),
            cell(&ours[0]),
            cell(&ours[1]),
            cell(&ours[2]),
            tops.0,
            tops.1
        );
    }
    println!("load average after: {}", load_average());
}
