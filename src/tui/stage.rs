//! The stage panel: for the current stage each formula, the numbers put into
//! it and the result (hidden in predict mode until revealed), then the notes;
//! page 0 is the lesson's overview.

use crate::render::fill::Fill;
use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget};

use super::app::App;
use super::wrap::{width, wrap};
use crate::format::placeholders;
use crate::trace::{Formula, Step};

/// Gutter marking a line whose numbers changed with the last edit.
const CHANGED: &str = "● ";
const PLAIN: &str = "  ";
/// The indent of a formula's `= …` lines when its left-hand side is long.
const SHORT_PAD: usize = 5;

/// One logical line before wrapping.
struct Row {
    text: String,
    style: Style,
    /// Continuation indent, in cells after the gutter.
    indent: usize,
    changed: bool,
}

impl Row {
    fn new(text: impl Into<String>, style: Style) -> Self {
        Row {
            text: text.into(),
            style,
            indent: 2,
            changed: false,
        }
    }
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    // The rows below lay out to this width (a border and the gutter aside).
    app.panel_width
        .set(area.width.saturating_sub(2 + PLAIN.len() as u16));
    let (title, rows) = match app.stage() {
        None => (" Overview ".to_string(), overview(app)),
        Some(s) => {
            let step = &app.trace.stages[s];
            (
                format!(" {}/{} {} ", s + 1, app.trace.stages.len(), step.title),
                stage_rows(app, s),
            )
        }
    };
    let block = Block::bordered()
        .border_style(t.border_focus())
        .title(Span::styled(title, t.title()));
    let inner = block.inner(area);
    let text_width = (inner.width as usize).saturating_sub(PLAIN.len());
    let mut lines: Vec<Line> = Vec::new();
    for row in rows {
        let gutter = if row.changed {
            Span::styled(CHANGED, t.changed())
        } else {
            Span::raw(PLAIN)
        };
        let style = if row.changed {
            row.style.patch(t.changed())
        } else {
            row.style
        };
        for (i, piece) in wrap(&row.text, text_width, row.indent)
            .into_iter()
            .enumerate()
        {
            let g = if i == 0 {
                gutter.clone()
            } else {
                Span::raw(PLAIN)
            };
            lines.push(Line::from(vec![g, Span::styled(piece, style)]));
        }
    }
    let overflow = (lines.len() as u16).saturating_sub(inner.height);
    app.scroll_max.set(overflow);
    app.page_rows.set(inner.height);
    let scroll = app.scroll.min(overflow);
    let mut block = block;
    if overflow > 0 {
        let hint = if scroll == 0 {
            format!(" ↓ {overflow} more · PgDn ")
        } else if scroll < overflow {
            format!(" ↑ {scroll} above · ↓ {} more · PgDn ", overflow - scroll)
        } else {
            format!(" ↑ {scroll} more above · PgUp ")
        };
        block =
            block.title_bottom(Line::from(Span::styled(hint, t.dim())).alignment(Alignment::Right));
    }
    Paragraph::new(lines)
        .scroll((scroll, 0))
        .block(block)
        .render(area, buf);
}

/// The panel's rows on show (the overview or the stage), each as one line
/// and as the lines it wraps into at the panel's width as last drawn.
pub fn wrapped_rows(app: &App) -> Vec<(String, Vec<String>)> {
    let rows = match app.stage() {
        None => overview(app),
        Some(s) => stage_rows(app, s),
    };
    let width = app.panel_width.get() as usize;
    rows.into_iter()
        .map(|r| {
            let lines = wrap(&r.text, width, r.indent);
            (r.text, lines)
        })
        .collect()
}

/// The panel line (after wrapping, as last drawn) where the symbols' list
/// starts on the stage on show, when it lists them.
pub fn symbols_line(app: &App) -> Option<u16> {
    let s = app.stage()?;
    let width = app.panel_width.get() as usize;
    let mut line = 0;
    for row in stage_rows(app, s) {
        if row.text.starts_with(SYMBOLS) {
            return Some(line);
        }
        line += wrap(&row.text, width, row.indent).len() as u16;
    }
    None
}

/// The heading of `s`'s list.
const SYMBOLS: &str = "Symbols in these formulas";

fn overview(app: &App) -> Vec<Row> {
    let t = &app.theme;
    let tr = &app.trace;
    let lesson = &app.entry().lesson;
    let f = &app.fmt;
    let mut rows = vec![Row::new(tr.title.clone(), t.title())];
    if !tr.source.is_empty() {
        rows.push(Row::new(tr.source.clone(), t.dim()));
    }
    rows.push(Row::new(
        format!("Contact {}", tr.contact_label),
        t.formula(),
    ));
    rows.push(Row::new("", Style::new()));
    if app.predict && !tr.summary.is_empty() {
        // The narrative quotes results: keep them for after the prediction.
        rows.push(Row::new(
            "(The lesson's narrative is hidden in predict mode: it quotes results.)",
            t.dim(),
        ));
        rows.push(Row::new("", Style::new()));
    }
    let summary = if app.predict { "" } else { tr.summary.as_str() };
    for para in summary.split("\n\n").filter(|p| !p.trim().is_empty()) {
        rows.push(Row {
            indent: 0,
            ..Row::new(
                para.split_whitespace().collect::<Vec<_>>().join(" "),
                t.note(),
            )
        });
        rows.push(Row::new("", Style::new()));
    }
    rows.push(Row::new("Bodies", t.title()));
    for b in &lesson.bodies {
        let shape = b
            .shape
            .as_ref()
            .map(crate::lesson::shape::describe)
            .unwrap_or_else(|| "no shape".into());
        let text = if b.movable() {
            format!(
                "{}: m = {}, {shape}, v = ({}), ω = ({})",
                b.name,
                f.num(b.mass),
                f.list(b.velocity.as_slice()),
                f.list(b.angular_velocity.as_slice())
            )
        } else {
            format!("{}: immovable (m = ∞), {shape}", b.name)
        };
        rows.push(Row {
            indent: 4,
            ..Row::new(format!("· {text}"), t.formula())
        });
    }
    let edits = &app.entry().edits;
    if !edits.is_empty() {
        rows.push(Row::new("", Style::new()));
        rows.push(Row::new("Edited (r resets)", t.warning()));
        for e in edits {
            rows.push(Row {
                indent: 4,
                ..Row::new(format!("· {e}"), t.warning())
            });
        }
    }
    for w in &tr.warnings {
        rows.push(Row {
            indent: 9,
            ..Row::new(format!("warning: {w}"), t.warning())
        });
    }
    rows.push(Row::new("", Style::new()));
    rows.push(Row::new(
        "→ or Space steps through the stages; ? lists every key.",
        t.dim(),
    ));
    rows
}

/// The lines of a formula: `lhs = rhs`, `= numbers`, `= result`.
fn formula_rows(app: &App, step: &Step, f: &Formula, hide_result: bool) -> Vec<Row> {
    let t = &app.theme;
    let fmt = &app.fmt;
    // The `= …` lines hang under the left-hand side's `=`, unless that
    // leaves less than half the panel for the numbers: then under a short indent.
    let pad = match width(&f.lhs) + 3 {
        pad if 2 * pad > app.panel_width.get() as usize => SHORT_PAD,
        pad => pad,
    };
    let changed = |names: &[&str]| names.iter().any(|n| app.changed(step.id.json_name(), n));
    let mut rows = Vec::new();
    let mut first = true;
    let mut push = |text: String, style: Style, changed: bool| {
        let prefix = if first {
            format!("{} = ", f.lhs)
        } else {
            format!("{} = ", " ".repeat(pad - 3))
        };
        first = false;
        rows.push(Row {
            text: prefix + &text,
            style,
            indent: pad,
            changed,
        });
    };
    if !f.rhs.is_empty() {
        push(f.rhs.to_string(), t.formula(), false);
    }
    let mut last = None;
    if let Some(s) = &f.substituted {
        let text = fmt.fill(s, step, false);
        last = Some(text.clone());
        push(text, t.substituted(), changed(&placeholders(s)));
    }
    if let Some(name) = &f.result {
        if let Some(v) = step.lookup(name) {
            let text = fmt.value(v);
            // The result carries its unit, as in the text output.
            let unit = crate::trace::glossary::unit(step, name);
            if hide_result {
                push("?   (Space reveals)".into(), t.hidden(), false);
            } else if last.as_ref() != Some(&text) {
                push(
                    crate::trace::glossary::with_unit(&text, unit),
                    t.result(),
                    changed(&[name]),
                );
            } else if !unit.is_empty() {
                // The substituted line was the result itself: give it the unit.
                if let Some(row) = rows.last_mut() {
                    row.text = crate::trace::glossary::with_unit(&row.text, unit);
                }
            }
        }
    }
    rows
}

fn stage_rows(app: &App, s: usize) -> Vec<Row> {
    let t = &app.theme;
    let step = &app.trace.stages[s];
    // Why before how: what the stage is for, above its formulas.
    let why = [
        Row {
            indent: 0,
            ..Row::new(step.id.why(), t.note())
        },
        Row::new("", Style::new()),
    ];
    if let Some(reason) = &step.skipped {
        return why
            .into_iter()
            .chain([
            Row::new(format!("Skipped: {reason}"), t.dim()),
            Row::new("", Style::new()),
            Row::new(
                if step.id == crate::physics::StageId::ExactImpact {
                    "The integration is a reference, not part of the lecture's resolver: ask for it with e (edit, exact impact law) or solve --exact."
                } else {
                    "The contact does not need this stage, so the resolver does no work here."
                },
                t.dim(),
            ),
            ])
            .collect();
    }
    let shown = if app.predict {
        app.revealed[s].min(step.formulas.len())
    } else {
        step.formulas.len()
    };
    let mut rows: Vec<Row> = why.into_iter().collect();
    for (i, f) in step.formulas.iter().enumerate() {
        if i > shown {
            break;
        }
        rows.extend(formula_rows(app, step, f, i == shown));
    }
    if app.symbols {
        rows.extend(symbol_rows(app, step, shown));
    }
    if shown < step.formulas.len() {
        let left = step.formulas.len() - shown;
        rows.push(Row::new("", Style::new()));
        rows.push(Row::new(
            format!("predict: {left} result(s) to go in this stage; type your answer and Enter grades it, or Space reveals"),
            t.hidden(),
        ));
        return rows;
    }
    if !step.notes.is_empty() {
        rows.push(Row::new("", Style::new()));
    }
    for note in &step.notes {
        rows.push(Row {
            changed: placeholders(note)
                .iter()
                .any(|n| app.changed(step.id.json_name(), n)),
            ..Row::new(format!("· {}", app.fmt.fill(note, step, false)), t.note())
        });
    }
    rows
}

/// `s`: the symbols of the formulas on show, each with its meaning and unit
/// (from the glossary).
fn symbol_rows(app: &App, step: &Step, shown: usize) -> Vec<Row> {
    let t = &app.theme;
    let text: String = step
        .formulas
        .iter()
        .take(shown + 1)
        .map(|f| format!("{} = {}\n", f.lhs, f.rhs))
        .collect();
    let mut rows = vec![
        Row::new("", Style::new()),
        Row::new(format!("{SYMBOLS} (s hides)"), t.title()),
    ];
    for sym in crate::trace::glossary::symbols_in(&text) {
        let unit = if sym.unit.is_empty() {
            String::new()
        } else {
            format!(" [{}]", sym.unit)
        };
        rows.push(Row {
            indent: 4,
            ..Row::new(
                format!("{}: {}{unit}", sym.symbol, sym.meaning),
                t.formula(),
            )
        });
    }
    rows
}
