//! The edit form (`e`): a list of the contact's editable inputs; Enter types a
//! new value (or cycles a choice), which the app sets through `lesson::edit`.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use crate::lesson::edit::{Field, Kind};

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
