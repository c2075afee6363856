//! A scene played step by step for the TUI: every frame computed so far is
//! kept (stepping back is instant), with a copy of the simulation every
//! [`CHECKPOINT`] steps so that any step's resolution can be recorded again
//! on request — the fast path records nothing. [`edit`] changes the run's
//! input at a step and computes it again from there.

mod background;
mod detect;
mod edit;
pub use background::{Detecting, Job, Recording};
pub use detect::{detect_trace, detect_trace_watched, toi_picture, toi_trace, PairToiRun};
pub use edit::SceneEdit;

use crate::lesson::Lesson;
use crate::physics::step::{BlowUp, Simulation, StepReport};
use crate::trace::resolver::Names;
use crate::trace::run::RunTrace;
use crate::trace::step::{record_next, StepTrace};
use std::sync::atomic::Ordering;
use std::sync::{Arc, Mutex};

/// Steps between two kept copies of the simulation.
pub const CHECKPOINT: u64 = 8;

/// A scene this large computes its steps on another thread (the TUI's keys
/// keep answering while a step takes seconds): this many movable bodies, or
/// this many contacts at the last step.
pub const BACKGROUND_BODIES: usize = 100;
pub const BACKGROUND_CONTACTS: usize = 2_000;

/// What [`Player::poll`] found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Poll {
    /// The next step is computed (true), or the run has ended (false).
    Ready(bool),
    /// The next step is being computed on another thread.
    Busy,
}

/// The outcome of a step computed on another thread, when it is done.
type Slot = Arc<Mutex<Option<(Simulation<f64>, Result<StepReport, BlowUp>)>>>;

/// A step being computed on another thread (clones share it).
#[derive(Clone)]
struct Background {
    step: u64,
    slot: Slot,
}

impl std::fmt::Debug for Background {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Background {{ step: {} }}", self.step)
    }
}

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
    /// The next step, when a large scene computes it on another thread.
    background: Option<Background>,
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
            background: None,
        })
    }

    /// The last step computed.
    pub fn computed(&self) -> u64 {
        self.run.frames.len() as u64 - 1
    }

    /// Computes one more step; false at the scene's end or once it blew up.
    /// (A step being computed on another thread is dropped: this one is
    /// computed here, from the last step kept.)
    pub fn advance(&mut self) -> bool {
        self.background = None;
        if self.ended() {
            return false;
        }
        let result = self.sim.advance();
        self.accept(result)
    }

    /// The run has stopped or reached the scene's last step.
    fn ended(&self) -> bool {
        self.run.stopped.is_some() || self.computed() >= self.steps
    }

    /// Whether the next steps go to another thread: a large scene.
    fn heavy(&self) -> bool {
        let movable = self.sim.world.bodies.iter().filter(|b| b.movable).count();
        movable >= BACKGROUND_BODIES || self.sim.world.contacts.len() >= BACKGROUND_CONTACTS
    }

    /// The step being computed on another thread, if one is.
    pub fn computing(&self) -> Option<u64> {
        self.background.as_ref().map(|b| b.step)
    }

    /// One more step without blocking on a large scene: a small scene's step
    /// is computed at once; a large scene's on another thread, `Busy` until
    /// it is done (call again to collect it).
    pub fn poll(&mut self) -> Poll {
        if let Some(bg) = &self.background {
            let done = bg.slot.lock().map(|mut s| s.take()).unwrap_or(None);
            let Some((sim, result)) = done else {
                return Poll::Busy;
            };
            self.background = None;
            self.sim = sim;
            return Poll::Ready(self.accept(result));
        }
        if self.ended() {
            return Poll::Ready(false);
        }
        if !self.heavy() {
            return Poll::Ready(self.advance());
        }
        let slot: Slot = Arc::new(Mutex::new(None));
        let mut sim = self.sim.clone();
        let out = Arc::clone(&slot);
        std::thread::spawn(move || {
            let result = sim.advance();
            if let Ok(mut s) = out.lock() {
                *s = Some((sim, result));
            }
        });
        self.background = Some(Background {
            step: self.computed() + 1,
            slot,
        });
        Poll::Busy
    }

    /// Keeps the outcome of the step just computed (into `self.sim`).
    fn accept(&mut self, result: Result<StepReport, BlowUp>) -> bool {
        match result {
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

    /// Whether recording a step's resolution goes to another thread (a large
    /// scene: [`Player::record_later`]).
    pub fn records_later(&self) -> bool {
        self.heavy()
    }

    /// [`Player::record`] on another thread: the UI keeps drawing and may
    /// cancel (the steps from the nearest copy stop at the next step; a step
    /// under way finishes and its result is dropped). `None` for step 0 or a
    /// step not computed yet.
    pub fn record_later(&self, step: u64) -> Option<Recording> {
        if step == 0 || step > self.computed() {
            return None;
        }
        let (_, from) = self.checkpoints.iter().rev().find(|(s, _)| *s < step)?;
        let mut sim = from.clone();
        let names = self.names.clone();
        Some(Job::spawn(step, move |stop| {
            while sim.step < step - 1 {
                if stop.load(Ordering::Relaxed) || sim.advance().is_err() {
                    return None;
                }
            }
            if stop.load(Ordering::Relaxed) {
                return None;
            }
            record_next(&mut sim, &names).ok()
        }))
    }
}

/// The reason a run stopped, in words (bodies by name).
pub fn blew_up(names: &Names, e: &BlowUp) -> String {
    let name = |body: usize| format!("'{}'", names.bodies.get(body).map_or("?", String::as_str));
    format!(
        "the scene blew up: {}",
        crate::trace::blow_up::words(e, &name)
    )
}
