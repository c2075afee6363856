//! The verdict matrix shown (docs/study.md "The verdict matrix"): a text
//! matrix (a row per criterion, a column per solver, ✓ or ✗ with the
//! measured figure), JSON per the study contract (`{ "verdicts": [ {
//! "scene", "solver", "pass", "criterion", "measured" } ] }`), and an SVG
//! grid of the same cells.

use serde_json::{json, Value};

use crate::format::Fmt;
use crate::knobs::Choice;
use crate::render::chart::escape;
use crate::study::verdicts::criteria::SCENES;
use crate::study::verdicts::{Matrix, Size, Verdict};

/// The words before the matrix: what ran, and at which size.
fn preamble(m: &Matrix) -> String {
    let mut out = format!(
        "Verdict matrix: {} scenes under {} solvers (every choice of the `solver` knob; warm-started too where `warm_start` applies), each cell ✓ (passes) or ✗ (fails) with the figure measured against the bound.\n",
        SCENES.len(),
        m.columns.len()
    );
    for (solver, why) in crate::study::verdicts::EXCLUDED {
        out += &format!("Not a column: {}: {why}.\n", solver.name());
    }
    if m.size == Size::Reduced {
        out += "Reduced sizes (--quick): stack of 4, pyramid base 3, overlapped stack of 2, 8 spheres, shorter runs; the bounds are the full matrix's.\n";
    }
    if m.not_run > 0 {
        out += &format!(
            "Interrupted: {} of {} cells not run (—).\n",
            m.not_run,
            SCENES.len() * m.columns.len()
        );
    }
    out
}

/// A cell as the text and the figure show it: ✓ or ✗ and the figure.
pub fn cell(fmt: &Fmt, v: &Verdict) -> String {
    let mark = if v.pass { "✓" } else { "✗" };
    match (&v.failure, v.measured.is_finite()) {
        (Some(_), _) => format!("{mark} blew up"),
        (None, true) => format!("{mark} {}", fmt.num(v.measured)),
        (None, false) => format!("{mark} none"),
    }
}

/// The text matrix, folded to `width` as a table (0: never).
pub fn text(m: &Matrix, fmt: &Fmt, width: usize) -> String {
    let mut out = preamble(m);
    out.push('\n');
    let mut head = vec!["scene".to_string(), "criterion".into(), "bound".into()];
    head.extend(m.columns.iter().cloned());
    let rows: Vec<Vec<String>> = m
        .rows
        .iter()
        .zip(&m.cells)
        .map(|(&(s, k), cells)| {
            let c = &SCENES[s].criteria[k];
            let mut row = vec![
                SCENES[s].id.to_string(),
                c.name.to_string(),
                format!("≤ {} {}", fmt.num(c.bound), c.unit),
            ];
            row.extend(
                cells
                    .iter()
                    .map(|v| v.as_ref().map_or("—".into(), |v| cell(fmt, v))),
            );
            row
        })
        .collect();
    out += &crate::render::wrap::table(0, 2, &head, &rows, width);
    out += "\nPasses: ";
    let passes: Vec<String> = m
        .columns
        .iter()
        .enumerate()
        .map(|(j, name)| {
            let run: Vec<&Verdict> = m.cells.iter().filter_map(|r| r[j].as_ref()).collect();
            let pass = run.iter().filter(|v| v.pass).count();
            format!("{name} {pass} of {}", run.len())
        })
        .collect();
    out += &passes.join(", ");
    out += ".\n\nThe scenes and their criteria:\n";
    for s in SCENES {
        out += &format!("  {}: {}.\n", s.id, s.what);
        for c in s.criteria {
            out += &format!("    {} ({}): {}.\n", c.name, c.unit, c.text);
        }
    }
    let failures: Vec<String> = m
        .verdicts()
        .filter_map(|v| {
            v.failure
                .as_ref()
                .map(|f| format!("  {} under {}: {f}", v.scene, v.solver))
        })
        .collect();
    if !failures.is_empty() {
        out += "\nRuns that blew up (they fail):\n";
        out += &failures.join("\n");
        out.push('\n');
    }
    out
}

fn number(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// The JSON: the contract's five keys first in each verdict, then the
/// row's name, the unit, the bound and a blow-up's message.
pub fn json(m: &Matrix) -> String {
    let verdicts: Vec<Value> = m
        .verdicts()
        .map(|v| {
            json!({
                "scene": v.scene,
                "solver": v.solver,
                "pass": v.pass,
                "criterion": v.criterion,
                "measured": number(v.measured),
                "name": v.name,
                "unit": v.unit,
                "bound": v.bound,
                "failure": v.failure,
            })
        })
        .collect();
    let doc = json!({
        "size": match m.size { Size::Full => "full", Size::Reduced => "reduced" },
        "solvers": m.columns,
        "not_run": m.not_run,
        "verdicts": verdicts,
    });
    let mut s = serde_json::to_string_pretty(&doc).unwrap_or_default();
    s.push('\n');
    s
}

const ROW: f64 = 34.0;
const LABEL: f64 = 300.0;
const COLUMN: f64 = 170.0;
const TOP: f64 = 70.0;
const PASS: &str = "#cfe8cf";
const FAIL: &str = "#f3c6c0";
const NOT_RUN: &str = "#e6e6e6";

/// The SVG grid: a row per criterion (scene and criterion at the left), a
/// column per solver, each cell green (passes) or red (fails) with ✓ or ✗
/// and the figure; grey when not run.
pub fn svg(m: &Matrix, fmt: &Fmt) -> String {
    let width = LABEL + COLUMN * m.columns.len() as f64 + 20.0;
    let height = TOP + ROW * m.rows.len() as f64 + 40.0;
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" viewBox=\"0 0 {width:.0} {height:.0}\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let title = match m.size {
        Size::Full => "Verdict matrix: each scene's criterion under each solver".to_string(),
        Size::Reduced => {
            "Verdict matrix (reduced sizes): each scene's criterion under each solver".to_string()
        }
    };
    s += &format!(
        "<text x=\"10\" y=\"24\" font-size=\"16\" font-weight=\"bold\">{}</text>\n",
        escape(&title)
    );
    for (j, name) in m.columns.iter().enumerate() {
        let x = LABEL + COLUMN * (j as f64 + 0.5);
        s += &format!(
            "<text x=\"{x:.1}\" y=\"{:.1}\" font-size=\"12\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>\n",
            TOP - 10.0,
            escape(name)
        );
    }
    for (i, (&(sc, k), cells)) in m.rows.iter().zip(&m.cells).enumerate() {
        let y = TOP + ROW * i as f64;
        let c = &SCENES[sc].criteria[k];
        s += &format!(
            "<text x=\"10\" y=\"{:.1}\" font-size=\"12\">{}</text>\n<text x=\"10\" y=\"{:.1}\" font-size=\"10\" fill=\"#555\">{} ≤ {} {}</text>\n",
            y + 14.0,
            escape(SCENES[sc].id),
            y + 27.0,
            escape(c.name),
            escape(&fmt.num(c.bound)),
            escape(c.unit)
        );
        for (j, v) in cells.iter().enumerate() {
            let x = LABEL + COLUMN * j as f64;
            let (fill, label) = match v {
                Some(v) => (if v.pass { PASS } else { FAIL }, cell(fmt, v)),
                None => (NOT_RUN, "not run".to_string()),
            };
            s += &format!(
                "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{fill}\" stroke=\"white\" stroke-width=\"2\"/>\n<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
                x,
                y,
                COLUMN,
                ROW,
                x + COLUMN / 2.0,
                y + ROW / 2.0 + 4.0,
                escape(&label)
            );
        }
    }
    s += &format!(
        "<text x=\"10\" y=\"{:.1}\" font-size=\"11\" fill=\"#555\">green: passes (measured ≤ bound); red: fails; the criteria in words: docs/study.md</text>\n</svg>\n",
        height - 14.0
    );
    s
}
