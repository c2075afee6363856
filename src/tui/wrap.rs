//! Word wrapping with a hanging indent, so that a long `= (…)` line continues
//! under its numbers rather than at the panel's edge.

use unicode_width::UnicodeWidthStr;

/// Display width of `s` in terminal cells.
pub fn width(s: &str) -> usize {
    UnicodeWidthStr::width(s)
}

/// Splits `text` into lines of at most `max` cells; lines after the first
/// start with `indent` spaces. Breaks at spaces outside brackets first, so a
/// vector `(1, 2, 3)` stays on one line when it fits on one; then at any
/// space; inside a word only when the word alone is too long.
pub fn wrap(text: &str, max: usize, indent: usize) -> Vec<String> {
    let mut w = Wrapper {
        max: max.max(1),
        indent: if indent + 8 > max { 0 } else { indent },
        lines: vec![],
        line: String::new(),
        width: 0,
    };
    for unit in units(text, 0) {
        w.unit(unit, 0);
    }
    let last = w.line.trim_end().to_string();
    if !last.trim().is_empty() || w.lines.is_empty() {
        w.lines.push(last);
    }
    w.lines
}

/// Pieces of `text` split after spaces inside at most `level` brackets.
fn units(text: &str, level: i32) -> Vec<&str> {
    let mut out = vec![];
    let mut depth = 0i32;
    let mut start = 0;
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ' ' if depth <= level => {
                out.push(&text[start..i + 1]);
                start = i + 1;
            }
            _ => {}
        }
    }
    if start < text.len() {
        out.push(&text[start..]);
    }
    out
}

struct Wrapper {
    max: usize,
    indent: usize,
    lines: Vec<String>,
    line: String,
    width: usize,
}

impl Wrapper {
    /// Where text starts on the current line: after the indent on a continuation.
    fn start(&self) -> usize {
        if self.lines.is_empty() {
            0
        } else {
            self.indent
        }
    }
    /// Where text would start after a [`newline`](Self::newline).
    fn fresh_start(&self) -> usize {
        if self.has_text() {
            self.indent
        } else {
            self.width
        }
    }
    fn has_text(&self) -> bool {
        self.width > self.start()
    }
    fn newline(&mut self) {
        if self.has_text() {
            let done = std::mem::replace(&mut self.line, " ".repeat(self.indent));
            self.lines.push(done.trim_end().to_string());
            self.width = self.indent;
        }
    }
    fn push(&mut self, s: &str) {
        self.line.push_str(s);
        self.width += width(s);
    }
    /// Places a piece split at bracket depth `level`: whole if it fits on
    /// this line or the next, else split one bracket deeper (matrix rows),
    /// else word by word.
    fn unit(&mut self, unit: &str, level: i32) {
        let uw = width(unit.trim_end());
        if self.width + uw <= self.max {
            self.push(unit);
        } else if self.fresh_start() + uw <= self.max {
            self.newline();
            self.push(unit);
        } else if level < 2 {
            for piece in units(unit, level + 1) {
                self.unit(piece, level + 1);
            }
        } else {
            for word in unit.split_inclusive(' ') {
                self.word(word);
            }
        }
    }

    fn word(&mut self, word: &str) {
        let ww = width(word.trim_end());
        if self.width + ww > self.max {
            self.newline();
        }
        if self.width + ww <= self.max {
            return self.push(word);
        }
        if !self.has_text() && ww <= self.max {
            // Too long for the hanging indent but not for the line: this
            // line starts further left, so that a number or a unit stays whole.
            let start = self.max - ww;
            self.line = " ".repeat(start);
            self.width = start;
            return self.push(word);
        }
        // A word longer than the whole line: broken after its operators
        // (never inside a number or a unit), cut only where a piece between
        // two operators is itself longer than the line.
        let pieces = operator_pieces(word);
        if pieces.len() > 1 {
            for piece in pieces {
                self.word(piece);
            }
            return;
        }
        for ch in word.chars() {
            let cw = width(ch.encode_utf8(&mut [0; 4]));
            if self.width + cw > self.max && self.has_text() {
                self.newline();
            }
            self.line.push(ch);
            self.width += cw;
        }
    }
}

/// `word` split after each operator (`·`, `×`, `+`, `=`, `,`) that stands
/// between two terms: not the sign of an exponent (`1e+5`), and never at `/`,
/// which units use (`(m/s)/(N·s)`).
fn operator_pieces(word: &str) -> Vec<&str> {
    let mut out = vec![];
    let mut start = 0;
    let mut prev = None;
    for (i, c) in word.char_indices() {
        let exponent = c == '+' && prev == Some('e');
        if "·×+=,".contains(c) && !exponent {
            let end = i + c.len_utf8();
            if end < word.len() {
                out.push(&word[start..end]);
                start = end;
            }
        }
        prev = Some(c);
    }
    out.push(&word[start..]);
    out
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

/// The end of `s` in at most `max` cells, starting with `…` when cut: a long
/// input line scrolled so that its end (where the cursor is) stays visible.
pub fn tail(s: &str, max: usize) -> String {
    if width(s) <= max {
        return s.to_string();
    }
    let mut kept = Vec::new();
    let mut w = 0;
    for ch in s.chars().rev() {
        let cw = width(ch.encode_utf8(&mut [0; 4]));
        if w + cw + 1 > max {
            break;
        }
        kept.push(ch);
        w += cw;
    }
    let mut out = String::from(if max > 0 { "…" } else { "" });
    out.extend(kept.into_iter().rev());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tail_keeps_the_end() {
        assert_eq!(tail("0.5", 10), "0.5");
        assert_eq!(tail("123456789", 5), "…6789");
        assert_eq!(width(&tail(&"é".repeat(3000), 40)), 40);
        assert_eq!(tail("abc", 0), "");
    }

    #[test]
    fn hanging_indent() {
        let lines = wrap("Δv = -(1 + c) v_s and more words here", 16, 4);
        assert_eq!(
            lines,
            ["Δv = -(1 + c)", "    v_s and more", "    words here"]
        );
        for l in &lines {
            assert!(width(l) <= 16);
        }
    }

    #[test]
    fn vectors_stay_whole_when_they_fit() {
        let lines = wrap("= (0, 0, 0.0091525) × (2.1966, -8.1966, 0)", 30, 2);
        assert_eq!(lines, ["= (0, 0, 0.0091525) ×", "  (2.1966, -8.1966, 0)"]);
        let lines = wrap(
            "= [[0.00416667, 0, 0], [0, 0.00416667, 0]] (0, 0, 2)",
            30,
            2,
        );
        assert!(lines.iter().all(|l| width(l) <= 30), "{lines:?}");
        assert_eq!(
            lines,
            [
                "= [[0.00416667, 0, 0],",
                "  [0, 0.00416667, 0]]",
                "  (0, 0, 2)"
            ]
        );
    }

    #[test]
    fn continuation_lines_count_their_indent() {
        let text = "      = [[1.5, 0, 0], [0, 0.6, 0], [0, 0, 0.6]] (0, 0, -3.91315)";
        let lines = wrap(text, 40, 6);
        assert!(lines.iter().all(|l| width(l) <= 40), "{lines:?}");
        assert_eq!(lines[0], "      = [[1.5, 0, 0], [0, 0.6, 0],");
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
    fn numbers_and_units_stay_whole_under_a_deep_indent() {
        // An indent of 30 leaves 10 cells: a number of 11 starts further left.
        let text = "Δq̇_t = 0.3 + (0.0750194) · 2 = 0.0750194 (m/s)/(N·s)";
        let lines = wrap(text, 40, 30);
        assert!(lines.iter().all(|l| width(l) <= 40), "{lines:?}");
        let words: Vec<&str> = lines.iter().flat_map(|l| l.split_whitespace()).collect();
        assert_eq!(words, text.split_whitespace().collect::<Vec<_>>());
    }

    #[test]
    fn a_word_longer_than_the_line_breaks_after_an_operator() {
        let lines = wrap("(1.5)·(2.25)+(3.125e+5)=4", 12, 0);
        assert_eq!(lines, ["(1.5)·", "(2.25)+", "(3.125e+5)=4"]);
    }

    #[test]
    fn truncation() {
        assert_eq!(truncate("Desired Δv", 20), "Desired Δv");
        assert_eq!(truncate("Desired Δv", 5), "Desi…");
        assert_eq!(truncate("abc", 0), "");
    }
}
