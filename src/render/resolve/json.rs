//! `resolve --format json`, the contract of docs/resolve.md: full f64 values; `log`
//! only when asked (`--log`); `seconds` of the fastest of `--repeat` runs.

use std::io::Write;

use serde::ser::{SerializeMap, SerializeSeq};
use serde::{Serialize, Serializer};
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

/// A phase's object; its `log` rows are built one at a time as they are
/// written, so a huge step's JSON is never held whole in memory.
struct PhaseJson<'a> {
    p: &'a PhaseTrace,
    log: bool,
    position: bool,
}

impl Serialize for PhaseJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let p = self.p;
        let (before, after) = if self.position {
            ("max_penetration_before", "max_penetration_after")
        } else {
            ("max_desired_before", "max_desired_after")
        };
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("iterations_used", &p.iterations_used)?;
        m.serialize_entry("iteration_limit", &p.iteration_limit)?;
        m.serialize_entry("epsilon", &num(p.epsilon))?;
        m.serialize_entry(before, &num(p.max_before))?;
        m.serialize_entry(after, &num(p.max_after))?;
        if self.log {
            m.serialize_entry("log", &LogJson(self))?;
        }
        m.end()
    }
}

struct LogJson<'a>(&'a PhaseJson<'a>);

impl Serialize for LogJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let value_name = if self.0.position {
            "penetration"
        } else {
            "desired"
        };
        let mut seq = s.serialize_seq(Some(self.0.p.log.len()))?;
        for it in &self.0.p.log {
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
            seq.serialize_element(&J::Object(e))?;
        }
        seq.end()
    }
}

/// The resolve object of docs/resolve.md, with `extra` keys after its own.
struct ResolveJson<'a> {
    trace: &'a ResolverTrace,
    seconds: &'a Seconds,
    log: bool,
    extra: &'a [(&'a str, J)],
}

impl Serialize for ResolveJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let (trace, seconds) = (self.trace, self.seconds);
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
        let phase = |p, position| PhaseJson {
            p,
            log: self.log,
            position,
        };
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("lesson", &trace.lesson)?;
        m.serialize_entry("contacts", &trace.before.len())?;
        m.serialize_entry("position", &phase(&trace.position, true))?;
        m.serialize_entry("velocity", &phase(&trace.velocity, false))?;
        m.serialize_entry(
            "seconds",
            &json!({
                "prepare": num(seconds.prepare),
                "position": num(seconds.position),
                "velocity": num(seconds.velocity),
            }),
        )?;
        m.serialize_entry("after", &after)?;
        if let Some(l) = &trace.lcp {
            m.serialize_entry("lcp", &super::lcp::json(l))?;
        }
        if let (Some(e), true) = (trace.elision, self.log) {
            m.serialize_entry(
                "elided",
                &json!({ "updated_every": e.every, "row_budget": e.budget }),
            )?;
        }
        for (key, v) in self.extra {
            m.serialize_entry(key, v)?;
        }
        m.end()
    }
}

/// Writes the resolve object of docs/resolve.md (pretty, one newline after)
/// to `out` as it is built, with `extra` keys after its own.
pub fn write(
    trace: &ResolverTrace,
    seconds: &Seconds,
    log: bool,
    extra: &[(&str, J)],
    out: &mut dyn Write,
) -> std::io::Result<()> {
    let mut out = std::io::BufWriter::new(out);
    let object = ResolveJson {
        trace,
        seconds,
        log,
        extra,
    };
    serde_json::to_writer_pretty(&mut out, &object)?;
    out.write_all(b"\n")?;
    out.flush()
}

pub fn render(trace: &ResolverTrace, seconds: &Seconds, log: bool) -> String {
    let mut bytes = vec![];
    write(trace, seconds, log, &[], &mut bytes).expect("JSON of a resolve");
    String::from_utf8(bytes).expect("JSON is UTF-8")
}
