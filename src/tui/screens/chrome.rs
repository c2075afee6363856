//! What every scene screen has: the breadcrumb header, the key bar of the
//! screen's keys, the help overlay listing them, and the dispatch to the
//! screen's body.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use super::{Screen, DETECT_KEYS, RESOLVER_KEYS, RUN_KEYS, SPEEDS};
use crate::physics::resolver::Phase;
use crate::tui::app::{App, Mode};
use crate::tui::wrap::{truncate, width};

/// Where the user is: `stack-5 › t = 1.250 s, step 75 › velocity iteration
/// 12 › contact 3 › impulse` (as far down as they went).
pub fn breadcrumb(app: &App) -> String {
    let mut parts = vec![app.lessons[app.lesson].lesson.id.clone()];
    if let Some(run) = &app.run {
        let frame = &run.player.run.frames[run.frame];
        parts.push(format!("t = {:.3} s, step {}", frame.time, frame.step));
    }
    if matches!(app.screen, Screen::Detect | Screen::Contact) {
        if let Some(d) = &app.detect {
            parts.push(match &d.toi {
                Some(_) if app.screen == Screen::Detect => "detection › time of collision".into(),
                _ => "detection".into(),
            });
        }
    }
    if !matches!(app.screen, Screen::Run | Screen::Detect) {
        if let (Some(r), Some(_)) = (&app.resolver, &app.detect) {
            // A contact opened from the detection: the step that resolves it.
            parts.push(format!("step {}'s resolver", r.trace.step));
        } else if let Some(r) = &app.resolver {
            let table = &r.trace.tables[r.stop];
            let (phase, used) = match table.stop.phase {
                Phase::Position => ("position", r.trace.resolver.position.iterations_used),
                Phase::Velocity => ("velocity", r.trace.resolver.velocity.iterations_used),
            };
            parts.push(if table.stop.iteration < used {
                format!("{phase} iteration {}", table.stop.iteration)
            } else {
                format!("{phase} phase done ({used} iterations)")
            });
        }
    }
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

/// The run or resolver screen, whole.
pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let [top, body, bottom] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(1),
    ])
    .areas(area);
    header(app, top, buf);
    key_bar(app, bottom, buf);
    match app.screen {
        Screen::Run => super::run::render(app, body, buf),
        Screen::Detect => super::detect::render(app, body, buf),
        _ => super::resolver::render(app, body, buf),
    }
    if app.mode == Mode::Help {
        let (title, keys, notes) = match app.screen {
            Screen::Run => (" Keys · run ", crate::tui::keys::help(RUN_KEYS), &NOTES[..]),
            Screen::Detect => (
                " Keys · detection ",
                crate::tui::keys::help(DETECT_KEYS),
                &DETECT_NOTES[..],
            ),
            _ => (
                " Keys · resolver ",
                crate::tui::keys::help(RESOLVER_KEYS),
                &NOTES[..],
            ),
        };
        crate::tui::overlay::help_list(app, title, &keys, notes, area, buf);
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

const NOTES: [&str; 4] = [
    "? again (or PgDn): page 2, the glossary of every symbol.",
    "Enter goes down a level: a step → its resolver iterations → an iteration's contact and its stages. Esc or Backspace goes back up.",
    "Mouse: click a contact or a body in the picture, or a table row, to select it; the wheel scrolls.",
    "The contact screen has its own keys (? there).",
];

const DETECT_NOTES: [&str; 3] = [
    "? again (or PgDn): page 2, the glossary of every symbol.",
    "A - B: the Minkowski difference seen in the view plane through the origin O, with the iteration's simplex (• kept, ✗ dropped), w_k, v_k and d_k; at the result -δn (the penetration) or v (the distance). x puts it beside the shapes, alone, or hides it.",
    "The iterations are the rows contact-lab detect --step N prints; the time of collision is detect --toi's (docs/detect.md, docs/ccd.md).",
];

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
        if run.recording.is_some() || run.detecting.is_some() {
            let text = match run.recording {
                Some(_) => super::run_nav::recording(run),
                None => super::background::detecting(run),
            };
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
        (false, Screen::Run) => &[
            ("Space", "play"),
            ("←→", "step"),
            ("Enter", "resolver"),
            ("d", "detection"),
            ("n", "next event"),
            ("+-", "speed"),
            ("g", "restart"),
            ("cosbm", "show"),
            ("/", "find"),
            ("?", "help"),
            ("q", "quit"),
        ],
        (false, Screen::Detect) if app.detect.as_ref().is_some_and(|d| d.toi.is_some()) => &[
            ("↑↓", "pair"),
            ("←→", "test"),
            ("t Esc", "iterations"),
            ("?", "help"),
            ("q", "quit"),
        ],
        (false, Screen::Detect) => &[
            ("↑↓", "pair"),
            ("←→", "iteration"),
            ("Enter", "stages"),
            ("x", "picture"),
            ("t", "time of collision"),
            ("Esc", "run"),
            ("?", "help"),
            ("q", "quit"),
        ],
        (false, _) => &[
            ("←→", "iteration"),
            ("⇥", "contact"),
            ("Enter", "stages"),
            ("Esc", "up"),
            ("?", "help"),
            ("q", "quit"),
        ],
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
