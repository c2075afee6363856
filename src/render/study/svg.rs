//! The study as a figure: per scene, error against cost on log–log axes,
//! one colour per knob (the budget split by solver), the Pareto front joined.
//! Rows with an error of 0 or that blew up cannot be drawn on a log axis and
//! are left out (the table has them).

use crate::render::chart::{escape, Chart, Mark, Scale, Series, PALETTE};
use crate::study::{Row, Study};

const WIDTH: f64 = 1000.0;
const PANEL: f64 = 360.0;

/// The series a row belongs to.
fn series_name(r: &Row) -> String {
    if r.knob == "budget" {
        format!("budget, {}", r.config.solver_label())
    } else {
        r.knob.clone()
    }
}

fn drawable(r: &Row, x: f64) -> bool {
    r.failure.is_none() && x > 0.0 && r.error_vs_reference > 0.0 && r.error_vs_reference.is_finite()
}

pub fn render(study: &Study) -> String {
    let height = 80.0 + PANEL * study.scenes.len() as f64;
    let x_label = if study.timed {
        "µs per step (median)"
    } else {
        "contact visits per step"
    };
    let mut out = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">
<rect width="100%" height="100%" fill="#FFFFFF"/>
<text x="24" y="36" font-size="22" font-weight="bold">Speed against accuracy</text>
<text x="24" y="60" font-size="14" fill="#444444">error against the reference (m) vs {}, log–log; one colour per knob; the Pareto front joined</text>
"##,
        escape(x_label)
    );
    for (i, s) in study.scenes.iter().enumerate() {
        let mut names: Vec<String> = Vec::new();
        for r in &s.rows {
            let n = series_name(r);
            if !names.contains(&n) {
                names.push(n);
            }
        }
        let series: Vec<Series> = names
            .iter()
            .enumerate()
            .map(|(k, name)| Series {
                name: name.clone(),
                points: s
                    .rows
                    .iter()
                    .filter(|r| series_name(r) == *name && drawable(r, r.cost()))
                    .map(|r| (r.cost(), r.error_vs_reference))
                    .collect(),
                colour: PALETTE[k % PALETTE.len()],
                mark: Mark::Dots,
                dashed: k >= PALETTE.len(),
            })
            .filter(|s| !s.points.is_empty())
            .collect();
        let front: Vec<(f64, f64)> = crate::study::pareto::front(&s.rows)
            .into_iter()
            .filter(|r| drawable(r, r.cost()))
            .map(|r| (r.cost(), r.error_vs_reference))
            .collect();
        let chart = Chart {
            title: format!("{} ({} s)", s.scene, s.seconds),
            x_label: x_label.into(),
            y_label: "error (m)".into(),
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            series,
            cursor: None,
            front: (!front.is_empty()).then_some(front),
            marks: Vec::new(),
        };
        chart.draw(
            &mut out,
            (24.0, 80.0 + PANEL * i as f64, WIDTH - 48.0, PANEL - 20.0),
        );
    }
    out.push_str("</svg>\n");
    out
}
