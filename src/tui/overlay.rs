//! Pop-ups drawn over the screen: help, the edit form, the write prompt and
//! the overwrite question.

use std::path::Path;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{
    Block, Clear, List, ListItem, ListState, Paragraph, StatefulWidget, Widget, Wrap,
};

use super::app::App;
use super::event::KEYS;
use super::form::Form;
use super::wrap::{tail, truncate, width, wrap};
use crate::lesson::edit::{self, Kind};

/// A `w × h` rectangle in the middle of `area` (clipped to it).
pub(super) fn centered(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

pub(super) fn frame(app: &App, title: &str, area: Rect, buf: &mut Buffer) -> Rect {
    Clear.render(area, buf);
    let block = Block::bordered()
        .border_style(app.theme.border_focus())
        .title(Span::styled(title, app.theme.title()));
    let inner = block.inner(area);
    block.render(area, buf);
    inner
}

pub fn help(app: &App, area: Rect, buf: &mut Buffer) {
    let mut notes = vec![
        "Edit form: ↑↓ field, Enter edits (or cycles a choice), Enter sets, Esc goes back.",
        "● changed by the last edit · ? results predict mode still hides",
        "Picture: v before, v′ after, ω spin, g impulse (-g on body 2), d̂ normal, r arms, q contact point.",
        "? again (or PgDn): page 2, the glossary of every symbol. Any other key closes this help.",
    ];
    if let Some(below) = app.below_contact() {
        notes.insert(0, below.up_note());
    }
    help_list(app, " Keys ", &super::keys::help(KEYS), &notes, area, buf);
}

/// Help's second page: every symbol with its meaning, unit, stages and the
/// lectures' name, scrolled by `scroll` lines (as far as it goes).
pub fn glossary(app: &App, scroll: u16, area: Rect, buf: &mut Buffer) {
    use crate::trace::glossary::GLOSSARY;
    let t = &app.theme;
    let rect_w = 92.min(area.width.saturating_sub(2));
    let text_w = rect_w.saturating_sub(3) as usize;
    let kw = GLOSSARY.iter().map(|s| width(s.symbol)).max().unwrap_or(0);
    let mut lines: Vec<Line> = Vec::new();
    let stages: Vec<String> = crate::physics::StageId::ALL
        .iter()
        .enumerate()
        .map(|(i, s)| format!("{} {}", i + 1, s.label()))
        .collect();
    let head = format!("Subscript ᵢ: body 1 or 2. Stages: {}.", stages.join(", "));
    for piece in wrap(&head, text_w, 0) {
        lines.push(Line::styled(format!(" {piece}"), t.dim()));
    }
    for sym in GLOSSARY {
        let unit = if sym.unit.is_empty() {
            "no unit"
        } else {
            sym.unit
        };
        let mut what = format!("{} [{unit}; stages {}]", sym.meaning, sym.stage_numbers());
        if !sym.elsewhere.is_empty() {
            what.push_str(&format!("; {}", sym.elsewhere));
        }
        for (i, piece) in wrap(&what, text_w.saturating_sub(kw + 2), 0)
            .into_iter()
            .enumerate()
        {
            let key = if i == 0 { sym.symbol } else { "" };
            let pad = " ".repeat(kw.saturating_sub(width(key)));
            lines.push(Line::from(vec![
                Span::styled(format!(" {key}{pad}  "), t.key()),
                Span::raw(piece),
            ]));
        }
    }
    app.glossary_max.set(scrolled(
        app,
        " Glossary (2/2) ",
        lines,
        scroll,
        rect_w,
        area,
        buf,
    ));
}

/// A help overlay: `keys` (key, what it does), then `notes`.
pub fn help_list(
    app: &App,
    title: &str,
    keys: &[(&str, &str)],
    notes: &[&str],
    area: Rect,
    buf: &mut Buffer,
) {
    let t = &app.theme;
    let rect_w = 92.min(area.width.saturating_sub(2));
    let text_w = rect_w.saturating_sub(3) as usize;
    let kw = keys.iter().map(|(k, _)| width(k)).max().unwrap_or(0);
    let mut lines: Vec<Line> = Vec::new();
    for (k, what) in keys {
        let wrapped = wrap(what, text_w.saturating_sub(kw + 2), 0);
        for (i, piece) in wrapped.into_iter().enumerate() {
            let key = if i == 0 { *k } else { "" };
            lines.push(Line::from(vec![
                Span::styled(format!(" {key:kw$}  "), t.key()),
                Span::raw(piece),
            ]));
        }
    }
    for text in notes {
        for piece in wrap(text, text_w, 0) {
            lines.push(Line::styled(format!(" {piece}"), t.dim()));
        }
    }
    app.help_max.set(scrolled(
        app,
        title,
        lines,
        app.help_scroll,
        rect_w,
        area,
        buf,
    ));
}

/// `lines` in a centred box `w` wide, as tall as they need or the screen
/// allows, scrolled by `scroll` (as far as it goes; the title says how to
/// scroll when they do not fit). Returns how far they can scroll.
pub(crate) fn scrolled(
    app: &App,
    title: &str,
    lines: Vec<Line>,
    scroll: u16,
    w: u16,
    area: Rect,
    buf: &mut Buffer,
) -> u16 {
    // The key bar's row stays in view: it says how to scroll and close.
    let area = Rect {
        height: area.height.saturating_sub(1),
        ..area
    };
    let rect = centered(area, w, lines.len() as u16 + 2);
    let overflow = (lines.len() as u16).saturating_sub(rect.height.saturating_sub(2));
    let scroll = scroll.min(overflow);
    let title = if overflow > 0 {
        format!("{title}· j/k ↑↓ scroll · {scroll}/{overflow} ")
    } else {
        title.to_string()
    };
    let inner = frame(app, &title, rect, buf);
    Paragraph::new(lines).scroll((scroll, 0)).render(inner, buf);
    overflow
}

pub fn form(app: &App, form: &Form, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let lesson = &app.entry().lesson;
    let k = app.contact;
    let rect = centered(
        area,
        72.min(area.width.saturating_sub(4)),
        (form.fields.len() as u16 + 8).min(area.height.saturating_sub(2)),
    );
    let title = format!(" Edit contact {} ", lesson.contact_label(k));
    let title = truncate(&title, rect.width.saturating_sub(4) as usize);
    let inner = frame(app, &title, rect, buf);
    // At most three rows of refusal, so the input line above it stays in view.
    let error = form
        .error
        .as_deref()
        .map(|e| truncate(e, (inner.width as usize * 5 / 2).saturating_sub(12)));
    let error_rows = error.as_deref().map_or(0, |e| {
        wrap(&format!(" refused: {e}"), inner.width as usize, 0).len() as u16
    });
    let [list_area, input_area, help_area] = Layout::vertical([
        Constraint::Fill(1),
        Constraint::Length(1 + error_rows),
        Constraint::Length(2),
    ])
    .areas(inner);
    let lw = form
        .fields
        .iter()
        .map(|f| f.label.chars().count())
        .max()
        .unwrap_or(0);
    let items: Vec<ListItem> = form
        .fields
        .iter()
        .map(|f| {
            let value = super::form::shown(&app.fmt, f, &edit::get(lesson, k, f));
            let hint = match f.kind() {
                Kind::Choice(_) => "  (Enter cycles)",
                _ => "",
            };
            ListItem::new(Line::from(vec![
                Span::raw(format!("{:lw$}  ", f.label)),
                Span::styled(value, t.result()),
                Span::styled(hint, t.dim()),
            ]))
        })
        .collect();
    let total = items.len();
    let mut state = ListState::default().with_selected(Some(form.selected));
    StatefulWidget::render(
        List::new(items)
            .highlight_style(t.selected())
            .highlight_symbol("▶"),
        list_area,
        buf,
        &mut state,
    );
    let (above, below) = super::more::hidden(total, state.offset(), list_area.height as usize);
    super::more::mark(app, rect, above, below, buf);
    let field = &form.fields[form.selected.min(form.fields.len().saturating_sub(1))];
    let mut lines = vec![];
    if let Some(input) = &form.input {
        let what = match field.kind() {
            Kind::Vector => "x, y, z",
            _ => "number",
        };
        let prompt = format!(" {} ({what}) = ", field.label);
        // One line, scrolled so that its end and the cursor stay visible.
        let room = (inner.width as usize).saturating_sub(width(&prompt) + 1);
        lines.push(Line::from(vec![
            Span::styled(prompt, t.key()),
            Span::raw(tail(input, room)),
            Span::styled("▏", t.key()),
        ]));
    }
    if let Some(e) = &error {
        lines.push(Line::styled(format!(" refused: {e}"), t.error()));
    }
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .render(input_area, buf);
    Paragraph::new(Line::styled(
        " Enter edits; every stage is solved again at once. Values are checked as in a lesson file.",
        t.dim(),
    ))
    .wrap(Wrap { trim: true })
    .render(help_area, buf);
}

pub fn write_prompt(app: &App, input: &str, error: Option<&str>, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let w = 70.min(area.width.saturating_sub(4));
    let text_w = w.saturating_sub(3) as usize;
    // The error wraps to at most three rows; the file name scrolls on one.
    let error_lines: Vec<String> = error.map_or_else(Vec::new, |e| {
        let mut l = wrap(e, text_w, 0);
        if l.len() > 3 {
            l.truncate(3);
            l[2] = truncate(&format!("{} …", l[2]), text_w);
        }
        l
    });
    let rows = 4 + error_lines.len() as u16;
    let rect = centered(area, w, rows);
    let inner = frame(app, " Write Markdown ", rect, buf);
    let dir = crate::output_file::shown(&app.write_dir);
    let mut lines = vec![
        Line::styled(
            truncate(&format!(" into {dir}"), inner.width as usize),
            t.dim(),
        ),
        Line::from(vec![
            Span::styled(" file: ", t.key()),
            Span::raw(tail(input, (inner.width as usize).saturating_sub(8))),
            Span::styled("▏", t.key()),
        ]),
    ];
    for e in error_lines {
        lines.push(Line::styled(format!(" {e}"), t.error()));
    }
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .render(inner, buf);
}

pub fn confirm(app: &App, path: &Path, area: Rect, buf: &mut Buffer) {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    yes_or_no(
        app,
        (" File exists ", &format!("{name} already exists.")),
        "overwrites it · any other key keeps it",
        area,
        buf,
    );
}

/// A question over whatever screen is on show: its (title, text) wrapped,
/// then "y" and what it does.
pub fn yes_or_no(
    app: &App,
    (title, text): (&str, &str),
    y_does: &str,
    area: Rect,
    buf: &mut Buffer,
) {
    let w = 70.min(area.width.saturating_sub(4));
    let mut lines: Vec<Line> = wrap(text, w.saturating_sub(3) as usize, 0)
        .into_iter()
        .map(|l| Line::raw(format!(" {l}")))
        .collect();
    lines.push(Line::from(vec![
        Span::styled(" y", app.theme.key()),
        Span::raw(format!(" {y_does}")),
    ]));
    let rect = centered(area, w, lines.len() as u16 + 2);
    let inner = frame(app, title, rect, buf);
    Paragraph::new(lines).render(inner, buf);
}
