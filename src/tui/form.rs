//! The edit form (`e`): a list of the contact's editable inputs; Enter types a
//! new value (or cycles a choice), which the app sets through `lesson::edit`.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use crate::format::Fmt;
use crate::knobs::Range;
use crate::lesson::edit::{Field, Key, Kind};

#[derive(Debug, Clone, PartialEq)]
pub struct Form {
    pub fields: Vec<Field>,
    pub selected: usize,
    /// Text being typed for the selected field.
    pub input: Option<String>,
    /// Why the last value was refused.
    pub error: Option<String>,
}

/// What a key did to the form.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    Stay,
    Close,
    /// Set field `.0` to the text `.1`.
    Set(usize, String),
}

impl Form {
    pub fn new(fields: Vec<Field>) -> Self {
        Form {
            fields,
            selected: 0,
            input: None,
            error: None,
        }
    }

    /// `current(field)` gives the field's text now, `next(field)` a choice's next name.
    pub fn key(
        &mut self,
        key: KeyEvent,
        current: impl Fn(&Field) -> String,
        next: impl Fn(&Field) -> Option<String>,
    ) -> Outcome {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        if let Some(input) = &mut self.input {
            match key.code {
                KeyCode::Enter => return Outcome::Set(self.selected, input.clone()),
                KeyCode::Esc => {
                    self.input = None;
                    self.error = None;
                }
                KeyCode::Backspace => {
                    input.pop();
                }
                KeyCode::Char('u') if ctrl => input.clear(),
                KeyCode::Char('c') if ctrl => return Outcome::Close,
                // A pasted control character (escape, CR) would reach the terminal.
                KeyCode::Char(c) if !ctrl && !c.is_control() => input.push(c),
                _ => {}
            }
            return Outcome::Stay;
        }
        let n = self.fields.len().max(1);
        let field = &self.fields[self.selected.min(n - 1)];
        match key.code {
            KeyCode::Esc | KeyCode::Char('q') => return Outcome::Close,
            KeyCode::Char('c') if ctrl => return Outcome::Close,
            KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => {
                self.selected = (self.selected + 1) % n;
                self.error = None;
            }
            KeyCode::Up | KeyCode::Char('k') | KeyCode::BackTab => {
                self.selected = (self.selected + n - 1) % n;
                self.error = None;
            }
            KeyCode::Enter | KeyCode::Char('e') | KeyCode::Char(' ') => {
                if let Kind::Choice(_) = field.kind() {
                    if let Some(name) = next(field) {
                        return Outcome::Set(self.selected, name);
                    }
                } else {
                    self.input = Some(current(field));
                }
            }
            // Typing a number starts a fresh value.
            KeyCode::Char(c)
                if !ctrl
                    && (c.is_ascii_digit() || "-+.(".contains(c))
                    && !matches!(field.kind(), Kind::Choice(_)) =>
            {
                self.input = Some(c.to_string());
            }
            _ => {}
        }
        Outcome::Stay
    }
}

/// A field's value as the form lists it: numbers through the formatter (a
/// duration of a whole fraction of a second as `1/60 s`), with the unit
/// where the field has one. `exact` is the value as editable text
/// (`edit::get`); what Enter puts in the input stays exact ([`prefill`]).
pub fn shown(fmt: &Fmt, field: &Field, exact: &str) -> String {
    let unit = unit(field);
    let with_unit = |s: String| {
        if unit.is_empty() {
            s
        } else {
            format!("{s} {unit}")
        }
    };
    match field.kind() {
        Kind::Choice(_) => exact.to_string(),
        Kind::Vector => {
            let xs: Option<Vec<f64>> = exact.split(',').map(|p| p.trim().parse().ok()).collect();
            match xs {
                Some(xs) if xs.len() == 3 && xs.iter().all(|x| x.is_finite()) => {
                    with_unit(format!("({})", fmt.list(&xs)))
                }
                _ => exact.to_string(),
            }
        }
        Kind::Number => match exact.parse::<f64>() {
            Ok(x) if x.is_finite() => with_unit(fraction(field, x).unwrap_or_else(|| fmt.num(x))),
            _ => exact.to_string(),
        },
    }
}

/// What Enter puts in the input to edit the field: its exact text, or the
/// fraction `1/n` a duration is exactly (it reads back as the same number).
pub fn prefill(field: &Field, exact: &str) -> String {
    match exact.parse::<f64>() {
        Ok(x) => fraction(field, x).unwrap_or_else(|| exact.to_string()),
        Err(_) => exact.to_string(),
    }
}

/// A duration that is exactly 1/n of a second, as `1/n`.
fn fraction(field: &Field, x: f64) -> Option<String> {
    let Key::Knob(knob) = field.key else {
        return None;
    };
    if knob.kind.range() != Some(Range::Duration) || !(x > 0.0 && x < 1.0) {
        return None;
    }
    let n = (1.0 / x).round();
    (n <= 1e6 && 1.0 / n == x).then(|| format!("1/{n}"))
}

/// The unit of a field's value (empty for a pure number).
fn unit(field: &Field) -> &'static str {
    match field.key {
        Key::Penetration => "m",
        Key::Mass => "kg",
        Key::Velocity => "m/s",
        Key::AngularVelocity => "rad/s",
        Key::Acceleration => "m/s²",
        Key::Knob(knob) if knob.kind.range() == Some(Range::Duration) => "s",
        _ => "",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::knobs::KNOBS;

    fn field(name: &str) -> Field {
        let knob = KNOBS.iter().find(|k| k.name == name).expect("knob");
        Field {
            key: Key::Knob(knob),
            body: None,
            label: name.into(),
        }
    }

    #[test]
    fn a_duration_shows_as_a_fraction_and_edits_exactly() {
        let f = Fmt::new(6);
        let d = field("duration");
        assert_eq!(shown(&f, &d, "0.016666666666666666"), "1/60 s");
        assert_eq!(prefill(&d, "0.016666666666666666"), "1/60");
        assert_eq!(shown(&f, &d, "0.0166"), "0.0166 s");
        assert_eq!(prefill(&d, "0.0166"), "0.0166");
        let v = Field {
            key: Key::Velocity,
            body: Some(0),
            label: "cube: velocity".into(),
        };
        assert_eq!(
            shown(&f, &v, "0, -0.30000000000000004, 0"),
            "(0, -0.3, 0) m/s"
        );
    }
}
