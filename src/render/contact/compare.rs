//! `solve --compare-friction`: every friction model's result side by side.

use crate::knobs::Choice;
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

/// One paragraph (folded with the rest of the text).
const HOW_THEY_DIFFER: &str = "\
How they differ: millington solves for the impulse that stops all sliding and, if that needs more than μ_s g_n, \
slides with μ_d g_n along it while keeping the normal velocity target; kinetic-direction (the collisions lectures: Lecture IV Collisions; Pronost) always \
applies μ_k j against the slip, however slow, so it can reverse the slip and, when friction turns the body, miss \
the normal target; velocity-scaling (the friction lecture: PSE Friction) sets a velocity target (remove, or scale by μ_d) instead of bounding \
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

/// The models side by side, the table folded to `width` as a table (0:
/// never).
pub fn text(compared: &[Compared], fmt: &Fmt, width: usize) -> String {
    let t = &compared[0].trace;
    let mut out = format!(
        "Friction models compared — {} ({}), contact {}\n\n",
        t.title, t.lesson, t.contact_label
    );
    let head: Vec<String> = std::iter::once(String::new())
        .chain(compared.iter().map(|c| c.model.name().to_string()))
        .collect();
    let rows: Vec<Vec<String>> = rows(compared, fmt)
        .into_iter()
        .map(|(label, cells)| std::iter::once(label).chain(cells).collect())
        .collect();
    out.push_str(&crate::render::wrap::table(0, 1, &head, &rows, width));
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
