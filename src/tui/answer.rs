//! Keys of the help pages (keys, then the glossary) and predict mode's
//! answers: typed, graded with [`crate::exercise::answer`], scored, revealed.

use crate::render::fill::Fill;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::app::{App, Mode};
use crate::exercise::answer as grade;
use crate::trace::{glossary, Value};

impl App {
    /// Help's first page: `?` (PgDn, →) the glossary, j/k scroll, any other key closes.
    pub(super) fn help_key(&mut self, key: KeyEvent) {
        match key.code {
            KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => self.quit = true,
            KeyCode::Char('?') | KeyCode::PageDown | KeyCode::Right => {
                self.mode = Mode::Glossary(0)
            }
            KeyCode::Char('j') | KeyCode::Down => {
                self.help_scroll = (self.help_scroll + 1).min(self.help_max.get());
                self.mode = Mode::Help;
            }
            KeyCode::Char('k') | KeyCode::Up => {
                self.help_scroll = self.help_scroll.saturating_sub(1);
                self.mode = Mode::Help;
            }
            _ => {}
        }
    }

    /// The glossary page: j/k, ↑↓, PgDn/PgUp scroll; ← or ? back to the keys.
    pub(super) fn glossary_key(&mut self, at: u16, key: KeyEvent) {
        let max = self.glossary_max.get();
        let to = |n: u16| Mode::Glossary(n.min(max));
        match key.code {
            KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => self.quit = true,
            KeyCode::Char('j') | KeyCode::Down => self.mode = to(at.saturating_add(1)),
            KeyCode::Char('k') | KeyCode::Up => self.mode = to(at.saturating_sub(1)),
            KeyCode::PageDown | KeyCode::Char(' ') => self.mode = to(at.saturating_add(10)),
            KeyCode::PageUp => self.mode = to(at.min(max).saturating_sub(10)),
            KeyCode::Left | KeyCode::Char('?') => self.mode = Mode::Help,
            _ => {}
        }
    }

    /// The result predict mode hides next on this page: its stage, value
    /// name and value, if it has one to grade.
    pub fn hidden_result(&self) -> Option<(usize, &str, &Value)> {
        if !self.hidden_here() {
            return None;
        }
        let s = self.page - 1;
        let step = &self.trace.stages[s];
        let name = step.formulas.get(self.revealed[s])?.result.as_deref()?;
        Some((s, name, step.lookup(name)?))
    }

    /// A key that starts an answer to the hidden result: a digit, a sign,
    /// a point or a bracket. Returns whether it did.
    pub(super) fn answer_start(&mut self, key: KeyEvent) -> bool {
        let KeyCode::Char(c) = key.code else {
            return false;
        };
        if key.modifiers.contains(KeyModifiers::CONTROL)
            || !(c.is_ascii_digit() || "-.([".contains(c))
            || self.hidden_result().is_none()
        {
            return false;
        }
        self.mode = Mode::Answer {
            input: c.to_string(),
            error: None,
        };
        true
    }

    pub(super) fn answer_key(&mut self, mut input: String, error: Option<String>, key: KeyEvent) {
        match key.code {
            KeyCode::Esc => {}
            KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => self.quit = true,
            KeyCode::Char('u') if key.modifiers.contains(KeyModifiers::CONTROL) => {
                self.mode = Mode::Answer {
                    input: String::new(),
                    error: None,
                }
            }
            KeyCode::Backspace => {
                input.pop();
                self.mode = Mode::Answer { input, error: None };
            }
            KeyCode::Char(c) => {
                input.push(c);
                self.mode = Mode::Answer { input, error: None };
            }
            KeyCode::Enter => self.grade_answer(input),
            _ => self.mode = Mode::Answer { input, error },
        }
    }

    /// Grades `input` against the hidden result: a refusal keeps the prompt
    /// open; a graded answer is scored, the result revealed and the right
    /// answer and the difference said.
    fn grade_answer(&mut self, input: String) {
        let Some((s, name, value)) = self
            .hidden_result()
            .map(|(s, n, v)| (s, n.to_string(), v.clone()))
        else {
            return;
        };
        let g = grade::grade(&input, &value);
        if let Some(problem) = g.problem.clone() {
            self.mode = Mode::Answer {
                input,
                error: Some(problem),
            };
            return;
        }
        let step = &self.trace.stages[s];
        let unit = glossary::unit(step, &name);
        let right = glossary::with_unit(&self.fmt.value(&value), unit);
        let text = if g.expected.is_empty() {
            let mark = if g.correct {
                "✓ right"
            } else {
                "✗ not quite"
            };
            format!("{mark}: the answer is {right}")
        } else {
            let diff = g
                .difference
                .iter()
                .map(|d| self.fmt.num(*d))
                .collect::<Vec<_>>()
                .join(", ");
            let diff = if g.difference.len() > 1 {
                format!("({diff})")
            } else {
                diff
            };
            // The verdict, the answer and the difference first: the status
            // line is one row, and what is cut at its end matters least.
            let mark = if g.correct { "✓ right" } else { "✗ off" };
            format!(
                "{mark}: {right}, difference {}; yours {}",
                glossary::with_unit(&diff, unit),
                input.trim()
            )
        };
        self.score.record(&g);
        self.revealed[s] += 1;
        let score = self.score.summary();
        self.say(format!("{text} · score {score}"), !g.correct);
    }
}
