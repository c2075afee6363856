//! Work for a large scene done on another thread so that the TUI's keys
//! keep answering: a step's resolution recorded ([`Player::record_later`]),
//! a step's detection ([`Player::detect_later`]). The UI polls for the
//! outcome and may cancel (the work stops where it checks, or finishes and
//! its outcome is dropped).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use super::detect::detect_trace_watched;
use super::Player;
use crate::lesson::Lesson;
use crate::trace::detect::DetectTrace;
use crate::trace::step::StepTrace;
use crate::trace::Plane;

/// The vertices from which a hull's detection goes to another thread in
/// the TUI: a hull of 100,000 vertices took over 10 s on the UI thread.
pub const DETECT_LATER_VERTICES: usize = 1_000;

/// The outcome when its thread is done (`None` inside: it could not be made).
type Slot<T> = Arc<Mutex<Option<Option<T>>>>;

/// Work under way on another thread for step `step`.
#[derive(Clone)]
pub struct Job<T> {
    /// The step the work is for.
    pub step: u64,
    slot: Slot<T>,
    cancel: Arc<AtomicBool>,
    /// The work's units done and their number (0 of 0: not counted).
    counts: Arc<[AtomicUsize; 2]>,
}

/// A step's resolution being recorded on another thread.
pub type Recording = Job<StepTrace>;

/// A step's detection being computed on another thread.
pub type Detecting = Job<DetectTrace>;

impl<T> std::fmt::Debug for Job<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Job {{ step: {} }}", self.step)
    }
}

impl<T: Send + 'static> Job<T> {
    /// Runs `work` on a new thread; it is handed the cancel flag to check.
    pub fn spawn(
        step: u64,
        work: impl FnOnce(&AtomicBool) -> Option<T> + Send + 'static,
    ) -> Job<T> {
        Job::spawn_counted(step, move |stop, _| work(stop))
    }

    /// [`Job::spawn`], `work` also handed the counts to keep up to date
    /// (units done, of how many) for [`Job::progress`].
    pub fn spawn_counted(
        step: u64,
        work: impl FnOnce(&AtomicBool, &[AtomicUsize; 2]) -> Option<T> + Send + 'static,
    ) -> Job<T> {
        let slot: Slot<T> = Arc::new(Mutex::new(None));
        let cancel = Arc::new(AtomicBool::new(false));
        let counts = Arc::new([AtomicUsize::new(0), AtomicUsize::new(0)]);
        let (out, stop, count) = (Arc::clone(&slot), Arc::clone(&cancel), Arc::clone(&counts));
        std::thread::spawn(move || {
            let done = work(&stop, &count);
            if stop.load(Ordering::Relaxed) {
                return;
            }
            if let Ok(mut s) = out.lock() {
                *s = Some(done);
            }
        });
        Job {
            step,
            slot,
            cancel,
            counts,
        }
    }

    /// The units done and their number, once the work has counted them.
    pub fn progress(&self) -> Option<(usize, usize)> {
        let [done, total] = &*self.counts;
        let total = total.load(Ordering::Relaxed);
        (total > 0).then(|| (done.load(Ordering::Relaxed), total))
    }

    /// The outcome once the thread is done (taken: later calls give `None`);
    /// `Some(None)` when it could not be made (the run blew up).
    pub fn poll(&self) -> Option<Option<T>> {
        self.slot.lock().ok()?.take()
    }

    /// Asks the thread to stop; its outcome, if any, is dropped.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
}

impl Player {
    /// Whether `d` (a step's detection) goes to another thread: a large
    /// scene, or a hull of [`DETECT_LATER_VERTICES`] vertices or more (one
    /// pair's GJK and EPA then walk them all at every iteration).
    pub fn detects_later(&self) -> bool {
        self.heavy()
            || self.sim.world.bodies.iter().any(|b| match &b.shape {
                Some(crate::physics::Shape::Hull(h)) => h.vertices().len() >= DETECT_LATER_VERTICES,
                _ => false,
            })
    }

    /// [`Player::detect`] on another thread, for every pair (`None` for a
    /// step not computed yet).
    pub fn detect_later(&self, lesson: &Lesson, step: u64, plane: Plane) -> Option<Detecting> {
        if step > self.computed() {
            return None;
        }
        let (_, from) = self.checkpoints.iter().rev().find(|(s, _)| *s <= step)?;
        let mut sim = from.clone();
        let lesson = lesson.clone();
        Some(Job::spawn_counted(step, move |stop, [done, total]| {
            while sim.step < step {
                if stop.load(Ordering::Relaxed) || sim.advance().is_err() {
                    return None;
                }
            }
            detect_trace_watched(&sim, &lesson, step, plane, None, &mut |d, of| {
                done.store(d, Ordering::Relaxed);
                total.store(of, Ordering::Relaxed);
                !stop.load(Ordering::Relaxed)
            })
        }))
    }
}
