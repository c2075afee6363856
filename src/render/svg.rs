//! A figure of one contact as SVG, written by hand: the bodies (and where
//! projection moves them), the contact point, the normal, the arms, the
//! velocities before and after, the spin, the impulse, labels and a legend.
//! 1280 × 720, for a slide. What is drawn comes from the
//! [figure model](crate::render::figure); here it is fitted to the page.
//! When the `exact_impact` stage ran, the impulse-space figure
//! ([`crate::render::contact::impact`]) goes below it, on a taller page.

mod labels;
mod legend;
mod page;

use std::fmt::Write;

use page::{c, colour, xml, LabelAt, Page, PageArrow, View, AREA, FILL, FONT, HEADS, HEIGHT};
use page::{INK, MOVED, WIDTH};

use crate::render::contact::impact;
use crate::render::figure::{flat, ArrowKind, Figure, PointKind, Silhouette, P};
pub use crate::trace::Plane;
use crate::trace::Trace;

/// The page arrows of the figure: velocities `v_scale` per unit speed, each
/// impulse 0.8 scene lengths, normals `normal_len` long (view units).
fn arrows(fig: &Figure, v_scale: f64, normal_len: f64) -> Vec<PageArrow> {
    let reach = fig.scene_length;
    let mut out = vec![];
    for a in &fig.arrows {
        let (from, to, dashed, width, at) = match a.kind {
            ArrowKind::Arm => (a.at, a.tip(1.0), true, 2.0, LabelAt::Middle),
            ArrowKind::Normal => (a.at, a.tip(normal_len), false, 3.0, LabelAt::Tip),
            ArrowKind::Impulse => {
                let size = a.contact.map_or(0.0, |k| fig.contacts[k].impulse_size);
                let g_scale = if size > 0.0 { 0.8 * reach / size } else { 0.0 };
                (a.tip(-g_scale), a.at, false, 5.0, LabelAt::Tail)
            }
            // Body 2's -g is left to the legend.
            ArrowKind::Reaction => continue,
            ArrowKind::Velocity => (a.at, a.tip(v_scale), true, 3.5, LabelAt::Tip),
            ArrowKind::VelocityAfter => (a.at, a.tip(v_scale), false, 3.5, LabelAt::Tip),
        };
        out.push(PageArrow {
            from,
            to,
            colour: colour(a.kind.ink()),
            width,
            dashed,
            label: a.label.clone(),
            at,
            head: a.kind != ArrowKind::Arm,
        });
    }
    out
}

/// Everything the page must show: contact points and a little of each
/// half-space, the bodies (where projection moves them, unless far off) and
/// the arrows.
fn fit(fig: &Figure, arrows: &[PageArrow]) -> View {
    let reach = fig.scene_length;
    let mut points: Vec<P> = vec![];
    for c in &fig.contacts {
        let (q, n) = (c.point, c.normal);
        points.push(flat(q));
        points.push([q[0] + -0.4 * reach * n[0], q[1] + -0.4 * reach * n[1]]);
    }
    for s in fig.surfaces.iter().filter_map(|s| s.section.as_ref()) {
        let (at, d) = (s.at, s.solid_side);
        points.push(at);
        points.push([at[0] + 0.4 * reach * d[0], at[1] + 0.4 * reach * d[1]]);
    }
    for b in &fig.bodies {
        points.push(flat(b.centre));
        let mut poses = vec![b.outline.as_ref()];
        // A projection that moves a body far off is noted, not fitted.
        if !fig.beyond(b) {
            poses.push(b.outline_after.as_ref().or(b.outline.as_ref()));
        }
        for o in poses.into_iter().flatten() {
            points.extend(o.silhouette.points());
        }
    }
    for a in arrows {
        points.push(flat(a.from));
        points.push(flat(a.to));
    }
    View::fit(&points)
}

fn header(p: &mut Page, trace: &Trace, plane: Plane) {
    let height = HEIGHT + trace.impact.as_ref().map_or(0.0, |_| impact::HEIGHT);
    let _ = writeln!(
        p.out,
        r##"<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" font-family="{FONT}">
  <title>{}</title>
  <defs>
    <clipPath id="area"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>
    <pattern id="hatch" width="14" height="14" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">
      <rect width="14" height="14" fill="#E4E4E4"/>
      <line x1="0" y1="0" x2="0" y2="14" stroke="#9A9A9A" stroke-width="3"/>
    </pattern>"##,
        xml(&format!(
            "{} — contact {}",
            trace.title, trace.contact_label
        )),
        c(AREA.0),
        c(AREA.1),
        c(AREA.2 - AREA.0),
        c(AREA.3 - AREA.1)
    );
    for colour in HEADS {
        let _ = writeln!(
            p.out,
            r#"    <marker id="head-{}" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="4.5" markerHeight="4.5" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="{colour}"/></marker>"#,
            &colour[1..]
        );
    }
    p.out
        .push_str("  </defs>\n  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    p.text([AREA.0, 40.0], 28.0, "start", "bold", INK, &trace.title);
    let subtitle = format!(
        "{} · contact {} · {} plane, {} toward the viewer",
        trace.lesson,
        trace.contact_label,
        plane.name(),
        ["x", "y", "z"][plane.axes().2]
    );
    p.text(
        [AREA.0, 72.0],
        18.0,
        "start",
        "normal",
        "#555555",
        &subtitle,
    );
}

/// Surfaces first, then the bodies; where projection moves them, a dashed
/// outline and an arrow from the old centre to the new.
fn bodies(p: &mut Page, fig: &Figure) {
    let reach = fig.scene_length;
    for s in &fig.surfaces {
        let name = s.body.map_or("the world", |b| &fig.bodies[b].name);
        if let Some(section) = &s.section {
            p.surface(section, name, reach);
        }
    }
    for b in &fig.bodies {
        let fill = if b.movable {
            FILL[b.slot.min(2)]
        } else {
            "url(#hatch)"
        };
        if let Some(o) = &b.outline {
            p.silhouette(&o.silhouette, fill, INK, false);
        } else if b.shape.is_none() {
            let marker = Silhouette::Circle {
                centre: flat(b.centre),
                radius: 0.15 * reach,
            };
            p.silhouette(&marker, fill, INK, true);
        }
    }
    for b in fig.bodies.iter().filter(|b| b.moved()) {
        if let Some(o) = &b.outline_after {
            p.silhouette(&o.silhouette, "none", MOVED, true);
        }
        let (from, to) = (
            p.view.page(flat(b.centre)),
            p.view.page(flat(b.centre_after)),
        );
        if ((to[0] - from[0]).powi(2) + (to[1] - from[1]).powi(2)).sqrt() > 6.0 {
            let _ = writeln!(
                p.out,
                r#"  <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{MOVED}" stroke-width="2.5" marker-end="url(#head-{})"/>"#,
                c(from[0]),
                c(from[1]),
                c(to[0]),
                c(to[1]),
                &MOVED[1..]
            );
            p.stroke(from, to, 2.5);
            p.stroke_head(from, to, 2.5);
        }
    }
}

/// Centres and contact points, with their names.
fn points(p: &mut Page, fig: &Figure) {
    for point in &fig.points {
        let at = p.view.page(flat(point.at));
        match point.kind {
            PointKind::Centre { body } => {
                let b = &fig.bodies[body];
                let _ = writeln!(
                    p.out,
                    r#"  <circle cx="{}" cy="{}" r="5" fill="{INK}"/>"#,
                    c(at[0]),
                    c(at[1])
                );
                p.stroke_circle(at, 2.5, 5.0);
                let label = if b.movable {
                    format!("{} {}", point.label, b.name)
                } else {
                    format!("{} (m = ∞)", b.name)
                };
                p.label(
                    [at[0] - 50.0, at[1] + 7.0],
                    20.0,
                    "end",
                    "normal",
                    INK,
                    &label,
                );
            }
            PointKind::Contact { contact } => {
                let _ = writeln!(
                    p.out,
                    r#"  <circle cx="{}" cy="{}" r="7" fill="{}" stroke="white" stroke-width="2"/>"#,
                    c(at[0]),
                    c(at[1]),
                    colour(crate::render::figure::Ink::Point)
                );
                p.stroke_circle(at, 4.0, 8.0);
                // The label sits along the contact plane, away from the normal and the impulse.
                let d = flat(fig.contacts[contact].normal);
                let len = (d[0] * d[0] + d[1] * d[1]).sqrt();
                let t = if len > 0.2 {
                    (d[1] / len, d[0] / len)
                } else {
                    (-0.7, 0.7)
                };
                let label_at = [at[0] - 26.0 * t.0.abs(), at[1] + 26.0 * t.1.abs() + 8.0];
                p.label(label_at, 22.0, "end", "bold", INK, &point.label);
            }
        }
    }
}

/// The figure of `trace`'s contact seen in `plane`: every stage's marks.
pub fn render(trace: &Trace, plane: Plane) -> String {
    render_at(trace, plane, None)
}

/// The figure as `stage` sees it (`Figure::at_stage`), or whole (`None`).
pub fn render_at(trace: &Trace, plane: Plane, stage: Option<crate::physics::StageId>) -> String {
    let fig = Figure::of_contact(&trace.scene, plane);
    let fig = match stage {
        Some(s) => fig.at_stage(s),
        None => fig,
    };
    let reach = fig.scene_length;
    let v_scale = if fig.top_speed > 0.0 {
        0.9 * reach / fig.top_speed
    } else {
        0.0
    };
    let view = fit(&fig, &arrows(&fig, v_scale, 0.45 * reach));
    // The normal is a direction: at least 60 px long whatever the scale.
    let normal_len = (0.45 * reach).max(60.0 / view.scale);
    let arrows = arrows(&fig, v_scale, normal_len);
    let mut p = Page {
        view,
        out: String::new(),
        placed: vec![],
        pending: vec![],
        strokes: vec![],
        moved: vec![],
    };
    header(&mut p, trace, plane);
    // Everything drawn stays in the drawing area, however far a value reaches.
    p.out.push_str("  <g clip-path=\"url(#area)\">\n");
    bodies(&mut p, &fig);
    // Spin about the view axis, before (dashed) and after; the arc's radius
    // grows with |ω| (the fastest spin drawn gets 46 px, none less than 18).
    let notable: Vec<&crate::render::figure::Spin> = fig
        .spins
        .iter()
        .filter(|s| fig.notable_spin(s.rate))
        .collect();
    let fastest = notable.iter().map(|s| s.rate.abs()).fold(0.0, f64::max);
    for s in notable {
        let ink = if s.after { page::AFTER } else { page::BEFORE };
        let radius = 18.0 + 28.0 * s.rate.abs() / fastest;
        p.spin(flat(s.at), s.rate, radius, ink, !s.after);
    }
    for a in &arrows {
        p.arrow(a);
    }
    points(&mut p, &fig);
    p.place_labels();
    p.out.push_str("  </g>\n");
    legend::legend(&mut p, &fig);
    if let Some(curves) = &trace.impact {
        let area = (AREA.0, HEIGHT, WIDTH - 2.0 * AREA.0, impact::HEIGHT - 16.0);
        impact::draw(&mut p.out, curves, area);
    }
    p.out.push_str("</svg>\n");
    p.out
}
