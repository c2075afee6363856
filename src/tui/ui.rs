//! The view: `impl Widget for &App` lays out the screen from the state alone
//! (header, lessons and stages, stage panel, picture, checks, key bar) and
//! puts the overlay of the active mode on top.

use crate::render::fill::Fill;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::app::{App, Mode};
use super::{lists, overlay, scene, stage};

/// Below this the screen says so instead of drawing a squeezed layout.
pub const MIN_WIDTH: u16 = 60;
pub const MIN_HEIGHT: u16 = 18;

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let small = area.width < MIN_WIDTH || area.height < MIN_HEIGHT;
        self.too_small.set(small);
        if small {
            too_small(area, buf);
            return;
        }
        if self.screen != super::screens::Screen::Contact {
            super::screens::render(self, area, buf);
            return;
        }
        let [top, body, bottom] = Layout::vertical([
            Constraint::Length(1),
            Constraint::Fill(1),
            Constraint::Length(1),
        ])
        .areas(area);
        header(self, top, buf);
        key_bar(self, bottom, buf);
        let wide = area.width >= 100;
        let [left, right] = Layout::horizontal([
            Constraint::Length(if wide { 28 } else { 22 }),
            Constraint::Fill(1),
        ])
        .areas(body);
        lists::render(self, left, buf);
        if self.zoom {
            scene::render(self, right, buf);
        } else if wide {
            // Stage panel | picture over checks.
            let side = (right.width * 2 / 5).min(60);
            let [panel, side] =
                Layout::horizontal([Constraint::Fill(1), Constraint::Length(side)]).areas(right);
            stage::render(self, panel, buf);
            let [pic, checks] =
                Layout::vertical([Constraint::Percentage(60), Constraint::Fill(1)]).areas(side);
            scene::render(self, pic, buf);
            render_checks(self, checks, buf);
        } else {
            // Stage panel over picture | checks.
            let lower = (body.height * 9 / 20).max(8);
            let [panel, low] =
                Layout::vertical([Constraint::Fill(1), Constraint::Length(lower)]).areas(right);
            stage::render(self, panel, buf);
            let [pic, checks] =
                Layout::horizontal([Constraint::Percentage(55), Constraint::Fill(1)]).areas(low);
            scene::render(self, pic, buf);
            render_checks(self, checks, buf);
        }
        match &self.mode {
            Mode::Normal => {}
            Mode::Help => overlay::help(self, area, buf),
            Mode::Glossary(scroll) => overlay::glossary(self, *scroll, area, buf),
            Mode::Answer { .. } => {}
            Mode::Edit(form) => overlay::form(self, form, area, buf),
            Mode::Write { input, error } => {
                overlay::write_prompt(self, input, error.as_deref(), area, buf)
            }
            Mode::Confirm(path) => overlay::confirm(self, path, area, buf),
            Mode::Pick(p) => super::picker::render(self, p, area, buf),
            Mode::Quit(lost) => super::quit::render(self, lost, area, buf),
            Mode::Events(_) => {}
        }
    }
}

fn too_small(area: Rect, buf: &mut Buffer) {
    let text = format!(
        "Terminal too small: {}×{}. contact-lab needs at least {MIN_WIDTH}×{MIN_HEIGHT} (80×24 or more is best). Enlarge the window, or q to quit.",
        area.width, area.height
    );
    Paragraph::new(text)
        .wrap(Wrap { trim: true })
        .render(area, buf);
}

fn header(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let tr = &app.trace;
    // The tags at the end (predict score, edits) always show: the title
    // gives way, shortened with an ellipsis.
    let mut tags = vec![];
    if app.predict {
        let score = if app.score.graded > 0 {
            format!("  [predict {}/{}]", app.score.correct, app.score.graded)
        } else {
            "  [predict]".to_string()
        };
        tags.push(Span::styled(score, t.hidden()));
    }
    if !app.entry().edits.is_empty() {
        tags.push(Span::styled(
            format!("  [edited ×{}]", app.entry().edits.len()),
            t.warning(),
        ));
    }
    let tags_w: usize = tags.iter().map(|s| s.width()).sum();
    let room = (area.width as usize).saturating_sub(tags_w);
    let mut spans = if app.resolver.is_some() {
        // Opened from a resolver iteration: where it came from.
        vec![
            Span::styled(" contact-lab ", t.selected()),
            Span::raw(" "),
            Span::styled(
                super::screens::breadcrumb_fit(app, room.saturating_sub(14)),
                t.title(),
            ),
        ]
    } else {
        let lesson = format!(" {} ", tr.lesson);
        let rest = format!("· {} · contact {}", tr.title, tr.contact_label);
        let left = room.saturating_sub(13 + super::wrap::width(&lesson));
        vec![
            Span::styled(" contact-lab ", t.selected()),
            Span::styled(lesson, t.title()),
            Span::raw(super::wrap::truncate(&rest, left)),
        ]
    };
    spans.extend(tags);
    Paragraph::new(Line::from(spans)).render(area, buf);
}

fn key_bar(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    if let Some(s) = &app.status {
        let style = if s.error { t.error() } else { t.info() };
        Paragraph::new(Line::styled(format!(" {}", s.text), style)).render(area, buf);
        return;
    }
    if let Mode::Answer { input, error } = &app.mode {
        let mut spans = vec![
            Span::styled(" your answer: ", t.key()),
            Span::raw(super::wrap::tail(
                input,
                (area.width as usize).saturating_sub(40),
            )),
            Span::styled("▏", t.key()),
        ];
        match error {
            Some(e) => spans.push(Span::styled(format!("  {e}"), t.error())),
            None => spans.push(Span::styled("  Enter grades · Esc cancels", t.dim())),
        }
        Paragraph::new(Line::from(spans)).render(area, buf);
        return;
    }
    let keys: &[(&str, &str)] = match app.mode {
        Mode::Edit(ref f) if f.input.is_some() => {
            &[("Enter", "set"), ("Esc", "cancel"), ("Ctrl-U", "clear")]
        }
        Mode::Edit(_) => &[("↑↓", "field"), ("Enter", "edit / cycle"), ("Esc", "close")],
        Mode::Write { .. } => &[("Enter", "write"), ("Esc", "cancel")],
        Mode::Confirm(_) => &[("y", "overwrites"), ("any other key", "keeps the file")],
        Mode::Quit(_) => &[("y", "quits"), ("any other key", "stays")],
        Mode::Events(_) => &[],
        Mode::Pick(_) => &[
            ("letters", "filter"),
            ("↑↓", "move"),
            ("⇥", "next group"),
            ("Enter", "open"),
            ("Esc", "close"),
        ],
        Mode::Help => &[
            ("?", "glossary"),
            ("j k", "scroll"),
            ("any other key", "closes"),
        ],
        Mode::Glossary(_) => &[
            ("j k ↑↓ PgDn PgUp", "scroll"),
            ("← ?", "keys"),
            ("any other key", "closes"),
        ],
        Mode::Answer { .. } => &[],
        Mode::Normal if app.resolver.is_some() => &[
            ("←→", "stage"),
            ("Esc", "up"),
            ("⇥", "contact"),
            ("e", "edit"),
            ("p", "predict"),
            ("w", "write"),
            ("v", "plane"),
            ("z", "zoom"),
            ("?", "help"),
            ("q", "quit"),
        ],
        Mode::Normal => &[
            ("←→", "stage"),
            ("⇥", "contact"),
            ("[]", "lesson"),
            ("jk", "scroll"),
            ("e", "edit"),
            ("p", "predict"),
            ("w", "write"),
            ("v", "plane"),
            ("z", "zoom"),
            ("r", "reset"),
            ("/", "find"),
            ("?", "help"),
            ("q", "quit"),
        ],
    };
    // Drop keys from the end (but never help and quit) until the bar fits.
    let cost = |(k, w): &(&str, &str)| super::wrap::width(k) + super::wrap::width(w) + 3;
    let split = if matches!(app.mode, Mode::Normal) {
        keys.len() - 2
    } else {
        keys.len()
    };
    let (head, tail) = keys.split_at(split);
    // The last item needs no trailing gap.
    let mut room = (area.width as usize + 2).saturating_sub(tail.iter().map(cost).sum());
    let mut shown: Vec<&(&str, &str)> = Vec::new();
    for item in head {
        if cost(item) > room {
            break;
        }
        room -= cost(item);
        shown.push(item);
    }
    shown.extend(tail);
    let mut spans = vec![];
    for (i, (k, what)) in shown.into_iter().enumerate() {
        if i > 0 {
            spans.push(Span::raw("  "));
        }
        spans.push(Span::styled(*k, t.key()));
        spans.push(Span::raw(format!(" {what}")));
    }
    Paragraph::new(Line::from(spans)).render(area, buf);
}

fn render_checks(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(" Checks ", t.title()));
    let lines: Vec<Line> = if !app.shown("checks") {
        super::wrap::wrap(
            "Hidden in predict mode until the Checks stage is revealed.",
            block.inner(area).width as usize,
            0,
        )
        .into_iter()
        .map(|l| Line::styled(l, t.hidden()))
        .collect()
    } else {
        let step = app.trace.stage("checks");
        let rows: Vec<(&str, Style, String, String)> = app
            .trace
            .verdicts
            .iter()
            .map(|v| {
                let style = match v.passed {
                    Some(true) => t.pass(),
                    Some(false) => t.fail(),
                    None => t.dim(),
                };
                let mark = v.mark();
                let detail = match step {
                    Some(s) => app.fmt.fill_units(&v.detail, s),
                    None => v.detail.clone(),
                };
                (mark, style, v.label.clone(), detail)
            })
            .collect();
        // With no room for every detail, the verdicts alone; with no room
        // for every verdict, those that fit and how many more the Checks
        // stage lists. Wrapped here, at spaces, so nothing is cut mid-word.
        let inner = block.inner(area);
        let w = inner.width as usize;
        let h = inner.height as usize;
        let wrapped = |text: &str| super::wrap::wrap(text, w, 2);
        let needed: usize = rows
            .iter()
            .map(|(_, _, label, detail)| wrapped(&format!("✓ {label}: {detail}")).len())
            .sum();
        let details = needed <= h;
        let mut lines: Vec<Line> = vec![];
        let n = rows.len();
        for (i, (mark, style, label, detail)) in rows.into_iter().enumerate() {
            let text = if details {
                format!("{mark} {label}: {detail}")
            } else {
                format!("{mark} {label}")
            };
            let pieces = wrapped(&text);
            let left = n - i - 1;
            // Room for this verdict, and for the "more" line if others follow.
            if lines.len() + pieces.len() + usize::from(left > 0) > h && lines.len() < h {
                let long = format!("+{} more (Checks stage)", n - i);
                let more = if super::wrap::width(&long) <= w {
                    long
                } else {
                    format!("+{}", n - i)
                };
                lines.push(Line::styled(more, t.dim()));
                break;
            }
            for (j, piece) in pieces.into_iter().enumerate() {
                if j == 0 {
                    let rest = piece.strip_prefix(mark).unwrap_or(&piece).to_string();
                    lines.push(Line::from(vec![Span::styled(mark, style), Span::raw(rest)]));
                } else {
                    lines.push(Line::styled(piece, t.dim()));
                }
            }
        }
        lines
    };
    Paragraph::new(lines).block(block).render(area, buf);
}
