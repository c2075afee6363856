//! `contact-lab glossary`: every symbol of the worked solution with its
//! meaning, unit, the stages that use it and the lectures' names, as text,
//! Markdown or LaTeX (all read from `trace::glossary`).

use std::fmt::Write;

use crate::physics::StageId;
use crate::render::tex::{prose, to_latex};
use crate::trace::glossary::{SolverSymbol, Symbol, GLOSSARY, SOLVER_GLOSSARY};

fn unit_text(s: &Symbol) -> &'static str {
    if s.unit.is_empty() {
        "—"
    } else {
        s.unit
    }
}

/// Plain text: one symbol a line, aligned.
pub fn text() -> String {
    let (first, last) = (StageId::ALL[0], StageId::ALL[StageId::ALL.len() - 1]);
    let mut out = format!(
        "Symbols of the worked solution (subscript ᵢ: body 1 or 2; stages: {} {} … {} {})\n\n",
        first.number(),
        first.label_in_text(),
        last.number(),
        last.label_in_text()
    );
    // Combining accents (d̂, q̇) take no column.
    let cols = |t: &str| {
        t.chars()
            .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
            .count()
    };
    let width = GLOSSARY.iter().map(|s| cols(s.symbol)).max().unwrap_or(0);
    for s in GLOSSARY {
        let pad = " ".repeat(width - cols(s.symbol));
        let _ = write!(
            out,
            "{}{pad}  {} [{}; stages {}]",
            s.symbol,
            s.meaning,
            unit_text(s),
            s.stage_numbers()
        );
        if !s.elsewhere.is_empty() {
            let _ = write!(out, " — {}", s.elsewhere);
        }
        out.push('\n');
    }
    out.push_str(&solver_text(cols));
    out
}

fn solver_unit(s: &SolverSymbol) -> &'static str {
    if s.unit.is_empty() {
        "—"
    } else {
        s.unit
    }
}

/// The soft-step and XPBD quantities, one a line: symbol, formula, meaning
/// [unit; solver; JSON key].
fn solver_text(cols: impl Fn(&str) -> usize) -> String {
    let mut out = String::from(
        "\nQuantities of the soft step and XPBD (simulate --trace-step, the TUI's substeps)\n\n",
    );
    let width = SOLVER_GLOSSARY
        .iter()
        .map(|s| cols(s.symbol))
        .max()
        .unwrap_or(0);
    for s in SOLVER_GLOSSARY {
        let pad = " ".repeat(width - cols(s.symbol));
        let _ = write!(out, "{}{pad}  ", s.symbol);
        if !s.formula.is_empty() {
            let _ = write!(out, "{}: ", s.formula);
        }
        let _ = write!(out, "{} [{}; {}", s.meaning, solver_unit(s), s.solver);
        if !s.key.is_empty() {
            let _ = write!(out, "; JSON `{}`", s.key);
        }
        out.push_str("]\n");
    }
    out
}

/// A Markdown table with the symbols as inline maths.
pub fn markdown() -> String {
    let mut out = format!("# Glossary\n\nSubscript $i$: body 1 or 2. Stages: {}.\n\n| symbol | meaning | unit | stages | in the lectures |\n|---|---|---|---|---|\n", StageId::numbered_list(|l| l.to_string()));
    for s in GLOSSARY {
        let _ = writeln!(
            out,
            "| ${}$ | {} | {} | {} | {} |",
            to_latex(s.symbol).replace('|', "\\vert "),
            super::contact::markdown::cell(s.meaning),
            unit_text(s),
            s.stage_numbers(),
            super::contact::markdown::cell(s.elsewhere)
        );
    }
    out.push_str("\n## Soft step and XPBD\n\n| symbol | formula | meaning | unit | solver | JSON key |\n|---|---|---|---|---|---|\n");
    for s in SOLVER_GLOSSARY {
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} |",
            super::contact::markdown::cell(s.symbol),
            super::contact::markdown::cell(s.formula),
            super::contact::markdown::cell(s.meaning),
            solver_unit(s),
            s.solver,
            if s.key.is_empty() {
                String::new()
            } else {
                format!("`{}`", s.key)
            }
        );
    }
    out
}

/// A standalone LaTeX document with one `longtable`-free tabular per page
/// (only `amsmath`/`amssymb`, as the worked solutions need).
pub fn latex() -> String {
    let mut body = format!(
        "\\section*{{Glossary}}\nSubscript $i$: body 1 or 2. Stages: {}.\n\n",
        StageId::numbered_list(prose)
    );
    for chunk in GLOSSARY.chunks(25) {
        body.push_str("\\begin{tabular}{l p{7.5cm} l l}\n\\hline\nsymbol & meaning & unit & stages \\\\\n\\hline\n");
        for s in chunk {
            let mut meaning = prose(s.meaning);
            if !s.elsewhere.is_empty() {
                meaning.push_str(&format!(" \\emph{{({})}}", prose(s.elsewhere)));
            }
            let unit = if s.unit.is_empty() {
                "---".to_string()
            } else {
                format!(
                    "${}$",
                    crate::trace::glossary::unit_latex(s.unit).trim_start_matches("\\,")
                )
            };
            let _ = writeln!(
                body,
                "${}$ & {meaning} & {unit} & {} \\\\",
                to_latex(s.symbol),
                s.stage_numbers()
            );
        }
        body.push_str("\\hline\n\\end{tabular}\n\n\\bigskip\n");
    }
    super::contact::latex::standalone(&body)
}

/// JSON: `{"symbols": [{"symbol", "meaning", "unit", "stages": [stage ids], "elsewhere"}],
/// "solver_symbols": [{"symbol", "key", "formula", "meaning", "unit", "solver"}]}`.
pub fn json() -> String {
    let symbols: Vec<serde_json::Value> = GLOSSARY
        .iter()
        .map(|s| {
            serde_json::json!({
                "symbol": s.symbol,
                "meaning": s.meaning,
                "unit": s.unit,
                "stages": s.stages.iter().map(|id| id.json_name()).collect::<Vec<_>>(),
                "elsewhere": s.elsewhere,
            })
        })
        .collect();
    let solver: Vec<serde_json::Value> = SOLVER_GLOSSARY
        .iter()
        .map(|s| {
            serde_json::json!({
                "symbol": s.symbol,
                "key": s.key,
                "formula": s.formula,
                "meaning": s.meaning,
                "unit": s.unit,
                "solver": s.solver,
            })
        })
        .collect();
    serde_json::to_string_pretty(
        &serde_json::json!({ "symbols": symbols, "solver_symbols": solver }),
    )
    .expect("JSON")
        + "\n"
}
