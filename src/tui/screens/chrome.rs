//! What every scene screen has: the breadcrumb header, the key bar of the
//! screen's keys, the help overlay listing them, and the dispatch to the
//! screen's body.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use super::{Screen, SPEEDS};
use crate::tui::app::{App, Mode};
use crate::tui::wrap::{truncate, width};

/// Where the user is: `stack-5 › t = 1.250 s, step 75 › velocity iteration
/// 12 › contact 3 › impulse` (as far down as they went).
pub fn breadcrumb(app: &App) -> String {
    let mut parts = vec![app.lessons[app.lesson].lesson.id.clone()];
    parts.extend(app.levels());
    if app.screen == Screen::Contact {
        parts.push(format!("contact {}", app.contact));
        parts.push(match app.stage() {
            Some(s) => app.trace.stages[s].id.label_in_text(),
            None => "overview".into(),
        });
    }
    parts.join(" › ")
}

/// The breadcrumb in `room` columns: the middle levels give way ("… ›") so
/// the lesson's name and the deepest level, where the user is, stay in
/// view; then the lesson's name too.
pub fn breadcrumb_fit(app: &App, room: usize) -> String {
    let full = breadcrumb(app);
    if width(&full) <= room {
        return full;
    }
    let parts: Vec<&str> = full.split(" › ").collect();
    for skip in 2..parts.len() {
        let text = format!("{} › … › {}", parts[0], parts[skip..].join(" › "));
        if width(&text) <= room {
            return text;
        }
    }
    for skip in 1..parts.len() {
        let text = format!("… › {}", parts[skip..].join(" › "));
        if width(&text) <= room {
            return text;
        }
    }
    truncate(parts.last().copied().unwrap_or(""), room)
}

/// The screen on top (run, resolver or detection), whole: the header,
/// the key bar, the screen's body ([`super::View`]) and the overlay on show.
pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let [top, body, bottom] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(1),
    ])
    .areas(area);
    header(app, top, buf);
    key_bar(app, bottom, buf);
    if let Some(view) = app.top() {
        view.render(app, body, buf);
        if app.mode == Mode::Help {
            let (title, notes) = view.help();
            let keys = crate::tui::keys::help(view.keys());
            crate::tui::overlay::help_list(app, title, &keys, notes, area, buf);
        }
    }
    if let Mode::Glossary(scroll) = app.mode {
        crate::tui::overlay::glossary(app, scroll, area, buf);
    }
    if let Mode::Pick(p) = &app.mode {
        crate::tui::picker::render(app, p, area, buf);
    }
    if let Mode::Events(scroll) = app.mode {
        super::events::render(app, scroll, area, buf);
    }
    if let Mode::Quit(lost) = &app.mode {
        crate::tui::quit::render(app, lost, area, buf);
    }
}

fn header(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let mut spans = vec![
        Span::styled(" contact-lab ", t.selected()),
        Span::raw(" "),
        Span::styled(
            breadcrumb_fit(app, (area.width as usize).saturating_sub(14)),
            t.title(),
        ),
    ];
    if let (Screen::Run, Some(run)) = (app.screen, &app.run) {
        let state = if run.playing {
            "▶ playing"
        } else {
            "⏸ paused"
        };
        spans.push(Span::raw(format!(
            "  {state} ×{}",
            ["¼", "½", "1", "2", "4"][run.speed.min(SPEEDS.len() - 1)]
        )));
    }
    Paragraph::new(Line::from(spans)).render(area, buf);
}

fn key_bar(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    if let Some(s) = &app.status {
        let style = if s.error { t.error() } else { t.info() };
        Paragraph::new(Line::styled(
            truncate(&format!(" {}", s.text), area.width as usize),
            style,
        ))
        .render(area, buf);
        return;
    }
    if let (Screen::Run, Some(run)) = (app.screen, &app.run) {
        if let Some(text) = run.busy() {
            Paragraph::new(Line::styled(
                truncate(&format!(" {text}"), area.width as usize),
                t.info(),
            ))
            .render(area, buf);
            return;
        }
    }
    let keys: &[(&str, &str)] = match (app.mode == Mode::Help, app.screen) {
        (true, _) => &[
            ("?", "glossary"),
            ("j k", "scroll"),
            ("any other key", "closes"),
        ],
        _ if matches!(app.mode, Mode::Pick(_)) => &[
            ("letters", "filter"),
            ("↑↓", "move"),
            ("⇥", "next group"),
            ("Enter", "open"),
            ("Esc", "close"),
        ],
        _ if matches!(app.mode, Mode::Quit(_)) => &[("y", "quits"), ("any other key", "stays")],
        _ if matches!(app.mode, Mode::Events(_)) => {
            &[("j k ↑↓ PgDn PgUp", "scroll"), ("any other key", "closes")]
        }
        _ if matches!(app.mode, Mode::Glossary(_)) => {
            &[("j k ↑↓ PgDn PgUp", "scroll"), ("any other key", "closes")]
        }
        _ => app.top().map_or(&[], |v| v.bar()),
    };
    let mut spans = vec![];
    let mut used = 0;
    let room = area.width as usize;
    for (i, (k, what)) in keys.iter().enumerate() {
        let cost = width(k) + width(what) + 3;
        // Keep the last two (help, quit) when the bar is short.
        let rest: usize = keys[i + 1..]
            .iter()
            .rev()
            .take(2)
            .map(|(k, w)| width(k) + width(w) + 3)
            .sum();
        if used + cost + if i + 2 < keys.len() { rest } else { 0 } > room + 2 {
            continue;
        }
        used += cost;
        if !spans.is_empty() {
            spans.push(Span::raw("  "));
        }
        spans.push(Span::styled(*k, t.key()));
        spans.push(Span::raw(format!(" {what}")));
    }
    Paragraph::new(Line::from(spans)).render(area, buf);
}
