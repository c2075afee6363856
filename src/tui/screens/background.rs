//! `d` on a large scene: the step's detection computed on another thread
//! (as Enter records a step's resolution), so the keys keep answering; the
//! key bar says it is working, Esc cancels, and `tick` opens the detection
//! screen when it is done, if the run is still on show.

use super::{RunView, Screen};
use crate::tui::app::{App, Mode};

impl App {
    /// Starts the detection of the frame on show on another thread (or
    /// says that one is under way).
    pub(crate) fn detect_later(&mut self) {
        let lesson = &self.lessons[self.lesson].lesson;
        let plane = self.plane;
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        if run.detecting.is_some() {
            let text = detecting(run);
            return self.say(text, false);
        }
        let at = std::time::Instant::now();
        run.detecting = run
            .player
            .detect_later(lesson, run.frame as u64, plane)
            .map(|d| (d, at));
    }

    /// A detection computed on another thread, shown when it is done.
    pub(crate) fn collect_detection(&mut self) {
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        let Some(done) = run.detecting.as_ref().and_then(|(d, _)| d.poll()) else {
            return;
        };
        let step = run.detecting.take().map_or(0, |(d, _)| d.step);
        match done {
            Some(trace) if self.screen == Screen::Run && self.mode == Mode::Normal => {
                self.show_detect(trace)
            }
            Some(_) => {}
            None => self.say(
                format!("step {step}'s bodies could not be found again: the run blew up"),
                true,
            ),
        }
    }

    /// Cancels a detection under way.
    pub(crate) fn cancel_detecting(&mut self) -> Option<u64> {
        let (d, _) = self.run.as_deref_mut()?.detecting.take()?;
        d.cancel();
        Some(d.step)
    }
}

/// What the key bar says while a step's detection is computed.
pub(crate) fn detecting(run: &RunView) -> String {
    let Some((d, since)) = &run.detecting else {
        return String::new();
    };
    let spin = ["⠋", "⠙", "⠹", "⠸", "⠼", "⠴", "⠦", "⠧", "⠇", "⠏"];
    let elapsed = since.elapsed();
    // The narrow phase's pairs done, once the worker has counted them.
    let counted = match d.progress() {
        Some((done, 1)) => format!(", {done} of 1 pair"),
        Some((done, total)) => format!(", {done} of {total} pairs"),
        None => String::new(),
    };
    format!(
        "{} working: detecting step {}'s contacts{counted} ({:.0} s; a large scene) · Esc cancels · q quits",
        spin[(elapsed.as_millis() / 100) as usize % spin.len()],
        d.step,
        elapsed.as_secs_f64().floor()
    )
}
