//! Clicks and the wheel on the run and resolver screens, and the lesson's
//! top screen; picking in the picture. (Keys go through the router: the
//! run's own are in [`super::run_nav`], the resolver's in
//! [`super::resolver_nav`].)

use ratatui::crossterm::event::{MouseButton, MouseEvent, MouseEventKind};

use super::{Pick, RunView, Screen};
use crate::session::Player;
use crate::trace::step::StepTrace;
use crate::tui::app::{App, Mode};

impl App {
    /// Opens the lesson's top screen: a scene's run; the resolver for a
    /// lesson with several contacts when `several`; else the stepper as it is.
    pub(crate) fn open_lesson_screen(&mut self, several: bool) {
        let lesson = &self.lessons[self.lesson].lesson;
        if let Some(player) = Player::new(lesson) {
            self.run = Some(Box::new(RunView::new(player)));
            self.screen = Screen::Run;
        } else if several && lesson.contacts.len() > 1 {
            let trace = StepTrace::of_lesson(lesson);
            self.show_resolver(trace);
        }
    }

    /// A mouse event: a click picks a contact, a body or a table row; the
    /// wheel scrolls.
    pub fn mouse(&mut self, m: MouseEvent) {
        if self.mode != Mode::Normal || self.too_small.get() {
            return;
        }
        let up = match m.kind {
            MouseEventKind::ScrollUp => Some(true),
            MouseEventKind::ScrollDown => Some(false),
            _ => None,
        };
        if let Some(up) = up {
            return self.wheel(up);
        }
        if m.kind != MouseEventKind::Down(MouseButton::Left) {
            return;
        }
        self.status = None;
        let table = self.targets.table.get();
        if self.screen == Screen::Resolver && contains(table, m.column, m.row) {
            let first = self.targets.table_first.get();
            let Some(r) = self.resolver.as_deref_mut() else {
                return;
            };
            // One line of border and one of headings above the rows.
            if let Some(row) = (m.row as usize).checked_sub(table.y as usize + 2) {
                let k = first + row;
                if k < r.trace.world.contacts.len() {
                    r.selected = k;
                }
            }
            return;
        }
        if let Some(pick) = self.pick(m.column, m.row) {
            match pick {
                Pick::Contact(k) => {
                    if let Some(r) = self.resolver.as_deref_mut() {
                        r.selected = k;
                    }
                    self.say(
                        format!("contact {k} selected (Enter opens its stages)"),
                        false,
                    );
                }
                Pick::Body(i) => {
                    let name = self.lessons[self.lesson].lesson.bodies[i].name.clone();
                    self.say(format!("body {i}: {name}"), false);
                }
            }
        }
    }

    /// The mouse wheel, or `j` / `k`: scrolls the screen's list or panel.
    pub(crate) fn wheel(&mut self, up: bool) {
        match self.screen {
            Screen::Run => {
                if let Some(run) = self.run.as_deref_mut() {
                    run.events_scroll = if up {
                        run.events_scroll + 1
                    } else {
                        run.events_scroll.saturating_sub(1)
                    };
                }
            }
            Screen::Resolver => {
                if let Some(r) = self.resolver.as_deref() {
                    let s = r.scroll.get();
                    r.scroll.set(if up { s.saturating_sub(1) } else { s + 1 });
                }
            }
            Screen::Contact => {
                self.scroll = if up {
                    self.scroll.saturating_sub(1)
                } else {
                    (self.scroll + 1).min(self.scroll_max.get())
                }
            }
            // The detection screen's lists follow the selection.
            _ => {}
        }
    }

    /// The contact or body drawn nearest the cell clicked (within two
    /// cells); clicking again where several lie (corners seen edge-on) takes
    /// the next of them.
    fn pick(&self, col: u16, row: u16) -> Option<Pick> {
        let area = self.targets.picture.get();
        if !matches!(self.screen, Screen::Run | Screen::Resolver) || !contains(area, col, row) {
            return None;
        }
        let [x0, x1, y0, y1] = self.targets.bounds.get();
        let (w, h) = (f64::from(area.width.max(2)), f64::from(area.height.max(2)));
        let cx = f64::from(col - area.x) + 0.5;
        let cy = f64::from(row - area.y) + 0.5;
        let points = self.targets.points.borrow();
        let mut near: Vec<(f64, Pick)> = points
            .iter()
            .map(|(p, pick)| {
                let px = (p[0] - x0) / (x1 - x0) * w;
                let py = (y1 - p[1]) / (y1 - y0) * h;
                ((px - cx).powi(2) + (2.0 * (py - cy)).powi(2), *pick)
            })
            .filter(|(d, _)| *d <= 4.0 * 4.0)
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        let best = near.first()?.0;
        // Those drawn in the same cell as the nearest.
        near.retain(|(d, _)| *d <= best + 1.0);
        let selected = self.resolver.as_ref().map(|r| Pick::Contact(r.selected));
        let at = near.iter().position(|(_, p)| Some(*p) == selected);
        Some(near[at.map_or(0, |i| (i + 1) % near.len())].1)
    }
}

fn contains(r: ratatui::layout::Rect, col: u16, row: u16) -> bool {
    col >= r.x && col < r.x + r.width && row >= r.y && row < r.y + r.height
}
