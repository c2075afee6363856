//! `i` on the run: the events the list shows, each in full and wrapped (the
//! list cuts a long one at its edge); j/k scroll, any other key closes.

use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use ratatui::text::Line;

use crate::tui::app::{App, Mode};
use crate::tui::wrap::wrap;

impl App {
    /// Opens the pop-up, or says there is nothing to read yet.
    pub(crate) fn show_events(&mut self) {
        let none = self.run.as_deref().is_none_or(|r| {
            let (start, end) = r.events_shown.get();
            start >= end
        });
        if none {
            self.say("no events on show yet: Space plays, → steps".into(), false);
        } else {
            self.mode = Mode::Events(0);
        }
    }

    pub(crate) fn events_key(&mut self, at: u16, key: KeyEvent) {
        let max = self.run.as_deref().map_or(0, |r| r.events_max.get());
        let to = |n: u16| Mode::Events(n.min(max));
        match key.code {
            KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => self.quit = true,
            KeyCode::Char('j') | KeyCode::Down => self.mode = to(at.saturating_add(1)),
            KeyCode::Char('k') | KeyCode::Up => self.mode = to(at.saturating_sub(1)),
            KeyCode::PageDown | KeyCode::Char(' ') => self.mode = to(at.saturating_add(10)),
            KeyCode::PageUp => self.mode = to(at.min(max).saturating_sub(10)),
            _ => {}
        }
    }
}

/// The pop-up over `area`: each event on show as time, step and its whole text.
pub fn render(app: &App, scroll: u16, area: Rect, buf: &mut Buffer) {
    let Some(run) = app.run.as_deref() else {
        return;
    };
    let t = &app.theme;
    let (start, end) = run.events_shown.get();
    let w = 76.min(area.width.saturating_sub(4));
    let text_w = w.saturating_sub(3) as usize;
    let mut lines = vec![];
    for (i, e) in run.player.run.events[start..end].iter().enumerate() {
        if i > 0 {
            lines.push(Line::raw(""));
        }
        let head = format!("t = {:.3} s, step {} ({})", e.time, e.step, e.kind);
        lines.push(Line::styled(format!(" {head}"), t.title()));
        for l in wrap(&e.text, text_w, 2) {
            lines.push(Line::raw(format!(" {l}")));
        }
    }
    let max = crate::tui::overlay::scrolled(app, " Events in full ", lines, scroll, w, area, buf);
    run.events_max.set(max);
}
