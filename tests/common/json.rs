//! Rounded, compact JSON for snapshots: every number to 9 significant
//! digits (the physics, not the last bits of round-off; text output prints
//! 6), and an array of numbers (a vector, a matrix row) on one line. The
//! snapshot keeps every value the output carries, in a third of the lines.

use serde_json::Value;

/// `json` with its numbers rounded; below `floor` a number is written 0
/// (round-off left by a resolver), `None` keeps every magnitude.
pub fn rounded(json: &str, floor: Option<f64>) -> String {
    let mut v: Value = serde_json::from_str(json).expect("the output is JSON");
    round(&mut v, floor);
    let mut out = String::new();
    write(&v, 0, &mut out);
    out.push('\n');
    out
}

/// Several JSON documents, one after another (`solve` prints one per contact).
pub fn rounded_stream(json: &str, floor: Option<f64>) -> String {
    serde_json::Deserializer::from_str(json)
        .into_iter::<Value>()
        .map(|v| rounded(&v.expect("the output is JSON").to_string(), floor))
        .collect()
}

fn round(v: &mut Value, floor: Option<f64>) {
    match v {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().unwrap();
            let r: f64 = format!("{x:.8e}").parse().unwrap();
            let r = match floor {
                Some(f) if r.abs() < f => 0.0,
                _ => r,
            };
            *v = serde_json::json!(r);
        }
        Value::Array(a) => a.iter_mut().for_each(|x| round(x, floor)),
        Value::Object(o) => o.values_mut().for_each(|x| round(x, floor)),
        _ => {}
    }
}

/// An array of numbers, or of arrays of numbers (a matrix), fits one
/// line; so do a few short strings (body names), but not notes.
fn flat(v: &Value) -> bool {
    let number = |x: &Value| matches!(x, Value::Number(_) | Value::Null | Value::Bool(_));
    let short = |x: &Value| matches!(x, Value::String(s) if s.chars().count() <= 24);
    match v {
        Value::Array(a) => a
            .iter()
            .all(|x| number(x) || short(x) || matches!(x, Value::Array(b) if b.iter().all(number))),
        _ => false,
    }
}

fn write(v: &Value, depth: usize, out: &mut String) {
    let pad = |d: usize| "  ".repeat(d);
    match v {
        Value::Array(a) if a.is_empty() => out.push_str("[]"),
        Value::Object(o) if o.is_empty() => out.push_str("{}"),
        Value::Array(a) if flat(v) => {
            let items: Vec<String> = a
                .iter()
                .map(|x| match x {
                    Value::Array(_) => {
                        let mut s = String::new();
                        write(x, depth, &mut s);
                        s
                    }
                    _ => x.to_string(),
                })
                .collect();
            out.push('[');
            out.push_str(&items.join(", "));
            out.push(']');
        }
        Value::Array(a) => {
            out.push_str("[\n");
            for (i, x) in a.iter().enumerate() {
                out.push_str(&pad(depth + 1));
                write(x, depth + 1, out);
                out.push_str(if i + 1 < a.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(depth));
            out.push(']');
        }
        Value::Object(o) => {
            out.push_str("{\n");
            for (i, (k, x)) in o.iter().enumerate() {
                out.push_str(&pad(depth + 1));
                out.push_str(&Value::String(k.clone()).to_string());
                out.push_str(": ");
                write(x, depth + 1, out);
                out.push_str(if i + 1 < o.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(depth));
            out.push('}');
        }
        _ => out.push_str(&v.to_string()),
    }
}
