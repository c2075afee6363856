//! A scene played step by step for the TUI: every frame computed so far is
//! kept (stepping back is instant), with a copy of the simulation every
//! [`CHECKPOINT`] steps so that any step's resolution can be recorded again
//! on request — the fast path records nothing. [`edit`] changes the run's
//! input at a step and computes it again from there.

mod edit;
pub use edit::SceneEdit;

use super::resolver::Names;
use super::run::RunTrace;
use super::step::{record_next, StepTrace};
use crate::lesson::Lesson;
use crate::physics::step::{BlowUp, Simulation};

/// Steps between two kept copies of the simulation.
pub const CHECKPOINT: u64 = 8;

#[derive(Debug, Clone)]
pub struct Player {
    /// Frame `n` is the state after step `n` (frame 0: before the first).
    pub run: RunTrace,
    /// The steps the scene runs (its `[step] steps`).
    pub steps: u64,
    names: Names,
    sim: Simulation<f64>,
    /// Copies of the simulation after the step they are paired with (every
    /// `CHECKPOINT`th, and where an edit changed it), in step order.
    checkpoints: Vec<(u64, Simulation<f64>)>,
}

impl Player {
    /// The scene's player at step 0; `None` for a lesson without time settings.
    pub fn new(lesson: &Lesson) -> Option<Player> {
        let scene = lesson.simulation.as_ref()?;
        let params = lesson.sim_params()?;
        let mut world = lesson.world::<f64>();
        world.contacts.clear();
        let sim = Simulation::new(world, params, scene.materials.clone());
        let names = Names::of_lesson(lesson);
        let mut run = RunTrace::new(&lesson.id, &lesson.title, names.bodies.clone(), &sim);
        run.frames.push(RunTrace::initial(&sim));
        Some(Player {
            run,
            steps: scene.steps.max(1),
            names,
            checkpoints: vec![(0, sim.clone())],
            sim,
        })
    }

    /// The last step computed.
    pub fn computed(&self) -> u64 {
        self.run.frames.len() as u64 - 1
    }

    /// Computes one more step; false at the scene's end or once it blew up.
    pub fn advance(&mut self) -> bool {
        if self.run.stopped.is_some() || self.computed() >= self.steps {
            return false;
        }
        match self.sim.advance() {
            Ok(report) => {
                self.run.add_events(&report);
                self.run.frames.push(RunTrace::frame(&self.sim, &report));
                if self.sim.step.is_multiple_of(CHECKPOINT) {
                    self.checkpoints.push((self.sim.step, self.sim.clone()));
                }
                true
            }
            Err(e) => {
                self.run.stopped = Some(blew_up(&self.names, &e));
                false
            }
        }
    }

    /// Computes steps until `step` is computed (or the run ends); whether it is.
    pub fn reach(&mut self, step: u64) -> bool {
        while self.computed() < step {
            if !self.advance() {
                return false;
            }
        }
        true
    }

    /// The resolution of step `step` (1 … computed), recorded again from the
    /// nearest copy before it.
    pub fn record(&self, step: u64) -> Option<StepTrace> {
        if step == 0 || step > self.computed() {
            return None;
        }
        let mut sim = self.state_after(step - 1)?;
        record_next(&mut sim, &self.names).ok()
    }

    /// The simulation after step `step` (≤ computed), from the nearest copy before it.
    fn state_after(&self, step: u64) -> Option<Simulation<f64>> {
        let (_, from) = self.checkpoints.iter().rev().find(|(s, _)| *s <= step)?;
        let mut sim = from.clone();
        while sim.step < step {
            sim.advance().ok()?;
        }
        Some(sim)
    }
}

/// The reason a run stopped, in words.
pub fn blew_up(names: &Names, e: &BlowUp) -> String {
    let name = |body: usize| names.bodies.get(body).map_or("?", String::as_str);
    match e {
        BlowUp::NonFinite { body, .. } | BlowUp::Energy { body, .. } => {
            format!("the scene blew up: {e} (body '{}')", name(*body))
        }
        BlowUp::Surge {
            step,
            before,
            after,
            bound,
            bodies,
        } => {
            let f = crate::format::Fmt::new(3);
            let list: Vec<String> = bodies
                .iter()
                .map(|(b, v0, v1)| format!("'{}' {} → {} m/s", name(*b), f.num(*v0), f.num(*v1)))
                .collect();
            format!(
                "the scene blew up: step {step}: the kinetic energy rose from {} J to {} J in one step, over {} times the {} J that the bodies' speeds and one step of gravity account for; the bodies that sped up most: {}",
                f.num(*before),
                f.num(*after),
                crate::physics::step::report::SURGE_FACTOR,
                f.num(*bound),
                list.join(", ")
            )
        }
    }
}
