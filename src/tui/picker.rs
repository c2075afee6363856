//! The lesson picker (`/`, issue 28 item 5): every lesson under its group
//! heading (lessons, robustness, scenes), filtered as the user types (by id
//! or title), Tab jumping to the next group; Enter opens the lesson. `{` and
//! `}` on the screens jump to the previous / next group's first lesson
//! without opening it.

use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, List, ListItem, ListState, StatefulWidget, Widget};

use super::app::{App, Mode};
use super::keys::{self, Binding};
use super::wrap::truncate;

/// The picker's state: the filter typed so far and the lesson under the cursor.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picker {
    pub filter: String,
    /// Index into `app.lessons` (one of the matches when there are any).
    pub at: usize,
}

/// What a key does in the picker (letters and digits are the filter's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PickKey {
    Down,
    Up,
    NextGroup,
    PrevGroup,
    Open,
    Erase,
    Close,
}

/// The picker's keys, for its footer and the help.
pub const PICKER_KEYS: &[Binding<PickKey>] = &[
    Binding {
        label: "letters",
        help: "filter by id or title",
        keys: &[],
    },
    Binding {
        label: "↓ / ↑",
        help: "next / previous match",
        keys: &[(KeyCode::Down, PickKey::Down), (KeyCode::Up, PickKey::Up)],
    },
    Binding {
        label: "Tab / Shift-Tab",
        help: "next / previous group: lessons, robustness, scenes",
        keys: &[
            (KeyCode::Tab, PickKey::NextGroup),
            (KeyCode::BackTab, PickKey::PrevGroup),
        ],
    },
    Binding {
        label: "Enter",
        help: "open the lesson",
        keys: &[(KeyCode::Enter, PickKey::Open)],
    },
    Binding {
        label: "Backspace",
        help: "erase a letter of the filter",
        keys: &[(KeyCode::Backspace, PickKey::Erase)],
    },
    Binding {
        label: "Esc",
        help: "close, the lesson unchanged",
        keys: &[(KeyCode::Esc, PickKey::Close)],
    },
];

/// The lessons whose id or title contains `filter` (any case), in list order.
pub fn matches(app: &App, filter: &str) -> Vec<usize> {
    let f = filter.to_lowercase();
    app.lessons
        .iter()
        .enumerate()
        .filter(|(_, e)| {
            e.lesson.id.to_lowercase().contains(&f) || e.lesson.title.to_lowercase().contains(&f)
        })
        .map(|(i, _)| i)
        .collect()
}

/// The first of `among` in the group after (or before) lesson `from`'s,
/// wrapping round; `from` itself when there is no other group.
pub fn group_jump(app: &App, among: &[usize], from: usize, next: bool) -> usize {
    let group = |i: usize| super::group(&app.lessons[i].lesson);
    let mut groups: Vec<&str> = vec![];
    for &i in among {
        if !groups.contains(&group(i)) {
            groups.push(group(i));
        }
    }
    let Some(here) = groups.iter().position(|g| *g == group(from)) else {
        return among.first().copied().unwrap_or(from);
    };
    let n = groups.len();
    let to = groups[if next {
        (here + 1) % n
    } else {
        (here + n - 1) % n
    }];
    among
        .iter()
        .copied()
        .find(|&i| group(i) == to)
        .unwrap_or(from)
}

impl App {
    /// `/`: the picker, on the lesson open.
    pub(super) fn open_picker(&mut self) {
        self.mode = Mode::Pick(Picker {
            filter: String::new(),
            at: self.lesson,
        });
    }

    /// `{` / `}`: the previous / next group's first lesson, opened.
    pub(super) fn jump_group(&mut self, next: bool) {
        let all: Vec<usize> = (0..self.lessons.len()).collect();
        let to = group_jump(self, &all, self.lesson, next);
        if to != self.lesson {
            self.goto_lesson(to);
        }
        self.say(
            format!(
                "{}: {} ({{ }} jump between groups, / finds a lesson)",
                super::group(&self.lessons[self.lesson].lesson),
                self.lessons[self.lesson].lesson.id
            ),
            false,
        );
    }

    pub(super) fn picker_key(&mut self, mut p: Picker, key: KeyEvent) {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        if ctrl && key.code == KeyCode::Char('c') {
            self.quit = true;
            return;
        }
        let found = matches(self, &p.filter);
        let pos = found.iter().position(|&i| i == p.at);
        match keys::find(PICKER_KEYS, key.code) {
            Some(PickKey::Close) => return,
            Some(PickKey::Open) => {
                if let Some(i) = pos.map(|k| found[k]) {
                    if i != self.lesson {
                        self.goto_lesson(i);
                    }
                    return;
                }
                // Nothing matches: the picker stays, saying so.
            }
            Some(PickKey::Down) if !found.is_empty() => {
                p.at = found[pos.map_or(0, |k| (k + 1) % found.len())];
            }
            Some(PickKey::Up) if !found.is_empty() => {
                let n = found.len();
                p.at = found[pos.map_or(0, |k| (k + n - 1) % n)];
            }
            Some(PickKey::NextGroup | PickKey::PrevGroup) if !found.is_empty() => {
                let next = keys::find(PICKER_KEYS, key.code) == Some(PickKey::NextGroup);
                p.at = group_jump(self, &found, pos.map_or(found[0], |k| found[k]), next);
            }
            Some(PickKey::Erase) => {
                p.filter.pop();
            }
            None => {
                if let KeyCode::Char(c) = key.code {
                    if !c.is_control() && !ctrl {
                        p.filter.push(c);
                    }
                }
            }
            _ => {}
        }
        // The cursor stays on a match when there is one.
        let found = matches(self, &p.filter);
        if !found.contains(&p.at) {
            if let Some(&first) = found.first() {
                p.at = first;
            }
        }
        self.mode = Mode::Pick(p);
    }
}

/// The picker, drawn over `area`.
pub fn render(app: &App, p: &Picker, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let w = area.width.saturating_sub(8).clamp(20, 70);
    let h = area.height.saturating_sub(4).max(6);
    let rect = Rect {
        x: area.x + (area.width.saturating_sub(w)) / 2,
        y: area.y + (area.height.saturating_sub(h)) / 2,
        width: w.min(area.width),
        height: h.min(area.height),
    };
    Clear.render(rect, buf);
    let block = Block::bordered()
        .border_style(t.border_focus())
        .title(Span::styled(
            " Lessons · type to filter · ⇥ next group · Enter opens · Esc ",
            t.title(),
        ));
    let inner = block.inner(rect);
    block.render(rect, buf);
    if inner.height < 3 {
        return;
    }
    let room = inner.width.saturating_sub(2) as usize;
    let found = matches(app, &p.filter);
    let filter = Line::from(vec![
        Span::styled(" / ", t.key()),
        Span::raw(p.filter.clone()),
        Span::styled("▏", t.key()),
        Span::styled(
            if found.is_empty() {
                "  no lesson matches".to_string()
            } else {
                format!("  {} of {}", found.len(), app.lessons.len())
            },
            t.dim(),
        ),
    ]);
    Widget::render(
        ratatui::widgets::Paragraph::new(filter),
        Rect { height: 1, ..inner },
        buf,
    );
    let mut items = vec![];
    let mut selected = None;
    let mut last_group = "";
    for &i in &found {
        let l = &app.lessons[i].lesson;
        let g = super::group(l);
        if g != last_group {
            items.push(ListItem::new(Line::styled(truncate(g, room), t.dim())));
            last_group = g;
        }
        if i == p.at {
            selected = Some(items.len());
        }
        items.push(ListItem::new(Line::raw(truncate(
            &format!("{} · {}", l.id, l.title),
            room,
        ))));
    }
    let total = items.len();
    let list = List::new(items)
        .highlight_style(t.selected())
        .highlight_symbol("▶ ");
    let mut state = ListState::default().with_selected(selected);
    StatefulWidget::render(
        list,
        Rect {
            y: inner.y + 1,
            height: inner.height - 1,
            ..inner
        },
        buf,
        &mut state,
    );
    let rows = inner.height as usize - 1;
    let (above, below) = super::more::hidden(total, state.offset(), rows);
    super::more::mark(app, rect, above, below, buf);
}
