//! The study as a figure: per scene, error against cost on log–log axes,
//! one colour and marker per row (eight colours × six markers), the Pareto
//! front joined, the reference named under the panel's title, and a legend
//! in its own column inside the canvas (★ beside the rows on the front).
//! Rows with an error of 0 or that blew up cannot be drawn on a log axis and
//! are left out of the plot; the legend lists them with "not drawn".

use crate::render::chart::{escape, marker, Chart, Mark, Scale, Series, PALETTE};
use crate::study::{Row, Study};

const WIDTH: f64 = 1000.0;
/// The plot's share of the width; the legend has the rest.
const PLOT: f64 = 560.0;
const PANEL: f64 = 360.0;
const LEGEND_LINE: f64 = 14.0;
/// The markers, in the order rows take them (colour first).
const MARKS: [Mark; 6] = [
    Mark::Dots,
    Mark::Squares,
    Mark::Triangles,
    Mark::Diamonds,
    Mark::Crosses,
    Mark::Pluses,
];

/// The colour and marker of the `k`-th row: distinct for 48 rows.
pub fn style(k: usize) -> (&'static str, Mark) {
    (
        PALETTE[k % PALETTE.len()],
        MARKS[(k / PALETTE.len()) % MARKS.len()],
    )
}

/// A row's name in the legend.
pub fn row_name(r: &Row) -> String {
    if r.knob == "budget" || r.knob == "default" {
        format!("{}: {}", r.knob, r.value)
    } else {
        format!("{} = {}", r.knob, r.value)
    }
}

fn drawable(r: &Row, x: f64) -> bool {
    r.failure.is_none() && x > 0.0 && r.error_vs_reference > 0.0 && r.error_vs_reference.is_finite()
}

/// Characters per legend line (11 px text in the column right of the plot).
pub const LEGEND_CHARS: usize = 52;
/// Lines the reference takes at most under the legend.
const REFERENCE_LINES: usize = 5;

/// The height of one scene's panel: the plot, or the legend and the
/// reference under it when longer.
fn panel_height(rows: usize) -> f64 {
    PANEL.max(64.0 + LEGEND_LINE * (rows + 2 + REFERENCE_LINES) as f64)
}

/// Words into lines of at most [`LEGEND_CHARS`] characters.
fn wrap(text: &str) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= LEGEND_CHARS => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

pub fn render(study: &Study) -> String {
    let height = 80.0
        + study
            .scenes
            .iter()
            .map(|s| panel_height(s.rows.len()))
            .sum::<f64>();
    let x_label = if study.timed {
        "µs per step (median)"
    } else {
        "visits + ccd tests per step"
    };
    let mut out = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">
<rect width="100%" height="100%" fill="#FFFFFF"/>
<text x="24" y="36" font-size="22" font-weight="bold">Speed against accuracy</text>
<text x="24" y="60" font-size="14" fill="#444444">error (m) vs {}, log–log: one colour and marker per row, the front dotted</text>
"##,
        escape(x_label)
    );
    let mut y0 = 80.0;
    for s in &study.scenes {
        let h = panel_height(s.rows.len());
        let series: Vec<Series> = s
            .rows
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let (colour, mark) = style(k);
                Series {
                    name: String::new(),
                    points: if drawable(r, r.cost()) {
                        vec![(r.cost(), r.error_vs_reference)]
                    } else {
                        Vec::new()
                    },
                    colour,
                    mark,
                    dashed: false,
                }
            })
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
            ..Chart::default()
        };
        chart.draw(&mut out, (24.0, y0 + 16.0, PLOT, PANEL - 36.0));
        // The legend: one line per row, in the column right of the plot.
        let lx = 24.0 + PLOT + 16.0;
        out.push_str(&format!(
            r##"<g font-size="11"><text x="{lx:.1}" y="{:.1}" font-size="11" font-weight="bold">rows (★ on the front; dotted line: the front)</text>
"##,
            y0 + 40.0
        ));
        for (k, r) in s.rows.iter().enumerate() {
            let (colour, mark) = style(k);
            let y = y0 + 40.0 + LEGEND_LINE * (k + 1) as f64;
            marker(&mut out, mark, lx + 5.0, y - 4.0, colour);
            let note = if !drawable(r, r.cost()) {
                " (not drawn)"
            } else if r.pareto {
                " ★"
            } else {
                ""
            };
            out.push_str(&format!(
                r##"<text x="{:.1}" y="{y:.1}" font-size="11">{}{note}</text>
"##,
                lx + 16.0,
                escape(&row_name(r))
            ));
        }
        // The reference, named under the legend, wrapped to the column.
        let first = y0 + 40.0 + LEGEND_LINE * (s.rows.len() + 2) as f64;
        for (i, line) in wrap(&format!("reference: {}", s.reference))
            .iter()
            .enumerate()
        {
            out.push_str(&format!(
                r##"<text x="{lx:.1}" y="{:.1}" font-size="11" fill="#444444">{}</text>
"##,
                first + LEGEND_LINE * i as f64,
                escape(line)
            ));
        }
        out.push_str("</g>\n");
        y0 += h;
    }
    out.push_str("</svg>\n");
    out
}
