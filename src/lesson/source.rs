//! Where a lesson came from, and diagnostics that point into its text.

use std::ops::Range;

use miette::{NamedSource, SourceSpan};

use super::snippet::{printable, File, Snippet};

/// A message about one place in a lesson file.
#[derive(Debug, Clone, PartialEq)]
pub struct Note {
    pub message: String,
    pub span: Range<usize>,
    pub label: String,
    pub help: Option<String>,
}

impl Note {
    pub fn new(message: impl Into<String>, span: Range<usize>) -> Self {
        let message = message.into();
        Note {
            label: "here".into(),
            message,
            span,
            help: None,
        }
    }

    pub fn help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }
}

/// A note resolved against its file: path, 1-based line and column, snippet.
#[derive(Debug, Clone, thiserror::Error, miette::Diagnostic)]
#[error("{path}:{line}:{column}: {message}")]
pub struct LessonDiagnostic {
    pub path: String,
    pub line: usize,
    pub column: usize,
    pub message: String,
    #[source_code]
    pub src: NamedSource<Snippet>,
    #[label("{label}")]
    pub span: SourceSpan,
    pub label: String,
    #[help]
    pub help: Option<String>,
}

impl LessonDiagnostic {
    pub fn new(path: &str, text: &str, note: Note) -> Self {
        Self::resolve(path, text, vec![note]).remove(0)
    }

    /// Resolves every note against one text, which they share.
    pub fn resolve(path: &str, text: &str, notes: Vec<Note>) -> Vec<Self> {
        if notes.is_empty() {
            return Vec::new();
        }
        let file = File::new(text);
        notes
            .into_iter()
            .map(|note| {
                let start = file.clamp(note.span.start);
                let end = file.clamp(note.span.end).max(start);
                let (line, column) = file.line_column(start);
                let (snippet, span) = file.snippet(start..end);
                LessonDiagnostic {
                    path: path.to_string(),
                    line,
                    column,
                    message: printable(note.message),
                    src: NamedSource::new(path, snippet),
                    span: (span.start, span.end - span.start).into(),
                    label: printable(note.label),
                    help: note.help.map(printable),
                }
            })
            .collect()
    }
}

fn clamp_to_char(text: &str, mut i: usize) -> usize {
    while i > 0 && !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// 1-based line and column (in characters) of byte offset `at`.
pub fn line_column(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..clamp_to_char(text, at.min(text.len()))];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// Why a lesson could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum LessonError {
    /// The named lesson is neither embedded nor a file (exit 66).
    #[error("lesson file missing: {path}: {reason}")]
    Missing { path: String, reason: String },
    /// The path exists but cannot be read as a lesson: permission denied, a
    /// directory, a FIFO, a device, an I/O error (exit 1).
    #[error("cannot read lesson file {path}: {reason}")]
    Unreadable { path: String, reason: String },
    /// The file was read but is not a valid lesson (exit 65).
    #[error("invalid lesson {path}: {}", .diagnostics.first().map(|d| d.to_string()).unwrap_or_default())]
    Invalid {
        path: String,
        diagnostics: Vec<LessonDiagnostic>,
        /// Further errors found but not reported (see `validate::MAX_ERRORS`).
        omitted: usize,
    },
}
