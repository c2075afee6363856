//! The resolver screen under `solver = "lcp"`: the simultaneous velocity
//! phase stepped pivot by pivot with the keys the screen steps iterations
//! with. After the position phase's stops come A and b, then each pivot of
//! Lemke's method (entering, leaving, the tableau's column, the ratio test,
//! λ so far), then the impulses applied and the bodies after.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::{Key, ResolverView};
use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::lcp::{Pivot, Problem, Record, Var};
use crate::render::resolve::lcp::{notes, pivot_line, ratio_test};
use crate::tui::app::App;

/// One pivot of the record: its problem, and its index there and overall.
struct At<'a> {
    problem: &'a Problem<f64>,
    local: usize,
    pivot: &'a Pivot<f64>,
}

/// Pivot `k` of the record (counted over every problem, in order).
fn pivot_at(record: &Record<f64>, k: usize) -> Option<At<'_>> {
    let mut left = k;
    for problem in &record.problems {
        if let Some(pivot) = problem.pivots.get(left) {
            return Some(At {
                problem,
                local: left,
                pivot,
            });
        }
        left -= problem.pivots.len();
    }
    None
}

impl ResolverView {
    fn lcp(&self) -> Option<&Record<f64>> {
        self.trace.resolver.lcp.as_ref()
    }

    /// The screen's stops under lcp, in order: the position phase's, then
    /// (velocity phase's first stop, Some(j)) for A and b (j = 0) and each
    /// pivot (j = 1, 2, …), then the last stop (the bodies after). None
    /// without an LCP, or when the velocity phase's stops were not kept.
    fn lcp_stops(&self) -> Option<Vec<(usize, Option<usize>)>> {
        let record = self.lcp()?;
        let start = self.trace.velocity_start();
        let last = self.trace.tables.len().checked_sub(1)?;
        if start > last || self.trace.tables.iter().any(|t| t.elided) {
            return None;
        }
        let pivots = record.pivots().count();
        let mut stops: Vec<_> = (0..start).map(|s| (s, None)).collect();
        stops.extend((0..=pivots).map(|j| (start, Some(j))));
        stops.push((last, None));
        Some(stops)
    }

    /// A stepping key under lcp: moves along [`Self::lcp_stops`] and says
    /// so (false: not an LCP resolution or not a stepping key).
    pub(crate) fn lcp_key(&mut self, action: Key) -> bool {
        let Some(stops) = self.lcp_stops() else {
            return false;
        };
        let here = (self.stop, self.pivot);
        let at = stops
            .iter()
            .position(|&s| s == here)
            .or_else(|| stops.iter().rposition(|&(s, _)| s <= self.stop))
            .unwrap_or(0);
        let to = match action {
            Key::Forward => (at + 1).min(stops.len() - 1),
            Key::Back => at.saturating_sub(1),
            Key::First => 0,
            Key::Last => stops.len() - 1,
            _ => return false,
        };
        (self.stop, self.pivot) = stops[to];
        if let Some(k) = self.trace.tables[self.stop].next {
            self.selected = k;
        }
        true
    }

    /// The breadcrumb's level on an LCP stop.
    pub(crate) fn lcp_crumb(&self) -> Option<String> {
        let j = self.pivot?;
        Some(match j {
            0 => "lcp: A and b".to_string(),
            j => format!("lcp pivot {}", j - 1),
        })
    }
}

/// Draws the LCP's panel and note when the stop on show is one of its
/// (false: the screen's own table and note are drawn).
pub(super) fn render(
    app: &App,
    r: &ResolverView,
    table: Rect,
    note: Rect,
    buf: &mut Buffer,
) -> bool {
    let Some(record) = r.lcp() else {
        return false;
    };
    let last = r.trace.tables.len() - 1;
    let (body, words) = match r.pivot {
        Some(j) => (pivot_lines(app, record, j), pivot_note(record, j)),
        None if r.stop == last && r.lcp_stops().is_some() => {
            (after_lines(app, r, record), after_note(record))
        }
        None => return false,
    };
    let t = &app.theme;
    let title = match r.pivot {
        Some(0) => " Simultaneous impact · A and b ".to_string(),
        Some(j) => format!(
            " Simultaneous impact · pivot {} of {} ",
            j - 1,
            record.pivots().count()
        ),
        None => " Simultaneous impact · after ".to_string(),
    };
    Paragraph::new(body)
        .wrap(Wrap { trim: false })
        .block(
            Block::bordered()
                .border_style(t.border())
                .title(Span::styled(title, t.title())),
        )
        .render(table, buf);
    let lines: Vec<Line> = words.into_iter().map(Line::raw).collect();
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(
            Block::bordered()
                .border_style(t.border())
                .title(Span::styled(
                    format!(" Stop {} of {} ", r.stop, last),
                    t.title(),
                )),
        )
        .render(note, buf);
    true
}

/// A and b, and at j ≥ 1 pivot j - 1 with its column, ratio test and λ so far.
fn pivot_lines(app: &App, record: &Record<f64>, j: usize) -> Vec<Line<'static>> {
    let t = &app.theme;
    let f = Fmt::new(4);
    let mut lines = vec![Line::styled(
        format!(
            "find λ >= 0 with w = Aλ + b >= 0, λ·w = 0 (Lemke's method, {} restitution)",
            record.restitution.name()
        ),
        t.dim(),
    )];
    for (i, row) in record.matrix.iter().enumerate() {
        let head = if i == 0 { "A = " } else { "    " };
        lines.push(Line::raw(format!("{head}[{}]", f.list(row))));
    }
    let at = j.checked_sub(1).and_then(|k| pivot_at(record, k));
    let problem = at
        .as_ref()
        .map(|a| a.problem)
        .or_else(|| record.problems.first());
    if let Some(p) = problem {
        lines.push(Line::raw(format!(
            "b = [{}]  ({} LCP)",
            f.list(&p.b),
            p.stage.name()
        )));
    }
    let Some(at) = at else {
        return lines;
    };
    let p = at.pivot;
    let stage = at.problem.stage.name();
    lines.push(Line::raw(""));
    lines.push(Line::styled(pivot_line(j - 1, stage, p, &f), t.title()));
    lines.push(Line::raw(format!(
        "entering: {}   leaving: {} (row {})",
        p.entering.name(),
        p.leaving.name(),
        p.row
    )));
    lines.push(Line::raw(format!(
        "tableau column of {}: [{}]",
        p.entering.name(),
        f.list(&p.column)
    )));
    lines.push(Line::raw(format!("ratio test: {}", ratio_test(p, &f))));
    lines.push(Line::styled(
        format!("ratio chosen: {}", f.num(p.ratio)),
        t.changed(),
    ));
    let basis: Vec<String> = at
        .problem
        .basis_after(at.local)
        .iter()
        .map(|(v, x)| format!("{} = {}", v.name(), f.num(*x)))
        .collect();
    lines.push(Line::raw(format!("basis after: {}", basis.join(", "))));
    lines.push(Line::styled(
        format!("λ so far: [{}]", f.list(&at.problem.lambda_after(at.local))),
        t.changed(),
    ));
    lines
}

/// What the pivot stop does next, in words.
fn pivot_note(record: &Record<f64>, j: usize) -> Vec<String> {
    let f = Fmt::new(4);
    let total = record.pivots().count();
    let mut out = vec![];
    match pivot_at(record, j) {
        Some(next) => out.push(format!(
            "Next: {}.",
            pivot_line(j, next.problem.stage.name(), next.pivot, &f)
        )),
        None if total == 0 => out.push(
            "b >= 0: no contact is closing, λ = 0 with no pivot. Next: the bodies after."
                .to_string(),
        ),
        None => out.push(format!(
            "{} after {total} pivot(s). Next: the impulses applied and the bodies after.",
            match record.failure() {
                Some(fail) => fail.describe(),
                None => "Solved: z0 has left the basis".to_string(),
            }
        )),
    }
    if let Some(last) = j.checked_sub(1).and_then(|k| pivot_at(record, k)) {
        let left = if last.pivot.leaving == Var::Z0 {
            ": λ is the solution"
        } else {
            ""
        };
        out.push(format!(
            "Last: {} entered at ratio {}, {} left{left}.",
            last.pivot.entering.name(),
            f.num(last.pivot.ratio),
            last.pivot.leaving.name()
        ));
    }
    out
}

/// The impulses applied, the normal velocities after, each body after.
fn after_lines(app: &App, r: &ResolverView, record: &Record<f64>) -> Vec<Line<'static>> {
    let t = &app.theme;
    let f = Fmt::new(4);
    let mut lines = vec![
        Line::styled(
            format!("impulses applied: [{}]", f.list(&record.impulses)),
            t.changed(),
        ),
        Line::raw(format!(
            "normal velocities after: [{}]",
            f.list(&record.velocities_after)
        )),
        Line::raw(format!(
            "restitution as applied: [{}]",
            f.list(&record.restitutions)
        )),
    ];
    if let Some(fr) = &record.friction {
        lines.push(Line::styled(
            format!(
                "friction (projected Gauss-Seidel, |λ_t| <= μ λ_n, {} sweep(s)):",
                fr.sweeps
            ),
            t.dim(),
        ));
        for row in &fr.rows {
            lines.push(Line::raw(format!(
                "  contact {}: λ_t ({}), {}",
                row.contact,
                f.list(&row.tangential),
                if row.sliding { "sliding" } else { "sticking" }
            )));
        }
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled("bodies after:", t.dim()));
    let before = r.trace.bodies_at(0);
    for (b, was) in r.trace.bodies_at(r.stop).iter().zip(&before) {
        if !b.movable {
            continue;
        }
        lines.push(Line::raw(format!(
            "{}: velocity ({}) m/s, was ({})",
            b.name,
            f.list(&b.velocity),
            f.list(&was.velocity)
        )));
    }
    lines
}

/// The phase's end in words, with the degeneracy, failure and friction notes.
fn after_note(record: &Record<f64>) -> Vec<String> {
    let mut out = vec![format!(
        "The simultaneous phase is done: {} pivot(s), every impulse applied at once.",
        record.pivots().count()
    )];
    out.extend(notes(record));
    out
}
