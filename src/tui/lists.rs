//! The left column: lessons (with the contacts of the open one beneath it)
//! and the stages of the contact, the current one marked, skipped ones dimmed
//! with their reason.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, HighlightSpacing, List, ListItem, ListState, StatefulWidget};

use super::app::App;
use super::wrap::{truncate, width};

/// The reason of a skipped stage up to its colon: `no friction (μ = 0)`.
fn short_reason(why: &str) -> &str {
    why.split(':').next().unwrap_or(why).trim()
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let stages_height = (app.pages() as u16 + 2).min(area.height.saturating_sub(3));
    let [lessons, stages] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(stages_height)]).areas(area);
    render_lessons(app, lessons, buf);
    render_stages(app, stages, buf);
}

fn render_lessons(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let w = area.width.saturating_sub(3) as usize;
    let mut items = Vec::new();
    let mut selected = 0;
    for (i, e) in app.lessons.iter().enumerate() {
        // A heading where a group starts (not above the first: the box's title says it).
        let group = super::group(&e.lesson);
        if i > 0 && super::group(&app.lessons[i - 1].lesson) != group {
            items.push(ListItem::new(Line::styled(truncate(group, w), t.dim())));
        }
        let edited = if e.edits.is_empty() { "" } else { " *" };
        let here = i == app.lesson;
        let mark = if here { "▾ " } else { "▸ " };
        let style = if here { t.title() } else { Style::new() };
        items.push(ListItem::new(Line::styled(
            truncate(&format!("{mark}{}{edited}", e.lesson.id), w),
            style,
        )));
        if here {
            // The stepper's lesson: a scene's step when opened from one.
            let shown = &app.entry().lesson;
            for k in 0..shown.contacts.len() {
                if k == app.contact {
                    selected = items.len();
                }
                items.push(ListItem::new(Line::raw(truncate(
                    &format!("  {}", shown.contact_label(k)),
                    w,
                ))));
            }
        }
    }
    let items_len = items.len();
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(" Lessons [ ] ⇥ ", t.title()));
    let list = List::new(items)
        .block(block)
        .highlight_style(t.selected())
        .highlight_symbol("▶")
        .highlight_spacing(HighlightSpacing::Always);
    let total = items_len;
    let mut state = ListState::default().with_selected(Some(selected));
    StatefulWidget::render(list, area, buf, &mut state);
    mark_cut(app, area, total, state.offset(), buf);
}

/// The list in the box `area` (`total` rows from `first`): how many are cut.
fn mark_cut(app: &App, area: Rect, total: usize, first: usize, buf: &mut Buffer) {
    let rows = area.height.saturating_sub(2) as usize;
    let (above, below) = super::more::hidden(total, first, rows);
    super::more::mark(app, area, above, below, buf);
}

fn render_stages(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let w = area.width.saturating_sub(3) as usize;
    let mut items = vec![ListItem::new(Line::raw(truncate("  0 Overview", w)))];
    for (s, step) in app.trace.stages.iter().enumerate() {
        let changed = app.stage_changed(s);
        let gutter = if changed {
            Span::styled("● ", t.changed())
        } else if app.predict && !app.revealed_all(s) {
            Span::styled("? ", t.hidden())
        } else {
            Span::raw("  ")
        };
        let name = format!("{} {}", s + 1, step.id.label());
        let line = match &step.skipped {
            Some(why) => {
                // As much of the reason as fits; the panel shows all of it.
                let room = w.saturating_sub(2);
                let text = [
                    format!("{name} – {}", short_reason(why)),
                    format!("{name} · skipped"),
                ]
                .into_iter()
                .find(|t| width(t) <= room)
                .unwrap_or_else(|| truncate(&name, room));
                Line::from(vec![gutter, Span::styled(text, t.dim())])
            }
            None => Line::from(vec![
                gutter,
                Span::raw(truncate(&name, w.saturating_sub(2))),
            ]),
        };
        items.push(ListItem::new(line));
    }
    let total = items.len();
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(" Stages ←→ ", t.title()));
    let list = List::new(items)
        .block(block)
        .highlight_style(t.selected())
        .highlight_symbol("▶")
        .highlight_spacing(HighlightSpacing::Always);
    let mut state = ListState::default().with_selected(Some(app.page));
    StatefulWidget::render(list, area, buf, &mut state);
    mark_cut(app, area, total, state.offset(), buf);
}
