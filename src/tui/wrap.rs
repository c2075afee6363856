//! Word wrapping with a hanging indent, so that a long `= (…)` line continues
//! under its numbers rather than at the panel's edge.

use unicode_width::UnicodeWidthStr;

/// Display width of `s` in terminal cells.
pub fn width(s: &str) -> usize {
    UnicodeWidthStr::width(s)
}

/// Splits `text` into lines of at most `max` cells; lines after the first
/// start with `indent` spaces. Breaks after spaces, and inside a word only
/// when the word alone is too long.
pub fn wrap(text: &str, max: usize, indent: usize) -> Vec<String> {
    let max = max.max(1);
    let indent = if indent + 8 > max { 0 } else { indent };
    let mut lines = Vec::new();
    let mut line = String::new();
    let mut w = 0;
    for word in text.split_inclusive(' ') {
        let ww = width(word.trim_end());
        if w + ww > max && w > indent_of(&lines, indent) {
            lines.push(line.trim_end().to_string());
            line = " ".repeat(indent);
            w = indent;
        }
        if w + ww > max {
            // A word longer than the line: cut it.
            for ch in word.chars() {
                let cw = width(ch.encode_utf8(&mut [0; 4]));
                if w + cw > max && w > indent_of(&lines, indent) {
                    lines.push(std::mem::replace(&mut line, " ".repeat(indent)));
                    w = indent;
                }
                line.push(ch);
                w += cw;
            }
        } else {
            line.push_str(word);
            w += width(word);
        }
    }
    let last = line.trim_end().to_string();
    if !last.trim().is_empty() || lines.is_empty() {
        lines.push(last);
    }
    lines
}

/// Indent of the line being filled: none on the first line.
fn indent_of(lines: &[String], indent: usize) -> usize {
    if lines.is_empty() {
        0
    } else {
        indent
    }
}

/// Cuts `s` to `max` cells, ending in `…` when cut.
pub fn truncate(s: &str, max: usize) -> String {
    if width(s) <= max {
        return s.to_string();
    }
    let mut out = String::new();
    let mut w = 0;
    for ch in s.chars() {
        let cw = width(ch.encode_utf8(&mut [0; 4]));
        if w + cw + 1 > max {
            break;
        }
        out.push(ch);
        w += cw;
    }
    if max > 0 {
        out.push('…');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hanging_indent() {
        let lines = wrap("Δv = −(1 + c) v_s and more words here", 16, 4);
        assert_eq!(
            lines,
            ["Δv = −(1 + c)", "    v_s and more", "    words here"]
        );
        for l in &lines {
            assert!(width(l) <= 16);
        }
    }

    #[test]
    fn long_words_are_cut_and_nothing_is_lost() {
        let lines = wrap("[[0.00416667,0,0],[0,0.00416667,0]]", 10, 2);
        assert!(lines.iter().all(|l| width(l) <= 10), "{lines:?}");
        let joined: String = lines.iter().map(|l| l.trim_start()).collect();
        assert_eq!(joined, "[[0.00416667,0,0],[0,0.00416667,0]]");
        assert_eq!(wrap("", 5, 0), [""]);
        assert_eq!(wrap("abc", 1, 0), ["a", "b", "c"]);
    }

    #[test]
    fn truncation() {
        assert_eq!(truncate("Desired Δv", 20), "Desired Δv");
        assert_eq!(truncate("Desired Δv", 5), "Desi…");
        assert_eq!(truncate("abc", 0), "");
    }
}
