//! The search's own run of a configuration: only what advise reads (the
//! work, the final positions, the per-step error), none of the study's
//! other measures (they generate every step's contacts a second time), and
//! stopped early as soon as the run cannot be chosen: its work passes the
//! cap, or, against a per-step target, one step's error passes it. The
//! bodies move exactly as in `run::measure` (`run::simulation`, the same steps), so a
//! configuration's cost and error are the same either way
//! (tests/measure/advise_every_scene.rs pastes each choice and runs it
//! through `run::measure`).

use nalgebra::Vector3;

use crate::lesson::Lesson;
use crate::physics::step::Simulation;
use crate::physics::{to_f64, Real};
use crate::study::{run, Config, Precision};

/// What a search run found.
pub(super) struct Ran {
    pub steps: usize,
    /// Contact visits of both phases plus continuous detection's tests.
    pub work: usize,
    /// Stopped at the cap on work.
    pub capped: bool,
    /// Stopped because a step's error passed the per-step target.
    pub over: bool,
    pub failed: bool,
    pub positions: Vec<Vector3<f64>>,
    /// The largest per-step error so far (0 without a trajectory).
    pub step_error: f64,
}

/// Runs `config` for `seconds`, stopped once its work passes `cap` or (with
/// `stop_over`) once a step's error against `reference` passes it.
pub(super) fn run(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    cap: usize,
    reference: Option<&run::Trajectory>,
    stop_over: Option<f64>,
) -> Ran {
    match config.precision {
        Precision::F64 => run_in::<f64>(lesson, config, seconds, cap, reference, stop_over),
        Precision::F32 => run_in::<f32>(lesson, config, seconds, cap, reference, stop_over),
    }
}

fn run_in<T: Real>(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    cap: usize,
    reference: Option<&run::Trajectory>,
    stop_over: Option<f64>,
) -> Ran {
    let mut sim = run::simulation::<T>(lesson, config);
    let n = run::steps(seconds, config.params.dt);
    let movable: Vec<usize> = (0..sim.world.bodies.len())
        .filter(|&i| sim.world.bodies[i].movable)
        .collect();
    let positions = |sim: &Simulation<T>| -> Vec<Vector3<f64>> {
        movable
            .iter()
            .map(|&i| sim.world.bodies[i].state.position.map(to_f64))
            .collect()
    };
    let mut ran = Ran {
        steps: n,
        work: 0,
        capped: false,
        over: false,
        failed: false,
        positions: Vec::new(),
        step_error: 0.0,
    };
    for step in 0..n {
        if ran.work.saturating_add(step) > cap {
            ran.capped = true;
            ran.steps = step;
            return ran;
        }
        let report = match sim.advance() {
            Ok(r) => r,
            Err(_) => {
                ran.failed = true;
                break;
            }
        };
        ran.work += report.position_iterations + report.velocity_iterations + report.ccd_tests;
        if let Some(r) = reference {
            // The step's time as the reference counts it: (step + 1) × dt.
            let there = r.at((step + 1) as f64 * config.params.dt);
            let e = run::rms_distance(&positions(&sim), &there);
            ran.step_error = ran.step_error.max(e);
            // A position gone NaN passes any target.
            if stop_over.is_some_and(|t| e.is_nan() || ran.step_error > t) {
                ran.over = true;
                ran.steps = step + 1;
                return ran;
            }
        }
    }
    ran.positions = positions(&sim);
    if ran.failed
        || ran
            .positions
            .iter()
            .any(|p| !p.iter().all(|x| x.is_finite()))
    {
        ran.failed = true;
    }
    ran
}
