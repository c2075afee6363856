//! The study as JSON (docs/study.md): `{ "scenes": [ { "scene", "reference",
//! "rows": [ { "config": {…}, "microseconds_per_step", …, "work_per_second",
//! …, "pareto" } ] } ] }`, the top-level `"cost"` naming the field the front
//! is computed on (`work_per_second`). Not-a-number values are `null`;
//! without timing the timing keys are absent.

use serde_json::{json, Map, Value};

use crate::lesson::knob_value;
use crate::study::{study_knobs, Budget, Config, Row, Study};

fn number(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// Every knob with its typed value.
pub fn config(c: &Config) -> Value {
    let mut o = Map::new();
    o.insert(
        "budget".into(),
        match c.budget {
            Budget::PerContact(n) => json!(n),
            Budget::Converged => json!("converged"),
        },
    );
    o.insert("precision".into(), json!(c.precision.name()));
    for k in study_knobs() {
        o.insert(k.name.into(), knob_value::json(c.get(k)));
    }
    Value::Object(o)
}

fn row(r: &Row) -> Value {
    let mut o = Map::new();
    o.insert("knob".into(), json!(r.knob));
    o.insert("value".into(), json!(r.value));
    o.insert("config".into(), config(&r.config));
    if let Some([median, lo, hi]) = r.microseconds {
        o.insert("microseconds_per_step".into(), number(median));
        o.insert(
            "microseconds_spread".into(),
            json!([number(lo), number(hi)]),
        );
    }
    if let Some([median, lo, hi]) = r.microseconds_per_second {
        o.insert("microseconds_per_second".into(), number(median));
        o.insert(
            "microseconds_per_second_spread".into(),
            json!([number(lo), number(hi)]),
        );
    }
    o.insert("work_per_second".into(), number(r.work_per_second));
    o.insert("contact_visits_per_step".into(), number(r.visits_per_step));
    o.insert("ccd_tests_per_step".into(), number(r.ccd_tests_per_step));
    o.insert("limit_steps".into(), json!(r.limit_steps));
    o.insert("steps".into(), json!(r.steps));
    o.insert("max_penetration".into(), number(r.max_penetration));
    o.insert(
        "max_closing_velocity".into(),
        number(r.max_closing_velocity),
    );
    o.insert("energy_gain".into(), number(r.energy_gain));
    o.insert("drift".into(), number(r.drift));
    o.insert("missed_collisions".into(), json!(r.missed_collisions));
    o.insert("error_vs_reference".into(), number(r.error_vs_reference));
    o.insert("pareto".into(), json!(r.pareto));
    o.insert("failure".into(), json!(r.failure));
    Value::Object(o)
}

pub fn render(study: &Study) -> String {
    let scenes: Vec<Value> = study
        .scenes
        .iter()
        .map(|s| {
            json!({
                "scene": s.scene,
                "title": s.title,
                "seconds": s.seconds,
                "reference": s.reference,
                "reference_config": config(&s.reference_config),
                "verdict": s.verdict,
                "partial": s.partial,
                "rows": s.rows.iter().map(row).collect::<Vec<_>>(),
            })
        })
        .collect();
    let mut top = Map::new();
    // The field the front (`pareto`) is computed on, timed or not.
    top.insert("cost".into(), json!("work_per_second"));
    if study.timed {
        top.insert("repeats".into(), json!(study.repeats));
    }
    top.insert("scenes".into(), json!(scenes));
    let mut s = serde_json::to_string_pretty(&Value::Object(top)).unwrap_or_default();
    s.push('\n');
    s
}
