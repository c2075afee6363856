//! Values and formulas of a trace shown with the one number formatter:
//! a value as text or LaTeX, and a template's `{name}` placeholders filled
//! with a stage's values (with their units for prose). The formatter itself
//! (`crate::format`) knows numbers only.

use crate::format::Fmt;
use crate::trace::{Step, Value};

/// A trace's values and templates shown through [`Fmt`].
pub trait Fill {
    /// Plain-text form of a value.
    fn value(&self, v: &Value) -> String;
    /// LaTeX form of a value.
    fn value_latex(&self, v: &Value) -> String;
    /// Replaces each `{name}` of `template` with the step's value `name`.
    fn fill(&self, template: &str, step: &Step, latex: bool) -> String;
    /// Like `fill`, with literal pieces and values shown by the caller.
    fn fill_with(
        &self,
        template: &str,
        step: &Step,
        literal: &dyn Fn(&str) -> String,
        value: &dyn Fn(&Value) -> String,
    ) -> String;
    /// `fill` for prose: each number followed by its unit.
    fn fill_units(&self, template: &str, step: &Step) -> String;
    /// Like `fill_with`, with the value's name passed to `value`.
    fn fill_named(
        &self,
        template: &str,
        step: &Step,
        literal: &dyn Fn(&str) -> String,
        value: &dyn Fn(&str, &Value) -> String,
    ) -> String;
}

impl Fill for Fmt {
    /// Plain-text form of a value.
    fn value(&self, v: &Value) -> String {
        match v {
            Value::Scalar(x) => self.num(*x),
            Value::Vector(a) => format!("({})", self.list(a)),
            Value::Quaternion(q) => format!("[{}]", self.list(q)),
            // Round-off against the whole matrix, not a row.
            Value::Matrix(m) => {
                let scale = crate::format::scale_of(m.iter().flatten());
                format!(
                    "[{}]",
                    m.iter()
                        .map(|r| format!(
                            "[{}]",
                            r.iter()
                                .map(|x| self.num_at(*x, scale))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            }
            Value::Text(s) => s.clone(),
            Value::List(items) => items.join("; "),
        }
    }

    /// LaTeX form of a value.
    fn value_latex(&self, v: &Value) -> String {
        let list = |xs: &[f64]| self.list_latex(xs);
        match v {
            Value::Scalar(x) => self.num_latex(*x),
            Value::Vector(a) => format!("({})", list(a)),
            Value::Quaternion(q) => format!("[{}]", list(q)),
            Value::Matrix(m) => {
                let scale = crate::format::scale_of(m.iter().flatten());
                format!(
                    "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
                    m.iter()
                        .map(|r| r
                            .iter()
                            .map(|x| self.num_latex(crate::format::snap_zero(*x, scale)))
                            .collect::<Vec<_>>()
                            .join(" & "))
                        .collect::<Vec<_>>()
                        .join(" \\\\ ")
                )
            }
            Value::Text(s) => format!("\\text{{{}}}", super::tex::escape_text(s)),
            Value::List(items) => {
                format!("\\text{{{}}}", super::tex::escape_text(&items.join("; ")))
            }
        }
    }

    /// Replaces each `{name}` of `template` with the step's value `name`.
    /// An unknown name is left as written.
    fn fill(&self, template: &str, step: &Step, latex: bool) -> String {
        self.fill_with(template, step, &|s| s.to_string(), &|v| {
            if latex {
                self.value_latex(v)
            } else {
                self.value(v)
            }
        })
    }

    /// Like [`Fill::fill`], with each literal piece of the template passed
    /// through `literal` and each value shown by `value` (renderers that
    /// escape text and typeset numbers differently).
    fn fill_with(
        &self,
        template: &str,
        step: &Step,
        literal: &dyn Fn(&str) -> String,
        value: &dyn Fn(&Value) -> String,
    ) -> String {
        self.fill_named(template, step, literal, &|_, v| value(v))
    }

    /// [`Fill::fill`] for prose (notes, verdicts): each number followed by its
    /// unit from the glossary (`closing at 1.25 m/s`).
    /// A unit the template already writes after the placeholder
    /// (`{rotation_degrees1}°`) is not added again.
    fn fill_units(&self, template: &str, step: &Step) -> String {
        use crate::trace::glossary::{unit, unit_to_add, with_unit};
        self.fill_named(template, step, &|s| s.to_string(), &|name, v| {
            with_unit(
                &self.value(v),
                unit_to_add(template, name, unit(step, name)),
            )
        })
    }

    /// Like [`Fill::fill_with`], with the value's name passed to `value`.
    fn fill_named(
        &self,
        template: &str,
        step: &Step,
        literal: &dyn Fn(&str) -> String,
        value: &dyn Fn(&str, &Value) -> String,
    ) -> String {
        let mut out = String::new();
        let mut text = String::new();
        let mut rest = template;
        while let Some(open) = rest.find('{') {
            text.push_str(&rest[..open]);
            let after = &rest[open + 1..];
            match after.find('}') {
                Some(close) if crate::format::is_name(&after[..close]) => {
                    let name = &after[..close];
                    match step.lookup(name) {
                        Some(v) => {
                            out.push_str(&literal(&std::mem::take(&mut text)));
                            out.push_str(&value(name, v));
                        }
                        None => text.push_str(&rest[open..open + close + 2]),
                    }
                    rest = &after[close + 1..];
                }
                _ => {
                    text.push('{');
                    rest = after;
                }
            }
        }
        text.push_str(rest);
        out.push_str(&literal(&text));
        out
    }
}
