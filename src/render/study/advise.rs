//! The advice shown: text and Markdown for a reader (the configuration as
//! a snippet to paste, its cost and error, what each kept knob buys, what
//! the scene does not need, what the run exercised, how the search went),
//! JSON for scripts (the advise contract, docs/study.md).

use serde_json::{json, Value};

use crate::format::Fmt;
use crate::study::advise::{settings_snippet, value_of, Advice};
use crate::study::exercised::findings;

fn num(fmt: &Fmt, x: f64) -> String {
    super::num(fmt, x)
}

/// A searched dimension's value as a reader reads it: the time step with
/// its unit (`1/30 s`).
fn shown(name: &str, value: &str) -> String {
    match name {
        "dt" => format!("{value} s"),
        _ => value.to_string(),
    }
}

/// The dimensions the advice sets away from the scene's own values:
/// `name: scene's → advice's`.
fn changed(a: &Advice) -> Vec<String> {
    a.values
        .iter()
        .filter_map(|(name, v)| {
            let own = value_of(&a.default, name);
            (own != *v).then(|| format!("{name} {} → {}", shown(name, &own), shown(name, v)))
        })
        .collect()
}

/// Said before anything else when the scene as written, or its reference,
/// blows up: the advice is then not the scene as written.
pub fn warning(a: &Advice) -> Option<String> {
    let own = a
        .default_failure
        .as_ref()
        .map(|why| format!("the scene's own run (its settings as written) blows up ({why})"));
    let reference = a
        .reference_failure
        .as_ref()
        .map(|why| format!("its reference run blows up ({why}), so the errors below are measured against a run that failed"));
    let what: Vec<String> = own.into_iter().chain(reference).collect();
    if what.is_empty() {
        return None;
    }
    let changes = changed(a);
    Some(format!(
        "Warning: {}. The advice does not model the scene as written: it changes {}.",
        what.join("; "),
        if changes.is_empty() {
            "nothing the search turns".to_string()
        } else {
            changes.join(", ")
        }
    ))
}

/// The parts both human formats show, as (heading, lines).
fn sections(a: &Advice, fmt: &Fmt) -> Vec<(String, Vec<String>)> {
    let c = &a.choice;
    let mut out = Vec::new();
    let mut found = vec![
        format!(
            "cost {} (work per simulated second: contact visits + 1 per step), error {} m against the target {} m (per {}: {})",
            num(fmt, c.cost),
            num(fmt, c.error),
            num(fmt, a.target),
            a.per.name(),
            a.per.describe()
        ),
        format!(
            "error at the run's end {} m, at its worst step {} m",
            num(fmt, a.end_error),
            num(fmt, a.worst_step_error)
        ),
    ];
    if let Some(times) = a.strays() {
        found.push(format!(
            "The run meets the target only as it ends: on the way it strays up to {} m from the reference ({}× the target); if the path matters, run `contact-lab advise {} --error {} --per step`.",
            num(fmt, a.worst_step_error),
            num(fmt, times),
            a.scene,
            a.target
        ));
    }
    found.extend([
        format!(
            "the reference costs {} ({}× this)",
            num(fmt, a.reference_cost),
            num(fmt, a.reference_cost / c.cost)
        ),
        a.values
            .iter()
            .map(|(k, v)| format!("{k} = {}", shown(k, v)))
            .collect::<Vec<_>>()
            .join(", "),
    ]);
    out.push(("The cheapest configuration found".to_string(), found));
    out.push((
        "What each knob kept buys (the error with that knob alone at its cheap setting)".into(),
        if a.needed.is_empty() {
            vec!["nothing: every knob is at its cheapest setting".into()]
        } else {
            a.needed
                .iter()
                .map(|n| {
                    format!(
                        "{} = {} (cheap: {}): error {} m without it",
                        n.knob,
                        shown(n.knob, &n.value),
                        shown(n.knob, &n.cheap),
                        num(fmt, n.error_without)
                    )
                })
                .collect()
        },
    ));
    // A knob the scene does not need is at its cheapest value, which the
    // snippet sets: named with that value, so the two agree.
    out.push((
        "Fine at their cheapest value, which the snippet sets (the scene does not need more)"
            .into(),
        vec![if a.not_needed.is_empty() {
            "none: every knob is kept above its cheapest value".into()
        } else {
            a.not_needed
                .iter()
                .map(|k| {
                    let v = a.values.iter().find(|(n, _)| n == k).map_or("", |(_, v)| v);
                    format!("{k} = {}", shown(k, v))
                })
                .collect::<Vec<_>>()
                .join(", ")
        }],
    ));
    out.push((
        "What the run exercised (the reference run)".into(),
        findings(&a.exercised)
            .iter()
            .map(|f| {
                format!(
                    "{} {}: {} → {}",
                    if f.present { "✓" } else { "·" },
                    f.feature,
                    f.evidence,
                    f.calls_for
                )
            })
            .collect(),
    ));
    let mut held: Vec<String> = a
        .held
        .iter()
        .map(|h| format!("{}: {}", h.name, h.why))
        .collect();
    if held.is_empty() {
        held.push("none".into());
    }
    out.push(("Knobs not searched".into(), held));
    out.push((
        "The search".into(),
        vec![format!(
            "searched {} configurations in {} s: coordinate descent from the reference ({}){}, each pass trying every value of one dimension with the others held and keeping the cheapest within the target; where no single change helps, pair moves (each value that alone cuts the cost with every value of another dimension) restart it from the cheapest pair within the target; then from the reference at each time step (a pair move, free moves included, and descents), and all of it again from the reference with the other solver, the cheapest end kept; {} passes, {} pair moves taken of {} pairs tried, {} steps simulated ({} s each)",
            a.runs,
            num(fmt, a.wall_seconds),
            a.reference,
            if a.per == crate::study::advise::Per::Run {
                " and from where the same descent against the per-step error stops"
            } else {
                ""
            },
            a.passes,
            a.escapes,
            a.pairs,
            a.steps,
            num(fmt, a.seconds)
        )],
    ));
    out
}

pub fn text(a: &Advice, fmt: &Fmt) -> String {
    let mut out = warning(a).map_or_else(String::new, |w| w + "\n\n");
    out += &format!(
        "{}  ({}, {} s): the cheapest model within {} m of the reference, per {}\n\nMerge into the scene's tables (a key the scene already sets is replaced):\n\n",
        a.title,
        a.scene,
        num(fmt, a.seconds),
        num(fmt, a.target),
        a.per.name()
    );
    for l in settings_snippet(a).lines() {
        out.push_str(&format!("    {l}\n"));
    }
    for (head, lines) in sections(a, fmt) {
        out.push_str(&format!("\n{head}:\n"));
        for l in lines {
            out.push_str(&format!("  {l}\n"));
        }
    }
    out
}

pub fn markdown(a: &Advice, fmt: &Fmt) -> String {
    let mut out = format!(
        "# {} (`{}`): the cheapest model within {} m, per {}\n\n{}Merge into the scene's tables (a key the scene already sets is replaced):\n\n```toml\n{}```\n",
        a.title,
        a.scene,
        num(fmt, a.target),
        a.per.name(),
        warning(a).map_or_else(String::new, |w| format!("**{w}**\n\n")),
        settings_snippet(a)
    );
    for (head, lines) in sections(a, fmt) {
        out.push_str(&format!("\n## {head}\n\n"));
        for l in lines {
            out.push_str(&format!("- {l}\n"));
        }
    }
    out
}

pub fn json(a: &Advice) -> String {
    let config = super::json::config(&a.choice.config);
    let number = |x: f64| if x.is_finite() { json!(x) } else { Value::Null };
    let v = json!({
        "scene": a.scene,
        "target": a.target,
        "per": a.per.name(),
        "seconds": a.seconds,
        "reference": a.reference,
        "reference_cost": a.reference_cost,
        "choice": { "config": config, "cost": a.choice.cost, "error": number(a.choice.error),
                    "end_error": number(a.end_error), "worst_step_error": number(a.worst_step_error) },
        "settings": settings_snippet(a),
        "needed": a.needed.iter().map(|n| json!({
            "knob": n.knob, "value": n.value, "cheap": n.cheap, "error_without": number(n.error_without),
        })).collect::<Vec<_>>(),
        "not_needed": a.not_needed,
        "warning": warning(a),
        "scene_run_failure": a.default_failure,
        "reference_failure": a.reference_failure,
        "not_searched": a.held.iter().map(|h| json!({ "knob": h.name, "why": h.why })).collect::<Vec<_>>(),
        "exercised": findings(&a.exercised).iter().map(|f| json!({
            "feature": f.feature, "present": f.present, "evidence": f.evidence, "calls_for": f.calls_for,
        })).collect::<Vec<_>>(),
        "search": { "method": if a.per == crate::study::advise::Per::Run {
                        "coordinate descent from the reference and from the per-step descent's stop, with pair moves out of local optima; then from the reference at each time step (a pair move, free moves included, and descents); then again from the reference with the other solver; the cheapest end kept"
                    } else {
                        "coordinate descent from the reference, with pair moves out of local optima; then from the reference at each time step (a pair move, free moves included, and descents); then again from the reference with the other solver; the cheapest end kept"
                    },
                    "passes": a.passes, "pair_moves": a.escapes, "pairs_tried": a.pairs,
                    "configurations": a.runs, "steps": a.steps, "seconds": a.wall_seconds },
    });
    serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
}
