//! Text that reaches a terminal: which characters would move the cursor or
//! reorder what is shown, and a message with them escaped (`\u{1b}`). A
//! leaf: the lesson loader, the output writer and the renderers use it.

/// Bidirectional formatting characters, which can reorder what is shown.
pub fn is_bidi(c: char) -> bool {
    matches!(c, '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
}

/// A message quoting a file (a name, a key, a path) with its control
/// characters escaped (`\u{1b}`), so it prints as text; line feeds stay.
pub fn printable(message: String) -> String {
    let bad = |c: char| (c.is_control() && c != '\n') || is_bidi(c);
    if !message.chars().any(bad) {
        return message;
    }
    message
        .chars()
        .map(|c| {
            if bad(c) {
                c.escape_unicode().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}
