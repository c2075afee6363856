//! `resolve --format json`, the contract of docs/resolve.md: full f64 values; `log`
//! only when asked (`--log`); `seconds` of the fastest of `--repeat` runs.

use serde_json::{json, Map, Value as J};

use super::Seconds;
use crate::render::contact::json::value;
use crate::trace::resolver::{PhaseTrace, ResolverTrace};
use crate::trace::Value;

fn num(x: f64) -> J {
    value(&Value::Scalar(x))
}

fn vector(v: &[f64; 3]) -> J {
    value(&Value::Vector(*v))
}

fn phase(p: &PhaseTrace, log: bool, position: bool) -> J {
    let (before, after, value_name) = if position {
        (
            "max_penetration_before",
            "max_penetration_after",
            "penetration",
        )
    } else {
        ("max_desired_before", "max_desired_after", "desired")
    };
    let mut out = Map::new();
    out.insert("iterations_used".into(), json!(p.iterations_used));
    out.insert("iteration_limit".into(), json!(p.iteration_limit));
    out.insert("epsilon".into(), num(p.epsilon));
    out.insert(before.into(), num(p.max_before));
    out.insert(after.into(), num(p.max_after));
    if log {
        let entries: Vec<J> = p
            .log
            .iter()
            .map(|it| {
                let mut e = Map::new();
                e.insert("iteration".into(), json!(it.iteration));
                e.insert("contact".into(), json!(it.contact));
                e.insert(value_name.into(), num(it.value));
                if let Some(g) = &it.impulse_contact {
                    e.insert("impulse_contact".into(), vector(g));
                }
                if it.elided {
                    // A huge step's recording kept no rows here: how many it changed.
                    e.insert("updated".into(), J::Null);
                    e.insert("changed".into(), json!(it.changed));
                } else {
                    let updated: Vec<J> = it
                        .updated
                        .iter()
                        .map(|u| json!([u.contact, num(u.to)]))
                        .collect();
                    e.insert("updated".into(), J::Array(updated));
                }
                J::Object(e)
            })
            .collect();
        out.insert("log".into(), J::Array(entries));
    }
    J::Object(out)
}

/// The resolve object of docs/resolve.md.
pub fn to_json(trace: &ResolverTrace, seconds: &Seconds, log: bool) -> J {
    let after: Map<String, J> = trace
        .after
        .iter()
        .map(|(name, a)| {
            (
                name.clone(),
                json!({
                    "position": vector(&a.position),
                    "orientation": value(&Value::Quaternion(a.orientation)),
                    "velocity": vector(&a.velocity),
                    "angular_velocity": vector(&a.angular_velocity),
                }),
            )
        })
        .collect();
    let mut out = json!({
        "lesson": trace.lesson,
        "contacts": trace.before.len(),
        "position": phase(&trace.position, log, true),
        "velocity": phase(&trace.velocity, log, false),
        "seconds": {
            "prepare": num(seconds.prepare),
            "position": num(seconds.position),
            "velocity": num(seconds.velocity),
        },
        "after": after,
    });
    if let (Some(e), true) = (trace.elision, log) {
        out["elided"] = json!({ "updated_every": e.every, "row_budget": e.budget });
    }
    out
}

pub fn render(trace: &ResolverTrace, seconds: &Seconds, log: bool) -> String {
    serde_json::to_string_pretty(&to_json(trace, seconds, log)).expect("JSON of a resolve") + "\n"
}
