//! What an edit changed: values that differ from the trace before it
//! (marked ● on screen), and the edit form's keys that make the edit.

use ratatui::crossterm::event::KeyEvent;

use super::app::{App, Mode};
use super::form::{Form, Outcome};
use super::screens::Screen;
use crate::lesson::edit;
use crate::trace::{Trace, Value};

impl App {
    /// Did value `name` of stage `id` change with the last edit?
    pub fn changed(&self, id: &str, name: &str) -> bool {
        let Some(base) = &self.baseline else {
            return false;
        };
        let now = self.trace.stage(id).and_then(|s| s.lookup(name));
        let then = base.stage(id).and_then(|s| s.lookup(name));
        match (now, then) {
            (Some(a), Some(b)) => !same(a, b),
            (Some(_), None) => true,
            _ => false,
        }
    }

    /// Did any value of stage `s` change with the last edit?
    pub fn stage_changed(&self, s: usize) -> bool {
        let step = &self.trace.stages[s];
        self.baseline.is_some()
            && step
                .values
                .iter()
                .chain(&step.inputs)
                .any(|(n, _)| self.changed(step.id.json_name(), n))
    }

    pub(super) fn edit_key(&mut self, mut form: Form, key: KeyEvent) {
        let lesson = &self.entry().lesson;
        let k = self.contact;
        let outcome = form.key(
            key,
            |f| super::form::prefill(f, &edit::get(lesson, k, f)),
            |f| edit::next_choice(lesson, k, f),
        );
        match outcome {
            Outcome::Stay => self.mode = Mode::Edit(form),
            Outcome::Close => {}
            Outcome::Set(i, text) => {
                let field = form.fields[i].clone();
                let before = self.trace.clone();
                let entry = self.entry_mut();
                let lesson_before = entry.lesson.clone();
                match edit::set(&mut entry.lesson, k, &field, &text) {
                    Ok(said) => {
                        entry.edits.push(said.clone());
                        self.recompute();
                        let changed = count_changed(&before, &self.trace);
                        self.baseline = Some(before);
                        form.input = None;
                        form.error = None;
                        // Why nothing changed, before the run's edit may leave the contact.
                        let why = match changed {
                            0 => self.why_unchanged(&field, &lesson_before),
                            _ => String::new(),
                        };
                        let run = self
                            .scene_edited(&field, &lesson_before)
                            .unwrap_or_default();
                        self.say(format!("{said}: {changed} values changed{why}{run}"), false);
                    }
                    Err(e) => form.error = Some(e),
                }
                // An edit that stopped the run went back to the run screen.
                if self.screen != Screen::Run {
                    self.mode = Mode::Edit(form);
                }
            }
        }
    }
}

impl App {
    /// Why an edit of `field` changed no value of the solution, in words
    /// after "0 values changed" (read from the trace: the velocity limit
    /// forcing restitution to 0, a separating contact), or nothing.
    fn why_unchanged(&self, field: &edit::Field, before: &crate::lesson::Lesson) -> String {
        let k = self.contact;
        let now = &self.entry().lesson;
        if k >= now.contacts.len() || k >= before.contacts.len() {
            return String::new();
        }
        if edit::get(before, k, field) == edit::get(now, k, field) {
            return " (the value is the one it had)".into();
        }
        let Some(dv) = self.trace.stage("desired_delta_velocity") else {
            return String::new();
        };
        let number = |name: &str| dv.lookup(name).and_then(|v| v.numbers().first().copied());
        let bounce = matches!(field.key, edit::Key::Restitution);
        match (
            number(crate::trace::contact::VELOCITY_LIMIT),
            number("separating_velocity"),
        ) {
            (Some(limit), Some(vs)) if bounce => format!(
                " (the closing speed |v_s| = {} m/s is below the velocity limit {} m/s, so restitution is forced to 0 whatever its value)",
                self.fmt.num(vs.abs()),
                self.fmt.num(limit)
            ),
            (_, Some(vs)) if vs >= 0.0 => format!(
                " (v_s = {} m/s ≥ 0: the contact is separating or at rest, so no impulse is applied whatever the {})",
                self.fmt.num(vs),
                field.label
            ),
            _ => String::new(),
        }
    }
}

/// Values compare by their numbers (NaN equal to NaN, so it is not "changed").
fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Text(x), Value::Text(y)) => x == y,
        (Value::List(x), Value::List(y)) => x == y,
        _ => {
            let (x, y) = (a.numbers(), b.numbers());
            x.len() == y.len()
                && x.iter()
                    .zip(&y)
                    .all(|(p, q)| p == q || (p.is_nan() && q.is_nan()))
        }
    }
}

/// Stage values (the JSON contract's) that differ between two traces.
fn count_changed(before: &Trace, after: &Trace) -> usize {
    after
        .stages
        .iter()
        .map(|s| {
            s.values
                .iter()
                .filter(|(n, v)| {
                    before
                        .value(s.id.json_name(), n)
                        .is_none_or(|old| !same(old, v))
                })
                .count()
        })
        .sum()
}
