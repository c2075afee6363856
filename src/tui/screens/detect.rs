//! The detection screen: the step's pairs (kept by the broad phase or ruled
//! out, and why), the selected pair's GJK then EPA iterations one at a time
//! as `contact-lab detect` prints their rows, the result, and the pair
//! drawn with the iteration's support points; `t`: its time-of-collision
//! trials ([`super::detect_toi`]), and beside the shapes A - B
//! ([`super::detect_minkowski`]). It reads the traces `session` built: no
//! physics here.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::picture::{self, Scene};
use super::{detect_minkowski, detect_toi};
use super::{DetectView, Key, Shown, Toggles, View, DETECT_KEYS};
use crate::render::detect::steps::{result_lines, stop_lines, stops, Stop};
use crate::trace::detect::{DetectTrace, PairTrace, V3};
use crate::trace::{BodyView, ContactView};
use crate::tui::app::App;
use crate::tui::keys::Binding;
use crate::tui::wrap::truncate;

impl View for DetectView {
    fn keys(&self) -> &'static [Binding<Key>] {
        DETECT_KEYS
    }

    fn help(&self) -> (&'static str, &'static [&'static str]) {
        (" Keys · detection ", &NOTES)
    }

    fn bar(&self) -> &'static [(&'static str, &'static str)] {
        if self.toi.is_some() {
            return &[
                ("↑↓", "pair"),
                ("←→", "test"),
                ("t Esc", "iterations"),
                ("?", "help"),
                ("q", "quit"),
            ];
        }
        &[
            ("↑↓", "pair"),
            ("←→", "iteration"),
            ("Enter", "stages"),
            ("x", "picture"),
            ("t", "time of collision"),
            ("Esc", "run"),
            ("?", "help"),
            ("q", "quit"),
        ]
    }

    fn render(&self, app: &App, area: Rect, buf: &mut Buffer) {
        render(app, self, area, buf)
    }

    fn up_note(&self) -> &'static str {
        "Esc or Backspace: back to the detection this contact came from."
    }
}

const NOTES: [&str; 3] = [
    "? again (or PgDn): page 2, the glossary of every symbol.",
    "A - B: the Minkowski difference seen in the view plane through the origin O, with the iteration's simplex (• kept, ✗ dropped), w_k, v_k and d_k; at the result -δn (the penetration) or v (the distance). x puts it beside the shapes, alone, or hides it.",
    "The iterations are the rows contact-lab detect --step N prints; the time of collision is detect --toi's (docs/detect.md, docs/ccd.md).",
];

fn render(app: &App, d: &DetectView, area: Rect, buf: &mut Buffer) {
    let side = (area.width * 11 / 20).clamp(30, 100);
    let [left, right] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(side)]).areas(area);
    let rows = (d.trace.pairs.len() + d.trace.dropped.len()) as u16 + 2;
    let [list, pic] = Layout::vertical([
        Constraint::Length(rows.clamp(3, (left.height / 2).max(3))),
        Constraint::Fill(1),
    ])
    .areas(left);
    render_pairs(app, d, list, buf);
    render_pictures(app, d, pic, buf);
    match &d.toi {
        Some((toi, trial)) => {
            let (a, b, _) = d.selected().unwrap_or(("", "", false));
            let search = (d.method, d.scene_method);
            detect_toi::render(app, &toi.trace, *trial, (a, b), search, right, buf)
        }
        None => render_stops(app, d, right, buf),
    }
}

/// The pairs: those the broad phase kept (selectable), then those it ruled out.
fn render_pairs(app: &App, d: &DetectView, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let tr = &d.trace;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(
                " Pairs · {} kept, {} ruled out (↑↓) ",
                tr.candidate_pairs,
                tr.dropped.len()
            ),
            t.title(),
        ));
    let inner = block.inner(area);
    block.render(area, buf);
    let w = inner.width as usize;
    let mut lines: Vec<Line> = tr
        .pairs
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let text = format!("{} {} – {}: {}", mark(k == d.pair), p.a, p.b, verdict(p));
            let style = if k == d.pair {
                t.selected()
            } else {
                ratatui::style::Style::new()
            };
            Line::styled(truncate(&text, w), style)
        })
        .collect();
    let kept = tr.pairs.len();
    lines.extend(tr.dropped.iter().enumerate().map(|(k, x)| {
        let chosen = kept + k == d.pair;
        Line::styled(
            truncate(
                &format!(
                    "{} {} – {}: ruled out, {}",
                    mark(chosen),
                    x.a,
                    x.b,
                    x.reason
                ),
                w,
            ),
            if chosen { t.selected() } else { t.dim() },
        )
    }));
    // Keep the selected pair in view.
    let skip = d
        .pair
        .saturating_sub(inner.height.saturating_sub(1) as usize);
    let (above, below) = crate::tui::more::hidden(lines.len(), skip, inner.height as usize);
    Paragraph::new(lines.into_iter().skip(skip).collect::<Vec<_>>()).render(inner, buf);
    crate::tui::more::mark(app, area, above, below, buf);
}

fn mark(selected: bool) -> &'static str {
    if selected {
        "▸"
    } else {
        " "
    }
}

/// A kept pair's outcome in a few words.
fn verdict(p: &PairTrace) -> String {
    let found = match p.contacts.len() {
        0 => "no contact".to_string(),
        1 => "1 contact".to_string(),
        n => format!("{n} contacts"),
    };
    match &p.gjk {
        Some(g) => format!("{}, GJK {}, {found}", p.method, g.result),
        None => format!("{}, {found}", p.method),
    }
}

/// The selected pair's iteration on show and its result.
fn render_stops(app: &App, d: &DetectView, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let f = &app.fmt;
    let Some(p) = d.narrow() else {
        let text = match d.trace.dropped.get(d.pair - d.trace.pairs.len()) {
            Some(x) => format!(
                "{} – {}: the broad phase rules this pair out ({}), so no GJK or EPA runs for it (contact-lab detect --pair {},{} runs it anyway).\n\nt: its time of collision over the next step.",
                x.a, x.b, x.reason, x.a, x.b
            ),
            None => "This step has no pair of bodies.".into(),
        };
        let block = Block::bordered()
            .border_style(t.border())
            .title(Span::styled(" Broad phase ", t.title()));
        Paragraph::new(text)
            .wrap(Wrap { trim: false })
            .block(block)
            .render(area, buf);
        return;
    };
    let all = stops(p);
    let mut lines: Vec<Line> = vec![];
    if let Some(why) = &p.forced {
        lines.push(Line::styled(format!("{why}."), t.dim()));
    }
    let title = match all.get(d.stop) {
        Some(stop) => {
            let (title, rows) = stop_lines(p, *stop, f);
            lines.extend(rows.into_iter().map(Line::from));
            title
        }
        None if all.is_empty() => {
            lines.push(Line::styled(
                format!(
                    "No GJK or EPA iterations: the {} routine decides.",
                    p.method
                ),
                t.dim(),
            ));
            "result".into()
        }
        None => "result".into(),
    };
    lines.push(Line::from(""));
    lines.push(Line::styled("Result", t.title()));
    lines.extend(result_lines(p, f).into_iter().map(Line::from));
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" {} – {} ({}) · {title} · ←→ ", p.a, p.b, p.method),
            t.title(),
        ));
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block)
        .render(area, buf);
}

/// The shapes and A - B (`x`): side by side in a wide area, one above the
/// other in a tall one; the shapes alone where two do not fit.
fn render_pictures(app: &App, d: &DetectView, area: Rect, buf: &mut Buffer) {
    // A cell is about twice as tall as it is wide.
    let wide = area.width >= 2 * area.height;
    let fits = if wide {
        area.width >= 2 * 16
    } else {
        area.height >= 2 * 6
    };
    match d.shown {
        Shown::Both if fits => {
            let halves = [Constraint::Fill(1), Constraint::Fill(1)];
            let [one, two] = if wide {
                Layout::horizontal(halves).areas(area)
            } else {
                Layout::vertical(halves).areas(area)
            };
            render_picture(app, d, one, buf);
            minkowski(app, d, two, buf);
        }
        Shown::Both | Shown::Shapes => render_picture(app, d, area, buf),
        Shown::Difference => minkowski(app, d, area, buf),
    }
}

/// The selected pair alone, with the iteration's support points (s_A(d_k)
/// on A, s_B(-d_k) on B) or, at the result, its contact points.
fn render_picture(app: &App, d: &DetectView, area: Rect, buf: &mut Buffer) {
    let tr = &d.trace;
    let Some((a, b, _)) = d.selected() else {
        return;
    };
    let mut bodies: Vec<BodyView> = [a, b].iter().filter_map(|name| body(tr, name)).collect();
    let mut what = String::new();
    let (marks, said): (Vec<V3>, &str) = match (&d.toi, d.narrow()) {
        (Some((run, trial)), _) => {
            // The pair where the search puts it at the trial's time (or at
            // the time of collision, or the step's end, after the trials).
            let p = run.trace.pairs.first();
            let time = match p.and_then(|p| p.record.tests().get(*trial).copied()) {
                Some(x) => x.time(),
                None => p.and_then(|p| p.time).unwrap_or(run.trace.dt),
            };
            if bodies.len() == 2 {
                for (v, (x, q)) in bodies.iter_mut().zip(run.poses_at(time)) {
                    v.position = x;
                    v.orientation = q;
                }
                what = format!("t = {} s", app.fmt.num(time));
            }
            (vec![], "")
        }
        (None, None) => (vec![], "at the step's start"),
        (None, Some(p)) => marks(p, d.stop),
    };
    if what.is_empty() {
        what = said.to_string();
    }
    let contacts: Vec<ContactView> = marks
        .iter()
        .enumerate()
        .map(|(k, point)| ContactView {
            number: k,
            bodies: [None, None],
            point: *point,
            normal: [0.0; 3],
            penetration: 0.0,
            impulse: None,
        })
        .collect();
    // At the result: the contacts numbered, the one Enter opens selected.
    let at_result = d.toi.is_none() && said == "• contacts" && !contacts.is_empty();
    let scene = Scene {
        title: format!("{a} – {b} · {what}"),
        asleep: vec![false; bodies.len()],
        bodies: &bodies,
        contacts: &contacts,
        next: None,
        selected: at_result.then_some(d.contact),
        toggles: Toggles {
            contacts: true,
            normals: false,
            sleep: false,
            names: true,
            bounds: false,
        },
        also: &[],
        movement: &[],
    };
    picture::render(app, &scene, area, buf);
}

/// The body `name` as the trace has it drawn.
fn body(tr: &DetectTrace, name: &str) -> Option<BodyView> {
    let b = tr.drawn.iter().find(|b| b.name == name)?;
    Some(BodyView {
        name: b.name.clone(),
        movable: true,
        slot: 0,
        shape: b.shape.clone(),
        position: b.position,
        orientation: b.orientation,
        position_after: b.position,
        orientation_after: b.orientation,
        velocity: [0.0; 3],
        velocity_after: [0.0; 3],
        angular_velocity: [0.0; 3],
        angular_velocity_after: [0.0; 3],
    })
}

/// The points the picture marks at stop `stop` of the kept pair `p`, and
/// what they are.
fn marks(p: &PairTrace, stop: usize) -> (Vec<V3>, &'static str) {
    match stops(p).get(stop) {
        Some(Stop::Node(_) | Stop::Triangle(_)) => {
            (vec![], "the mesh's mid phase: no support points")
        }
        Some(Stop::Gjk(k)) => {
            let it = &p.gjk.as_ref().map(|g| &g.iterations[*k]);
            (
                it.map_or(vec![], |it| vec![it.support_a, it.support_b]),
                "• s_A(d_k), s_B(-d_k)",
            )
        }
        Some(Stop::Epa(k)) => {
            let it = &p.epa.as_ref().map(|e| &e.iterations[*k]);
            (
                it.map_or(vec![], |it| vec![it.support_a, it.support_b]),
                "• s_A(n_k), s_B(-n_k)",
            )
        }
        None => match (&p.gjk, p.contacts.is_empty()) {
            (Some(g), true) if g.closest.is_some() => {
                (g.closest.map_or(vec![], |c| c.to_vec()), "• closest points")
            }
            _ => (p.contacts.iter().map(|c| c.point).collect(), "• contacts"),
        },
    }
}

/// A - B of the selected pair at the stop on show.
fn minkowski(app: &App, d: &DetectView, area: Rect, buf: &mut Buffer) {
    let (pair, plane) = (d.narrow(), d.trace.plane);
    detect_minkowski::render(app, pair, plane, d.stop, d.toi.is_some(), area, buf);
}
