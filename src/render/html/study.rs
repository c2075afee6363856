//! `study` as a web page: how each number is measured, the chart (the
//! study's SVG inline, each mark's details in its `<title>`, shown on
//! hover), then per scene the reference, the trade and the table. Without
//! the script the tables are plain; with it each column heading sorts its
//! table (study.js), by the numbers the cells show (`data-sort`).

use std::fmt::Write;

use super::{esc, figure, page};
use crate::format::Fmt;
use crate::render::study::{self as show, MEASURES};
use crate::study::{Row, Study};

const SCRIPT: &str = include_str!("study.js");

/// The number each cell sorts by, in the column order of
/// [`show::headers`]; `None` sorts by the cell's text (knob, value).
pub fn sort_keys(r: &Row, timed: bool) -> Vec<Option<f64>> {
    let mut k = vec![
        None,
        None,
        Some(r.work_per_second),
        Some(r.error_vs_reference),
        Some(if r.failure.is_some() {
            -1.0
        } else {
            f64::from(u8::from(r.pareto))
        }),
    ];
    if timed {
        k.push(r.microseconds_per_second.map(|[m, _, _]| m));
    }
    k.extend([
        Some(r.work()),
        Some(r.limit_steps as f64),
        Some(r.max_penetration),
        Some(r.max_closing_velocity),
        Some(r.energy_gain),
        Some(r.drift),
        Some(r.missed_collisions as f64),
    ]);
    k
}

fn table(study: &Study, rows: &[Row], fmt: &Fmt, caption: &str) -> String {
    let mut out = format!(
        "<table class=\"sortable\">\n<caption>{}</caption>\n<thead><tr>",
        esc(caption)
    );
    for h in show::headers(study.timed) {
        let _ = write!(out, "<th scope=\"col\">{}</th>", esc(h));
    }
    out.push_str("</tr></thead>\n<tbody>\n");
    for r in rows {
        let class = if r.pareto { " class=\"front\"" } else { "" };
        let _ = write!(out, "<tr{class}>");
        let keys = sort_keys(r, study.timed);
        for (i, c) in show::cells(fmt, r, study.timed).iter().enumerate() {
            let key = match keys.get(i).copied().flatten() {
                Some(x) if x.is_finite() => format!(" data-sort=\"{x:e}\""),
                Some(_) => " data-sort=\"NaN\"".into(),
                None => String::new(),
            };
            let _ = write!(out, "<td{key}>{}</td>", esc(c));
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody>\n</table>\n");
    out
}

pub fn document(study: &Study, fmt: &Fmt) -> String {
    let mut head = String::from("<h1>Speed against accuracy</h1>\n<p>Each scene runs under its own settings (the default row), then with one knob turned at a time, and with the iteration budget of each solver. Every configuration is compared with the most accurate one of the same scene, the reference. ★ marks the Pareto front: no other configuration is both cheaper in work per simulated second and more accurate.</p>\n");
    head.push_str("<details><summary>How each number is measured</summary>\n<ul>\n");
    for m in MEASURES {
        let _ = writeln!(head, "<li>{}</li>", esc(m));
    }
    if study.timed {
        let _ = writeln!(
            head,
            "<li>{} timed runs per configuration</li>",
            study.repeats
        );
    }
    head.push_str("</ul>\n</details>\n");
    let mut body = String::from("<main>\n<section class=\"chart\" aria-labelledby=\"chart-h\">\n<h2 id=\"chart-h\">Error against work</h2>\n<p class=\"meta\">Hover a mark (or focus the table) for its configuration's numbers.</p>\n");
    let _ = writeln!(
        body,
        "<figure>{}<figcaption>Error (m) against work per simulated second, log–log: a colour per family, a marker per value, the front a dotted staircase.</figcaption></figure>\n</section>",
        figure::inline(&show::svg::render_with(study, true), "study")
    );
    for (n, s) in study.scenes.iter().enumerate() {
        let _ = writeln!(
            body,
            "<section class=\"scene\" aria-labelledby=\"s{n}\">\n<h2 id=\"s{n}\">{} (<code>{}</code>, {} s)</h2>\n<p><strong>Reference:</strong> {}.</p>\n<p><strong>The trade:</strong> {}</p>",
            esc(&s.title),
            esc(&s.scene),
            fmt.num(s.seconds),
            esc(&s.reference),
            esc(&s.verdict)
        );
        body.push_str(&table(
            study,
            &s.rows,
            fmt,
            &format!("{}: one row per configuration", s.scene),
        ));
        body.push_str("</section>\n");
    }
    body.push_str("</main>");
    page::page_with(
        "Speed against accuracy — study",
        page::Steps::Plain,
        &head,
        &body,
        SCRIPT,
    )
}
