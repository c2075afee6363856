//! `w`: the worked solution as a Markdown file, written through
//! [`crate::output_file`] (atomically, never over a device, FIFO, directory or
//! symbolic link) and never over an existing file unless the user said so.

use std::path::{Path, PathBuf};

use crate::format::Fmt;
use crate::render::contact::markdown;
use crate::trace::Trace;

pub use super::write_context::Context;

/// The Markdown document of `render::contact::markdown` for one contact:
/// the lesson's preamble, where in the TUI it was written from (`context`:
/// scene, time, step, phase, iteration, and the command that reproduces
/// it), the edits made in the TUI, then the stages.
pub fn markdown(trace: &Trace, context: &Context, edits: &[String], fmt: &Fmt) -> String {
    let mut out = markdown::preamble(trace, 1);
    out.push_str(&context.header());
    if !edits.is_empty() {
        out.push_str("Edited in contact-lab (these differ from the lesson file):\n\n");
        for e in edits {
            out.push_str(&format!("- {}\n", markdown::escape(e)));
        }
        out.push('\n');
    }
    out.push_str(&markdown::contact(trace, fmt, 2, None));
    out.truncate(out.trim_end().len());
    out.push('\n');
    out
}

/// Why a write did not happen.
#[derive(Debug)]
pub enum WriteError {
    /// The file is there and `overwrite` was false: ask first.
    Exists(PathBuf),
    Io(String),
}

/// Writes `text` to `path` through [`crate::output_file`] (atomically,
/// only ever replacing a regular file). Without `overwrite`, an existing
/// file is left alone and [`WriteError::Exists`] returned.
pub fn write_atomic(path: &Path, text: &str, overwrite: bool) -> Result<(), WriteError> {
    use crate::output_file::{write, Error, Existing};
    let existing = if overwrite {
        Existing::Replace
    } else {
        Existing::Keep
    };
    match write(path, text.as_bytes(), existing) {
        Ok(()) => Ok(()),
        Err(Error::Exists(p)) => Err(WriteError::Exists(p)),
        // The prompt shows the directory and the name; the reason is what is new.
        Err(e) => Err(WriteError::Io(e.reason())),
    }
}

use super::app::Mode;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// The write prompt's keys (the file name is text: it reads keys itself).
impl super::app::App {
    pub(super) fn write_key(&mut self, mut input: String, error: Option<String>, key: KeyEvent) {
        match key.code {
            KeyCode::Esc => self.say("not written".into(), false),
            KeyCode::Enter if input.trim().is_empty() => {
                self.mode = Mode::Write {
                    input,
                    error: Some("a file name, please".into()),
                }
            }
            KeyCode::Enter => {
                let path = self.write_dir.join(input.trim());
                self.write_to(path, false)
            }
            code => {
                match code {
                    KeyCode::Backspace => {
                        input.pop();
                    }
                    KeyCode::Char('u') if key.modifiers.contains(KeyModifiers::CONTROL) => {
                        input.clear()
                    }
                    KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => {
                        return self.say("not written".into(), false);
                    }
                    KeyCode::Char(c) if !c.is_control() => input.push(c),
                    _ => {}
                }
                self.mode = Mode::Write { input, error };
            }
        }
    }

    pub(super) fn write_to(&mut self, path: PathBuf, overwrite: bool) {
        let text = markdown(
            &self.trace,
            &Context::of(self),
            &self.entry().edits,
            &self.fmt,
        );
        match write_atomic(&path, &text, overwrite) {
            Ok(()) => self.say(format!("wrote {}", path.display()), false),
            Err(WriteError::Exists(p)) => self.mode = Mode::Confirm(p),
            Err(WriteError::Io(e)) => {
                let input = path
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_default();
                self.mode = Mode::Write {
                    input,
                    error: Some(format!("cannot write: {e}")),
                };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("contact-lab-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn never_overwrites_without_asking() {
        let d = dir("write");
        let p = d.join("a.md");
        write_atomic(&p, "one", false).unwrap();
        assert!(matches!(
            write_atomic(&p, "two", false),
            Err(WriteError::Exists(_))
        ));
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "one");
        write_atomic(&p, "three", true).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "three");
        let left: Vec<_> = std::fs::read_dir(&d).unwrap().collect();
        assert_eq!(left.len(), 1, "no temporary file left behind");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn missing_directory_is_an_error() {
        let p = std::env::temp_dir().join("contact-lab-no-such-dir-xyz/a.md");
        assert!(matches!(
            write_atomic(&p, "x", false),
            Err(WriteError::Io(_))
        ));
    }
}
