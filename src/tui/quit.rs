//! Quitting: `q`, and Esc at the top screen, quit at once when nothing
//! would be lost; with edits or a predict score they ask first (y quits,
//! any other key stays). Ctrl-C always quits.

use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;

use super::app::{App, Mode};

impl App {
    /// What quitting now would lose, in words; empty when nothing.
    pub fn unsaved(&self) -> String {
        let mut lost = vec![];
        let edited: Vec<String> = self
            .lessons
            .iter()
            .filter(|e| !e.edits.is_empty())
            .map(|e| format!("{} ({} edit(s))", e.lesson.id, e.edits.len()))
            .collect();
        if !edited.is_empty() {
            lost.push(format!("the edits to {}", edited.join(", ")));
        }
        let opened = self.opened.as_ref().map_or(0, |e| e.edits.len());
        if opened + self.run_edits > 0 {
            lost.push(format!(
                "the edits to this scene's run ({})",
                opened.max(self.run_edits)
            ));
        }
        if self.predict && self.score.graded > 0 {
            lost.push(format!(
                "the predict score {}/{}",
                self.score.correct, self.score.graded
            ));
        }
        lost.join(" and ")
    }

    /// `q`, or Esc with no level above: quits, or asks when work would be lost.
    pub(crate) fn request_quit(&mut self) {
        let lost = self.unsaved();
        if lost.is_empty() {
            self.quit = true;
        } else {
            self.mode = Mode::Quit(lost);
        }
    }

    /// The answer to "quit?": y (or Ctrl-C) quits, any other key stays.
    pub(super) fn quit_key(&mut self, key: KeyEvent) {
        let ctrl_c =
            key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL);
        if ctrl_c || matches!(key.code, KeyCode::Char('y') | KeyCode::Char('Y')) {
            self.quit = true;
        } else {
            self.say("not quit: everything is as it was".into(), false);
        }
    }
}

/// The question, over whatever screen is on show.
pub fn render(app: &App, lost: &str, area: Rect, buf: &mut Buffer) {
    super::overlay::yes_or_no(
        app,
        (" Quit? ", &format!("Quit? This loses {lost}.")),
        "quits · any other key stays",
        area,
        buf,
    );
}
