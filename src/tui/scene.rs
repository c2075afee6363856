//! The picture panel (Canvas, braille): the contact's bodies to scale in the
//! chosen plane, the contact point, the normal, the arms r₁ r₂, velocities
//! before and after and the impulse, zoomed to fit, with a key. Everything
//! comes from the [figure model](crate::render::figure); [`picture`] turns it
//! into segments and labels, this file fits them to cells and places labels.

mod picture;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Color;
use ratatui::symbols::Marker;
use ratatui::text::{Line as TextLine, Span};
use ratatui::widgets::canvas::{Canvas, Context, Line};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::app::App;
use super::theme::{Ink, Theme};
use crate::render::figure::{ArrowKind, Figure, P};
use picture::{picture, Mark, Show};

/// Bounds with a margin, widened so a braille dot is as wide as it is tall
/// (a cell is 2 × 4 dots and about twice as tall as wide).
fn fit(b: [f64; 4], cols: u16, rows: u16) -> ([f64; 2], [f64; 2]) {
    let (cx, cy) = ((b[0] + b[1]) / 2.0, (b[2] + b[3]) / 2.0);
    let mut w = (b[1] - b[0]).max(1e-9) * 1.15;
    let mut h = (b[3] - b[2]).max(1e-9) * 1.15;
    let (dx, dy) = (f64::from(cols.max(1)) * 2.0, f64::from(rows.max(1)) * 4.0);
    if w / dx > h / dy {
        h = w / dx * dy;
    } else {
        w = h / dy * dx;
    }
    ([cx - w / 2.0, cx + w / 2.0], [cy - h / 2.0, cy + h / 2.0])
}

/// Puts each label in free cells near its point: first by rank, trying the cell itself,
/// then its neighbours; a label with no free place nearby is left out.
fn place_labels(
    marks: &[Mark],
    xb: [f64; 2],
    yb: [f64; 2],
    cols: u16,
    rows: u16,
) -> Vec<(P, String, Ink)> {
    let (w, h) = (i32::from(cols), i32::from(rows));
    let (xr, yr) = (xb[1] - xb[0], yb[1] - yb[0]);
    if w < 2 || h < 2 || xr <= 0.0 || yr <= 0.0 {
        return vec![];
    }
    let mut labels: Vec<(&P, &String, Ink, u8, Option<P>)> = marks
        .iter()
        .filter_map(|m| match m {
            Mark::Label(p, text, ink, rank, lean) => Some((p, text, *ink, *rank, *lean)),
            Mark::Seg(..) => None,
        })
        .collect();
    labels.sort_by_key(|l| l.3);
    let mut taken = vec![false; (w * h) as usize];
    // Cells the drawing passes through: a label goes elsewhere when it can.
    let mut drawn = vec![false; (w * h) as usize];
    let cell = |p: P| {
        let c = ((p[0] - xb[0]) * f64::from(2 * w - 1) / xr).round() as i32 / 2;
        let r = ((yb[1] - p[1]) * f64::from(4 * h - 1) / yr).round() as i32 / 4;
        (c, r)
    };
    for m in marks {
        if let Mark::Seg(a, b, _) = m {
            let ((c0, r0), (c1, r1)) = (cell(*a), cell(*b));
            let n = (c1 - c0).abs().max((r1 - r0).abs()).clamp(1, 4 * (w + h));
            for i in 0..=n {
                let s = f64::from(i) / f64::from(n);
                let (c, r) = cell([a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s]);
                if (0..w).contains(&c) && (0..h).contains(&r) {
                    drawn[(r * w + c) as usize] = true;
                }
            }
        }
    }
    let mut out = vec![];
    for (p, text, ink, _, lean) in labels {
        if !(xb[0]..=xb[1]).contains(&p[0]) || !(yb[0]..=yb[1]).contains(&p[1]) {
            continue;
        }
        // The cell of the braille dot the point is drawn at (2 × 4 dots a cell).
        let c = ((p[0] - xb[0]) * f64::from(2 * w - 1) / xr).round() as i32 / 2;
        let r = ((yb[1] - p[1]) * f64::from(4 * h - 1) / yr).round() as i32 / 4;
        let n = super::wrap::width(text) as i32;
        let near = [
            (0, 0),
            (1, 0),
            (-n, 0),
            (0, -1),
            (0, 1),
            (1, -1),
            (1, 1),
            (-n, -1),
            (-n, 1),
            (2, 0),
            (-n - 1, 0),
        ];
        // An arrow's label first past its head: to the right of a head
        // pointing right, to the left of one pointing left, above or below
        // one pointing up or down (a cell is about twice as tall as wide).
        let past: &[(i32, i32)] = match lean {
            Some(u) if u[0].abs() >= 0.5 * u[1].abs() && u[0] > 0.0 => &[(1, 0), (1, -1), (1, 1)],
            Some(u) if u[0].abs() >= 0.5 * u[1].abs() => &[(-n, 0), (-n, -1), (-n, 1)],
            Some(u) if u[1] > 0.0 => &[(0, -1), (1, -1), (-n, -1)],
            Some(_) => &[(0, 1), (1, 1), (-n, 1)],
            None => &[],
        };
        let free = |c: i32, r: i32| {
            r >= 0
                && r < h
                && c >= 0
                && c + n <= w
                && (c..c + n).all(|x| !taken[(r * w + x) as usize])
        };
        let clear = |c: i32, r: i32| free(c, r) && (c..c + n).all(|x| !drawn[(r * w + x) as usize]);
        let spot = |tries: &[(i32, i32)], ok: &dyn Fn(i32, i32) -> bool| {
            tries
                .iter()
                .map(|(dc, dr)| (c + dc, r + dr))
                .find(|&(c, r)| ok(c, r))
        };
        // Past the head even over the drawing, before anywhere else near.
        let place = spot(past, &clear)
            .or_else(|| spot(past, &free))
            .or_else(|| spot(&near, &clear))
            .or_else(|| spot(&near, &free));
        if let Some((c, r)) = place {
            for x in c..c + n {
                taken[(r * w + x) as usize] = true;
            }
            // A point the canvas prints in cell (c, r): labels map with
            // (cells - 1) steps, unlike the dots.
            let x = (xb[0] + (f64::from(c) + 0.01) * xr / f64::from(w - 1)).min(xb[1]);
            let y = (yb[1] - (f64::from(r) + 0.01) * yr / f64::from(h - 1)).max(yb[0]);
            out.push(([x, y], text.clone(), ink));
        }
    }
    out
}

/// The segment `a`–`c` as dashes `step` long with gaps as long between
/// them (a segment shorter than two steps stays whole).
fn dashes(a: P, c: P, step: f64) -> Vec<(P, P)> {
    let len = (c[0] - a[0]).hypot(c[1] - a[1]);
    if !(step > 0.0 && len >= 2.0 * step) {
        return vec![(a, c)];
    }
    let at = |s: f64| {
        [
            a[0] + (c[0] - a[0]) * s / len,
            a[1] + (c[1] - a[1]) * s / len,
        ]
    };
    let mut out = vec![];
    let mut s = 0.0;
    while s < len {
        out.push((at(s), at((s + step).min(len))));
        s += 2.0 * step;
    }
    out
}

/// The key to the picture's colours and labels; `compact` keeps to the symbols.
fn legend(
    t: &Theme,
    show: &Show,
    moved: bool,
    compact: bool,
    corrected: Option<&str>,
) -> TextLine<'static> {
    let mut items = vec![];
    if show.before_velocity {
        items.push((Ink::VelocityBefore, "v", "before"));
    }
    if show.after_velocity {
        let what = if t.color { "after" } else { "after (dashed)" };
        items.push((Ink::VelocityAfter, "v′", what));
    }
    if show.impulse {
        items.push((Ink::Impulse, "g", "impulse"));
    }
    items.push((Ink::Normal, "d̂", "normal"));
    items.push((Ink::Arm, "r", "arm"));
    if show.after_pose && moved {
        let what = if t.color {
            "after projection"
        } else {
            "after projection (dashed)"
        };
        items.push((Ink::BodyAfter, "▒", what));
    }
    let mut spans = vec![];
    for (ink, sym, what) in items {
        spans.push(Span::styled(sym, t.ink_style(ink)));
        if compact {
            spans.push(Span::raw(" "));
        } else {
            spans.push(Span::raw(format!(" {what}  ")));
        }
    }
    // The lesson draws the lecture's geometry corrected: say so, briefly (the
    // whole note would take the picture's rows; the overview explains it).
    match corrected {
        Some(_) if compact => spans.push(Span::raw("(corrected geometry)")),
        Some(_) => spans.push(Span::raw("· drawn with corrected geometry (see Overview)")),
        None => {}
    }
    TextLine::from(spans)
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" Scene · {} plane (v) ", app.plane.name()),
            t.title(),
        ));
    let inner = block.inner(area);
    block.render(area, buf);
    // The state the current stage works on (the overview shows it all).
    let mut fig = Figure::of_contact(&app.trace.scene, app.plane);
    if let Some(s) = app.stage() {
        fig = fig.at_stage(app.trace.stages[s].id);
    }
    let has = |k: ArrowKind| fig.arrows.iter().any(|a| a.kind == k);
    let show = Show {
        before_velocity: has(ArrowKind::Velocity) || fig.spins.iter().any(|s| !s.after),
        impulse: app.shown("impulse") && app.shown("friction_clamp") && has(ArrowKind::Impulse),
        after_velocity: app.shown("apply_impulse")
            && (has(ArrowKind::VelocityAfter) || fig.spins.iter().any(|s| s.after)),
        after_pose: app.shown("nonlinear_projection")
            && app.shown("orientation_update")
            && fig.bodies.iter().any(|b| b.outline_after.is_some()),
    };
    let moved = fig.bodies.iter().any(|b| b.pose_change > 0.0);
    let corrected = fig.corrected.as_deref();
    let full = legend(t, &show, moved, false, corrected);
    let rows_for = |l: &TextLine| (l.width() as u16).div_ceil(inner.width.max(1));
    let (legend, legend_rows) = if inner.height >= rows_for(&full) + 8 {
        let r = rows_for(&full);
        (full, r)
    } else {
        let compact = legend(t, &show, moved, true, corrected);
        (compact, u16::from(inner.height >= 5))
    };
    let [canvas_area, legend_area] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(legend_rows)]).areas(inner);
    Paragraph::new(legend)
        .wrap(Wrap { trim: true })
        .render(legend_area, buf);
    if canvas_area.width < 2 || canvas_area.height < 2 {
        return;
    }
    let (pic, b) = picture(&fig, &show);
    let (xb, yb) = fit(b, canvas_area.width, canvas_area.height);
    let color = |ink: Ink| t.ink(ink);
    let labels = place_labels(&pic.marks, xb, yb, canvas_area.width, canvas_area.height);
    // Without colour the state after the impulse (and after the projection)
    // is drawn dashed, so that it still differs from the state before.
    let dash = (xb[1] - xb[0]) / f64::from(canvas_area.width.max(1));
    let paint = |ctx: &mut Context| {
        for m in &pic.marks {
            if let Mark::Seg(a, c, ink) = m {
                let after = matches!(ink, Ink::VelocityAfter | Ink::BodyAfter);
                if after && !t.color {
                    for (p, q) in dashes(*a, *c, dash) {
                        ctx.draw(&Line::new(p[0], p[1], q[0], q[1], color(*ink)));
                    }
                } else {
                    ctx.draw(&Line::new(a[0], a[1], c[0], c[1], color(*ink)));
                }
            }
        }
        ctx.layer();
        for (at, text, ink) in &labels {
            ctx.print(at[0], at[1], Span::styled(text.clone(), t.ink_style(*ink)));
        }
    };
    Canvas::default()
        .marker(Marker::Braille)
        .background_color(Color::Reset)
        .x_bounds(xb)
        .y_bounds(yb)
        .paint(paint)
        .render(canvas_area, buf);
}

#[cfg(test)]
mod tests {
    use super::picture::Mark;
    use super::{dashes, place_labels};
    use crate::tui::theme::Ink;

    #[test]
    fn a_label_goes_beside_the_drawing_when_there_is_room() {
        // A horizontal line across a 10 × 5 canvas through the label's point.
        let marks = vec![
            Mark::Seg([0.0, 2.0], [10.0, 2.0], Ink::Body),
            Mark::Label([5.0, 2.0], "q".into(), Ink::Point, 0, None),
        ];
        let placed = place_labels(&marks, [0.0, 10.0], [0.0, 4.0], 10, 5);
        assert_eq!(placed.len(), 1);
        let y = placed[0].0[1];
        assert!(
            (y - 2.0).abs() > 0.5,
            "the label is off the line's row: y = {y}"
        );
    }

    #[test]
    fn two_arrow_heads_that_meet_keep_their_labels_past_each_head() {
        // v₁ arrives from the left, v₂ from the right, both heads at (5, 2)
        // (two-boxes: A's and B's velocities meet at the contact).
        let marks = vec![
            Mark::Seg([1.0, 2.0], [5.0, 2.0], Ink::VelocityBefore),
            Mark::Seg([9.0, 2.0], [5.0, 2.0], Ink::VelocityBefore),
            Mark::Label(
                [5.0, 2.0],
                "v₁".into(),
                Ink::VelocityBefore,
                3,
                Some([1.0, 0.0]),
            ),
            Mark::Label(
                [5.0, 2.0],
                "v₂".into(),
                Ink::VelocityBefore,
                3,
                Some([-1.0, 0.0]),
            ),
        ];
        let placed = place_labels(&marks, [0.0, 10.0], [0.0, 4.0], 21, 5);
        let x = |name: &str| placed.iter().find(|l| l.1 == name).expect(name).0[0];
        let y = |name: &str| placed.iter().find(|l| l.1 == name).expect(name).0[1];
        assert!(x("v₁") > 5.0, "v₁ right of the heads: {placed:?}");
        assert!(x("v₂") < 5.0, "v₂ left of the heads: {placed:?}");
        assert_eq!(y("v₁"), y("v₂"), "both on the heads' row: {placed:?}");
    }

    #[test]
    fn predict_mode_draws_the_set_up_at_a_scale_the_answers_do_not_set() {
        // Every embedded lesson's first contact at restitution 0 and 1 (only
        // the answers differ): with the results hidden, the same marks.
        use super::picture::{picture, Show};
        use crate::render::figure::Figure;
        use crate::trace::Plane;
        let hidden = Show {
            before_velocity: true,
            impulse: false,
            after_velocity: false,
            after_pose: false,
        };
        let marks = |text: &str| {
            let lesson = crate::lesson::validate::parse("test.toml", text).unwrap();
            let trace = crate::worked_solution(&lesson, 0);
            let fig = Figure::of_contact(&trace.scene, Plane::Xy);
            format!("{:?}", picture(&fig, &hidden).0.marks)
        };
        let with_e = |text: &str, e: &str| {
            text.lines()
                .map(|l| {
                    if l.trim_start().starts_with("restitution =") {
                        format!("restitution = {e}")
                    } else {
                        l.to_string()
                    }
                })
                .collect::<Vec<_>>()
                .join("\n")
        };
        let mut compared = 0;
        for id in crate::lesson::embedded::ids() {
            let text = crate::lesson::embedded::find(id).unwrap();
            if !text.contains("restitution =") || !text.contains("[[contact") {
                continue;
            }
            let (a, b) = (marks(&with_e(text, "0")), marks(&with_e(text, "1")));
            assert_eq!(a, b, "{id}: the hidden answers set the picture's scale");
            compared += 1;
        }
        assert!(compared >= 5, "{compared} lessons compared");
    }

    #[test]
    fn a_spin_arc_grows_with_the_rate() {
        use super::picture::spin_size;
        // ω₁ = 0.0136 against ω₁′ = 0.17 rad/s: visibly different arcs.
        let (slow, fast) = (spin_size(0.0136, 0.17), spin_size(-0.17, 0.17));
        assert_eq!(fast, 1.0);
        assert!(slow < 0.36, "{slow}");
        assert!(spin_size(0.05, 0.17) > slow && spin_size(0.05, 0.17) < fast);
    }

    #[test]
    fn a_dashed_segment_has_gaps_and_keeps_its_ends() {
        let d = dashes([0.0, 0.0], [10.0, 0.0], 1.0);
        assert_eq!(d.len(), 5);
        assert_eq!(d[0], ([0.0, 0.0], [1.0, 0.0]));
        assert_eq!(d[1].0, [2.0, 0.0], "a gap of one step");
        assert_eq!(d[4], ([8.0, 0.0], [9.0, 0.0]));
        // Too short to dash: whole.
        assert_eq!(dashes([0.0, 0.0], [1.5, 0.0], 1.0).len(), 1);
    }
}
