//! The JSON of `solve --format json`, documented in `docs/json.md`: full f64
//! values, one object per stage.

use crate::render::fill::Fill;
use serde_json::{json, Map, Value as J};

use crate::format::Fmt;
use crate::trace::{Trace, Value};

pub fn value(v: &Value) -> J {
    // `x + 0.0` turns -0 into 0; a non-finite number (never produced) would be null.
    let num = |x: f64| serde_json::Number::from_f64(x + 0.0).map_or(J::Null, J::Number);
    match v {
        Value::Scalar(x) => num(*x),
        Value::Vector(a) => J::Array(a.iter().map(|x| num(*x)).collect()),
        Value::Quaternion(q) => J::Array(q.iter().map(|x| num(*x)).collect()),
        Value::Matrix(m) => J::Array(
            m.iter()
                .map(|r| J::Array(r.iter().map(|x| num(*x)).collect()))
                .collect(),
        ),
        Value::Text(s) => J::String(s.clone()),
        Value::List(items) => J::Array(items.iter().cloned().map(J::String).collect()),
    }
}

/// The trace as the JSON object scripts read.
pub fn to_json(trace: &Trace) -> J {
    let fmt = Fmt::default();
    let stages: Vec<J> = trace
        .stages
        .iter()
        .map(|s| {
            let values: Map<String, J> = s.values.iter().map(|(n, v)| (n.to_string(), value(v))).collect();
            let notes: Vec<J> = s.notes.iter().map(|n| J::String(fmt.fill_units(n, s))).collect();
            json!({ "id": s.id.json_name(), "title": s.title, "skipped": s.skipped, "values": values, "notes": notes })
        })
        .collect();
    let after: Map<String, J> = trace
        .after
        .iter()
        .map(|(name, a)| {
            (
                name.clone(),
                json!({
                    "position": value(&Value::Vector(a.position)),
                    "orientation": value(&Value::Quaternion(a.orientation)),
                    "velocity": value(&Value::Vector(a.velocity)),
                    "angular_velocity": value(&Value::Vector(a.angular_velocity)),
                }),
            )
        })
        .collect();
    json!({
        "lesson": trace.lesson,
        "title": trace.title,
        "contact": trace.contact,
        "bodies": trace.bodies,
        "stages": stages,
        "after": after,
    })
}

pub fn render(trace: &Trace) -> String {
    serde_json::to_string_pretty(&to_json(trace)).expect("JSON of a trace") + "\n"
}
