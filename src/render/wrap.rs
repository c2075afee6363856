//! Plain text folded to a width: a line longer than the width breaks at
//! the last space that fits, preferring one outside brackets (so a vector
//! `(x, y, z)` stays on one line), and its continuation lines hang under
//! the line's text. Only plain text is folded: Markdown tables, LaTeX and
//! JSON are written as they are.

use std::io::{self, Write};

/// The width plain text is folded to when stdout is not a terminal and no
/// `--width` is given.
pub const DEFAULT_WIDTH: usize = 100;

/// How far continuation lines of `line` are indented: under the second
/// column when the line starts with a label followed by two spaces
/// (`   p0    contact 10: …`, `deepest penetration  0.01 m …`) or a word
/// ending in a colon (`   box1: position …`), else two spaces past the
/// line's own indentation.
fn hanging_indent(line: &str, width: usize) -> usize {
    let chars: Vec<char> = line.chars().collect();
    let lead = chars.iter().take_while(|c| **c == ' ').count();
    let limit = (width / 2).min(chars.len());
    let column = (lead..limit).find_map(|i| {
        let gap = chars[i..].iter().take_while(|c| **c == ' ').count();
        let after_label = i > lead && (gap >= 2 || chars[i - 1] == ':');
        (chars[i] == ' ' && after_label && i + gap < limit).then_some(i + gap)
    });
    column.unwrap_or((lead + 2).min(width / 2))
}

/// Where to break `chars` (a char index of a space) so that the part before
/// fits in `room`: the last space after a comma, semicolon, colon or bar
/// outside brackets in the second half of the room, else the last space
/// outside brackets past a third, else the last space at all; `None` when
/// no space fits.
fn break_at(chars: &[char], room: usize) -> Option<usize> {
    let mut depth = 0i32;
    let (mut punctuated, mut outside, mut any) = (None, None, None);
    for (i, c) in chars.iter().enumerate().take(room + 1) {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth -= 1,
            ' ' if i > 0 => {
                any = Some(i);
                if depth <= 0 && i >= room / 3 {
                    outside = Some(i);
                }
                let after_mark =
                    matches!(chars[i - 1], ',' | ';' | ':' | '|') || chars.get(i + 1) == Some(&'|');
                if depth <= 0 && i >= room / 2 && after_mark {
                    punctuated = Some(i);
                }
            }
            _ => {}
        }
    }
    punctuated.or(outside).or(any)
}

/// `line` (no newline) folded to `width` columns; a word longer than the
/// room is left whole. `width` 0 leaves the line as it is.
pub fn wrap_line(line: &str, width: usize) -> Vec<String> {
    if width == 0 || line.chars().count() <= width {
        return vec![line.to_string()];
    }
    let indent = hanging_indent(line, width);
    let mut out = Vec::new();
    let mut rest: Vec<char> = line.chars().collect();
    let mut prefix = 0;
    loop {
        let room = width - prefix;
        if rest.len() <= room {
            break;
        }
        let Some(at) = break_at(&rest, room) else {
            break;
        };
        let head: String = rest[..at].iter().collect();
        out.push(format!("{}{}", " ".repeat(prefix), head.trim_end()));
        let skip = rest[at..].iter().take_while(|c| **c == ' ').count();
        rest.drain(..at + skip);
        prefix = indent;
    }
    let tail: String = rest.into_iter().collect();
    out.push(format!("{}{tail}", " ".repeat(prefix)));
    out
}

/// Every line of `text` folded to `width` (0: unchanged).
pub fn wrap(text: &str, width: usize) -> String {
    if width == 0 {
        return text.to_string();
    }
    let mut out = String::with_capacity(text.len() + text.len() / 16);
    for piece in text.split_inclusive('\n') {
        let (line, newline) = match piece.strip_suffix('\n') {
            Some(l) => (l, "\n"),
            None => (piece, ""),
        };
        out.push_str(&wrap_line(line, width).join("\n"));
        out.push_str(newline);
    }
    out
}

/// A table laid out in aligned columns (two spaces between them, `indent`
/// spaces before each line, trailing spaces trimmed) and folded to `width`
/// as a table: when the columns are wider than the width, the first `keys`
/// columns (the row's name) stay and the others are split into blocks that
/// fit, one after another with a blank line between; a block of one column
/// still too wide folds its lines under that column. Width 0 never folds.
/// Each line ends with a newline; no blank line follows the last block.
pub fn table(
    indent: usize,
    keys: usize,
    head: &[String],
    rows: &[Vec<String>],
    width: usize,
) -> String {
    let n = head.len();
    let cell = |r: &[String], k: usize| r.get(k).map_or(0, |c| c.chars().count());
    let widths: Vec<usize> = (0..n)
        .map(|k| {
            rows.iter()
                .map(|r| cell(r, k))
                .chain([cell(head, k)])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let span = |cols: &[usize]| {
        indent + cols.iter().map(|k| widths[*k]).sum::<usize>() + 2 * cols.len().saturating_sub(1)
    };
    let all: Vec<usize> = (0..n).collect();
    let blocks: Vec<Vec<usize>> = if width == 0 || n < 2 || span(&all) <= width {
        vec![all]
    } else {
        // The name columns, fewer when they leave no room for a value.
        let narrowest = (1..n).map(|k| widths[k]).min().unwrap_or(0);
        let keys = (1..=keys.clamp(1, n - 1))
            .rev()
            .find(|k| span(&all[..*k]) + 2 + narrowest <= width)
            .unwrap_or(1);
        let mut blocks: Vec<Vec<usize>> = Vec::new();
        for k in keys..n {
            match blocks.last_mut() {
                Some(b) if span(&[b.as_slice(), &[k]].concat()) <= width => b.push(k),
                _ => blocks.push([&all[..keys], &[k]].concat()),
            }
        }
        blocks
    };
    let line = |r: &[String], cols: &[usize]| {
        let mut l = " ".repeat(indent);
        for (i, k) in cols.iter().enumerate() {
            let c = r.get(*k).map_or("", String::as_str);
            if i > 0 {
                l.push_str("  ");
            }
            l.push_str(c);
            l.push_str(&" ".repeat(widths[*k] - c.chars().count()));
        }
        let l = l.trim_end();
        // A line still too wide hangs under its second column.
        let hang = span(&cols[..cols.len() - 1]) + 2;
        if width == 0 || l.chars().count() <= width || cols.len() < 2 || hang > width / 2 {
            return wrap_line(l, width);
        }
        let (name, rest): (String, String) = {
            let chars: Vec<char> = l.chars().collect();
            (
                chars[..hang].iter().collect(),
                chars[hang..].iter().collect(),
            )
        };
        let mut out = Vec::new();
        for (j, piece) in wrap_line(&rest, width - hang).into_iter().enumerate() {
            let lead = if j == 0 {
                name.clone()
            } else {
                " ".repeat(hang)
            };
            out.push(
                format!("{lead}{}", piece.trim_start())
                    .trim_end()
                    .to_string(),
            );
        }
        out
    };
    let mut out = String::new();
    for (b, cols) in blocks.iter().enumerate() {
        if b > 0 {
            out.push('\n');
        }
        for r in std::iter::once(head).chain(rows.iter().map(Vec::as_slice)) {
            for l in line(r, cols) {
                out.push_str(&l);
                out.push('\n');
            }
        }
    }
    out
}

/// A writer that folds whole lines to a width as they pass through (for
/// output written as it is computed, like `simulate`'s table).
pub struct WrapWriter<W: Write> {
    out: W,
    width: usize,
    pending: Vec<u8>,
}

impl<W: Write> WrapWriter<W> {
    pub fn new(out: W, width: usize) -> Self {
        WrapWriter {
            out,
            width,
            pending: Vec::new(),
        }
    }
}

impl<W: Write> Write for WrapWriter<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.width == 0 {
            return self.out.write(buf);
        }
        self.pending.extend_from_slice(buf);
        if let Some(last) = self.pending.iter().rposition(|b| *b == b'\n') {
            let whole: Vec<u8> = self.pending.drain(..=last).collect();
            let text = String::from_utf8_lossy(&whole);
            self.out.write_all(wrap(&text, self.width).as_bytes())?;
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if !self.pending.is_empty() {
            let rest = std::mem::take(&mut self.pending);
            let text = String::from_utf8_lossy(&rest);
            self.out.write_all(wrap(&text, self.width).as_bytes())?;
        }
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_line_is_kept() {
        assert_eq!(wrap("a b c\n", 10), "a b c\n");
        assert_eq!(wrap("a b c d e f g\n", 0), "a b c d e f g\n");
    }

    #[test]
    fn a_long_line_hangs_under_its_tag_and_keeps_vectors_whole() {
        let line = "   p0    contact 10: penetration 0.0467 → 0; top Δp (-0.000134, 0.00785, 8.17e-5), Δθ (-0.0274, -0.000654, 0.0178)";
        let lines = wrap_line(line, 60);
        assert!(lines.len() > 1, "{lines:?}");
        for l in &lines {
            assert!(l.chars().count() <= 60, "{l:?} is wider than 60");
        }
        for l in &lines[1..] {
            assert!(
                l.starts_with("         ") && !l.starts_with("          "),
                "{l:?}"
            );
        }
        assert!(
            lines
                .iter()
                .any(|l| l.contains("(-0.000134, 0.00785, 8.17e-5)")),
            "{lines:?}"
        );
        let joined: Vec<&str> = lines.iter().flat_map(|l| l.split_whitespace()).collect();
        assert_eq!(joined, line.split_whitespace().collect::<Vec<_>>());
    }

    #[test]
    fn prose_hangs_two_spaces_in() {
        let lines = wrap_line("one two three four five six seven eight nine ten", 20);
        assert_eq!(lines[0], "one two three four");
        assert!(lines[1..]
            .iter()
            .all(|l| l.starts_with("  ") && !l.starts_with("   ")));
    }

    fn strings(cells: &[&str]) -> Vec<String> {
        cells.iter().map(|c| c.to_string()).collect()
    }

    #[test]
    fn a_table_that_fits_is_aligned_columns() {
        let head = strings(&["k", "value", "note"]);
        let rows = vec![strings(&["1", "2.5", "first"]), strings(&["10", "-3", ""])];
        let want = " k   value  note\n 1   2.5    first\n 10  -3\n";
        assert_eq!(table(1, 1, &head, &rows, 80), want);
        assert_eq!(table(1, 1, &head, &rows, 0), want);
    }

    #[test]
    fn a_wide_table_splits_into_blocks_that_repeat_the_name_columns() {
        let head = strings(&["knob", "value", "aaaaaaaaaa", "bbbbbbbbbb", "cccccccccc"]);
        let rows = vec![strings(&["dt", "1/30", "1", "2", "3"])];
        let text = table(0, 2, &head, &rows, 30);
        let want = "knob  value  aaaaaaaaaa\n\
                    dt    1/30   1\n\
                    \n\
                    knob  value  bbbbbbbbbb\n\
                    dt    1/30   2\n\
                    \n\
                    knob  value  cccccccccc\n\
                    dt    1/30   3\n";
        assert_eq!(text, want);
        // Two value columns fit in 40.
        let text = table(0, 2, &head, &rows, 40);
        assert!(
            text.starts_with("knob  value  aaaaaaaaaa  bbbbbbbbbb\n"),
            "{text}"
        );
    }

    #[test]
    fn a_cell_wider_than_the_room_folds_under_its_column() {
        let head = strings(&["k", "w_k"]);
        let rows = vec![strings(&["1", "(1, 2, 3) = (4, 5, 6) - (3, 3, 3)"])];
        let text = table(0, 1, &head, &rows, 20);
        assert_eq!(
            text,
            "k  w_k\n1  (1, 2, 3) =\n   (4, 5, 6) -\n   (3, 3, 3)\n"
        );
    }

    #[test]
    fn the_writer_folds_as_the_plain_function_does() {
        let text = "short\n".to_string() + &"word ".repeat(40) + "\nend";
        let mut w = WrapWriter::new(Vec::new(), 30);
        for chunk in text.as_bytes().chunks(7) {
            w.write_all(chunk).unwrap();
        }
        w.flush().unwrap();
        assert_eq!(String::from_utf8(w.out).unwrap(), wrap(&text, 30));
    }
}
