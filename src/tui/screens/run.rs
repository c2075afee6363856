//! The run screen: the scene at the frame on show, charts of energy,
//! deepest penetration and awake bodies against time with a cursor at the
//! frame, and the events so far.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, Paragraph, Widget};

use super::picture::{self, Scene};
use super::{Key, RunView, View, EVENT_KINDS, RUN_KEYS};
use crate::trace::run::{Frame, RunTrace};
use crate::trace::{BodyView, ContactView};
use crate::tui::app::App;
use crate::tui::keys::Binding;
use crate::tui::wrap::truncate;

/// Every body of `frame` as the picture draws it.
pub fn body_views(run: &RunTrace, frame: &Frame) -> Vec<BodyView> {
    frame
        .bodies
        .iter()
        .enumerate()
        .map(|(i, b)| BodyView {
            name: run.names.get(i).cloned().unwrap_or_default(),
            movable: run.movable.get(i).copied().unwrap_or(false),
            slot: 0,
            shape: run.shapes.get(i).cloned().flatten(),
            position: b.position,
            orientation: b.orientation,
            position_after: b.position,
            orientation_after: b.orientation,
            velocity: b.velocity,
            velocity_after: b.velocity,
            angular_velocity: b.angular_velocity,
            angular_velocity_after: b.angular_velocity,
        })
        .collect()
}

impl View for RunView {
    fn keys(&self) -> &'static [Binding<Key>] {
        RUN_KEYS
    }

    fn help(&self) -> (&'static str, &'static [&'static str]) {
        (" Keys · run ", &NOTES)
    }

    fn bar(&self) -> &'static [(&'static str, &'static str)] {
        &[
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
        ]
    }

    fn render(&self, app: &App, area: Rect, buf: &mut Buffer) {
        render(app, self, area, buf)
    }
}

/// The help's notes on the run and the resolver.
pub(super) const NOTES: [&str; 4] = [
    "? again (or PgDn): page 2, the glossary of every symbol.",
    "Enter goes down a level: a step → its resolver iterations → an iteration's contact and its stages. Esc or Backspace goes back up.",
    "Mouse: click a contact or a body in the picture, or a table row, to select it; the wheel scrolls.",
    "The contact screen has its own keys (? there).",
];

fn render(app: &App, run: &RunView, area: Rect, buf: &mut Buffer) {
    let trace = &run.player.run;
    let frame = &trace.frames[run.frame];
    let events_h = (area.height / 5).clamp(3, 7);
    let [main, events] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(events_h)]).areas(area);
    let side = (main.width * 2 / 5).clamp(20, 60);
    let [pic, charts] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(side)]).areas(main);
    let bodies = body_views(trace, frame);
    let first = body_views(trace, &trace.frames[0]);
    let contacts: Vec<ContactView> = frame
        .contact_points
        .iter()
        .enumerate()
        .map(|(k, (point, normal))| ContactView {
            number: k,
            bodies: [None, None],
            point: *point,
            normal: *normal,
            penetration: 0.0,
            impulse: None,
        })
        .collect();
    let legend = if frame.movement.is_empty() || !run.toggles.bounds {
        ""
    } else {
        ", movement bounds (m)"
    };
    let scene = Scene {
        title: format!(
            "{} contact(s), {} awake{legend}",
            frame.contacts, frame.awake
        ),
        asleep: frame
            .bodies
            .iter()
            .zip(&trace.movable)
            .map(|(b, m)| *m && !b.awake)
            .collect(),
        bodies: &bodies,
        contacts: &contacts,
        next: None,
        selected: None,
        toggles: run.toggles,
        also: &first,
        movement: &frame.movement,
    };
    picture::render(app, &scene, pic, buf);
    render_charts(app, run, charts, buf);
    render_events(app, run, events, buf);
}

fn render_charts(app: &App, run: &RunView, area: Rect, buf: &mut Buffer) {
    let trace = &run.player.run;
    let [a, b, c] = Layout::vertical([Constraint::Fill(1); 3]).areas(area);
    let t_end = (run.player.steps as f64 * trace.dt).max(trace.dt);
    let now = trace.frames[run.frame].time;
    let series = |get: &dyn Fn(&Frame) -> f64| -> Vec<(f64, f64)> {
        trace.frames.iter().map(|f| (f.time, get(f))).collect()
    };
    chart(
        app,
        "energy J: kinetic, potential",
        vec![
            (series(&|f| f.kinetic_energy), Color::Cyan),
            (series(&|f| f.potential_energy), Color::Yellow),
        ],
        now,
        t_end,
        a,
        buf,
    );
    chart(
        app,
        "deepest penetration m",
        vec![(series(&|f| f.max_penetration), Color::Magenta)],
        now,
        t_end,
        b,
        buf,
    );
    chart(
        app,
        "awake bodies",
        vec![(series(&|f| f.awake as f64), Color::Green)],
        now,
        t_end,
        c,
        buf,
    );
}

/// A small line chart with a vertical cursor at `now` (x from 0 to `x_end`).
pub fn chart(
    app: &App,
    title: &str,
    series: Vec<(Vec<(f64, f64)>, Color)>,
    now: f64,
    x_end: f64,
    area: Rect,
    buf: &mut Buffer,
) {
    let t = &app.theme;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (points, _) in &series {
        for (_, y) in points.iter().filter(|p| p.1.is_finite()) {
            lo = lo.min(*y);
            hi = hi.max(*y);
        }
    }
    if lo > hi {
        (lo, hi) = (0.0, 1.0);
    }
    // Counts and sizes from zero.
    lo = lo.min(0.0);
    if hi - lo < 1e-12 {
        hi = lo + 1e-12f64.max(lo.abs() * 1e-6);
    }
    let cursor = [(now, lo), (now, hi)];
    let colour = |c: Color| {
        if t.color {
            Style::new().fg(c)
        } else {
            Style::new()
        }
    };
    let mut sets: Vec<Dataset> = series
        .iter()
        .map(|(points, c)| {
            Dataset::default()
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(colour(*c))
                .data(points)
        })
        .collect();
    sets.push(
        Dataset::default()
            .marker(Marker::Braille)
            .graph_type(GraphType::Line)
            .style(colour(Color::Red))
            .data(&cursor),
    );
    let f = crate::format::Fmt::new(3);
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(format!(" {title} "), t.title()));
    Chart::new(sets)
        .block(block)
        .x_axis(Axis::default().bounds([0.0, x_end]))
        .y_axis(
            Axis::default()
                .bounds([lo, hi])
                .labels([Span::raw(f.num(lo)), Span::raw(f.num(hi))]),
        )
        .render(area, buf);
}

/// An event as the list shows it: time, step, what happened.
pub fn event_line(e: &crate::trace::run::EventLine) -> String {
    format!("{:>8.3} s  {:>5}  {}", e.time, e.step, e.text)
}

fn render_events(app: &App, run: &RunView, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let trace = &run.player.run;
    let step = run.frame as u64;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(
                " Events · n/N jump to {} (f) · {} ",
                EVENT_KINDS[run.event_kind],
                match &trace.stopped {
                    Some(why) => why.clone(),
                    None => format!(
                        "{} of {} steps computed",
                        trace.frames.len() - 1,
                        run.player.steps
                    ),
                }
            ),
            t.title(),
        ));
    let inner = block.inner(area);
    block.render(area, buf);
    let shown = trace.events.iter().filter(|e| e.step <= step).count();
    let rows = inner.height as usize;
    let end = shown.saturating_sub(run.events_scroll.min(shown.saturating_sub(rows.min(shown))));
    let start = end.saturating_sub(rows);
    run.events_shown.set((start, end));
    let w = inner.width as usize;
    let lines: Vec<Line> = trace.events[start..end]
        .iter()
        .map(|e| {
            let style = if e.step == step {
                t.selected()
            } else {
                Style::new()
            };
            Line::styled(truncate(&event_line(e), w), style)
        })
        .collect();
    let cut = trace.events[start..end]
        .iter()
        .any(|e| crate::tui::wrap::width(&event_line(e)) > w);
    if lines.is_empty() {
        Paragraph::new(Line::styled("no events yet: Space plays, → steps", t.dim()))
            .render(inner, buf);
    } else {
        Paragraph::new(lines).render(inner, buf);
    }
    let (above, below) = (start, shown - end);
    crate::tui::more::mark(app, area, above, below, buf);
    if cut {
        // Where the list cuts an event, say how to read it whole.
        let hint = " i: in full ";
        if area.width as usize > crate::tui::wrap::width(hint) + 2 {
            buf.set_string(area.x + 1, area.bottom() - 1, hint, t.dim());
        }
    }
}
