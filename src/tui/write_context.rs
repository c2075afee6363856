//! Where a `w` file was written from (issue 28, item 4): the scene or
//! lesson, the time and step, the resolver's phase and iteration and the
//! contact, as the file's name and its header, with the command line that
//! prints the same resolution.
//!
//! File names, most specific first (each part only when the view has it):
//!
//! - a scene's step, opened at a resolver stop:
//!   `stack-5-t1.500-step90-velocity-it0-contact-13.md` (`…-velocity-done-…`
//!   once the phase has finished);
//! - a lesson's contacts resolved together, opened at a stop:
//!   `box-stack-position-it2-contact-1.md`;
//! - a lesson's contact on its own: `lecture-2-contact-0.md`.

use super::app::App;
use crate::output_file::file_stem;
use crate::physics::resolver::Phase;

/// The context of the contact on show.
#[derive(Debug, Clone, PartialEq)]
pub struct Context {
    /// The lesson's or scene's id.
    pub id: String,
    /// How the command line names the lesson: its id when embedded, else its path.
    pub arg: String,
    /// A scene's time (s) after the step, and the step.
    pub step: Option<(f64, u64)>,
    /// The resolver stop the contact was opened at: phase, iteration, and
    /// whether the phase was done at that stop.
    pub stop: Option<(&'static str, usize, bool)>,
    /// Whether the contact shown is the one the stop's iteration takes.
    pub taken: bool,
    pub contact: usize,
    /// The view was edited in the TUI (the command gives the file's values).
    pub edited: bool,
}

impl Context {
    pub fn of(app: &App) -> Context {
        let lesson = &app.lessons[app.lesson].lesson;
        let arg = if lesson.origin.ends_with("(embedded)") {
            lesson.id.clone()
        } else {
            shell_word(&lesson.origin)
        };
        // The step whose resolution the contact is in (the frame on show,
        // or the next one for a contact opened from the detection).
        let step = (app.run.as_ref())
            .and(app.resolver.as_ref())
            .map(|r| (r.trace.time, r.trace.step));
        let stop = app.resolver.as_ref().map(|r| {
            // (Under the soft step or XPBD the stop is a substep: the first table.)
            let table = &r.trace.tables[r.stop.min(r.trace.tables.len() - 1)];
            let (name, used) = match table.stop.phase {
                Phase::Position => ("position", r.trace.resolver.position.iterations_used),
                Phase::Velocity => ("velocity", r.trace.resolver.velocity.iterations_used),
            };
            (name, table.stop.iteration, table.stop.iteration >= used)
        });
        let taken = app
            .resolver
            .as_ref()
            .is_some_and(|r| r.trace.tables.get(r.stop).and_then(|t| t.next) == Some(app.contact));
        Context {
            id: lesson.id.clone(),
            arg,
            step: if app.resolver.is_some() { step } else { None },
            stop,
            taken,
            contact: app.contact,
            edited: !app.entry().edits.is_empty() || !app.lessons[app.lesson].edits.is_empty(),
        }
    }

    /// The file name: scene, time, step, phase, iteration, contact.
    pub fn file_name(&self) -> String {
        let mut parts = vec![file_stem(&self.id)];
        if let Some((time, step)) = self.step {
            parts.push(format!("t{time:.3}"));
            parts.push(format!("step{step}"));
        }
        if let Some((phase, it, done)) = self.stop {
            parts.push(phase.to_string());
            parts.push(if done {
                "done".to_string()
            } else {
                format!("it{it}")
            });
        }
        parts.push(format!("contact-{}", self.contact));
        parts.join("-") + ".md"
    }

    /// The command line that prints the same resolution.
    pub fn command(&self) -> String {
        match (self.step, self.stop) {
            (Some((_, step)), _) => {
                format!("contact-lab simulate {} --trace-step {step}", self.arg)
            }
            (None, Some((phase, it, false))) if self.taken => {
                format!("contact-lab resolve {} --show {phase}:{it}", self.arg)
            }
            (None, Some(_)) => format!("contact-lab resolve {}", self.arg),
            (None, None) => format!("contact-lab solve {} --contact {}", self.arg, self.contact),
        }
    }

    /// The header's lines (Markdown): where the view was, and how to get it again.
    pub fn header(&self) -> String {
        let mut place = vec![format!("`{}`", self.id)];
        if let Some((time, step)) = self.step {
            place.push(format!("t = {time:.3} s, step {step}"));
        }
        if let Some((phase, it, done)) = self.stop {
            place.push(if done {
                format!("{phase} phase done ({it} iterations)")
            } else {
                format!("{phase} iteration {it}")
            });
        }
        place.push(format!("contact {}", self.contact));
        let mut out = format!("Written from contact-lab's TUI at {}.", place.join(" › "));
        if self.stop.is_some() {
            out.push_str(" The bodies are as that stop of the resolver finds them.");
        }
        out.push_str(&format!(
            "\n\nReproduce: `{}`{}\n\n",
            self.command(),
            self.reproduces()
        ));
        out
    }

    /// What the command shows of this view, in words.
    fn reproduces(&self) -> String {
        let row = |phase: &str, it: usize| format!("{}{it}", &phase[..1]);
        let what = match (self.step, self.stop) {
            (Some(_), Some((phase, it, false))) => format!(
                " (the step's resolution: contact {} in the table before the phases, row `{}` for {phase} iteration {it})",
                self.contact,
                row(phase, it)
            ),
            (Some(_), _) => " (the step's resolution)".to_string(),
            (None, Some((_, _, false))) if self.taken => {
                " (this contact's worked solution at that iteration)".to_string()
            }
            (None, Some(_)) => " (the resolution, iteration by iteration)".to_string(),
            (None, None) => String::new(),
        };
        if self.edited {
            what + "; it gives the lesson file's values, not the edits listed below."
        } else {
            what + "."
        }
    }
}

/// `s` as one shell word (quoted when it needs to be).
fn shell_word(s: &str) -> String {
    let plain = s
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "-_./+:=@".contains(c));
    if plain && !s.is_empty() {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}
