//! One cell of the verdict matrix run: a scene under one solver column,
//! stepped with what each criterion reads recorded after every step (the
//! movable bodies' positions, velocities and spins, the total energy and,
//! where a criterion asks, the deepest overlap).

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::Vector3;

use crate::lesson::Lesson;
use crate::physics::collide::{BodyContact, ContactGenerator, Options};
use crate::physics::step::energy;
use crate::study::run::simulation;
use crate::study::Config;

/// The movable bodies after one step.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub positions: Vec<Vector3<f64>>,
    pub velocities: Vec<Vector3<f64>>,
    pub spins: Vec<Vector3<f64>>,
    /// Kinetic + potential energy (J).
    pub energy: f64,
    /// The deepest overlap (no margin), m; 0 when not recorded.
    pub penetration: f64,
}

/// A run: the start (frame 0) and every step after it.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub dt: f64,
    pub frames: Vec<Frame>,
    /// Gravity (m/s²).
    pub gravity: Vector3<f64>,
    /// Why the run stopped early (it blew up, or a position is not finite).
    pub failure: Option<String>,
}

impl Record {
    pub fn first(&self) -> &Frame {
        &self.frames[0]
    }

    pub fn last(&self) -> &Frame {
        &self.frames[self.frames.len() - 1]
    }

    /// The time of frame `k` (s).
    pub fn time(&self, k: usize) -> f64 {
        k as f64 * self.dt
    }
}

/// Runs `lesson` under `config` for `steps` steps, recording every frame
/// (the overlap too when `penetration`). `None` when `stop` was set
/// (Ctrl-C) before the run ended.
pub fn run(
    lesson: &Lesson,
    config: &Config,
    steps: usize,
    penetration: bool,
    stop: &AtomicBool,
) -> Option<Record> {
    let mut sim = simulation::<f64>(lesson, config);
    let gravity = sim.params.world.gravity;
    let movable: Vec<usize> = (0..sim.world.bodies.len())
        .filter(|&i| sim.world.bodies[i].movable)
        .collect();
    let mut generator = ContactGenerator::<f64>::new();
    let mut generated: Vec<BodyContact<f64>> = Vec::new();
    let options = Options {
        box_box: sim.params.box_box,
        tolerance: 0.0,
        narrow_phase: sim.params.narrow_phase,
        broad_phase: sim.params.broad_phase,
        internal_edges: sim.params.internal_edges,
    };
    let mut frame = |sim: &crate::physics::step::Simulation<f64>| {
        let state = |i: &usize| &sim.world.bodies[*i].state;
        let deepest = if penetration {
            generator.generate_world(&sim.world.bodies, &options, &mut generated);
            generated
                .iter()
                .map(|k| k.contact.penetration)
                .fold(0.0, f64::max)
        } else {
            0.0
        };
        Frame {
            positions: movable.iter().map(|i| state(i).position).collect(),
            velocities: movable.iter().map(|i| state(i).velocity).collect(),
            spins: movable.iter().map(|i| state(i).angular_velocity).collect(),
            energy: energy::total(&sim.world, &gravity),
            penetration: deepest,
        }
    };
    let mut frames = Vec::with_capacity(steps + 1);
    frames.push(frame(&sim));
    let mut failure = None;
    for _ in 0..steps {
        if stop.load(Ordering::SeqCst) {
            return None;
        }
        match sim.advance() {
            Ok(_) => {
                let f = frame(&sim);
                if f.positions.iter().any(|p| !p.iter().all(|x| x.is_finite())) {
                    failure = Some("a position is not finite".to_string());
                    break;
                }
                frames.push(f);
            }
            Err(e) => {
                failure = Some(crate::trace::blow_up::plain(&e));
                break;
            }
        }
    }
    Some(Record {
        dt: config.params.dt,
        frames,
        gravity,
        failure,
    })
}
