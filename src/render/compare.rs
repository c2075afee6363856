//! `solve --compare-friction`: every friction model's result side by side.

use serde_json::json;

use crate::format::Fmt;
use crate::physics::FrictionModel;
use crate::trace::{Trace, Verdict};

const HOW_THEY_DIFFER: &str = "\
How they differ: millington solves for the impulse that stops all sliding and, if that needs more than μ_s g_n,
slides with μ_d g_n along it while keeping the normal velocity target; kinetic-direction (seeds 002/003) always
applies μ_k j against the slip, however slow, so it can reverse the slip and, when friction turns the body, miss
the normal target; velocity-scaling (seed 004) sets a velocity target (remove, or scale by μ_d) instead of bounding
the impulse, so its impulse can leave the Coulomb cone.";

fn final_impulse(t: &Trace) -> Option<&crate::trace::Value> {
    t.value("friction_clamp", "impulse_world")
        .or_else(|| t.value("impulse", "impulse_world"))
}

fn verdict<'a>(t: &'a Trace, prefix: &str) -> Option<&'a Verdict> {
    t.verdicts.iter().find(|v| v.label.starts_with(prefix))
}

fn mark(v: Option<&Verdict>) -> &'static str {
    v.map_or("–", Verdict::mark)
}

/// Rows of (label, one cell per model).
fn rows(traces: &[(FrictionModel, Trace)], fmt: &Fmt) -> Vec<(String, Vec<String>)> {
    let cell = |t: &Trace, stage: &str, name: &str| {
        t.value(stage, name)
            .map_or("–".to_string(), |v| fmt.value(v))
    };
    let mut rows = vec![
        (
            "regime".to_string(),
            traces
                .iter()
                .map(|(_, t)| cell(t, "friction_clamp", "regime"))
                .collect(),
        ),
        (
            "impulse (world)".to_string(),
            traces
                .iter()
                .map(|(_, t)| final_impulse(t).map_or("–".into(), |v| fmt.value(v)))
                .collect(),
        ),
    ];
    let first = &traces[0].1;
    for (n, name) in first.bodies.iter().enumerate() {
        let n = n + 1;
        if first.value("apply_impulse", &format!("v{n}")).is_none() {
            continue;
        }
        rows.push((
            format!("{name} v′"),
            traces
                .iter()
                .map(|(_, t)| cell(t, "apply_impulse", &format!("v{n}")))
                .collect(),
        ));
        rows.push((
            format!("{name} ω′"),
            traces
                .iter()
                .map(|(_, t)| cell(t, "apply_impulse", &format!("w{n}")))
                .collect(),
        ));
    }
    rows.push((
        "energy change".into(),
        traces
            .iter()
            .map(|(_, t)| cell(t, "checks", "energy_change"))
            .collect(),
    ));
    rows.push((
        "slip speed after".into(),
        traces
            .iter()
            .map(|(_, t)| cell(t, "checks", "slip_speed_after"))
            .collect(),
    ));
    rows.push((
        "inside friction cone".into(),
        traces
            .iter()
            .map(|(_, t)| mark(verdict(t, "impulse inside")).into())
            .collect(),
    ));
    rows.push((
        "normal target met".into(),
        traces
            .iter()
            .map(|(_, t)| mark(verdict(t, "separating velocity")).into())
            .collect(),
    ));
    rows.push((
        "energy does not rise".into(),
        traces
            .iter()
            .map(|(_, t)| mark(verdict(t, "kinetic energy")).into())
            .collect(),
    ));
    rows
}

pub fn text(traces: &[(FrictionModel, Trace)], fmt: &Fmt) -> String {
    let t = &traces[0].1;
    let mut out = format!(
        "Friction models compared — {} ({}), contact {}\n\n",
        t.title, t.lesson, t.contact_label
    );
    let rows = rows(traces, fmt);
    let label_w = rows
        .iter()
        .map(|(l, _)| l.chars().count())
        .max()
        .unwrap_or(0);
    let col_w: Vec<usize> = (0..traces.len())
        .map(|i| {
            rows.iter()
                .map(|(_, c)| c[i].chars().count())
                .chain([traces[i].0.name().len()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let pad = |s: &str, w: usize| format!("{s}{}", " ".repeat(w.saturating_sub(s.chars().count())));
    let mut header = pad("", label_w);
    for (i, (m, _)) in traces.iter().enumerate() {
        header.push_str("  ");
        header.push_str(&pad(m.name(), col_w[i]));
    }
    out.push_str(header.trim_end());
    out.push('\n');
    for (label, cells) in &rows {
        let mut line = pad(label, label_w);
        for (i, c) in cells.iter().enumerate() {
            line.push_str("  ");
            line.push_str(&pad(c, col_w[i]));
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out.push('\n');
    out.push_str(HOW_THEY_DIFFER);
    out.push('\n');
    out
}

pub fn json(traces: &[(FrictionModel, Trace)]) -> String {
    let models: Vec<_> = traces
        .iter()
        .map(|(m, t)| json!({ "model": m.name(), "solution": super::json::to_json(t) }))
        .collect();
    serde_json::to_string_pretty(&json!({ "models": models })).expect("JSON") + "\n"
}
