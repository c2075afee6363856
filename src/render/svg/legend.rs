//! The SVG figure's legend: one line per item of the figure's legend, with
//! a sample of the stroke where the item has one.

use std::fmt::Write;

use super::page::{c, xml, Page, AFTER, AREA, ARM, BEFORE, IMPULSE, INK, MOVED, NORMAL, WIDTH};
use crate::format::Fmt;
use crate::render::figure::{Figure, LegendItem};

/// A stroke sample: colour, dashed, width.
type Sample = Option<(&'static str, bool, f64)>;

struct Lines<'a> {
    page: &'a mut Page,
    x0: f64,
    y: f64,
}

impl Lines<'_> {
    fn line(&mut self, sample: Sample, text: &str) {
        let (x0, y) = (self.x0, self.y);
        if let Some((colour, dashed, width)) = sample {
            let dash = if dashed {
                r#" stroke-dasharray="9 6""#
            } else {
                ""
            };
            let _ = writeln!(
                self.page.out,
                r#"  <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="{width}"{dash}/>"#,
                c(x0),
                c(y - 6.0),
                c(x0 + 34.0),
                c(y - 6.0)
            );
        }
        let _ = writeln!(
            self.page.out,
            r#"  <text x="{}" y="{}" font-size="16" fill="{INK}">{}</text>"#,
            c(x0 + if sample.is_some() { 44.0 } else { 0.0 }),
            c(y),
            xml(text)
        );
        self.y += 25.0;
    }
}

pub fn legend(page: &mut Page, fig: &Figure) {
    let fmt = Fmt::new(4);
    let v = |x: [f64; 3]| format!("({})", fmt.list(&x));
    let x0 = AREA.2 + 20.0;
    let y = AREA.1 + 8.0;
    let _ = writeln!(
        page.out,
        r##"  <rect x="{}" y="{}" width="{}" height="{}" rx="10" fill="#FAFAFA" stroke="#CCCCCC"/>"##,
        c(x0 - 12.0),
        c(y - 30.0),
        c(WIDTH - x0 - 8.0),
        c(AREA.3 - y + 30.0)
    );
    let _ = writeln!(
        page.out,
        r#"  <text x="{}" y="{}" font-size="18" font-weight="bold" fill="{INK}">Legend</text>"#,
        c(x0),
        c(y)
    );
    let mut out = Lines {
        page,
        x0,
        y: y + 27.0,
    };
    let name = |body: usize| &fig.bodies[body].name;
    let tag = |body: usize| fig.bodies[body].tag;
    for item in &fig.legend {
        match *item {
            LegendItem::Body { body } => {
                let b = &fig.bodies[body];
                let what = if b.movable { "" } else { " (immovable)" };
                out.line(None, &format!("body {}: {}{what}", b.slot, b.name));
            }
            LegendItem::ContactPoint { contact, at } => {
                let q = &fig.contacts[contact].label;
                out.line(None, &format!("{q} contact point {} m", v(at)));
            }
            LegendItem::Normal { direction, .. } => {
                out.line(
                    Some((NORMAL, false, 3.0)),
                    &format!("d̂ normal {}", v(direction)),
                );
            }
            LegendItem::Impulse { impulse, .. } => {
                out.line(
                    Some((IMPULSE, false, 5.0)),
                    &format!("g on body 1 {} N·s", v(impulse)),
                );
            }
            LegendItem::Reaction { .. } => out.line(None, "(body 2 receives -g)"),
            LegendItem::Arm { body, arm, .. } => {
                let n = tag(body);
                out.line(
                    Some((ARM, true, 2.0)),
                    &format!("r{n} = q - p{n} {} m", v(arm)),
                );
            }
            LegendItem::Velocity {
                body,
                before,
                after,
            } => {
                let n = tag(body);
                // Only the arrows drawn (a stage's figure may hold one of them).
                let drawn = |kind| {
                    fig.arrows
                        .iter()
                        .any(|a| a.body == Some(body) && a.kind == kind)
                };
                if drawn(crate::render::figure::ArrowKind::Velocity) {
                    out.line(
                        Some((BEFORE, true, 3.5)),
                        &format!("v{n} before {} m/s", v(before)),
                    );
                }
                if drawn(crate::render::figure::ArrowKind::VelocityAfter) {
                    out.line(
                        Some((AFTER, false, 3.5)),
                        &format!("v{n}′ after {} m/s", v(after)),
                    );
                }
            }
            LegendItem::Spin {
                body,
                before,
                after,
            } => {
                let n = tag(body);
                let text = match fig.spin_line(before, after) {
                    Some((true, true)) => format!("ω{n} {} → {} rad/s", v(before), v(after)),
                    Some((true, false)) => format!("ω{n} {} rad/s", v(before)),
                    Some(_) => format!("ω{n}′ {} rad/s", v(after)),
                    None => continue,
                };
                out.line(None, &text);
            }
            LegendItem::Travel { body, distance } => {
                let moves = format!("projection moves {} by {} m", name(body), fmt.num(distance));
                out.line(None, &moves);
                out.line(None, "(beyond the figure)");
            }
            LegendItem::Moved => out.line(Some((MOVED, true, 2.5)), "after projection"),
            LegendItem::Scales => {
                out.y += 6.0;
                // Only the scales of what is drawn: a set-up has no impulse.
                use crate::render::figure::ArrowKind as K;
                let drawn = |kinds: &[K]| {
                    fig.arrows
                        .iter()
                        .any(|a| kinds.contains(&a.kind) && a.tip(1.0) != a.at)
                };
                match (
                    drawn(&[K::Velocity, K::VelocityAfter]),
                    drawn(&[K::Impulse, K::Reaction]),
                ) {
                    (true, true) => {
                        out.line(None, "Velocities to one scale, the impulse");
                        out.line(None, "to another; ⊙ toward you, ⊗ away.");
                    }
                    (true, false) => {
                        out.line(None, "Velocities to scale;");
                        out.line(None, "⊙ toward you, ⊗ away.");
                    }
                    (false, true) => {
                        out.line(None, "The impulse to scale;");
                        out.line(None, "⊙ toward you, ⊗ away.");
                    }
                    (false, false) => out.line(None, "⊙ toward you, ⊗ away."),
                }
            }
            LegendItem::OffSurface { body, distance, .. } => {
                let side = if distance > 0.0 { "outside" } else { "inside" };
                let off = format!("⚠ q is {} m {side} {}", fmt.num(distance.abs()), name(body));
                out.line(None, &off);
                out.line(None, "as drawn (shape or orientation");
                out.line(None, "in the lesson do not fit q).");
            }
        }
    }
    // The lesson's figure-only correction of the lecture's geometry.
    if let Some(note) = &fig.corrected {
        out.y += 6.0;
        for line in wrap(note, 40) {
            out.line(None, &line);
        }
    }
    // Labels with no free place in the drawing, by their markers.
    let moved = std::mem::take(&mut out.page.moved);
    if !moved.is_empty() {
        out.y += 6.0;
        out.line(None, "Labels with no room in the drawing:");
    }
    for (mark, text, fill) in &moved {
        let line = match mark {
            Some(mark) => format!("{mark} {text}"),
            None => text.clone(),
        };
        let _ = writeln!(
            out.page.out,
            r#"  <text x="{}" y="{}" font-size="16" font-weight="bold" fill="{}">{}</text>"#,
            c(out.x0),
            c(out.y),
            xml(fill),
            xml(&line)
        );
        out.y += 25.0;
    }
}

/// Words of `text` in lines of at most `width` characters (a longer word
/// has a line of its own). A formula's operator binds its two operands, so
/// `r = q - p` is never split.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let operator = |w: &str| matches!(w, "=" | "-" | "+" | "·" | "×" | "/");
    let mut units: Vec<String> = vec![];
    for word in text.split_whitespace() {
        match units.last_mut() {
            Some(u) if operator(word) || u.rsplit(' ').next().is_some_and(operator) => {
                u.push(' ');
                u.push_str(word);
            }
            _ => units.push(word.to_string()),
        }
    }
    let mut lines: Vec<String> = vec![];
    for word in &units {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::wrap;

    #[test]
    fn a_formula_is_not_split_at_its_operators() {
        let lines = wrap("The numbers use only r = q - p, as printed.", 24);
        assert_eq!(lines, ["The numbers use only", "r = q - p, as printed."]);
        assert!(wrap("a b c d", 3).iter().all(|l| l.chars().count() <= 3));
    }
}
