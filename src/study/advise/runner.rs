//! The search's own run of a configuration: only what advise reads (the
//! work, the final positions, the per-step error), none of the study's
//! other measures (they generate every step's contacts a second time), and
//! stopped early as soon as the run cannot be chosen: its work passes the
//! cap, or, against a per-step target, one step's error passes it. Against
//! the per-run target only the run's last tenth is compared with the
//! reference (`run::settle_from`), the settled error. The
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
    /// The largest per-step error so far, over the steps from the run's
    /// `from` (0 without a trajectory).
    pub step_error: f64,
    /// The largest over the run's last tenth (`run::settle_from`).
    pub settle_error: f64,
}

/// Which steps a run compares with the reference, and when it stops.
#[derive(Clone, Copy)]
pub(super) struct Against<'a> {
    pub reference: &'a run::Trajectory,
    /// Compare from this step on (0: every step; `run::settle_from`: the
    /// last tenth).
    pub from: usize,
    /// Stop at the first compared step whose error passes it.
    pub stop_over: Option<f64>,
}

/// Runs `config` for `seconds`, stopped once its work passes `cap` or (with
/// a `stop_over`) once a step's error against the reference passes it.
pub(super) fn run(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    cap: usize,
    against: Option<Against>,
) -> Ran {
    match config.precision {
        Precision::F64 => run_in::<f64>(lesson, config, seconds, cap, against),
        Precision::F32 => run_in::<f32>(lesson, config, seconds, cap, against),
    }
}

fn run_in<T: Real>(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    cap: usize,
    against: Option<Against>,
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
        settle_error: 0.0,
    };
    let settled = run::settle_from(n);
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
        if let Some(a) = against.filter(|a| step >= a.from) {
            // The step's time as the reference counts it: (step + 1) × dt.
            let there = a.reference.at((step + 1) as f64 * config.params.dt);
            let e = run::rms_distance(&positions(&sim), &there);
            ran.step_error = ran.step_error.max(e);
            if step >= settled {
                // (A position gone NaN fails the run: its error is NaN.)
                ran.settle_error = ran.settle_error.max(e);
            }
            // A position gone NaN passes any target.
            if a.stop_over
                .is_some_and(|t| e.is_nan() || ran.step_error > t)
            {
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
