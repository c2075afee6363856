//! The source text a diagnostic shows under its message.
//!
//! A lesson file is untrusted text printed to a terminal, and it may be huge:
//! - control characters (ESC, NUL, bidi overrides, …) are replaced by
//!   characters of the same byte length, so the file cannot drive the terminal
//!   and every span stays valid;
//! - when a line near the error is too long to print, only an excerpt of the
//!   error's line is shown;
//! - either way miette is told the file's own line and column, counted in
//!   characters as `path:line:column` is (miette alone counts bytes).

use std::ops::Range;

use crate::printable::is_bidi;
pub use crate::printable::printable;
use std::sync::Arc;

use miette::{MietteError, MietteSpanContents, SourceCode, SourceSpan, SpanContents};

/// Lines around an error longer than this (in bytes) are not printed whole.
pub const MAX_LINE: usize = 300;
/// Bytes of the error's line kept either side of the error in an excerpt.
const WINDOW: usize = 80;

/// Text shown by one diagnostic; `text` starts at `line` (0-based) of the
/// file, `column` characters into that line.
#[derive(Debug, Clone)]
pub struct Snippet {
    text: Arc<str>,
    line: usize,
    column: usize,
}

impl SourceCode for Snippet {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let inner = self.text.as_bytes().read_span(span, before, after)?;
        let byte_column = inner.column();
        let column = if byte_column == 0 {
            0
        } else {
            let start = span.offset();
            let chars = self
                .text
                .get(start.saturating_sub(byte_column)..start)
                .map_or(byte_column, |s| s.chars().count());
            chars + if inner.line() == 0 { self.column } else { 0 }
        };
        Ok(Box::new(MietteSpanContents::new(
            inner.data(),
            *inner.span(),
            inner.line() + self.line,
            column,
            inner.line_count() + self.line,
        )))
    }
}

/// One file's text, made safe to print, with the start of every line.
pub struct File {
    text: Arc<str>,
    line_starts: Vec<usize>,
}

impl File {
    pub fn new(text: &str) -> File {
        let line_starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        File {
            text: neutralise(text).into(),
            line_starts,
        }
    }

    /// Byte offset `at` moved back to a character boundary and into the text.
    pub fn clamp(&self, at: usize) -> usize {
        let mut i = at.min(self.text.len());
        while !self.text.is_char_boundary(i) {
            i -= 1;
        }
        i
    }

    /// 0-based line of byte offset `at`, and the offset where that line starts.
    fn line_of(&self, at: usize) -> (usize, usize) {
        let line = self.line_starts.partition_point(|&s| s <= at) - 1;
        (line, self.line_starts[line])
    }

    /// End of line `line` (before its newline), or of the text.
    fn line_end(&self, line: usize) -> usize {
        self.line_starts
            .get(line + 1)
            .map_or(self.text.len(), |&s| s - 1)
    }

    /// 1-based line and column (in characters) of byte offset `at`.
    pub fn line_column(&self, at: usize) -> (usize, usize) {
        let at = self.clamp(at);
        let (line, start) = self.line_of(at);
        (line + 1, self.text[start..at].chars().count() + 1)
    }

    /// What to show for `span`, and the span within it: the whole file, or
    /// an excerpt of the span's line when a line miette would print (the
    /// span's lines and one either side) is longer than [`MAX_LINE`].
    pub fn snippet(&self, span: Range<usize>) -> (Snippet, Range<usize>) {
        let (first, line_start) = self.line_of(span.start);
        let (last, _) = self.line_of(span.end.max(span.start));
        let shown = first.saturating_sub(1)..=(last + 1).min(self.line_starts.len() - 1);
        let long = shown.into_iter().any(|l| {
            let start = self.line_starts[l];
            self.line_end(l).saturating_sub(start) > MAX_LINE
        });
        if !long {
            let whole = Snippet {
                text: self.text.clone(),
                line: 0,
                column: 0,
            };
            return (whole, span);
        }
        let line_end = self.line_end(first);
        let from = self.clamp(span.start.saturating_sub(WINDOW).max(line_start));
        let to = self.clamp((span.start + WINDOW).min(line_end));
        let to = if to < span.start { span.start } else { to };
        let prefix = if from > line_start { "…" } else { "" };
        let suffix = if to < line_end { "…" } else { "" };
        let text = format!("{prefix}{}{suffix}", &self.text[from..to]);
        let start = span.start - from + prefix.len();
        let end = span.end.clamp(span.start, to) - from + prefix.len();
        let excerpt = Snippet {
            text: text.into(),
            line: first,
            column: self.text[line_start..from].chars().count() - prefix.chars().count(),
        };
        (excerpt, start..end)
    }
}

/// `text` with every character that could act on a terminal replaced by a
/// visible one of the same UTF-8 length, so byte offsets do not move.
pub fn neutralise(text: &str) -> String {
    let bytes = text.as_bytes();
    if !(0..bytes.len()).any(|i| suspect(&bytes[i..])) {
        return text.to_string();
    }
    text.chars()
        .map(|c| match c {
            '\n' | '\r' | '\t' => c,
            c if c.is_control() || is_bidi(c) => match c.len_utf8() {
                1 => '?',
                2 => '¿',
                _ => '\u{FFFD}',
            },
            c => c,
        })
        .collect()
}

/// Whether the character starting `w` may need replacing: C0 controls
/// but line breaks and tabs, DEL, C1 controls (`C2 80`–`C2 9F`) and the bidi
/// characters (`E2 80 8E`–`8F`, `E2 80 AA`–`AE`, `E2 81 A6`–`A9`).
fn suspect(w: &[u8]) -> bool {
    match *w {
        [b, ..] if b < 0x20 => !matches!(b, b'\n' | b'\r' | b'\t'),
        [0x7F, ..] => true,
        [0xC2, 0x80..=0x9F, ..] => true,
        [0xE2, 0x80, 0x8E | 0x8F | 0xAA..=0xAE, ..] => true,
        [0xE2, 0x81, 0xA6..=0xA9, ..] => true,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neutralise_keeps_byte_offsets() {
        let text = "a\u{1b}[31m\u{85}\u{202E}b\n\tc\r\n";
        let safe = neutralise(text);
        assert_eq!(safe.len(), text.len());
        assert_eq!(safe, "a?[31m¿\u{FFFD}b\n\tc\r\n");
        let shown = [
            ("\u{0}", "?"),
            ("\u{7f}", "?"),
            ("\u{9f}", "¿"),
            ("\u{200f}", "\u{FFFD}"),
        ];
        for (c, shown) in shown
            .into_iter()
            .chain([("\u{2066}", "\u{FFFD}"), ("\u{2069}", "\u{FFFD}")])
        {
            assert_eq!(neutralise(&format!("−×{c}")), format!("−×{shown}"), "{c:?}");
        }
        assert_eq!(neutralise("Δv − 2 → ≈ é\n"), "Δv − 2 → ≈ é\n");
    }

    #[test]
    fn printable_escapes_controls_only() {
        assert_eq!(printable("ball\u{1b}[31m".into()), "ball\\u{1b}[31m");
        assert_eq!(printable("Δv ok\n".into()), "Δv ok\n");
    }

    #[test]
    fn excerpt_keeps_the_file_line_and_column() {
        let long = "x".repeat(1000);
        let text = format!("a = 1\nb = \"{long}\" ~\nc = 2\n");
        let file = File::new(&text);
        let at = text.find('~').unwrap();
        let (snippet, span) = file.snippet(at..at + 1);
        assert!(snippet.text.len() < 2 * WINDOW + 10, "{}", snippet.text);
        assert_eq!(&snippet.text[span.clone()], "~");
        let contents = snippet.read_span(&span.into(), 0, 0).unwrap();
        assert_eq!((contents.line(), contents.column()), (1, 1007));
        assert_eq!(file.line_column(at), (2, 1008));
    }

    #[test]
    fn columns_count_characters() {
        let text = "bodies = [\"bäll\", \"ballé\"]\n";
        let file = File::new(text);
        let at = text.find("\"ballé").unwrap();
        let (snippet, span) = file.snippet(at..at + 7);
        let contents = snippet.read_span(&span.into(), 0, 0).unwrap();
        assert_eq!(contents.column() + 1, file.line_column(at).1);
        assert_eq!(file.line_column(at), (1, 19));
    }
}
