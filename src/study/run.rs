//! Runs one configuration of a scene and measures it: a measuring run (the
//! metrics, deterministic) and, unless timing is off, timed runs of the bare
//! step loop (nothing measured inside them).
//!
//! What is measured, per step of the measuring run:
//! - penetration left: the deepest overlap of the bodies after the step
//!   (contacts generated again from the shapes, no margin);
//! - closing velocity left: the fastest closing normal velocity, after the
//!   step, at the contacts the step resolved;
//! - energy gained: the largest rise of kinetic + potential energy above the
//!   start (J);
//! - drift: how far the top body (highest against gravity at the start, the
//!   last in file order on ties) has moved across gravity by the end (with no
//!   gravity: how far it moved);
//! - missed collisions: the run's `tunnelled` events (pairs that crossed
//!   inside a step without a contact);
//! - the final positions, for the error against the reference (RMS over the
//!   movable bodies of the distance to the reference's final positions, m);
//! - given the reference's [`Trajectory`], the per-step error: the largest,
//!   over the run's steps, of the RMS distance to the reference at the same
//!   time (the reference linearly interpolated between its steps), and the
//!   settled error: the same, largest over the run's last tenth
//!   ([`settle_from`]), what advise's per-run target bounds.

use std::time::Instant;

use nalgebra::Vector3;

use super::{Config, Precision};
use crate::lesson::Lesson;
use crate::physics::collide::{BodyContact, ContactGenerator, Options};
use crate::physics::step::{energy, SimParams, Simulation};
use crate::physics::{to_f64, Real};

/// What the measuring run found.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    pub steps: usize,
    pub visits_per_step: f64,
    /// Continuous detection's GJK calls per step, mean over the run.
    pub ccd_tests_per_step: f64,
    pub limit_steps: usize,
    pub max_penetration: f64,
    pub max_closing_velocity: f64,
    pub energy_gain: f64,
    pub drift: f64,
    /// Tunnelled events: pairs that crossed inside a step without a contact.
    pub missed_collisions: usize,
    /// Final position of each movable body.
    pub positions: Vec<Vector3<f64>>,
    pub failure: Option<String>,
    /// Stopped early: the work (visits + steps) passed the cap it was given.
    pub capped: bool,
    /// Max over steps of the RMS distance to the reference's trajectory at
    /// the same time, m (0 when no trajectory was given).
    pub step_error: f64,
    /// Max of the same over the run's last tenth of steps (from
    /// [`settle_from`]), m (0 when no trajectory was given).
    pub settle_error: f64,
}

/// A run's movable bodies' positions after every step (index 0: the start),
/// for the per-step error against it.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    pub dt: f64,
    pub positions: Vec<Vec<Vector3<f64>>>,
}

impl Trajectory {
    /// The positions at time `t`: linear between the two steps around it
    /// (the last step's beyond the end).
    pub fn at(&self, t: f64) -> Vec<Vector3<f64>> {
        let last = self.positions.len().saturating_sub(1);
        let x = (t / self.dt).max(0.0);
        let i = (x.floor() as usize).min(last);
        let j = (i + 1).min(last);
        let s = (x - i as f64).clamp(0.0, 1.0);
        // A time within round-off of a step takes that step.
        if s < 1e-9 || i == j {
            return self.positions[i].clone();
        }
        if s > 1.0 - 1e-9 {
            return self.positions[j].clone();
        }
        self.positions[i]
            .iter()
            .zip(&self.positions[j])
            .map(|(a, b)| a + (b - a) * s)
            .collect()
    }
}

/// The trajectory of `config` over `seconds` (f64).
pub fn trajectory(lesson: &Lesson, config: &Config, seconds: f64) -> Trajectory {
    let mut sim = simulation::<f64>(lesson, config);
    let movable: Vec<usize> = (0..sim.world.bodies.len())
        .filter(|&i| sim.world.bodies[i].movable)
        .collect();
    let at = |sim: &Simulation<f64>| -> Vec<Vector3<f64>> {
        movable
            .iter()
            .map(|&i| sim.world.bodies[i].state.position)
            .collect()
    };
    let mut positions = vec![at(&sim)];
    for _ in 0..steps(seconds, config.params.dt) {
        if sim.advance().is_err() {
            break;
        }
        positions.push(at(&sim));
    }
    Trajectory {
        dt: config.params.dt,
        positions,
    }
}

/// The first step (0-based, the step's end at (step + 1) × dt) of a run of
/// `n` steps whose error counts as settled: the run's last tenth, at least
/// its last step. A state the run only passes through (a bouncing ball at
/// the floor, a wobbling stack within reach of the reference's) at its
/// end does not stay within a target over a tenth of the run (docs/study.md).
pub fn settle_from(n: usize) -> usize {
    n - n.div_ceil(10).max(1).min(n)
}

/// The number of steps `seconds` takes at `dt`.
pub fn steps(seconds: f64, dt: f64) -> usize {
    ((seconds / dt).round() as usize).max(1)
}

/// The run's parameters (f64): the configuration's knobs, its budget as
/// visits per contact.
pub fn params(config: &Config) -> SimParams<f64> {
    let mut p = config.params;
    p.resolver.visits_per_contact = config.budget.per_contact();
    p.resolver.position_iterations = None;
    p.resolver.velocity_iterations = None;
    p
}

/// The same parameters in another float type.
fn cast<T: Real>(p: &SimParams<f64>) -> SimParams<T> {
    // Through the knobs: every knob of the run, in float type `T`.
    crate::physics::Settings::of_run(p).sim_params()
}

/// The simulation a configuration runs (advise's runner starts from it too).
pub(crate) fn simulation<T: Real>(lesson: &Lesson, config: &Config) -> Simulation<T> {
    let p = cast::<T>(&params(config));
    let mut world = lesson.world::<T>();
    world.contacts.clear();
    let materials = lesson
        .simulation
        .as_ref()
        .map(|s| s.materials.clone())
        .unwrap_or_default();
    Simulation::new(world, p, materials)
}

/// Runs `config` for `seconds` and measures it.
pub fn measure(lesson: &Lesson, config: &Config, seconds: f64) -> Measured {
    match config.precision {
        Precision::F64 => measure_in::<f64>(lesson, config, seconds, usize::MAX, None, &mut |_| {}),
        Precision::F32 => measure_in::<f32>(lesson, config, seconds, usize::MAX, None, &mut |_| {}),
    }
}

/// As [`measure`], stopped as soon as the work (contact visits + steps)
/// passes `cap`: then `capped` is set and the numbers are partial.
pub fn measure_capped(lesson: &Lesson, config: &Config, seconds: f64, cap: usize) -> Measured {
    measure_against(lesson, config, seconds, cap, None)
}

/// As [`measure_capped`], with the per-step error against `reference` when given.
pub fn measure_against(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    cap: usize,
    reference: Option<&Trajectory>,
) -> Measured {
    match config.precision {
        Precision::F64 => measure_in::<f64>(lesson, config, seconds, cap, reference, &mut |_| {}),
        Precision::F32 => measure_in::<f32>(lesson, config, seconds, cap, reference, &mut |_| {}),
    }
}

/// As [`measure`], in f64 whatever the configuration says, with
/// `after_step` shown the simulation after every step (what a run
/// exercised is read from it).
pub fn measure_watched(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    after_step: &mut dyn FnMut(&Simulation<f64>),
) -> Measured {
    measure_in::<f64>(lesson, config, seconds, usize::MAX, None, after_step)
}

fn measure_in<T: Real>(
    lesson: &Lesson,
    config: &Config,
    seconds: f64,
    cap: usize,
    reference: Option<&Trajectory>,
    after_step: &mut dyn FnMut(&Simulation<T>),
) -> Measured {
    let mut sim = simulation::<T>(lesson, config);
    let n = steps(seconds, config.params.dt);
    let g = sim.params.world.gravity.map(to_f64);
    let up = if g.norm() > 0.0 {
        -g / g.norm()
    } else {
        Vector3::zeros()
    };
    let position = |sim: &Simulation<T>, i: usize| sim.world.bodies[i].state.position.map(to_f64);
    let movable: Vec<usize> = (0..sim.world.bodies.len())
        .filter(|&i| sim.world.bodies[i].movable)
        .collect();
    let top = movable
        .iter()
        .copied()
        .max_by(|a, b| {
            position(&sim, *a)
                .dot(&up)
                .total_cmp(&position(&sim, *b).dot(&up))
        })
        .unwrap_or(0);
    let start = position(&sim, top);
    let energy0 = to_f64(energy::total(&sim.world, &sim.params.world.gravity));
    let mut generator = ContactGenerator::<T>::new();
    let mut generated: Vec<BodyContact<T>> = Vec::new();
    let options = Options {
        box_box: sim.params.box_box,
        tolerance: T::zero(),
        narrow_phase: sim.params.narrow_phase,
        broad_phase: sim.params.broad_phase,
        internal_edges: sim.params.internal_edges,
    };
    let mut m = Measured {
        steps: n,
        visits_per_step: 0.0,
        ccd_tests_per_step: 0.0,
        limit_steps: 0,
        max_penetration: 0.0,
        max_closing_velocity: 0.0,
        energy_gain: 0.0,
        drift: 0.0,
        missed_collisions: 0,
        positions: Vec::new(),
        failure: None,
        capped: false,
        step_error: 0.0,
        settle_error: 0.0,
    };
    let settled = settle_from(n);
    // Work so far (contact visits and continuous detection's tests, for
    // the cap) and continuous detection's share of it.
    let mut visits = 0usize;
    let mut ccd_tests = 0usize;
    for step in 0..n {
        if visits.saturating_add(step) > cap {
            m.capped = true;
            m.steps = step;
            break;
        }
        let report = match sim.advance() {
            Ok(r) => r,
            Err(e) => {
                m.failure = Some(crate::trace::blow_up::plain(&e));
                break;
            }
        };
        after_step(&sim);
        m.missed_collisions += report
            .events
            .iter()
            .filter(|e| matches!(e, crate::physics::step::Event::Tunnelled { .. }))
            .count();
        visits += report.position_iterations + report.velocity_iterations + report.ccd_tests;
        ccd_tests += report.ccd_tests;
        // A phase that used its whole budget (it may have just made it).
        let limit = config.budget.per_contact() * report.contacts;
        if report.contacts > 0
            && (report.position_iterations >= limit || report.velocity_iterations >= limit)
        {
            m.limit_steps += 1;
        }
        generator.generate_world(&sim.world.bodies, &options, &mut generated);
        for k in &generated {
            m.max_penetration = m.max_penetration.max(to_f64(k.contact.penetration));
        }
        for k in &sim.world.contacts {
            let v = |id: Option<crate::physics::BodyId>| {
                id.map_or(Vector3::zeros(), |id| {
                    let b = &sim.world.body(id).state;
                    b.point_velocity(&(k.input.point - b.position))
                })
            };
            let vn = to_f64((v(Some(k.body1)) - v(k.body2)).dot(&k.input.normal));
            m.max_closing_velocity = m.max_closing_velocity.max(-vn);
        }
        let e = to_f64(energy::total(&sim.world, &sim.params.world.gravity));
        m.energy_gain = m.energy_gain.max(e - energy0);
        if let Some(r) = reference {
            // The step's time as the reference counts it: (step + 1) × dt.
            let here: Vec<Vector3<f64>> = movable.iter().map(|&i| position(&sim, i)).collect();
            let there = r.at((step + 1) as f64 * config.params.dt);
            let e = rms_distance(&here, &there);
            m.step_error = m.step_error.max(e);
            if step >= settled {
                m.settle_error = m.settle_error.max(e);
            }
        }
    }
    m.visits_per_step = (visits - ccd_tests) as f64 / n as f64;
    m.ccd_tests_per_step = ccd_tests as f64 / n as f64;
    let moved = position(&sim, top) - start;
    m.drift = (moved - up * moved.dot(&up)).norm();
    m.positions = movable.iter().map(|&i| position(&sim, i)).collect();
    if m.failure.is_some() || m.positions.iter().any(|p| !p.iter().all(|x| x.is_finite())) {
        m.failure
            .get_or_insert_with(|| "a position is not finite".into());
        for x in [
            &mut m.step_error,
            &mut m.settle_error,
            &mut m.max_penetration,
            &mut m.max_closing_velocity,
            &mut m.energy_gain,
            &mut m.drift,
        ] {
            *x = f64::NAN;
        }
    }
    m
}

/// µs per step of `repeats` timed runs of the bare step loop.
pub fn time(lesson: &Lesson, config: &Config, seconds: f64, repeats: usize) -> Vec<f64> {
    (0..repeats)
        .map(|_| match config.precision {
            Precision::F64 => time_in::<f64>(lesson, config, seconds),
            Precision::F32 => time_in::<f32>(lesson, config, seconds),
        })
        .collect()
}

fn time_in<T: Real>(lesson: &Lesson, config: &Config, seconds: f64) -> f64 {
    let mut sim = simulation::<T>(lesson, config);
    let n = steps(seconds, config.params.dt);
    let t0 = Instant::now();
    for _ in 0..n {
        if sim.advance().is_err() {
            break;
        }
    }
    t0.elapsed().as_secs_f64() * 1e6 / n as f64
}

/// RMS over bodies of the distance between two sets of final positions.
pub fn rms_distance(a: &[Vector3<f64>], b: &[Vector3<f64>]) -> f64 {
    if a.is_empty() || a.len() != b.len() {
        return f64::NAN;
    }
    let sum: f64 = a.iter().zip(b).map(|(p, q)| (p - q).norm_squared()).sum();
    (sum / a.len() as f64).sqrt()
}

/// Median, min and max.
pub fn spread(samples: &[f64]) -> Option<[f64; 3]> {
    let mut s: Vec<f64> = samples.iter().copied().filter(|x| x.is_finite()).collect();
    if s.is_empty() {
        return None;
    }
    s.sort_by(f64::total_cmp);
    let n = s.len();
    let median = if n % 2 == 1 {
        s[n / 2]
    } else {
        0.5 * (s[n / 2 - 1] + s[n / 2])
    };
    Some([median, s[0], s[n - 1]])
}
