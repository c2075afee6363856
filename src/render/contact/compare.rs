//! `solve --compare-friction`: every friction model's result side by side.

use crate::render::fill::Fill;
use serde_json::json;

use crate::format::Fmt;
use crate::physics::checks::CheckKind;
use crate::physics::{FrictionModel, Solution};
use crate::trace::contact::regime_name;
use crate::trace::{Trace, Value, Verdict};

/// One friction model's result: the solution (for its physics facts) and
/// its trace (for the values shown).
#[derive(Debug, Clone)]
pub struct Compared {
    pub model: FrictionModel,
    pub solution: Solution<f64>,
    pub trace: Trace,
}

const HOW_THEY_DIFFER: &str = "\
How they differ: millington solves for the impulse that stops all sliding and, if that needs more than μ_s g_n,
slides with μ_d g_n along it while keeping the normal velocity target; kinetic-direction (the collisions lectures: Lecture IV Collisions; Pronost) always
applies μ_k j against the slip, however slow, so it can reverse the slip and, when friction turns the body, miss
the normal target; velocity-scaling (the friction lecture: PSE Friction) sets a velocity target (remove, or scale by μ_d) instead of bounding
the impulse, so its impulse can leave the Coulomb cone.";

/// ✓, ✗ or · for a check the solution ran, – for one it did not.
fn mark(s: &Solution<f64>, kind: CheckKind) -> &'static str {
    s.checks
        .get(kind)
        .map_or("–", |c| Verdict::mark_of(c.passed))
}

/// Rows of (label, one cell per model).
fn rows(compared: &[Compared], fmt: &Fmt) -> Vec<(String, Vec<String>)> {
    let cell = |t: &Trace, stage: &str, name: &str| {
        t.value(stage, name)
            .map_or("–".to_string(), |v| fmt.value(v))
    };
    let mut rows = vec![
        (
            "regime".to_string(),
            compared
                .iter()
                .map(|c| c.solution.regime().map_or("–", regime_name).to_string())
                .collect(),
        ),
        (
            "impulse (world)".to_string(),
            compared
                .iter()
                .map(|c| {
                    c.solution
                        .final_impulse_world()
                        .map_or("–".into(), |g| fmt.value(&Value::from(g)))
                })
                .collect(),
        ),
    ];
    let first = &compared[0];
    for (n, name) in first.trace.bodies.iter().enumerate() {
        let applied = first.solution.applied.as_ref();
        if applied.is_none_or(|a| a.bodies[n].is_none()) {
            continue;
        }
        let n = n + 1;
        rows.push((
            format!("{name} v′"),
            compared
                .iter()
                .map(|Compared { trace: t, .. }| cell(t, "apply_impulse", &format!("v{n}")))
                .collect(),
        ));
        rows.push((
            format!("{name} ω′"),
            compared
                .iter()
                .map(|Compared { trace: t, .. }| cell(t, "apply_impulse", &format!("w{n}")))
                .collect(),
        ));
    }
    rows.push((
        "energy change".into(),
        compared
            .iter()
            .map(|Compared { trace: t, .. }| cell(t, "checks", "energy_change"))
            .collect(),
    ));
    rows.push((
        "slip speed after".into(),
        compared
            .iter()
            .map(|Compared { trace: t, .. }| cell(t, "checks", "slip_speed_after"))
            .collect(),
    ));
    rows.push((
        "inside friction cone".into(),
        compared
            .iter()
            .map(|c| mark(&c.solution, CheckKind::FrictionCone).into())
            .collect(),
    ));
    rows.push((
        "normal target met".into(),
        compared
            .iter()
            .map(|c| mark(&c.solution, CheckKind::Restitution).into())
            .collect(),
    ));
    rows.push((
        "energy does not rise".into(),
        compared
            .iter()
            .map(|c| mark(&c.solution, CheckKind::Energy).into())
            .collect(),
    ));
    rows
}

pub fn text(compared: &[Compared], fmt: &Fmt) -> String {
    let t = &compared[0].trace;
    let mut out = format!(
        "Friction models compared — {} ({}), contact {}\n\n",
        t.title, t.lesson, t.contact_label
    );
    let rows = rows(compared, fmt);
    let label_w = rows
        .iter()
        .map(|(l, _)| l.chars().count())
        .max()
        .unwrap_or(0);
    let col_w: Vec<usize> = (0..compared.len())
        .map(|i| {
            rows.iter()
                .map(|(_, c)| c[i].chars().count())
                .chain([compared[i].model.name().len()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let pad = |s: &str, w: usize| format!("{s}{}", " ".repeat(w.saturating_sub(s.chars().count())));
    let mut header = pad("", label_w);
    for (i, c) in compared.iter().enumerate() {
        header.push_str("  ");
        header.push_str(&pad(c.model.name(), col_w[i]));
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

pub fn json(compared: &[Compared]) -> String {
    let models: Vec<_> = compared
        .iter()
        .map(|c| json!({ "model": c.model.name(), "solution": super::json::to_json(&c.trace) }))
        .collect();
    serde_json::to_string_pretty(&json!({ "models": models })).expect("JSON") + "\n"
}
