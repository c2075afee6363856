//! Which characters lesson strings may hold. Names and one-line texts reach
//! the terminal, Markdown tables and LaTeX as they are, so a character that
//! moves the cursor (CR, LF, escape sequences), reorders text (bidirectional
//! overrides) or breaks a line (U+2028) is refused by name rather than
//! escaped in every renderer.

/// The refusal for a character, naming it: `(found U+000D), a carriage return`.
fn refusal(c: char) -> String {
    let name = match c {
        '\r' => ", a carriage return",
        '\n' => ", a line feed (line break)",
        '\t' => ", a tab",
        '\u{1b}' => ", an escape (starts a terminal control sequence)",
        '\u{7}' => ", a bell",
        '\u{8}' => ", a backspace",
        '\0' => ", a NUL",
        '\u{7f}' => ", a delete",
        '\u{85}' => ", a next-line",
        '\u{2028}' => ", a line separator",
        '\u{2029}' => ", a paragraph separator",
        c if is_bidi(c) => ", a bidirectional-text control (reorders what follows)",
        _ => "",
    };
    format!(
        "must not contain control characters (found U+{:04X}){name}",
        c as u32
    )
}

use crate::printable::is_bidi;

/// Characters no lesson string may hold, whatever its kind.
fn always_refused(c: char) -> bool {
    (c.is_control() && !matches!(c, '\n' | '\r' | '\t'))
        || is_bidi(c)
        || matches!(c, '\u{2028}' | '\u{2029}')
}

/// Ids, body and contact names: one line, no control character at all
/// (not even a tab: names fill table cells and headings).
pub fn name(s: &str) -> Result<(), String> {
    match s.chars().find(|&c| always_refused(c) || c.is_control()) {
        Some(c) => Err(refusal(c)),
        None => Ok(()),
    }
}

/// One-line texts (title, source, a printed entry's `value` and `where`):
/// tabs are fine, line breaks are not.
pub fn line(s: &str) -> Result<(), String> {
    match s
        .chars()
        .find(|&c| always_refused(c) || matches!(c, '\n' | '\r'))
    {
        Some(c) => Err(refusal(c)),
        None => Ok(()),
    }
}

/// Multi-line texts (summary, erratum): line breaks (LF or CR LF) and tabs;
/// a CR on its own would send the cursor back over the line.
pub fn lines(s: &str) -> Result<(), String> {
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        let lone_cr = c == '\r' && chars.peek() != Some(&'\n');
        if always_refused(c) || lone_cr {
            return Err(refusal(c));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_refuse_every_control_character_by_name() {
        assert!(name("cube 2 (é)").is_ok());
        for (s, found) in [
            ("a\rb", "U+000D), a carriage return"),
            ("a\nb", "U+000A), a line feed"),
            ("a\tb", "U+0009), a tab"),
            ("a\u{1b}[2Jb", "U+001B), an escape"),
            ("a\u{202E}b", "U+202E), a bidirectional"),
            ("a\u{2028}b", "U+2028), a line separator"),
            ("a\u{85}b", "U+0085), a next-line"),
        ] {
            let e = name(s).unwrap_err();
            assert!(e.contains(found), "{s:?}: {e}");
        }
    }

    #[test]
    fn one_line_texts_take_tabs_but_no_line_break() {
        assert!(line("a\tb").is_ok());
        assert!(line("a\nb").unwrap_err().contains("U+000A"));
        assert!(line("a\rb").unwrap_err().contains("U+000D"));
        assert!(line("a\u{1b}b").unwrap_err().contains("U+001B"));
    }

    #[test]
    fn multi_line_texts_take_lf_and_crlf_but_not_a_lone_cr() {
        assert!(lines("a\nb\r\nc\td").is_ok());
        assert!(lines("a\rb").unwrap_err().contains("U+000D"));
        assert!(lines("ab\r").unwrap_err().contains("U+000D"));
        assert!(lines("a\u{7}").unwrap_err().contains("U+0007), a bell"));
    }
}
