//! The resolver screen: the scene with its contacts numbered (the one the
//! next iteration takes in red), the contact table at the stop on show (the
//! values the last iteration changed highlighted with their change), a
//! convergence chart with a cursor, and what the iteration does in words,
//! with a note when a phase reached its iteration limit.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::picture::{self, Scene};
use super::run::chart;
use super::run::NOTES;
use super::{Key, ResolverView, Toggles, View, RESOLVER_KEYS};
use crate::format::Fmt;
use crate::physics::resolver::Phase;
use crate::tui::app::App;
use crate::tui::keys::Binding;
use crate::tui::wrap::truncate;

impl View for ResolverView {
    fn keys(&self) -> &'static [Binding<Key>] {
        RESOLVER_KEYS
    }

    fn help(&self) -> (&'static str, &'static [&'static str]) {
        (" Keys · resolver ", &NOTES)
    }

    fn bar(&self) -> &'static [(&'static str, &'static str)] {
        if self.trace.substeps.is_some() {
            return super::resolver_substeps::BAR;
        }
        &[
            ("←→", "iteration"),
            ("⇥", "contact"),
            ("Enter", "stages"),
            ("Esc", "up"),
            ("?", "help"),
            ("q", "quit"),
        ]
    }

    fn render(&self, app: &App, area: Rect, buf: &mut Buffer) {
        render(app, self, area, buf)
    }

    fn up_note(&self) -> &'static str {
        "Esc or Backspace: up to the resolver iterations this contact came from."
    }
}

fn render(app: &App, r: &ResolverView, area: Rect, buf: &mut Buffer) {
    // A step of the soft step or XPBD: its own record, substep by substep.
    if let Some(rec) = &r.trace.substeps {
        return super::resolver_substeps::render(app, r, rec, area, buf);
    }
    let left_w = (area.width * 9 / 20).max(20);
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_w), Constraint::Fill(1)]).areas(area);
    let [pic, conv] =
        Layout::vertical([Constraint::Percentage(60), Constraint::Fill(1)]).areas(left);
    let note_h = (area.height / 4).clamp(3, 7);
    let [table, note] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(note_h)]).areas(right);
    let bodies = r.trace.bodies_at(r.stop);
    let contacts = r.trace.contact_views(r.stop);
    let scene = Scene {
        title: format!("{} contact(s)", contacts.len()),
        asleep: vec![],
        bodies: &bodies,
        contacts: &contacts,
        next: r.trace.tables[r.stop].next,
        selected: Some(r.selected),
        toggles: Toggles::default(),
        also: &[],
        movement: &[],
    };
    picture::render(app, &scene, pic, buf);
    convergence(app, r, conv, buf);
    if !super::resolver_lcp::render(app, r, table, note, buf) {
        render_table(app, r, table, buf);
        render_note(app, r, note, buf);
    }
}

fn convergence(app: &App, r: &ResolverView, area: Rect, buf: &mut Buffer) {
    let max = |v: &[f64]| {
        v.iter()
            .copied()
            .filter(|x| x.is_finite())
            .fold(0.0f64, f64::max)
    };
    let mut pen = vec![];
    let mut dv = vec![];
    for (i, t) in r.trace.tables.iter().enumerate() {
        // A huge step keeps no whole table here: the value the iteration took.
        let elided = |log: &[crate::trace::resolver::Iteration]| {
            log.get(t.stop.iteration).map_or(0.0, |it| it.value)
        };
        match t.stop.phase {
            Phase::Position if t.elided => {
                pen.push((i as f64, elided(&r.trace.resolver.position.log)))
            }
            Phase::Velocity if t.elided => {
                dv.push((i as f64, elided(&r.trace.resolver.velocity.log)))
            }
            Phase::Position => pen.push((i as f64, max(&t.penetration))),
            Phase::Velocity => dv.push((i as f64, max(&t.desired))),
        }
    }
    let end = (r.trace.tables.len().max(2) - 1) as f64;
    chart(
        app,
        "deepest penetration, then largest Δv",
        vec![(pen, Color::Magenta), (dv, Color::Cyan)],
        r.stop as f64,
        end,
        area,
        buf,
    );
}

fn render_table(app: &App, r: &ResolverView, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let f = Fmt::new(4);
    let table = &r.trace.tables[r.stop];
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            " Contacts · ▶ taken next · ⇥ selects · Enter opens ",
            t.title(),
        ));
    let inner = block.inner(area);
    block.render(area, buf);
    app.targets.table.set(area);
    if table.elided {
        render_elided_table(app, r, inner, buf);
        return;
    }
    let rows = (inner.height as usize).saturating_sub(1);
    let n = table.penetration.len();
    // Keep the selected and the next contact in view.
    let mut first = r.scroll.get().min(n.saturating_sub(rows));
    for k in [Some(r.selected), table.next].into_iter().flatten() {
        if k < first {
            first = k;
        } else if rows > 0 && k >= first + rows {
            first = k + 1 - rows;
        }
    }
    r.scroll.set(first);
    app.targets.table_first.set(first);
    // Wide: both columns and the change; narrow: the phase's column and the change.
    let active = table.stop.phase;
    let wide = inner.width >= 2 + 12 + 2 * 13 + 10;
    let columns: Vec<Phase> = if wide {
        vec![Phase::Position, Phase::Velocity]
    } else {
        vec![active]
    };
    let label_w = (inner.width as usize)
        .saturating_sub(2 + columns.len() * 13 + 10)
        .clamp(4, 30);
    let heading = |p: Phase| match p {
        Phase::Position => "penetration",
        Phase::Velocity => "desired Δv",
    };
    let mut head = format!("  {:label_w$}", "contact");
    for p in &columns {
        head.push_str(&format!("  {:<11}", heading(*p)));
    }
    head.push_str("  change");
    let mut lines = vec![Line::styled(head, t.dim())];
    for k in first..(first + rows).min(n) {
        let label = r.trace.names.contacts.get(k).cloned().unwrap_or_default();
        let mark = if table.next == Some(k) { "▶ " } else { "  " };
        let row_style = if k == r.selected {
            t.selected()
        } else {
            Style::new()
        };
        let change = table
            .changed
            .iter()
            .rev()
            .find(|c| c.0 == k)
            .map(|c| c.2 - c.1);
        let mut spans = vec![
            Span::styled(mark, t.ink_style(crate::tui::theme::Ink::Impulse)),
            Span::styled(format!("{:label_w$}", truncate(&label, label_w)), row_style),
        ];
        for p in &columns {
            let value = match p {
                Phase::Position => table.penetration[k],
                Phase::Velocity => table.desired[k],
            };
            let style = if *p == active && change.is_some() {
                t.changed()
            } else {
                Style::new()
            };
            spans.push(Span::raw("  "));
            spans.push(Span::styled(
                format!("{:<11}", truncate(&f.num(value), 11)),
                style,
            ));
        }
        if let Some(d) = change {
            let sign = if d >= 0.0 { "+" } else { "" };
            spans.push(Span::styled(format!("  {sign}{}", f.num(d)), t.changed()));
        }
        lines.push(Line::from(spans));
    }
    Paragraph::new(lines).render(inner, buf);
    let (above, below) = crate::tui::more::hidden(n, first, rows);
    crate::tui::more::mark(app, area, above, below, buf);
}

/// A huge step's stop whose whole table was not kept: what it says, then
/// the rows the last iteration changed (when kept) and the one taken next.
fn render_elided_table(app: &App, r: &ResolverView, inner: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let f = Fmt::new(4);
    let table = &r.trace.tables[r.stop];
    let phase = match table.stop.phase {
        Phase::Position => &r.trace.resolver.position,
        Phase::Velocity => &r.trace.resolver.velocity,
    };
    let what = match table.stop.phase {
        Phase::Position => "penetration",
        Phase::Velocity => "desired Δv",
    };
    let last = table
        .stop
        .iteration
        .checked_sub(1)
        .and_then(|i| phase.log.get(i));
    let mut lines = vec![Line::styled(
        format!(
            "Table elided: a huge step ({} contacts) keeps the whole table at each phase's first and last stop only.",
            r.trace.names.contacts.len()
        ),
        t.warning(),
    )];
    let shown = r.trace.bodies_stop(r.stop);
    if shown != r.stop {
        lines.push(Line::styled(
            format!("The picture shows the bodies as at stop {shown} (the recording elided the later ones)."),
            t.dim(),
        ));
    }
    let label = |k: usize| r.trace.names.contacts.get(k).cloned().unwrap_or_default();
    if let Some(k) = table.next {
        lines.push(Line::from(vec![
            Span::styled("▶ ", t.ink_style(crate::tui::theme::Ink::Impulse)),
            Span::raw(format!(
                "{}  {what} {}",
                label(k),
                f.num(phase.log[table.stop.iteration].value)
            )),
        ]));
    }
    if let Some(it) = last {
        let rows = if it.elided {
            format!(
                "Last iteration changed {} other contact(s), {} for the worse; its rows elided (kept at iterations 0, {}, {}, …):",
                it.changed,
                it.worse,
                r.trace.resolver.elision.map_or(1, |e| e.every),
                r.trace.resolver.elision.map_or(2, |e| 2 * e.every)
            )
        } else {
            format!("Last iteration changed {} other contact(s):", it.changed)
        };
        lines.push(Line::styled(rows, t.dim()));
        for c in &table.changed {
            lines.push(Line::from(vec![
                Span::raw(format!("  {}  ", label(c.0))),
                Span::styled(f.change(c.1, c.2), t.changed()),
            ]));
        }
    }
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .render(inner, buf);
}

fn render_note(app: &App, r: &ResolverView, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let f = Fmt::new(4);
    let table = &r.trace.tables[r.stop];
    let stop = table.stop;
    let phase = match stop.phase {
        Phase::Position => &r.trace.resolver.position,
        Phase::Velocity => &r.trace.resolver.velocity,
    };
    let (name, what) = match stop.phase {
        Phase::Position => ("position", "penetration"),
        Phase::Velocity => ("velocity", "desired Δv"),
    };
    let mut lines = vec![];
    match phase.log.get(stop.iteration) {
        Some(it) => lines.push(Line::styled(
            format!(
                "Next: {name} iteration {} takes contact {} at {what} {} ({}).",
                it.iteration,
                it.contact,
                f.num(it.value),
                match phase.solver {
                    crate::physics::Solver::SequentialImpulse =>
                        "sequential impulses visit the contacts in turn".to_string(),
                    _ => format!("the largest above ε = {}", f.num(phase.epsilon)),
                }
            ),
            t.title(),
        )),
        None if phase.limit_reached => lines.push(Line::styled(
            format!(
                "Iteration limit {} of the {name} phase reached: largest {what} left {} at contact {}.",
                phase.iteration_limit,
                f.num(phase.max_after),
                phase.max_after_contact
            ),
            t.warning(),
        )),
        None => lines.push(Line::raw(format!(
            "The {name} phase is done after {} iteration(s): every {what} is within ε = {}.",
            phase.iterations_used,
            f.num(phase.epsilon)
        ))),
    }
    if let Some(prev) = stop.iteration.checked_sub(1).and_then(|i| phase.log.get(i)) {
        lines.push(Line::raw(format!(
            "Last: {name} iteration {} took contact {}: {what} {}; it changed {} other contact(s), {} for the worse.",
            prev.iteration,
            prev.contact,
            f.change(prev.value, prev.own_after),
            prev.changed,
            prev.worse
        )));
    }
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" Stop {} of {} ", r.stop, r.trace.tables.len() - 1),
            t.title(),
        ));
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(block)
        .render(area, buf);
}
