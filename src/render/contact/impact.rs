//! The impulse-space figure of an integrated impact: the contact velocity
//! (v_n and each tangential component that moves) against the normal
//! impulse P_n, the phase changes marked, drawn with `render::chart`.

use crate::render::chart::{escape, Chart, Mark, Series, PALETTE};
use crate::trace::{ImpactCurves, Trace};

/// Width and height of the figure, alone or below the contact's picture.
pub const WIDTH: f64 = 1280.0;
pub const HEIGHT: f64 = 440.0;

/// The chart of the curves: v_n solid, v_t0 and v_t1 dashed, zero line, events.
pub fn chart(c: &ImpactCurves) -> Chart {
    let series = |name: &str, i: usize, colour: usize| Series {
        name: name.into(),
        points: c.samples.iter().map(|s| (s[0], s[i])).collect(),
        colour: PALETTE[colour],
        mark: Mark::Line,
        dashed: i > 1,
    };
    let mut all = vec![series("v_n (normal)", 1, 0)];
    // A tangential component that stays zero throughout says nothing.
    for (i, name) in [(2, "v_t0 (tangent t₀)"), (3, "v_t1 (tangent t₁)")] {
        if c.samples.iter().any(|s| s[i] != 0.0) {
            all.push(series(name, i, i - 1));
        }
    }
    let end = c.samples.last().map_or(0.0, |s| s[0]);
    all.push(Series {
        name: "v = 0".into(),
        points: vec![(0.0, 0.0), (end, 0.0)],
        colour: PALETTE[7],
        mark: Mark::Line,
        dashed: false,
    });
    Chart {
        title: format!(
            "Impulse space ({} restitution): contact velocity against the normal impulse",
            c.law
        ),
        x_label: "normal impulse P_n (N·s)".into(),
        y_label: "contact velocity u (m/s)".into(),
        series: all,
        marks: c.events.clone(),
        ..Chart::default()
    }
}

/// Draws the chart into `out` in the box `(x, y, width, height)`.
pub fn draw(out: &mut String, c: &ImpactCurves, area: (f64, f64, f64, f64)) {
    chart(c).draw(out, area);
}

/// The figure alone, as an SVG document; `None` when the trace has no
/// integrated impact.
pub fn svg(trace: &Trace) -> Option<String> {
    let c = trace.impact.as_ref()?;
    let mut out = format!(
        r##"<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}">
  <title>{} — contact {}: impulse space</title>
  <rect width="100%" height="100%" fill="white"/>
"##,
        escape(&trace.title),
        escape(&trace.contact_label)
    );
    draw(&mut out, c, (24.0, 8.0, WIDTH - 48.0, HEIGHT - 16.0));
    out.push_str("</svg>\n");
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curves() -> ImpactCurves {
        ImpactCurves {
            law: "stronge".into(),
            samples: vec![
                [0.0, -2.0, 0.0, 1.0],
                [0.5, -1.0, 0.0, 0.0],
                [0.75, 0.0, 0.0, -0.3],
                [1.1, 0.9, 0.0, -0.5],
            ],
            events: vec![
                (0.5, "halts, reverses".into()),
                (0.75, "max compression".into()),
            ],
        }
    }

    #[test]
    fn the_chart_shows_u_n_the_moving_tangent_and_the_events() {
        let c = chart(&curves());
        let names: Vec<_> = c.series.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["v_n (normal)", "v_t1 (tangent t₁)", "v = 0"]);
        assert_eq!(c.series[0].points[2], (0.75, 0.0));
        assert_eq!(c.marks.len(), 2);
        assert!(c.title.contains("stronge"));
    }

    #[test]
    fn the_svg_marks_each_event_with_its_label() {
        let mut out = String::new();
        draw(&mut out, &curves(), (0.0, 0.0, 800.0, 400.0));
        assert!(out.contains(">halts, reverses</text>"));
        assert!(out.contains(">max compression</text>"));
        assert_eq!(out.matches("stroke-dasharray=\"2 3\"").count(), 2);
    }
}
