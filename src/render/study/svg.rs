//! The study as a figure: per scene, error against the cost the front is
//! computed on (work per simulated second) on log–log axes. One colour per
//! family of rows (a solver's iteration budgets, the time step, the friction
//! knobs, …: at most eight, [`families`]), one marker per value within a
//! family, the Pareto front drawn as a staircase, the reference named under
//! the panel's title, and the legend in its own column right of the plot,
//! so nothing is written over a curve. Rows with an error of 0 or that blew
//! up cannot be drawn on a log axis and are left out of the plot; the legend
//! lists them with "not drawn".

use crate::knobs;
use crate::render::chart::{escape, marker, Chart, Mark, Scale, Series, PALETTE};
use crate::study::{Row, Study};

const WIDTH: f64 = 1000.0;
/// The plot's share of the width; the legend has the rest.
const PLOT: f64 = 560.0;
const PANEL: f64 = 360.0;
const LEGEND_LINE: f64 = 15.0;
/// The legend column's left edge and width.
const LEGEND_X: f64 = 24.0 + PLOT + 16.0;
const LEGEND_WIDTH: f64 = WIDTH - LEGEND_X - 16.0;
/// Legend type size, and the widest a character is taken to be (em).
const LEGEND_SIZE: f64 = 11.0;
const CHAR_EM: f64 = 0.62;
/// The markers, in the order a family's values take them.
const MARKS: [Mark; 6] = [
    Mark::Dots,
    Mark::Squares,
    Mark::Triangles,
    Mark::Diamonds,
    Mark::Crosses,
    Mark::Pluses,
];
/// The most legend entries (families) a panel has.
pub const MAX_FAMILIES: usize = 8;
/// The colours families take, in order: the chart's palette (Okabe–Ito)
/// with its yellow, too faint on white for a slide, replaced by olive.
const COLOURS: [&str; MAX_FAMILIES] = [
    PALETTE[0], PALETTE[1], PALETTE[2], PALETTE[3], PALETTE[4], PALETTE[5], PALETTE[7], "#999933",
];

/// The families of the study's one-knob rows, by knob: (family, knobs).
/// A knob not named here is a family of its own.
const KNOB_FAMILIES: [(&str, &[&str]); 5] = [
    ("time step", &[knobs::DT.name]),
    (
        "friction",
        &[knobs::FRICTION_MODEL.name, knobs::VELOCITY_LIMIT.name],
    ),
    (
        "contact resolution",
        &[
            knobs::RELAXATION.name,
            knobs::PROJECTION.name,
            knobs::RESTITUTION_FROM.name,
        ],
    ),
    (
        "detection",
        &[
            knobs::CCD.name,
            knobs::ROLLBACK.name,
            knobs::BOX_BOX.name,
            knobs::NARROW_PHASE.name,
        ],
    ),
    (
        "epsilons, float type, sleep",
        &[
            knobs::POSITION_EPSILON.name,
            knobs::VELOCITY_EPSILON.name,
            "precision",
            knobs::SLEEP.name,
        ],
    ),
];

/// One legend entry: a family of rows in one colour, each row a marker.
#[derive(Debug, Clone, PartialEq)]
pub struct Family {
    pub name: String,
    pub colour: &'static str,
    /// (row index, marker, the row's value as the legend names it).
    pub members: Vec<(usize, Mark, String)>,
}

/// A row's family and its value's label within it.
fn family_of(r: &Row) -> (String, String) {
    match r.knob.as_str() {
        "default" => (
            r.config.solver_label().to_string(),
            format!("{} (default)", r.config.budget.label()),
        ),
        "budget" => (r.config.solver_label().to_string(), r.config.budget.label()),
        // A --grid cross product: its first knob's value is the family.
        k if k.contains('+') => match r.value.split_once(", ") {
            Some((first, rest)) => (first.to_string(), rest.to_string()),
            None => (k.to_string(), r.value.clone()),
        },
        k => {
            let value = r
                .value
                .strip_prefix(&format!("{k}="))
                .unwrap_or(&r.value)
                .to_string();
            let family = KNOB_FAMILIES
                .iter()
                .find(|(_, knobs)| knobs.contains(&k))
                .map_or(k, |(f, _)| *f);
            if family == k {
                (k.to_string(), value)
            } else if family == "time step" {
                (format!("{family} ({k}, s)"), value)
            } else {
                (family.to_string(), format!("{k} = {value}"))
            }
        }
    }
}

/// The rows grouped into families, in the order they first appear: one
/// colour each, at most [`MAX_FAMILIES`] (the rest join the last, named
/// "other rows"), and within a family one marker per row in row order.
pub fn families(rows: &[Row]) -> Vec<Family> {
    let mut out: Vec<Family> = Vec::new();
    for (i, r) in rows.iter().enumerate() {
        let (name, value) = family_of(r);
        let at = match out.iter().position(|f| f.name == name) {
            Some(at) => at,
            None if out.len() < MAX_FAMILIES => {
                out.push(Family {
                    name,
                    colour: COLOURS[out.len()],
                    members: Vec::new(),
                });
                out.len() - 1
            }
            None => {
                let last = out.len() - 1;
                if out[last].name != "other rows" {
                    let first = std::mem::take(&mut out[last].members);
                    out[last].name = "other rows".into();
                    let old = family_of(&rows[first[0].0]).0;
                    out[last].members = first
                        .into_iter()
                        .map(|(j, m, v)| (j, m, format!("{old}: {v}")))
                        .collect();
                }
                out[last]
                    .members
                    .push((i, Mark::Dots, format!("{name}: {value}")));
                last
            }
        };
        if out[at].members.last().map(|m| m.0) != Some(i) {
            out[at].members.push((i, Mark::Dots, value));
        }
    }
    for f in &mut out {
        for (k, m) in f.members.iter_mut().enumerate() {
            m.1 = MARKS[k % MARKS.len()];
        }
    }
    out
}

fn drawable(r: &Row) -> bool {
    r.failure.is_none()
        && r.cost() > 0.0
        && r.cost().is_finite()
        && r.error_vs_reference > 0.0
        && r.error_vs_reference.is_finite()
}

/// The front as a staircase through its rows, cheapest first: from each
/// row across to the next one's cost, then down to its error (what the
/// front guarantees holds between two of its rows).
pub fn staircase(front: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for (k, &(x, y)) in front.iter().enumerate() {
        if k > 0 {
            out.push((x, front[k - 1].1));
        }
        out.push((x, y));
    }
    out
}

/// One piece of the legend: a family's heading (its colour) or a value
/// (its marker), at (x, line).
enum Piece {
    Heading(&'static str, String),
    Value(&'static str, Mark, String),
}

/// The legend laid out in the column: (piece, x offset, line).
fn legend(s: &crate::study::SceneStudy) -> (Vec<(Piece, f64, usize)>, usize) {
    let width = |text: &str| CHAR_EM * LEGEND_SIZE * text.chars().count() as f64;
    let mut out = Vec::new();
    let mut line = 0;
    for f in families(&s.rows) {
        out.push((Piece::Heading(f.colour, f.name.clone()), 0.0, line));
        line += 1;
        let mut x = 12.0;
        for (i, mark, value) in &f.members {
            let r = &s.rows[*i];
            let note = if !drawable(r) {
                " (not drawn)"
            } else if r.pareto {
                " ★"
            } else {
                ""
            };
            let text = format!("{value}{note}");
            let w = 14.0 + width(&text) + 12.0;
            if x > 12.0 && x + w > LEGEND_WIDTH {
                line += 1;
                x = 12.0;
            }
            out.push((Piece::Value(f.colour, *mark, text), x, line));
            x += w;
        }
        line += 1;
    }
    (out, line)
}

/// Characters per line of the reference under the legend.
pub const LEGEND_CHARS: usize = (LEGEND_WIDTH / (CHAR_EM * LEGEND_SIZE)) as usize;
/// Lines the reference takes at most under the legend.
const REFERENCE_LINES: usize = 5;

/// The height of one scene's panel: the plot, or the legend and the
/// reference under it when longer.
fn panel_height(legend_lines: usize) -> f64 {
    PANEL.max(64.0 + LEGEND_LINE * (legend_lines + 2 + REFERENCE_LINES) as f64)
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

/// The x axis's label: the cost the front is computed on.
pub const X_LABEL: &str = "work per simulated second (visits + ccd tests + 1 per step)";

pub fn render(study: &Study) -> String {
    render_with(study, false)
}

/// [`render`], each mark with its row's hover details as its `<title>`
/// when `tips` (the web page's chart).
pub fn render_with(study: &Study, tips: bool) -> String {
    let height = 80.0
        + study
            .scenes
            .iter()
            .map(|s| panel_height(legend(s).1))
            .sum::<f64>();
    let mut out = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">
<rect width="100%" height="100%" fill="#FFFFFF"/>
<text x="24" y="36" font-size="22" font-weight="bold">Speed against accuracy</text>
<text x="24" y="60" font-size="14" fill="#444444">error (m) vs work per simulated second, log–log: a colour per family, a marker per value, the front a staircase</text>
"##
    );
    let mut y0 = 80.0;
    for s in &study.scenes {
        let (pieces, lines) = legend(s);
        let h = panel_height(lines);
        let series: Vec<Series> = families(&s.rows)
            .iter()
            .flat_map(|f| {
                f.members.iter().map(|(i, mark, _)| {
                    let r = &s.rows[*i];
                    Series {
                        name: String::new(),
                        points: if drawable(r) {
                            vec![(r.cost(), r.error_vs_reference)]
                        } else {
                            Vec::new()
                        },
                        colour: f.colour,
                        mark: *mark,
                        dashed: false,
                    }
                })
            })
            .collect();
        let front: Vec<(f64, f64)> = crate::study::pareto::front(&s.rows)
            .into_iter()
            .filter(|r| drawable(r))
            .map(|r| (r.cost(), r.error_vs_reference))
            .collect();
        let tips: Vec<Vec<String>> = if tips {
            families(&s.rows)
                .iter()
                .flat_map(|f| f.members.iter().map(|(i, _, _)| vec![tip(&s.rows[*i])]))
                .collect()
        } else {
            Vec::new()
        };
        let chart = Chart {
            tips,
            title: format!("{} ({} s)", s.scene, s.seconds),
            x_label: X_LABEL.into(),
            y_label: "error (m)".into(),
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            series,
            cursor: None,
            front: (!front.is_empty()).then(|| staircase(&front)),
            marks: Vec::new(),
            ..Chart::default()
        };
        chart.draw(&mut out, (24.0, y0 + 16.0, PLOT, PANEL - 36.0));
        // The legend: a heading per family, its values under it.
        let lx = LEGEND_X;
        let top = y0 + 40.0;
        out.push_str(&format!(
            r##"<g font-size="11"><text x="{lx:.1}" y="{top:.1}" font-size="11" font-weight="bold">families (★ on the front, drawn as a dotted staircase)</text>
"##
        ));
        for (piece, dx, line) in &pieces {
            let y = top + LEGEND_LINE * (*line + 1) as f64;
            match piece {
                Piece::Heading(colour, name) => out.push_str(&format!(
                    r##"<rect x="{:.1}" y="{:.1}" width="10" height="10" fill="{colour}"/><text x="{:.1}" y="{y:.1}" font-size="11" font-weight="bold">{}</text>
"##,
                    lx + dx,
                    y - 9.0,
                    lx + dx + 16.0,
                    escape(name)
                )),
                Piece::Value(colour, mark, text) => {
                    marker(&mut out, *mark, lx + dx + 5.0, y - 4.0, colour);
                    out.push_str(&format!(
                        r##"<text x="{:.1}" y="{y:.1}" font-size="11">{}</text>
"##,
                        lx + dx + 14.0,
                        escape(text)
                    ));
                }
            }
        }
        // The reference, named under the legend, wrapped to the column.
        let first = top + LEGEND_LINE * (lines + 2) as f64;
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

/// A row's hover details: its knob and value, the two axes, the front.
fn tip(r: &crate::study::Row) -> String {
    let fmt = crate::format::Fmt::new(3);
    format!(
        "{} = {}: work/s {}, error {} m{}",
        r.knob,
        r.value,
        super::work(&fmt, r.cost()),
        super::num(&fmt, r.error_vs_reference),
        if r.pareto { ", on the front ★" } else { "" }
    )
}
