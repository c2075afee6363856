//! A knob's value read from a lesson file, a command line, the TUI's edit
//! form or the study's `--grid`, checked against the knob's range rule and
//! worded the same way everywhere (`knobs` declares the rules).

use crate::format::exact;
use crate::knobs::{Kind, Knob, Range, Value, MAX_DT};
use crate::lesson::ranges;

/// Why `value` is refused for `knob` (`Ok` when it is accepted).
pub fn check(knob: &Knob, value: Value) -> Result<(), String> {
    let name = knob.name;
    match (knob.kind, value) {
        (Kind::Number { range, .. }, Value::Number(x)) => number(name, range, x),
        (Kind::Number { optional: true, .. }, Value::Unset) => Ok(()),
        (Kind::Count { max, .. }, Value::Count(n)) if n > max => Err(format!(
            "{name} must be a whole number from 0 to {}, got {n}",
            count_text(max)
        )),
        // A substep count of 0 would be no step at all.
        (Kind::Count { max, .. }, Value::Count(0)) if name == crate::knobs::SUBSTEPS.name => Err(
            format!("{name} must be a whole number from 1 to {max}, got 0"),
        ),
        (Kind::Count { .. }, Value::Count(_)) => Ok(()),
        (Kind::Count { optional: true, .. }, Value::Unset) => Ok(()),
        (Kind::Flag, Value::Flag(_)) => Ok(()),
        (Kind::Choice { .. }, Value::Choice(c)) if knob.choice(c).is_some() => Ok(()),
        (Kind::Vector, Value::Vector(v)) => {
            for (i, x) in v.iter().enumerate() {
                if let Some(e) = ranges::problem(*x) {
                    return Err(format!("{name} {}: {e}", ["x", "y", "z"][i]));
                }
            }
            Ok(())
        }
        _ => Err(format!("{name} must be {}", expected(knob))),
    }
}

fn count_text(n: u64) -> String {
    match n {
        1_000_000_000 => "10⁹ (1000000000)".into(),
        n => n.to_string(),
    }
}

/// A number against its range rule.
fn number(name: &str, range: Range, x: f64) -> Result<(), String> {
    let tiny = x != 0.0 && x.abs() < ranges::MIN_MAGNITUDE;
    match range {
        Range::NonNegative if x.is_nan() || x < 0.0 || x.is_infinite() => Err(format!(
            "{name} must be a finite number ≥ 0, got {}",
            exact(x)
        )),
        Range::NonNegative => ranges::problem(x).map_or(Ok(()), |e| Err(format!("{name} {e}"))),
        Range::NonNegativeOrInf if x.is_nan() || x < 0.0 => Err(format!(
            "{name} must be ≥ 0 (inf = no limit), got {}",
            exact(x)
        )),
        Range::NonNegativeOrInf => Ok(()),
        Range::Share | Range::Damping if tiny && x > 0.0 => {
            Err(format!("{name} {}", ranges::too_small_positive(x)))
        }
        Range::Share if x > 0.0 && x <= 1.0 => Ok(()),
        Range::Share => Err(format!("{name} must be in (0, 1], got {}", exact(x))),
        Range::Damping if x > 0.0 && x <= 1.0 => Ok(()),
        Range::Damping => Err(format!(
            "{name} is the fraction of velocity kept per second and must be in (0, 1], got {}",
            exact(x)
        )),
        Range::Duration if x.is_nan() || x <= 0.0 => Err(format!(
            "{name} must be a finite number > 0, got {}",
            exact(x)
        )),
        Range::Duration if x > MAX_DT => Err(format!(
            "{name} must be at most {} s, got {}",
            exact(MAX_DT),
            exact(x)
        )),
        Range::Duration if tiny => Err(format!("{name} {}", ranges::too_small_positive(x))),
        Range::Duration => Ok(()),
    }
}

/// What the knob takes, in words: `a number in (0, 1]`, `one of "a", "b"`.
pub fn expected(knob: &Knob) -> String {
    match knob.kind {
        Kind::Number {
            range: Range::NonNegative,
            ..
        } => "a finite number ≥ 0".into(),
        Kind::Number {
            range: Range::NonNegativeOrInf,
            ..
        } => "a number ≥ 0 (inf = no limit)".into(),
        Kind::Number {
            range: Range::Share | Range::Damping,
            ..
        } => "a number in (0, 1]".into(),
        Kind::Number {
            range: Range::Duration,
            ..
        } => {
            format!("a number of seconds > 0, at most {}", exact(MAX_DT))
        }
        Kind::Count { max, .. } => format!("a whole number from 0 to {}", count_text(max)),
        Kind::Flag => "true or false".into(),
        Kind::Choice { choices, .. } => format!(
            "one of {}",
            choices
                .iter()
                .map(|c| format!("\"{}\"", c.name))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Kind::Vector => "three numbers x, y, z".into(),
    }
}

/// The value a TOML entry gives `knob`, checked.
pub fn from_toml(knob: &Knob, value: &toml::Value) -> Result<Value, String> {
    let v = match (knob.kind, value) {
        (Kind::Number { .. }, toml::Value::Float(x)) => Value::Number(*x),
        (Kind::Number { .. }, toml::Value::Integer(n)) => Value::Number(*n as f64),
        (Kind::Count { .. }, toml::Value::Integer(n)) if *n < 0 => {
            return Err(format!("{} must be {}, got {n}", knob.name, expected(knob)))
        }
        (Kind::Count { .. }, toml::Value::Integer(n)) => Value::Count(*n as u64),
        (Kind::Flag, toml::Value::Boolean(b)) => Value::Flag(*b),
        (Kind::Choice { .. }, toml::Value::String(s)) => match knob.choice(s) {
            Some(c) => Value::Choice(c),
            None => {
                return Err(format!(
                    "{} must be {}, got \"{s}\"",
                    knob.name,
                    expected(knob)
                ))
            }
        },
        (Kind::Vector, toml::Value::Array(a)) => {
            let numbers: Vec<f64> = a
                .iter()
                .filter_map(|x| match x {
                    toml::Value::Float(x) => Some(*x),
                    toml::Value::Integer(n) => Some(*n as f64),
                    _ => None,
                })
                .collect();
            match <[f64; 3]>::try_from(numbers) {
                Ok(v) if a.len() == 3 => Value::Vector(v),
                _ => {
                    return Err(format!(
                        "{} must be an array of 3 numbers, got {} element(s)",
                        knob.name,
                        a.len()
                    ))
                }
            }
        }
        (_, other) => {
            return Err(format!(
                "{} must be {}, got {}",
                knob.name,
                expected(knob),
                describe(other)
            ))
        }
    };
    check(knob, v).map(|()| v)
}

fn describe(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => format!("\"{s}\""),
        toml::Value::Integer(n) => n.to_string(),
        toml::Value::Float(x) => exact(*x),
        toml::Value::Boolean(b) => b.to_string(),
        toml::Value::Datetime(_) => "a date".into(),
        toml::Value::Array(_) => "an array".into(),
        toml::Value::Table(_) => "a table".into(),
    }
}

/// What a user typed (command line, edit form, `--grid`), checked.
pub fn from_text(knob: &Knob, text: &str) -> Result<Value, String> {
    let t = text.trim();
    let refuse = || {
        Err(format!(
            "{} must be {}, got '{}'",
            knob.name,
            expected(knob),
            echo(t)
        ))
    };
    let v = match knob.kind {
        _ if matches!(t, "default" | "auto") && optional_kind(knob) => Value::Unset,
        Kind::Number { .. } => match parse_number(t) {
            Some(x) => Value::Number(x),
            None => return refuse(),
        },
        Kind::Count { .. } => match t.parse::<u64>() {
            Ok(n) => Value::Count(n),
            Err(_) => return refuse(),
        },
        Kind::Flag => match t {
            "true" | "on" | "yes" => Value::Flag(true),
            "false" | "off" | "no" => Value::Flag(false),
            _ => return refuse(),
        },
        Kind::Choice { .. } => match knob.choice(t) {
            Some(c) => Value::Choice(c),
            None => return refuse(),
        },
        Kind::Vector => {
            let parts: Vec<&str> = t
                .trim_start_matches(['(', '['])
                .trim_end_matches([')', ']'])
                .split([',', ' '])
                .filter(|s| !s.trim().is_empty())
                .collect();
            let numbers: Option<Vec<f64>> = parts.iter().map(|p| parse_number(p)).collect();
            match numbers.map(<[f64; 3]>::try_from) {
                Some(Ok(v)) => Value::Vector(v),
                _ => {
                    return Err(format!(
                        "{}: expected three numbers x, y, z, got {} ('{}')",
                        knob.name,
                        parts.len(),
                        echo(t)
                    ))
                }
            }
        }
    };
    check(knob, v).map(|()| v)
}

fn optional_kind(knob: &Knob) -> bool {
    matches!(
        knob.kind,
        Kind::Count { optional: true, .. } | Kind::Number { optional: true, .. }
    )
}

/// A number as typed: `inf`, `∞`, or a fraction `1/60`.
pub fn parse_number(t: &str) -> Option<f64> {
    let t = t.trim();
    let t = if t == "∞" { "inf" } else { t };
    match t.split_once('/') {
        Some((a, b)) => Some(a.trim().parse::<f64>().ok()? / b.trim().parse::<f64>().ok()?),
        None => t.parse().ok(),
    }
}

/// What the user typed, quoted back in a refusal (a knob's value, an edit
/// form's field): control characters escaped, at most 40 characters, so a
/// pasted page does not fill the form.
pub fn echo(text: &str) -> String {
    let escaped: String = text.escape_debug().collect();
    match escaped.char_indices().nth(40) {
        Some((i, _)) => format!("{}…", &escaped[..i]),
        None => escaped,
    }
}

/// A value as text that reads back as the same value (full precision).
pub fn text(value: Value) -> String {
    match value {
        Value::Number(x) => exact(x),
        Value::Count(n) => n.to_string(),
        Value::Flag(b) => b.to_string(),
        Value::Choice(c) => c.to_string(),
        Value::Vector([x, y, z]) => format!("{}, {}, {}", exact(x), exact(y), exact(z)),
        Value::Unset => "default".into(),
    }
}

/// A value as JSON.
pub fn json(value: Value) -> serde_json::Value {
    match value {
        Value::Number(x) => serde_json::json!(x),
        Value::Count(n) => serde_json::json!(n),
        Value::Flag(b) => serde_json::json!(b),
        Value::Choice(c) => serde_json::json!(c),
        Value::Vector(v) => serde_json::json!(v),
        Value::Unset => serde_json::Value::Null,
    }
}
