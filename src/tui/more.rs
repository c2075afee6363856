//! The mark of a cut list: how many of its rows are out of view above and
//! below, written on the bottom border of its box (`… 2 more below`).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use super::app::App;
use super::wrap::width;

/// The words for `above` rows hidden above and `below` hidden below; `None`
/// when the list shows every row.
pub fn text(above: usize, below: usize) -> Option<String> {
    match (above, below) {
        (0, 0) => None,
        (0, b) => Some(format!(" … {b} more below ")),
        (a, 0) => Some(format!(" … {a} more above ")),
        (a, b) => Some(format!(" … {a} more above, {b} below ")),
    }
}

/// The same in fewer cells, for a narrow box: ` ↑2 ↓3 `.
fn short(above: usize, below: usize) -> String {
    let mut s = String::from(" ");
    if above > 0 {
        s.push_str(&format!("↑{above} "));
    }
    if below > 0 {
        s.push_str(&format!("↓{below} "));
    }
    s
}

/// Writes the mark right-aligned on the bottom border of `outer` (the box
/// around the list), in the dim style; nothing when no row is hidden.
pub fn mark(app: &App, outer: Rect, above: usize, below: usize, buf: &mut Buffer) {
    let Some(long) = text(above, below) else {
        return;
    };
    if outer.height < 2 || outer.width < 4 {
        return;
    }
    let room = outer.width as usize - 2;
    let text = [long, short(above, below)]
        .into_iter()
        .find(|t| width(t) <= room)
        .unwrap_or_default();
    let x = outer.right() - 1 - width(&text) as u16;
    buf.set_string(x, outer.bottom() - 1, text, app.theme.dim());
}

/// Rows hidden above and below a list of `total` rows showing `rows` from `first`.
pub fn hidden(total: usize, first: usize, rows: usize) -> (usize, usize) {
    let first = first.min(total);
    (first, total.saturating_sub(first + rows))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words() {
        assert_eq!(text(0, 0), None);
        assert_eq!(text(0, 2).unwrap(), " … 2 more below ");
        assert_eq!(text(3, 0).unwrap(), " … 3 more above ");
        assert_eq!(text(1, 2).unwrap(), " … 1 more above, 2 below ");
        assert_eq!(hidden(20, 0, 18), (0, 2));
        assert_eq!(hidden(15, 3, 12), (3, 0));
        assert_eq!(hidden(5, 0, 12), (0, 0));
    }
}
