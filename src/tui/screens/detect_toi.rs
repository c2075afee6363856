//! The detection screen's time of collision (`t`): the trial on show of
//! the pair's search over the next step, the outcome, and which search it
//! is (the scene's continuous detection, bisection when it runs none, or
//! `m`'s switch). It reads the trace `session` built: no physics here.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use crate::physics::detect::ToiMethod;
use crate::render::toi::{outcome_line, test_line};
use crate::trace::toi::{method_words, DetectToi};
use crate::tui::app::App;

/// The pair's time-of-collision trial on show and the outcome.
/// `pair`: its two bodies' names; `search`: the search on show and the
/// scene's (`None`: it runs no continuous detection).
pub fn render(
    app: &App,
    toi: &DetectToi,
    trial: usize,
    pair: (&str, &str),
    search: (ToiMethod, Option<ToiMethod>),
    area: Rect,
    buf: &mut Buffer,
) {
    let t = &app.theme;
    let f = &app.fmt;
    let mut lines = vec![
        Line::from(format!(
            "Step {} (t = {} s to {} s), by {}.",
            toi.step,
            f.num(toi.time),
            f.num(toi.time + toi.dt),
            method_words(toi.method)
        )),
        Line::styled(method_origin(search), t.dim()),
    ];
    let title = match toi.pairs.first() {
        None => {
            lines.push(Line::from(
                "The pair's movement bounds do not meet over the step: nothing to search.",
            ));
            "time of collision".to_string()
        }
        Some(p) => {
            // The scan's pieces first, then the trials: every test the
            // command prints, as many as the outcome counts.
            let tests = p.record.tests();
            let n = tests.len();
            lines.push(Line::from(format!(
                "Movement bounds: swept AABBs overlap: {}; swept spheres meet: {}.",
                yes(p.aabbs_overlap),
                yes(p.spheres_meet)
            )));
            lines.push(Line::from(""));
            match tests.get(trial) {
                Some(x) => lines.push(Line::from(format!(
                    "Test {} of {n}: {}",
                    trial + 1,
                    test_line(p, x, f)
                ))),
                None => lines.push(Line::styled(
                    match n {
                        0 => "No test: the search ended before its first.".to_string(),
                        1 => "The one test done.".to_string(),
                        n => format!("All {n} tests done."),
                    },
                    t.dim(),
                )),
            }
            lines.push(Line::from(""));
            lines.push(Line::styled("Result", t.title()));
            lines.push(Line::from(outcome_line(p, f)));
            match trial < n {
                true => format!("time of collision · test {} of {n}", trial + 1),
                false => "time of collision · result".into(),
            }
        }
    };
    let (a, b) = pair;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" {a} – {b} · {title} · ←→ "),
            t.title(),
        ));
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block)
        .render(area, buf);
}

/// Where the search comes from: the scene's continuous detection, the
/// default when it runs none, or `m`.
fn method_origin((method, scene): (ToiMethod, Option<ToiMethod>)) -> String {
    let name = super::detect_nav::method_name;
    match scene {
        Some(m) if m == method => format!(
            "The scene's continuous detection (its ccd knob) searches by {}; m: the other search.",
            name(m)
        ),
        None if method == ToiMethod::Bisection => {
            "The scene runs no continuous detection (ccd none): bisection, the lecture's; m: conservative advancement.".into()
        }
        Some(m) => format!(
            "m switched from the scene's search ({}, its ccd knob).",
            name(m)
        ),
        None => "m switched from bisection (the scene runs no continuous detection).".into(),
    }
}

fn yes(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}
